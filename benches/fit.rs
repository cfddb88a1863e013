//! What a fit costs, printed (A/B in one run; this machine is shared and noisy, so compare the
//! lines of one run, not runs of different days):
//!
//! 1. `chain_forced_surge` (60 s, N = 40) fitting C_dn and C_an to MoorDyn's fairlead tension
//!    record (`validation/calibration/`): wall time, iterations, runs (goal: under 5 s on this
//!    2-core machine);
//! 2. `moored_buoy` fitting three damping and drag parameters (surge and heave drag, a linear heave
//!    damper) to a 120 s heave and surge record made by Tether with other values (goal: under
//!    15 s);
//! 3. the parallel efficiency of the Jacobian's runs: a batch of 8 runs of the buoy's fit on one
//!    thread and on every core, twice, alternating — runs per second each way and
//!    `T₁ / (N · T_N)`.
//!
//! `cargo bench -p tether --bench fit`

use std::fmt::Write as _;
use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};
use std::time::Instant;
use tether_analysis::fit::run;
use tether_analysis::fit::setup::Setup;
use tether_analysis::runner::{Runner, all_cores};

fn repo(path: &str) -> PathBuf {
    std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join(path)
}

fn fit(spec: &Path, runner: &Runner) -> (Setup, run::Outcome, f64) {
    let setup = Setup::load(spec).unwrap_or_else(|e| panic!("{e}"));
    let start = Instant::now();
    let outcome = run::fit(&setup, runner, |_| {}).unwrap_or_else(|e| panic!("{e}"));
    (setup, outcome, start.elapsed().as_secs_f64())
}

fn describe(name: &str, setup: &Setup, outcome: &run::Outcome, wall: f64, goal: f64) {
    let values: Vec<String> = setup
        .model
        .parameters
        .iter()
        .zip(&outcome.parameters)
        .map(|(p, f)| {
            let interval = f.interval.map_or_else(|| "undetermined".into(), |(lo, hi)| format!("{lo:.4} … {hi:.4}"));
            format!("{} = {:.5} ({interval})", p.name, f.value)
        })
        .collect();
    println!(
        "{name}: {wall:.2} s wall (goal < {goal} s: {}), {} iterations, {} runs, {}",
        if wall < goal { "met" } else { "MISSED" },
        outcome.iterations.last().map_or(0, |i| i.iteration),
        outcome.runs,
        if outcome.partial() { "partial" } else { "converged" }
    );
    for value in values {
        println!("    {value}");
    }
}

/// The buoy's record: `moored_buoy` with surge drag 1.2, heave drag 1.6 and a linear heave damper
/// of 5e3 N·s/m (the scene: 0.8, 1.0 and none), its G's x and z every 0.1 s for 120 s.
fn buoy_record(dir: &Path) -> PathBuf {
    let scene = repo("scenes/moored_buoy.ron");
    let text = std::fs::read_to_string(&scene)
        .expect("the shipped scene")
        .replace("drag: (0.8, 0.8, 1.0),", "drag: (1.2, 0.8, 1.6), linear_damping: (0.0, 0.0, 5.0e3),");
    let mut world = tether_scene::parse(&text, &scene).unwrap_or_else(|e| panic!("{e}")).world;
    let mut csv = String::from("time_s,surge_m,heave_m\n");
    let every = (0.1 / world.dt()).round() as u64;
    let steps = (120.0 / world.dt()).round() as u64;
    for step in 0..=steps {
        if step > 0 {
            world.step().expect("the buoy runs");
        }
        if step % every == 0 {
            let p = world.state(0).position;
            let _ = writeln!(csv, "{:.3},{:.6},{:.6}", world.time(), p.x, p.z);
        }
    }
    std::fs::write(dir.join("buoy.csv"), csv).expect("a temporary file");
    let spec = dir.join("buoy.ron");
    std::fs::write(
        &spec,
        format!(
            r#"Fit(
    scene: "{}",
    record: "buoy.csv",
    signals: [
        Signal(column: "surge_m", of: Position("buoy", X)),
        Signal(column: "heave_m", of: Position("buoy", Z)),
    ],
    parameters: [
        Parameter(path: "bodies.buoy.hydro.drag.0", from: 0.2, to: 5.0, scale: Log),
        Parameter(path: "bodies.buoy.hydro.drag.2", from: 0.2, to: 5.0, scale: Log),
        Parameter(path: "bodies.buoy.hydro.linear_damping.2", from: 0.0, to: 5.0e4),
    ],
)"#,
            scene.display()
        ),
    )
    .expect("a temporary file");
    spec
}

fn main() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let all = Runner::new(all_cores());
    println!("fit benchmarks on {} threads", all.jobs());

    let chain = dir.path().join("chain.ron");
    std::fs::write(
        &chain,
        format!(
            r#"Fit(
    scene: "{}",
    record: "{}",
    window: Window(from: 10.0, to: 60.0),
    signals: [Signal(column: "fairlead_tension_N", of: EndTension("chain", End2))],
    parameters: [
        Parameter(path: "couplings.chain.model.drag_normal", from: 0.5, to: 5.0, scale: Log),
        Parameter(path: "couplings.chain.model.added_mass_normal", from: 0.2, to: 3.0, scale: Log),
    ],
)"#,
            repo("scenes/chain_forced_surge.ron").display(),
            repo("validation/calibration/moordyn_chain_cdn1.6.csv").display()
        ),
    )
    .expect("a temporary file");
    let (setup, outcome, wall) = fit(&chain, &all);
    describe(
        "chain_forced_surge, C_dn and C_an to MoorDyn's tension (C_dn 1.6, C_an 1.0)",
        &setup,
        &outcome,
        wall,
        5.0,
    );

    let buoy = buoy_record(dir.path());
    let (setup, outcome, wall) = fit(&buoy, &all);
    describe(
        "moored_buoy, surge and heave drag and heave damper to 120 s of heave and surge (1.2, 1.6, 5000)",
        &setup,
        &outcome,
        wall,
        15.0,
    );

    let one = Runner::new(NonZeroUsize::MIN);
    let start: Vec<f64> = setup.start();
    let batch: Vec<Vec<f64>> = (0..8)
        .map(|i| {
            start.iter().enumerate().map(|(j, v)| if j == i % start.len() { v * 1.01 + 1e-3 } else { *v }).collect()
        })
        .collect();
    let mut rates = [Vec::new(), Vec::new()];
    for _ in 0..2 {
        for (k, runner) in [&one, &all].into_iter().enumerate() {
            let timer = Instant::now();
            let (results, runs) = setup.model.evaluate(&batch, runner);
            assert!(results.iter().all(Result::is_ok));
            rates[k].push(runs as f64 / timer.elapsed().as_secs_f64());
        }
    }
    let best = |r: &[f64]| r.iter().copied().fold(0.0, f64::max);
    let (r1, rn) = (best(&rates[0]), best(&rates[1]));
    println!(
        "parallel efficiency of the Jacobian's runs (moored_buoy, 120 s each, batches of 8): {r1:.2} runs/s on 1 thread, {rn:.2} runs/s on {} threads: {:.0} % (T₁ / (N · T_N))",
        all.jobs(),
        100.0 * rn / (r1 * all.jobs().get() as f64)
    );
}
