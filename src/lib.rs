//! Tether, the application: the command line, the integrator study and the window (control
//! panel and embedded Rerun viewer) around the workspace's library crates:
//! `tether-physics` (pure numerics, no GUI or viewer), `tether-scene` (RON files into a world),
//! `tether-record` (the Rerun adapter that logs a world). [`gui`] sends a running world
//! commands; [`sweep`] runs a scene over a design of factor values and [`study`] measures the
//! integrators against a reference run, both on the engine of many cases in [`runner`], and
//! write tables and charts ([`chart_style`]); [`statics`] reports static equilibria and offset
//! curves. The `tether` binary's command line lives beside `main.rs`. The window is the `gui`
//! feature (on by default); without it the library and the binary are headless.

pub mod chart_style;
pub mod figures;
pub mod fit;
#[cfg(feature = "gui")]
pub mod gui;
pub mod interrupt;
pub mod line_hint;
pub mod parameters;
pub mod quantity;
pub mod rao_chart;
pub mod run_length;
pub mod runner;
pub mod statics;
pub mod storm;
pub mod study;
pub mod sweep;
