//! A rigid body: constant properties and display shape (PHYSICS.md §1); its state, support and
//! kinematics live in the submodules.
//!
//! Frames: the *principal frame* has its origin at G and its axes along the principal axes of
//! inertia; [`BodyState::orientation`] rotates it into the world. The *reference frame* is what
//! scene files use for points on a body: origin at the declared master node, axes parallel to the
//! world axes at t = 0. [`RigidBody::reference_in_principal`] converts between the two.
//!
//! - [`state`]: a body's state, the kinematics a force evaluation sees, its accelerations;
//! - [`load`]: the force and moment about G that the forces add up to;
//! - [`support`]: master-node boundary conditions and prescribed motions;
//! - [`kinematics`]: the integrators' building blocks (kick, drift, exact rotation increments).

pub mod kinematics;
pub mod load;
pub mod state;
pub mod support;

use crate::mass_properties::MassProperties;
use crate::math::Vec3;
pub use load::Load;
use nalgebra::Isometry3;
pub use state::{Acceleration, BodyFrame, BodyState};
pub use support::{Harmonic, PrescribedMotion, Support, VelocityProfile};

/// Display and contact shape in the body's reference frame \[m].
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
    /// A closed triangle mesh: vertices \[m] and counter-clockwise triangles.
    Mesh { vertices: Vec<Vec3>, triangles: Vec<[u32; 3]> },
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
    /// Slave node positions in the principal frame \[m] (rebuilt into the world from the pose).
    pub slave_nodes: Vec<Vec3>,
    pub support: Support,
    pub shape: Shape,
}

impl RigidBody {
    /// Builds a body whose master node was declared at `master_position` \[m].
    pub fn new(
        name: String,
        mass_properties: MassProperties,
        master_position: Vec3,
        slave_positions: &[Vec3],
        support: Support,
        shape: Shape,
    ) -> Self {
        let principal_to_world =
            nalgebra::Isometry3::from_parts(mass_properties.center_of_mass.into(), mass_properties.principal_axes);
        let reference_to_world =
            nalgebra::Isometry3::translation(master_position.x, master_position.y, master_position.z);
        let reference_in_principal = principal_to_world.inverse() * reference_to_world;
        let slave_nodes =
            slave_positions.iter().map(|p| principal_to_world.inverse_transform_point(&(*p).into()).coords).collect();
        let inverse_principal_moments = mass_properties.principal_moments.map(|m| 1.0 / m);
        let inverse_mass = mass_properties.mass.recip();
        Self {
            name,
            mass_properties,
            inverse_mass,
            inverse_principal_moments,
            reference_in_principal,
            slave_nodes,
            support,
            shape,
        }
    }

    /// `m` \[kg].
    pub fn mass(&self) -> f64 {
        self.mass_properties.mass
    }

    /// Principal moments `I1, I2, I3` [kg·m²].
    pub fn principal_moments(&self) -> Vec3 {
        self.mass_properties.principal_moments
    }

    /// A point given in the reference frame, expressed in the principal frame \[m].
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

    /// Kinetic energy `½ m |v|² + ½ ωᵀ I ω` \[J] for velocity `velocity` (any axes) and angular
    /// velocity `spin` (principal frame).
    pub fn kinetic_energy(&self, velocity: &Vec3, spin: &Vec3) -> f64 {
        0.5 * (self.mass() * velocity.norm_squared() + spin.dot(&self.principal_moments().component_mul(spin)))
    }

    /// Whether the body moves by prescription rather than by forces.
    pub fn is_kinematic(&self) -> bool {
        matches!(self.support, Support::Kinematic(_))
    }
}
