//! The accuracy-versus-speed study: a scene run with each integrator at a ladder of time steps
//! (tolerances for the adaptive `dopri45`), each run measured against a reference solution.
//!
//! Every run is sampled at common times `k·Δs` (Δs a multiple of every time step, so no run is
//! interpolated). Against the reference, at each sample: the position error, the largest
//! `|x_G − x_G,ref|` over the bodies \[m], and the orientation error, the largest angle of
//! `q_ref⁻¹ q` \[rad]; reported at the end and as the maximum over time. The energy-balance error
//! is the largest `|B(t) − B(0)|` (`B = total + dissipated − external work`, PHYSICS.md §5)
//! over the samples, relative to the energy budget: the largest kinetic + elastic energy of the
//! reference run. The cost is the thread's CPU time per simulated second, and the integrator
//! steps taken (rejected ones included for `dopri45`). A run that diverges is reported as such.
//! The runs are cases of the engine `tether sweep` runs on ([`crate::runner`]): independent,
//! on every core, each timed by its own thread's CPU clock.
//!
//! The reference is a run of a fine integrator or, where the scene is a damped linear
//! oscillator, its [`closed_form`].
//!
//! [`report`] writes the CSV and Markdown tables, [`chart`] the work-precision chart; [`lines`]
//! is the study of a scene's line models (quasi-static against dynamic at N segments).

pub mod chart;
pub mod closed_form;
pub mod lines;
pub mod report;

use crate::runner::{Runner, thread_cpu_seconds};
use tether_physics::integrator::{Integrator, Substeps};
use tether_physics::math::Vec3;
use tether_physics::world::{StepError, World};
use tether_scene::file::AdaptiveDef;
use tether_scene::{Scene, SceneError};

/// What a study runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Plan {
    pub integrators: Vec<Integrator>,
    /// Time steps of the fixed-step schemes \[s], each dividing `sample_interval`.
    pub dts: Vec<f64>,
    /// Relative tolerances of `dopri45` (its absolute tolerance is 1e-3 of each).
    pub tolerances: Vec<f64>,
    /// Simulated duration \[s], a multiple of `sample_interval`.
    pub duration: f64,
    /// Δs \[s]: the runs are compared at its multiples.
    pub sample_interval: f64,
    pub reference: Reference,
}

/// The solution the runs are measured against.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Reference {
    /// `dopri45` at relative tolerance `rtol` (absolute 1e-3 of it).
    Adaptive { rtol: f64 },
    /// A fixed-step scheme at time step `dt` \[s] (dividing the sample interval).
    Fixed { integrator: Integrator, dt: f64 },
    /// The exact solution of a scene that is a damped linear oscillator ([`closed_form`]).
    ClosedForm,
}

impl Reference {
    /// `dopri45 at rtol 1e-12`, `rk4 at dt 1e-5 s` or `the closed form`.
    pub fn describe(&self) -> String {
        match self {
            Self::Adaptive { rtol } => format!("dopri45 at rtol {rtol:e}"),
            Self::Fixed { integrator, dt } => format!("{} at dt {dt:e} s", integrator.name()),
            Self::ClosedForm => "the closed form of the damped oscillator".into(),
        }
    }
}

/// The step setting of one run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Setting {
    /// Fixed time step \[s].
    Step(f64),
    /// `dopri45`'s relative tolerance.
    Tolerance(f64),
}

/// What one run measured.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measures {
    /// Position error at the end and its maximum over time \[m].
    pub position_error_end: f64,
    pub position_error_max: f64,
    /// Orientation error at the end and its maximum over time \[rad].
    pub orientation_error_end: f64,
    pub orientation_error_max: f64,
    /// Largest energy-balance drift over the energy budget [–].
    pub energy_error: f64,
    /// Thread CPU seconds per simulated second.
    pub cpu_per_second: f64,
    /// Integrator steps accepted, and rejected (`dopri45`).
    pub steps: u64,
    pub rejected: u64,
}

/// How one run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    Finished(Measures),
    /// The run stopped at `time` \[s] with `message`.
    Failed {
        time: f64,
        message: String,
    },
}

