//! What a scene file says about water (PHYSICS.md §6): the top-level `water: Water(...)` and a
//! body's `hydro: Hydro(...)`, as plain serde data, and their conversion into the physics'
//! specs. Angles are in degrees here (keys say so), radians in the physics.
//!
//! ```ron
//! water: Water(
//!     density: 1025.0,            // kg/m³ (default 1025)
//!     level: 0.0,                 // still-water level z_w [m] (default 0)
//!     depth: 50.0,                // m; absent: deep water
//!     current: Current(speed: 0.5, heading_deg: 30.0, profile: PowerLaw),
//!     waves: Regular(height: 2.0, period: 8.0, heading_deg: 0.0, phase_deg: 0.0),
//!     // or Jonswap(hs: 2.5, tp: 9.0, gamma: 3.3, heading_deg: 0.0, components: 50, seed: 1)
//!     ramp: 20.0,                 // s; absent: two wave periods
//! ),
//! ```

use super::finite::{Triple, finite, finite_option, finite3, finite3_option};
use super::spelling::{CurrentProfileForm, DriftModelForm, HydrostaticsModelForm, RadiationMethodForm};
use serde::{Deserialize, Serialize};
use tether_physics::math::Vec3;
use tether_physics::potential::{DriftModel, HydrostaticsModel, RadiationMethod};
use tether_physics::water::morison::HydroSpec;
use tether_physics::water::{CurrentProfile, CurrentSpec, WaterError, WaterField, WaterSpec, WaveSpec};

/// The scene's water.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Water", deny_unknown_fields)]
pub struct WaterDef {
    /// ρ [kg/m³] > 0 (default 1025).
    #[serde(default = "default_density", deserialize_with = "finite")]
    pub density: f64,
    /// Still-water level `z_w` \[m] (default 0).
    #[serde(default, deserialize_with = "finite")]
    pub level: f64,
    /// Depth \[m] > 0; absent for deep water.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite_option")]
    pub depth: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub current: Option<CurrentDef>,
    #[serde(default)]
    pub waves: WavesDef,
    /// Ramp time \[s] ≥ 0 of waves and current; absent for two wave periods.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite_option")]
    pub ramp: Option<f64>,
}

fn default_density() -> f64 {
    1025.0
}

/// A current: surface speed [m/s] toward `heading_deg` (counter-clockwise from +x).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Current", deny_unknown_fields)]
pub struct CurrentDef {
    #[serde(deserialize_with = "finite")]
    pub speed: f64,
    #[serde(default, deserialize_with = "finite")]
    pub heading_deg: f64,
    /// `Uniform` (default) or `PowerLaw` (1/7 power law to zero at the seabed; needs a depth).
    #[serde(default, with = "CurrentProfileForm")]
    pub profile: CurrentProfile,
}

/// Waves.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum WavesDef {
    /// Still water (the default).
    #[default]
    Calm,
    /// An Airy wave: `height` \[m] crest to trough, `period` \[s], heading and phase \[deg].
    Regular {
        #[serde(deserialize_with = "finite")]
        height: f64,
        #[serde(deserialize_with = "finite")]
        period: f64,
        #[serde(default, deserialize_with = "finite")]
        heading_deg: f64,
        #[serde(default, deserialize_with = "finite")]
        phase_deg: f64,
    },
    /// A JONSWAP sea: `hs` \[m], `tp` \[s], `gamma` ≥ 1 (default 3.3), heading \[deg],
    /// `components` (default 50) with phases drawn from `seed` (default 1).
    Jonswap {
        #[serde(deserialize_with = "finite")]
        hs: f64,
        #[serde(deserialize_with = "finite")]
        tp: f64,
        #[serde(default = "default_gamma", deserialize_with = "finite")]
        gamma: f64,
        #[serde(default, deserialize_with = "finite")]
        heading_deg: f64,
        #[serde(default = "default_components")]
        components: u32,
        #[serde(default = "default_seed")]
        seed: u64,
    },
}

fn default_gamma() -> f64 {
    3.3
}

fn default_components() -> u32 {
    50
}

fn default_seed() -> u64 {
    1
}

/// A body's hydrodynamic coefficients, per axis of its reference frame (SI units; every one
/// defaults to zero: a body with `hydro: Hydro()` feels only the pressure).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename = "Hydro", deny_unknown_fields)]
pub struct HydroDef {
    /// Drag coefficients `C_d` [–] ≥ 0.
    #[serde(default, deserialize_with = "finite3")]
    pub drag: Triple,
    /// Drag areas \[m²] > 0; absent: the hull's projected areas.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite3_option")]
    pub drag_areas: Option<Triple>,
    /// Rotational drag `C_r` [N·m·s²] ≥ 0.
    #[serde(default, deserialize_with = "finite3")]
    pub rotational_drag: Triple,
    /// Linear damping [N·s/m] ≥ 0.
    #[serde(default, deserialize_with = "finite3")]
    pub linear_damping: Triple,
    /// Rotational damping [N·m·s] ≥ 0.
    #[serde(default, deserialize_with = "finite3")]
    pub rotational_damping: Triple,
    /// Added-mass coefficients `C_a` [–] ≥ 0 (added mass `C_a ρ V` when fully wet).
    #[serde(default, deserialize_with = "finite3")]
    pub added_mass: Triple,
    /// Added inertia [kg·m²] ≥ 0 about each axis, when fully wet.
    #[serde(default, deserialize_with = "finite3")]
    pub added_inertia: Triple,
    /// Drag centre in the reference frame \[m]; absent: G.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite3_option")]
    pub drag_center: Option<Triple>,
    /// Potential flow from a panel code's WAMIT files (PHYSICS.md §9); absent: none. With it
    /// the incident wave's pressure and `added_mass`/`added_inertia` are not applied (the
    /// files hold them); buoyancy from the mesh and the drag stay.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub potential: Option<WamitDef>,
}

