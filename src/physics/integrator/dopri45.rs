//! Adaptive Dormand–Prince 5(4) (Dormand & Prince 1980; Hairer, Nørsett & Wanner, *Solving
//! Ordinary Differential Equations I*, §II.5 and §II.4 for the step control) on the variables of
//! [`super::runge_kutta`] (PHYSICS.md §1).
//!
//! Seven stages, the seventh at the new state ("first same as last": it is the next step's
//! first). The fifth-order solution is kept; the difference with the embedded fourth-order one
//! estimates the error, measured as the root-mean-square of `δ_i / (atol + rtol·max(|y0_i|,
//! |y1_i|))` ([`super::Tolerances`]). A step with error ≤ 1 is accepted; either way the next
//! step is `h · clamp(0.9 err^(−1/5), 0.2, 5)` (never larger right after a rejection), at most
//! the maximum step. Every world step (or sub-step) ends exactly on its boundary: the last
//! adaptive step is clipped to it (or split in two halves to avoid a sliver), so recordings
//! log at the requested rate.
//!
//! - Order: 5 (local error estimate of order 4); the global error follows the tolerance.
//! - Conserves: linear momentum and, torque-free, the angular momentum exactly (as
//!   [`super::rk4`]); energy to the tolerance, with a slow drift.
//! - Stability: adapts. A stiff coupling holds the step near the edge of the stability region
//!   of its polynomial (`ωh ≈ 3.3`), shown by [`crate::physics::stability`] as a stiffness
//!   limit, at the price of rejected steps.
//! - Cost: six force evaluations per attempted step.

use super::runge_kutta::{self, Tableau};
use crate::physics::world::{StepError, World};

/// The Dormand–Prince tableau; `b` the fifth-order weights.
const TABLEAU: Tableau = Tableau {
    c: &[0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    a: &[
        &[],
        &[1.0 / 5.0],
        &[3.0 / 40.0, 9.0 / 40.0],
        &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
        &[19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0],
        &[9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0],
        &[35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
    ],
    b: &[35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
};

/// Fifth-order minus fourth-order weights: `δ = h Σ e_j k_j` estimates the local error.
const ERROR: [f64; 7] = [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];

/// Safety factor and the bounds of the step change per step.
const SAFETY: f64 = 0.9;
const SHRINK_AT_MOST: f64 = 0.2;
const GROW_AT_MOST: f64 = 5.0;

/// Evaluates t = 0.
pub(crate) fn start(world: &mut World) -> Result<(), StepError> {
    runge_kutta::start(world, &TABLEAU)
}

/// One accepted step toward the boundary `end` [s] (rejected attempts included); returns
/// whether it reached the boundary, in which case the clock reads exactly `end`.
///
/// # Errors
/// A coupling that cannot give its forces, or a step that had to shrink below round-off of
/// the time (the scene is too stiff or has blown up).
pub(crate) fn step(world: &mut World, end: f64) -> Result<bool, StepError> {
    let tolerances = world.tolerances();
    let t0 = world.time();
    let remaining = end - t0;
    let max_step = tolerances.max_step.map_or(world.step_size(), |m| m.min(world.step_size()));
    let proposal = match world.runge_kutta.next_step {
        h if h > 0.0 => h.min(max_step),
        _ => max_step,
    };
    // Reach the boundary exactly; rather two halves than a step and a sliver.
    let mut h = if proposal >= remaining {
        remaining
    } else if proposal > 0.5 * remaining {
        0.5 * remaining
    } else {
        proposal
    };
    let mut rejected = false;
    loop {
        let last = runge_kutta::attempt(world, &TABLEAU, h)?;
        let error = runge_kutta::error_norm(world, &ERROR, h, tolerances.rtol, tolerances.atol);
        let factor = if error == 0.0 { GROW_AT_MOST } else { (SAFETY * error.powf(-0.2)).clamp(SHRINK_AT_MOST, GROW_AT_MOST) };
        if error <= 1.0 {
            runge_kutta::accept(world, &TABLEAU, h, last);
            let reached = h == remaining;
            world.set_time(if reached { end } else { t0 + h });
            world.count_integrator_step(false);
            // A step shortened to meet the boundary says nothing against the longer proposal.
            let next = if rejected { h * factor.min(1.0) } else { (h * factor).max(if h < proposal { proposal } else { 0.0 }) };
            world.runge_kutta.next_step = next.min(max_step);
            return Ok(reached);
        }
        runge_kutta::reject(world);
        world.count_integrator_step(true);
        rejected = true;
        h *= factor.min(SAFETY);
        if h <= 16.0 * f64::EPSILON * t0.abs().max(remaining) {
            return Err(world.stalled(h));
        }
    }
}
