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
//!   of its polynomial (`ωh ≈ 3.3`), shown by [`crate::stability`] as a stiffness
//!   limit, at the price of rejected steps.
//! - Cost: six force evaluations per attempted step.

use super::context::StepContext;
use super::report::{StepFailure, StepReport};
use super::runge_kutta::{Stages, Tableau};
use super::settings::Tolerances;
use crate::energy::{BodyEnergy, Work};
use crate::system::EvaluationError;

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
const ERROR: [f64; 7] =
    [71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0];

/// Safety factor and the bounds of the step change per step.
const SAFETY: f64 = 0.9;
const SHRINK_AT_MOST: f64 = 0.2;
const GROW_AT_MOST: f64 = 5.0;

/// Dormand–Prince's scratch: its stages and its step control.
#[derive(Debug, Clone)]
pub struct Dopri45 {
    stages: Stages,
    tolerances: Tolerances,
    /// Largest step [s]: the tolerances' `max_step`, at most the integrator step.
    max_step: f64,
    /// The proposal for the next step [s] (0 before the first).
    next_step: f64,
    /// After a rejected attempt, the shorter step to attempt next [s].
    retry: Option<f64>,
}

impl Dopri45 {
    /// The scheme with `tolerances`, for integrator steps of `step` \[s] and `bodies` bodies.
    pub fn new(tolerances: Tolerances, step: f64, bodies: usize) -> Self {
        let max_step = tolerances.max_step().map_or(step, |m| m.min(step));
        Self { stages: Stages::new(&TABLEAU, bodies), tolerances, max_step, next_step: 0.0, retry: None }
    }

    /// Evaluates `time`.
    pub fn start(&mut self, context: StepContext) -> Result<BodyEnergy, EvaluationError> {
        (self.next_step, self.retry) = (0.0, None);
        self.stages.start(context)
    }

    /// One attempt from the context's `time` \[s] toward the end of the span `h` \[s] left to
    /// reach: accepted (the
    /// report says whether it reached the end, which it meets exactly) or rejected (the states
    /// are back at `time`, and the next attempt is shorter).
    ///
    /// # Errors
    /// A coupling that cannot give its forces, or a step that had to shrink below round-off of
    /// the time (the scene is too stiff or has blown up).
    pub fn step(&mut self, context: StepContext) -> Result<StepReport, StepFailure> {
        let StepContext { system, states, evaluation, time, h: remaining } = context;
        let (rtol, atol) = (self.tolerances.rtol(), self.tolerances.atol());
        let proposal = match self.next_step {
            h if h > 0.0 => h.min(self.max_step),
            _ => self.max_step,
        };
        let rejected = self.retry.is_some();
        // Reach the boundary exactly; rather two halves than a step and a sliver.
        let h = self.retry.take().unwrap_or(if proposal >= remaining {
            remaining
        } else if proposal > 0.5 * remaining {
            0.5 * remaining
        } else {
            proposal
        });
        let last =
            self.stages.attempt(StepContext { system, states: &mut *states, evaluation: &mut *evaluation, time, h })?;
        let error = self.stages.error_norm(system, states, &ERROR, h, rtol, atol);
        let factor =
            if error == 0.0 { GROW_AT_MOST } else { (SAFETY * error.powf(-0.2)).clamp(SHRINK_AT_MOST, GROW_AT_MOST) };
        if error <= 1.0 {
            let (work, energy) = self.stages.accept(system, states, h, last);
            // A step shortened to meet the boundary says nothing against the longer proposal.
            let next = if rejected {
                h * factor.min(1.0)
            } else {
                (h * factor).max(if h < proposal { proposal } else { 0.0 })
            };
            self.next_step = next.min(self.max_step);
            return Ok(StepReport { advanced: h, accepted: true, reached: h == remaining, work, energy });
        }
        self.stages.reject(states);
        let shorter = h * factor.min(SAFETY);
        if shorter <= 16.0 * f64::EPSILON * time.abs().max(remaining) {
            return Err(StepFailure::Stalled { step: shorter });
        }
        self.retry = Some(shorter);
        Ok(StepReport {
            advanced: 0.0,
            accepted: false,
            reached: false,
            work: Work::default(),
            energy: BodyEnergy::default(),
        })
    }
}
