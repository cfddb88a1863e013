//! Pure rigid-body physics: no GUI, no viewer, no file format.
//!
//! - [`mass_properties`]: mass, centre of mass and principal inertia from master + slave nodes (§1).
//! - [`body`]: a rigid body's constant properties, its state, and its master-node support (§1).
//! - [`coupling`]: the forces between bodies and the world (§2–4).
//! - [`mesh`]: boundary meshes of bodies for contact, and their distance queries (§4).
//! - [`integrator`]: how a state advances in time (§1, time integration).
//! - [`world`]: bodies + couplings + time, and the named stages of one step.
//! - [`energy`]: the energy balance that checks it all (§5).
//! - [`stability`]: the stable time step of each coupling and spinning body.
//! - [`table`]: piecewise-linear tables with exact integrals, for curve-defined laws.

pub mod body;
pub mod coupling;
pub mod dynamics;
pub mod energy;
pub mod integrator;
pub mod mass_properties;
pub mod mesh;
pub mod stability;
pub mod table;
pub mod world;

/// 3-vector of `f64` (positions in m, forces in N, …).
pub type Vec3 = nalgebra::Vector3<f64>;
/// 3×3 matrix of `f64` (inertia tensors in kg·m², rotations).
pub type Mat3 = nalgebra::Matrix3<f64>;
/// Unit quaternion: a body's orientation, principal frame → world frame.
pub type Rotation = nalgebra::UnitQuaternion<f64>;

/// Corners `(low, high)` of the axis-aligned box around `points` (componentwise minimum and
/// maximum); `(+∞, −∞)` when there are none.
pub(crate) fn bounding_box(points: impl IntoIterator<Item = Vec3>) -> (Vec3, Vec3) {
    points.into_iter().fold((Vec3::repeat(f64::INFINITY), Vec3::repeat(f64::NEG_INFINITY)), |(low, high), p| (low.inf(&p), high.sup(&p)))
}
