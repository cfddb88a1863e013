//! Explicit Runge–Kutta machinery shared by [`super::rk4`] and [`super::dopri45`].
//!
//! The integrated variables of each body are position `x_G` \[m], orientation quaternion `q`,
//! velocity `v_G` [m/s] and angular momentum in the world `L = R I ω` [kg·m²/s] (PHYSICS.md §1):
//!
//! `ẋ = v`, `q̇ = ½ q ⊗ (0, ω)`, `v̇ = F/m`, `L̇ = M` (world moment about G), with
//! `ω = I⁻¹ Rᵀ L` in the principal frame and `R` the rotation of the normalised `q`.
//!
//! Euler's equations are hidden in `ω = I⁻¹ Rᵀ L`: a torque-free body keeps `L` exactly, so
//! |L| is exact and only the orientation carries the scheme's error. Stage quaternions are
//! normalised before use (the exact flow keeps `|q| = 1`, so the order is kept) and the new
//! quaternion is normalised at the end of the step. Kinematic bodies are put where their motion
//! says at every stage time; fixed components have zero rates.
//!
//! The work is one more integrated variable: dissipated and external work over a step are
//! `h Σ b_j P_j` with the stage powers `P_j`, the same weights as the state, so the energy
//! balance keeps the scheme's order.

use super::context::StepContext;
use crate::body::{BodyFrame, BodyState, Load, RigidBody, Support};
use crate::dynamics::accelerations;
use crate::energy::{BodyEnergy, Powers, Work};
use crate::evaluation::Evaluation;
use crate::math::{Rotation, Vec3};
use crate::system::{EvaluationError, System};
use nalgebra::Quaternion;

/// An explicit Runge–Kutta scheme: `c_i`, the rows `a_ij` (j < i) and the weights `b_j`.
#[derive(Debug, PartialEq)]
pub struct Tableau {
    pub c: &'static [f64],
    pub a: &'static [&'static [f64]],
    pub b: &'static [f64],
}

impl Tableau {
    /// Stages whose state is evaluated.
    fn stages(&self) -> usize {
        self.c.len()
    }

    /// Whether the last stage is the new state (`a_sj = b_j`, "first same as last"): its
    /// evaluation is then the next step's first.
    fn first_same_as_last(&self) -> bool {
        self.a[self.stages() - 1] == self.b
    }

    /// Rate slots: the stages, plus one for the evaluation at the new state when the scheme
    /// does not give it.
    fn slots(&self) -> usize {
        self.stages() + usize::from(!self.first_same_as_last())
    }
}

/// Time derivative of one body's integrated variables.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Rate {
    /// `ẋ = v` [m/s].
    velocity: Vec3,
    /// `q̇ = ½ q ⊗ (0, ω)` [1/s].
    spin: Quaternion<f64>,
    /// `v̇ = F/m` [m/s²].
    acceleration: Vec3,
    /// `L̇ = M` [N·m], world.
    moment: Vec3,
}

const REST: Rate = Rate {
    velocity: Vec3::new(0.0, 0.0, 0.0),
    spin: Quaternion::new(0.0, 0.0, 0.0, 0.0),
    acceleration: Vec3::new(0.0, 0.0, 0.0),
    moment: Vec3::new(0.0, 0.0, 0.0),
};

/// A Runge–Kutta scheme's scratch: its tableau and the buffers of its stages, allocated once.
#[derive(Debug, Clone)]
pub struct Stages {
    tableau: &'static Tableau,
    /// States at the start of the step being attempted.
    start: Vec<BodyState>,
    /// World angular momenta at the start of the step [kg·m²/s].
    momentum: Vec<Vec3>,
    /// `rates[slot][body]`; slot 0 holds the rates at the current state.
    rates: Vec<Vec<Rate>>,
    /// Dissipated and external power at each slot [W].
    powers: Vec<Powers>,
}

