//! The two ends of a coupling: where each is attached, where it is and how fast it moves, and
//! how a force there reaches its body (PHYSICS.md §2: each end force also gives its body a
//! moment about G).

use crate::body::{BodyFrame, Load};
use crate::math::Vec3;

/// Where a coupling's end is attached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Endpoint {
    /// A point fixed in the world \[m].
    World(Vec3),
    /// A point fixed on body `body` (index in the world), in its principal frame \[m].
    Body { body: usize, point: Vec3 },
    /// The centre of mass G of body `body`: no lever arm, so no moment and no rotation to
    /// evaluate (a chain of point-like bodies pays for none).
    Center { body: usize },
}

impl Endpoint {
    /// An end at `point` (principal frame) of body `body`: [`Endpoint::Center`] when it is G.
    pub fn on_body(body: usize, point: Vec3) -> Self {
        if point == Vec3::zeros() { Self::Center { body } } else { Self::Body { body, point } }
    }

    /// The end's point in the body's principal frame \[m], or in the world for a world end.
    pub fn point(&self) -> Vec3 {
        match *self {
            Self::World(point) | Self::Body { point, .. } => point,
            Self::Center { .. } => Vec3::zeros(),
        }
    }

    /// The body the end is on, if any.
    pub fn body(&self) -> Option<usize> {
        match *self {
            Self::World(_) => None,
            Self::Body { body, .. } | Self::Center { body } => Some(body),
        }
    }

    /// Where the end is and how fast it moves (PHYSICS.md §1 \[19]: `v_i = v_G + ω × (x_i − x_G)`).
    #[inline(always)]
    pub fn motion(&self, frames: &[BodyFrame]) -> EndMotion {
        match *self {
            Self::World(position) => EndMotion { position, velocity: Vec3::zeros(), attachment: Attachment::World },
            Self::Center { body } => {
                let frame = &frames[body];
                EndMotion { position: frame.position, velocity: frame.velocity, attachment: Attachment::Center(body) }
            }
            Self::Body { body, point } => {
                let frame = &frames[body];
                let arm = frame.rotation * point;
                EndMotion {
                    position: frame.position + arm,
                    velocity: frame.velocity + frame.rotation * frame.angular_velocity.cross(&point),
                    attachment: Attachment::Arm(body, arm),
                }
            }
        }
    }
}

/// How a force at an end reaches a body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Attachment {
    World,
    Center(usize),
    /// Body index and lever arm `x_end − x_G` \[m], world axes.
    Arm(usize, Vec3),
}

/// Position \[m] and velocity [m/s] of an end, world frame, and how it is attached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndMotion {
    pub position: Vec3,
    pub velocity: Vec3,
    pub attachment: Attachment,
}

impl EndMotion {
    /// Adds force `force` \[N] at this end to its body's load: `F += f`, `M += arm × f`.
    #[inline(always)]
    pub fn apply(&self, force: &Vec3, loads: &mut [Load]) {
        match self.attachment {
            Attachment::World => {}
            Attachment::Center(body) => loads[body].force += force,
            Attachment::Arm(body, arm) => {
                loads[body].force += force;
                loads[body].moment += arm.cross(force);
            }
        }
    }
}
