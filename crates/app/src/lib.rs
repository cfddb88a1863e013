//! Tether, the application: the command line, the integrator study and the window (control
//! panel and embedded Rerun viewer) around the workspace's library crates:
//! `tether-physics` (pure numerics, no GUI or viewer), `tether-scene` (RON files into a world),
//! `tether-record` (the Rerun adapter that logs a world). [`gui`] sends a running world
//! commands; [`study`] measures the integrators against a reference run and writes tables and a
//! chart. The `tether` binary's command line lives beside `main.rs`.

pub mod cpu_time;
pub mod gui;
pub mod study;
