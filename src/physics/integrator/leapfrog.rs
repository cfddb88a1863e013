//! The seed's leapfrog (central difference) scheme, as Radioss does it (PHYSICS.md §1 [17]–[18]).
//!
//! `v(t+½dt) = v(t−½dt) + γ(t) dt`, `ω(t+½dt) = ω(t−½dt) + α(t) dt` (ω in the principal frame),
//! `x_G(t+dt) = x_G(t) + v(t+½dt) dt`, `q(t+dt) = q(t) ⊗ exp(ω(t+½dt) dt)` (exact rotation by
//! the rotation vector, then renormalised).
//!
//! - Order: 2 in translation; 1 in rotation, because the gyroscopic term `ω × Iω` at t only has
//!   `ω(t−½dt)` available (|L| and energy of a precessing body drift ~ exp(½ Ω² dt T)).
//! - Velocity-dependent forces (dampers) see the predicted `v(t) ≈ v(t−½dt) + ½dt γ(t−dt)`,
//!   which keeps them second order.
//! - Conserves: linear momentum exactly (forces are pairwise equal and opposite); symplectic
//!   for conservative translational forces, so energy oscillates with no trend.
//! - Stability: `ω_max dt < 2` for an undamped spring, `2(√(1+ζ²) − ζ)` with damping.
//! - Cost: one force evaluation per step.

use crate::physics::body::BodyState;
use crate::physics::coupling::BodyFrame;
use crate::physics::dynamics::accelerations;
use crate::physics::energy::EnergyLedger;
use crate::physics::world::World;
use crate::physics::{Rotation, Vec3};

/// Evaluates t = 0 and turns the synchronised initial velocities into `v(−½dt) = v(0) − ½dt γ(0)`.
pub(crate) fn start(world: &mut World) {
    world.prescribe_kinematic_bodies();
    for (frame, state) in world.frames.iter_mut().zip(&world.states) {
        *frame = body_frame(state, state.velocity, state.angular_velocity);
    }
    world.evaluate_loads();
    compute_accelerations(world);
    let half = 0.5 * world.dt();
    for ((state, acceleration), body) in world.states.iter_mut().zip(&world.accelerations).zip(&world.bodies) {
        if !body.is_kinematic() {
            state.velocity -= acceleration.linear * half;
            state.angular_velocity -= acceleration.angular * half;
        }
    }
    world.ledger = EnergyLedger::new(world.dissipated_power(), world.external_power());
}

/// One leapfrog step: kick, drift, then the force stages at the new time.
pub(crate) fn step(world: &mut World) {
    let dt = world.dt();
    kick_and_drift(world, dt);
    world.advance_clock();
    world.prescribe_kinematic_bodies();
    predict_frames(world, 0.5 * dt);
    world.evaluate_loads();
    compute_accelerations(world);
    world.ledger.advance(dt, world.dissipated_power(), world.external_power());
}

/// The state at the current time t, velocities synchronised: `v(t) = v(t−½dt) + ½dt γ(t)`.
pub(crate) fn synchronized_state(world: &World, index: usize) -> BodyState {
    let mut state = world.states[index];
    if !world.bodies[index].is_kinematic() {
        let half = 0.5 * world.dt();
        state.velocity += world.accelerations[index].linear * half;
        state.angular_velocity += world.accelerations[index].angular * half;
    }
    state
}

/// `v += γ dt`, `ω += α dt` (fixed components stay at rest), then `x += v dt`, `q ⊗= exp(ω dt)`.
fn kick_and_drift(world: &mut World, dt: f64) {
    for ((state, acceleration), body) in world.states.iter_mut().zip(&world.accelerations).zip(&world.bodies) {
        if body.is_kinematic() {
            continue;
        }
        state.velocity += acceleration.linear * dt;
        state.angular_velocity += acceleration.angular * dt;
        if let crate::physics::body::Support::Fixed { translation, rotation } = &body.support {
            for axis in (0..3).filter(|&axis| translation[axis]) {
                state.velocity[axis] = 0.0;
            }
            if *rotation {
                state.angular_velocity = Vec3::zeros();
            }
        }
        state.position += state.velocity * dt;
        state.orientation = rotate_by(&state.orientation, &(state.angular_velocity * dt));
    }
}

/// `q ⊗ exp(φ)` for a rotation vector `φ` in the body frame [rad], renormalised.
pub(crate) fn rotate_by(orientation: &Rotation, rotation_vector: &Vec3) -> Rotation {
    let angle = rotation_vector.norm();
    let (sin_half, cos_half) = (0.5 * angle).sin_cos();
    // sin(θ/2)/θ, with its series where θ is too small to divide by.
    let scale = if angle > 1e-8 { sin_half / angle } else { 0.5 - angle * angle / 48.0 };
    let v = rotation_vector * scale;
    let increment = nalgebra::Quaternion::new(cos_half, v.x, v.y, v.z);
    Rotation::new_normalize(orientation.into_inner() * increment)
}

/// Kinematics at the new time for the force stage: dynamic bodies get the predicted velocities
/// `v(t−½dt) + ½dt γ(t−dt)`; kinematic bodies their prescribed ones.
fn predict_frames(world: &mut World, half_dt: f64) {
    for (((frame, state), acceleration), body) in
        world.frames.iter_mut().zip(&world.states).zip(&world.accelerations).zip(&world.bodies)
    {
        *frame = if body.is_kinematic() {
            body_frame(state, state.velocity, state.angular_velocity)
        } else {
            body_frame(state, state.velocity + acceleration.linear * half_dt, state.angular_velocity + acceleration.angular * half_dt)
        };
    }
}

fn body_frame(state: &BodyState, velocity: Vec3, angular_velocity: Vec3) -> BodyFrame {
    let rotation = state.orientation.to_rotation_matrix().into_inner();
    BodyFrame { position: state.position, rotation, velocity, angular_velocity: rotation * angular_velocity }
}

/// Stage *accelerations*: Euler's equations with the gyroscopic term at `ω(t−½dt)` (the seed's choice).
fn compute_accelerations(world: &mut World) {
    for (index, body) in world.bodies.iter().enumerate() {
        let state = &world.states[index];
        world.accelerations[index] = accelerations(body, &state.orientation, &world.loads[index], &state.angular_velocity);
    }
}
