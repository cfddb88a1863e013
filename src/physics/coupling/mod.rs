//! Couplings: forces between two ends, each on a body or fixed in the world (PHYSICS.md §2–4).
//!
//! A coupling is plain data in the closed enum [`CouplingKind`]; every kind writes its own
//! [`CouplingForces`] each evaluation, so its forces can be plotted, recorded and tested apart
//! from the others before they are summed into the bodies' [`Load`]s.

pub mod elastic_law;
pub mod spring_damper;

use super::{Mat3, Vec3};
pub use elastic_law::ElasticLaw;
pub use spring_damper::SpringDamper;

/// Where a coupling's end is attached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Endpoint {
    /// A point fixed in the world [m].
    World(Vec3),
    /// A point fixed on body `body` (index in the world), in its principal frame [m].
    Body { body: usize, point: Vec3 },
}

/// A body's kinematics at the instant the forces are evaluated, in world axes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyFrame {
    /// `x_G` [m].
    pub position: Vec3,
    /// Principal frame → world rotation matrix.
    pub rotation: Mat3,
    /// `v_G` [m/s].
    pub velocity: Vec3,
    /// `ω` in world axes [rad/s].
    pub angular_velocity: Vec3,
}

/// Position [m] and velocity [m/s] of an end, world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndMotion {
    pub position: Vec3,
    pub velocity: Vec3,
}

impl Endpoint {
    /// Where the end is and how fast it moves (seed 003 [19]: `v_i = v_G + ω × (x_i − x_G)`).
    pub fn motion(&self, frames: &[BodyFrame]) -> EndMotion {
        match *self {
            Self::World(position) => EndMotion { position, velocity: Vec3::zeros() },
            Self::Body { body, point } => {
                let frame = &frames[body];
                let arm = frame.rotation * point;
                EndMotion { position: frame.position + arm, velocity: frame.velocity + frame.angular_velocity.cross(&arm) }
            }
        }
    }

    /// The body this end is on, if any.
    pub fn body(&self) -> Option<usize> {
        match *self {
            Self::World(_) => None,
            Self::Body { body, .. } => Some(body),
        }
    }
}

/// Sum of the forces [N] and moments about G [N·m] on one body, world axes (seed 003 [11]–[12]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Load {
    pub force: Vec3,
    pub moment: Vec3,
}

impl Load {
    /// Adds force `force` applied at world point `at`: `M += (at − x_G) × F`.
    pub fn apply(&mut self, force: &Vec3, at: &Vec3, frame: &BodyFrame) {
        self.force += force;
        self.moment += (at - frame.position).cross(force);
    }
}

/// What one coupling did at the last evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CouplingForces {
    /// End positions, world [m].
    pub point1: Vec3,
    pub point2: Vec3,
    /// Force exerted by the coupling on end 1 and on end 2, world [N].
    pub f1: Vec3,
    pub f2: Vec3,
    /// Scalar force of the coupling [N] (a spring's `f1 = f_e + k_d ẋ`, positive in tension).
    pub tension: f64,
    /// Power dissipated by damping [W] ≥ 0.
    pub dissipated_power: f64,
}

/// The physical model of a coupling.
#[derive(Debug, Clone, PartialEq)]
pub enum CouplingKind {
    SpringDamper(SpringDamper),
}

/// A named coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct Coupling {
    pub name: String,
    pub kind: CouplingKind,
}

impl Coupling {
    /// The coupling's two ends.
    pub fn ends(&self) -> [Endpoint; 2] {
        match &self.kind {
            CouplingKind::SpringDamper(spring) => [spring.end1, spring.end2],
        }
    }

    /// Short name of the kind, as in scene files and JSON output.
    pub fn kind_name(&self) -> &'static str {
        match &self.kind {
            CouplingKind::SpringDamper(_) => "spring_damper",
        }
    }

    /// Evaluates the forces at the kinematics `frames`.
    pub fn forces(&mut self, frames: &[BodyFrame]) -> CouplingForces {
        match &mut self.kind {
            CouplingKind::SpringDamper(spring) => spring.forces(frames),
        }
    }

    /// Potential energy stored in the coupling [J].
    pub fn potential_energy(&self, frames: &[BodyFrame]) -> f64 {
        match &self.kind {
            CouplingKind::SpringDamper(spring) => spring.potential_energy(frames),
        }
    }
}
