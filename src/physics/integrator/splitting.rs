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

use super::leapfrog::{body_frame, kick, renormalize};
use crate::physics::body::{BodyState, RigidBody, Support, prescribed_state};
use crate::physics::dynamics::accelerations;
use crate::physics::energy::EnergyLedger;
use crate::physics::world::{StepError, World, gravity_load};
use crate::physics::Vec3;
use nalgebra::Quaternion;

/// Evaluates t = 0: forces, and the accelerations of the first kick (velocities stay
/// synchronised).
pub(crate) fn start(world: &mut World) -> Result<(), StepError> {
    let time = world.time();
    world.prescribe_kinematic_bodies(time);
    for (frame, state) in world.frames.iter_mut().zip(&world.states) {
        *frame = body_frame(state);
    }
    let dissipated = world.evaluate_loads()?;
    kick_and_energies(world, 0.0);
    world.ledger = EnergyLedger::new(dissipated, world.external_power());
    Ok(())
}

/// One step of `dt / substeps`: kick, drift (with the rotation sequence), forces, kick.
pub(crate) fn step(world: &mut World) -> Result<(), StepError> {
    let h = world.step_size();
    world.advance_clock();
    let time = world.time();
    let per_body = world.bodies.iter().zip(world.states.iter_mut()).zip(&world.accelerations).zip(world.frames.iter_mut()).zip(world.loads.iter_mut()).zip(&world.initial_states);
    for (((((body, state), acceleration), frame), load), initial) in per_body {
        if let Support::Kinematic(motion) = &body.support {
            *state = prescribed_state(motion, initial, time);
            *frame = body_frame(state);
        } else {
            kick(state, acceleration, &body.support, 0.5 * h);
            state.position += state.velocity * h;
            if rotate_freely(body, state, h) {
                *frame = body_frame(state);
            } else {
                frame.position = state.position;
                frame.velocity = state.velocity;
                frame.angular_velocity = state.angular_velocity;
            }
        }
        *load = gravity_load(&world.gravity, body);
    }
    let dissipated = world.apply_couplings()?;
    kick_and_energies(world, 0.5 * h);
    world.ledger.advance(h, dissipated, world.external_power());
    Ok(())
}

/// Accelerations from the loads (the moment's part only: the rotation sequence carries the
/// gyroscopic term), the closing kick by `half` [s], and the bodies' kinetic and gravity
/// energies at the now synchronised velocities.
fn kick_and_energies(world: &mut World, half: f64) {
    let (mut kinetic, mut gravity) = (0.0, 0.0);
    let per_body = world.bodies.iter().zip(world.states.iter_mut()).zip(&world.frames).zip(&world.loads);
    for ((((body, state), frame), load), acceleration) in per_body.zip(world.accelerations.iter_mut()) {
        if body.is_kinematic() {
            continue;
        }
        *acceleration = accelerations(body, &frame.rotation, load, &Vec3::zeros());
        kick(state, acceleration, &body.support, half);
        kinetic += body.kinetic_energy(&state.velocity, &state.angular_velocity);
        gravity -= body.mass() * world.gravity.dot(&state.position);
    }
    world.body_energy = (kinetic, gravity);
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
