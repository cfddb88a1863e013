//! A dynamic line's parameters beyond those it shares with the catenary (PHYSICS.md §8), and
//! the model a line coupling runs: [`LineModel`]. These are also the scene file's types (one type
//! from the file to the step): a file writes
//!
//! ```ron
//! model: Dynamic(segments: 40, damping: Ratio(0.8), drag_normal: 2.4, drag_tangential: 1.15,
//!                added_mass_normal: 1.0, added_mass_tangential: 0.5)
//! ```
//!
//! and the scene's build passes what was read through [`LumpedMass::new`], the one place that
//! refuses a value out of its range.

use crate::parameter::{Bound, ParameterError, require};

/// Most segments a line may have: past this the sub-step shrinks as `1/N` and the cost grows
/// as `N²` per simulated second for no gain in accuracy a mooring study can use.
pub const MAX_SEGMENTS: u32 = 10_000;

/// How a line coupling is modelled: `QuasiStatic` (the default) or `Dynamic(…)`, written in a
/// scene file as [`super::file_form`] says.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum LineModel {
    /// The elastic catenary of PHYSICS.md §3/§7: no inertia, tension from the end positions.
    #[default]
    QuasiStatic,
    /// The lumped-mass line of PHYSICS.md §8.
    Dynamic(LumpedMass),
}

impl LineModel {
    /// The model dynamic at `count` segments: a dynamic one keeps its other values, a
    /// quasi-static one becomes [`LumpedMass::wire`].
    pub fn dynamic_with(self, count: u32) -> Self {
        match self {
            Self::Dynamic(line) => Self::Dynamic(LumpedMass { segments: count, ..line }),
            Self::QuasiStatic => Self::Dynamic(LumpedMass::wire(count)),
        }
    }

    /// Whether this is the default, quasi-static model (left out when a file is written).
    pub fn is_quasi_static(&self) -> bool {
        *self == Self::QuasiStatic
    }

    /// This model with each of its values checked ([`LumpedMass::new`]).
    ///
    /// # Errors
    /// A value out of its range.
    pub fn checked(self) -> Result<Self, ParameterError> {
        match self {
            Self::QuasiStatic => Ok(Self::QuasiStatic),
            Self::Dynamic(line) => Ok(Self::Dynamic(LumpedMass::new(line)?)),
        }
    }
}

/// Internal (axial) damping of the line's segments (PHYSICS.md §8).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum InternalDamping {
    /// `BA` \[N·s]: a segment carries `BA ε̇` along it.
    Coefficient(f64),
    /// A damping ratio `ζ` of the line's highest axial mode: `BA = ζ l √(EA λ0)` (MoorDyn's
    /// negative `BA` input).
    Ratio(f64),
}

impl InternalDamping {
    /// `BA` \[N·s] for segments of unstretched length `segment` l \[m], axial stiffness `ea` \[N]
    /// and mass per length `mass_per_length` λ0 [kg/m].
    pub fn coefficient(&self, segment: f64, ea: f64, mass_per_length: f64) -> f64 {
        match *self {
            Self::Coefficient(ba) => ba,
            Self::Ratio(zeta) => zeta * segment * (ea * mass_per_length).sqrt(),
        }
    }
}

/// The parameters of a dynamic line beyond those it shares with the catenary, built by
/// [`LumpedMass::new`], which checks each. A file may leave out the drag and added-mass
/// coefficients (0) and the seabed's values (MoorDyn's, [`LumpedMass::SEABED_STIFFNESS`] …).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LumpedMass {
    /// `N` segments, 1 ..= [`MAX_SEGMENTS`].
    pub segments: u32,
    /// `BA` or `ζ`, ≥ 0 (`ζ` ≤ 1).
    pub damping: InternalDamping,
    /// `C_dn`, `C_dt` [–] ≥ 0: drag normal and tangential to the line, on the diameter `d`
    /// and on the surface `π d` per length.
    #[serde(default)]
    pub drag_normal: f64,
    #[serde(default)]
    pub drag_tangential: f64,
    /// `C_an`, `C_at` [–] ≥ 0: added mass normal and tangential, on `ρ A_d` per length.
    #[serde(default)]
    pub added_mass_normal: f64,
    #[serde(default)]
    pub added_mass_tangential: f64,
    /// `k_b` [Pa/m] > 0 and `c_b` [Pa·s/m] ≥ 0 of the seabed under a node: per penetration
    /// `δ` the bottom pushes `(k_b δ − c_b v_z) d l_i`.
    #[serde(default = "LumpedMass::default_seabed_stiffness")]
    pub seabed_stiffness: f64,
    #[serde(default = "LumpedMass::default_seabed_damping")]
    pub seabed_damping: f64,
    /// `v_s` [m/s] > 0: the sliding speed at which the seabed's friction reaches `tanh(1)` of
    /// its Coulomb value (§4's regularisation).
    #[serde(default = "LumpedMass::default_friction_speed")]
    pub friction_speed: f64,
}

impl LumpedMass {
    /// MoorDyn's defaults for the seabed (`kBot` 3·10⁶ Pa/m, `cBot` 3·10⁵ Pa·s/m) and a
    /// friction speed of 1 cm/s.
    pub const SEABED_STIFFNESS: f64 = 3.0e6;
    pub const SEABED_DAMPING: f64 = 3.0e5;
    pub const FRICTION_SPEED: f64 = 0.01;

    fn default_seabed_stiffness() -> f64 {
        Self::SEABED_STIFFNESS
    }

    fn default_seabed_damping() -> f64 {
        Self::SEABED_DAMPING
    }

