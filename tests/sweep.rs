//! `tether sweep`: metrics against closed forms, the designs' cases, the same rows bit for bit
//! serial, parallel and sharded, a killed run resumed, failing cases as rows, recordings per
//! case, and every bad input refused in one line with nothing overwritten.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use tether_analysis::runner::Runner;
use tether_analysis::sweep::design::DEFAULT_MAX_CASES;
use tether_analysis::sweep::spec::Level;
use tether_analysis::sweep::{self, Options, Plan};

/// An undamped oscillator along x (body "m", 1 kg, spring "spring" to the origin, rest length
/// 1 m, released at rest at x = 1.1 m), leapfrog at dt = 0.1 ms, for three periods of the
/// k = 100 N/m spring (ω = 10 rad/s).
fn oscillator(damping: f64, duration: f64) -> String {
    format!(
        r#"Scene(
    gravity: (0.0, 0.0, 0.0),
    dt: 1e-4,
    duration: {duration:e},
    bodies: [Body(name: "m", master: Node(position: (1.1, 0.0, 0.0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
        support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
    couplings: [SpringDamper(name: "spring", end1: World((0.0, 0.0, 0.0)), end2: Body(body: "m"),
        law: Linear(stiffness: 100.0, rest_length: 1.0), damping: {damping:e})],
)
"#
    )
}

/// Three periods of ω = 10 rad/s [s].
const THREE_PERIODS: f64 = 3.0 * std::f64::consts::TAU / 10.0;

/// A folder with `oscillator.ron` and the spec `sweep.ron` (its scene: `oscillator.ron`).
fn folder(scene: &str, spec: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("oscillator.ron"), scene).unwrap();
    std::fs::write(dir.path().join("sweep.ron"), spec).unwrap();
    dir
}

fn tether(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tether")).args(args).current_dir(dir).output().unwrap()
}

/// Runs `args` in `dir`, which must succeed.
fn tether_ok(args: &[&str], dir: &Path) -> String {
    let out = tether(args, dir);
    assert!(out.status.success(), "tether {args:?} failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The one-line error of `args` in `dir`, which must fail with exit code 1.
fn tether_error(args: &[&str], dir: &Path) -> String {
    let out = tether(args, dir);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "tether {args:?} should fail: {stderr}");
    let lines: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error: ")).collect();
    assert_eq!(lines.len(), 1, "one error line: {stderr}");
    lines[0].trim_start_matches("error: ").to_string()
}

/// A results table: the header and the rows, as text.
fn table(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let mut reader = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let header = reader.headers().unwrap().iter().map(String::from).collect();
    let rows = reader.records().map(|r| r.unwrap().iter().map(String::from).collect()).collect();
    (header, rows)
}

/// The table without its `cpu_s` column (a measurement, the one column two runs differ in).
fn without_cpu(path: &Path) -> Vec<Vec<String>> {
    let (header, rows) = table(path);
    let cpu = header.iter().position(|h| h == "cpu_s").unwrap();
    std::iter::once(header)
        .chain(rows)
        .map(|mut row| {
            row.remove(cpu);
            row
        })
        .collect()
}

/// The value of column `name` in `row`.
fn cell(header: &[String], row: &[String], name: &str) -> f64 {
    let at = header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name} in {header:?}"));
    row[at].parse().unwrap_or_else(|_| panic!("{name} = `{}`", row[at]))
}

fn plan(dir: &Path) -> Plan {
    Plan::load(&dir.join("sweep.ron"), DEFAULT_MAX_CASES).unwrap_or_else(|e| panic!("{e}"))
}

fn runner(jobs: usize) -> Runner {
    Runner::new(std::num::NonZeroUsize::new(jobs).unwrap())
}

/// Runs the sweep in `dir` into `dir/out` as a library call.
fn run(dir: &Path, jobs: usize) -> PathBuf {
    let out = dir.join("out");
    let options = Options { runner: runner(jobs), shard: None, resume: false, record: None };
    let report = sweep::run(&plan(dir), &out, &options, |_| {}).unwrap_or_else(|e| panic!("{e}"));
    assert!(report.written.is_some(), "a whole sweep writes its results");
    out
}

/// The standard and declared metrics of an undamped oscillator x = x0 + A cos ωt, over three
/// periods of the slower spring: tension k(x − x0) from +kA to −kA (mean 0, rms kA/√2); the
/// body's excursion from its start and its range both 2A; speed ωA; kinetic energy ½kA²;
/// nothing rotates; the energy balance holds.
#[test]
fn metrics_of_an_undamped_oscillator_match_the_closed_form() {
    let spec = r#"Sweep(
        scene: "oscillator.ron",
        design: Grid,
        factors: [
            Factor(path: "couplings.spring.law.stiffness", values: List([100.0, 400.0])),
            Factor(path: "bodies.m.master.position.0", values: List([1.1, 1.2])),
        ],
        metrics: [
            Metric(name: "tension_rms", of: Tension("spring"), take: Rms),
            Metric(name: "tension_mean", of: Tension("spring"), take: Mean),
            Metric(name: "x_range", of: Position("m", X), take: Range),
            Metric(name: "speed_max", of: Speed("m"), take: Max),
            Metric(name: "kinetic_max_late", of: Energy(Kinetic), take: Max, after: 1.0),
            Metric(name: "length_final", of: Length("spring"), take: Final),
        ],
    )"#;
    let dir = folder(&oscillator(0.0, THREE_PERIODS), spec);
    let out = run(dir.path(), 2);
    let (header, rows) = table(&out.join("results.csv"));
    assert_eq!(rows.len(), 4);
    for (row, (k, x)) in rows.iter().zip([(100.0, 1.1), (100.0, 1.2), (400.0, 1.1), (400.0, 1.2)]) {
        let amplitude: f64 = x - 1.0;
        let omega = f64::sqrt(k);
        let value = |name: &str| cell(&header, row, name);
        let near = |name: &str, expected: f64, tolerance: f64| {
            let got = value(name);
            assert!(
                (got - expected).abs() <= tolerance * expected.abs().max(k * amplitude),
                "k = {k}, x = {x}: {name} = {got}, expected {expected}"
            );
        };
        assert_eq!((value("couplings.spring.law.stiffness"), value("bodies.m.master.position.0")), (k, x));
        assert_eq!(row[header.iter().position(|h| h == "status").unwrap()], "ok");
        // Sampled at steps of ω dt ≤ 2e-3 rad, the leapfrog's turning points and amplitude
        // are off by O((ω dt)²) ≈ 4e-6 relative: 1e-4 is 25× that.
        near("spring.tension_max_N", k * amplitude, 1e-4);
        near("spring.tension_min_N", -k * amplitude, 1e-4);
        near("m.excursion_max_m", 2.0 * amplitude, 1e-4);
        near("x_range", 2.0 * amplitude, 1e-4);
        near("speed_max", omega * amplitude, 1e-4);
        near("kinetic_max_late", 0.5 * k * amplitude * amplitude, 2e-4);
        // Whole periods (3 or 6) up to 4e-5 s, and the end sample counted with the start:
        // the mean is off zero by 1e-3 kA at most, the rms off kA/√2 by 1e-3 of it.
        near("tension_rms", k * amplitude / 2f64.sqrt(), 1e-3);
        assert!(value("tension_mean").abs() < 1e-3 * k * amplitude, "mean {}", value("tension_mean"));
        // Three periods later the body is back at its start, within (ω·4e-5 s)² A.
        near("length_final", x, 1e-6);
        assert_eq!(value("m.rotation_max_rad"), 0.0, "held against rotation");
        // The leapfrog keeps the energy balance to O((ω dt)²).
        assert!(value("energy_error") < 1e-5, "energy error {}", value("energy_error"));
        // Undamped, it never settles: the band is left again in the last period.
        assert!(
            value("settle_time_s") > THREE_PERIODS - std::f64::consts::TAU / omega,
            "settle {}",
            value("settle_time_s")
        );
        assert_eq!(value("steps"), (THREE_PERIODS / 1e-4).round());
    }
}

/// A damped oscillator (ζ = 0.1, ω = 10 rad/s) released at A: |x − x0| ≤ A e^{−ζωt}/√(1−ζ²),
/// which enters the 2 % band at t = (ln 50 − ½ ln(1/(1−ζ²)))/(ζω) = 3.907 s; the last peak
/// outside it comes less than half a damped period (0.316 s) earlier.
#[test]
fn settle_time_is_where_the_envelope_enters_the_band() {
    let spec = r#"Sweep(scene: "oscillator.ron", design: Grid, factors: [Factor(path: "couplings.spring.damping", values: List([2.0]))])"#;
    let dir = folder(&oscillator(2.0, 8.0), spec);
    let out = run(dir.path(), 1);
    let (header, rows) = table(&out.join("results.csv"));
    let settle = cell(&header, &rows[0], "settle_time_s");
    // Positions are kept every ⌈80000 / 2048⌉ = 40 steps: 4 ms of resolution.
    assert!((3.907 - 0.316 - 0.004..=3.907 + 0.004).contains(&settle), "settle time {settle} s");
}

/// A grid runs every combination, the last factor fastest; one at a time goes around the base;
/// a Latin hypercube puts one case in each stratum of each factor, the same for the same seed.
#[test]
fn designs_make_the_cases_they_promise() {
    let scene = oscillator(0.0, 0.01);
    let factors = r#"factors: [
            Factor(path: "couplings.spring.law.stiffness", values: List([50.0, 100.0, 200.0])),
            Factor(path: "couplings.spring.damping", values: List([0.0, 1.0])),
            Factor(path: "integrator", values: List(["leapfrog", "rk4"])),
        ]"#;
    let values = |design: &str| {
        let dir = folder(&scene, &format!("Sweep(scene: \"oscillator.ron\", design: {design}, {factors})"));
        let plan = plan(dir.path());
        (0..plan.cases.len()).map(|c| plan.values(c)).collect::<Vec<_>>()
    };
    let (n, t) = (Level::Number, |s: &str| Level::Text(s.into()));
    let grid = values("Grid");
    assert_eq!(grid.len(), 12);
    assert_eq!(grid[0], [n(50.0), n(0.0), t("leapfrog")]);
    assert_eq!(grid[1], [n(50.0), n(0.0), t("rk4")]);
    assert_eq!(grid[2], [n(50.0), n(1.0), t("leapfrog")]);
    assert_eq!(grid[11], [n(200.0), n(1.0), t("rk4")]);
    // Base: k = 100, damping 0, leapfrog; then k = 50, 200; damping 1; rk4.
    let around = values("OneAtATime");
    assert_eq!(
        around,
        [
            vec![n(100.0), n(0.0), t("leapfrog")],
            vec![n(50.0), n(0.0), t("leapfrog")],
            vec![n(200.0), n(0.0), t("leapfrog")],
            vec![n(100.0), n(1.0), t("leapfrog")],
            vec![n(100.0), n(0.0), t("rk4")],
        ]
    );
    let ranges = r#"factors: [
            Factor(path: "couplings.spring.law.stiffness", values: LogUniform(from: 10.0, to: 1000.0)),
            Factor(path: "couplings.spring.damping", values: Uniform(from: 0.0, to: 2.0)),
            Factor(path: "integrator", values: List(["leapfrog", "rk4"])),
        ]"#;
    let latin = |seed: u64| {
        let dir = folder(
            &scene,
            &format!("Sweep(scene: \"oscillator.ron\", design: LatinHypercube(samples: 20, seed: {seed}), {ranges})"),
        );
        let plan = plan(dir.path());
        (0..plan.cases.len()).map(|c| plan.values(c)).collect::<Vec<_>>()
    };
    let cases = latin(7);
    assert_eq!(cases.len(), 20);
    let mut strata = [[0; 20]; 2];
    for case in &cases {
        let (k, c) = (case[0].number().unwrap(), case[1].number().unwrap());
        // Stratum of each factor: 20 equal slices of log10 k ∈ [1, 3] and of c ∈ [0, 2].
        strata[0][((k.log10() - 1.0) / 2.0 * 20.0) as usize] += 1;
        strata[1][(c / 2.0 * 20.0) as usize] += 1;
    }
    assert_eq!(strata, [[1; 20]; 2], "one case per stratum of each factor");
    let rk4 = cases.iter().filter(|c| c[2] == t("rk4")).count();
    assert_eq!(rk4, 10, "a list of two levels is two strata of ten");
    assert_eq!(latin(7), cases, "the same seed draws the same cases");
    assert_ne!(latin(8), cases, "another seed draws others");
}

