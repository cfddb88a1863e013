//! How a scene file spells the physics' closed enums: `integrator: rk4`, `substeps: Auto`,
//! `profile: PowerLaw`, `radiation: Convolution`, `hydrostatics: Linear`. The physics crate knows
//! no file format; each mirror here is serde's remote derive of one physics type (a field reads
//! `#[serde(with = "…")]`), so the compiler checks it against the type, variant for variant: a
//! variant added to the physics fails to compile here until the file can spell it.

use serde::{Deserialize, Serialize};
use tether_physics::integrator::{Integrator, Substeps};
use tether_physics::potential::{HydrostaticsModel, RadiationMethod};
use tether_physics::water::CurrentProfile;

/// [`Integrator`], in lower case as the command line spells it ([`Integrator::name`]).
#[derive(Serialize, Deserialize)]
#[serde(remote = "Integrator", rename_all = "snake_case")]
pub enum IntegratorForm {
    Leapfrog,
    Leapfrog2,
    Splitting,
    Rk4,
    Dopri45,
}

/// [`Substeps`]: `Fixed(n)` or `Auto`.
#[derive(Serialize, Deserialize)]
#[serde(remote = "Substeps")]
pub enum SubstepsForm {
    Fixed(u32),
    Auto,
}

/// [`CurrentProfile`]: `Uniform` or `PowerLaw`.
#[derive(Serialize, Deserialize)]
#[serde(remote = "CurrentProfile")]
pub enum CurrentProfileForm {
    Uniform,
    PowerLaw,
}

/// [`RadiationMethod`]: `StateSpace` or `Convolution`.
#[derive(Serialize, Deserialize)]
#[serde(remote = "RadiationMethod")]
pub enum RadiationMethodForm {
    StateSpace,
    Convolution,
}

/// [`HydrostaticsModel`]: `Mesh` or `Linear`.
#[derive(Serialize, Deserialize)]
#[serde(remote = "HydrostaticsModel")]
pub enum HydrostaticsModelForm {
    Mesh,
    Linear,
}
