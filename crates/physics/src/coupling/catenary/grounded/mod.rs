//! A catenary lying on the seabed (PHYSICS.md §7, the model of MoorPy's `catenary()` with
//! seabed friction): its equations in units of the line ([`profile`]) and their solve
//! ([`solver`]). The catenary coupling ([`super`]) decides when a line is grounded and turns
//! the dimensionless profile into forces, energy, stiffness and a shape in the world.

pub mod profile;
pub mod solver;

pub use profile::{Grounding, Profile, Sensitivity, Suspended};
pub use solver::{Outcome, Solved};
