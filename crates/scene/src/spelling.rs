//! How a scene file spells the physics' closed enums and a dynamic line's values: `integrator:
//! rk4`, `substeps: Auto`, `profile: PowerLaw`, `radiation: Convolution`, `hydrostatics: Linear`,
//! `damping: Ratio(0.8)`. The physics crate knows
//! no file format; each mirror here is serde's remote derive of one physics type (a field reads
//! `#[serde(with = "…")]`), so the compiler checks it against the type, variant for variant: a
//! variant added to the physics fails to compile here until the file can spell it.

use serde::{Deserialize, Serialize};
use tether_physics::coupling::{InternalDamping, LumpedMassSpec};
use tether_physics::integrator::{Integrator, Substeps};
use tether_physics::potential::{DriftModel, HydrostaticsModel, RadiationMethod};
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

/// [`DriftModel`]: `Off`, `Mean` or `Newman` (PHYSICS.md §10).
#[derive(Serialize, Deserialize)]
#[serde(remote = "DriftModel")]
pub enum DriftModelForm {
    Off,
    Mean,
    Newman,
}

/// [`InternalDamping`]: `Coefficient(BA)` \[N·s] or `Ratio(ζ)` [–].
#[derive(Serialize, Deserialize)]
#[serde(remote = "InternalDamping")]
pub enum InternalDampingForm {
    Coefficient(f64),
    Ratio(f64),
}

/// [`LumpedMassSpec`], a dynamic line's values, each as the physics documents it. A file may leave
/// out the drag and added-mass coefficients (0) and the seabed's values (MoorDyn's,
/// [`LumpedMassSpec::SEABED_STIFFNESS`] …). Written inside `Dynamic(…)` (`crate::line_model`).
#[derive(Serialize, Deserialize)]
#[serde(remote = "LumpedMassSpec", deny_unknown_fields)]
pub struct LumpedMassSpecForm {
    segments: u32,
    #[serde(with = "InternalDampingForm")]
    damping: InternalDamping,
    #[serde(default)]
    drag_normal: f64,
    #[serde(default)]
    drag_tangential: f64,
    #[serde(default)]
    added_mass_normal: f64,
    #[serde(default)]
    added_mass_tangential: f64,
    #[serde(default = "seabed_stiffness")]
    seabed_stiffness: f64,
    #[serde(default = "seabed_damping")]
    seabed_damping: f64,
    #[serde(default = "friction_speed")]
    friction_speed: f64,
}

fn seabed_stiffness() -> f64 {
    LumpedMassSpec::SEABED_STIFFNESS
}

fn seabed_damping() -> f64 {
    LumpedMassSpec::SEABED_DAMPING
}

fn friction_speed() -> f64 {
    LumpedMassSpec::FRICTION_SPEED
}
