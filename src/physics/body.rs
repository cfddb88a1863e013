//! A rigid body: constant properties, master-node support, display shape and state (PHYSICS.md §1).
//!
//! Frames: the *principal frame* has its origin at G and its axes along the principal axes of
//! inertia; [`BodyState::orientation`] rotates it into the world. The *reference frame* is what
//! scene files use for points on a body: origin at the declared master node, axes parallel to the
//! world axes at t = 0. [`RigidBody::reference_in_principal`] converts between the two.

use super::mass_properties::MassProperties;
use super::{Rotation, Vec3};
use nalgebra::Isometry3;

/// Display and contact shape in the body's reference frame [m].
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    /// Box with full edge lengths `size` along the reference axes, centred at `center`; as a
    /// contact boundary, each face split into `subdivisions²` squares.
    Box { size: Vec3, center: Vec3, subdivisions: u32 },
    /// Sphere of `radius` centred at `center`; as a contact boundary, an icosphere split
    /// `subdivisions` times.
    Sphere { radius: f64, center: Vec3, subdivisions: u32 },
    /// Cylinder of `radius` and `length` along the unit `axis`, centred at `center`.
    Cylinder { radius: f64, length: f64, axis: Vec3, center: Vec3 },
    /// A closed triangle mesh: vertices [m] and counter-clockwise triangles.
    Mesh { vertices: Vec<Vec3>, triangles: Vec<[u32; 3]> },
}

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

    /// Displacement `∫_0^t v dt'` [m], exact for the piecewise-linear profile.
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

/// Boundary conditions of the master node (seed 003, BC section; slave nodes carry none).
#[derive(Debug, Clone, PartialEq)]
pub enum Support {
    Free,
    /// Fixed world translation components (x, y, z) and, optionally, fixed rotation.
    Fixed { translation: [bool; 3], rotation: bool },
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

/// Constant properties of a rigid body.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidBody {
    pub name: String,
    pub mass_properties: MassProperties,
    /// `1/m` [1/kg] (the step multiplies; it never divides).
    pub inverse_mass: f64,
    /// `1/I1, 1/I2, 1/I3` [1/(kg·m²)].
    pub inverse_principal_moments: Vec3,
    /// Pose of the reference frame in the principal frame (constant: the body is rigid).
    pub reference_in_principal: Isometry3<f64>,
    /// Slave node positions in the principal frame [m] (rebuilt into the world from the pose).
    pub slave_nodes: Vec<Vec3>,
    pub support: Support,
    pub shape: Shape,
}

impl RigidBody {
    /// Builds a body whose master node was declared at `master_position` [m].
    pub fn new(
        name: String,
        mass_properties: MassProperties,
        master_position: Vec3,
        slave_positions: &[Vec3],
        support: Support,
        shape: Shape,
    ) -> Self {
        let principal_to_world = nalgebra::Isometry3::from_parts(
            mass_properties.center_of_mass.into(),
            mass_properties.principal_axes,
        );
        let reference_to_world = nalgebra::Isometry3::translation(master_position.x, master_position.y, master_position.z);
        let reference_in_principal = principal_to_world.inverse() * reference_to_world;
        let slave_nodes = slave_positions.iter().map(|p| principal_to_world.inverse_transform_point(&(*p).into()).coords).collect();
        let inverse_principal_moments = mass_properties.principal_moments.map(|m| 1.0 / m);
        let inverse_mass = mass_properties.mass.recip();
        Self { name, mass_properties, inverse_mass, inverse_principal_moments, reference_in_principal, slave_nodes, support, shape }
    }

    /// `m` [kg].
    pub fn mass(&self) -> f64 {
        self.mass_properties.mass
    }

    /// Principal moments `I1, I2, I3` [kg·m²].
    pub fn principal_moments(&self) -> Vec3 {
        self.mass_properties.principal_moments
    }

    /// A point given in the reference frame, expressed in the principal frame [m].
    pub fn principal_point(&self, reference_point: &Vec3) -> Vec3 {
        self.reference_in_principal.transform_point(&(*reference_point).into()).coords
    }

    /// The state at t = 0 for initial velocity `velocity` (world, m/s) and angular velocity
    /// `angular_velocity` (world, rad/s).
    /// Components a [`Support::Fixed`] holds are set to zero.
    pub fn initial_state(&self, mut velocity: Vec3, mut angular_velocity: Vec3) -> BodyState {
        self.support.hold(&mut velocity, &mut angular_velocity);
        let orientation = self.mass_properties.principal_axes;
        BodyState {
            position: self.mass_properties.center_of_mass,
            orientation,
            velocity,
            angular_velocity: orientation.inverse_transform_vector(&angular_velocity),
        }
    }

    /// Kinetic energy `½ m |v|² + ½ ωᵀ I ω` [J] for velocity `velocity` (any axes) and angular
    /// velocity `spin` (principal frame).
    pub fn kinetic_energy(&self, velocity: &Vec3, spin: &Vec3) -> f64 {
        0.5 * (self.mass() * velocity.norm_squared() + spin.dot(&self.principal_moments().component_mul(spin)))
    }

    /// Whether the body moves by prescription rather than by forces.
    pub fn is_kinematic(&self) -> bool {
        matches!(self.support, Support::Kinematic(_))
    }
}

/// The state of a body at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// `x_G`, world [m].
    pub position: Vec3,
    /// Principal frame → world.
    pub orientation: Rotation,
    /// `v_G`, world [m/s].
    pub velocity: Vec3,
    /// `ω`, principal frame [rad/s].
    pub angular_velocity: Vec3,
}

impl BodyState {
    /// World position of a point fixed in the principal frame, `x_G + R r` [m] (seed 003 [19]).
    pub fn point(&self, principal_point: &Vec3) -> Vec3 {
        self.position + self.orientation * principal_point
    }
}

/// Pose and velocity of a kinematic body at time `t`, starting from `start` at t = 0.
pub fn prescribed_state(motion: &PrescribedMotion, start: &BodyState, t: f64) -> BodyState {
    let spin = Rotation::from_scaled_axis(motion.angular_velocity * t);
    let orientation = spin * start.orientation;
    BodyState {
        position: start.position + motion.velocity.displacement(t),
        orientation,
        velocity: motion.velocity.velocity(t),
        angular_velocity: orientation.inverse_transform_vector(&motion.angular_velocity),
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
        let start = BodyState { position: Vec3::zeros(), orientation: Rotation::identity(), velocity: Vec3::zeros(), angular_velocity: Vec3::zeros() };
        let motion = PrescribedMotion { velocity: VelocityProfile::Constant(Vec3::new(1.0, 0.0, 0.0)), angular_velocity: Vec3::new(0.0, 0.0, std::f64::consts::PI) };
        let s = prescribed_state(&motion, &start, 0.5);
        assert_relative_eq!(s.position, Vec3::new(0.5, 0.0, 0.0), epsilon = 1e-15);
        assert_relative_eq!(s.point(&Vec3::x()), Vec3::new(0.5, 1.0, 0.0), epsilon = 1e-15);
    }
}
