//! The seed's leapfrog (central difference) scheme, as Radioss does it (PHYSICS.md §1 [17]–[18]).
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

use crate::physics::body::{BodyState, RigidBody, Support, prescribed_state};
use crate::physics::coupling::BodyFrame;
use crate::physics::dynamics::{Acceleration, accelerations};
use crate::physics::energy::EnergyLedger;
use crate::physics::world::{StepError, World, gravity_load};
use crate::physics::{Rotation, Vec3};

/// Evaluates t = 0 and turns the synchronised initial velocities into `v(−½dt) = v(0) − ½dt γ(0)`.
pub(crate) fn start(world: &mut World) -> Result<(), StepError> {
    let time = world.time();
    world.prescribe_kinematic_bodies(time);
    for (frame, state) in world.frames.iter_mut().zip(&world.states) {
        *frame = body_frame(state);
    }
    let dissipated = world.evaluate_loads()?;
    // The initial velocities are synchronised: ω(0) is exact for either variant.
    compute_accelerations(world, Gyroscopic::Lagged);
    let half = 0.5 * world.step_size();
    for ((state, acceleration), body) in world.states.iter_mut().zip(&world.accelerations).zip(&world.bodies) {
        if !body.is_kinematic() {
            state.velocity -= acceleration.linear * half;
            state.angular_velocity -= acceleration.angular * half;
        }
    }
    world.body_energy = kinetic_and_gravity(world);
    world.ledger = EnergyLedger::new(dissipated, world.external_power());
    Ok(())
}

/// At which angular velocity the gyroscopic term `ω × Iω` is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Gyroscopic {
    /// `ω(t−½dt)`, the seed's (first order in rotation).
    Lagged,
    /// `ω(t) ≈ ω(t−½dt) + ½dt α(t−dt)` ([`super::leapfrog2`], second order).
    Predicted,
}

/// One leapfrog step. Stages 1–4 (advance, prescribe, predict, clear + gravity) run in two
/// passes over the bodies, translation first and rotation second (a short loop, in which the
/// processor overlaps one body's chain of rotation arithmetic with the next's); then couplings,
/// accelerations and the ledger. Built for AVX2 as well, chosen at run time, with the per-body
/// stages inlined (same results, bit for bit: no fused multiply–add is introduced).
#[multiversion::multiversion(targets("x86_64+avx2+fma"))]
pub(crate) fn step(world: &mut World, gyroscopic: Gyroscopic) -> Result<(), StepError> {
    let dt = world.step_size();
    world.advance_clock();
    let time = world.time();
    let per_body = world
        .bodies
        .iter()
        .zip(world.states.iter_mut())
        .zip(&world.accelerations)
        .zip(world.frames.iter_mut())
        .zip(world.loads.iter_mut())
        .zip(&world.initial_states);
    for (((((body, state), acceleration), frame), load), initial) in per_body {
        match &body.support {
            Support::Kinematic(motion) => {
                *state = prescribed_state(motion, initial, time);
                *frame = body_frame(state);
            }
            support => {
                kick_and_drift(state, acceleration, support, dt);
                // Velocity-dependent forces see v(t−½dt), as in Radioss.
                frame.position = state.position;
                frame.velocity = state.velocity;
                frame.angular_velocity = state.angular_velocity;
            }
        }
        *load = gravity_load(&world.gravity, body);
    }
    for ((body, state), frame) in world.bodies.iter().zip(world.states.iter_mut()).zip(world.frames.iter_mut()) {
        // A body that does not turn keeps its orientation and rotation matrix.
        if !body.is_kinematic() && turn(state, dt) {
            frame.rotation = rotation_matrix(state);
        }
    }
    let dissipated = world.apply_couplings()?;
    compute_accelerations(world, gyroscopic);
    world.ledger.advance(dt, dissipated, world.external_power());
    Ok(())
}

