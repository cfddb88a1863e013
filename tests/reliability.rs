//! Bad input, divergence and interrupted recordings (README "When things go wrong"; PHYSICS.md §5 "Health check").

mod common;

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn tether() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tether"))
}

/// Every scalar and translation in a recording, which must all be finite.
fn recorded_numbers(path: &Path) -> (Vec<f64>, Vec<f32>, usize) {
    let mut file = std::fs::File::open(path).unwrap();
    let stores = rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
    let (mut scalars, mut translations, mut energy_rows) = (Vec::new(), Vec::new(), 0);
    for store in stores.values() {
        for chunk in store.iter_physical_chunks() {
            for row in chunk.iter_slices::<f64>(rerun::Scalars::descriptor_scalars().component) {
                scalars.extend_from_slice(row);
            }
            for row in chunk.iter_slices::<[f32; 3]>(rerun::Transform3D::descriptor_translation().component) {
                translations.extend(row.iter().flatten());
            }
            if chunk.entity_path().to_string() == "/plots/energy/stored" {
                energy_rows += chunk.num_rows();
            }
        }
    }
    (scalars, translations, energy_rows)
}

fn verify(path: &Path) {
    let verify = Command::new("rerun")
        .args(["rrd", "verify", path.to_str().unwrap()])
        .output()
        .expect("`rerun` CLI (pip install rerun-sdk==0.36.3)");
    assert!(verify.status.success(), "rerun rrd verify: {}", String::from_utf8_lossy(&verify.stderr));
}

#[test]
fn a_diverging_run_stops_names_the_culprit_and_keeps_nan_out_of_the_recording() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("unstable.rrd");
    let run = tether()
        .args([
            "record",
            common::repo("crates/scene/tests/fixtures/unstable_chain.ron").to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--log-hz",
            "200",
        ])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(stderr.contains("warning: the integrator step 5.000e-3 s exceeds the stable time step"), "{stderr}");
    assert!(stderr.contains("the simulation diverged at t = "), "{stderr}");
    assert!(stderr.contains("body \"b"), "{stderr}");
    assert!(stderr.contains("the stable time step is 4.472e-3 s, set by coupling \"s"), "{stderr}");
    verify(&out);
    let (scalars, translations, energy_rows) = recorded_numbers(&out);
    assert!(energy_rows >= 2, "frames before the blow-up were kept: {energy_rows}");
    assert!(!scalars.is_empty() && !translations.is_empty());
    assert!(scalars.iter().all(|x| x.is_finite()), "a non-finite scalar was recorded");
    assert!(translations.iter().all(|x| x.is_finite()), "a non-finite translation was recorded");
}

/// Ctrl-C (SIGINT) and SIGTERM to a real `tether record`: it stops, exits 130, and the file
/// holds everything up to the interruption and passes `rerun rrd verify`.
#[test]
fn interrupting_a_recording_leaves_a_complete_file() {
    for signal in ["INT", "TERM"] {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("long.rrd");
        let child = tether()
            .args([
                "record",
                common::repo("scenes/bench/chain100_air.ron").to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "--duration",
                "100000",
            ])
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Wait until frames are being written.
        let start = Instant::now();
        while std::fs::metadata(&out).map_or(0, |m| m.len()) < 200_000 {
            assert!(start.elapsed() < Duration::from_secs(60), "no data written");
            std::thread::sleep(Duration::from_millis(50));
        }
        let killed = Command::new("kill").args([format!("-{signal}"), child.id().to_string()]).status().unwrap();
        assert!(killed.success());
        let output = child.wait_with_output().unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(130), "SIG{signal}: {stderr}");
        assert!(stderr.contains("interrupted at t = "), "{stderr}");
        verify(&out);
        let (scalars, _, energy_rows) = recorded_numbers(&out);
        assert!(energy_rows > 10, "SIG{signal}: {energy_rows} frames");
        assert!(scalars.iter().all(|x| x.is_finite()));
    }
}

/// Issue 48's line 10³⁰ N stiff, which ran for ever at 4·10⁹ sub-steps a step and ignored
/// SIGTERM: `tether record` now stops at its second step, exit code 1, naming the coupling, the
/// sub-steps it would need and the bound (a hang would fail at the deadline).
#[test]
fn a_line_too_stiff_to_step_is_refused_as_it_runs() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(common::repo("scenes/chain_forced_surge.ron")).unwrap();
    assert_eq!(text.matches("stiffness: 442714.0").count(), 1);
    let scene = dir.path().join("stiff.ron");
    std::fs::write(&scene, text.replace("stiffness: 442714.0", "stiffness: 1e30")).unwrap();
    let out = dir.path().join("stiff.rrd");
    let mut child = tether()
        .args(["record", scene.to_str().unwrap(), "-o", out.to_str().unwrap(), "--duration", "0.5"])
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        assert!(start.elapsed() < Duration::from_secs(60), "still running after 60 s");
        std::thread::sleep(Duration::from_millis(50));
    }
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("coupling \"chain\" at t = 0.01 s: the dynamic line needs "), "{stderr}");
    assert!(
        stderr.contains("more than 100000: its stiffness, length or segments make it too stiff to step"),
        "{stderr}"
    );
    verify(&out);
}