/// One integrator at one setting.
#[derive(Debug, Clone, PartialEq)]
pub struct Run {
    pub integrator: Integrator,
    pub setting: Setting,
    pub outcome: Outcome,
}

/// A finished study.
#[derive(Debug, Clone, PartialEq)]
pub struct Study {
    /// The scene's file name.
    pub scene: String,
    pub duration: f64,
    pub sample_interval: f64,
    pub reference: Reference,
    /// The energy budget \[J] the energy errors are relative to.
    pub energy_budget: f64,
    /// Whether any body of the reference run moved its G (otherwise positions carry no error
    /// and the chart shows orientation errors).
    pub translates: bool,
    pub runs: Vec<Run>,
}

/// Why a study could not be made.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// A setting that does not fit the study.
    #[error("{0}")]
    Plan(String),
    /// The scene cannot be rebuilt with a run's settings.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The reference run failed: no run can be measured.
    #[error("the reference run ({reference}) failed: {source}")]
    Reference { reference: String, source: StepError },
    /// Writing the tables or the chart.
    #[error("{path}: {message}")]
    Output { path: String, message: String },
}

/// Whether `step` \[s] divides `interval` \[s] to round-off.
pub fn divides(step: f64, interval: f64) -> bool {
    let ratio = interval / step;
    step > 0.0 && ratio >= 1.0 - 1e-9 && (ratio - ratio.round()).abs() <= 1e-6 * ratio
}

impl Plan {
    /// Checks that every step and the duration fit the sample interval.
    ///
    /// # Errors
    /// [`StudyError::Plan`] naming the setting at fault.
    pub fn check(&self) -> Result<(), StudyError> {
        let positive = |name: &str, value: f64| {
            if value.is_finite() && value > 0.0 {
                Ok(())
            } else {
                Err(StudyError::Plan(format!("{name} must be a positive number, got {value}")))
            }
        };
        positive("the duration", self.duration)?;
        positive("the sample interval", self.sample_interval)?;
        if self.integrators.is_empty() {
            return Err(StudyError::Plan("no integrator to study".into()));
        }
        for &dt in &self.dts {
            positive("a time step", dt)?;
            if !divides(dt, self.sample_interval) {
                return Err(StudyError::Plan(format!(
                    "the time step {dt:e} s does not divide the sample interval {:e} s: the runs could not be compared at common times",
                    self.sample_interval
                )));
            }
        }
        if self.dts.is_empty() && self.integrators.iter().any(|i| !i.is_adaptive()) {
            return Err(StudyError::Plan("no time step for the fixed-step integrators".into()));
        }
        for &rtol in &self.tolerances {
            if !(rtol > 0.0 && rtol < 1.0) {
                return Err(StudyError::Plan(format!("a tolerance must be > 0 and < 1, got {rtol}")));
            }
        }
        if self.tolerances.is_empty() && self.integrators.contains(&Integrator::Dopri45) {
            return Err(StudyError::Plan("no tolerance for dopri45".into()));
        }
        match self.reference {
            Reference::Adaptive { rtol } if !(rtol > 0.0 && rtol < 1.0) => {
                Err(StudyError::Plan(format!("the reference tolerance must be > 0 and < 1, got {rtol}")))
            }
            Reference::Fixed { dt, .. } if !divides(dt, self.sample_interval) => Err(StudyError::Plan(format!(
                "the reference time step {dt:e} s does not divide the sample interval {:e} s",
                self.sample_interval
            ))),
            _ if !divides(self.sample_interval, self.duration) => Err(StudyError::Plan(format!(
                "the duration {} s is not a multiple of the sample interval {:e} s",
                self.duration, self.sample_interval
            ))),
            _ => Ok(()),
        }
    }
}

/// One run's samples: per sample time, each body's G and orientation, and the energy balance.
struct Samples {
    poses: Vec<Vec<(Vec3, tether_physics::math::Rotation)>>,
    balances: Vec<f64>,
    /// Largest kinetic + elastic energy [J] over the samples.
    peak_energy: f64,
    cpu_seconds: f64,
}

