//! The scene file's air (PHYSICS.md §10, docs/design-loads.md): the `air` section beside
//! `water`, and a body's `windage` and `rotor`.
//!
//! ```ron
//! air: Air(
//!     density: 1.225,                      // ρ_a [kg/m³] (default 1.225)
//!     wind: Wind(
//!         speed: 20.0,                     // U_r [m/s] at `height`
//!         height: 10.0,                    // z_r [m] above the still water level (default 10)
//!         heading_deg: 0.0,                // the direction it blows toward [deg] (default 0)
//!         profile: PowerLaw(0.11),         // or Logarithmic(z0 [m]) (default PowerLaw(0.11))
//!         gusts: Npd(seed: 3),             // or Steady, or Kaimal(intensity: 0.12, seed: 3) (default Steady)
//!     ),
//!     ramp: 20.0,                          // T_r [s]: the wind comes in over it (default: the water's ramp, else 0)
//! ),
//! // in a body:
//! windage: Windage(coefficients: (1.0, 1.0, 0.0), areas: (12.0, 12.0, 0.0), center: (0.0, 0.0, 2.0)),
//! rotor: Rotor(point: (-5.0, 0.0, 90.0), area: 12469.0, thrust: Table([(3.0, 0.8), (11.4, 0.75), (25.0, 0.1)])),
//! ```
//!
//! A windage's `areas` \[m²] are its projected areas normal to the body's reference axes, and its
//! `center` \[m] (reference frame) where the wind acts; without `areas`, both come from the hull
//! above the still water at t = 0. A rotor's `axis` (default `(1, 0, 0)`) is the direction of
//! its thrust when the wind blows along it.

use super::finite::{Triple, finite, finite_option, finite_pairs, finite3, finite3_option};
use serde::{Deserialize, Serialize};
use tether_physics::air::{
    AIR_DENSITY, AirSpec, GustSpec, RotorSpec, WindLoadSpec, WindProfile, WindSpec, WindageSpec,
};
use tether_physics::math::Vec3;

/// The `air` section.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Air", deny_unknown_fields)]
pub struct AirDef {
    #[serde(default = "default_density", deserialize_with = "finite")]
    pub density: f64,
    pub wind: WindDef,
    /// `T_r` \[s]; absent: the water's ramp, or 0 without water.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite_option")]
    pub ramp: Option<f64>,
}

/// The mean wind and its gusts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Wind", deny_unknown_fields)]
pub struct WindDef {
    #[serde(deserialize_with = "finite")]
    pub speed: f64,
    #[serde(default = "default_height", deserialize_with = "finite")]
    pub height: f64,
    #[serde(default, deserialize_with = "finite")]
    pub heading_deg: f64,
    #[serde(default)]
    pub profile: ProfileDef,
    #[serde(default)]
    pub gusts: GustsDef,
}

/// The mean wind's height profile.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ProfileDef {
    /// `U(z) = U_r (z/z_r)^α`.
    PowerLaw(#[serde(deserialize_with = "finite")] f64),
    /// `U(z) = U_r ln(z/z₀)/ln(z_r/z₀)`, z₀ \[m].
    Logarithmic(#[serde(deserialize_with = "finite")] f64),
}

impl Default for ProfileDef {
    /// The offshore power law of API RP 2A and DNV-RP-C205.
    fn default() -> Self {
        Self::PowerLaw(0.11)
    }
}

/// The gusts.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum GustsDef {
    /// None: the mean wind alone (the default).
    #[default]
    Steady,
    /// NPD (Frøya), API RP 2A / ISO 19901-1.
    Npd {
        #[serde(default = "default_seed")]
        seed: u64,
        #[serde(default = "default_components")]
        components: u32,
    },
    /// Kaimal, IEC 61400-1.
    Kaimal {
        #[serde(deserialize_with = "finite")]
        intensity: f64,
        #[serde(default = "default_length_scale", deserialize_with = "finite")]
        length_scale: f64,
        #[serde(default = "default_seed")]
        seed: u64,
        #[serde(default = "default_components")]
        components: u32,
    },
}

/// Which spectrum the gusts follow, if any: a [`GustsDef`]'s variant without its values (the
/// window's choice).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GustKind {
    Steady,
    Npd,
    Kaimal,
}

impl GustKind {
    /// Every kind.
    pub const ALL: [Self; 3] = [Self::Steady, Self::Npd, Self::Kaimal];

    /// Its name as a person reads it.
    pub fn name(self) -> &'static str {
        match self {
            Self::Steady => "steady",
            Self::Npd => "NPD (API, ISO 19901-1)",
            Self::Kaimal => "Kaimal (IEC 61400-1)",
        }
    }
}