impl Stages {
    pub fn new(tableau: &'static Tableau, bodies: usize) -> Self {
        let slots = tableau.slots();
        Self {
            tableau,
            start: vec![rest_state(); bodies],
            momentum: vec![Vec3::zeros(); bodies],
            rates: vec![vec![REST; bodies]; slots],
            powers: vec![Powers::default(); slots],
        }
    }

    /// Evaluates the rates at `time` \[s] into slot 0; returns the bodies' energies.
    pub fn start(&mut self, context: StepContext) -> Result<BodyEnergy, EvaluationError> {
        let StepContext { system, states, evaluation, time, .. } = context;
        self.evaluate(system, states, evaluation, time, 0)?;
        Ok(BodyEnergy::sum(system.bodies(), states.iter(), system.gravity()))
    }

    /// Attempts a step of `h` \[s] from the states at `time`: evaluates the stages and leaves the
    /// new state (synchronised) in `states`, with the forces evaluated there. Returns the slot
    /// that holds the rates at the new state. [`Stages::accept`] or [`Stages::reject`] must
    /// follow.
    pub fn attempt(&mut self, context: StepContext) -> Result<usize, EvaluationError> {
        let StepContext { system, states, evaluation, time, h } = context;
        self.start.copy_from_slice(states);
        for ((momentum, state), body) in self.momentum.iter_mut().zip(states.iter()).zip(system.bodies()) {
            *momentum = state.orientation * body.principal_moments().component_mul(&state.angular_velocity);
        }
        let tableau = self.tableau;
        for stage in 1..tableau.stages() {
            self.set_state(system, states, tableau.a[stage], h);
            self.evaluate(system, states, evaluation, time + tableau.c[stage] * h, stage)?;
        }
        if tableau.first_same_as_last() {
            return Ok(tableau.stages() - 1);
        }
        let last = tableau.stages();
        self.set_state(system, states, tableau.b, h);
        self.evaluate(system, states, evaluation, time + h, last)?;
        Ok(last)
    }

    /// Accepts the attempted step of `h` \[s] whose new rates are in slot `last`: the new rates
    /// become slot 0. Returns the work over the step, `h Σ b_j P_j`, and the bodies' energies.
    pub fn accept(&mut self, system: &System, states: &[BodyState], h: f64, last: usize) -> (Work, BodyEnergy) {
        let work = Work::quadrature(h, self.tableau.b, &self.powers);
        self.rates.swap(0, last);
        self.powers.swap(0, last);
        (work, BodyEnergy::sum(system.bodies(), states.iter(), system.gravity()))
    }

    /// Puts `states` back at the start of the rejected attempt (slot 0 still holds its rates).
    pub fn reject(&self, states: &mut [BodyState]) {
        states.copy_from_slice(&self.start);
    }

    /// Root-mean-square of `δ_i / (atol + rtol·max(|y0_i|, |y1_i|))` over the components of the
    /// bodies that respond to forces, with `δ = h Σ_j e_j k_j` the error estimate of the attempted
    /// step (`e` the difference of the two weight rows): position, velocity, quaternion and the
    /// angular velocity `I⁻¹ Rᵀ δL`. Infinite when the attempt is not finite.
    pub fn error_norm(&self, system: &System, states: &[BodyState], e: &[f64], h: f64, rtol: f64, atol: f64) -> f64 {
        let (mut sum, mut count) = (0.0, 0usize);
        let mut add = |delta: &[f64], y0: &[f64], y1: &[f64]| {
            for ((d, a), b) in delta.iter().zip(y0).zip(y1) {
                let scaled = d / (atol + rtol * a.abs().max(b.abs()));
                sum += scaled * scaled;
            }
            count += delta.len();
        };
        for (i, body) in system.bodies().iter().enumerate().filter(|(_, b)| !b.is_kinematic()) {
            let mut delta = REST;
            for (&weight, rates) in e.iter().zip(&self.rates) {
                if weight != 0.0 {
                    let rate = &rates[i];
                    delta.velocity += rate.velocity * weight;
                    delta.spin += rate.spin * weight;
                    delta.acceleration += rate.acceleration * weight;
                    delta.moment += rate.moment * weight;
                }
            }
            let (s0, s1) = (&self.start[i], &states[i]);
            let delta_omega = s1
                .orientation
                .inverse_transform_vector(&(delta.moment * h))
                .component_mul(&body.inverse_principal_moments);
            add((delta.velocity * h).as_slice(), s0.position.as_slice(), s1.position.as_slice());
            add((delta.acceleration * h).as_slice(), s0.velocity.as_slice(), s1.velocity.as_slice());
            add((delta.spin * h).coords.as_slice(), s0.orientation.coords.as_slice(), s1.orientation.coords.as_slice());
            add(delta_omega.as_slice(), s0.angular_velocity.as_slice(), s1.angular_velocity.as_slice());
        }
        let norm = if count == 0 { 0.0 } else { (sum / count as f64).sqrt() };
        if norm.is_finite() { norm } else { f64::INFINITY }
    }

