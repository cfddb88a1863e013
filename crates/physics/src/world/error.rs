//! What stops a world: a step that could not be completed, or a live edit refused.

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

/// A live edit refused ([`super::World::replace_coupling`], [`super::World::set_seabed`],
/// [`super::World::place`], [`super::World::replace_water`], [`super::World::replace_hydro`],
/// [`super::World::set_timing`]); the world is then unchanged. Each kind carries its typed
/// source and prints as it does: one line, naming what is at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EditError {
    /// A coupling replaced at an index the world does not have.
    #[error("the world has no coupling {index} (it has {count})")]
    NoSuchCoupling { index: usize, count: usize },
    /// The edit would make the system inconsistent: an unknown body, an anchor below a raised
    /// seabed, water that cannot be, a body that does not float.
    #[error(transparent)]
    System(#[from] SystemError),
    /// The forces cannot be evaluated after it.
    #[error(transparent)]
    Forces(#[from] StepError),
}
