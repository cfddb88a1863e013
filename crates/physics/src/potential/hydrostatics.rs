//! A potential-flow body's hydrostatics (PHYSICS.md §9, "Linear hydrostatics"): from its mesh
//! (the default, exact at every pose) or linear, from the panel code's `.hst` stiffness, as
//! OpenFAST's HydroDyn and WEC-Sim's linear option take it.
//!
//! Linear, about the reference point P, world axes, small rotations:
//! `Q = Q₀ − C ξ`, where `ξ = (x_P − x_P⁰, θ)` is P's displacement \[m] and the rotation vector
//! θ \[rad] of the body's turn since t = 0, `C` the file's 6 × 6 stiffness \[N/m, N, N·m/rad], and
//! `Q₀ = (f₀, m₀)` the mesh's still-water pressure load at the body's pose at t = 0 \[N, N·m about
//! P]: the buoyancy `ρ g V₀` through the centre of buoyancy. The body's weight stays where every
//! body's is (at G, exact): the file must hold buoyancy only, as WAMIT writes it when run with
//! the centre of gravity at the origin (Capytaine's `compute_hydrostatic_stiffness` does when the
//! centre of mass is the rotation centre).

use super::coefficients::{Matrix6, Vector6};
use crate::body::{BodyFrame, Load};
use crate::math::{Mat3, Vec3};

/// Which hydrostatics a potential-flow body feels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum HydrostaticsModel {
    /// The still-water pressure integrated over the mesh at its actual pose (PHYSICS.md §6).
    #[default]
    Mesh,
    /// `Q₀ − C ξ` from the panel code's `.hst` (module docs).
    Linear,
}

/// The linear hydrostatics of one body (module docs), about its pose at t = 0.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearHydrostatics {
    /// `C` about P, world axes.
    stiffness: Matrix6,
    /// P in the body's principal frame \[m].
    reference: Vec3,
    /// P at t = 0 \[m].
    start_position: Vec3,
    /// The body's principal frame → world rotation at t = 0.
    start_rotation: Mat3,
    /// `Q₀`: force \[N] and moment about P \[N·m].
    preload: Vector6,
}

impl LinearHydrostatics {
    /// The model of stiffness `stiffness` about a body at `start` (t = 0), whose reference point
    /// is `arm` = `x_P − x_G` \[m] from G there and on which the still water's pressure over the
    /// mesh is `pressure` (about G, world axes).
    pub fn new(stiffness: Matrix6, start: &BodyFrame, arm: &Vec3, pressure: &Load) -> Self {
        let moment = pressure.moment - arm.cross(&pressure.force);
        let preload = Vector6::new(pressure.force.x, pressure.force.y, pressure.force.z, moment.x, moment.y, moment.z);
        Self {
            stiffness,
            reference: start.rotation.transpose() * arm,
            start_position: start.position + arm,
            start_rotation: start.rotation,
            preload,
        }
    }

    /// `C` about P, world axes \[N/m, N, N·m/rad].
    pub fn stiffness(&self) -> &Matrix6 {
        &self.stiffness
    }

    /// `ξ`: P's displacement since t = 0 and the rotation vector of the body's turn, for a body
    /// at `frame`.
    pub fn displacement(&self, frame: &BodyFrame) -> Vector6 {
        let moved = frame.position + frame.rotation * self.reference - self.start_position;
        // Both are rotation matrices, so their product is one; through the quaternion (Shepperd's
        // method, then an atan2) the angle stays accurate near zero, where the matrix's trace
        // and an acos would lose half the digits.
        let product = nalgebra::Rotation3::from_matrix_unchecked(frame.rotation * self.start_rotation.transpose());
        let turn = nalgebra::UnitQuaternion::from_rotation_matrix(&product).scaled_axis();
        Vector6::new(moved.x, moved.y, moved.z, turn.x, turn.y, turn.z)
    }

    /// `Q = Q₀ − C ξ` for a body at `frame`, moved from P to G: force \[N] and moment about G
    /// \[N·m], world axes.
    pub fn load(&self, frame: &BodyFrame) -> Load {
        let q = self.preload - self.stiffness * self.displacement(frame);
        let force = Vec3::new(q[0], q[1], q[2]);
        Load { force, moment: Vec3::new(q[3], q[4], q[5]) + (frame.rotation * self.reference).cross(&force) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Rotation;

    fn frame(position: Vec3, rotation: Mat3) -> BodyFrame {
        BodyFrame { position, rotation, ..BodyFrame::default() }
    }

    /// At t = 0's pose the load is the mesh's; a heave of 0.1 m and a pitch of 0.02 rad about P
    /// take `C`'s columns off it, about P.
    #[test]
    fn the_load_is_the_preload_less_the_stiffness_times_the_displacement() {
        let mut c = Matrix6::zeros();
        c[(2, 2)] = 3.0e5;
        c[(4, 4)] = 2.0e7;
        c[(2, 4)] = 1.0e5;
        let arm = Vec3::new(0.0, 0.0, 4.0);
        let start = frame(Vec3::new(1.0, 2.0, -4.0), Mat3::identity());
        let pressure = Load { force: Vec3::new(0.0, 0.0, 1.7e6), moment: Vec3::new(0.0, 2.0e5, 0.0) };
        let linear = LinearHydrostatics::new(c, &start, &arm, &pressure);
        let at_start = linear.load(&start);
        assert_eq!(at_start, pressure);

        let pitch = Rotation::from_scaled_axis(Vec3::new(0.0, 0.02, 0.0));
        let p = start.position + arm;
        let turned_arm = pitch * arm;
        let moved = frame(p + Vec3::new(0.0, 0.0, 0.1) - turned_arm, pitch.to_rotation_matrix().into_inner());
        let xi = linear.displacement(&moved);
        approx::assert_relative_eq!(xi, Vector6::new(0.0, 0.0, 0.1, 0.0, 0.02, 0.0), epsilon = 1e-12);
        let load = linear.load(&moved);
        let (heave, pitch_moment) = (1.7e6 - 3.0e5 * 0.1 - 1.0e5 * 0.02, 2.0e5 - 2.0e7 * 0.02);
        approx::assert_relative_eq!(load.force, Vec3::new(0.0, 0.0, heave), epsilon = 1e-6);
        // About P the moment is the closed form; about G it gains r × f.
        approx::assert_relative_eq!(
            load.moment - turned_arm.cross(&load.force),
            Vec3::new(0.0, pitch_moment, 0.0),
            epsilon = 1e-6
        );
    }
}
