//! A sweep's errors, each one line for the user, placed in the spec or scene where it can be.

use crate::runner::Runner;
use crate::spec_text::SpecError;
use tether_scene::SceneError;

/// Why a sweep cannot run or its results cannot be written: one line for the user.
#[derive(Debug, thiserror::Error)]
pub enum SweepError {
    /// The spec is wrong: `spec.ron:line:col: message`, naming the factor or metric.
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// The base scene is wrong: `scene.ron:line:col: message`.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The scene loader refuses a case's combination of values.
    #[error("case {case} ({values}): {message}")]
    Case { case: usize, values: String, message: String },
    /// The output directory cannot take the sweep, or holds something that is not a sweep's.
    #[error("{0}")]
    Directory(String),
    /// A file that cannot be read or written.
    #[error("{path}: {message}")]
    Io { path: String, message: String },
    /// A merge of a sweep whose cases do not all have a row.
    #[error("{0}")]
    Incomplete(String),
    /// The run was stopped (Ctrl-C, SIGTERM) at a stage that keeps nothing of itself.
    #[error("interrupted while {0}")]
    Interrupted(Stage),
    /// A table or chart that cannot be written.
    #[error("{path}: {message}")]
    Output { path: String, message: String },
}

/// A stage of a sweep a Ctrl-C or SIGTERM can stop, and what stopping it leaves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// Building every case's scene before anything runs: nothing was run or written.
    Checking,
    /// Writing the results from the rows: every row is kept, no results file half-written.
    Writing,
}

impl std::fmt::Display for Stage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Checking => "the cases were being checked; nothing was run",
            Self::Writing => "the results were being written; every row is kept (`tether sweep merge` writes them)",
        })
    }
}

/// `Err(Interrupted(stage))` once `runner` is cancelled (Ctrl-C, SIGTERM): what a stage checks
/// between its steps — a value, a row, a chart — so that it stops within one of them.
///
/// # Errors
/// [`SweepError::Interrupted`] at `stage`.
pub fn unless_cancelled(runner: &Runner, stage: Stage) -> Result<(), SweepError> {
    if runner.cancelled() { Err(SweepError::Interrupted(stage)) } else { Ok(()) }
}
