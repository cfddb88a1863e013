//! Energy accounting (PHYSICS.md §5).
//!
//! `total = kinetic + gravity + elastic` [J]. Dampers dissipate `dissipated = ∫ P_d dt` ≥ 0 and
//! kinematic (prescribed) bodies inject `external_work = −∫ Σ (F_k·v_k + M_k·ω_k) dt`, the work
//! the drivers do against the couplings. The balance `total + dissipated − external_work` is
//! constant for the exact motion; a numerical run keeps it to the integrator's order.

/// Energies of a world at one instant [J].
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
    /// Work done by prescribed motions on the system since t = 0.
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

/// Running integrals of dissipated power and external power: by the trapezoid rule for the
/// one-evaluation schemes, by the scheme's own weights for the Runge–Kutta ones.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EnergyLedger {
    pub dissipated: f64,
    pub external_work: f64,
    dissipated_power: f64,
    external_power: f64,
}

impl EnergyLedger {
    /// Starts the integrals with the powers at t = 0 [W].
    pub fn new(dissipated_power: f64, external_power: f64) -> Self {
        Self { dissipated: 0.0, external_work: 0.0, dissipated_power, external_power }
    }

    /// Adds work integrated elsewhere [J] (the Runge–Kutta schemes integrate the powers with
    /// their own weights).
    pub fn add(&mut self, dissipated: f64, external_work: f64) {
        self.dissipated += dissipated;
        self.external_work += external_work;
    }

    /// Advances by `dt` [s] to the new powers [W].
    pub fn advance(&mut self, dt: f64, dissipated_power: f64, external_power: f64) {
        self.dissipated += 0.5 * dt * (self.dissipated_power + dissipated_power);
        self.external_work += 0.5 * dt * (self.external_power + external_power);
        self.dissipated_power = dissipated_power;
        self.external_power = external_power;
    }
}