/// The spec of the reproducibility, sharding and resume tests: nine cases of the oscillator,
/// three integrators × three stiffnesses, 0.3 s each.
fn nine_cases() -> tempfile::TempDir {
    let spec = r#"Sweep(
        scene: "oscillator.ron",
        duration: 0.3,
        design: Grid,
        factors: [
            Factor(path: "integrator", values: List(["leapfrog", "rk4", "dopri45"])),
            Factor(path: "couplings.spring.law.stiffness", values: Log(from: 100.0, to: 10000.0, count: 3)),
        ],
    )"#;
    folder(&oscillator(0.5, 1.0), spec)
}

/// One thread, two threads, three shards merged: the same rows, bit for bit (but `cpu_s`).
#[test]
fn serial_parallel_and_sharded_runs_give_the_same_rows() {
    let dir = nine_cases();
    let here = dir.path();
    tether_ok(&["sweep", "sweep.ron", "-o", "serial", "--jobs", "1"], here);
    tether_ok(&["sweep", "sweep.ron", "-o", "parallel", "--jobs", "2"], here);
    for shard in ["0/3", "1/3", "2/3"] {
        let printed = tether_ok(&["sweep", "sweep.ron", "-o", "sharded", "--shard", shard], here);
        assert!(printed.contains("tether sweep merge sharded"), "{printed}");
    }
    assert!(!here.join("sharded/results.csv").exists(), "shards leave the results to the merge");
    let merged = tether_ok(&["sweep", "merge", "sharded"], here);
    assert!(merged.contains("9 ok"), "{merged}");
    let serial = without_cpu(&here.join("serial/results.csv"));
    assert_eq!(serial.len(), 10);
    assert_eq!(without_cpu(&here.join("parallel/results.csv")), serial);
    assert_eq!(without_cpu(&here.join("sharded/results.csv")), serial);
    let (_, shard) = table(&here.join("sharded/runs/shard-1-of-3.csv"));
    let cases: Vec<&str> = shard.iter().map(|r| r[0].as_str()).collect();
    assert_eq!(cases.len(), 3);
    assert!(cases.iter().all(|c| c.parse::<usize>().unwrap() % 3 == 1), "{cases:?}");
    // The summaries agree but for the CPU time.
    let summary = |name: &str| {
        std::fs::read_to_string(here.join(name).join("summary.md"))
            .unwrap()
            .lines()
            .filter(|l| !l.contains("CPU time"))
            .map(String::from)
            .collect::<Vec<_>>()
    };
    assert_eq!(summary("sharded"), summary("serial"));
}

