//! Couplings: forces between two ends, each on a body or fixed in the world (PHYSICS.md §2–4):
//! spring-dampers, catenary lines, and contact between a body's faces and a boundary.
//!
//! A coupling is plain data in the closed enum [`CouplingKind`]; every kind writes its own
//! [`CouplingForces`] each evaluation, so its forces can be plotted, recorded and tested apart
//! from the others before they are summed into the bodies' [`Load`]s.

pub mod catenary;
pub mod contact;
pub mod elastic_law;
pub mod spring_damper;

use super::{Mat3, Vec3};
pub use catenary::{Catenary, CatenaryError};
pub use contact::Contact;
pub use elastic_law::ElasticLaw;
pub use spring_damper::SpringDamper;

/// Where a coupling's end is attached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Endpoint {
    /// A point fixed in the world [m].
    World(Vec3),
    /// A point fixed on body `body` (index in the world), in its principal frame [m].
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

    /// The end's point in the body's principal frame [m], or in the world for a world end.
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
    /// `ω` in the principal frame [rad/s] (turned into world axes only where an end needs it).
    pub angular_velocity: Vec3,
}

/// How a force at an end reaches a body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Attachment {
    World,
    Center(usize),
    /// Body index and lever arm `x_end − x_G` [m], world axes.
    Arm(usize, Vec3),
}

/// Position [m] and velocity [m/s] of an end, world frame, and how it is attached.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndMotion {
    pub position: Vec3,
    pub velocity: Vec3,
    pub attachment: Attachment,
}

impl EndMotion {
    /// Adds force `force` [N] at this end to its body's load: `F += f`, `M += arm × f`.
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

impl Endpoint {
    /// Where the end is and how fast it moves (seed 003 [19]: `v_i = v_G + ω × (x_i − x_G)`).
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

/// Sum of the forces [N] and moments about G [N·m] on one body, world axes (seed 003 [11]–[12]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Load {
    pub force: Vec3,
    pub moment: Vec3,
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
    /// Potential energy stored in the coupling [J].
    pub potential: f64,
}

/// The physical model of a coupling.
#[derive(Debug, Clone, PartialEq)]
pub enum CouplingKind {
    SpringDamper(SpringDamper),
    Catenary(Catenary),
    Contact(Contact),
}

/// Why a coupling could not give its forces.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum CouplingError {
    #[error(transparent)]
    Catenary(#[from] CatenaryError),
    /// A coupling replaced at an index the world does not have.
    #[error("the world has no coupling {0}")]
    NoSuchCoupling(usize),
}

/// A named coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct Coupling {
    pub name: String,
    pub kind: CouplingKind,
}

impl Coupling {
    /// The coupling's two ends (a contact's: the centres of its body and of the opposing body,
    /// or the world origin for the environment).
    pub fn ends(&self) -> [Endpoint; 2] {
        match &self.kind {
            CouplingKind::SpringDamper(spring) => [spring.end1, spring.end2],
            CouplingKind::Catenary(line) => [line.end1, line.end2],
            CouplingKind::Contact(contact) => {
                let other = contact.other_body().map_or(Endpoint::World(Vec3::zeros()), |body| Endpoint::Center { body });
                [Endpoint::Center { body: contact.body }, other]
            }
        }
    }

    /// Short name of the kind, as in JSON output.
    pub fn kind_name(&self) -> &'static str {
        match &self.kind {
            CouplingKind::SpringDamper(_) => "spring_damper",
            CouplingKind::Catenary(_) => "catenary",
            CouplingKind::Contact(_) => "contact",
        }
    }

    /// Evaluates the forces at the kinematics `frames` under `gravity`, adds them to the end
    /// bodies' `loads` and writes what the coupling did to `out`.
    #[inline(always)]
    pub fn apply(&mut self, frames: &[BodyFrame], gravity: &Vec3, loads: &mut [Load], out: &mut CouplingForces) -> Result<(), CouplingError> {
        match &mut self.kind {
            CouplingKind::SpringDamper(spring) => spring.apply(frames, loads, out),
            CouplingKind::Catenary(line) => line.apply(frames, gravity, loads, out)?,
            CouplingKind::Contact(contact) => contact.apply(frames, loads, out),
        }
        Ok(())
    }
}
