//! A dynamic line's parameters beyond those it shares with the catenary (PHYSICS.md §8), and
//! the model a line coupling runs: [`LineModel`]. The values come in as a [`LumpedMassSpec`]
//! (plain fields, as a scene file or an importer states them) and are checked once, by
//! [`LumpedMass::new`]; a [`LumpedMass`] is only ever a checked one.

use crate::parameter::{Bound, ParameterError, require};

/// Most segments a line may have: past this the sub-step shrinks as `1/N` and the cost grows
/// as `N²` per simulated second for no gain in accuracy a mooring study can use.
pub const MAX_SEGMENTS: u32 = 10_000;

/// How a line coupling is modelled: `QuasiStatic` (the default) or `Dynamic`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum LineModel {
    /// The elastic catenary of PHYSICS.md §3/§7: no inertia, tension from the end positions.
    #[default]
    QuasiStatic,
    /// The lumped-mass line of PHYSICS.md §8.
    Dynamic(LumpedMass),
}

/// Internal (axial) damping of the line's segments (PHYSICS.md §8).
#[derive(Debug, Clone, Copy, PartialEq)]
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

/// The values of a dynamic line as stated, unchecked: [`LumpedMass::new`] checks them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LumpedMassSpec {
    /// `N` segments, 1 ..= [`MAX_SEGMENTS`].
    pub segments: u32,
    /// `BA` or `ζ`, ≥ 0 (`ζ` ≤ 1).
    pub damping: InternalDamping,
    /// `C_dn` [–] ≥ 0: drag normal to the line, on the diameter `d`.
    pub drag_normal: f64,
    /// `C_dt` [–] ≥ 0: drag tangential to the line, on the surface `π d` per length.
    pub drag_tangential: f64,
    /// `C_an` [–] ≥ 0: added mass normal to the line, on `ρ A_d` per length.
    pub added_mass_normal: f64,
    /// `C_at` [–] ≥ 0: added mass tangential to the line, on `ρ A_d` per length.
    pub added_mass_tangential: f64,
    /// `k_b` [Pa/m] > 0 of the seabed under a node: per penetration `δ` the bottom pushes
    /// `(k_b δ − c_b v_z) d l_i`.
    pub seabed_stiffness: f64,
    /// `c_b` [Pa·s/m] ≥ 0 of the seabed under a node.
    pub seabed_damping: f64,
    /// `v_s` [m/s] > 0: the sliding speed at which the seabed's friction reaches `tanh(1)` of
    /// its Coulomb value (§4's regularisation).
    pub friction_speed: f64,
}

impl LumpedMassSpec {
    /// MoorDyn's defaults for the seabed (`kBot` 3·10⁶ Pa/m, `cBot` 3·10⁵ Pa·s/m) and a
    /// friction speed of 1 cm/s: what a file that leaves them out gets.
    pub const SEABED_STIFFNESS: f64 = 3.0e6;
    pub const SEABED_DAMPING: f64 = 3.0e5;
    pub const FRICTION_SPEED: f64 = 0.01;

    /// A dynamic line of `segments` with a wire's coefficients (C_dn 1.2, C_dt 0.008, C_an 1,
    /// C_at 0), ζ = 0.8 and MoorDyn's seabed: what a quasi-static line becomes when switched.
    pub fn wire(segments: u32) -> Self {
        Self {
            drag_normal: 1.2,
            drag_tangential: 0.008,
            added_mass_normal: 1.0,
            ..Self::plain(segments, InternalDamping::Ratio(0.8))
        }
    }

    /// `N` segments with damping `damping`, no drag, no added mass and MoorDyn's seabed.
    pub fn plain(segments: u32, damping: InternalDamping) -> Self {
        Self {
            segments,
            damping,
            drag_normal: 0.0,
            drag_tangential: 0.0,
            added_mass_normal: 0.0,
            added_mass_tangential: 0.0,
            seabed_stiffness: Self::SEABED_STIFFNESS,
            seabed_damping: Self::SEABED_DAMPING,
            friction_speed: Self::FRICTION_SPEED,
        }
    }
}

