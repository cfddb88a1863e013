//! The line-model study (PHYSICS.md §8): a scene's mooring lines run quasi-static and dynamic at
//! N = 10, 20, 40, 80 segments, each against the dynamic lines at N = 160, measured by what a
//! mooring engineer sizes a line on — the peak and the minimum tension at each line's end 2 (the
//! fairlead) over the second half of the run, once the start-up has passed — and by the CPU
//! seconds per simulated second. The runs are cases of the sweep's engine ([`crate::runner`]).
//!
//! A line the scene declares quasi-static takes, when dynamic, a wire's coefficients and ζ = 0.8
//! (as the window's switch does); a line the scene declares dynamic keeps its own, with its
//! segment count replaced.

use crate::runner::{Runner, thread_cpu_seconds};
use tether_physics::world::World;
use tether_scene::file::CouplingDef;
use tether_scene::line_model::LineModelDef;
use tether_scene::{Scene, SceneError};

/// Segment counts of the dynamic runs, and of the reference.
pub const SEGMENTS: [u32; 4] = [10, 20, 40, 80];
pub const REFERENCE_SEGMENTS: u32 = 160;

/// How the lines of one run are modelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineSetting {
    QuasiStatic,
    Dynamic(u32),
}

impl std::fmt::Display for LineSetting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::QuasiStatic => f.write_str("quasi-static"),
            Self::Dynamic(n) => write!(f, "dynamic N = {n}"),
        }
    }
}

/// The fairlead tension of one line in one run over the second half \[N].
#[derive(Debug, Clone, PartialEq)]
pub struct LineTensions {
    pub line: String,
    pub peak: f64,
    pub minimum: f64,
}

/// One run: its setting, each line's tensions, its cost.
#[derive(Debug, Clone, PartialEq)]
pub struct LineRun {
    pub setting: LineSetting,
    pub lines: Vec<LineTensions>,
    /// CPU seconds per simulated second.
    pub cpu_per_second: f64,
}

/// The study: each run and the reference.
#[derive(Debug, Clone, PartialEq)]
pub struct LineStudy {
    pub scene: String,
    pub duration: f64,
    pub reference: LineRun,
    pub runs: Vec<LineRun>,
}

/// Why the study could not be made.
#[derive(Debug, thiserror::Error)]
pub enum LineStudyError {
    #[error("the scene has no catenary line to study")]
    NoLines,
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error("{setting}: {message}")]
    Run { setting: LineSetting, message: String },
}

/// Runs `scene`'s lines in every model for `duration` \[s] on `runner`; `progress` hears one
/// line per finished run.
///
/// # Errors
/// A scene without lines, a model the scene cannot be rebuilt with, a run that diverges.
pub fn run(
    runner: &Runner,
    scene: &Scene,
    duration: f64,
    mut progress: impl FnMut(&str),
) -> Result<LineStudy, LineStudyError> {
    if !scene.file.couplings.iter().any(|c| matches!(c, CouplingDef::Catenary { .. })) {
        return Err(LineStudyError::NoLines);
    }
    let settings: Vec<LineSetting> = std::iter::once(LineSetting::Dynamic(REFERENCE_SEGMENTS))
        .chain(std::iter::once(LineSetting::QuasiStatic))
        .chain(SEGMENTS.iter().map(|&n| LineSetting::Dynamic(n)))
        .collect();
    let mut runs: Vec<Option<LineRun>> = vec![None; settings.len()];
    runner.run(
        settings.iter().copied().enumerate(),
        |&(_, setting), _watch| measure(scene, setting, duration),
        |(index, _), result| {
            let run = result?;
            progress(&format!("{}: {:.4} s of CPU per simulated second", run.setting, run.cpu_per_second));
            runs[index] = Some(run);
            Ok::<(), LineStudyError>(())
        },
    )?;
    let mut runs = runs.into_iter().flatten();
    let reference = runs.next().ok_or(LineStudyError::NoLines)?;
    let scene_name =
        scene.path.file_name().map_or_else(|| scene.path.display().to_string(), |n| n.to_string_lossy().into_owned());
    Ok(LineStudy { scene: scene_name, duration, reference, runs: runs.collect() })
}

/// One run of `scene` with its lines as `setting` says, for `duration` \[s].
fn measure(scene: &Scene, setting: LineSetting, duration: f64) -> Result<LineRun, LineStudyError> {
    let mut file = scene.file.clone();
    for coupling in &mut file.couplings {
        if let CouplingDef::Catenary { model, .. } = coupling {
            *model = modelled(*model, setting);
        }
    }
    let variant = tether_scene::build_variant(&scene.text, &scene.path, file)?;
    let mut world = variant.world;
    let lines: Vec<(usize, String)> = world
        .couplings()
        .iter()
        .enumerate()
        .filter(|(_, c)| c.kind_name() == "catenary")
        .map(|(i, c)| (i, c.name.clone()))
        .collect();
    let mut extremes = vec![(0.0_f64, f64::INFINITY); lines.len()];
    let start = thread_cpu_seconds();
    let failed = |error: tether_physics::world::StepError| LineStudyError::Run { setting, message: error.to_string() };
    while world.time() < duration - 0.5 * world.dt() {
        world.step().map_err(failed)?;
        if world.time() >= 0.5 * duration {
            record_extremes(&world, &lines, &mut extremes);
        }
    }
    let cpu = thread_cpu_seconds() - start;
    Ok(LineRun {
        setting,
        lines: lines
            .iter()
            .zip(&extremes)
            .map(|((_, name), &(peak, minimum))| LineTensions { line: name.clone(), peak, minimum })
            .collect(),
        cpu_per_second: cpu / world.time(),
    })
}

/// Each line's end-2 tension widens its `(peak, minimum)`.
fn record_extremes(world: &World, lines: &[(usize, String)], extremes: &mut [(f64, f64)]) {
    for ((index, _), (peak, minimum)) in lines.iter().zip(extremes.iter_mut()) {
        let tension = world.coupling_forces()[*index].f2.norm();
        *peak = peak.max(tension);
        *minimum = minimum.min(tension);
    }
}

/// The model of a line declared `declared`, as `setting` runs it.
fn modelled(declared: LineModelDef, setting: LineSetting) -> LineModelDef {
    match setting {
        LineSetting::QuasiStatic => LineModelDef::QuasiStatic,
        LineSetting::Dynamic(n) => declared.dynamic_with(n),
    }
}

/// The study as a Markdown table: per run and line, the peak and minimum fairlead tension
/// \[kN], their errors against the reference [%], and the CPU per simulated second.
pub fn markdown(study: &LineStudy) -> String {
    let mut out = format!(
        "Line models of `{}` over {} s (peak and minimum fairlead tension over the second half; reference: dynamic N = {REFERENCE_SEGMENTS})\n\n\
         | model | line | peak [kN] | peak error | minimum [kN] | minimum error | CPU s per simulated s |\n|---|---|---|---|---|---|---|\n",
        study.scene, study.duration
    );
    for run in std::iter::once(&study.reference).chain(&study.runs) {
        for (tensions, reference) in run.lines.iter().zip(&study.reference.lines) {
            let error = |value: f64, of: f64| format!("{:+.2} %", 100.0 * (value / of - 1.0));
            out.push_str(&format!(
                "| {} | {} | {:.2} | {} | {:.2} | {} | {:.4} |\n",
                run.setting,
                tensions.line,
                tensions.peak / 1e3,
                error(tensions.peak, reference.peak),
                tensions.minimum / 1e3,
                error(tensions.minimum, reference.minimum),
                run.cpu_per_second
            ));
        }
    }
    out
}
