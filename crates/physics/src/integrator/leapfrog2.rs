//! The leapfrog with a second-order rotation: identical to [`super::leapfrog`] except that the
//! gyroscopic term `ω × Iω` of Euler's equations at t uses the predicted
//! `ω(t) ≈ ω(t−½dt) + ½dt α(t−dt)` instead of `ω(t−½dt)`.
//!
//! - Order: 2 in translation and rotation (dampers still see `v(t−½dt)`, first order, as in
//!   the leapfrog, which keeps Belytschko's damped stability limit).
//! - Conserves: linear momentum exactly; |L| and energy of a torque-free body drift at second
//!   order instead of the leapfrog's first (bounded over long runs, not exactly).
//! - Stability: as the leapfrog (`ω_max dt < 2`, `2(√(1+ζ²) − ζ)/ω` damped; `|ω| dt < 1`),
//!   except that the prediction feeds a stiff coupling's moment back into the gyroscopic term:
//!   a fast spinner on a stiff penalty pivot (the heavy top of `tests/rotation.rs`, 200 rad/s,
//!   k = 1e7 N/m) diverges at dt = 1e-4 s, half its spring limit, and runs at 2e-5 s. The
//!   [`super::splitting`] has no such coupling.
//! - Cost: one force evaluation per step, six more multiply-adds per body.

use super::context::StepContext;
use super::leapfrog::Leapfrog;
use super::report::StepReport;
use crate::system::EvaluationError;

/// One step of `h` \[s] from `time`: the leapfrog's, built with [`super::leapfrog::Gyroscopic::Predicted`].
pub fn step(scheme: &mut Leapfrog, context: StepContext) -> Result<StepReport, EvaluationError> {
    scheme.step(context)
}