    /// `y = y0 + h Σ_j a_j k_j` into `states` for the bodies that respond to forces.
    fn set_state(&self, system: &System, states: &mut [BodyState], a: &[f64], h: f64) {
        for (i, (state, body)) in states.iter_mut().zip(system.bodies()).enumerate() {
            if body.is_kinematic() {
                continue;
            }
            let start = &self.start[i];
            let (mut position, mut velocity, mut momentum, mut quaternion) =
                (start.position, start.velocity, self.momentum[i], start.orientation.into_inner());
            for (weight, rates) in a.iter().zip(&self.rates) {
                if *weight != 0.0 {
                    let (rate, w) = (&rates[i], weight * h);
                    position += rate.velocity * w;
                    velocity += rate.acceleration * w;
                    momentum += rate.moment * w;
                    quaternion += rate.spin * w;
                }
            }
            let orientation = Rotation::new_normalize(quaternion);
            *state = BodyState {
                position,
                orientation,
                velocity,
                angular_velocity: orientation
                    .inverse_transform_vector(&momentum)
                    .component_mul(&body.inverse_principal_moments),
            };
        }
    }

    /// The rates at `states` and time `time` [s] into slot `slot`: kinematic bodies prescribed,
    /// the force evaluation, then each body's derivative.
    fn evaluate(
        &mut self,
        system: &System,
        states: &mut [BodyState],
        evaluation: &mut Evaluation,
        time: f64,
        slot: usize,
    ) -> Result<(), EvaluationError> {
        system.prescribe(states, time);
        self.powers[slot] = system.evaluate(states, evaluation, time)?;
        let per_body = system.bodies().iter().zip(states.iter()).zip(&evaluation.frames).zip(&evaluation.loads);
        for ((((body, state), frame), load), rate) in per_body.zip(self.rates[slot].iter_mut()) {
            *rate = derivative(body, state, frame, load);
        }
        Ok(())
    }
}

/// A body at rest at the origin (the buffers' contents before the first step).
fn rest_state() -> BodyState {
    BodyState {
        position: Vec3::zeros(),
        orientation: Rotation::identity(),
        velocity: Vec3::zeros(),
        angular_velocity: Vec3::zeros(),
    }
}

/// `(v, ½ q ⊗ (0, ω), F/m, M)` of one body; fixed components and kinematic bodies at rest.
fn derivative(body: &RigidBody, state: &BodyState, frame: &BodyFrame, load: &Load) -> Rate {
    let moment = match &body.support {
        Support::Kinematic(_) => return REST,
        Support::Fixed { rotation: true, .. } => Vec3::zeros(),
        Support::Free | Support::Fixed { .. } => load.moment,
    };
    // The angular part is not used: the moment integrates into L directly.
    let linear =
        accelerations(body, &frame.rotation, &Load { force: load.force, moment: Vec3::zeros() }, &Vec3::zeros()).linear;
    let w = &state.angular_velocity;
    let spin = state.orientation.into_inner() * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
    Rate { velocity: state.velocity, spin, acceleration: linear, moment }
}
