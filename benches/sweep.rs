//! What a sweep costs beyond its simulations, measured A/B in one run (this machine is shared
//! and noisy: compare the lines of one run, not runs of different days):
//!
//! 1. parallel efficiency: 40 cases of the moored buoy (about 0.5 s of CPU each), run on one
//!    thread and on every core, twice, alternating: `T₁ / (N · T_N)` from the wall time of the
//!    running phase, and how busy the N threads were with simulations (CPU of the cases over
//!    N × wall), and — unaffected by whatever else the machine runs — the simulations' CPU time
//!    on N threads against one (do cases slow each other down?) and the share of the process's
//!    CPU time spent in them;
//! 2. overhead per case: 400 cases of ten steps each on one thread — the process's CPU time
//!    less the cases' simulation CPU time, per case (building and checking its scene, running
//!    the runner, writing its row);
//! 3. memory: the largest resident set while 1,000 and then 10,000 such cases run (results
//!    stream to disk, so it must not grow with the number of cases).
//!
//! `cargo bench -p tether --bench sweep`

use std::num::NonZeroUsize;
use std::path::Path;
use std::time::Duration;
use tether_analysis::runner::{Runner, all_cores};
use tether_analysis::sweep::{self, Options, Plan, Report};

/// Resident set size of this process now [bytes] (`/proc/self/statm`).
fn resident_bytes() -> u64 {
    let pages = std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|t| t.split_whitespace().nth(1).and_then(|p| p.parse::<u64>().ok()))
        .unwrap_or(0);
    // SAFETY: sysconf has no preconditions.
    pages * unsafe { libc::sysconf(libc::_SC_PAGESIZE) } as u64
}

/// Runs the spec at `spec` into a fresh `out` on `jobs` threads; also the largest resident set
/// seen as its cases finished.
fn run(spec: &Path, out: &Path, jobs: NonZeroUsize) -> (Report, u64) {
    let plan = Plan::load(spec, tether_analysis::sweep::design::DEFAULT_MAX_CASES).unwrap_or_else(|e| panic!("{e}"));
    let options = Options { runner: Runner::new(jobs), shard: None, resume: false, record: None };
    let mut largest = 0;
    let report =
        sweep::run(&plan, out, &options, |_| largest = largest.max(resident_bytes())).unwrap_or_else(|e| panic!("{e}"));
    (report, largest)
}

fn seconds(duration: Duration) -> f64 {
    duration.as_secs_f64()
}

fn main() {
    let dir = tempfile::tempdir().unwrap();
    let repo = std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    );
    let cores = all_cores();
    let one = NonZeroUsize::MIN;
    println!(
        "{} cores; load average {}",
        cores,
        std::fs::read_to_string("/proc/loadavg")
            .unwrap_or_default()
            .split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    );

    // 1. Parallel efficiency.
    let buoy = dir.path().join("buoy.ron");
    std::fs::write(
        &buoy,
        format!(
            r#"Sweep(scene: "{}", duration: 50.0, design: Grid, factors: [
                Factor(path: "dt", values: List([2e-4])),
                Factor(name: "line_stiffness", path: ["couplings.mooring1.stiffness", "couplings.mooring2.stiffness", "couplings.mooring3.stiffness"],
                       values: Log(from: 1e6, to: 1e7, count: 5)),
                Factor(path: "bodies.buoy.master.mass", values: Linear(from: 2000.0, to: 4000.0, count: 8)),
            ])"#,
            repo.join("scenes/moored_buoy.ron").display()
        ),
    )
    .unwrap();
    let mut efficiencies = Vec::new();
    for round in 1..=2 {
        let (serial, _) = run(&buoy, &dir.path().join(format!("serial-{round}")), one);
        let (parallel, _) = run(&buoy, &dir.path().join(format!("parallel-{round}")), cores);
        let (t1, tn) = (seconds(serial.running), seconds(parallel.running));
        let efficiency = t1 / (cores.get() as f64 * tn);
        let busy = parallel.case_cpu_seconds / (cores.get() as f64 * tn);
        println!(
            "parallel efficiency, round {round}: 40 cases of {:.2} s of CPU on average; T1 = {t1:.2} s, T{cores} = {tn:.2} s: T1/({cores}·T{cores}) = {efficiency:.3}; the {cores} threads {:.1} % busy with simulations",
            serial.case_cpu_seconds / 40.0,
            100.0 * busy
        );
        // Independent of the machine's other load: do cases slow each other down (memory
        // bandwidth, locks), and does the process spend its CPU on anything but them?
        println!(
            "  CPU of the simulations, {cores} threads against one: {:.3}; share of the process's CPU in simulations: {:.1} % (one thread), {:.1} % ({cores} threads)",
            parallel.case_cpu_seconds / serial.case_cpu_seconds,
            100.0 * serial.case_cpu_seconds / serial.process_cpu_seconds,
            100.0 * parallel.case_cpu_seconds / parallel.process_cpu_seconds
        );
        efficiencies.push(efficiency);
        let overhead = (serial.process_cpu_seconds - serial.case_cpu_seconds) / serial.ran as f64;
        println!(
            "  per-case CPU beyond the simulation (serial run, building the buoy with its catenaries): {:.2} ms",
            1e3 * overhead
        );
    }
    println!("parallel efficiency: {}", efficiencies.iter().map(|e| format!("{e:.3}")).collect::<Vec<_>>().join(", "));

    // 2. Overhead per case.
    std::fs::write(dir.path().join("spring.ron"), SPRING).unwrap();
    let tiny = |cases: usize, name: &str| {
        let spec = dir.path().join(format!("{name}.ron"));
        std::fs::write(&spec, format!(r#"Sweep(scene: "spring.ron", design: Grid, factors: [Factor(path: "couplings.spring.law.stiffness", values: Linear(from: 100.0, to: 200.0, count: {cases}))])"#)).unwrap();
        spec
    };
    let (report, _) = run(&tiny(400, "overhead"), &dir.path().join("overhead"), one);
    let per_case = |total: f64| 1e3 * total / report.ran as f64;
    println!(
        "overhead per case (400 cases of 10 steps, one thread): {:.3} ms of CPU beyond the simulation ({:.3} ms of simulation); wall {:.3} ms per case checking and running",
        per_case(report.process_cpu_seconds - report.case_cpu_seconds),
        per_case(report.case_cpu_seconds),
        per_case(seconds(report.checking + report.running))
    );

    // 3. Memory.
    for cases in [1_000, 10_000] {
        let (report, largest) =
            run(&tiny(cases, &format!("memory-{cases}")), &dir.path().join(format!("memory-{cases}")), cores);
        println!(
            "memory: {cases} cases on {cores} threads: largest resident set while they ran {:.1} MB ({:.2} s running)",
            largest as f64 / 1e6,
            seconds(report.running)
        );
    }
}

/// 1 kg on a 100 N/m spring, 1 ms steps, ten of them.
const SPRING: &str = r#"Scene(
    gravity: (0.0, 0.0, 0.0),
    dt: 0.001,
    duration: 0.01,
    bodies: [Body(name: "m", master: Node(position: (1.1, 0.0, 0.0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
        support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
    couplings: [SpringDamper(name: "spring", end1: World((0.0, 0.0, 0.0)), end2: Body(body: "m"),
        law: Linear(stiffness: 100.0, rest_length: 1.0), damping: 0.0)],
)
"#;