/// The state at the current time t, velocities synchronised: `v(t) = v(t−½dt) + ½dt γ(t)`.
pub(crate) fn synchronized_state(world: &World, index: usize) -> BodyState {
    let mut state = world.states[index];
    if !world.bodies[index].is_kinematic() {
        let half = 0.5 * world.step_size();
        state.velocity += world.accelerations[index].linear * half;
        state.angular_velocity += world.accelerations[index].angular * half;
    }
    state
}

/// `Σ ½ m |v(t)|² + ½ ω(t)ᵀ I ω(t)` and `Σ −m g·x_G` [J] over the bodies that respond to
/// forces, with the synchronised velocities.
fn kinetic_and_gravity(world: &World) -> (f64, f64) {
    let half = 0.5 * world.step_size();
    world.bodies.iter().zip(&world.states).zip(&world.accelerations).fold((0.0, 0.0), |(k, g), ((body, state), acceleration)| {
        let (dk, dg) = body_energy(body, state, acceleration, half, &world.gravity);
        (k + dk, g + dg)
    })
}

/// Kinetic energy `½ m |v(t)|² + ½ ω(t)ᵀ I ω(t)` and gravity energy `−m g·x_G` [J] of one body
/// (zero for a kinematic body), `v(t) = v(t−½dt) + ½dt γ(t)`.
#[inline(always)]
fn body_energy(body: &RigidBody, state: &BodyState, acceleration: &Acceleration, half: f64, gravity: &Vec3) -> (f64, f64) {
    if body.is_kinematic() {
        return (0.0, 0.0);
    }
    let velocity = state.velocity + acceleration.linear * half;
    let spin = state.angular_velocity + acceleration.angular * half;
    (body.kinetic_energy(&velocity, &spin), -body.mass() * gravity.dot(&state.position))
}

/// Stage *advance* of one body, translation: `v += γ dt`, `ω += α dt` (fixed components stay
/// at rest), then `x += v dt`.
#[inline(always)]
fn kick_and_drift(state: &mut BodyState, acceleration: &Acceleration, support: &Support, dt: f64) {
    kick(state, acceleration, support, dt);
    state.position += state.velocity * dt;
}

/// Stage *advance* of one body, rotation: `q ⊗= exp(ω dt)`. Returns whether the body turned: one
/// with `ω = 0` exactly (a point mass held at G, a fixed rotation) pays nothing for rotation.
#[inline(always)]
fn turn(state: &mut BodyState, dt: f64) -> bool {
    let w = &state.angular_velocity;
    let turned = w.x != 0.0 || w.y != 0.0 || w.z != 0.0;
    if turned {
        state.orientation = rotate_by(&state.orientation, &(state.angular_velocity * dt));
    }
    turned
}

/// `v += γ h`, `ω += α h`, fixed components held at rest.
#[inline(always)]
pub(crate) fn kick(state: &mut BodyState, acceleration: &Acceleration, support: &Support, h: f64) {
    // Worked out in locals and written once: updated in place, the state was written
    // component by component and read straight back as vectors, which stalled the processor
    // (a load spanning two stores is not forwarded from them).
    let mut velocity = state.velocity + acceleration.linear * h;
    let mut angular_velocity = state.angular_velocity + acceleration.angular * h;
    support.hold(&mut velocity, &mut angular_velocity);
    (state.velocity, state.angular_velocity) = (velocity, angular_velocity);
}

