//! Tether's analyses of a scene, below the command line, the window and the Python module that
//! present them: the engine of many runs ([`runner`]) and what is built on it — sweeps over a
//! design of factor values ([`sweep`]), the integrator study ([`study`]), storms over seeds
//! ([`storm`]), fits of a scene's knobs to a measured record ([`fit`]) — and the static
//! equilibria and offset curves reported from the physics' statics ([`statics`]).
//!
//! What they share sits below all of them: a scene value's path ([`value_path`]), a spec file's
//! text and its errors ([`spec_text`]), the quantities a run is measured by ([`quantity`]), the
//! catalogue of tunable numbers ([`parameters`]), the check of a run's length ([`run_length`]),
//! the stop a signal asks for ([`interrupt`]) and the charts' style ([`chart_style`],
//! [`rao_chart`]). Nothing here draws a window or parses a command line (`tests/architecture.rs`).

pub mod chart_style;
pub mod fit;
pub mod interrupt;
pub mod parameters;
pub mod quantity;
pub mod rao_chart;
pub mod run_length;
pub mod runner;
pub mod spec_text;
pub mod statics;
pub mod storm;
pub mod study;
pub mod sweep;
pub mod value_path;
