//! One case: its world (the base scene with the case's values, built by the scene loader) run
//! for its duration under the runner's [`Watch`], measured after every world step and, with
//! `--record`, recorded. A case that diverges, whose coupling refuses to give its forces, or that
//! runs past its time limit ends with that status and a message; the sweep goes on.

use super::metrics::{Metric, Observer};
use crate::runner::{Stop, Watch, thread_cpu_seconds};
use serde::{Deserialize, Serialize};
use std::path::PathBuf;
use tether_physics::world::{StepError, World};
use tether_record::{FrameSchedule, Recorder};

/// The watch is asked every this many world steps (a clock read costs about as much as a tenth
/// of the cheapest scene's step).
const WATCH_EVERY: u64 = 16;

/// How a case ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// It ran to its end; its metrics are in the row.
    Ok,
    /// The health check stopped it (PHYSICS.md §5): a blow-up.
    Diverged,
    /// A coupling could not give its forces (a catenary whose ends are farther apart than it
    /// can reach, say).
    Refused,
    /// It ran past its wall-time limit.
    TimedOut,
}

impl Status {
    /// Every status, failures last.
    pub const ALL: [Self; 4] = [Self::Ok, Self::Diverged, Self::Refused, Self::TimedOut];

    /// As the results table writes it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Ok => "ok",
            Self::Diverged => "diverged",
            Self::Refused => "refused",
            Self::TimedOut => "timed_out",
        }
    }

    /// The status written `name`.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// How a case ended and what it took: the part of its [`Outcome`] its results row
/// ([`super::table::Row`]) holds as it is.
#[derive(Debug, Clone, PartialEq)]
pub struct Ending {
    pub status: Status,
    /// Why it failed (empty when it is ok).
    pub message: String,
    /// Simulated time reached \[s].
    pub end_time: f64,
    /// Integrator steps accepted, and rejected (`dopri45`).
    pub steps: u64,
    pub rejected_steps: u64,
    /// CPU time of the run's thread from t = 0 to the end \[s] (building the world excluded): a
    /// measurement, the one column that differs between two runs.
    pub cpu_seconds: f64,
}

/// What one case gave.
#[derive(Debug, Clone, PartialEq)]
pub struct Outcome {
    pub ending: Ending,
    /// The metrics, in the sweep's order (only when it is ok: a failed run's are not its own).
    pub metrics: Option<Vec<f64>>,
}

/// Where and how a case is recorded.
#[derive(Debug, Clone)]
pub struct Recording<'a> {
    pub path: PathBuf,
    /// The sweep's name: the recording's application id.
    pub application: &'a str,
    /// The case's id: the recording's id.
    pub id: String,
    /// Frames per simulated second.
    pub log_hz: f64,
}

/// Why a case gave no outcome.
#[derive(Debug, Clone, PartialEq)]
pub enum CaseError {
    /// The run was cancelled: the case is left for a resumed run.
    Cancelled,
    /// Its recording could not be written.
    Recording(String),
}

/// Runs `world` for `duration` \[s], measuring `metrics` (settle band `settle_band`).
///
/// # Errors
/// [`CaseError::Cancelled`] when the run is cancelled mid-case; [`CaseError::Recording`] when
/// the recording cannot be written.
pub fn run(
    mut world: World,
    duration: f64,
    metrics: &[Metric],
    settle_band: f64,
    watch: &Watch<'_>,
    recording: Option<&Recording<'_>>,
) -> Result<Outcome, CaseError> {
    let dt = world.dt();
    let total_steps = (duration / dt).round().max(1.0) as u64;
    let mut recorder = recording
        .map(|r| {
            Recorder::to_file_as(&r.path, &world, r.application, &r.id)
                .map_err(|e| CaseError::Recording(unwritable(r, &e)))
        })
        .transpose()?;
    let frames = recording.map(|r| FrameSchedule::new(r.log_hz, dt, total_steps));
    let mut log = |world: &World| {
        recorder
            .as_mut()
            .map_or(Ok(()), |rec| rec.log_frame(world))
            .map_err(|e| recording.map_or_else(String::new, |r| unwritable(r, &e)))
    };
    log(&world).map_err(CaseError::Recording)?;
    let cpu_start = thread_cpu_seconds();
    let mut observer = Observer::new(metrics, &world, total_steps);
    let mut ended: Option<(Status, String, f64)> = None;
    for step in 1..=total_steps {
        if let Err(error) = world.step() {
            let (status, time) = match &error {
                StepError::Diverged { time, .. } => (Status::Diverged, *time),
                StepError::Coupling { time, .. } => (Status::Refused, *time),
            };
            ended = Some((status, error.to_string(), time));
            break;
        }
        observer.observe(&world);
        if frames.is_some_and(|frames| frames.is_due(step)) {
            log(&world).map_err(CaseError::Recording)?;
        }
        if step % WATCH_EVERY == 0 {
            match watch.check() {
                Ok(()) => {}
                Err(Stop::Cancelled) => return Err(CaseError::Cancelled),
                Err(Stop::TimedOut) => {
                    let message = format!("stopped by the case time limit at t = {} s of {duration} s", world.time());
                    ended = Some((Status::TimedOut, message, world.time()));
                    break;
                }
            }
        }
    }
    let cpu_seconds = thread_cpu_seconds() - cpu_start;
    if let Some(recorder) = recorder {
        recorder.finish().map_err(|e| CaseError::Recording(format!("cannot finish the recording: {e}")))?;
    }
    let (status, message, end_time, metrics) = match ended {
        Some((status, message, time)) => (status, message, time, None),
        None => match observer.finish(&world, settle_band) {
            Ok(values) => (Status::Ok, String::new(), world.time(), Some(values)),
            Err(message) => (Status::Diverged, message, world.time(), None),
        },
    };
    let ending = Ending {
        status,
        message,
        end_time,
        steps: world.integrator_steps(),
        rejected_steps: world.rejected_steps(),
        cpu_seconds,
    };
    Ok(Outcome { ending, metrics })
}

fn unwritable(recording: &Recording<'_>, error: &dyn std::fmt::Display) -> String {
    format!("cannot write {}: {error}", recording.path.display())
}
