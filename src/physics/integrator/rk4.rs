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
//!   ([`crate::physics::stability`]); `|ω| h < 1` for spinning bodies.
//! - Cost: four force evaluations per step (the fourth at the new state is the next step's
//!   first), and a normalised quaternion per body and stage.

use super::runge_kutta::{self, Tableau};
use crate::physics::world::{StepError, World};

/// The classical tableau.
const TABLEAU: Tableau = Tableau {
    c: &[0.0, 0.5, 0.5, 1.0],
    a: &[&[], &[0.5], &[0.0, 0.5], &[0.0, 0.0, 1.0]],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
};

/// Evaluates t = 0.
pub(crate) fn start(world: &mut World) -> Result<(), StepError> {
    runge_kutta::start(world, &TABLEAU)
}

/// One step of `dt / substeps`.
pub(crate) fn step(world: &mut World) -> Result<(), StepError> {
    let h = world.step_size();
    let last = runge_kutta::attempt(world, &TABLEAU, h)?;
    runge_kutta::accept(world, &TABLEAU, h, last);
    world.advance_clock();
    Ok(())
}