/// `q ⊗ exp(φ)` for a rotation vector `φ` in the body frame [rad], renormalised.
///
/// `exp(φ) = (cos(θ/2), sin(θ/2)/θ · φ)`, θ = |φ|. Below θ = 0.05 rad (the usual case: stable
/// steps keep ω dt well under 1) both factors are taken from their Taylor series to θ⁶, whose
/// remainder (< θ⁸/10⁷ ≈ 4e-18) is below double-precision round-off; above, from `sin_cos`.
#[inline(always)]
pub(crate) fn rotate_by(orientation: &Rotation, rotation_vector: &Vec3) -> Rotation {
    let angle_squared = rotation_vector.norm_squared();
    let (cos_half, sin_half_over_angle) = if angle_squared < 0.05 * 0.05 {
        // Multiplications by constant reciprocals: a division here would cost more than the
        // whole series.
        let t = angle_squared;
        (
            1.0 - t * (1.0 / 8.0) * (1.0 - t * (1.0 / 48.0) * (1.0 - t * (1.0 / 120.0))),
            0.5 * (1.0 - t * (1.0 / 24.0) * (1.0 - t * (1.0 / 80.0) * (1.0 - t * (1.0 / 168.0)))),
        )
    } else {
        let angle = angle_squared.sqrt();
        let (sin_half, cos_half) = (0.5 * angle).sin_cos();
        (cos_half, sin_half / angle)
    };
    let v = rotation_vector * sin_half_over_angle;
    let increment = nalgebra::Quaternion::new(cos_half, v.x, v.y, v.z);
    renormalize(orientation.into_inner() * increment)
}

/// Pulls a quaternion that is unit up to round-off back onto the unit sphere with one Newton
/// step for `1/|q|`: `q (3 − |q|²)/2`. The error ε = |q|² − 1 becomes O(ε²), so round-off
/// cannot accumulate, and there is no square root or division in the hot loop.
pub(crate) fn renormalize(q: nalgebra::Quaternion<f64>) -> Rotation {
    Rotation::new_unchecked(q * (1.5 - 0.5 * q.norm_squared()))
}

/// Stage *predict*: the kinematics the forces see, world axes.
#[inline(always)]
pub(crate) fn body_frame(state: &BodyState) -> BodyFrame {
    BodyFrame { position: state.position, rotation: rotation_matrix(state), velocity: state.velocity, angular_velocity: state.angular_velocity }
}

/// The principal frame → world rotation matrix of `state`'s orientation.
#[inline(always)]
fn rotation_matrix(state: &BodyState) -> crate::physics::Mat3 {
    state.orientation.to_rotation_matrix().into_inner()
}

/// Stage *accelerations*: Euler's equations with the gyroscopic term at the chosen angular
/// velocity. In the same pass, the bodies' kinetic and gravity energies at t.
#[inline(always)]
fn compute_accelerations(world: &mut World, gyroscopic: Gyroscopic) {
    let half = 0.5 * world.step_size();
    let (mut kinetic, mut gravity) = (0.0, 0.0);
    let per_body = world.bodies.iter().zip(&world.states).zip(&world.frames).zip(&world.loads);
    for ((((body, state), frame), load), acceleration) in per_body.zip(world.accelerations.iter_mut()) {
        let omega = match gyroscopic {
            Gyroscopic::Lagged => state.angular_velocity,
            // `acceleration` still holds α(t−dt) here.
            Gyroscopic::Predicted => state.angular_velocity + acceleration.angular * half,
        };
        *acceleration = accelerations(body, &frame.rotation, load, &omega);
        let (dk, dg) = body_energy(body, state, acceleration, half, &world.gravity);
        kinetic += dk;
        gravity += dg;
    }
    world.body_energy = (kinetic, gravity);
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn rotation_increment_matches_the_exact_exponential_on_both_sides_of_the_series_switch() {
        let start = Rotation::from_euler_angles(0.3, -0.2, 1.1);
        for angle in [0.0, 1e-9, 1e-4, 0.01, 0.0499, 0.0501, 0.3, 2.0] {
            let phi = Vec3::new(1.0, -2.0, 0.5).normalize() * angle;
            let expected = start * Rotation::from_scaled_axis(phi);
            assert_relative_eq!(rotate_by(&start, &phi), expected, epsilon = 4e-16);
        }
    }

    #[test]
    fn a_million_increments_stay_unit() {
        let mut q = Rotation::identity();
        for i in 0..1_000_000 {
            q = rotate_by(&q, &Vec3::new(0.013, -0.007 * (i % 7) as f64, 0.021));
        }
        assert_relative_eq!(q.quaternion().norm(), 1.0, epsilon = 1e-14);
    }
}
