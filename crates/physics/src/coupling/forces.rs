//! What one coupling did at an evaluation: every kind writes its own record, so its forces can
//! be plotted, recorded and tested apart from the others before they are summed into the
//! bodies' loads (MuJoCo's per-source force buffers).

use crate::math::Vec3;

/// What one coupling did at the last evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CouplingForces {
    /// End positions, world \[m].
    pub point1: Vec3,
    pub point2: Vec3,
    /// Force exerted by the coupling on end 1 and on end 2, world \[N].
    pub f1: Vec3,
    pub f2: Vec3,
    /// Scalar force of the coupling \[N] (a spring's `f1 = f_e + k_d ẋ`, positive in tension).
    pub tension: f64,
    /// Power dissipated by damping and by friction against slip \[W] ≥ 0.
    pub dissipated_power: f64,
    /// Power into the energy a quasi-static grounded line's seabed friction holds \[W] (either
    /// sign: it gives back what it took, PHYSICS.md §7; booked with the stored energy).
    pub held_power: f64,
    /// Potential energy stored in the coupling \[J].
    pub potential: f64,
}
