//! Time integrators (PHYSICS.md §1, time integration). A closed enum: each scheme is a module.

pub mod leapfrog;
pub mod leapfrog2;

/// The scheme that advances a world by one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Integrator {
    /// The seed's central-difference scheme ([`leapfrog`]).
    #[default]
    Leapfrog,
    /// The leapfrog with the gyroscopic term at a predicted ω(t) ([`leapfrog2`]).
    Leapfrog2,
}

/// How many integrator steps one world step takes: the world advances by `dt`, its integrator
/// by `dt / n` (recordings log world steps).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Substeps {
    /// `n ≥ 1` integrator steps per world step.
    Fixed(u32),
    /// Enough integrator steps to keep each under 0.9 of the binding stable time step at t = 0
    /// and of every contact's impact resolution τ/10, up to
    /// [`crate::physics::world::MAX_AUTO_SUBSTEPS`].
    Auto,
}

impl Default for Substeps {
    fn default() -> Self {
        Self::Fixed(1)
    }
}

/// The time step settings of a world.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    /// World step [s] > 0.
    pub dt: f64,
    pub integrator: Integrator,
    pub substeps: Substeps,
}
