//! Energy accounting (PHYSICS.md §5).
//!
//! `total = kinetic + gravity + elastic` \[J]. Dampers dissipate `dissipated = ∫ P_d dt` ≥ 0 and
//! kinematic (prescribed) bodies inject `−∫ Σ (F_k·v_k + M_k·ω_k) dt`, the work the drivers do
//! against the couplings, and the water (§6) and the air (§10) `∫ Σ (F_w·v + M_w·ω) dt` on the
//! bodies they load:
//! together the `external_work`. The balance `total + dissipated − external_work` is
//! constant for the exact motion; a numerical run keeps it to the integrator's order. Each
//! integrator integrates the powers by its own rule ([`crate::integrator::StepReport::work`]);
//! the world adds up the work in its [`EnergyLedger`].
//!
//! A quasi-static grounded line's seabed friction (PHYSICS.md §7) is not a dissipation: its law
//! gives the end forces from the ends' positions alone, with the friction always toward the
//! anchor, so what it takes as a fairlead moves out it gives back as the fairlead comes in (no
//! hysteresis). Its work `held = ∫ P_h dt` is booked with the couplings' stored energy:
//! `elastic = Σ U_c + held`, and `dissipated` counts only what dissipates.

use crate::body::{BodyState, RigidBody};
use crate::math::Vec3;

/// Energies of a world at one instant \[J].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyReport {
    /// `Σ ½ m |v|² + ½ ωᵀ I ω` of the bodies that respond to forces.
    pub kinetic: f64,
    /// `Σ −m g·x_G` of the bodies that respond to forces.
    pub gravity: f64,
    /// Energy stored in the couplings: their potentials and the work the quasi-static lines'
    /// seabed friction holds.
    pub elastic: f64,
    /// Work dissipated since t = 0 (dampers, contact, friction against slip): never decreases.
    pub dissipated: f64,
    /// Work done by prescribed motions, the water and the air on the system since t = 0.
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

/// Power \[W] of the couplings at one force evaluation: dissipated (≥ 0), and held by the
/// quasi-static lines' seabed friction (either sign, see the module's notes).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CouplingPower {
    pub dissipated: f64,
    pub held: f64,
}

/// Power \[W] at one force evaluation: the couplings', put in by prescribed motions, and put in
/// by the environment, water and air (kept apart: the staggered schemes integrate it with their
/// half-step velocities, see [`crate::integrator::leapfrog`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Powers {
    pub couplings: CouplingPower,
    pub external: f64,
    pub environment: f64,
}

/// Work \[J] over a span of time: dissipated, held by the quasi-static lines' seabed friction,
/// and put in by prescribed motions, the water and the air.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Work {
    pub dissipated: f64,
    pub held: f64,
    pub external: f64,
}

impl Work {
    /// Work `external` \[J] put in, nothing dissipated or held.
    pub fn external(external: f64) -> Self {
        Self { external, ..Self::default() }
    }

    /// `h Σ b_j P_j`: the quadrature of weights `weights` over a step `h` \[s] of the couplings'
    /// and the external powers at the evaluations `powers` (the environment's included: the schemes
    /// that take it apart add theirs).
    pub fn quadrature<'a>(h: f64, weights: &[f64], powers: impl IntoIterator<Item = &'a Powers>) -> Self {
        let sum = weights.iter().zip(powers).fold(Self::default(), |sum, (b, p)| Self {
            dissipated: sum.dissipated + b * p.couplings.dissipated,
            held: sum.held + b * p.couplings.held,
            external: sum.external + b * (p.external + p.environment),
        });
        Self { dissipated: h * sum.dissipated, held: h * sum.held, external: h * sum.external }
    }

    /// `½ h (P_a + P_b)`: the trapezoid rule over a step `h` \[s] between two evaluations, of the
    /// couplings' and the external power (the environment's is the caller's).
    pub fn trapezoid(h: f64, a: &Powers, b: &Powers) -> Self {
        let half = 0.5 * h;
        Self {
            dissipated: half * (a.couplings.dissipated + b.couplings.dissipated),
            held: half * (a.couplings.held + b.couplings.held),
            external: half * (a.external + b.external),
        }
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

/// Running totals of the work dissipated, held and put in since t = 0 \[J].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyLedger {
    pub dissipated: f64,
    pub held: f64,
    pub external_work: f64,
}

impl EnergyLedger {
    /// Adds the work of a span of time.
    pub fn add(&mut self, work: &Work) {
        self.dissipated += work.dissipated;
        self.held += work.held;
        self.external_work += work.external;
    }
}
