//! What a scene file says about how a line is modelled (PHYSICS.md §3 quasi-static, §8
//! dynamic), and its build into the physics' [`LineModel`], whose constructor checks each value.
//!
//! ```ron
//! model: Dynamic(segments: 40, damping: Ratio(0.8), drag_normal: 2.4, drag_tangential: 1.15,
//!                added_mass_normal: 1.0, added_mass_tangential: 0.5)
//! ```

use super::finite::finite;
use serde::{Deserialize, Serialize};
use tether_physics::coupling::{InternalDamping, LineModel, LumpedMass};
use tether_physics::parameter::ParameterError;

/// A line's model: `QuasiStatic` (the default) or `Dynamic(…)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub enum LineModelDef {
    /// The elastic catenary (PHYSICS.md §3, §7): no inertia.
    #[default]
    QuasiStatic,
    /// The lumped-mass line (PHYSICS.md §8): `segments` N (1 … 10,000); `damping` internal,
    /// `Ratio(ζ)` (0 … 1, MoorDyn's negative BA) or `Coefficient(BA)` \[N·s]; drag `drag_normal`
    /// C_dn and `drag_tangential` C_dt, added mass `added_mass_normal` C_an and
    /// `added_mass_tangential` C_at (all ≥ 0, default 0); the seabed under a node:
    /// `seabed_stiffness` k_b [Pa/m] (default 3e6), `seabed_damping` c_b [Pa·s/m] (default
    /// 3e5), `friction_speed` v_s [m/s] (default 0.01) of the seabed's `line_friction`.
    Dynamic {
        segments: u32,
        damping: DampingDef,
        #[serde(default, deserialize_with = "finite")]
        drag_normal: f64,
        #[serde(default, deserialize_with = "finite")]
        drag_tangential: f64,
        #[serde(default, deserialize_with = "finite")]
        added_mass_normal: f64,
        #[serde(default, deserialize_with = "finite")]
        added_mass_tangential: f64,
        #[serde(default = "seabed_stiffness", deserialize_with = "finite")]
        seabed_stiffness: f64,
        #[serde(default = "seabed_damping", deserialize_with = "finite")]
        seabed_damping: f64,
        #[serde(default = "friction_speed", deserialize_with = "finite")]
        friction_speed: f64,
    },
}

/// A dynamic line's internal damping.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum DampingDef {
    /// `ζ` of the highest axial mode: `BA = ζ l √(EA λ0)`.
    Ratio(#[serde(deserialize_with = "finite")] f64),
    /// `BA` \[N·s].
    Coefficient(#[serde(deserialize_with = "finite")] f64),
}

fn seabed_stiffness() -> f64 {
    LumpedMass::SEABED_STIFFNESS
}

fn seabed_damping() -> f64 {
    LumpedMass::SEABED_DAMPING
}

fn friction_speed() -> f64 {
    LumpedMass::FRICTION_SPEED
}

impl LineModelDef {
    /// A dynamic line of `segments` with a wire's coefficients (C_dn 1.2, C_dt 0.008, C_an 1,
    /// C_at 0), ζ = 0.8 and MoorDyn's seabed: what a quasi-static line becomes when switched.
    pub fn wire(segments: u32) -> Self {
        Self::Dynamic {
            segments,
            damping: DampingDef::Ratio(0.8),
            drag_normal: 1.2,
            drag_tangential: 0.008,
            added_mass_normal: 1.0,
            added_mass_tangential: 0.0,
            seabed_stiffness: LumpedMass::SEABED_STIFFNESS,
            seabed_damping: LumpedMass::SEABED_DAMPING,
            friction_speed: LumpedMass::FRICTION_SPEED,
        }
    }

    /// The model dynamic at `count` segments: a dynamic one keeps its other values, a
    /// quasi-static one becomes [`LineModelDef::wire`].
    pub fn dynamic_with(mut self, count: u32) -> Self {
        match &mut self {
            Self::Dynamic { segments, .. } => {
                *segments = count;
                self
            }
            Self::QuasiStatic => Self::wire(count),
        }
    }

    /// Whether this is the default, quasi-static model (left out when a file is written).
    pub fn is_quasi_static(&self) -> bool {
        *self == Self::QuasiStatic
    }

    /// The physics' model.
    ///
    /// # Errors
    /// A value out of its range, by [`LumpedMass::new`].
    pub fn build(&self) -> Result<LineModel, ParameterError> {
        match *self {
            Self::QuasiStatic => Ok(LineModel::QuasiStatic),
            Self::Dynamic {
                segments,
                damping,
                drag_normal,
                drag_tangential,
                added_mass_normal,
                added_mass_tangential,
                seabed_stiffness,
                seabed_damping,
                friction_speed,
            } => Ok(LineModel::Dynamic(LumpedMass::new(LumpedMass {
                segments,
                damping: match damping {
                    DampingDef::Ratio(zeta) => InternalDamping::Ratio(zeta),
                    DampingDef::Coefficient(ba) => InternalDamping::Coefficient(ba),
                },
                drag_normal,
                drag_tangential,
                added_mass_normal,
                added_mass_tangential,
                seabed_stiffness,
                seabed_damping,
                friction_speed,
            })?)),
        }
    }
}
