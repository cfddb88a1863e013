//! The leapfrog (central difference) scheme, as Radioss does it (PHYSICS.md §1 "Time integration", \[17]–\[18]).
//!
//! `v(t+½dt) = v(t−½dt) + γ(t) dt`, `ω(t+½dt) = ω(t−½dt) + α(t) dt` (ω in the principal frame),
//! `x_G(t+dt) = x_G(t) + v(t+½dt) dt`, `q(t+dt) = q(t) ⊗ exp(ω(t+½dt) dt)` (exact rotation by
//! the rotation vector, then renormalised).
//!
//! - Order: 2 in translation; 1 in rotation, because the gyroscopic term `ω × Iω` at t only has
//!   `ω(t−½dt)` available (|L| and energy of a precessing body drift ~ exp(½ Ω² dt T)).
//! - Velocity-dependent forces (dampers) see `v(t−½dt)`, the latest velocity there is, as in
//!   Radioss: the damping force is first-order accurate, and the damped stability limit is
//!   exactly Belytschko's `2(√(1+ζ²) − ζ)/ω`.
//! - Conserves: linear momentum exactly (forces are pairwise equal and opposite); symplectic
//!   for conservative translational forces, so energy oscillates with no trend.
//! - Stability: `ω_max dt < 2` for an undamped spring, `2(√(1+ζ²) − ζ)` with damping.
//! - Cost: one force evaluation per step.
//! - Work: the trapezoid rule on the powers at consecutive evaluations; for the water's forces
//!   (PHYSICS.md §6), which have no potential, the trapezoid of the forces at both ends against
//!   the half-step velocity between them, `½ h (F_n + F_{n+1})·v_{n+½}`: second order for a
//!   position-dependent force such as the buoyancy.

use super::context::StepContext;
use super::kick_drift;
use super::report::StepReport;
use crate::body::kinematics::{drift, kick, turn};
use crate::body::{Acceleration, BodyState};
use crate::dynamics::accelerations;
use crate::energy::{BodyEnergy, Powers};
use crate::evaluation::Evaluation;
use crate::system::{EvaluationError, System};

/// At which angular velocity the gyroscopic term `ω × Iω` is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Gyroscopic {
    /// `ω(t−½dt)`, as PHYSICS.md §1 has it (first order in rotation).
    Lagged,
    /// `ω(t) ≈ ω(t−½dt) + ½dt α(t−dt)` ([`super::leapfrog2`], second order).
    Predicted,
}

/// The leapfrog's scratch: the accelerations at the last evaluation (the next kick, and the
/// half step that synchronises the velocities) and the powers there (the trapezoid's left end).
#[derive(Debug, Clone)]
pub struct Leapfrog {
    gyroscopic: Gyroscopic,
    accelerations: Vec<Acceleration>,
    powers: Powers,
}

impl Leapfrog {
    pub fn new(gyroscopic: Gyroscopic, bodies: usize) -> Self {
        Self { gyroscopic, accelerations: vec![Acceleration::default(); bodies], powers: Powers::default() }
    }

    /// Evaluates `time` and turns the synchronised velocities into `v(t − ½h) = v(t) − ½h γ(t)`.
    pub fn start(&mut self, context: StepContext) -> Result<BodyEnergy, EvaluationError> {
        let StepContext { system, states, evaluation, time, h } = context;
        system.prescribe(states, time);
        self.powers = system.evaluate(states, evaluation, time)?;
        // The velocities are synchronised: ω(t) is exact for either variant.
        self.accelerate(system, states, evaluation, Gyroscopic::Lagged, 0.0);
        let half = 0.5 * h;
        for ((state, acceleration), body) in states.iter_mut().zip(&self.accelerations).zip(system.bodies()) {
            if !body.is_kinematic() {
                state.velocity -= acceleration.linear * half;
                state.angular_velocity -= acceleration.angular * half;
            }
        }
        Ok(self.energy(system, states, half))
    }

    /// One step of `h` \[s] from `time`.
    #[inline]
    pub fn step(&mut self, context: StepContext) -> Result<StepReport, EvaluationError> {
        let StepContext { system, states, evaluation, time, h } = context;
        system.supported_level().run(
            #[inline(always)]
            || self.step_built(system, states, evaluation, time, h),
        )
    }