/// Shards started at the same moment into one new directory, as a Slurm array's tasks are: each
/// runs its cases, whichever creates the directory, and the merge has every row. Before the
/// store wrote its manifest ahead of its runs folder (and looked for it again when it found the
/// directory not empty), and read a run file without a whole line as empty, a shard could find
/// the folder without the manifest ("not empty and holds no sweep") or another shard's file
/// before its header ("its columns are not this sweep's"): 5 of 160 such starts failed, so that
/// these 160 all pass by chance with a probability under 1 %.
#[test]
fn shards_started_together_all_run() {
    let dir = nine_cases();
    let here = dir.path();
    for round in 0..20 {
        let out = format!("together-{round}");
        let shards: Vec<_> = (0..8)
            .map(|k| {
                Command::new(env!("CARGO_BIN_EXE_tether"))
                    .args(["sweep", "sweep.ron", "-o", &out, "--shard", &format!("{k}/8")])
                    .current_dir(here)
                    .stdout(std::process::Stdio::null())
                    .stderr(std::process::Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        for (k, shard) in shards.into_iter().enumerate() {
            let done = shard.wait_with_output().unwrap();
            assert!(done.status.success(), "round {round}, shard {k}/8: {}", String::from_utf8_lossy(&done.stderr));
        }
        let merged = tether_ok(&["sweep", "merge", &out], here);
        assert!(merged.contains("9 ok"), "round {round}: {merged}");
    }
}

/// `results.parquet` holds the rows of `results.csv`: the same numbers, typed, nulls where a
/// failed case has no value.
#[test]
fn parquet_holds_the_rows_of_the_csv() {
    use arrow_array::{Array as _, Float64Array, StringArray, UInt64Array};
    let dir = nine_cases();
    let out = run(dir.path(), 2);
    let (header, rows) = table(&out.join("results.csv"));
    let file = std::fs::File::open(out.join("results.parquet")).unwrap();
    let reader = parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder::try_new(file).unwrap().build().unwrap();
    let batches: Vec<_> = reader.map(Result::unwrap).collect();
    assert_eq!(batches.iter().map(|b| b.num_rows()).sum::<usize>(), rows.len());
    let batch = &batches[0];
    let names: Vec<String> = batch.schema().fields().iter().map(|f| f.name().clone()).collect();
    assert_eq!(names, header);
    let column = |name: &str| batch.column_by_name(name).unwrap().clone();
    let cases = column("case");
    let cases = cases.as_any().downcast_ref::<UInt64Array>().unwrap();
    let integrators = column("integrator");
    let integrators = integrators.as_any().downcast_ref::<StringArray>().unwrap();
    let tension = column("spring.tension_max_N");
    let tension = tension.as_any().downcast_ref::<Float64Array>().unwrap();
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(cases.value(i).to_string(), row[0]);
        assert_eq!(integrators.value(i), row[1]);
        assert_eq!(tension.value(i).to_bits(), cell(&header, row, "spring.tension_max_N").to_bits());
    }
    let unit = batch.schema().field_with_name("spring.tension_max_N").unwrap().metadata().get("unit").cloned();
    assert_eq!(unit.as_deref(), Some("N"));
    assert_eq!(tension.null_count(), 0);
}

/// Twelve cases of 20 s at dt = 0.1 ms, 200,000 steps each (about 20 ms of CPU or more): a
/// sweep long enough to be stopped midway.
fn twelve_long_cases() -> tempfile::TempDir {
    let spec = r#"Sweep(
        scene: "oscillator.ron",
        duration: 20.0,
        design: Grid,
        factors: [Factor(path: "couplings.spring.law.stiffness", values: Linear(from: 100.0, to: 200.0, count: 12))],
    )"#;
    folder(&oscillator(0.5, 1.0), spec)
}

/// Waits until the sweep `child` has written `rows` rows (and its header) to `rows_file`, and
/// fails if it ends first or writes none for a minute.
fn wait_for_rows(rows_file: &Path, rows: usize, child: &mut std::process::Child) {
    let start = std::time::Instant::now();
    while std::fs::read_to_string(rows_file).map_or(0, |t| t.lines().count()) < rows + 1 {
        assert!(start.elapsed().as_secs() < 60, "no rows after a minute");
        assert!(child.try_wait().unwrap().is_none(), "the sweep ended before it could be stopped");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
}

/// A run killed with SIGKILL mid-sweep keeps every row it wrote whole; `--resume` runs only the
/// cases without one, and the results are those of a run never killed. Without `--resume`, the
/// directory is refused and nothing in it changes.
#[test]
fn a_killed_sweep_resumes_where_it_stopped() {
    let dir = twelve_long_cases();
    let here = dir.path();
    let mut child = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["sweep", "sweep.ron", "-o", "out", "--jobs", "1"])
        .current_dir(here)
        .spawn()
        .unwrap();
    let rows_file = here.join("out/runs/all.csv");
    wait_for_rows(&rows_file, 3, &mut child);
    child.kill().unwrap();
    child.wait().unwrap();
    let (_, kept) = table(&rows_file);
    assert!((3..12).contains(&kept.len()), "{} rows kept", kept.len());
    assert!(!here.join("out/results.csv").exists());
    let before = std::fs::read(&rows_file).unwrap();
    let refused = tether_error(&["sweep", "sweep.ron", "-o", "out"], here);
    assert!(
        refused.contains(&format!("already holds rows for {} of this sweep's 12 cases: pass --resume", kept.len())),
        "{refused}"
    );
    assert_eq!(std::fs::read(&rows_file).unwrap(), before, "nothing overwritten");
    let resumed = tether_ok(&["sweep", "sweep.ron", "-o", "out", "--resume"], here);
    assert!(
        resumed.contains(&format!("ran {} of 12 cases ({} had a row already)", 12 - kept.len(), kept.len())),
        "{resumed}"
    );
    tether_ok(&["sweep", "sweep.ron", "-o", "fresh"], here);
    assert_eq!(without_cpu(&here.join("out/results.csv")), without_cpu(&here.join("fresh/results.csv")));
}

/// Sends `signal` to `child` and waits for it to end; returns its output and how long it took
/// to end after the signal.
fn signal_and_wait(child: std::process::Child, signal: libc::c_int) -> (Output, std::time::Duration) {
    let sent = std::time::Instant::now();
    // SAFETY: signalling the child this test started.
    unsafe { libc::kill(child.id() as libc::pid_t, signal) };
    let out = child.wait_with_output().unwrap();
    (out, sent.elapsed())
}

/// Ctrl-C (SIGINT) and SIGTERM stop the cases in flight within a second (each checks between
/// steps) and keep the rows written: exit code 130, and `--resume` finishes the sweep.
#[test]
fn ctrl_c_and_sigterm_keep_the_rows_written_and_resume_finishes() {
    for signal in [libc::SIGINT, libc::SIGTERM] {
        stop_a_run_with(signal);
    }
}

fn stop_a_run_with(signal: libc::c_int) {
    let dir = twelve_long_cases();
    let here = dir.path();
    let mut child = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["sweep", "sweep.ron", "-o", "out", "--jobs", "2"])
        .current_dir(here)
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let rows_file = here.join("out/runs/all.csv");
    wait_for_rows(&rows_file, 2, &mut child);
    let (out, took) = signal_and_wait(child, signal);
    assert_eq!(out.status.code(), Some(130), "signal {signal}");
    assert!(took.as_secs_f64() < 1.0, "signal {signal}: the sweep took {took:?} to stop");
    assert!(
        String::from_utf8_lossy(&out.stdout)
            .contains("interrupted: the finished cases are kept; run again with --resume"),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let (_, kept) = table(&rows_file);
    assert!((2..12).contains(&kept.len()), "{} rows kept", kept.len());
    let resumed = tether_ok(&["sweep", "sweep.ron", "-o", "out", "--resume"], here);
    assert!(resumed.contains(&format!("ran {} of 12 cases", 12 - kept.len())), "{resumed}");
    let (_, rows) = table(&here.join("out/results.csv"));
    assert_eq!(rows.len(), 12);
}

/// SIGTERM while a large sweep's cases are being checked (a million values of a factor, each
/// built into the base scene: minutes of work) stops it within a second: exit code 130, the
/// stage named, nothing run and nothing written.
#[test]
fn sigterm_stops_the_checking_of_a_large_sweep_within_a_second() {
    use std::io::BufRead as _;
    let spec = r#"Sweep(scene: "oscillator.ron", duration: 0.01, design: Grid, factors: [
        Factor(path: "couplings.spring.law.stiffness", values: Linear(from: 100.0, to: 200.0, count: 1000000)),
    ])"#;
    let dir = folder(&oscillator(0.0, 0.01), spec);
    let mut child = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["sweep", "sweep.ron", "-o", "out"])
        .current_dir(dir.path())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // The first line comes once the plan is made, as its checking starts.
    let mut stderr = std::io::BufReader::new(child.stderr.take().unwrap());
    let mut first = String::new();
    stderr.read_line(&mut first).unwrap();
    assert!(first.starts_with("sweep sweep: 1000000 cases (full grid)"), "{first}");
    std::thread::sleep(std::time::Duration::from_millis(300));
    assert!(child.try_wait().unwrap().is_none(), "a million values are not checked in 0.3 s");
    let (out, took) = signal_and_wait(child, libc::SIGTERM);
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut stderr, &mut rest).unwrap();
    assert_eq!(out.status.code(), Some(130), "{rest}");
    assert!(took.as_secs_f64() < 1.0, "the checking took {took:?} to stop");
    assert_eq!(rest.trim(), "interrupted while the cases were being checked; nothing was run");
    assert!(!dir.path().join("out").exists(), "nothing written");
}