/// A body's potential-flow data (PHYSICS.md §9):
///
/// ```ron
/// potential: Wamit(
///     file: "hydro/buoy",      // reads hydro/buoy.1 and .3, relative to the scene file
///     length: 1.0,             // WAMIT's length scale L [m] (default 1)
///     reference: (0, 0, 0),    // the panel code's origin in the body's reference frame [m] (default 0)
///     radiation: StateSpace,   // or Convolution: the direct convolution, the reference (default StateSpace)
///     fit_error: 1e-2,         // the state-space fit's relative L2 error per pair (default 1e-2)
///     max_order: 30,           // its highest order per pair (default 30)
///     kernel_duration: 60.0,   // the kernel's truncation t_K [s] (default 60)
///     kernel_step: 0.05,       // its sampling step [s] (default 0.05)
///     hydrostatics: Mesh,      // or Linear: Q₀ − C ξ from hydro/buoy.hst, about the pose at t = 0 (default Mesh)
///     drift: Off,              // or Mean, or Newman: the second-order drift from hydro/buoy.8 (else .9) (default Off; §10)
/// ),
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Wamit", deny_unknown_fields)]
pub struct WamitDef {
    pub file: String,
    #[serde(default = "default_length", deserialize_with = "finite")]
    pub length: f64,
    #[serde(default, deserialize_with = "finite3")]
    pub reference: Triple,
    #[serde(default, with = "RadiationMethodForm")]
    pub radiation: RadiationMethod,
    #[serde(default = "default_fit_error", deserialize_with = "finite")]
    pub fit_error: f64,
    #[serde(default = "default_max_order")]
    pub max_order: u32,
    #[serde(default = "default_kernel_duration", deserialize_with = "finite")]
    pub kernel_duration: f64,
    #[serde(default = "default_kernel_step", deserialize_with = "finite")]
    pub kernel_step: f64,
    #[serde(default, with = "HydrostaticsModelForm")]
    pub hydrostatics: HydrostaticsModel,
    #[serde(default, with = "DriftModelForm", skip_serializing_if = "is_off")]
    pub drift: DriftModel,
}

fn is_off(drift: &DriftModel) -> bool {
    *drift == DriftModel::Off
}

fn default_length() -> f64 {
    1.0
}

fn default_fit_error() -> f64 {
    1e-2
}

fn default_max_order() -> u32 {
    30
}

fn default_kernel_duration() -> f64 {
    60.0
}

fn default_kernel_step() -> f64 {
    0.05
}

fn vec3(t: Triple) -> Vec3 {
    Vec3::new(t[0], t[1], t[2])
}

impl WaterDef {
    /// The physics' spec (angles to radians).
    pub fn spec(&self) -> WaterSpec {
        let current = self.current.as_ref().map_or_else(CurrentSpec::default, |c| CurrentSpec {
            speed: c.speed,
            heading: c.heading_deg.to_radians(),
            profile: c.profile,
        });
        let waves = match self.waves {
            WavesDef::Calm => WaveSpec::Calm,
            WavesDef::Regular { height, period, heading_deg, phase_deg } => {
                WaveSpec::Regular { height, period, heading: heading_deg.to_radians(), phase: phase_deg.to_radians() }
            }
            WavesDef::Jonswap { hs, tp, gamma, heading_deg, components, seed } => WaveSpec::Jonswap {
                significant_height: hs,
                peak_period: tp,
                gamma,
                heading: heading_deg.to_radians(),
                components,
                seed,
            },
        };
        WaterSpec { density: self.density, level: self.level, depth: self.depth, current, waves, ramp: self.ramp }
    }

    /// The water section's field that `error` is about.
    pub fn field_of(error: &WaterError) -> &'static str {
        match error {
            WaterError::Gamma(_) => "gamma",
            WaterError::Components(_) => "components",
            WaterError::Breaking { .. } => "waves",
            WaterError::ProfileWithoutDepth => "profile",
            WaterError::Gravity(..) => "water",
            WaterError::Parameter { field, .. } => match field {
                WaterField::WaveHeight => "height",
                WaterField::WavePeriod => "period",
                WaterField::SignificantHeight => "hs",
                WaterField::PeakPeriod => "tp",
                WaterField::CurrentSpeed => "speed",
                WaterField::CurrentHeading => "current",
                WaterField::Ramp => "ramp",
                WaterField::Level => "level",
                WaterField::Density => "density",
                WaterField::Depth => "depth",
                WaterField::Gamma => "gamma",
                WaterField::WaveHeading | WaterField::WavePhase => "waves",
            },
        }
    }
}

impl HydroDef {
    /// The physics' spec.
    pub fn spec(&self) -> HydroSpec {
        HydroSpec {
            drag: vec3(self.drag),
            drag_areas: self.drag_areas.map(vec3),
            rotational_drag: vec3(self.rotational_drag),
            linear_damping: vec3(self.linear_damping),
            rotational_damping: vec3(self.rotational_damping),
            added_mass: vec3(self.added_mass),
            added_inertia: vec3(self.added_inertia),
            drag_center: self.drag_center.map(vec3),
        }
    }
}
