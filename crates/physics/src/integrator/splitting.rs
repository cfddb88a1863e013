//! Symplectic splitting: kick–drift–kick for the forces, and the free rigid body split into
//! exact rotations about its principal axes (Dullweber, Leimkuhler & McLachlan, "Symplectic
//! splitting methods for rigid body molecular dynamics", J. Chem. Phys. 107, 1997; the NO_SQUISH
//! scheme of Miller et al. 2002 is the same splitting). PHYSICS.md §1.
//!
//! With the body-frame angular momentum `π = I ω`, one step of `h`:
//! 1. *kick* `v += ½h F/m`, `π += ½h M` (moment in the principal frame; no gyroscopic term);
//! 2. *drift* `x += h v`, and the free rotation `T = Σ π_k²/(2 I_k)` by the symmetric sequence
//!    `R1(h/2) R2(h/2) R3(h) R2(h/2) R1(h/2)`, where `Rk(τ)` is the exact flow of
//!    `π_k²/(2 I_k)` alone: a rotation by `φ = τ π_k / I_k` about principal axis k,
//!    `q ← q ⊗ exp(φ e_k)`, while `π` turns by `−φ` about `e_k`;
//! 3. forces at the new positions, then *kick* again by `½h`.
//!
//! - Order: 2 in translation and rotation (Strang splitting). Dampers see the half-step
//!   velocity `v(t+½h)`, as in the leapfrog, so damping is first order and the translation is
//!   the leapfrog's exactly.
//! - Conserves: linear momentum; |L| exactly in torque-free motion (every sub-flow is a rotation
//!   of `π`); symplectic and time-reversible, so energy oscillates with no trend.
//! - Stability: as the leapfrog (`ω_max h < 2`, `2(√(1+ζ²) − ζ)/ω` damped; `|ω| h < 1`).
//! - Cost: one force evaluation per step; five axis rotations (sine and cosine) per spinning
//!   body.
//! - Work: the trapezoid rule on the powers at consecutive evaluations; the water's as the
//!   leapfrog's (`½ h (F_n + F_{n+1})·v_{n+½}`).

use super::context::StepContext;
use super::kick_drift;
use super::report::StepReport;
use crate::body::kinematics::{drift, kick, renormalize};
use crate::body::{Acceleration, BodyState, RigidBody};
use crate::dynamics::accelerations;
use crate::energy::{BodyEnergy, Powers};
use crate::evaluation::Evaluation;
use crate::math::Vec3;
use crate::system::{EvaluationError, System};
use nalgebra::Quaternion;

/// The splitting's scratch: the accelerations of the next kick and the powers at the last
/// evaluation.
#[derive(Debug, Clone)]
pub struct Splitting {
    accelerations: Vec<Acceleration>,
    powers: Powers,
}

impl Splitting {
    pub fn new(bodies: usize) -> Self {
        Self { accelerations: vec![Acceleration::default(); bodies], powers: Powers::default() }
    }

    /// Evaluates `time`: forces, and the accelerations of the first kick (velocities stay
    /// synchronised).
    pub fn start(&mut self, context: StepContext) -> Result<BodyEnergy, EvaluationError> {
        let StepContext { system, states, evaluation, time, .. } = context;
        system.prescribe(states, time);
        self.powers = system.evaluate(states, evaluation, time)?;
        Ok(self.kick_and_energies(system, states, evaluation, 0.0))
    }

    /// One step of `h` \[s] from `time`: kick, drift (with the rotation sequence), forces, kick.
    pub fn step(&mut self, context: StepContext) -> Result<StepReport, EvaluationError> {
        let StepContext { system, states, evaluation, time, h } = context;
        let time = time + h;
        kick_drift::advance_bodies(
            system,
            states,
            &self.accelerations,
            evaluation,
            time,
            |body, state, acceleration, frame| {
                kick(state, acceleration, &body.support, 0.5 * h);
                drift(state, h);
                if rotate_freely(body, state, h) {
                    *frame = state.frame();
                } else {
                    frame.follow_translation(state);
                }
            },
        );
        let forces = kick_drift::end_forces(system, evaluation, time)?;
        let energy = self.kick_and_energies(system, states, evaluation, 0.5 * h);
        Ok(forces.report(system, evaluation, h, &mut self.powers, energy))
    }

    /// Accelerations from the loads (the moment's part only: the rotation sequence carries the
    /// gyroscopic term), the closing kick by `half` [s], and the bodies' kinetic and gravity
    /// energies at the now synchronised velocities.
    fn kick_and_energies(
        &mut self,
        system: &System,
        states: &mut [BodyState],
        evaluation: &Evaluation,
        half: f64,
    ) -> BodyEnergy {
        let mut energy = BodyEnergy::default();
        let per_body = system.bodies().iter().zip(states.iter_mut()).zip(&evaluation.frames).zip(&evaluation.loads);
        for ((((body, state), frame), load), acceleration) in per_body.zip(self.accelerations.iter_mut()) {
            if body.is_kinematic() {
                continue;
            }
            *acceleration = accelerations(body, &frame.rotation, load, &Vec3::zeros());
            kick(state, acceleration, &body.support, half);
            energy = energy + BodyEnergy::of(body, state, system.gravity());
        }
        energy
    }
}

/// The free rotation over `h` by `R1(h/2) R2(h/2) R3(h) R2(h/2) R1(h/2)`; returns whether the
/// body turned (one with `ω = 0` exactly pays nothing).
fn rotate_freely(body: &RigidBody, state: &mut BodyState, h: f64) -> bool {
    let w = &state.angular_velocity;
    if w.x == 0.0 && w.y == 0.0 && w.z == 0.0 {
        return false;
    }
    let moments = body.principal_moments();
    let mut momentum = moments.component_mul(&state.angular_velocity);
    let mut orientation = state.orientation.into_inner();
    for (axis, fraction) in [(0, 0.5), (1, 0.5), (2, 1.0), (1, 0.5), (0, 0.5)] {
        let angle = fraction * h * momentum[axis] * body.inverse_principal_moments[axis];
        // One sine and cosine of the half angle give the quaternion and the full angle.
        let (sin_half, cos_half) = (0.5 * angle).sin_cos();
        let (sin, cos) = (2.0 * sin_half * cos_half, 1.0 - 2.0 * sin_half * sin_half);
        // π turns by −φ about e_k: (π_i, π_j) ← (cos φ π_i + sin φ π_j, −sin φ π_i + cos φ π_j)
        // for the cyclic order (k, i, j).
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let (pi, pj) = (momentum[i], momentum[j]);
        momentum[i] = cos * pi + sin * pj;
        momentum[j] = -sin * pi + cos * pj;
        let mut axis_part = Vec3::zeros();
        axis_part[axis] = sin_half;
        orientation *= Quaternion::from_parts(cos_half, axis_part);
    }
    state.orientation = renormalize(orientation);
    state.angular_velocity = momentum.component_mul(&body.inverse_principal_moments);
    true
}
