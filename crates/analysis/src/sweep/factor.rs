//! A factor: the scene values it sets (one path or several, set alike) and the values it takes —
//! a list of levels, a linear or logarithmic ladder of levels, or a range the Latin hypercube
//! samples.

use super::spec::{FactorDef, Level, LevelKind, ValuesDef};
use super::table::compact;
use crate::spec_text::{SpecError, SpecText};
use crate::value_path::{ValuePath, number_value};
use serde_json::Value;

/// A factor, its paths found in the base scene's data.
#[derive(Debug, Clone, PartialEq)]
pub struct Factor {
    /// Its column in the results.
    pub name: String,
    pub paths: Vec<ValuePath>,
    pub values: Values,
    /// What the base scene says at its paths (`None` when the scene leaves it to the loader's
    /// default, or its paths disagree).
    pub base: Option<Level>,
}

/// The values a factor takes.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// These levels, in order.
    Levels(Vec<Level>),
    /// Any number from `from` to `to`, uniformly or (`log`) uniformly in logarithm.
    Range { from: f64, to: f64, log: bool },
}

impl Factor {
    /// The factor `def` of the spec `spec`, its paths found in the base scene's data `tree`; it
    /// may have at most `max_cases` levels (the sweep's limit), counted before they are made.
    ///
    /// # Errors
    /// A path that leads nowhere, values that are not values or more levels than `max_cases`,
    /// placed at the factor's path.
    pub fn new(def: &FactorDef, tree: &Value, spec: &SpecText<'_>, max_cases: usize) -> Result<Self, SpecError> {
        let paths = def.path.paths();
        let first = paths.first().map_or("", String::as_str);
        let fail = |message: String| spec.error_at(first, "factors", message);
        let name = match (&def.name, paths) {
            (Some(name), _) => name.clone(),
            (None, [path]) => path.clone(),
            (None, _) => return Err(fail("a factor that sets several paths needs a `name` for its column".into())),
        };
        let mut found = Vec::with_capacity(paths.len());
        for path in paths {
            let value_path = ValuePath::find(tree, path)
                .map_err(|message| spec.error_at(path, "factors", format!("factor `{name}`: {message}")))?;
            if found.iter().any(|p: &ValuePath| p.text == *path) {
                return Err(spec.error_at(path, "factors", format!("factor `{name}` names `{path}` twice")));
            }
            found.push(value_path);
        }
        let values = values(&def.values, max_cases)
            .map_err(|message| spec.error_after(first, "values", format!("factor `{name}`: {message}")))?;
        let bases: Vec<Option<Level>> = found.iter().map(|p| p.get(tree).and_then(level_of)).collect();
        let base = bases.first().cloned().flatten().filter(|b| bases.iter().all(|other| other.as_ref() == Some(b)));
        Ok(Self { name, paths: found, values, base })
    }

    /// The kind of value the factor takes.
    pub fn kind(&self) -> LevelKind {
        match &self.values {
            Values::Levels(levels) => levels.first().map_or(LevelKind::Number, Level::kind),
            Values::Range { .. } => LevelKind::Number,
        }
    }

    /// Whether its values are spread in logarithm (its plots then use a log axis).
    pub fn logarithmic(&self) -> bool {
        match &self.values {
            Values::Levels(levels) => {
                // A ladder of positive numbers, each step a ratio rather than a difference.
                let numbers: Vec<f64> = levels.iter().filter_map(Level::number).collect();
                numbers.len() >= 3 && numbers.iter().all(|&x| x > 0.0) && {
                    let ratio = numbers[1] / numbers[0];
                    (ratio - 1.0).abs() > 1e-9 && numbers.windows(2).all(|w| ((w[1] / w[0]) / ratio - 1.0).abs() < 1e-9)
                }
            }
            Values::Range { log, .. } => *log,
        }
    }

