//! The dynamic lumped-mass line (PHYSICS.md §8): a catenary coupling's line as `N` segments
//! between `N + 1` nodes that carry its mass, added mass, wet weight, drag and seabed contact,
//! integrated in time (MoorDyn's model without bending and torsion).
//!
//! A line coupling is [`LineModel::QuasiStatic`] (the §3/§7 catenary, no inertia) or
//! [`LineModel::Dynamic`] with the [`LumpedMass`] parameters here; the two share the line's
//! `λ0`, `L`, `EA = D L` and `A_d` ([`super::Catenary`]) and switch live.
//!
//! - [`parameters`]: the model and its parameters, each checked once;
//! - [`discrete`]: the per-node and per-segment constants of one line in its surroundings, and
//!   its stable sub-step;
//! - [`nodes`]: the node state and the forces on it (§8 "Node i");
//! - [`axial`]: the segments' tensions over a sub-step, taken implicitly (§8 "The axial
//!   stiffness implicit");
//! - [`statics`]: the line at rest in its discrete static equilibrium, by Newton (§8 "Initial
//!   state");
//! - [`run`]: what a run of the line remembers and how it advances to the next evaluation.

pub mod axial;
pub mod discrete;
pub mod nodes;
pub mod parameters;
pub mod run;
pub mod statics;

pub use discrete::Discrete;
pub use nodes::LineNodes;
pub use parameters::{InternalDamping, LineModel, LumpedMass, LumpedMassSpec, MAX_SEGMENTS};
pub use run::{LineError, LineRun};
