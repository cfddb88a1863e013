//! What the couplings see around them: gravity, the fluid their lines are weighed in, and the
//! seabed (PHYSICS.md §3, §7). Part of the constant [`crate::system::System`]; the couplings
//! stage hands it to every coupling.

use crate::math::Vec3;
use crate::seabed::Seabed;

/// Gravity, the fluid and the seabed, as the couplings see them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surroundings {
    /// Gravity [m/s²].
    pub gravity: Vec3,
    /// `ρ` [kg/m³] of the fluid the lines are immersed in: a line's submerged weight per length
    /// is `w = (λ0 − ρ A_d) g` (PHYSICS.md §7). 0 in air (a dry scene).
    pub fluid_density: f64,
    /// The bottom the lines lie on, if the scene has one.
    pub seabed: Option<Seabed>,
}

impl Surroundings {
    /// Dry surroundings without a seabed, under `gravity` [m/s²].
    pub fn dry(gravity: Vec3) -> Self {
        Self { gravity, fluid_density: 0.0, seabed: None }
    }
}