/// SIGTERM to each long stage of the headless commands, sent once it runs: the process is gone
/// within a second with exit code 130 and says it was interrupted. The recording's step loop,
/// the storm's seeds and the fit's iterations stop at the flag (cooperatively); the RAO runs
/// and the study's runs do not look at it, and the watchdog ends them 0.5 s after it (crates/analysis/src/interrupt.rs), as it would
/// any other stage.
#[test]
fn sigterm_stops_every_long_stage_within_a_second() {
    let dir = tempfile::tempdir().unwrap();
    let path = |p: &str| common::repo(p).to_str().unwrap().to_string();
    let out = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    let stages: [(&str, Vec<String>); 5] = [
        (
            "the recording's steps",
            vec![
                "record".into(),
                path("scenes/chain_forced_surge.ron"),
                "-o".into(),
                out("a.rrd"),
                "--duration".into(),
                "100000".into(),
            ],
        ),
        (
            "the RAO runs",
            [
                "rao",
                &path("validation/potential-flow/cylinder.ron"),
                "--body",
                "cylinder",
                "--periods",
                "6,8,10,12",
                "--time-domain",
                "--duration",
                "100000",
            ]
            .map(String::from)
            .to_vec(),
        ),
        (
            "the study's runs",
            ["study", &path("scenes/chain_forced_surge.ron"), "--duration", "100000", "-o", &out("study")]
                .map(String::from)
                .to_vec(),
        ),
        (
            "the storm's seeds",
            ["storm", &path("scenes/buoy_in_a_storm.ron"), "-o", &out("storm"), "--hours", "1000", "--seeds", "2"]
                .map(String::from)
                .to_vec(),
        ),
        (
            "the fit's iterations",
            [
                "fit",
                &path("validation/calibration/chain_cdn.ron"),
                "-o",
                &out("fit"),
                "--scene-out",
                &out("fitted.ron"),
                "--jobs",
                "1",
            ]
            .map(String::from)
            .to_vec(),
        ),
    ];
    for (stage, args) in stages {
        let mut child = tether().args(&args).stderr(Stdio::piped()).stdout(Stdio::piped()).spawn().unwrap();
        // Into the stage: the fit once its first iteration is reported (it converges in
        // seconds), the others after 3 s (each would run for hours).
        let (ready, lines) = std::sync::mpsc::channel();
        let stderr = BufReader::new(child.stderr.take().unwrap());
        let reader = std::thread::spawn(move || {
            let mut text = String::new();
            for line in stderr.lines().map_while(Result::ok) {
                if line.starts_with("iteration 1:") {
                    let _ = ready.send(());
                }
                text += &line;
                text.push('\n');
            }
            text
        });
        if stage.contains("fit") {
            lines.recv_timeout(Duration::from_secs(60)).expect("the fit's first iteration");
        } else {
            std::thread::sleep(Duration::from_secs(3));
        }
        let sent = Instant::now();
        // SAFETY: kill with a valid pid and signal has no memory effects.
        unsafe { libc::kill(child.id() as i32, libc::SIGTERM) };
        let status = child.wait().unwrap();
        let took = sent.elapsed();
        let stderr = reader.join().unwrap();
        let mut stdout = String::new();
        std::io::Read::read_to_string(&mut child.stdout.take().unwrap(), &mut stdout).unwrap();
        assert_eq!(status.code(), Some(130), "{stage} ({status}): {stderr}");
        // The fit's report (on stdout) says so; the others say so on stderr.
        assert!(stderr.contains("interrupted") || stdout.contains("PARTIAL (stopped by Ctrl-C)"), "{stage}: {stderr}");
        assert!(took < Duration::from_secs(1), "{stage}: {took:?} after SIGTERM");
        eprintln!("{stage}: stopped {:.0} ms after SIGTERM", took.as_secs_f64() * 1e3);
    }
}

#[test]
fn unknown_integrator_and_bad_time_step_flags_are_refused() {
    let scene = common::repo("scenes/chain.ron");
    let out = tether()
        .args(["record", scene.to_str().unwrap(), "-o", "/tmp/never.rrd", "--integrator", "euler"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&out.stderr)
            .contains("unknown integrator `euler`, expected one of leapfrog, leapfrog2, splitting, rk4, dopri45")
    );
    let out =
        tether().args(["record", scene.to_str().unwrap(), "-o", "/tmp/never.rrd", "--dt=-0.001"]).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--dt: dt must be > 0 s, got -0.001"));
}