    /// Writes `level` at each of the factor's paths in `tree`.
    pub fn set(&self, tree: &mut Value, level: &Level) {
        let value = match level {
            // Levels are checked finite when the spec is read.
            Level::Number(x) => number_value(*x).unwrap_or(Value::Null),
            Level::Flag(flag) => Value::Bool(*flag),
            Level::Text(text) => Value::String(text.clone()),
        };
        for path in &self.paths {
            path.set(tree, value.clone());
        }
    }

    /// `couplings.mooring1.stiffness` or `mooring_stiffness (couplings.mooring1.stiffness, …)`.
    pub fn describe_paths(&self) -> String {
        let paths: Vec<&str> = self.paths.iter().map(|p| p.text.as_str()).collect();
        paths.join(", ")
    }

    /// `Log(1e6 … 1e7, 4 levels)`-like description for the summary.
    pub fn describe_values(&self) -> String {
        match &self.values {
            Values::Levels(levels) => {
                let shown: Vec<String> =
                    levels.iter().take(8).map(|l| l.number().map_or_else(|| l.to_string(), compact)).collect();
                let more = if levels.len() > 8 { format!(", … ({} levels)", levels.len()) } else { String::new() };
                format!("{}{more}", shown.join(", "))
            }
            Values::Range { from, to, log } => {
                format!("{} from {} to {}", if *log { "log-uniform" } else { "uniform" }, compact(*from), compact(*to))
            }
        }
    }
}

/// A leaf of the scene's data as a level.
fn level_of(value: &Value) -> Option<Level> {
    match value {
        Value::Number(n) => n.as_f64().map(Level::Number),
        Value::Bool(flag) => Some(Level::Flag(*flag)),
        Value::String(text) => Some(Level::Text(text.clone())),
        _ => None,
    }
}

/// The values `def` gives, checked: at least one, at most `max_cases` (no design runs more
/// levels of a factor than the sweep may have cases: the count is checked before a ladder is
/// made), finite, of one kind; a logarithmic ladder or range of positive numbers.
fn values(def: &ValuesDef, max_cases: usize) -> Result<Values, String> {
    let count = match def {
        ValuesDef::List(levels) => levels.len(),
        ValuesDef::Linear { count, .. } | ValuesDef::Log { count, .. } => usize::try_from(*count).unwrap_or(usize::MAX),
        // A range has no levels: the Latin hypercube's samples are its size.
        ValuesDef::Uniform { .. } | ValuesDef::LogUniform { .. } => 0,
    };
    if count > max_cases {
        return Err(format!(
            "{count} levels, more than the limit of {max_cases} cases a sweep may have: ask for fewer, or raise the limit with --max-cases {count}"
        ));
    }
    let finite = |name: &str, x: f64| {
        if x.is_finite() { Ok(x) } else { Err(format!("`{name}` must be a finite number, got {x}")) }
    };
    let positive = |name: &str, x: f64| {
        if x > 0.0 { Ok(x) } else { Err(format!("`{name}` of a logarithmic spread must be > 0, got {x}")) }
    };
    match def {
        ValuesDef::List(levels) => {
            let Some(first) = levels.first() else { return Err("the list of values is empty".into()) };
            if let Some(other) = levels.iter().find(|l| l.kind() != first.kind()) {
                return Err(format!(
                    "the values mix kinds ({first} and {other}): give numbers, names or flags, not several"
                ));
            }
            for level in levels {
                if let Level::Number(x) = level {
                    finite("values", *x)?;
                }
            }
            Ok(Values::Levels(levels.clone()))
        }
        &ValuesDef::Linear { from, to, count } => {
            let (from, to) = (finite("from", from)?, finite("to", to)?);
            Ok(Values::Levels(ladder(from, to, count, |a, b, t| a + t * (b - a))?))
        }
        &ValuesDef::Log { from, to, count } => {
            let (from, to) = (positive("from", finite("from", from)?)?, positive("to", finite("to", to)?)?);
            Ok(Values::Levels(ladder(from, to, count, |a, b, t| (a.ln() + t * (b.ln() - a.ln())).exp())?))
        }
        &ValuesDef::Uniform { from, to } => range(finite("from", from)?, finite("to", to)?, false),
        &ValuesDef::LogUniform { from, to } => {
            range(positive("from", finite("from", from)?)?, positive("to", finite("to", to)?)?, true)
        }
    }
}