/// Runs the study on every core; `progress` hears one line per run as it finishes.
///
/// # Errors
/// A plan that does not fit ([`Plan::check`]), a scene that cannot be built with a run's
/// settings, or a reference run that fails.
pub fn run(scene: &Scene, plan: &Plan, progress: impl FnMut(&str)) -> Result<Study, StudyError> {
    run_on(&Runner::on_all_cores(), scene, plan, progress)
}

/// Runs the study on `runner`, the engine of many cases `tether sweep` runs on: the reference
/// first, then every integrator at every setting as a case of its own; `progress` hears one
/// line per run as it finishes (in the order they finish), the runs are kept in plan order.
///
/// # Errors
/// As [`run`].
pub fn run_on(
    runner: &Runner,
    scene: &Scene,
    plan: &Plan,
    mut progress: impl FnMut(&str),
) -> Result<Study, StudyError> {
    plan.check()?;
    let samples = (plan.duration / plan.sample_interval).round() as usize;
    let reference = reference_samples(scene, plan, samples)?;
    progress(&format!("reference ({}) done in {:.2} s of CPU", plan.reference.describe(), reference.cpu_seconds));
    let energy_budget = if reference.peak_energy > 0.0 { reference.peak_energy } else { 1.0 };
    let start = &reference.poses[0];
    let translates =
        reference.poses.iter().any(|poses| poses.iter().zip(start).any(|(a, b)| (a.0 - b.0).norm() > 1e-12));
    let settings: Vec<(Integrator, Setting)> = plan
        .integrators
        .iter()
        .flat_map(|&integrator| {
            let settings: Vec<Setting> = if integrator.is_adaptive() {
                plan.tolerances.iter().map(|&r| Setting::Tolerance(r)).collect()
            } else {
                plan.dts.iter().map(|&dt| Setting::Step(dt)).collect()
            };
            settings.into_iter().map(move |setting| (integrator, setting))
        })
        .collect();
    let mut runs: Vec<Option<Run>> = vec![None; settings.len()];
    let measured =
        |&(integrator, setting): &(Integrator, Setting), _: &crate::runner::Watch<'_>| -> Result<Run, StudyError> {
            let mut world = match setting {
                Setting::Step(dt) => world(scene, integrator, dt, None)?,
                Setting::Tolerance(rtol) => world(scene, integrator, plan.sample_interval, Some(rtol))?,
            };
            let outcome = match sample(&mut world, plan.sample_interval, samples) {
                Err(error) => Outcome::Failed { time: error_time(&error), message: error.to_string() },
                Ok(run) => Outcome::Finished(measure(&run, &reference, energy_budget, plan.duration, &world)),
            };
            Ok(Run { integrator, setting, outcome })
        };
    let numbered = settings.iter().copied().enumerate();
    runner.run(
        numbered,
        |(_, setting), watch| measured(setting, watch),
        |(index, _), result| {
            let run = result?;
            progress(&report::describe(&run));
            runs[index] = Some(run);
            Ok::<(), StudyError>(())
        },
    )?;
    let scene_name =
        scene.path.file_name().map_or_else(|| scene.path.display().to_string(), |n| n.to_string_lossy().into_owned());
    Ok(Study {
        scene: scene_name,
        duration: plan.duration,
        sample_interval: plan.sample_interval,
        reference: plan.reference,
        energy_budget,
        translates,
        runs: runs.into_iter().flatten().collect(),
    })
}

/// The reference's samples: a run of the reference integrator, or the closed form at the
/// sample times.
///
/// # Errors
/// A scene that the closed form does not describe, or a reference run that fails.
fn reference_samples(scene: &Scene, plan: &Plan, samples: usize) -> Result<Samples, StudyError> {
    let mut reference_world = match plan.reference {
        Reference::Adaptive { rtol } => world(scene, Integrator::Dopri45, plan.sample_interval, Some(rtol))?,
        Reference::Fixed { integrator, dt } => world(scene, integrator, dt, None)?,
        Reference::ClosedForm => {
            let oscillator = closed_form::Oscillator::of_scene(scene)
                .map_err(|why| StudyError::Plan(format!("the scene has no closed form: {why}")))?;
            return Ok(exact_samples(&oscillator, plan.sample_interval, samples));
        }
    };
    sample(&mut reference_world, plan.sample_interval, samples)
        .map_err(|source| StudyError::Reference { reference: plan.reference.describe(), source })
}

