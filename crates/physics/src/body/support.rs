//! Boundary conditions of a body's master node (PHYSICS.md §1 [BC section]; slave nodes carry none):
//! fixed components, or a prescribed (kinematic) motion that forces do not change.

use super::state::BodyState;
use crate::math::{Rotation, Vec3};

/// Velocity of a kinematic body's master node, world frame [m/s].
#[derive(Debug, Clone, PartialEq)]
pub enum VelocityProfile {
    Constant(Vec3),
    /// `(t [s], v [m/s])` points with strictly increasing t; linear between them, held beyond.
    Table(Vec<(f64, Vec3)>),
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
        }
    }

    /// Displacement `∫_0^t v dt'` \[m], exact for the piecewise-linear profile.
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
