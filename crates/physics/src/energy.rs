//! Energy accounting (PHYSICS.md §5).
//!
//! `total = kinetic + gravity + elastic` \[J]. Dampers dissipate `dissipated = ∫ P_d dt` ≥ 0 and
//! kinematic (prescribed) bodies inject `−∫ Σ (F_k·v_k + M_k·ω_k) dt`, the work the drivers do
//! against the couplings, and the water (§6) `∫ Σ (F_w·v + M_w·ω) dt` on the floating bodies:
//! together the `external_work`. The balance `total + dissipated − external_work` is
//! constant for the exact motion; a numerical run keeps it to the integrator's order. Each
//! integrator integrates the powers by its own rule ([`crate::integrator::StepReport::work`]);
//! the world adds up the work in its [`EnergyLedger`].

use crate::body::{BodyState, RigidBody};
use crate::math::Vec3;

/// Energies of a world at one instant \[J].
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct EnergyReport {
    /// `Σ ½ m |v|² + ½ ωᵀ I ω` of the bodies that respond to forces.
    pub kinetic: f64,
    /// `Σ −m g·x_G` of the bodies that respond to forces.
    pub gravity: f64,
    /// Potential stored in the couplings.
    pub elastic: f64,
    /// Work dissipated by dampers since t = 0.
    pub dissipated: f64,
    /// Work done by prescribed motions and by the water on the system since t = 0.
    pub external_work: f64,
}

impl EnergyReport {
    /// Mechanical energy `kinetic + gravity + elastic`.
    pub fn total(&self) -> f64 {
        self.kinetic + self.gravity + self.elastic
    }

    /// The invariant `total + dissipated − external_work`.
    pub fn balance(&self) -> f64 {
        self.total() + self.dissipated - self.external_work
    }
}

/// Power \[W] at one force evaluation: dissipated by dampers (≥ 0), put in by prescribed
/// motions, and put in by the water (kept apart: the staggered schemes integrate it with their
/// half-step velocities, see [`crate::integrator::leapfrog`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Powers {
    pub dissipated: f64,
    pub external: f64,
    pub water: f64,
}

/// Work \[J] over a span of time: dissipated by dampers, and put in by prescribed motions and the
/// water.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Work {
    pub dissipated: f64,
    pub external: f64,
}

impl Work {
    /// `½ h (P_a + P_b)`: the trapezoid rule over a step `h` \[s] between two evaluations, of the
    /// dissipated and the external power (the water's is the caller's).
    pub fn trapezoid(h: f64, a: &Powers, b: &Powers) -> Self {
        Self { dissipated: 0.5 * h * (a.dissipated + b.dissipated), external: 0.5 * h * (a.external + b.external) }
    }
}

/// Kinetic and gravity energy of the bodies \[J].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyEnergy {
    /// `Σ ½ m |v|² + ½ ωᵀ I ω`.
    pub kinetic: f64,
    /// `Σ −m g·x_G`.
    pub gravity: f64,
}

impl BodyEnergy {
    /// The energies of one body in state `state` (velocities at the same instant as the
    /// position) under `gravity` [m/s²]; nothing for a kinematic body, which forces do not move.
    #[inline(always)]
    pub fn of(body: &RigidBody, state: &BodyState, gravity: &Vec3) -> Self {
        if body.is_kinematic() {
            return Self::default();
        }
        Self {
            kinetic: body.kinetic_energy(&state.velocity, &state.angular_velocity),
            gravity: -body.mass() * gravity.dot(&state.position),
        }
    }

    /// The energies of `bodies` in the synchronised `states`.
    pub fn sum<'a>(bodies: &[RigidBody], states: impl IntoIterator<Item = &'a BodyState>, gravity: &Vec3) -> Self {
        bodies.iter().zip(states).fold(Self::default(), |total, (body, state)| total + Self::of(body, state, gravity))
    }
}

impl std::ops::Add for BodyEnergy {
    type Output = Self;
    #[inline(always)]
    fn add(self, other: Self) -> Self {
        Self { kinetic: self.kinetic + other.kinetic, gravity: self.gravity + other.gravity }
    }
}

/// Running totals of the work dissipated and put in since t = 0 \[J].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyLedger {
    pub dissipated: f64,
    pub external_work: f64,
}

impl EnergyLedger {
    /// Adds the work of a span of time.
    pub fn add(&mut self, work: &Work) {
        self.dissipated += work.dissipated;
        self.external_work += work.external;
    }
}
