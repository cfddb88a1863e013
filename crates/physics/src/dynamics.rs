//! Accelerations of a rigid body from its load (PHYSICS.md §1 \[13]–\[16]).
//!
//! `γ = F/m` [m/s²]; Euler's equations in the principal frame
//! `I1 α1 = M1 − (I3 − I2) ω2 ω3`, `I2 α2 = M2 − (I1 − I3) ω3 ω1`, `I3 α3 = M3 − (I2 − I1) ω1 ω2`
//! [rad/s²], which is `α = I⁻¹ (M − ω × Iω)`. Master-node supports then remove the accelerations
//! of the fixed components.

use crate::body::{Acceleration, Load, RigidBody, Support};
use crate::math::{Mat3, Vec3};

/// `α = I⁻¹ (M − ω × Iω)` in the principal frame, for moment `moment` and angular velocity
/// `omega` (both principal frame). The integrator chooses at which instant `omega` is taken.
#[inline(always)]
pub fn euler_angular_acceleration(body: &RigidBody, moment: &Vec3, omega: &Vec3) -> Vec3 {
    let inertia = body.principal_moments();
    let gyroscopic = omega.cross(&inertia.component_mul(omega));
    (moment - gyroscopic).component_mul(&body.inverse_principal_moments)
}

/// Accelerations of `body` with orientation `rotation` (principal → world) under `load` (world
/// axes), with the gyroscopic term evaluated at `omega` (principal frame), after its supports.
#[inline(always)]
pub fn accelerations(body: &RigidBody, rotation: &Mat3, load: &Load, omega: &Vec3) -> Acceleration {
    match &body.support {
        Support::Kinematic(_) => Acceleration::default(),
        Support::Free => free_accelerations(body, rotation, load, omega),
        Support::Fixed { translation, rotation: fixed_rotation } => {
            let mut acceleration = if *fixed_rotation {
                Acceleration { linear: load.force * body.inverse_mass, angular: Vec3::zeros() }
            } else {
                free_accelerations(body, rotation, load, omega)
            };
            for (axis, &held) in translation.iter().enumerate() {
                if held {
                    acceleration.linear[axis] = 0.0;
                }
            }
            acceleration
        }
    }
}

#[inline(always)]
fn free_accelerations(body: &RigidBody, rotation: &Mat3, load: &Load, omega: &Vec3) -> Acceleration {
    // Bodies held only at G (point masses on springs) carry no moment: skip the rotation.
    let m = &load.moment;
    let moment = if m.x == 0.0 && m.y == 0.0 && m.z == 0.0 { Vec3::zeros() } else { rotation.tr_mul(m) };
    Acceleration { linear: load.force * body.inverse_mass, angular: euler_angular_acceleration(body, &moment, omega) }
}
