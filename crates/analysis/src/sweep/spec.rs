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
use crate::spec_text::PathsDef;
use serde::{Deserialize, Serialize};

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
    /// Simulated duration of every case \[s] (default: the scene's; a factor may sweep it).
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
