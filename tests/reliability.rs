//! Bad input, divergence and interrupted recordings (README "When things go wrong"; PHYSICS.md §5 "Health check").

mod common;

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
            if chunk.entity_path().to_string() == "/plots/energy" {
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
