//! Boundary conditions of a body's master node (PHYSICS.md §1 [BC section]; slave nodes carry none):
//! fixed components, or a prescribed (kinematic) motion that forces do not change.

use super::state::BodyState;
use crate::math::{Rotation, Vec3};
use crate::parameter::{Bound, ParameterError, require};
use std::f64::consts::TAU;

/// Velocity of a kinematic body's master node, world frame [m/s]; each profile's velocity is
/// continuous in time (a table's is piecewise linear), so the driven couplings see no jump.
#[derive(Debug, Clone, PartialEq)]
pub enum VelocityProfile {
    Constant(Vec3),
    /// `(t [s], v [m/s])` points with strictly increasing t; linear between them, held beyond.
    Table(Vec<(f64, Vec3)>),
    /// A forced oscillation, per axis `x(t) = x0 + A sin(ωt + φ)`: see [`Harmonic`].
    Harmonic(Harmonic),
}

/// A harmonic prescribed motion (PHYSICS.md §1 [BC section]), per world axis i:
/// `x_i(t) = x0_i + A_i sin(ω t + φ_i)`, `v_i(t) = A_i ω cos(ω t + φ_i)`, `ω = 2π / T`.
///
/// The body starts where the scene puts it, `x(0) = x_start`, so the centre of the oscillation
/// is `x0 = x_start − A sin φ` (the start itself when φ = 0). Amplitudes `A` \[m] (any sign,
/// finite), one period `T` \[s] (> 0) for the three axes, phases `φ` \[rad] (finite), each
/// checked once by [`Harmonic::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    amplitude: Vec3,
    omega: f64,
    phase: Vec3,
}

impl Harmonic {
    /// The oscillation of `amplitude` \[m] per axis, `period` \[s] and `phase` \[rad] per axis.
    ///
    /// # Errors
    /// [`ParameterError::OutOfRange`] naming `amplitude` (not finite), `period` (not > 0) or
    /// `phase` (not finite).
    pub fn new(amplitude: Vec3, period: f64, phase: Vec3) -> Result<Self, ParameterError> {
        for axis in 0..3 {
            require("amplitude", amplitude[axis], Bound::Finite, "m")?;
            require("phase", phase[axis], Bound::Finite, "rad")?;
        }
        let period = require("period", period, Bound::Positive, "s")?;
        Ok(Self { amplitude, omega: TAU / period, phase })
    }

    /// Amplitude `A` per axis \[m].
    pub fn amplitude(&self) -> Vec3 {
        self.amplitude
    }

    /// Period `T = 2π / ω` \[s].
    pub fn period(&self) -> f64 {
        TAU / self.omega
    }

    /// Phase `φ` per axis \[rad].
    pub fn phase(&self) -> Vec3 {
        self.phase
    }

    /// `v(t) = A ω cos(ω t + φ)` per axis \[m/s].
    pub fn velocity(&self, t: f64) -> Vec3 {
        let wt = self.omega * t;
        Vec3::from_fn(|i, _| self.amplitude[i] * self.omega * (wt + self.phase[i]).cos())
    }

    /// `x(t) − x(0) = A (sin(ω t + φ) − sin φ)` per axis \[m].
    pub fn displacement(&self, t: f64) -> Vec3 {
        let wt = self.omega * t;
        Vec3::from_fn(|i, _| self.amplitude[i] * ((wt + self.phase[i]).sin() - self.phase[i].sin()))
    }
}

impl VelocityProfile {
    /// `v(t)` [m/s].
    pub fn velocity(&self, t: f64) -> Vec3 {
        match self {
            Self::Constant(v) => *v,
            Self::Table(points) => {
                let after = points.partition_point(|(ti, _)| *ti <= t);
                if after == 0 {
                    points[0].1
                } else if after == points.len() {
                    points[after - 1].1
                } else {
                    let ((ta, va), (tb, vb)) = (points[after - 1], points[after]);
                    va + (vb - va) * ((t - ta) / (tb - ta))
                }
            }
            Self::Harmonic(harmonic) => harmonic.velocity(t),
        }
    }

