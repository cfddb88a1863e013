//! Current: a horizontal flow, uniform or sheared (PHYSICS.md §6, Water).
//!
//! `U(z) = U_s e` [m/s] (uniform), or the 1/7 power law `U(z) = U_s ((z' − z_b)/h)^(1/7) e`
//! with `z' = min(z, z_w)` clamped to the seabed `z_b = z_w − h`, `h` the depth \[m];
//! `U_s` the surface speed [m/s], `e` the horizontal heading unit vector.

use crate::math::Vec3;

/// How the current's speed varies with depth.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Profile {
    /// The same speed at every depth.
    #[default]
    Uniform,
    /// `U_s ((z' − z_b)/h)^(1/7)`: zero at the seabed (needs a depth).
    PowerLaw,
}

impl Profile {
    /// Whether the profile is defined only over a finite depth (the water refuses it in deep water).
    pub fn needs_depth(self) -> bool {
        match self {
            Self::Uniform => false,
            Self::PowerLaw => true,
        }
    }
}

/// A current over water of a given level and depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Current {
    /// `U_s e` [m/s].
    surface: Vec3,
    profile: Profile,
    /// `z_w` [m] and `h` [m] (`None`: deep water, where only the uniform profile is defined).
    level: f64,
    depth: Option<f64>,
}

impl Current {
    /// Speed `speed` [m/s] toward `heading` [rad, counter-clockwise from +x].
    pub fn new(speed: f64, heading: f64, profile: Profile, level: f64, depth: Option<f64>) -> Self {
        Self { surface: Vec3::new(heading.cos(), heading.sin(), 0.0) * speed, profile, level, depth }
    }

    /// Whether there is no current.
    pub fn is_still(&self) -> bool {
        self.surface == Vec3::zeros()
    }

    /// `U(z)` [m/s] at height `z` \[m] (unramped).
    pub fn velocity(&self, z: f64) -> Vec3 {
        match (self.profile, self.depth) {
            (Profile::PowerLaw, Some(h)) => {
                let above_seabed = (z.min(self.level) - (self.level - h)).max(0.0);
                self.surface * (above_seabed / h).powf(1.0 / 7.0)
            }
            // Deep water has the uniform profile only (the water refuses a power law without a depth).
            (Profile::Uniform, _) | (Profile::PowerLaw, None) => self.surface,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn the_power_law_is_the_surface_speed_at_the_top_and_zero_at_the_seabed() {
        let current = Current::new(1.2, std::f64::consts::FRAC_PI_2, Profile::PowerLaw, 1.0, Some(50.0));
        assert_relative_eq!(current.velocity(1.0), Vec3::new(0.0, 1.2, 0.0), epsilon = 1e-15);
        assert_relative_eq!(current.velocity(5.0), Vec3::new(0.0, 1.2, 0.0), epsilon = 1e-15);
        assert_eq!(current.velocity(-49.0).norm(), 0.0);
        assert_relative_eq!(current.velocity(-24.0).y, 1.2 * 0.5_f64.powf(1.0 / 7.0), epsilon = 1e-15);
    }
}
