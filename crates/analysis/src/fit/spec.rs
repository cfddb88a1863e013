//! What a fit spec file says (RON, in the sweep spec's style): the scene, the measured record,
//! which model signal each measured column is, the parameters to fit by the sweep's value
//! paths with their bounds, and optionally the time window and a time shift.
//!
//! ```ron
//! Fit(
//!     scene: "../../scenes/spring_mass.ron",      // relative to this file
//!     record: "decay.csv",                         // CSV, Parquet, or a Tether recording (.rrd)
//!     time_column: "t",                            // optional: the record's time column [s] (default: the first)
//!     window: Window(from: 0.5, to: 5.0),          // optional: the record's times compared [s]
//!     signals: [
//!         Signal(column: "x", of: Position("mass", X)),                  // weight: 1/σ of the column
//!         Signal(column: "F", of: Tension("spring"), weight: 0.01),      // or 1/unit, as given
//!     ],
//!     parameters: [
//!         Parameter(path: "couplings.spring.law.stiffness", from: 50.0, to: 200.0),
//!         Parameter(path: "couplings.spring.damping", from: 0.1, to: 10.0, scale: Log),
//!         Parameter(path: "bodies.mass.velocity.0", from: -1.0, to: 1.0),   // an initial condition
//!     ],
//!     time_shift: Shift(from: -0.1, to: 0.1),     // optional: the model leads the record by τ [s]
//!     max_iterations: 50,                          // optional
//! )
//! ```

use crate::quantity::Quantity;
use crate::spec_text::PathsDef;
use serde::{Deserialize, Serialize};

/// A whole fit spec file.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename = "Fit", deny_unknown_fields)]
pub struct FitFile {
    /// The scene, relative to the spec file.
    pub scene: String,
    /// The measured record, relative to the spec file.
    pub record: String,
    /// The record's time column (default: its first column).
    #[serde(default)]
    pub time_column: Option<String>,
    /// The record's times compared (default: every time the record and the scene's run share).
    #[serde(default)]
    pub window: Option<Window>,
    pub signals: Vec<SignalDef>,
    pub parameters: Vec<ParameterDef>,
    /// A time shift fitted with the parameters: the model at `t + τ` is compared with the record
    /// at `t`.
    #[serde(default)]
    pub time_shift: Option<ShiftDef>,
    /// Iterations at most (default 50).
    #[serde(default = "default_iterations")]
    pub max_iterations: u32,
}

fn default_iterations() -> u32 {
    50
}

/// The record's times compared \[s].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Window", deny_unknown_fields)]
pub struct Window {
    pub from: f64,
    pub to: f64,
}

/// A measured column and the model signal it is.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename = "Signal", deny_unknown_fields)]
pub struct SignalDef {
    pub column: String,
    pub of: Quantity,
    /// The residual's weight [1/unit] (default: 1 / the column's standard deviation in the
    /// window, so that every signal counts alike).
    #[serde(default)]
    pub weight: Option<f64>,
}

/// A parameter to fit: one value path, or several set to the same value, and its bounds.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename = "Parameter", deny_unknown_fields)]
pub struct ParameterDef {
    /// Its name in the report (default: its path; required when it sets several paths).
    #[serde(default)]
    pub name: Option<String>,
    pub path: PathsDef,
    /// Bounds.
    pub from: f64,
    pub to: f64,
    /// `Linear` (default) or `Log`, for a parameter that spans decades (both bounds > 0).
    #[serde(default)]
    pub scale: Scale,
    /// Where the fit starts (default: the scene's value, or the bounds' middle if the scene's
    /// is outside them).
    #[serde(default)]
    pub start: Option<f64>,
}

/// How a parameter maps to the solver's unit interval.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Scale {
    /// `z = (θ − from) / (to − from)`.
    #[default]
    Linear,
    /// `z = ln(θ / from) / ln(to / from)`.
    Log,
}

/// The bounds of a fitted time shift \[s].
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(rename = "Shift", deny_unknown_fields)]
pub struct ShiftDef {
    pub from: f64,
    pub to: f64,
    /// Where the fit starts (default 0, or the bounds' middle if 0 is outside them).
    #[serde(default)]
    pub start: Option<f64>,
}
