//! Paths to values of a scene file: `dt`, `integrator`, `bodies.buoy.master.mass`,
//! `couplings.mooring1.stiffness`, `couplings.buoyancy.law.stiffness`, `bodies.buoy.velocity.0`.
//!
//! A path is read against the scene's serde data (the scene file serialised to a
//! [`serde_json::Value`] tree: structs are maps, enums maps of one variant, lists arrays), not
//! against Tether's types, so every section a scene file has — those added after this module
//! too, `water:` or `seabed:` — can be swept without changing it. Segments are separated by
//! dots; at each one:
//! - in a struct, the segment names a field;
//! - in a list, it names the item whose `name` is the segment (a body, a coupling), or gives the
//!   item's index (`gravity.2`, a table's point `law.points.3.1`);
//! - an enum's variant is stepped through without being named (`law.stiffness` in
//!   `law: Linear(stiffness: …)`), or may be named (`law.Linear.stiffness`);
//! - an optional section the scene leaves out (`adaptive`) and a field it leaves to its default
//!   can be set: the scene loader then checks the field exists and the value fits.
//!
//! The path must end at a single value: a number, a name, a flag, or an enum of one value
//! (`substeps` in `substeps: Fixed(4)`, set with a number).

use serde_json::{Map, Value};

/// One step down the tree.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Step {
    /// A field of a struct, or an enum's variant.
    Key(String),
    /// An item of a list.
    Index(usize),
}

/// A path found in a scene's data.
#[derive(Debug, Clone, PartialEq)]
pub struct ValuePath {
    /// As the spec writes it.
    pub text: String,
    steps: Vec<Step>,
    /// The path ends at an enum holding one number (`Fixed(4)`): a number goes inside.
    into_variant: bool,
}

impl ValuePath {
    /// Finds `text` in `tree`.
    ///
    /// # Errors
    /// A message naming the segment that leads nowhere and what is there instead.
    pub fn find(tree: &Value, text: &str) -> Result<Self, String> {
        if text.is_empty() {
            return Err("the path is empty".into());
        }
        let mut steps = Vec::new();
        let mut node = Some(tree);
        let mut walked = String::new();
        for segment in text.split('.') {
            if segment.is_empty() {
                return Err(format!("`{text}` has an empty segment"));
            }
            node = match node {
                // Past an absent optional section: the loader checks the rest.
                None | Some(Value::Null) => {
                    steps.push(Step::Key(segment.to_string()));
                    None
                }
                Some(Value::Object(map)) => {
                    let (taken, next) = in_map(map, segment, &walked)?;
                    steps.extend(taken);
                    next
                }
                Some(Value::Array(items)) => {
                    let index = in_list(items, segment, &walked)?;
                    steps.push(Step::Index(index));
                    Some(&items[index])
                }
                Some(leaf) => {
                    return Err(format!("`{walked}` is {}: nothing is inside it for `{segment}`", describe(leaf)));
                }
            };
            walked = if walked.is_empty() { segment.to_string() } else { format!("{walked}.{segment}") };
        }
        let into_variant = match node {
            None | Some(Value::Null | Value::Number(_) | Value::String(_) | Value::Bool(_)) => false,
            Some(Value::Object(map)) if single_variant(map).is_some_and(|(_, inner)| inner.is_number()) => true,
            Some(Value::Object(map)) => {
                let fields: Vec<&str> = map.keys().map(String::as_str).collect();
                return Err(format!(
                    "`{text}` is not a single value: it holds {}; name one of them",
                    fields.join(", ")
                ));
            }
            Some(Value::Array(items)) => {
                return Err(format!("`{text}` is a list of {}: name one item, e.g. `{text}.0`", items.len()));
            }
        };
        Ok(Self { text: text.to_string(), steps, into_variant })
    }

    /// The steps down the scene's data, as found: a field or an enum's variant, or a list's item
    /// (a named item as its index). The fit writes a value back into the scene's text by them.
    pub fn steps(&self) -> &[Step] {
        &self.steps
    }

    /// Whether the path ends inside an enum of one number (`Fixed(4)`).
    pub fn into_variant(&self) -> bool {
        self.into_variant
    }

