//! The moves every integrator is built of (PHYSICS.md §1, time integration): a *kick* changes
//! velocities by accelerations over a time, a *drift* moves the position by the velocity, a
//! *turn* rotates the orientation exactly by `ω h`. Fixed components of a support stay at rest.

use super::state::{Acceleration, BodyState};
use super::support::Support;
use crate::math::{Rotation, Vec3};

/// `v += γ h`, `ω += α h` [m/s, rad/s], fixed components held at rest.
#[inline(always)]
pub fn kick(state: &mut BodyState, acceleration: &Acceleration, support: &Support, h: f64) {
    // Worked out in locals and written once: updated in place, the state was written
    // component by component and read straight back as vectors, which stalled the processor
    // (a load spanning two stores is not forwarded from them).
    let mut velocity = state.velocity + acceleration.linear * h;
    let mut angular_velocity = state.angular_velocity + acceleration.angular * h;
    support.hold(&mut velocity, &mut angular_velocity);
    (state.velocity, state.angular_velocity) = (velocity, angular_velocity);
}

/// `x += v h` \[m].
#[inline(always)]
pub fn drift(state: &mut BodyState, h: f64) {
    state.position += state.velocity * h;
}

/// `q ⊗= exp(ω h)`. Returns whether the body turned: one with `ω = 0` exactly (a point mass
/// held at G, a fixed rotation) pays nothing for rotation.
#[inline(always)]
pub fn turn(state: &mut BodyState, h: f64) -> bool {
    let w = &state.angular_velocity;
    let turned = w.x != 0.0 || w.y != 0.0 || w.z != 0.0;
    if turned {
        state.orientation = rotate_by(&state.orientation, &(state.angular_velocity * h));
    }
    turned
}

/// `q ⊗ exp(φ)` for a rotation vector `φ` in the body frame \[rad], renormalised.
///
/// `exp(φ) = (cos(θ/2), sin(θ/2)/θ · φ)`, θ = |φ|. Below θ = 0.05 rad (the usual case: stable
/// steps keep ω dt well under 1) both factors are taken from their Taylor series to θ⁶, whose
/// remainder (< θ⁸/10⁷ ≈ 4e-18) is below double-precision round-off; above, from `sin_cos`.
#[inline(always)]
pub fn rotate_by(orientation: &Rotation, rotation_vector: &Vec3) -> Rotation {
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
#[inline(always)]
pub fn renormalize(q: nalgebra::Quaternion<f64>) -> Rotation {
    Rotation::new_unchecked(q * (1.5 - 0.5 * q.norm_squared()))
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
