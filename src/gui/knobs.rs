//! A group of knobs over values of the scene file (the couplings, the water, each body's water
//! coefficients): what each knob shows, accepted or not, and which of its fields were refused
//! and why; an edited one checked by the scene builder into the tuned scene, field by field
//! when the builder refuses the whole (a fixed field applies though another stays refused);
//! all of them back to what the file says.
//! No egui in it, and no check of its own: a value is what the [`Group`]'s build says it is.

use super::simulation::Command;
use crate::figures;
use serde::Serialize;
use serde::de::DeserializeOwned;
use serde_json::Value;
use tether_scene::SceneFile;
use tether_scene::build::Bodies;

/// Where a group's values are in a scene file and how the scene builder turns one into the
/// command that applies it to the running simulation — or why it refuses it (`R`, shown as the
/// builder words it). Knob `index` is value `index` of `values`.
pub struct Group<D, R> {
    /// The group's values in a scene file, in knob order.
    pub values: fn(&SceneFile) -> Vec<D>,
    /// Value `index` of a scene file set to this.
    pub put: fn(&mut SceneFile, usize, D),
    /// Value `index` of a candidate scene, checked and built against the scene's bodies.
    pub build: fn(&SceneFile, usize, &mut Bodies) -> Result<Command, R>,
}

/// One knob: what it shows (accepted or not) and, for each of its fields the scene builder
/// refused, why (the run keeps its own value of those fields).
#[derive(Debug, Clone, PartialEq)]
pub struct Knob<D, R> {
    pub draft: D,
    pub refusals: Vec<Refused<R>>,
}

/// A field of a knob's draft that the scene builder refused: the run goes on with its value.
#[derive(Debug, Clone, PartialEq)]
pub struct Refused<R> {
    /// The field, as the scene file names it (`waves.tp`, `law.stiffness`, `drag[2]`).
    pub field: String,
    /// The draft's value of it, and the one the run uses, as a person reads them.
    pub draft: String,
    pub running: String,
    pub reason: R,
}

impl<R: std::fmt::Display> std::fmt::Display for Refused<R> {
    /// `law.stiffness = -5 not applied (the run keeps 200000): stiffness must be ≥ 0 N/m, got -5`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} = {} not applied (the run keeps {}): {}", self.field, self.draft, self.running, self.reason)
    }
}

/// A field of a draft that differs from what runs: where it is (a JSON pointer into the
/// draft's serde tree) and the draft's value there.
struct Edit {
    pointer: String,
    value: Value,
}

/// The fields where `draft` differs from `running`, deepest first: objects with the same keys
/// and arrays of the same length are compared member by member; anything else (a line switched
/// to dynamic, a table grown) differs whole.
fn edits(draft: &Value, running: &Value, pointer: &str, found: &mut Vec<Edit>) {
    match (draft, running) {
        (Value::Object(d), Value::Object(r)) if d.len() == r.len() && d.keys().all(|k| r.contains_key(k)) => {
            for (key, value) in d {
                let escaped = key.replace('~', "~0").replace('/', "~1");
                edits(value, &r[key], &format!("{pointer}/{escaped}"), found);
            }
        }
        (Value::Array(d), Value::Array(r)) if d.len() == r.len() => {
            for (index, (value, running)) in d.iter().zip(r).enumerate() {
                edits(value, running, &format!("{pointer}/{index}"), found);
            }
        }
        _ if draft != running => found.push(Edit { pointer: pointer.to_string(), value: draft.clone() }),
        _ => {}
    }
}

/// A pointer as a person reads the field: variant names (capitalised) left out, array indices
/// in brackets: `/Catenary/length` → `length`, `/waves/Jonswap/tp` → `waves.tp`, `/drag/2` →
/// `drag[2]`; the whole value is "value".
fn field_name(pointer: &str) -> String {
    let mut name = String::new();
    for part in pointer.split('/').skip(1) {
        if part.starts_with(|c: char| c.is_ascii_uppercase()) {
            continue;
        }
        if part.parse::<usize>().is_ok() {
            name.push_str(&format!("[{part}]"));
        } else {
            if !name.is_empty() {
                name.push('.');
            }
            name.push_str(&part.replace("~1", "/").replace("~0", "~"));
        }
    }
    if name.is_empty() { "value".into() } else { name }
}

/// A value of a draft as a person reads it: numbers by [`figures::editable`], the rest as JSON.
fn shown(value: Option<&Value>) -> String {
    match value {
        Some(Value::Number(n)) => n.as_f64().map_or_else(|| n.to_string(), |x| figures::editable(x, 6)),
        Some(other) => other.to_string(),
        None => "none".into(),
    }
}

