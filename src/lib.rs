//! Tether: coupled rigid bodies (spring-dampers, catenaries, contact) for engineers who tune them.
//!
//! The crate is split along one rule: [`physics`] is pure numerics with no GUI or viewer
//! dependency; [`scene`] turns a RON file into a [`physics::World`]; [`record`] is the Rerun
//! adapter that reads a world and writes `.rrd` recordings; [`gui`] is the window (control panel
//! and embedded Rerun viewer) that sends a running world commands; [`study`] measures the
//! integrators against a reference run and writes tables and a chart. The `tether` binary's
//! command line lives beside `main.rs`.
//!
//! Units are SI throughout (`../shared/PHYSICS.md` header):
//!
//! | quantity            | unit      | quantity              | unit        |
//! |---------------------|-----------|-----------------------|-------------|
//! | length, position    | m         | force                 | N = kg·m/s² |
//! | mass                | kg        | moment                | N·m         |
//! | time                | s         | stiffness (spring)    | N/m         |
//! | velocity            | m/s       | damping (spring)      | N·s/m       |
//! | angular velocity    | rad/s     | inertia               | kg·m²       |
//! | energy, work        | J = N·m   | gravity               | m/s²        |
//!
//! The world frame is right-handed with z up.

pub mod gui;
pub mod physics;
pub mod record;
pub mod scene;
pub mod study;
