//! Statics (PHYSICS.md §7 "Static equilibrium"): what a system does at rest. Its degrees of freedom ([`dofs`]), its
//! tangent stiffness from every force source ([`stiffness`]), its static equilibrium
//! ([`equilibrium`], MoorPy's `solveEquilibrium`) and a body's restoring force as it is held
//! at offsets from there ([`offsets`], the mooring engineer's offset curve).

pub mod dofs;
pub mod equilibrium;
pub mod offsets;
pub mod stiffness;

pub use dofs::{Direction, Dof, Dofs};
pub use equilibrium::{Equilibrium, EquilibriumError, Settings};
pub use offsets::{Offset, OffsetCurve};