/// The knobs of one [`Group`].
pub struct Knobs<D: 'static, R: 'static> {
    group: &'static Group<D, R>,
    knobs: Vec<Knob<D, R>>,
}

impl<D: Clone + PartialEq + Serialize + DeserializeOwned + 'static, R: 'static> Knobs<D, R> {
    /// The knobs of `group`, showing what `file` says.
    pub fn of(group: &'static Group<D, R>, file: &SceneFile) -> Self {
        let knobs = (group.values)(file).into_iter().map(|draft| Knob { draft, refusals: Vec::new() }).collect();
        Self { group, knobs }
    }

    /// The knobs, to draw and edit.
    pub fn knobs(&self) -> &[Knob<D, R>] {
        &self.knobs
    }

    /// The knobs, to draw and edit (an edited one is then [`tune`](Self::tune)d).
    pub fn knobs_mut(&mut self) -> &mut [Knob<D, R>] {
        &mut self.knobs
    }

    /// Knob `index` shows what `file` says (a fit's values; then [`tune`](Self::tune) it).
    pub fn show(&mut self, index: usize, file: &SceneFile) {
        let value = (self.group.values)(file).into_iter().nth(index);
        if let (Some(knob), Some(value)) = (self.knobs.get_mut(index), value) {
            knob.draft = value;
        }
    }

    /// Checks knob `index`'s draft with the scene builder, in `tuned` with its other values.
    /// The draft's edits (its fields that differ from what runs) are tried together, and if
    /// the builder refuses them, one by one: each accepted field goes into `tuned` (a fixed
    /// field applies though another is refused), each refused one stays in the draft with the
    /// builder's reason. Returns the command that applies what was accepted, if anything was (nothing
    /// when the draft is what runs).
    pub fn tune(&mut self, index: usize, tuned: &mut SceneFile, bodies: &mut Bodies) -> Option<Command> {
        let group = self.group;
        let knob = self.knobs.get_mut(index)?;
        let running = (group.values)(tuned).into_iter().nth(index)?;
        let (Ok(draft_tree), Ok(running_tree)) = (serde_json::to_value(&knob.draft), serde_json::to_value(&running))
        else {
            return None;
        };
        let mut changed = Vec::new();
        edits(&draft_tree, &running_tree, "", &mut changed);
        knob.refusals.clear();
        // A field that reports a change without one (a click into a number field) applies, and
        // logs, nothing: what is logged as applied is what changed.
        if changed.is_empty() {
            return None;
        }
        let build = |tree: &Value, tuned: &SceneFile, bodies: &mut Bodies| {
            let value: D = serde_json::from_value(tree.clone()).ok()?;
            let mut candidate = tuned.clone();
            (group.put)(&mut candidate, index, value);
            Some(((group.build)(&candidate, index, bodies), candidate))
        };
        // All the edits at once (fields that are valid only together), else each on its own.
        let mut accepted = None;
        let mut refused = Vec::new();
        match build(&draft_tree, tuned, bodies) {
            Some((Ok(command), candidate)) => accepted = Some((command, candidate)),
            Some((Err(reason), _)) if changed.len() <= 1 => refused.extend(changed.first().map(|e| (e, reason))),
            _ => {
                let mut tree = running_tree.clone();
                for edit in &changed {
                    let mut trial = tree.clone();
                    let Some(slot) = trial.pointer_mut(&edit.pointer) else { continue };
                    *slot = edit.value.clone();
                    match build(&trial, tuned, bodies) {
                        Some((Ok(command), candidate)) => {
                            tree = trial;
                            accepted = Some((command, candidate));
                        }
                        Some((Err(reason), _)) => refused.push((edit, reason)),
                        None => {}
                    }
                }
            }
        }
        knob.refusals = refused
            .into_iter()
            .map(|(edit, reason)| Refused {
                field: field_name(&edit.pointer),
                draft: shown(Some(&edit.value)),
                running: shown(running_tree.pointer(&edit.pointer)),
                reason,
            })
            .collect();
        let (command, candidate) = accepted?;
        *tuned = candidate;
        Some(command)
    }

    /// Every knob back to what `file` says; returns the knobs to [`tune`](Self::tune) again for
    /// the running simulation to follow: those whose value in `tuned` is not the file's, and
    /// those refused.
    pub fn revert(&mut self, file: &SceneFile, tuned: &SceneFile) -> Vec<usize> {
        let values = (self.group.values)(file).into_iter().zip((self.group.values)(tuned));
        let mut again = Vec::new();
        for (index, (knob, (value, running))) in self.knobs.iter_mut().zip(values).enumerate() {
            if value != running || !knob.refusals.is_empty() {
                again.push(index);
            }
            knob.draft = value;
        }
        again
    }
}
