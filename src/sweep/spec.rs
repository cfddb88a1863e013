//! What a sweep spec file says (RON, plain serde data), and where in its text each part is, so
//! that every error about it reads `spec.ron:line:col: message`.
//!
//! ```ron
//! Sweep(
//!     name: "buoy-moorings",                       // optional: the file's stem
//!     scene: "../../scenes/moored_buoy.ron",       // relative to this file
//!     duration: 30.0,                              // optional: the scene's [s]
//!     design: Grid,                                // OneAtATime, LatinHypercube(samples: 64, seed: 7)
//!     factors: [
//!         Factor(path: "bodies.buoy.master.mass", values: Linear(from: 2000.0, to: 4000.0, count: 5)),
//!         Factor(name: "mooring_stiffness",
//!                path: ["couplings.mooring1.stiffness", "couplings.mooring2.stiffness", "couplings.mooring3.stiffness"],
//!                values: Log(from: 1e6, to: 1e7, count: 4)),
//!         Factor(path: "integrator", values: List(["leapfrog", "rk4"])),
//!     ],
//!     metrics: [Metric(name: "heave", of: Position("buoy", Z), take: MaxAbs, after: 5.0)],
//! )
//! ```

use super::metrics::MetricDef;
use serde::{Deserialize, Serialize};
use std::path::Path;
use tether_scene::source::Source;

/// A whole spec file.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename = "Sweep", deny_unknown_fields)]
pub struct SpecFile {
    /// The sweep's name: the recordings' application id, the summary's title (default: the
    /// spec file's stem).
    #[serde(default)]
    pub name: Option<String>,
    /// The base scene, relative to the spec file.
    pub scene: String,
    /// Simulated duration of every case [s] (default: the scene's; a factor may sweep it).
    #[serde(default)]
    pub duration: Option<f64>,
    pub design: Design,
    pub factors: Vec<FactorDef>,
    /// Metrics beyond the standard set.
    #[serde(default)]
    pub metrics: Vec<MetricDef>,
    /// Whether each coupling's tension range and each body's excursion and rotation are
    /// measured (default true; settle time, energy error, CPU time and steps always are).
    #[serde(default = "yes")]
    pub standard_metrics: bool,
    /// The settle time's band, as a fraction of each body's largest distance from where it
    /// ends (default 0.02).
    #[serde(default = "default_settle_band")]
    pub settle_band: f64,
}

fn yes() -> bool {
    true
}

fn default_settle_band() -> f64 {
    0.02
}

/// Which cases a sweep runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Design {
    /// Every combination of every factor's levels; the last factor varies fastest.
    Grid,
    /// The base scene, then each factor through its levels with the others at the base's values.
    OneAtATime,
    /// `samples` cases, each factor's range cut into `samples` equal strata and each stratum
    /// drawn once, in an order and at a place within it drawn from `seed`.
    LatinHypercube { samples: u32, seed: u64 },
}

impl Design {
    /// `grid`, `one-at-a-time`, `Latin hypercube (64 samples, seed 7)`.
    pub fn describe(&self) -> String {
        match self {
            Self::Grid => "full grid".into(),
            Self::OneAtATime => "one factor at a time around the base scene".into(),
            Self::LatinHypercube { samples, seed } => format!("Latin hypercube ({samples} samples, seed {seed})"),
        }
    }
}

/// A factor: the scene values it sets and the values it takes.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename = "Factor", deny_unknown_fields)]
pub struct FactorDef {
    /// Its column name (default: its path; required when it sets several paths).
    #[serde(default)]
    pub name: Option<String>,
    /// One path, or several set to the same value.
    pub path: PathsDef,
    pub values: ValuesDef,
}

/// `"couplings.mooring1.stiffness"` or a list of such paths.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum PathsDef {
    One(String),
    Many(Vec<String>),
}

impl PathsDef {
    pub fn paths(&self) -> &[String] {
        match self {
            Self::One(path) => std::slice::from_ref(path),
            Self::Many(paths) => paths,
        }
    }
}

/// The values a factor takes.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ValuesDef {
    /// These levels: numbers, names (`"rk4"`) or `true`/`false`.
    List(Vec<Level>),
    /// `count` levels evenly spaced from `from` to `to`, both included.
    Linear { from: f64, to: f64, count: u32 },
    /// `count` levels evenly spaced in logarithm from `from` to `to` (both > 0), both included.
    Log { from: f64, to: f64, count: u32 },
    /// Any value from `from` to `to`, as the Latin hypercube draws it.
    Uniform { from: f64, to: f64 },
    /// Any value from `from` to `to` (both > 0), drawn uniformly in logarithm.
    LogUniform { from: f64, to: f64 },
}

/// One value of a factor, as the spec writes it and the results table shows it (its `Display`,
/// with the table's numbers, is in [`super::table`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Level {
    Number(f64),
    Flag(bool),
    Text(String),
}

impl Level {
    /// The kind of value.
    pub fn kind(&self) -> LevelKind {
        match self {
            Self::Number(_) => LevelKind::Number,
            Self::Flag(_) => LevelKind::Flag,
            Self::Text(_) => LevelKind::Text,
        }
    }

    /// The number, if it is one.
    pub fn number(&self) -> Option<f64> {
        match self {
            Self::Number(x) => Some(*x),
            _ => None,
        }
    }
}

/// What kind of values a factor takes: its column's type.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LevelKind {
    Number,
    Flag,
    Text,
}

/// A problem with a spec file, placed in its text.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path}:{line}:{col}: {message}")]
pub struct SpecError {
    pub path: String,
    pub line: usize,
    pub col: usize,
    pub message: String,
}

/// A spec file's text, to place problems in it.
pub struct SpecText<'a> {
    pub path: &'a Path,
    pub text: &'a str,
}

impl SpecText<'_> {
    /// Parses the spec (a sweep's [`SpecFile`], or another spec in its style: a fit's).
    ///
    /// # Errors
    /// A syntax error or a value of the wrong type, at its line and column.
    pub fn parse<T: serde::de::DeserializeOwned>(&self) -> Result<T, SpecError> {
        let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        options.from_str(self.text).map_err(|e| SpecError {
            path: self.path.display().to_string(),
            line: e.position.line.max(1),
            col: e.position.col.max(1),
            message: e.code.to_string(),
        })
    }

    /// `message` placed at the first string literal `"literal"`, or at the first `field:` if
    /// there is no such literal, else at the start of the file.
    pub fn error_at(&self, literal: &str, field: &str, message: impl Into<String>) -> SpecError {
        let source = Source::new(self.text);
        let offset = source.literal(0, literal).or_else(|| source.field(0, field)).unwrap_or(0);
        let (line, col) = source.line_col(offset);
        SpecError { path: self.path.display().to_string(), line, col, message: message.into() }
    }

    /// `message` placed at the first `field:` at or after the string literal `"literal"`.
    pub fn error_after(&self, literal: &str, field: &str, message: impl Into<String>) -> SpecError {
        let source = Source::new(self.text);
        let start = source.literal(0, literal).unwrap_or(0);
        let offset = source.field(start, field).unwrap_or(start);
        let (line, col) = source.line_col(offset);
        SpecError { path: self.path.display().to_string(), line, col, message: message.into() }
    }
}