    /// Displacement `∫_0^t v dt'` \[m], exact for every profile (the table's trapezoids are exact
    /// for its piecewise-linear velocity; the harmonic one is integrated in closed form).
    pub fn displacement(&self, t: f64) -> Vec3 {
        match self {
            Self::Constant(v) => v * t,
            Self::Table(points) => {
                let mut knots: Vec<f64> = vec![0.0];
                knots.extend(points.iter().map(|(ti, _)| *ti).filter(|&ti| ti > 0.0 && ti < t));
                knots.push(t);
                // v is linear between consecutive knots, so the trapezoid rule is exact.
                knots.windows(2).map(|w| (self.velocity(w[0]) + self.velocity(w[1])) * (0.5 * (w[1] - w[0]))).sum()
            }
            Self::Harmonic(harmonic) => harmonic.displacement(t),
        }
    }
}

/// Prescribed (kinematic) motion of a master node: the body moves as told, whatever the forces.
#[derive(Debug, Clone, PartialEq)]
pub struct PrescribedMotion {
    pub velocity: VelocityProfile,
    /// Constant angular velocity about G, world frame [rad/s].
    pub angular_velocity: Vec3,
}

/// Boundary conditions of the master node (PHYSICS.md §1 [BC section]; slave nodes carry none).
#[derive(Debug, Clone, PartialEq)]
pub enum Support {
    Free,
    /// Fixed world translation components (x, y, z) and, optionally, fixed rotation.
    Fixed {
        translation: [bool; 3],
        rotation: bool,
    },
    Kinematic(PrescribedMotion),
}

impl Support {
    /// Sets to zero the velocity components [m/s] and, for a fixed rotation, the angular
    /// velocity [rad/s] (any axes: all of it) that a [`Support::Fixed`] holds.
    #[inline]
    pub fn hold(&self, velocity: &mut Vec3, angular_velocity: &mut Vec3) {
        if let Self::Fixed { translation, rotation } = self {
            for axis in (0..3).filter(|&axis| translation[axis]) {
                velocity[axis] = 0.0;
            }
            if *rotation {
                *angular_velocity = Vec3::zeros();
            }
        }
    }
}