/// Every stage stops at a cancelled runner and keeps what it had: checking the factors' values
/// and the cases runs nothing; a merge writes no results and leaves no draft behind, and the
/// rows are untouched for the next merge.
#[test]
fn every_stage_stops_at_a_cancelled_runner() {
    use std::sync::Arc;
    use std::sync::atomic::AtomicBool;
    use tether_analysis::sweep::{Stage, SweepError};
    let dir = nine_cases();
    let plan = plan(dir.path());
    let cancelled = runner(2).with_cancel(Arc::new(AtomicBool::new(true)));
    let stage = |result: Result<_, SweepError>| match result {
        Err(SweepError::Interrupted(stage)) => stage,
        other => panic!("{:?}", other.map(drop)),
    };
    assert_eq!(stage(plan.check_factors(&cancelled)), Stage::Checking);
    assert_eq!(stage(plan.check_cases(&cancelled, 0..plan.cases.len())), Stage::Checking);
    let here = dir.path();
    tether_ok(&["sweep", "sweep.ron", "-o", "out", "--shard", "0/1"], here);
    let rows = std::fs::read(here.join("out/runs/shard-0-of-1.csv")).unwrap();
    assert_eq!(stage(sweep::merge(&here.join("out"), &cancelled).map(drop)), Stage::Writing);
    let left: Vec<String> =
        std::fs::read_dir(here.join("out")).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    assert!(
        !left.iter().any(|name| name.starts_with("results") || name.ends_with(".tmp") || name == "summary.md"),
        "{left:?}"
    );
    assert_eq!(std::fs::read(here.join("out/runs/shard-0-of-1.csv")).unwrap(), rows, "the rows are kept");
    let merged = sweep::merge(&here.join("out"), &runner(2)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(merged.statuses, "9 ok");
    assert_eq!(table(&here.join("out/results.csv")).1.len(), 9);
}

/// A sweep past the case limit (1,000,000, or `--max-cases N`) is refused at once — counted,
/// never made — in one line with its size and the flag that raises the limit; nothing written.
#[test]
fn a_sweep_past_the_case_limit_is_refused_at_once_with_its_size() {
    let scene = oscillator(0.0, 0.01);
    let refused = |spec: &str, extra: &[&str]| {
        let dir = folder(&scene, spec);
        let mut args = vec!["sweep", "sweep.ron", "-o", "out"];
        args.extend(extra);
        let start = std::time::Instant::now();
        let message = tether_error(&args, dir.path());
        let took = start.elapsed();
        assert!(took.as_secs_f64() < 1.0, "refused after {took:?}: {message}");
        assert!(!dir.path().join("out").exists(), "nothing written for: {message}");
        message
    };
    let grid = |factors: &str| format!("Sweep(scene: \"oscillator.ron\", design: Grid, factors: [\n  {factors}\n])");
    // The new user's mistyped count: 100 million levels, 3.2 GB of them had they been made.
    assert_eq!(
        refused(&grid(r#"Factor(path: "dt", values: Linear(from: 1e-4, to: 1e-3, count: 100000000))"#), &[]),
        "sweep.ron:2:22: factor `dt`: 100000000 levels, more than the limit of 1000000 cases a sweep may have: ask for fewer, or raise the limit with --max-cases 100000000"
    );
    let thousand = |path: &str| format!(r#"Factor(path: "{path}", values: Linear(from: 1.0, to: 2.0, count: 1000))"#);
    let cube = [thousand("couplings.spring.law.stiffness"), thousand("couplings.spring.damping"), thousand("dt")];
    assert_eq!(
        refused(&grid(&cube.join(",\n  ")), &[]),
        "sweep.ron:1:32: the grid (1000 × 1000 × 1000 levels) has 1000000000 cases, more than the limit of 1000000: ask for fewer, or raise the limit with --max-cases 1000000000"
    );
    assert_eq!(
        refused(
            r#"Sweep(scene: "oscillator.ron", design: LatinHypercube(samples: 4000000000, seed: 1), factors: [Factor(path: "dt", values: Uniform(from: 1e-4, to: 1e-3))])"#,
            &[]
        ),
        "sweep.ron:1:32: the Latin hypercube has 4000000000 cases, more than the limit of 1000000: ask for fewer, or raise the limit with --max-cases 4000000000"
    );
    // Nine cases: refused under a limit of 8, run under one of 9.
    let dir = nine_cases();
    assert_eq!(
        refused(&std::fs::read_to_string(dir.path().join("sweep.ron")).unwrap(), &["--max-cases", "8"]),
        "sweep.ron:4:9: the grid (3 × 3 levels) has 9 cases, more than the limit of 8: ask for fewer, or raise the limit with --max-cases 9"
    );
    let printed = tether_ok(&["sweep", "sweep.ron", "-o", "out", "--max-cases", "9"], dir.path());
    assert!(printed.contains("ran 9 of 9 cases: 9 ok"), "{printed}");
}

/// A torn last line (a machine that went down mid-write) is cut off on resume, and its case
/// run again.
#[test]
fn a_torn_last_row_is_cut_off_and_run_again() {
    let dir = nine_cases();
    let here = dir.path();
    tether_ok(&["sweep", "sweep.ron", "-o", "out"], here);
    let rows_file = here.join("out/runs/all.csv");
    let text = std::fs::read_to_string(&rows_file).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    // Header, six whole rows, and half of the seventh.
    let torn = format!("{}\n{}", lines[..7].join("\n"), &lines[7][..lines[7].len() / 2]);
    std::fs::write(&rows_file, torn).unwrap();
    std::fs::remove_file(here.join("out/results.csv")).unwrap();
    let resumed = tether_ok(&["sweep", "sweep.ron", "-o", "out", "--resume"], here);
    assert!(resumed.contains("ran 3 of 9 cases (6 had a row already)"), "{resumed}");
    let (_, rows) = table(&rows_file);
    assert_eq!(rows.len(), 9);
    tether_ok(&["sweep", "sweep.ron", "-o", "fresh"], here);
    assert_eq!(without_cpu(&here.join("out/results.csv")), without_cpu(&here.join("fresh/results.csv")));
}

/// A case that blows up, one that runs past its time limit and ones that run well are each a
/// row with its status; the failures have no metrics and are listed in the summary; the sweep
/// ends normally.
#[test]
fn failing_cases_are_rows_and_the_sweep_goes_on() {
    // The leapfrog's limit for k = 100 N/m, m = 1 kg is 2/ω = 0.2 s: dt = 0.5 s diverges;
    // dt = 1e-8 s would take 10⁸ steps, stopped by the 1 s limit.
    let spec = r#"Sweep(
        scene: "oscillator.ron",
        duration: 1.0,
        design: Grid,
        factors: [Factor(path: "dt", values: List([1e-3, 0.5, 1e-8]))],
    )"#;
    let dir = folder(&oscillator(0.0, 1.0), spec);
    let here = dir.path();
    let printed = tether_ok(&["sweep", "sweep.ron", "-o", "out", "--case-timeout", "1"], here);
    assert!(printed.contains("ran 3 of 3 cases: 1 ok, 1 diverged, 1 timed_out"), "{printed}");
    let (header, rows) = table(&here.join("out/results.csv"));
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let statuses: Vec<&str> = rows.iter().map(|r| r[column("status")].as_str()).collect();
    assert_eq!(statuses, ["ok", "diverged", "timed_out"]);
    assert!(rows[1][column("message")].starts_with("the simulation diverged at t = "), "{:?}", rows[1]);
    assert!(rows[2][column("message")].starts_with("stopped by the case time limit at t = "), "{:?}", rows[2]);
    let end = cell(&header, &rows[2], "end_time_s");
    // About a million steps a second: the limit stops it near 0.01 s of the 1 s asked for.
    assert!(end > 0.0 && end < 0.5, "a 1 s limit reaches {end} s of simulated time at 1e-8 s steps");
    for row in &rows[1..] {
        assert_eq!(row[column("spring.tension_max_N")], "", "no metrics for a failed case");
        assert_eq!(row[column("energy_error")], "");
    }
    assert!(cell(&header, &rows[0], "spring.tension_max_N") > 9.99);
    let summary = std::fs::read_to_string(here.join("out/summary.md")).unwrap();
    assert!(
        summary.contains("**Cases:** 3 — 1 ok, 1 diverged, 1 timed_out.")
            && summary.contains("| 1 | dt = 0.5 | diverged | the simulation diverged"),
        "{summary}"
    );
}

/// With `--record`, each case's recording: application id the sweep's name, recording id the
/// case's, complete (`rerun rrd verify`).
#[test]
fn recordings_carry_the_sweep_and_the_case() {
    let dir = nine_cases();
    let here = dir.path();
    tether_ok(&["sweep", "sweep.ron", "-o", "out", "--record", "--log-hz", "30"], here);
    for case in 0..9 {
        let path = here.join(format!("out/recordings/case-{case}.rrd"));
        let mut file = std::fs::File::open(&path).unwrap();
        let stores =
            rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
        let ids: Vec<(String, String)> = stores
            .keys()
            .map(|id| (id.application_id().as_str().to_string(), id.recording_id().as_str().to_string()))
            .collect();
        assert_eq!(ids, [("sweep".to_string(), format!("case-{case}"))]);
    }
    let verify = Command::new("rerun")
        .args(["rrd", "verify"])
        .arg(here.join("out/recordings/case-4.rrd"))
        .output()
        .expect("the `rerun` CLI (pip install rerun-sdk==0.36.3)");
    assert!(verify.status.success(), "{}", String::from_utf8_lossy(&verify.stderr));
}

/// Paths reach every part of a scene: the time step settings, an optional section the scene
/// leaves out, a list item by name through its enum, a contact of a mesh body (the mesh found
/// from the base scene's folder).
#[test]
fn factor_paths_reach_every_part_of_a_scene() {
    let dir = tempfile::tempdir().unwrap();
    let fender = common::repo("scenes/fender.ron");
    let text = std::fs::read_to_string(&fender).unwrap();
    let contact = text.split("Contact(").nth(1).and_then(|rest| rest.split('"').nth(1)).unwrap().to_string();
    let spec = format!(
        r#"Sweep(scene: "{}", duration: 0.01, design: OneAtATime, factors: [
            Factor(path: "couplings.{contact}.stiffness", values: List([1e7])),
            Factor(path: "substeps", values: List([2])),
        ])"#,
        fender.display()
    );
    std::fs::write(dir.path().join("sweep.ron"), spec).unwrap();
    let plan = plan(dir.path());
    assert_eq!(plan.cases.len(), 3);
    let file = plan.scene_file(&plan.values(1)).unwrap();
    let stiffness = file.couplings.iter().find_map(|c| match c {
        tether_scene::file::CouplingDef::Contact { name, stiffness, .. } if *name == contact => Some(*stiffness),
        _ => None,
    });
    assert_eq!(stiffness, Some(1e7));
    assert_eq!(plan.scene_file(&plan.values(2)).unwrap().substeps, tether_physics::integrator::Substeps::Fixed(2));
    plan.scene(&plan.values(2)).unwrap();

    let rtol = folder(
        &oscillator(0.0, 0.01),
        r#"Sweep(scene: "oscillator.ron", design: Grid, factors: [
        Factor(path: "adaptive.rtol", values: Log(from: 1e-8, to: 1e-4, count: 2)),
        Factor(path: "integrator", values: List(["dopri45"])),
    ])"#,
    );
    let plan = self::plan(rtol.path());
    let file = plan.scene_file(&plan.values(0)).unwrap();
    assert_eq!(file.adaptive.map(|a| a.rtol), Some(1e-8));
    assert_eq!(file.adaptive.map(|a| a.atol), Some(1e-9), "the rest of the section from its defaults");
    assert_eq!(plan.scene(&plan.values(1)).unwrap().world.tolerances().rtol(), 1e-4);
}