    /// The value at the path in `tree`, if the tree has one there (not a section or field the
    /// scene leaves to its default).
    pub fn get<'t>(&self, tree: &'t Value) -> Option<&'t Value> {
        let mut node = tree;
        for step in &self.steps {
            node = match (step, node) {
                (Step::Key(key), Value::Object(map)) => map.get(key)?,
                (Step::Index(index), Value::Array(items)) => items.get(*index)?,
                _ => return None,
            };
        }
        match node {
            Value::Object(map) if self.into_variant => single_variant(map).map(|(_, inner)| inner),
            Value::Null => None,
            value => Some(value),
        }
    }

    /// Sets the value at the path in `tree` to `value`, making the absent sections on the way.
    /// A whole number goes in as an integer (so that it also fits a count, `subdivisions: 4`).
    pub fn set(&self, tree: &mut Value, value: Value) {
        let mut node = tree;
        for step in &self.steps {
            node = match step {
                Step::Key(key) => {
                    if !node.is_object() {
                        *node = Value::Object(Map::new());
                    }
                    let Value::Object(map) = node else { unreachable!("made an object above") };
                    map.entry(key.clone()).or_insert(Value::Null)
                }
                // Indices were found in this tree's shape, which factors do not change.
                Step::Index(index) => match node {
                    Value::Array(items) if *index < items.len() => &mut items[*index],
                    _ => return,
                },
            };
        }
        if self.into_variant
            && let Value::Object(map) = node
            && let Some(inner) = map.values_mut().next()
            && value.is_number()
        {
            *inner = value;
            return;
        }
        *node = value;
    }
}

/// A number as the scene data holds it: whole numbers as integers, so that they fit integer
/// fields as well as real ones; `None` for a number JSON cannot hold (not finite).
pub fn number_value(x: f64) -> Option<Value> {
    // Whole numbers within ±2⁵³ are exact as integers, and read back as the same f64.
    const EXACT: f64 = 9_007_199_254_740_992.0;
    if x.fract() == 0.0 && x.abs() <= EXACT {
        Some(Value::from(x as i64))
    } else {
        serde_json::Number::from_f64(x).map(Value::Number)
    }
}

/// Steps for `segment` in a struct or an enum: the field, or the variant stepped through to it.
fn in_map<'t>(
    map: &'t Map<String, Value>,
    segment: &str,
    walked: &str,
) -> Result<(Vec<Step>, Option<&'t Value>), String> {
    if let Some(next) = map.get(segment) {
        return Ok((vec![Step::Key(segment.to_string())], Some(next)));
    }
    let fields: Vec<&str> = map.keys().map(String::as_str).collect();
    if let Some((variant, inner)) = single_variant(map) {
        return match inner {
            _ if starts_upper(segment) => Err(format!("`{walked}` is `{variant}(…)`, not `{segment}(…)`")),
            Value::Object(inner_fields) => {
                let (mut steps, next) = in_map(inner_fields, segment, walked)?;
                steps.insert(0, Step::Key(variant.to_string()));
                Ok((steps, next))
            }
            _ => Err(format!("`{walked}` is `{variant}(…)`, which has no `{segment}`")),
        };
    }
    // Every section of a scene is in its data (an optional one left out as null), so a name
    // missing at the top is not one; deeper down, a field left to its default is missing from
    // the data, and the scene loader says whether the name exists.
    if walked.is_empty() {
        Err(format!("the scene has no `{segment}` (it has: {})", fields.join(", ")))
    } else if starts_upper(segment) {
        Err(format!("`{walked}` has no `{segment}` (it has: {})", fields.join(", ")))
    } else {
        Ok((vec![Step::Key(segment.to_string())], None))
    }
}

fn starts_upper(text: &str) -> bool {
    text.chars().next().is_some_and(char::is_uppercase)
}

/// The variant and content of an enum value (`{"Linear": {…}}`), if `map` is one.
fn single_variant(map: &Map<String, Value>) -> Option<(&str, &Value)> {
    let mut entries = map.iter();
    let (key, inner) = entries.next()?;
    (entries.next().is_none() && starts_upper(key)).then_some((key.as_str(), inner))
}

/// The item of a list that `segment` names, by `name` or by index.
fn in_list(items: &[Value], segment: &str, walked: &str) -> Result<usize, String> {
    let names: Vec<Option<&str>> = items.iter().map(item_name).collect();
    let named: Vec<usize> = names.iter().enumerate().filter(|(_, n)| **n == Some(segment)).map(|(i, _)| i).collect();
    match named.as_slice() {
        [index] => return Ok(*index),
        [_, _, ..] => return Err(format!("`{walked}` has {} items named \"{segment}\"", named.len())),
        [] => {}
    }
    if let Ok(index) = segment.parse::<usize>() {
        return if index < items.len() {
            Ok(index)
        } else {
            Err(format!("`{walked}` has {} items: no item {index}", items.len()))
        };
    }
    let known: Vec<&str> = names.iter().flatten().copied().collect();
    if known.is_empty() {
        Err(format!("`{walked}` is a list of {} unnamed items: give an index", items.len()))
    } else {
        Err(format!("`{walked}` has no item named \"{segment}\" (it has: {})", known.join(", ")))
    }
}

/// The `name` of a list item: a struct's, or its enum variant's.
fn item_name(item: &Value) -> Option<&str> {
    let map = item.as_object()?;
    match map.get("name") {
        Some(Value::String(name)) => Some(name),
        _ => single_variant(map).and_then(|(_, inner)| inner.get("name")).and_then(Value::as_str),
    }
}

