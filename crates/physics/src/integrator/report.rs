//! What an integrator step tells the world, and why it could fail.

use crate::energy::{BodyEnergy, Work};
use crate::system::EvaluationError;

/// What one integrator step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepReport {
    /// Time the states advanced \[s]: the step, or 0 for a rejected adaptive attempt.
    pub advanced: f64,
    /// Whether the step was kept (an adaptive attempt whose error was too large was not: the
    /// states are back where they were).
    pub accepted: bool,
    /// Whether an adaptive step reached the end of the span it was given (the world then sets
    /// its clock to the span's end exactly); always true for a fixed step.
    pub reached: bool,
    /// Work the dampers dissipated and the prescribed motions put in over the step \[J], by the
    /// scheme's own quadrature of the powers.
    pub work: Work,
    /// Kinetic and gravity energy of the bodies at the end of the step (synchronised).
    pub energy: BodyEnergy,
}

impl StepReport {
    /// A kept step of `h` [s].
    pub(crate) fn accepted(h: f64, work: Work, energy: BodyEnergy) -> Self {
        Self { advanced: h, accepted: true, reached: true, work, energy }
    }
}

/// Why an integrator step could not be taken.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum StepFailure {
    /// A coupling could not give its forces.
    Evaluation(EvaluationError),
    /// An adaptive step had to shrink to `step` \[s], below round-off of the time: the system is
    /// too stiff for the tolerance, or has blown up.
    Stalled { step: f64 },
}

impl From<EvaluationError> for StepFailure {
    fn from(error: EvaluationError) -> Self {
        Self::Evaluation(error)
    }
}
