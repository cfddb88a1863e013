//! Statics for people (PHYSICS.md §7): the static equilibrium of a scene as a report (poses, line
//! tensions, grounded lengths and touchdowns, each body's 6 × 6 stiffness) and a body's offset
//! curve as a table, a CSV file and a chart; the equilibrium as data ([`data`]: JSON, Python). The solves themselves are the physics crate's
//! ([`tether_physics::statics`]); the command line and the window both show them from here.

pub mod chart;
pub mod data;
pub mod offsets;
pub mod report;
