//! How a [`LineModel`] is written in a scene file (PHYSICS.md §8): `QuasiStatic`, or
//! `Dynamic(segments: 40, damping: Ratio(0.8), …)` with [`LumpedMass`]'s own fields inside the
//! variant's one pair of parentheses — a struct variant, though the type is the newtype
//! `LineModel::Dynamic(LumpedMass)`, so that the scene file reads and writes the physics' type
//! itself (no mirror of its fields) while shipped files keep their syntax.
//!
//! Serde's derive would write a newtype variant, `Dynamic((segments: 40, …))`; RON's
//! `unwrap_variant_newtypes` extension would accept the single parentheses, but for every newtype
//! variant of the file, and so refuses `World((237.0, 0.0, -50.0))`. Hence the two impls here:
//! the struct variant's fields go to [`LumpedMass`]'s derived `Deserialize` through serde's
//! `MapAccessDeserializer`, and are written field by field from an exhaustive destructuring (a
//! field added to [`LumpedMass`] fails to compile here until it is written).

use super::parameters::{LineModel, LumpedMass};
use serde::de::value::MapAccessDeserializer;
use serde::de::{EnumAccess, MapAccess, VariantAccess, Visitor};
use serde::ser::SerializeStructVariant;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

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
    type Value = LineModel;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a line model, QuasiStatic or Dynamic(segments: …, damping: …)")
    }

    fn visit_enum<A: EnumAccess<'de>>(self, data: A) -> Result<LineModel, A::Error> {
        let (variant, access) = data.variant::<Variant>()?;
        match variant {
            Variant::QuasiStatic => access.unit_variant().map(|()| LineModel::QuasiStatic),
            Variant::Dynamic => access.struct_variant(FIELDS, LumpedMassVisitor).map(LineModel::Dynamic),
        }
    }
}

/// The fields of `Dynamic(…)`, read by [`LumpedMass`]'s derived `Deserialize`.
struct LumpedMassVisitor;

impl<'de> Visitor<'de> for LumpedMassVisitor {
    type Value = LumpedMass;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str("a dynamic line's parameters (segments: …, damping: …)")
    }

    fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<LumpedMass, A::Error> {
        LumpedMass::deserialize(MapAccessDeserializer::new(map))
    }
}

impl<'de> Deserialize<'de> for LineModel {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_enum(NAME, VARIANTS, ModelVisitor)
    }
}

impl Serialize for LineModel {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Self::QuasiStatic => serializer.serialize_unit_variant(NAME, 0, VARIANTS[0]),
            Self::Dynamic(line) => {
                let LumpedMass {
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
                variant.serialize_field(FIELDS[1], damping)?;
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