/// IEC 61400-1's reference turbulence intensity of class B, a Kaimal wind's when it is chosen
/// from another kind.
const KAIMAL_INTENSITY: f64 = 0.14;

impl GustsDef {
    /// Which spectrum.
    pub fn kind(&self) -> GustKind {
        match self {
            Self::Steady => GustKind::Steady,
            Self::Npd { .. } => GustKind::Npd,
            Self::Kaimal { .. } => GustKind::Kaimal,
        }
    }

    /// The gusts of `kind`, with this one's seed and number of components where it has them
    /// (the defaults otherwise), a Kaimal wind's intensity IEC class B's (0.14) when it is new.
    pub fn of_kind(&self, kind: GustKind) -> Self {
        let (seed, components) = match *self {
            Self::Steady => (default_seed(), default_components()),
            Self::Npd { seed, components } | Self::Kaimal { seed, components, .. } => (seed, components),
        };
        match (kind, *self) {
            (GustKind::Steady, _) => Self::Steady,
            (GustKind::Npd, _) => Self::Npd { seed, components },
            (GustKind::Kaimal, kaimal @ Self::Kaimal { .. }) => kaimal,
            (GustKind::Kaimal, Self::Steady | Self::Npd { .. }) => {
                Self::Kaimal { intensity: KAIMAL_INTENSITY, length_scale: default_length_scale(), seed, components }
            }
        }
    }
}

/// A body's windage.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Windage", deny_unknown_fields)]
pub struct WindageDef {
    #[serde(deserialize_with = "finite3")]
    pub coefficients: Triple,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite3_option")]
    pub areas: Option<Triple>,
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite3_option")]
    pub center: Option<Triple>,
}

/// A body's rotor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Rotor", deny_unknown_fields)]
pub struct RotorDef {
    #[serde(deserialize_with = "finite3")]
    pub point: Triple,
    #[serde(default = "default_axis", deserialize_with = "finite3")]
    pub axis: Triple,
    #[serde(deserialize_with = "finite")]
    pub area: f64,
    pub thrust: ThrustDef,
}

/// A rotor's thrust curve `C_T(U)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ThrustDef {
    /// `(U [m/s], C_T [–])` points, U increasing.
    Table(#[serde(deserialize_with = "finite_pairs")] Vec<(f64, f64)>),
}

fn default_density() -> f64 {
    AIR_DENSITY
}

fn default_height() -> f64 {
    10.0
}

fn default_seed() -> u64 {
    1
}

fn default_components() -> u32 {
    200
}

/// IEC 61400-1's integral length above 60 m: 8.1 × 42 m.
fn default_length_scale() -> f64 {
    340.2
}

fn default_axis() -> Triple {
    [1.0, 0.0, 0.0]
}

fn vec3(t: Triple) -> Vec3 {
    Vec3::new(t[0], t[1], t[2])
}

impl AirDef {
    /// The physics' spec (degrees to radians), the ramp `water_ramp` \[s] when the section gives
    /// none.
    pub fn spec(&self, water_ramp: f64) -> AirSpec {
        let wind = &self.wind;
        let profile = match wind.profile {
            ProfileDef::PowerLaw(exponent) => WindProfile::PowerLaw(exponent),
            ProfileDef::Logarithmic(roughness) => WindProfile::Logarithmic(roughness),
        };
        let gusts = match wind.gusts {
            GustsDef::Steady => GustSpec::Steady,
            GustsDef::Npd { seed, components } => GustSpec::Npd { seed, components },
            GustsDef::Kaimal { intensity, length_scale, seed, components } => {
                GustSpec::Kaimal { intensity, length_scale, seed, components }
            }
        };
        AirSpec {
            density: self.density,
            wind: WindSpec {
                speed: wind.speed,
                height: wind.height,
                heading: wind.heading_deg.to_radians(),
                profile,
                gusts,
            },
            ramp: self.ramp.unwrap_or(water_ramp),
        }
    }
}

/// A body's wind loads from its `windage` and `rotor`, `None` with neither.
pub fn wind_load_spec(windage: Option<&WindageDef>, rotor: Option<&RotorDef>) -> Option<WindLoadSpec> {
    if windage.is_none() && rotor.is_none() {
        return None;
    }
    Some(WindLoadSpec {
        windage: windage.map(|w| WindageSpec {
            coefficients: w.coefficients,
            areas: w.areas,
            center: w.center.map(vec3),
        }),
        rotor: rotor.map(|r| RotorSpec {
            point: vec3(r.point),
            axis: vec3(r.axis),
            area: r.area,
            thrust: match &r.thrust {
                ThrustDef::Table(points) => points.clone(),
            },
        }),
    })
}