fn error_of(text: &str) -> String {
    match tether_scene::parse(text, Path::new("bad.ron")) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

const BODY: &str = "Body(name: \"b\", master: Node(position: (0, 0, 0), mass: 1.0, inertia: Inertia(xx: 1, yy: 1, zz: 1)), shape: Sphere(radius: 0.1))";

#[test]
fn empty_wrong_types_huge_and_negative_inputs_are_errors() {
    let cases = [
        ("".to_string(), "bad.ron:1:1: "),
        ("Scene(dt: \"fast\", bodies: [])".to_string(), "bad.ron:1:11: "),
        (format!("Scene(dt: 0.01, bodies: [{}])", BODY.replace("position: (0, 0, 0)", "position: (0, 0, 0), mass_kg: 2")), "bad.ron:1:"),
        (
            format!("Scene(dt: 0.01, bodies: [{}])", BODY.replace("shape:", "slaves: [Node(position: (1e200, 0, 0), mass: 1e300)], shape:")),
            "bad.ron:1:",
        ),
        (format!("Scene(dt: 0.01, bodies: [{}])", BODY.replace("radius: 0.1", "radius: -0.1")), "bad.ron:1:"),
        (
            format!("Scene(dt: 0.01, bodies: [{BODY}], couplings: [SpringDamper(name: \"s\", end1: World((1, 0, 0)), end2: Body(body: \"b\"), law: Linear(stiffness: 1, rest_length: -1))])"),
            "bad.ron:1:",
        ),
        (
            format!("Scene(dt: 0.01, bodies: [{BODY}], couplings: [Catenary(name: \"c\", end1: World((1, 0, 0)), end2: Body(body: \"b\"), mass_per_length: 1, length: -3, stiffness: 1e5)])"),
            "bad.ron:1:",
        ),
        (format!("Scene(dt: 1e400, bodies: [{BODY}])"), "bad.ron:1:"),
        ("Scene(dt: 0.01, bodies: [Body(name: \"b\", master: Node(position: (0, 0, 0), mass: 1.0), shape: Sphere(radius: 0.1))])".to_string(), "bad.ron:1:"),
    ];
    let expected_words = [
        "Expected opening `(` for struct `Scene`",
        "Expected float",
        "mass_kg",
        "overflow",
        "radius must be > 0",
        "rest_length must be ≥ 0",
        "length must be > 0",
        "finite",
        "not positive definite",
    ];
    for ((text, prefix), words) in cases.iter().zip(expected_words) {
        let error = error_of(text);
        assert!(error.starts_with(prefix), "{error}");
        assert!(error.contains(words), "{error} lacks {words:?}");
        assert_eq!(error.lines().count(), 1, "{error}");
    }
}

/// A run whose step count (duration ÷ dt × sub-steps) is past `--max-steps` is refused before
/// its first step, in one line naming the value that makes it long, with nothing written:
/// `floating_box` at dt = 1e-12 s for 0.5 s needs 5·10¹¹ steps; `spring_mass` for 2 s at its
/// own dt (10⁻³ s) needs 2,000, past a limit of 1,000 set by the flag, and runs under 2,000.
#[test]
fn a_run_past_the_step_limit_is_refused_before_it_starts() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("long.rrd");
    let scene = common::repo("scenes/floating_box.ron");
    let long = tether()
        .args(["record", scene.to_str().unwrap(), "-o", out.to_str().unwrap(), "--duration", "0.5", "--dt", "1e-12"])
        .output()
        .unwrap();
    assert_eq!(long.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&long.stderr);
    let error: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(error.len(), 1, "{stderr}");
    assert!(error[0].contains("the run needs 5.00e11 integrator steps, past the limit of 1e8"), "{stderr}");
    assert!(error[0].contains("the time step dt = 1.000e-12 s is"), "{stderr}");
    assert!(error[0].contains(" days at the speed of its first steps"), "{stderr}");
    assert!(!out.exists(), "nothing is written for a refused run");

    let spring = common::repo("scenes/spring_mass.ron");
    let record = |max_steps: &str| {
        tether()
            .args(["record", spring.to_str().unwrap(), "-o", out.to_str().unwrap(), "--duration", "2"])
            .args(["--max-steps", max_steps])
            .output()
            .unwrap()
    };
    let refused = record("1000");
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(stderr.contains("the run needs 2.00e3 integrator steps, past the limit of 1e3"), "{stderr}");
    assert!(stderr.contains("the duration 2 s at dt = 1.000e-3 s: shorten the duration"), "{stderr}");
    assert!(record("2000").status.success());
}
