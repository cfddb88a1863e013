//! Couplings: forces between two ends, each on a body or fixed in the world (PHYSICS.md §2–4):
//! spring-dampers, catenary lines, and contact between a body's faces and a boundary.
//!
//! A coupling is plain data in the closed enum [`CouplingKind`]: its parameters, which do not
//! change while it runs. What a run remembers from one evaluation to the next (a spring's last
//! direction, a line's warm start, a contact's face lists) is its [`CouplingCache`], kept apart
//! by the caller. Every kind writes its own [`CouplingForces`] each evaluation.
//!
//! - [`ends`]: where the ends are attached and how a force there reaches a body;
//! - [`forces`]: the record of what a coupling did;
//! - [`spring_damper`] with its [`elastic_law`], [`catenary`] (quasi-static, or dynamic by
//!   [`lumped_line`]), [`contact`]: the kinds.

pub mod catenary;
pub mod contact;
pub mod elastic_law;
pub mod ends;
pub mod forces;
pub mod lumped_line;
pub mod spring_damper;

use crate::body::{BodyFrame, Load};
use crate::math::Vec3;
use crate::surroundings::Surroundings;
pub use catenary::{Catenary, CatenaryCache, CatenaryError};
pub use contact::{Contact, ContactCache};
pub use elastic_law::ElasticLaw;
pub use ends::{Attachment, EndMotion, Endpoint};
pub use forces::CouplingForces;
pub use lumped_line::{InternalDamping, LineError, LineModel, LumpedMass, LumpedMassSpec};
pub use spring_damper::{SpringCache, SpringDamper};

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
    #[error(transparent)]
    Line(#[from] LineError),
}

/// A named coupling.
#[derive(Debug, Clone, PartialEq)]
pub struct Coupling {
    pub name: String,
    pub kind: CouplingKind,
}

/// What one coupling remembers between evaluations of one run: nothing that changes its forces,
/// only how fast they are found (and, for a spring whose ends meet, the last direction).
#[derive(Debug, Clone, PartialEq)]
#[allow(
    clippy::large_enum_variant,
    reason = "one per coupling, made once per run; a line's last solve is read at every evaluation, where a box would add an indirection"
)]
pub enum CouplingCache {
    SpringDamper(SpringCache),
    Catenary(CatenaryCache),
    Contact(ContactCache),
}

impl Coupling {
    /// The coupling's two ends (a contact's: the centres of its body and of the opposing body,
    /// or the world origin for the environment).
    pub fn ends(&self) -> [Endpoint; 2] {
        match &self.kind {
            CouplingKind::SpringDamper(spring) => [spring.end1(), spring.end2()],
            CouplingKind::Catenary(line) => [line.end1(), line.end2()],
            CouplingKind::Contact(contact) => {
                let other =
                    contact.other_body().map_or(Endpoint::World(Vec3::zeros()), |body| Endpoint::Center { body });
                [Endpoint::Center { body: contact.body() }, other]
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

    /// A fresh cache for a run of this coupling.
    pub fn new_cache(&self) -> CouplingCache {
        match &self.kind {
            CouplingKind::SpringDamper(_) => CouplingCache::SpringDamper(SpringCache::default()),
            CouplingKind::Catenary(_) => CouplingCache::Catenary(CatenaryCache::default()),
            CouplingKind::Contact(contact) => CouplingCache::Contact(contact.new_cache()),
        }
    }

    /// Evaluates the forces at the kinematics `frames` in `surroundings` (gravity, fluid,
    /// seabed), adds them to the end bodies' `loads` and writes what the coupling did to `out`. A `cache` of another kind
    /// (never given by the world, which makes each from its coupling) is started afresh.
    #[inline(always)]
    pub fn apply(
        &self,
        cache: &mut CouplingCache,
        frames: &[BodyFrame],
        surroundings: &Surroundings,
        loads: &mut [Load],
        out: &mut CouplingForces,
    ) -> Result<(), CouplingError> {
        match (&self.kind, cache) {
            (CouplingKind::SpringDamper(spring), CouplingCache::SpringDamper(memory)) => {
                spring.apply(memory, frames, loads, out)
            }
            (CouplingKind::Catenary(line), CouplingCache::Catenary(memory)) => {
                line.apply(memory, frames, surroundings, loads, out)?
            }
            (CouplingKind::Contact(contact), CouplingCache::Contact(memory)) => {
                contact.apply(memory, frames, loads, out)
            }
            // A cache of another kind, every kind listed: a kind missing here would fall through to
            // a fresh cache of its own kind and back, for ever.
            (CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) | CouplingKind::Contact(_), cache) => {
                return self.apply_with_fresh_cache(cache, frames, surroundings, loads, out);
            }
        }
        Ok(())
    }

    /// [`Coupling::apply`] with `cache` made afresh for this coupling first (out of line: the
    /// world never gets here).
    #[cold]
    #[inline(never)]
    fn apply_with_fresh_cache(
        &self,
        cache: &mut CouplingCache,
        frames: &[BodyFrame],
        surroundings: &Surroundings,
        loads: &mut [Load],
        out: &mut CouplingForces,
    ) -> Result<(), CouplingError> {
        *cache = self.new_cache();
        self.apply(cache, frames, surroundings, loads, out)
    }
}
