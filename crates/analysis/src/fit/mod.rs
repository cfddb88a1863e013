//! Calibration: the scene's knobs fitted to a measured record — a tank test's decay, a CFD run,
//! a field record, another code's run — by bounded nonlinear least squares, with honest
//! confidence intervals, the combinations the data cannot determine named, and the fitted scene
//! written back (docs/calibration.md).
//!
//! The way through:
//! - [`spec`]: the fit spec file (RON, in the sweep spec's style): scene, record, signals,
//!   parameters by the sweep's value paths, window, time shift;
//! - [`measured`]: the record (CSV, Parquet; a Tether recording by [`recording_input`]), each
//!   signal a [`series`];
//! - [`parameter`]: a parameter's bounds, scale and map to the solver's unit box;
//! - [`setup`]: all of it checked against the scene and the record before any run;
//! - [`model`]: one run of the scene with a set of values, its signals at the record's times,
//!   the weighted residuals; a batch of runs on the runner's threads;
//! - [`solver`]: box-bounded Levenberg–Marquardt, the Jacobian's columns run with each trial;
//! - [`uncertainty`]: covariance, intervals, correlations, undetermined directions;
//! - [`run`]: the fit, start to report; [`report`]: text and JSON; [`chart`]: a PNG per signal;
//!   [`write_back`]: the scene's text with the fitted values in place; [`output`]: the files of
//!   a fit (report, charts, the recording of the fitted run, the fitted scene).

pub mod chart;
pub mod measured;
pub mod model;
pub mod output;
pub mod parameter;
pub mod recording_input;
pub mod report;
pub mod run;
pub mod series;
pub mod setup;
pub mod solver;
pub mod spec;
pub mod uncertainty;
pub mod write_back;
