//! Classical fourth-order Runge–Kutta on position, orientation quaternion, linear and angular
//! momentum (PHYSICS.md §1; the variables and their rates are in [`super::runge_kutta`]).
//!
//! `k1 = f(t, y)`, `k2 = f(t + h/2, y + h/2 k1)`, `k3 = f(t + h/2, y + h/2 k2)`,
//! `k4 = f(t + h, y + h k3)`, `y(t+h) = y + h/6 (k1 + 2k2 + 2k3 + k4)`.
//!
//! - Order: 4 in translation and rotation; dampers see the stage velocities, so damping is
//!   fourth order too, and velocities are synchronised with positions.
//! - Conserves: linear momentum and, torque-free, the angular momentum `L` exactly (its rate is
//!   the applied moment). It is not symplectic: an undamped oscillator loses energy steadily,
//!   by a factor `|R(iωh)|² = 1 − (ωh)⁶/72 + (ωh)⁸/576` per step.
//! - Stability: `|R(hλ)| ≤ 1` for `R(z) = 1 + z + z²/2 + z³/6 + z⁴/24` and every oscillator
//!   eigenvalue `λ`: `ωh ≤ 2√2` undamped, with damping from the polynomial
//!   ([`crate::stability`]); `|ω| h < 1` for spinning bodies.
//! - Cost: four force evaluations per step (the fourth at the new state is the next step's
//!   first), and a normalised quaternion per body and stage.

use super::context::StepContext;
use super::report::StepReport;
use super::runge_kutta::{Stages, Tableau};
use crate::system::EvaluationError;

/// The classical tableau.
pub const TABLEAU: Tableau = Tableau {
    c: &[0.0, 0.5, 0.5, 1.0],
    a: &[&[], &[0.5], &[0.0, 0.5], &[0.0, 0.0, 1.0]],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
};

/// One step of `h` \[s] from `time`.
pub fn step(stages: &mut Stages, context: StepContext) -> Result<StepReport, EvaluationError> {
    let StepContext { system, states, evaluation, time, h } = context;
    let last = stages.attempt(StepContext { system, states: &mut *states, evaluation, time, h })?;
    let (work, energy) = stages.accept(system, states, h, last);
    Ok(StepReport::accepted(h, work, energy))
}
