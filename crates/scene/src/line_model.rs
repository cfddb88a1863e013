//! How a line coupling's model is written in a scene file (PHYSICS.md §8): `QuasiStatic`, or
//!
//! ```ron
//! model: Dynamic(segments: 40, damping: Ratio(0.8), drag_normal: 2.4, drag_tangential: 1.15,
//!                added_mass_normal: 1.0, added_mass_tangential: 0.5)
//! ```
//!
//! with [`LumpedMassSpec`]'s fields inside the variant's one pair of parentheses. The build turns
//! it into the physics' [`LineModel`] through [`LineModelDef::build`], where
//! [`LumpedMass::new`] refuses a value out of its range.
//!
//! `Dynamic` holds one struct, yet the file writes a struct variant: serde's derive would write a
//! newtype variant, `Dynamic((segments: 40, …))`, and RON's `unwrap_variant_newtypes` extension,
//! which would accept the single parentheses, does so for every newtype variant of the file and so
//! refuses `World((237.0, 0.0, -50.0))`. Hence the two impls here: the struct variant's fields go
//! to [`LumpedMassSpecForm`]'s derived `Deserialize` through serde's `MapAccessDeserializer`, and
//! are written field by field from an exhaustive destructuring (a field added to
//! [`LumpedMassSpec`] fails to compile here until it is written).

use crate::spelling::{InternalDampingForm, LumpedMassSpecForm};
use serde::de::value::MapAccessDeserializer;
use serde::de::{EnumAccess, MapAccess, VariantAccess, Visitor};
use serde::ser::SerializeStructVariant;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;
use tether_physics::coupling::{InternalDamping, LineModel, LumpedMass, LumpedMassSpec};
use tether_physics::parameter::ParameterError;

/// A line coupling's `model:` as written: `QuasiStatic` (the default) or `Dynamic(…)`, the
/// physics' [`LumpedMassSpec`] as the file states it (its spelling: [`LumpedMassSpecForm`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum LineModelDef {
    /// The elastic catenary of PHYSICS.md §3/§7.
    #[default]
    QuasiStatic,
    /// The lumped-mass line of PHYSICS.md §8.
    Dynamic(LumpedMassSpec),
}

impl LineModelDef {
    /// Whether this is the default, quasi-static model (left out when a file is written).
    pub fn is_quasi_static(&self) -> bool {
        *self == Self::QuasiStatic
    }

    /// The model dynamic at `count` segments: a dynamic one keeps its other values, a
    /// quasi-static one becomes [`LumpedMassSpec::wire`].
    pub fn dynamic_with(self, count: u32) -> Self {
        match self {
            Self::Dynamic(line) => Self::Dynamic(LumpedMassSpec { segments: count, ..line }),
            Self::QuasiStatic => Self::Dynamic(LumpedMassSpec::wire(count)),
        }
    }

    /// The physics' model, each value checked ([`LumpedMass::new`]).
    ///
    /// # Errors
    /// A value out of its range, named by its field.
    pub fn build(self) -> Result<LineModel, ParameterError> {
        match self {
            Self::QuasiStatic => Ok(LineModel::QuasiStatic),
            Self::Dynamic(line) => Ok(LineModel::Dynamic(LumpedMass::new(line)?)),
        }
    }
}

const NAME: &str = "LineModel";
const VARIANTS: &[&str] = &["QuasiStatic", "Dynamic"];
const FIELDS: &[&str] = &[
    "segments",
    "damping",
    "drag_normal",
    "drag_tangential",
    "added_mass_normal",
    "added_mass_tangential",
    "seabed_stiffness",
    "seabed_damping",
    "friction_speed",
];

/// The variant's name as the file spells it.
#[derive(Deserialize)]
#[serde(variant_identifier)]
enum Variant {
    QuasiStatic,
    Dynamic,
}

struct ModelVisitor;

impl<'de> Visitor<'de> for ModelVisitor {
    type Value = LineModelDef;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a line model, QuasiStatic or Dynamic(segments: …, damping: …)")
    }

    fn visit_enum<A: EnumAccess<'de>>(self, data: A) -> Result<LineModelDef, A::Error> {
        let (variant, access) = data.variant::<Variant>()?;
        match variant {
            Variant::QuasiStatic => access.unit_variant().map(|()| LineModelDef::QuasiStatic),
            Variant::Dynamic => access.struct_variant(FIELDS, DynamicLineVisitor).map(LineModelDef::Dynamic),
        }
    }
}

/// The fields of `Dynamic(…)`, read by [`LumpedMassSpecForm`]'s derived `Deserialize`.
struct DynamicLineVisitor;

impl<'de> Visitor<'de> for DynamicLineVisitor {
    type Value = LumpedMassSpec;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a dynamic line's parameters (segments: …, damping: …)")
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<LumpedMassSpec, A::Error> {
        LumpedMassSpecForm::deserialize(MapAccessDeserializer::new(map))
    }
}

impl<'de> Deserialize<'de> for LineModelDef {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_enum(NAME, VARIANTS, ModelVisitor)
    }
}

impl Serialize for LineModelDef {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Self::QuasiStatic => serializer.serialize_unit_variant(NAME, 0, VARIANTS[0]),
            Self::Dynamic(line) => {
                let LumpedMassSpec {
                    segments,
                    damping,
                    drag_normal,
                    drag_tangential,
                    added_mass_normal,
                    added_mass_tangential,
                    seabed_stiffness,
                    seabed_damping,
                    friction_speed,
                } = line;
                let mut variant = serializer.serialize_struct_variant(NAME, 1, VARIANTS[1], FIELDS.len())?;
                variant.serialize_field(FIELDS[0], segments)?;
                variant.serialize_field(FIELDS[1], &Damping(damping))?;
                variant.serialize_field(FIELDS[2], drag_normal)?;
                variant.serialize_field(FIELDS[3], drag_tangential)?;
                variant.serialize_field(FIELDS[4], added_mass_normal)?;
                variant.serialize_field(FIELDS[5], added_mass_tangential)?;
                variant.serialize_field(FIELDS[6], seabed_stiffness)?;
                variant.serialize_field(FIELDS[7], seabed_damping)?;
                variant.serialize_field(FIELDS[8], friction_speed)?;
                variant.end()
            }
        }
    }
}

/// A line's damping written as the file spells it ([`InternalDampingForm`]).
struct Damping<'a>(&'a InternalDamping);

impl Serialize for Damping<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        InternalDampingForm::serialize(self.0, serializer)
    }
}
