//! Time integrators (PHYSICS.md §1, time integration). A closed enum: each scheme is a module.
//!
//! | scheme | order (translation / rotation) | force evaluations per step | stable step, spring `ω`, damping `ζ` |
//! |---|---|---|---|
//! | [`leapfrog`] | 2 (1 with dampers) / 1 | 1 | `2(√(1+ζ²) − ζ)/ω` |
//! | [`leapfrog2`] | 2 (1 with dampers) / 2 | 1 | `2(√(1+ζ²) − ζ)/ω` |
//! | [`splitting`] | 2 (1 with dampers) / 2 | 1 | `2(√(1+ζ²) − ζ)/ω` |
//! | [`rk4`] | 4 / 4 | 4 | `2√2/ω` undamped; damped from RK4's stability polynomial |
//! | [`dopri45`] | 5 (error estimate 4), adaptive | 6 per attempt | none: the step adapts |
//!
//! The leapfrog and leapfrog2 keep velocities half a step behind positions; the splitting, RK4
//! and Dormand–Prince keep them synchronised. [`Scheme::synchronized`] always gives the
//! synchronised state.
//!
//! The interface is narrow: a [`Scheme`] (an integrator with its own scratch) advances the
//! bodies' states by one step of a [`System`], evaluating its forces into an
//! [`Evaluation`](crate::evaluation::Evaluation), and returns a [`StepReport`]: how far it
//! advanced, whether the step was accepted, the work the forces did over it and the bodies'
//! energies at its end. It does not touch the clock, the energy ledger or the health check: the
//! world does.

pub mod context;
pub mod dopri45;
pub mod kick_drift;
pub mod leapfrog;
pub mod leapfrog2;
pub mod report;
pub mod rk4;
pub mod runge_kutta;
pub mod settings;
pub mod splitting;

use crate::body::BodyState;
use crate::energy::BodyEnergy;
use crate::system::{EvaluationError, System};
pub use context::StepContext;
pub use report::{StepFailure, StepReport};
pub use settings::{Integrator, MAX_AUTO_SUBSTEPS, Substeps, Timing, Tolerances};

/// An integrator with its scratch (accelerations, stage rates, step control).
#[derive(Debug, Clone)]
pub enum Scheme {
    Leapfrog(leapfrog::Leapfrog),
    Leapfrog2(leapfrog::Leapfrog),
    Splitting(splitting::Splitting),
    Rk4(runge_kutta::Stages),
    Dopri45(dopri45::Dopri45),
}

impl Scheme {
    /// `integrator` for `bodies` bodies, stepping by `step` \[s] (the adaptive scheme's largest
    /// step, with `tolerances`).
    pub fn new(integrator: Integrator, tolerances: Tolerances, step: f64, bodies: usize) -> Self {
        match integrator {
            Integrator::Leapfrog => Self::Leapfrog(leapfrog::Leapfrog::new(leapfrog::Gyroscopic::Lagged, bodies)),
            Integrator::Leapfrog2 => Self::Leapfrog2(leapfrog::Leapfrog::new(leapfrog::Gyroscopic::Predicted, bodies)),
            Integrator::Splitting => Self::Splitting(splitting::Splitting::new(bodies)),
            Integrator::Rk4 => Self::Rk4(runge_kutta::Stages::new(&rk4::TABLEAU, bodies)),
            Integrator::Dopri45 => Self::Dopri45(dopri45::Dopri45::new(tolerances, step, bodies)),
        }
    }

    pub fn integrator(&self) -> Integrator {
        match self {
            Self::Leapfrog(_) => Integrator::Leapfrog,
            Self::Leapfrog2(_) => Integrator::Leapfrog2,
            Self::Splitting(_) => Integrator::Splitting,
            Self::Rk4(_) => Integrator::Rk4,
            Self::Dopri45(_) => Integrator::Dopri45,
        }
    }

    /// Starts at the context's `time` \[s] from synchronised `states` (the staggered schemes
    /// move their velocities half a step `h` \[s] back): evaluates the forces and returns the
    /// bodies' energies.
    ///
    /// # Errors
    /// A coupling that cannot give its forces.
    pub fn start(&mut self, context: StepContext) -> Result<BodyEnergy, EvaluationError> {
        match self {
            Self::Leapfrog(scheme) | Self::Leapfrog2(scheme) => scheme.start(context),
            Self::Splitting(scheme) => scheme.start(context),
            Self::Rk4(stages) => stages.start(context),
            Self::Dopri45(scheme) => scheme.start(context),
        }
    }

    /// One step from the context's `time` \[s]: of `h` \[s] for the fixed-step schemes; for
    /// `dopri45` one attempt toward the end of the span `h` (accepted or not, and perhaps short
    /// of it).
    ///
    /// # Errors
    /// A coupling that cannot give its forces (the states are then mid-step), or an adaptive
    /// step that stalled.
    pub fn step(&mut self, context: StepContext) -> Result<StepReport, StepFailure> {
        Ok(match self {
            Self::Leapfrog(scheme) => scheme.step(context)?,
            Self::Leapfrog2(scheme) => leapfrog2::step(scheme, context)?,
            Self::Splitting(scheme) => scheme.step(context)?,
            Self::Rk4(stages) => rk4::step(stages, context)?,
            Self::Dopri45(scheme) => return scheme.step(context),
        })
    }

    /// State of body `index` at the current time, velocities synchronised (the leapfrogs add
    /// the half step `h` \[s] of acceleration they hold back).
    pub fn synchronized(&self, system: &System, states: &[BodyState], index: usize, h: f64) -> BodyState {
        match self {
            Self::Leapfrog(scheme) | Self::Leapfrog2(scheme) => scheme.synchronized(system, states, index, h),
            Self::Splitting(_) | Self::Rk4(_) | Self::Dopri45(_) => states[index],
        }
    }
}
