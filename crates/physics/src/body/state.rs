//! What changes as a body moves (PHYSICS.md §1): its state, the kinematics a force evaluation
//! sees, and its accelerations.

use crate::math::{Mat3, Rotation, Vec3};

/// The state of a body at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyState {
    /// `x_G`, world \[m].
    pub position: Vec3,
    /// Principal frame → world.
    pub orientation: Rotation,
    /// `v_G`, world [m/s].
    pub velocity: Vec3,
    /// `ω`, principal frame [rad/s].
    pub angular_velocity: Vec3,
}

impl BodyState {
    /// World position of a point fixed in the principal frame, `x_G + R r` \[m] (PHYSICS.md §1 \[19]).
    pub fn point(&self, principal_point: &Vec3) -> Vec3 {
        self.position + self.orientation * principal_point
    }

    /// The principal frame → world rotation matrix `R`.
    #[inline(always)]
    pub fn rotation_matrix(&self) -> Mat3 {
        self.orientation.to_rotation_matrix().into_inner()
    }

    /// The kinematics a force evaluation sees at this state (stage *predict*).
    #[inline(always)]
    pub fn frame(&self) -> BodyFrame {
        BodyFrame {
            position: self.position,
            rotation: self.rotation_matrix(),
            velocity: self.velocity,
            angular_velocity: self.angular_velocity,
        }
    }

    /// Whether every component is finite.
    pub fn is_finite(&self) -> bool {
        self.position
            .iter()
            .chain(self.velocity.iter())
            .chain(self.angular_velocity.iter())
            .chain(self.orientation.coords.iter())
            .all(|x| x.is_finite())
    }
}

/// A body's kinematics at the instant the forces are evaluated, in world axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyFrame {
    /// `x_G` \[m].
    pub position: Vec3,
    /// Principal frame → world rotation matrix.
    pub rotation: Mat3,
    /// `v_G` [m/s].
    pub velocity: Vec3,
    /// `ω` in the principal frame [rad/s] (turned into world axes only where an end needs it).
    pub angular_velocity: Vec3,
}

impl BodyFrame {
    /// Takes `state`'s position and velocities, keeping the rotation matrix: a body that has
    /// drifted but not turned (or turns in a later pass).
    #[inline(always)]
    pub fn follow_translation(&mut self, state: &BodyState) {
        self.position = state.position;
        self.velocity = state.velocity;
        self.angular_velocity = state.angular_velocity;
    }
}

impl Default for BodyFrame {
    fn default() -> Self {
        Self {
            position: Vec3::zeros(),
            rotation: Mat3::identity(),
            velocity: Vec3::zeros(),
            angular_velocity: Vec3::zeros(),
        }
    }
}

/// Linear acceleration of G (world) and angular acceleration (principal frame).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Acceleration {
    /// `γ` [m/s²], world.
    pub linear: Vec3,
    /// `α` [rad/s²], principal frame.
    pub angular: Vec3,
}