    fn default_friction_speed() -> f64 {
        Self::FRICTION_SPEED
    }

    /// `parts` with each value checked.
    ///
    /// # Errors
    /// A value out of its range, named as the scene file spells it.
    pub fn new(parts: Self) -> Result<Self, ParameterError> {
        if !(1..=MAX_SEGMENTS).contains(&parts.segments) {
            return Err(if parts.segments < 1 {
                ParameterError::TooFew { field: "segments", value: parts.segments, least: 1 }
            } else {
                ParameterError::TooMany { field: "segments", value: parts.segments, most: MAX_SEGMENTS }
            });
        }
        let damping = match parts.damping {
            InternalDamping::Coefficient(ba) => {
                InternalDamping::Coefficient(require("damping", ba, Bound::NonNegative, "N·s")?)
            }
            InternalDamping::Ratio(zeta) => {
                let zeta = require("damping ratio", zeta, Bound::NonNegative, "")?;
                if zeta > 1.0 {
                    return Err(ParameterError::OutOfRange {
                        field: "damping ratio",
                        value: zeta,
                        bound: Bound::UnitInterval,
                        unit: "",
                    });
                }
                InternalDamping::Ratio(zeta)
            }
        };
        Ok(Self {
            segments: parts.segments,
            damping,
            drag_normal: require("drag_normal", parts.drag_normal, Bound::NonNegative, "")?,
            drag_tangential: require("drag_tangential", parts.drag_tangential, Bound::NonNegative, "")?,
            added_mass_normal: require("added_mass_normal", parts.added_mass_normal, Bound::NonNegative, "")?,
            added_mass_tangential: require(
                "added_mass_tangential",
                parts.added_mass_tangential,
                Bound::NonNegative,
                "",
            )?,
            seabed_stiffness: require("seabed_stiffness", parts.seabed_stiffness, Bound::Positive, "Pa/m")?,
            seabed_damping: require("seabed_damping", parts.seabed_damping, Bound::NonNegative, "Pa·s/m")?,
            friction_speed: require("friction_speed", parts.friction_speed, Bound::Positive, "m/s")?,
        })
    }

    /// A dynamic line of `segments` with a wire's coefficients (C_dn 1.2, C_dt 0.008, C_an 1,
    /// C_at 0), ζ = 0.8 and MoorDyn's seabed: what a quasi-static line becomes when switched
    /// (unchecked: [`LumpedMass::new`] checks it where the scene is built).
    pub fn wire(segments: u32) -> Self {
        Self {
            segments,
            damping: InternalDamping::Ratio(0.8),
            drag_normal: 1.2,
            drag_tangential: 0.008,
            added_mass_normal: 1.0,
            added_mass_tangential: 0.0,
            seabed_stiffness: Self::SEABED_STIFFNESS,
            seabed_damping: Self::SEABED_DAMPING,
            friction_speed: Self::FRICTION_SPEED,
        }
    }

    /// `N` segments with damping `damping`, no drag, no added mass and MoorDyn's seabed.
    ///
    /// # Errors
    /// As [`LumpedMass::new`].
    pub fn plain(segments: u32, damping: InternalDamping) -> Result<Self, ParameterError> {
        Self::new(Self {
            segments,
            damping,
            drag_normal: 0.0,
            drag_tangential: 0.0,
            added_mass_normal: 0.0,
            added_mass_tangential: 0.0,
            seabed_stiffness: Self::SEABED_STIFFNESS,
            seabed_damping: Self::SEABED_DAMPING,
            friction_speed: Self::FRICTION_SPEED,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_bad_value_is_refused_by_name() {
        let ok = LumpedMass::plain(40, InternalDamping::Ratio(0.8)).unwrap();
        assert_eq!(
            LumpedMass::plain(0, InternalDamping::Ratio(0.8)).unwrap_err().to_string(),
            "segments must be at least 1, got 0"
        );
        assert_eq!(
            LumpedMass::plain(10_001, InternalDamping::Ratio(0.8)).unwrap_err().to_string(),
            "segments must be at most 10000, got 10001"
        );
        assert_eq!(
            LumpedMass::plain(4, InternalDamping::Ratio(1.5)).unwrap_err().to_string(),
            "damping ratio must be ≥ 0 and ≤ 1, got 1.5"
        );
        assert_eq!(
            LumpedMass::plain(4, InternalDamping::Coefficient(-1.0)).unwrap_err().to_string(),
            "damping must be ≥ 0 N·s, got -1"
        );
        let refused = LumpedMass::new(LumpedMass { drag_normal: f64::NAN, ..ok }).unwrap_err();
        assert_eq!(refused.field(), "drag_normal");
        let refused = LumpedMass::new(LumpedMass { added_mass_tangential: -0.1, ..ok }).unwrap_err();
        assert_eq!(refused.to_string(), "added_mass_tangential must be ≥ 0, got -0.1");
        let refused = LumpedMass::new(LumpedMass { seabed_stiffness: 0.0, ..ok }).unwrap_err();
        assert_eq!(refused.to_string(), "seabed_stiffness must be > 0 Pa/m, got 0");
    }

    #[test]
    fn a_damping_ratio_is_moordyn_s_coefficient() {
        // MoorDyn's chain of the dynamic-line issue at N = 40: BA = 0.8 · 6.25 · √(EA λ0).
        let ba = InternalDamping::Ratio(0.8).coefficient(6.25, 110_678_400.0, 25.7904);
        assert!((ba - 267_135.0).abs() < 1.0, "{ba}");
    }
}
