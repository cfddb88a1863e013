//! Explicit Runge–Kutta machinery shared by [`super::rk4`] and [`super::dopri45`].
//!
//! The integrated variables of each body are position `x_G` [m], orientation quaternion `q`,
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
//! The energy ledger is one more integrated variable: dissipated and external work advance by
//! `h Σ b_j P_j` with the stage powers `P_j`, the same weights as the state, so the balance
//! keeps the scheme's order.

use crate::physics::body::{BodyState, RigidBody, Support};
use crate::physics::coupling::{BodyFrame, Load};
use crate::physics::dynamics::accelerations;
use crate::physics::energy::EnergyLedger;
use crate::physics::world::{StepError, World};
use crate::physics::{Rotation, Vec3};
use nalgebra::Quaternion;

/// An explicit Runge–Kutta scheme: `c_i`, the rows `a_ij` (j < i) and the weights `b_j`.
pub(crate) struct Tableau {
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
pub(crate) struct Rate {
    /// `ẋ = v` [m/s].
    velocity: Vec3,
    /// `q̇ = ½ q ⊗ (0, ω)` [1/s].
    spin: Quaternion<f64>,
    /// `v̇ = F/m` [m/s²].
    acceleration: Vec3,
    /// `L̇ = M` [N·m], world.
    moment: Vec3,
}

const REST: Rate = Rate { velocity: Vec3::new(0.0, 0.0, 0.0), spin: Quaternion::new(0.0, 0.0, 0.0, 0.0), acceleration: Vec3::new(0.0, 0.0, 0.0), moment: Vec3::new(0.0, 0.0, 0.0) };

/// Buffers of a Runge–Kutta world, allocated once at the start.
#[derive(Debug, Clone, Default)]
pub(crate) struct Workspace {
    /// States at the start of the step being attempted.
    start: Vec<BodyState>,
    /// World angular momenta at the start of the step [kg·m²/s].
    momentum: Vec<Vec3>,
    /// `rates[slot][body]`; slot 0 holds the rates at the current state.
    rates: Vec<Vec<Rate>>,
    /// Dissipated and external power at each slot [W].
    powers: Vec<(f64, f64)>,
    /// [`super::dopri45`]'s proposal for its next step [s] (0 before the first).
    pub next_step: f64,
}

/// Evaluates the rates at t = 0 into slot 0 and starts the energy ledger.
pub(crate) fn start(world: &mut World, tableau: &Tableau) -> Result<(), StepError> {
    let n = world.bodies.len();
    let slots = tableau.slots();
    world.runge_kutta = Workspace { start: world.states.clone(), momentum: vec![Vec3::zeros(); n], rates: vec![vec![REST; n]; slots], powers: vec![(0.0, 0.0); slots], next_step: 0.0 };
    let time = world.time();
    evaluate(world, time, 0)?;
    let (dissipated, external) = world.runge_kutta.powers[0];
    world.ledger = EnergyLedger::new(dissipated, external);
    world.body_energy = synchronous_body_energy(world);
    Ok(())
}

/// Attempts a step of `h` [s] from the current state: evaluates the stages and leaves the new
/// state (synchronised) in `world.states`, with the forces evaluated there. Returns the slot
/// that holds the rates at the new state. The clock is not moved; [`accept`] or [`reject`]
/// must follow.
pub(crate) fn attempt(world: &mut World, tableau: &Tableau, h: f64) -> Result<usize, StepError> {
    let t0 = world.time();
    let workspace = &mut world.runge_kutta;
    workspace.start.copy_from_slice(&world.states);
    for ((momentum, state), body) in workspace.momentum.iter_mut().zip(&world.states).zip(&world.bodies) {
        *momentum = state.orientation * body.principal_moments().component_mul(&state.angular_velocity);
    }
    for stage in 1..tableau.stages() {
        set_state(world, tableau.a[stage], h);
        evaluate(world, t0 + tableau.c[stage] * h, stage)?;
    }
    if tableau.first_same_as_last() {
        return Ok(tableau.stages() - 1);
    }
    let last = tableau.stages();
    set_state(world, tableau.b, h);
    evaluate(world, t0 + h, last)?;
    Ok(last)
}

/// Accepts the attempted step of `h` whose new rates are in slot `last`: the ledger advances
/// with the weights `b`, the new rates become slot 0, and the bodies' energies are updated.
pub(crate) fn accept(world: &mut World, tableau: &Tableau, h: f64, last: usize) {
    let workspace = &mut world.runge_kutta;
    let (dissipated, external) = tableau.b.iter().zip(&workspace.powers).fold((0.0, 0.0), |(d, e), (b, (pd, pe))| (d + b * pd, e + b * pe));
    world.ledger.add(h * dissipated, h * external);
    workspace.rates.swap(0, last);
    workspace.powers.swap(0, last);
    world.body_energy = synchronous_body_energy(world);
}

/// Puts the world back at the start of the rejected attempt (slot 0 still holds its rates).
pub(crate) fn reject(world: &mut World) {
    world.states.copy_from_slice(&world.runge_kutta.start);
}

/// Root-mean-square of `δ_i / (atol + rtol·max(|y0_i|, |y1_i|))` over the components of the
/// bodies that respond to forces, with `δ = h Σ_j e_j k_j` the error estimate of the attempted
/// step (`e` the difference of the two weight rows): position, velocity, quaternion and the
/// angular velocity `I⁻¹ Rᵀ δL`. Infinite when the attempt is not finite.
pub(crate) fn error_norm(world: &World, e: &[f64], h: f64, rtol: f64, atol: f64) -> f64 {
    let workspace = &world.runge_kutta;
    let (mut sum, mut count) = (0.0, 0usize);
    let mut add = |delta: &[f64], y0: &[f64], y1: &[f64]| {
        for ((d, a), b) in delta.iter().zip(y0).zip(y1) {
            let scaled = d / (atol + rtol * a.abs().max(b.abs()));
            sum += scaled * scaled;
        }
        count += delta.len();
    };
    for (i, body) in world.bodies.iter().enumerate().filter(|(_, b)| !b.is_kinematic()) {
        let mut delta = REST;
        for (&weight, rates) in e.iter().zip(&workspace.rates) {
            if weight != 0.0 {
                let rate = &rates[i];
                delta.velocity += rate.velocity * weight;
                delta.spin += rate.spin * weight;
                delta.acceleration += rate.acceleration * weight;
                delta.moment += rate.moment * weight;
            }
        }
        let (s0, s1) = (&workspace.start[i], &world.states[i]);
        let delta_omega = s1.orientation.inverse_transform_vector(&(delta.moment * h)).component_mul(&body.inverse_principal_moments);
        add((delta.velocity * h).as_slice(), s0.position.as_slice(), s1.position.as_slice());
        add((delta.acceleration * h).as_slice(), s0.velocity.as_slice(), s1.velocity.as_slice());
        add((delta.spin * h).coords.as_slice(), s0.orientation.coords.as_slice(), s1.orientation.coords.as_slice());
        add(delta_omega.as_slice(), s0.angular_velocity.as_slice(), s1.angular_velocity.as_slice());
    }
    let norm = if count == 0 { 0.0 } else { (sum / count as f64).sqrt() };
    if norm.is_finite() { norm } else { f64::INFINITY }
}

/// `y = y0 + h Σ_j a_j k_j` into `world.states` for the bodies that respond to forces.
fn set_state(world: &mut World, a: &[f64], h: f64) {
    let workspace = &world.runge_kutta;
    for (i, (state, body)) in world.states.iter_mut().zip(&world.bodies).enumerate() {
        if body.is_kinematic() {
            continue;
        }
        let start = &workspace.start[i];
        let (mut position, mut velocity, mut momentum, mut quaternion) = (start.position, start.velocity, workspace.momentum[i], start.orientation.into_inner());
        for (weight, rates) in a.iter().zip(&workspace.rates) {
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
            angular_velocity: orientation.inverse_transform_vector(&momentum).component_mul(&body.inverse_principal_moments),
        };
    }
}

/// The rates at the current states and time `time` [s] into slot `slot`: kinematic bodies
/// prescribed, kinematics, gravity and couplings, then each body's derivative.
fn evaluate(world: &mut World, time: f64, slot: usize) -> Result<(), StepError> {
    world.prescribe_kinematic_bodies(time);
    for (frame, state) in world.frames.iter_mut().zip(&world.states) {
        *frame = BodyFrame { position: state.position, rotation: state.orientation.to_rotation_matrix().into_inner(), velocity: state.velocity, angular_velocity: state.angular_velocity };
    }
    let dissipated = world.evaluate_loads()?;
    world.runge_kutta.powers[slot] = (dissipated, world.external_power());
    let per_body = world.bodies.iter().zip(&world.states).zip(&world.frames).zip(&world.loads);
    for ((((body, state), frame), load), rate) in per_body.zip(world.runge_kutta.rates[slot].iter_mut()) {
        *rate = derivative(body, state, frame, load);
    }
    Ok(())
}

/// `(v, ½ q ⊗ (0, ω), F/m, M)` of one body; fixed components and kinematic bodies at rest.
fn derivative(body: &RigidBody, state: &BodyState, frame: &BodyFrame, load: &Load) -> Rate {
    let moment = match &body.support {
        Support::Kinematic(_) => return REST,
        Support::Fixed { rotation: true, .. } => Vec3::zeros(),
        Support::Free | Support::Fixed { .. } => load.moment,
    };
    // The angular part is not used: the moment integrates into L directly.
    let linear = accelerations(body, &frame.rotation, &Load { force: load.force, moment: Vec3::zeros() }, &Vec3::zeros()).linear;
    let w = &state.angular_velocity;
    let spin = state.orientation.into_inner() * Quaternion::new(0.0, w.x, w.y, w.z) * 0.5;
    Rate { velocity: state.velocity, spin, acceleration: linear, moment }
}

/// Kinetic and gravity energy [J] of the bodies that respond to forces, from the synchronised
/// states.
pub(crate) fn synchronous_body_energy(world: &World) -> (f64, f64) {
    world.bodies.iter().zip(&world.states).filter(|(b, _)| !b.is_kinematic()).fold((0.0, 0.0), |(k, g), (body, state)| {
        (k + body.kinetic_energy(&state.velocity, &state.angular_velocity), g - body.mass() * world.gravity.dot(&state.position))
    })
}
