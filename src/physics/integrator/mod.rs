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
