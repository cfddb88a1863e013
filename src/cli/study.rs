//! `tether study SCENE`: every integrator at a ladder of time steps against a reference run, the
//! runs on every core (the sweep's runner); prints the table and writes `study.csv`, `study.md`
//! and the chart `study.png`.

use super::flags::{at_least_one, positive};
use anyhow::Context as _;
use clap::Args;
use std::num::NonZeroUsize;
use std::path::PathBuf;
use tether_analysis::runner::{Runner, all_cores};
use tether_analysis::study::{self, Plan, Reference};
use tether_physics::integrator::Integrator;

#[derive(Debug, Args)]
pub struct StudyArgs {
    /// Scene file (.ron).
    scene: PathBuf,
    /// Integrators to run, comma-separated (default: all).
    #[arg(long, value_delimiter = ',', value_parser = super::record::parse_integrator)]
    integrators: Vec<Integrator>,
    /// Time steps of the fixed-step integrators [s], comma-separated; each must divide the
    /// largest (default: the ladder).
    #[arg(long, value_delimiter = ',', conflicts_with_all = ["dt_ladder", "dt_max"])]
    dts: Vec<f64>,
    /// Number of time steps in the ladder, halving from --dt-max.
    #[arg(long, default_value_t = 5)]
    dt_ladder: u32,
    /// Largest time step of the ladder [s] (default: 4× the scene's dt).
    #[arg(long)]
    dt_max: Option<f64>,
    /// Relative tolerances of dopri45, comma-separated (its absolute tolerance is 1e-3 of each).
    #[arg(long, value_delimiter = ',', default_values_t = [1e-4, 1e-6, 1e-8, 1e-10])]
    tolerances: Vec<f64>,
    /// Simulated duration [s] (default: the scene's, rounded to the sample interval).
    #[arg(long)]
    duration: Option<f64>,
    /// Reference: `dopri45:RTOL`, `NAME:DT` (a fixed-step integrator at time step DT), or
    /// `closed-form` (the exact solution, for a scene that is a damped linear oscillator: one body
    /// free along one axis on one linear spring-damper to a world point). The default is accurate
    /// to about 1e-10 relative over tens of seconds of tumbling; a finer fixed-step reference
    /// gains nothing (its round-off grows with its steps).
    #[arg(long, default_value = "dopri45:1e-13", value_parser = parse_reference)]
    reference: Reference,
    /// Number of common sample times (errors are compared there; dopri45 ends a step on each).
    #[arg(long, default_value_t = 100)]
    samples: u32,
    /// Output directory (default: study-<scene name>).
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Runs measured at once (default: every core; each run's CPU time is its own thread's).
    #[arg(long)]
    jobs: Option<NonZeroUsize>,
    /// Study the scene's line models instead (PHYSICS.md §8): quasi-static and dynamic at
    /// N = 10, 20, 40, 80 against dynamic N = 160, by peak and minimum fairlead tension over the
    /// second half of the run and CPU per simulated second; writes `lines.md`.
    #[arg(long)]
    line_models: bool,
}

/// `dopri45:1e-12`, `rk4:1e-5` or `closed-form`.
fn parse_reference(text: &str) -> Result<Reference, String> {
    if text == "closed-form" {
        return Ok(Reference::ClosedForm);
    }
    let (name, value) = text
        .split_once(':')
        .ok_or_else(|| format!("expected closed-form or NAME:VALUE (e.g. dopri45:1e-12 or rk4:1e-5), got `{text}`"))?;
    let integrator = super::record::parse_integrator(name)?;
    let value: f64 = value.parse().map_err(|_| format!("`{value}` is not a number"))?;
    if !(value.is_finite() && value > 0.0) {
        return Err(format!("the reference's value must be positive, got {value}"));
    }
    Ok(if integrator.is_adaptive() {
        Reference::Adaptive { rtol: value }
    } else {
        Reference::Fixed { integrator, dt: value }
    })
}

pub fn run(args: &StudyArgs) -> anyhow::Result<()> {
    let scene = super::load(&args.scene)?;
    if args.line_models {
        return line_models(args, &scene);
    }
    let integrators = if args.integrators.is_empty() { Integrator::ALL.to_vec() } else { args.integrators.clone() };
    let dts = if args.dts.is_empty() {
        let largest = args.dt_max.unwrap_or(4.0 * scene.file.dt);
        positive("--dt-max", largest, "s")?;
        at_least_one("--dt-ladder", args.dt_ladder)?;
        (0..args.dt_ladder).map(|k| largest / f64::from(1u32 << k.min(30))).collect()
    } else {
        args.dts.clone()
    };
    // Sample at a multiple of the largest step, about --samples times.
    let largest = dts.iter().copied().fold(0.0_f64, f64::max).max(match args.reference {
        Reference::Fixed { dt, .. } => dt,
        Reference::Adaptive { .. } | Reference::ClosedForm => 0.0,
    });
    let wanted = args.duration.unwrap_or(scene.file.duration);
    positive("--duration", wanted, "s")?;
    let base = if largest > 0.0 { largest } else { scene.file.dt };
    at_least_one("--samples", args.samples)?;
    let sample_interval = base * (wanted / (f64::from(args.samples) * base)).round().max(1.0);
    let duration = sample_interval * (wanted / sample_interval).round().max(1.0);
    let plan = Plan {
        integrators,
        dts,
        tolerances: args.tolerances.clone(),
        duration,
        sample_interval,
        reference: args.reference,
    };
    let runner = Runner::new(args.jobs.unwrap_or_else(all_cores));
    let result = study::run_on(&runner, &scene, &plan, |line| eprintln!("{line}"))?;

    let stem = args.scene.file_stem().map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
    let directory = args.output.clone().unwrap_or_else(|| PathBuf::from(format!("study-{stem}")));
    std::fs::create_dir_all(&directory).with_context(|| format!("cannot create {}", directory.display()))?;
    let table = study::report::markdown(&result);
    for (name, text) in [("study.csv", study::report::csv(&result)), ("study.md", table.clone())] {
        let path = directory.join(name);
        std::fs::write(&path, text).with_context(|| format!("cannot write {}", path.display()))?;
    }
    study::chart::write(&result, &directory.join("study.png"))?;
    super::print(&format!("{table}\nwritten: {0}/study.csv, {0}/study.md, {0}/study.png\n", directory.display()))
}

/// `tether study SCENE --line-models`: the line-model study, printed and written to `lines.md`.
fn line_models(args: &StudyArgs, scene: &tether_scene::Scene) -> anyhow::Result<()> {
    let duration = args.duration.unwrap_or(scene.file.duration);
    positive("--duration", duration, "s")?;
    let runner = Runner::new(args.jobs.unwrap_or_else(all_cores));
    let result = study::lines::run(&runner, scene, duration, |line| eprintln!("{line}"))?;
    let stem = args.scene.file_stem().map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
    let directory = args.output.clone().unwrap_or_else(|| PathBuf::from(format!("study-{stem}")));
    std::fs::create_dir_all(&directory).with_context(|| format!("cannot create {}", directory.display()))?;
    let table = study::lines::markdown(&result);
    let path = directory.join("lines.md");
    std::fs::write(&path, &table).with_context(|| format!("cannot write {}", path.display()))?;
    super::print(&format!("{table}\nwritten: {}\n", path.display()))
}
