//! Tether, the application: the command line and the window (control panel and embedded Rerun
//! viewer) around the workspace's library crates: `tether-physics` (pure numerics, no GUI or
//! viewer), `tether-scene` (RON files into a world), `tether-record` (the Rerun adapter that
//! logs a world) and `tether-analysis` (sweeps, the integrator study, storms, fits and statics
//! reports on the engine of many runs). [`gui`] sends a running world commands; [`figures`]
//! writes numbers for a person; [`line_hint`] says when a quasi-static line is likely wrong. The
//! `tether` binary's command line lives beside `main.rs`. The window is the `gui` feature (on by
//! default); without it the library and the binary are headless.

pub mod figures;
#[cfg(feature = "gui")]
pub mod gui;
pub mod line_hint;