impl PrescribedMotion {
    /// Pose and velocity at time `t` \[s] of a body that started from `start` at t = 0.
    pub fn state_at(&self, start: &BodyState, t: f64) -> BodyState {
        let spin = Rotation::from_scaled_axis(self.angular_velocity * t);
        let orientation = spin * start.orientation;
        BodyState {
            position: start.position + self.velocity.displacement(t),
            orientation,
            velocity: self.velocity.velocity(t),
            angular_velocity: orientation.inverse_transform_vector(&self.angular_velocity),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn tabulated_velocity_integrates_exactly() {
        // v ramps 0 → 2 m/s over 1 s, holds 2 m/s: x(0.5) = 0.25, x(3) = 1 + 4 = 5.
        let profile = VelocityProfile::Table(vec![(0.0, Vec3::zeros()), (1.0, Vec3::new(2.0, 0.0, 0.0))]);
        assert_relative_eq!(profile.displacement(0.5).x, 0.25, epsilon = 1e-15);
        assert_relative_eq!(profile.displacement(3.0).x, 5.0, epsilon = 1e-15);
        assert_relative_eq!(profile.velocity(0.25).x, 0.5, epsilon = 1e-15);
    }

    /// `x(t) − x(0) = A (sin(ωt + φ) − sin φ)` and `v = A ω cos(ωt + φ)` against the closed form
    /// at points off any grid, and `v` as the derivative of `x` (central difference, error
    /// `A ω³ h²/6 < 1e-9 m/s` at h = 1e-5 s).
    #[test]
    fn harmonic_motion_matches_its_closed_form() {
        let (amplitude, period, phase) = (Vec3::new(2.0, -0.5, 0.3), 10.0, Vec3::new(0.0, 1.0, -2.5));
        let profile = VelocityProfile::Harmonic(Harmonic::new(amplitude, period, phase).unwrap());
        let omega = std::f64::consts::TAU / period;
        for t in [0.0, 0.37, 2.5, 7.1, 61.3] {
            let (x, v) = (profile.displacement(t), profile.velocity(t));
            for i in 0..3 {
                let exact_x = amplitude[i] * ((omega * t + phase[i]).sin() - phase[i].sin());
                let exact_v = amplitude[i] * omega * (omega * t + phase[i]).cos();
                assert_relative_eq!(x[i], exact_x, epsilon = 1e-14);
                assert_relative_eq!(v[i], exact_v, epsilon = 1e-14);
            }
            let h = 1e-5;
            let slope = (profile.displacement(t + h) - profile.displacement(t - h)) / (2.0 * h);
            assert_relative_eq!(slope, v, epsilon = 1e-9);
        }
        // Surge x = 2 sin(2πt/10): a quarter period in, 2 m out and at rest; at t = 0 and after one
        // period, at the start moving at A ω = 0.4π m/s.
        let surge = VelocityProfile::Harmonic(Harmonic::new(Vec3::new(2.0, 0.0, 0.0), 10.0, Vec3::zeros()).unwrap());
        assert_relative_eq!(surge.displacement(2.5), Vec3::new(2.0, 0.0, 0.0), epsilon = 1e-15);
        assert_relative_eq!(surge.velocity(2.5).x, 0.0, epsilon = 1e-15);
        assert_relative_eq!(surge.displacement(10.0).x, 0.0, epsilon = 1e-14);
        assert_relative_eq!(surge.velocity(0.0).x, 0.4 * std::f64::consts::PI, epsilon = 1e-15);
        assert_relative_eq!(surge.velocity(10.0).x, 0.4 * std::f64::consts::PI, epsilon = 1e-14);
    }

    #[test]
    fn harmonic_motion_refuses_what_it_cannot_move_by() {
        let message = |a: Vec3, t: f64, p: Vec3| Harmonic::new(a, t, p).unwrap_err().to_string();
        let (one, zero) = (Vec3::new(1.0, 0.0, 0.0), Vec3::zeros());
        assert_eq!(message(one, 0.0, zero), "period must be > 0 s, got 0");
        assert_eq!(message(one, -3.0, zero), "period must be > 0 s, got -3");
        assert_eq!(message(one, f64::INFINITY, zero), "period must be > 0 s, got inf");
        assert_eq!(message(Vec3::new(0.0, f64::NAN, 0.0), 1.0, zero), "amplitude must be finite, got NaN");
        assert_eq!(message(one, 1.0, Vec3::new(0.0, 0.0, f64::NEG_INFINITY)), "phase must be finite, got -inf");
        let harmonic = Harmonic::new(one, 4.0, zero).unwrap();
        assert_eq!((harmonic.amplitude(), harmonic.period(), harmonic.phase()), (one, 4.0, zero));
    }

    #[test]
    fn prescribed_spin_rotates_about_the_world_axis() {
        let start = BodyState {
            position: Vec3::zeros(),
            orientation: Rotation::identity(),
            velocity: Vec3::zeros(),
            angular_velocity: Vec3::zeros(),
        };
        let motion = PrescribedMotion {
            velocity: VelocityProfile::Constant(Vec3::new(1.0, 0.0, 0.0)),
            angular_velocity: Vec3::new(0.0, 0.0, std::f64::consts::PI),
        };
        let s = motion.state_at(&start, 0.5);
        assert_relative_eq!(s.position, Vec3::new(0.5, 0.0, 0.0), epsilon = 1e-15);
        assert_relative_eq!(s.point(&Vec3::x()), Vec3::new(0.5, 1.0, 0.0), epsilon = 1e-15);
    }
}
