//! What stops a world: a step that could not be completed, a time step setting or a live edit
//! refused.

use crate::coupling::CouplingError;
use crate::system::SystemError;

/// A step that could not be completed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StepError {
    /// A coupling could not give its forces.
    #[error("coupling \"{coupling}\" at t = {time} s: {source}")]
    Coupling { coupling: String, time: f64, source: CouplingError },
    /// The state blew up: `body` is the body at fault (non-finite, or the most energetic),
    /// `advice` names the binding stable time step of the starting configuration.
    #[error("the simulation diverged at t = {time} s: body \"{body}\" {cause}; {advice}")]
    Diverged { time: f64, body: String, cause: String, advice: String },
}

/// A live edit refused by [`super::World::set_seabed`] or [`super::World::place`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EditError {
    /// The edit would make the system inconsistent (an anchor below a raised seabed).
    #[error(transparent)]
    System(#[from] SystemError),
    /// The forces cannot be evaluated after it.
    #[error(transparent)]
    Forces(#[from] StepError),
}

/// A time step setting refused by [`super::World::set_timing`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TimingError {
    #[error("time step dt must be > 0 s, got {0}")]
    Step(f64),
    #[error("substeps must be at least 1")]
    NoSubsteps,
    #[error(transparent)]
    Forces(StepError),
}

/// A live edit of the water refused by [`super::World::replace_water`] or
/// [`super::World::replace_hydro`]; the world is then unchanged.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WaterEditError {
    /// The new water or coefficients cannot be.
    #[error(transparent)]
    Refused(SystemError),
    #[error(transparent)]
    Forces(StepError),
}