    /// One step. Stages *advance*, *prescribe*, *predict*, *clear* and *gravity* run in two
    /// passes over the bodies, translation first and rotation second (a short loop, in which
    /// the processor overlaps one body's chain of rotation arithmetic with the next's); then
    /// *couplings*, *water*, *accelerations* and *powers*. Built for AVX-512 and AVX2 as well
    /// ([`crate::simd::SupportedLevel::run`]), with the per-body stages inlined (same results,
    /// bit for bit).
    #[inline(always)]
    fn step_built(
        &mut self,
        system: &System,
        states: &mut [BodyState],
        evaluation: &mut Evaluation,
        time: f64,
        h: f64,
    ) -> Result<StepReport, EvaluationError> {
        let time = time + h;
        kick_drift::advance_bodies(
            system,
            states,
            &self.accelerations,
            evaluation,
            time,
            |body, state, acceleration, frame| {
                kick(state, acceleration, &body.support, h);
                drift(state, h);
                // Velocity-dependent forces see v(t−½dt), as in Radioss.
                frame.follow_translation(state);
            },
        );
        for ((body, state), frame) in system.bodies().iter().zip(states.iter_mut()).zip(evaluation.frames.iter_mut()) {
            // A body that does not turn keeps its orientation and rotation matrix.
            if !body.is_kinematic() && turn(state, h) {
                frame.rotation = state.rotation_matrix();
            }
        }
        let forces = kick_drift::end_forces(system, evaluation, time)?;
        let energy = self.accelerate(system, states, evaluation, self.gyroscopic, 0.5 * h);
        Ok(forces.report(system, evaluation, h, &mut self.powers, energy))
    }

    /// The state of body `index` at the current time, velocities synchronised:
    /// `v(t) = v(t−½h) + ½h γ(t)`.
    pub fn synchronized(&self, system: &System, states: &[BodyState], index: usize, h: f64) -> BodyState {
        synchronized(&system.bodies()[index], &states[index], &self.accelerations[index], 0.5 * h)
    }

    /// Stage *accelerations*: Euler's equations with the gyroscopic term at the chosen angular
    /// velocity; in the same pass, the bodies' energies at t with the velocities synchronised by
    /// `half` [s] of acceleration.
    #[inline(always)]
    fn accelerate(
        &mut self,
        system: &System,
        states: &[BodyState],
        evaluation: &Evaluation,
        gyroscopic: Gyroscopic,
        half: f64,
    ) -> BodyEnergy {
        let mut energy = BodyEnergy::default();
        let per_body = system.bodies().iter().zip(states).zip(&evaluation.frames).zip(&evaluation.loads);
        for ((((body, state), frame), load), acceleration) in per_body.zip(self.accelerations.iter_mut()) {
            let omega = match gyroscopic {
                Gyroscopic::Lagged => state.angular_velocity,
                // `acceleration` still holds α(t−dt) here.
                Gyroscopic::Predicted => state.angular_velocity + acceleration.angular * half,
            };
            *acceleration = accelerations(body, &frame.rotation, load, &omega);
            energy = energy + BodyEnergy::of(body, &synchronized(body, state, acceleration, half), system.gravity());
        }
        energy
    }

    /// The bodies' energies with the velocities synchronised by `half` [s].
    fn energy(&self, system: &System, states: &[BodyState], half: f64) -> BodyEnergy {
        let per_body = system.bodies().iter().zip(states).zip(&self.accelerations);
        per_body.fold(BodyEnergy::default(), |total, ((body, state), acceleration)| {
            total + BodyEnergy::of(body, &synchronized(body, state, acceleration, half), system.gravity())
        })
    }
}

/// `state` with its velocities moved on by `half` [s] of `acceleration` (a kinematic body's are
/// already at t).
#[inline(always)]
fn synchronized(body: &crate::body::RigidBody, state: &BodyState, acceleration: &Acceleration, half: f64) -> BodyState {
    if body.is_kinematic() {
        return *state;
    }
    BodyState {
        velocity: state.velocity + acceleration.linear * half,
        angular_velocity: state.angular_velocity + acceleration.angular * half,
        ..*state
    }
}
