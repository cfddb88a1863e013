//! A sweep's errors, each one line for the user, placed in the spec or scene where it can be.

use super::spec::SpecError;
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
    /// The run was stopped (Ctrl-C) before any case ran.
    #[error("interrupted while the cases were being checked; nothing was run")]
    Interrupted,
    /// A table or chart that cannot be written.
    #[error("{path}: {message}")]
    Output { path: String, message: String },
}