/// The specs shipped in `examples/sweeps/` load and check against their scenes.
#[test]
fn shipped_specs_load() {
    let folder = common::repo("examples/sweeps");
    let specs: Vec<PathBuf> = std::fs::read_dir(&folder)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "ron"))
        .collect();
    assert!(!specs.is_empty());
    for spec in specs {
        let plan = Plan::load(&spec, DEFAULT_MAX_CASES).unwrap_or_else(|e| panic!("{e}"));
        plan.check_factors(&runner(2)).unwrap_or_else(|e| panic!("{e}"));
        plan.check_cases(&runner(2), 0..plan.cases.len()).unwrap_or_else(|e| panic!("{e}"));
    }
}

/// Each bad input is one line naming what is wrong (the spec's `path:line:col`, the factor, the
/// case), exit code 1 or clap's 2, and nothing written or overwritten.
#[test]
fn bad_input_is_one_line_and_overwrites_nothing() {
    let scene = oscillator(0.0, 0.01);
    let error = |spec: &str, extra: &[&str]| {
        let dir = folder(&scene, spec);
        let mut args = vec!["sweep", "sweep.ron", "-o", "out"];
        args.extend(extra);
        let message = tether_error(&args, dir.path());
        assert!(!dir.path().join("out").exists(), "nothing written for: {message}");
        message
    };
    let grid = |factors: &str| {
        format!("Sweep(\n  scene: \"oscillator.ron\",\n  design: Grid,\n  factors: [\n    {factors}\n  ],\n)")
    };
    assert_eq!(
        error(
            "Sweep(scene: \"oscillator.ron\", design: Grid, factors: [Factor(path: \"dt\", values: List([1e-3])]",
            &[]
        ),
        "sweep.ron:1:95: Expected comma"
    );
    assert_eq!(
        error(&grid(r#"Factor(path: "couplings.sprung.damping", values: List([1.0]))"#), &[]),
        "sweep.ron:5:18: factor `couplings.sprung.damping`: `couplings` has no item named \"sprung\" (it has: spring)"
    );
    assert_eq!(
        error(&grid(r#"Factor(path: "water.waves.height", values: List([1.0]))"#), &[]),
        "sweep.ron:5:18: factor `water.waves.height`: the scene has no `water` (it has: adaptive, bodies, couplings, dt, duration, gravity, integrator, substeps)"
    );
    assert_eq!(
        error(&grid(r#"Factor(path: "couplings.spring.law.stiffness", values: List([100.0, -5.0]))"#), &[]),
        "sweep.ron:5:52: factor `couplings.spring.law.stiffness` = -5: oscillator.ron:8:21: coupling \"spring\": stiffness must be ≥ 0 N/m, got -5"
    );
    assert_eq!(
        error(&grid(r#"Factor(path: "integrator", values: List(["euler"]))"#), &[]),
        "sweep.ron:5:32: factor `integrator` = euler: unknown variant `euler`, expected one of `leapfrog`, `leapfrog2`, `splitting`, `rk4`, `dopri45`"
    );
    assert_eq!(
        error(&grid(r#"Factor(path: "dt", values: List([]))"#), &[]),
        "sweep.ron:5:24: factor `dt`: the list of values is empty"
    );
    assert_eq!(
        error("Sweep(scene: \"oscillator.ron\", design: Grid, factors: [])", &[]),
        "sweep.ron:1:32: the sweep has no factor: the design is empty"
    );
    assert_eq!(
        error(&grid(r#"Factor(path: "dt", values: Uniform(from: 1e-4, to: 1e-3))"#), &[]),
        "sweep.ron:3:3: factor `dt` is a range (uniform from 1e-4 to 0.001), which only a Latin hypercube samples: give a grid levels (List, Linear or Log)"
    );
    let metric = "Sweep(scene: \"oscillator.ron\", design: Grid, factors: [Factor(path: \"dt\", values: List([1e-3]))],\n  metrics: [Metric(name: \"heave\", of: Position(\"buoy\", Z), take: Max)])";
    assert_eq!(error(metric, &[]), "sweep.ron:2:26: metric \"heave\": the scene has no body \"buoy\" (bodies: m)");
    // Each value alone is fine; together the force curve's x would not increase.
    let curve = oscillator(0.0, 0.01)
        .replace("Linear(stiffness: 100.0, rest_length: 1.0)", "ForceCurve(points: [(0.9, -10.0), (1.1, 10.0)])");
    let dir = folder(
        &curve,
        &grid(
            r#"Factor(path: "couplings.spring.law.points.0.0", values: List([0.9, 1.05])),
    Factor(path: "couplings.spring.law.points.1.0", values: List([1.1, 1.0]))"#,
        ),
    );
    let message = tether_error(&["sweep", "sweep.ron", "-o", "out"], dir.path());
    assert!(
        message.starts_with(
            "case 3 (couplings.spring.law.points.0.0 = 1.05, couplings.spring.law.points.1.0 = 1): oscillator.ron:"
        ),
        "{message}"
    );
    assert!(!dir.path().join("out").exists());
    // Shards: out of range, and Slurm without an array.
    let dir = folder(&scene, &grid(r#"Factor(path: "dt", values: List([1e-3, 2e-3]))"#));
    let out = tether(&["sweep", "sweep.ron", "-o", "out", "--shard", "4/4"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("shard index 4 is out of range for 4 shards (0 to 3)"));
    let out = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["sweep", "sweep.ron", "-o", "out", "--shard", "auto"])
        .env("SLURM_JOB_ID", "41")
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&out.stderr).starts_with("error: --shard auto: Slurm job 41 is not a job array"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!dir.path().join("out").exists());
    // Directories: another sweep's, a folder of other files, a merge of an unfinished sweep.
    tether_ok(&["sweep", "sweep.ron", "-o", "out"], dir.path());
    let results = std::fs::read(dir.path().join("out/results.csv")).unwrap();
    std::fs::write(dir.path().join("other.ron"), grid(r#"Factor(path: "dt", values: List([5e-4]))"#)).unwrap();
    let message = tether_error(&["sweep", "other.ron", "-o", "out", "--resume"], dir.path());
    assert!(message.starts_with("out holds another sweep's results (its spec is not this one; spec "), "{message}");
    assert_eq!(std::fs::read(dir.path().join("out/results.csv")).unwrap(), results, "nothing overwritten");
    std::fs::create_dir(dir.path().join("notes")).unwrap();
    std::fs::write(dir.path().join("notes/todo.txt"), "x").unwrap();
    assert_eq!(
        tether_error(&["sweep", "sweep.ron", "-o", "notes"], dir.path()),
        "notes is not empty and holds no sweep: choose a new or empty directory"
    );
    tether_ok(&["sweep", "sweep.ron", "-o", "half", "--shard", "0/2"], dir.path());
    let message = tether_error(&["sweep", "merge", "half"], dir.path());
    assert!(
        message.starts_with("half: 1 of 2 cases have no row yet (cases 1): wait for the shards still running"),
        "{message}"
    );
    assert!(tether_error(&["sweep", "merge", "notes"], dir.path()).starts_with("notes holds no sweep (no sweep.json)"));
}