/// The closed form at `samples` sample intervals `interval` [s] (t = 0 included): the motion
/// keeps its energy balance exactly.
fn exact_samples(oscillator: &closed_form::Oscillator, interval: f64, samples: usize) -> Samples {
    let states: Vec<closed_form::Exact> = (0..=samples).map(|k| oscillator.at(k as f64 * interval)).collect();
    Samples {
        poses: states.iter().map(|s| vec![(s.position, s.orientation)]).collect(),
        balances: vec![0.0; samples + 1],
        peak_energy: states.iter().map(|s| s.kinetic + s.elastic).fold(0.0, f64::max),
        cpu_seconds: 0.0,
    }
}

/// The scene's world with `integrator` at world step `dt` [s], one sub-step, and (dopri45)
/// relative tolerance `rtol`, absolute 1e-3 of it, no maximum step but the world step.
fn world(scene: &Scene, integrator: Integrator, dt: f64, rtol: Option<f64>) -> Result<World, StudyError> {
    let mut file = scene.file.clone();
    file.dt = dt;
    file.integrator = integrator;
    file.substeps = Substeps::Fixed(1);
    if let Some(rtol) = rtol {
        file.adaptive = Some(AdaptiveDef { rtol, atol: 1e-3 * rtol, max_step: None });
    }
    Ok(tether_scene::world_with_timing(scene, &file)?)
}

/// When a failed step happened [s].
fn error_time(error: &StepError) -> f64 {
    match error {
        StepError::Coupling { time, .. } | StepError::Diverged { time, .. } => *time,
    }
}

/// Runs `world` to `samples` sample intervals, recording every sample (t = 0 included).
fn sample(world: &mut World, interval: f64, samples: usize) -> Result<Samples, StepError> {
    let record = |w: &World, out: &mut Samples| {
        out.poses.push(
            (0..w.bodies().len())
                .map(|i| {
                    let s = w.state(i);
                    (s.position, s.orientation)
                })
                .collect(),
        );
        let energy = w.energy();
        out.balances.push(energy.balance());
        out.peak_energy = out.peak_energy.max(energy.kinetic + energy.elastic.abs());
    };
    let mut out = Samples {
        poses: Vec::with_capacity(samples + 1),
        balances: Vec::with_capacity(samples + 1),
        peak_energy: 0.0,
        cpu_seconds: 0.0,
    };
    record(world, &mut out);
    let dt = world.dt();
    let start = thread_cpu_seconds();
    for k in 1..=samples {
        let target = k as f64 * interval;
        // Ends: each step moves the clock on by dt > 0 (the world refuses any other).
        while world.time() < target - 0.5 * dt {
            world.step()?;
        }
        record(world, &mut out);
    }
    out.cpu_seconds = thread_cpu_seconds() - start;
    Ok(out)
}

/// A run's measures against the reference, for the run's `finished` world.
fn measure(run: &Samples, reference: &Samples, budget: f64, duration: f64, finished: &World) -> Measures {
    let largest = |values: &mut dyn Iterator<Item = f64>| values.fold(0.0_f64, f64::max);
    let errors: Vec<(f64, f64)> = run
        .poses
        .iter()
        .zip(&reference.poses)
        .map(|(poses, exact)| {
            let position = largest(&mut poses.iter().zip(exact).map(|(a, b)| (a.0 - b.0).norm()));
            let orientation = largest(&mut poses.iter().zip(exact).map(|(a, b)| (b.1.inverse() * a.1).angle()));
            (position, orientation)
        })
        .collect();
    let (end_position, end_orientation) = errors.last().copied().unwrap_or_default();
    let start = run.balances.first().copied().unwrap_or_default();
    Measures {
        position_error_end: end_position,
        position_error_max: largest(&mut errors.iter().map(|e| e.0)),
        orientation_error_end: end_orientation,
        orientation_error_max: largest(&mut errors.iter().map(|e| e.1)),
        energy_error: largest(&mut run.balances.iter().map(|b| (b - start).abs())) / budget,
        cpu_per_second: run.cpu_seconds / duration,
        steps: finished.integrator_steps(),
        rejected: finished.rejected_steps(),
    }
}
