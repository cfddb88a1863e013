//! The air (PHYSICS.md §10, "Wind"): an environment stage a scene declares beside the water, and
//! skipped when it declares none.
//!
//! - [`wind`]: density, the mean wind's speed, height profile and heading, and its ramp;
//! - [`gusts`]: NPD and Kaimal spectra realised as seeded harmonic sums;
//! - [`windage`]: a body's quadratic drag per axis at the relative wind, areas stated or from
//!   its hull above the water;
//! - [`rotor`]: a wind turbine's quasi-steady thrust curve at its hub;
//! - [`stage`]: the stage of the force evaluation that applies them and books their work.

pub mod gusts;
pub mod rotor;
pub mod stage;
pub mod wind;
pub mod windage;

pub use gusts::{BAND, GustError, GustPoint, GustSpec, GustSpectrum, Gusts};
pub use rotor::{Rotor, RotorSpec};
pub use stage::{AirForces, AirStage, AirStageError, WindBody, WindLoadError, WindLoadSpec};
pub use wind::{AIR_DENSITY, Air, AirError, AirSpec, WindProfile, WindSpec};
pub use windage::{Windage, WindageSpec};
