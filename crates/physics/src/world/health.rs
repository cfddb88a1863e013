//! Stage *health*: a blow-up detected within a few steps of its start, and reported with the
//! body at fault and the time step that would have held (PHYSICS.md §5: the energy balance).
//!
//! After every integrator step the world checks that every body's state is finite and that its
//! mechanical energy, less the work put in by prescribed motions, has not drifted from its
//! start by more than [`DIVERGENCE_FACTOR`] times the energy budget: `|kinetic| + |gravity| +
//! |elastic|` at t = 0, the energy of a fall across the scene, and the work put in by
//! prescribed motions since. An unstable step grows the energy geometrically, so this stops a
//! blow-up long before anything overflows.
//!
//! The dissipated work is left out on both sides: dampers remove at most the budget, a blow-up
//! with a damper dissipates as fast as it grows, and a scheme that resolves a damper poorly at a
//! large but stable step (RK4 near its damped limit, where the physical decay per step is far
//! faster than the scheme's) books more dissipation than its bounded state loses, which is
//! inaccuracy, not divergence.

use super::error::StepError;
use crate::body::BodyState;
use crate::energy::EnergyReport;
use crate::math::bounding_box;
use crate::stability::Limit;
use crate::system::System;

/// Energy balance drift, in multiples of the energy budget, taken as a blow-up.
pub const DIVERGENCE_FACTOR: f64 = 10.0;

/// What the check compares with: the start of the run.
#[derive(Debug, Clone, Copy, Default)]
pub struct Health {
    /// Energies at t = 0.
    pub initial_energy: EnergyReport,
    /// `Σ m |g| ℓ` \[J] with ℓ the size of the scene at t = 0: the energy the bodies could gain
    /// by falling across it, part of the budget whatever the height of the origin.
    pub fall_energy: f64,
    /// The binding stable time step, for the message.
    pub limit: Option<Limit>,
}

/// How far the balance drifted, against the budget \[J].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Drift {
    pub drift: f64,
    pub budget: f64,
}

impl Health {
    /// The drift of `energy`, if it exceeds [`DIVERGENCE_FACTOR`] times the budget (or is not
    /// finite).
    pub fn drift(&self, energy: &EnergyReport) -> Option<Drift> {
        let start = &self.initial_energy;
        let budget = start.kinetic.abs()
            + start.gravity.abs()
            + start.elastic.abs()
            + self.fall_energy
            + energy.external_work.abs();
        let drift = (energy.total() - energy.external_work - start.total()).abs();
        if drift <= DIVERGENCE_FACTOR * budget.max(f64::MIN_POSITIVE) { None } else { Some(Drift { drift, budget }) }
    }

    /// The divergence behind `drift` at `time` \[s], with the bodies' synchronised `states` and
    /// the integrator step `step` \[s]: the first body whose state is not finite, else the body
    /// with the most kinetic energy.
    pub fn diverged(&self, system: &System, states: &[BodyState], drift: Drift, time: f64, step: f64) -> StepError {
        let dynamic = || (0..system.bodies().len()).filter(|&i| !system.bodies()[i].is_kinematic());
        match dynamic().find(|&i| !states[i].is_finite()) {
            Some(body) => self.stopped(system, body, "has a non-finite state".to_string(), time, step),
            None => self.stopped(
                system,
                most_energetic_body(system, states),
                format!(
                    "carries the most kinetic energy as the energy drifts by {:.3e} J (budget {:.3e} J)",
                    drift.drift, drift.budget
                ),
                time,
                step,
            ),
        }
    }

    /// An adaptive step that shrank to `shrunk` \[s], below round-off of the time.
    pub fn stalled(&self, system: &System, states: &[BodyState], shrunk: f64, time: f64, step: f64) -> StepError {
        let cause = format!(
            "carries the most kinetic energy as the adaptive step shrinks to {shrunk:.3e} s (too stiff, or blown up)"
        );
        self.stopped(system, most_energetic_body(system, states), cause, time, step)
    }

    /// [`StepError::Diverged`] naming body `body` and the binding stable time step.
    fn stopped(&self, system: &System, body: usize, cause: String, time: f64, step: f64) -> StepError {
        let advice = match self.limit {
            Some(limit) => format!(
                "the stable time step is {:.3e} s, set by {} (step {step:.3e} s)",
                limit.dt,
                limit.describe(system)
            ),
            None => format!("no coupling limits the time step (step {step:.3e} s)"),
        };
        StepError::Diverged {
            time,
            body: system.bodies().get(body).map_or_else(String::new, |b| b.name.clone()),
            cause,
            advice,
        }
    }
}

/// The body that responds to forces with the most kinetic energy (0 if none does).
fn most_energetic_body(system: &System, states: &[BodyState]) -> usize {
    let kinetic = |i: usize| system.bodies()[i].kinetic_energy(&states[i].velocity, &states[i].angular_velocity);
    (0..system.bodies().len())
        .filter(|&i| !system.bodies()[i].is_kinematic())
        .max_by(|&a, &b| kinetic(a).total_cmp(&kinetic(b)))
        .unwrap_or(0)
}

/// `Σ m |g| ℓ` \[J], ℓ the diagonal of the box around the bodies' centres of mass and the
/// coupling ends `ends` \[m]; and for each floating body `ρ g V · 2r`, the work of its buoyancy
/// across its own size (`V` its hull's volume, `r` the radius of the ball about G that holds
/// it): a body floating at rest alone has no other scale.
pub fn fall_energy(system: &System, states: &[BodyState], ends: impl Iterator<Item = crate::math::Vec3>) -> f64 {
    let (low, high) = bounding_box(states.iter().map(|s| s.position).chain(ends));
    let size = if low.x.is_finite() { (high - low).norm() } else { 0.0 };
    let mass: f64 = system.bodies().iter().filter(|b| !b.is_kinematic()).map(|b| b.mass()).sum();
    let floating = system.water().map_or(0.0, |stage| {
        let rho_g = stage.water.specific_weight();
        stage.floating.iter().map(|f| rho_g * f.hull().volume() * 2.0 * f.hull().bounding_radius()).sum()
    });
    mass * system.gravity().norm() * size + floating
}