/// `count` levels from `from` to `to` by `between(from, to, t)`, t = k/(count − 1); the ends
/// exactly as written.
fn ladder(from: f64, to: f64, count: u32, between: impl Fn(f64, f64, f64) -> f64) -> Result<Vec<Level>, String> {
    match count {
        0 => Err("`count` must be at least 1".into()),
        1 => Ok(vec![Level::Number(from)]),
        _ => Ok((0..count)
            .map(|k| match k {
                0 => from,
                k if k == count - 1 => to,
                k => between(from, to, f64::from(k) / f64::from(count - 1)),
            })
            .map(Level::Number)
            .collect()),
    }
}

fn range(from: f64, to: f64, log: bool) -> Result<Values, String> {
    if from < to {
        Ok(Values::Range { from, to, log })
    } else {
        Err(format!("`from` must be below `to`, got {from} and {to}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn numbers(def: ValuesDef) -> Vec<f64> {
        match values(&def, 100).unwrap() {
            Values::Levels(levels) => levels.iter().map(|l| l.number().unwrap()).collect(),
            range => panic!("{range:?}"),
        }
    }

    /// Ladders end exactly where the spec says and step evenly (in logarithm for `Log`).
    #[test]
    fn ladders_are_even_and_end_exactly() {
        assert_eq!(numbers(ValuesDef::Linear { from: 1.0, to: 2.0, count: 5 }), [1.0, 1.25, 1.5, 1.75, 2.0]);
        let log = numbers(ValuesDef::Log { from: 1e6, to: 1e9, count: 4 });
        assert_eq!((log[0], log[3]), (1e6, 1e9));
        // exp∘ln costs a few ulps: 1e-14 relative is round-off, a wrong formula is off by 10×.
        assert!((log[1] / 1e7 - 1.0).abs() < 1e-14 && (log[2] / 1e8 - 1.0).abs() < 1e-14, "{log:?}");
        assert_eq!(numbers(ValuesDef::Linear { from: 3.0, to: 9.0, count: 1 }), [3.0]);
    }

    #[test]
    fn refuses_values_that_are_not_values() {
        let error = |def: ValuesDef| values(&def, 100).unwrap_err();
        assert_eq!(error(ValuesDef::List(vec![])), "the list of values is empty");
        assert_eq!(error(ValuesDef::Linear { from: 0.0, to: 1.0, count: 0 }), "`count` must be at least 1");
        assert_eq!(
            error(ValuesDef::Log { from: 0.0, to: 1.0, count: 3 }),
            "`from` of a logarithmic spread must be > 0, got 0"
        );
        assert_eq!(error(ValuesDef::Uniform { from: 2.0, to: 1.0 }), "`from` must be below `to`, got 2 and 1");
        assert_eq!(
            error(ValuesDef::List(vec![Level::Number(f64::INFINITY)])),
            "`values` must be a finite number, got inf"
        );
        assert_eq!(
            error(ValuesDef::List(vec![Level::Number(1.0), Level::Text("rk4".into())])),
            "the values mix kinds (1 and rk4): give numbers, names or flags, not several"
        );
        assert_eq!(
            error(ValuesDef::Linear { from: 0.0, to: 1.0, count: 101 }),
            "101 levels, more than the limit of 100 cases a sweep may have: ask for fewer, or raise the limit with --max-cases 101"
        );
        assert_eq!(numbers(ValuesDef::Linear { from: 0.0, to: 99.0, count: 100 }).len(), 100, "at the limit");
    }
}