/// The parameters of a dynamic line beyond those it shares with the catenary, built by
/// [`LumpedMass::new`], which checks each; read through its accessors (documented on
/// [`LumpedMassSpec`]'s fields).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LumpedMass {
    values: LumpedMassSpec,
}

impl LumpedMass {
    /// `spec` with each value checked.
    ///
    /// # Errors
    /// A value out of its range, named as the scene file spells it.
    pub fn new(spec: LumpedMassSpec) -> Result<Self, ParameterError> {
        if !(1..=MAX_SEGMENTS).contains(&spec.segments) {
            return Err(if spec.segments < 1 {
                ParameterError::TooFew { field: "segments", value: spec.segments, least: 1 }
            } else {
                ParameterError::TooMany { field: "segments", value: spec.segments, most: MAX_SEGMENTS }
            });
        }
        let damping = match spec.damping {
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
        let values = LumpedMassSpec {
            segments: spec.segments,
            damping,
            drag_normal: require("drag_normal", spec.drag_normal, Bound::NonNegative, "")?,
            drag_tangential: require("drag_tangential", spec.drag_tangential, Bound::NonNegative, "")?,
            added_mass_normal: require("added_mass_normal", spec.added_mass_normal, Bound::NonNegative, "")?,
            added_mass_tangential: require(
                "added_mass_tangential",
                spec.added_mass_tangential,
                Bound::NonNegative,
                "",
            )?,
            seabed_stiffness: require("seabed_stiffness", spec.seabed_stiffness, Bound::Positive, "Pa/m")?,
            seabed_damping: require("seabed_damping", spec.seabed_damping, Bound::NonNegative, "Pa·s/m")?,
            friction_speed: require("friction_speed", spec.friction_speed, Bound::Positive, "m/s")?,
        };
        Ok(Self { values })
    }

    /// [`LumpedMassSpec::plain`], checked.
    ///
    /// # Errors
    /// As [`LumpedMass::new`].
    pub fn plain(segments: u32, damping: InternalDamping) -> Result<Self, ParameterError> {
        Self::new(LumpedMassSpec::plain(segments, damping))
    }

    /// The checked values, as a spec (to write them out, or to change one and check again).
    pub fn spec(&self) -> LumpedMassSpec {
        self.values
    }

    pub fn segments(&self) -> u32 {
        self.values.segments
    }

    pub fn damping(&self) -> InternalDamping {
        self.values.damping
    }

    pub fn drag_normal(&self) -> f64 {
        self.values.drag_normal
    }

    pub fn drag_tangential(&self) -> f64 {
        self.values.drag_tangential
    }

    pub fn added_mass_normal(&self) -> f64 {
        self.values.added_mass_normal
    }

    pub fn added_mass_tangential(&self) -> f64 {
        self.values.added_mass_tangential
    }

    pub fn seabed_stiffness(&self) -> f64 {
        self.values.seabed_stiffness
    }

    pub fn seabed_damping(&self) -> f64 {
        self.values.seabed_damping
    }

    pub fn friction_speed(&self) -> f64 {
        self.values.friction_speed
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
        let refused = LumpedMass::new(LumpedMassSpec { drag_normal: f64::NAN, ..ok.spec() }).unwrap_err();
        assert_eq!(refused.field(), "drag_normal");
        let refused = LumpedMass::new(LumpedMassSpec { added_mass_tangential: -0.1, ..ok.spec() }).unwrap_err();
        assert_eq!(refused.to_string(), "added_mass_tangential must be ≥ 0, got -0.1");
        let refused = LumpedMass::new(LumpedMassSpec { seabed_stiffness: 0.0, ..ok.spec() }).unwrap_err();
        assert_eq!(refused.to_string(), "seabed_stiffness must be > 0 Pa/m, got 0");
    }

    #[test]
    fn a_damping_ratio_is_moordyn_s_coefficient() {
        // MoorDyn's chain of the dynamic-line issue at N = 40: BA = 0.8 · 6.25 · √(EA λ0).
        let ba = InternalDamping::Ratio(0.8).coefficient(6.25, 110_678_400.0, 25.7904);
        assert!((ba - 267_135.0).abs() < 1.0, "{ba}");
    }
}