/// `a number`, `the name "rk4"`, …, for messages.
fn describe(leaf: &Value) -> String {
    match leaf {
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the name \"{s}\""),
        Value::Bool(b) => format!("the flag {b}"),
        _ => "a single value".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn tree() -> Value {
        json!({
            "dt": 0.002,
            "integrator": "leapfrog",
            "substeps": {"Fixed": 1},
            "adaptive": null,
            "gravity": [0.0, 0.0, -9.8],
            "bodies": [{"name": "buoy", "master": {"mass": 3000.0}, "shape": {"Box": {"size": [1.0, 1.0, 1.0], "subdivisions": 4}}}],
            "couplings": [
                {"Catenary": {"name": "mooring1", "stiffness": 5e6}},
                {"SpringDamper": {"name": "buoyancy", "law": {"Linear": {"stiffness": 31600.0, "rest_length": 94.0}}, "damping": 1950.0}},
                {"Contact": {"name": "fender", "stiffness": 1e9}}
            ]
        })
    }

    fn at(tree: &Value, path: &str) -> Option<Value> {
        ValuePath::find(tree, path).unwrap_or_else(|e| panic!("{path}: {e}")).get(tree).cloned()
    }

    #[test]
    fn finds_fields_named_items_variants_and_indices() {
        let t = tree();
        assert_eq!(at(&t, "dt"), Some(json!(0.002)));
        assert_eq!(at(&t, "integrator"), Some(json!("leapfrog")));
        assert_eq!(at(&t, "bodies.buoy.master.mass"), Some(json!(3000.0)));
        assert_eq!(at(&t, "couplings.mooring1.stiffness"), Some(json!(5e6)));
        assert_eq!(at(&t, "couplings.buoyancy.law.stiffness"), Some(json!(31600.0)));
        assert_eq!(at(&t, "couplings.buoyancy.law.Linear.stiffness"), Some(json!(31600.0)));
        assert_eq!(at(&t, "couplings.1.damping"), Some(json!(1950.0)));
        assert_eq!(at(&t, "gravity.2"), Some(json!(-9.8)));
        assert_eq!(at(&t, "substeps"), Some(json!(1)));
        assert_eq!(at(&t, "bodies.buoy.shape.subdivisions"), Some(json!(4)));
        // Left to their defaults: found, with no value in the base.
        assert_eq!(at(&t, "adaptive.rtol"), None);
        assert_eq!(at(&t, "couplings.fender.expected_area"), None);
    }

    #[test]
    fn sets_values_in_place_and_makes_absent_sections() {
        let mut t = tree();
        ValuePath::find(&t, "couplings.buoyancy.law.stiffness").unwrap().set(&mut t, json!(1.5e4));
        ValuePath::find(&t, "substeps").unwrap().set(&mut t, number_value(4.0).unwrap());
        ValuePath::find(&t, "adaptive.rtol").unwrap().set(&mut t, json!(1e-8));
        ValuePath::find(&t, "integrator").unwrap().set(&mut t, json!("rk4"));
        assert_eq!(t["couplings"][1]["SpringDamper"]["law"]["Linear"]["stiffness"], json!(1.5e4));
        assert_eq!(t["substeps"], json!({"Fixed": 4}));
        assert_eq!(t["adaptive"], json!({"rtol": 1e-8}));
        assert_eq!(t["integrator"], json!("rk4"));
        assert_eq!(number_value(4.0), Some(json!(4)));
        assert_eq!(number_value(0.25), Some(json!(0.25)));
        assert_eq!(number_value(f64::NAN), None);
    }

    #[test]
    fn says_what_is_there_when_a_path_leads_nowhere() {
        let t = tree();
        let error = |path: &str| ValuePath::find(&t, path).unwrap_err();
        assert_eq!(
            error("couplings.mooring9.stiffness"),
            "`couplings` has no item named \"mooring9\" (it has: mooring1, buoyancy, fender)"
        );
        assert_eq!(
            error("water.waves.height"),
            "the scene has no `water` (it has: adaptive, bodies, couplings, dt, gravity, integrator, substeps)"
        );
        assert_eq!(
            error("couplings.mooring1"),
            "`couplings.mooring1` is not a single value: it holds Catenary; name one of them"
        );
        assert_eq!(error("gravity"), "`gravity` is a list of 3: name one item, e.g. `gravity.0`");
        assert_eq!(error("gravity.3"), "`gravity` has 3 items: no item 3");
        assert_eq!(error("dt.x"), "`dt` is the number 0.002: nothing is inside it for `x`");
        assert_eq!(error("bodies..mass"), "`bodies..mass` has an empty segment");
        assert_eq!(
            error("couplings.buoyancy.law.Polynomial"),
            "`couplings.buoyancy.law` is `Linear(…)`, not `Polynomial(…)`"
        );
    }
}
