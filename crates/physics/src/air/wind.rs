//! The air a scene declares (PHYSICS.md §10, "Wind"): its density, the mean wind's speed at a
//! reference height, its height profile and heading, its gusts, and the ramp it comes in over.
//!
//! The mean wind at height `z` above the still water level (above `z = 0` without water) blows
//! toward `e = (cos θ, sin θ, 0)`, θ the heading (the convention of the waves' heading, §6), at
//! - `PowerLaw(α)`: `U(z) = U_r (z/z_r)^α` (α = 0.11 offshore, API RP 2A / DNV-RP-C205), or
//! - `Logarithmic(z₀)`: `U(z) = U_r ln(z/z₀) / ln(z_r/z₀)`, z₀ the roughness length \[m],
//!
//! `U_r` [m/s] the mean speed at the reference height `z_r` \[m] (10 m in the codes of practice),
//! and none at or below the water (`z ≤ 0`, or `z ≤ z₀`). The gusts add `u(t)` along `e`
//! ([`super::gusts`]). Mean wind and gusts come in over the ramp `T_r` \[s] by
//! `½ (1 − cos(π t/T_r))`, as the waves do.

use super::gusts::{GustError, GustSpec, Gusts};
use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require};

/// Dry air at 15 °C and sea level \[kg/m³] (ISO 2533).
pub const AIR_DENSITY: f64 = 1.225;

/// How the mean wind speed varies with height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WindProfile {
    /// `U(z) = U_r (z/z_r)^α`, α ≥ 0 (0.11 offshore).
    PowerLaw(f64),
    /// `U(z) = U_r ln(z/z₀)/ln(z_r/z₀)`, z₀ > 0 the roughness length \[m] (2e-4 m over open sea).
    Logarithmic(f64),
}

/// What a scene says of the wind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WindSpec {
    /// `U_r` [m/s] ≥ 0.
    pub speed: f64,
    /// `z_r` \[m] > 0.
    pub height: f64,
    /// θ \[rad]: the direction the wind blows toward, counter-clockwise from +x.
    pub heading: f64,
    pub profile: WindProfile,
    pub gusts: GustSpec,
}

/// What a scene says of the air.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AirSpec {
    /// ρ_a \[kg/m³] > 0.
    pub density: f64,
    pub wind: WindSpec,
    /// `T_r` \[s] ≥ 0: the wind comes in over it.
    pub ramp: f64,
}

/// Air that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AirError {
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    #[error("gusts: {0}")]
    Gusts(#[from] GustError),
    #[error("a logarithmic profile's roughness z₀ = {roughness} m must lie below the reference height {height} m")]
    RoughnessAboveReference { roughness: f64, height: f64 },
}

/// The air of a system: its spec, checked, and its gusts realised once.
#[derive(Debug, Clone, PartialEq)]
pub struct Air {
    spec: AirSpec,
    direction: Vec3,
    gusts: Gusts,
}

impl Air {
    /// Checks `spec` and realises its gusts.
    ///
    /// # Errors
    /// A number out of its range (naming its field), or gusts that cannot be realised.
    pub fn new(spec: AirSpec) -> Result<Self, AirError> {
        require("density", spec.density, Bound::Positive, "kg/m³")?;
        require("ramp", spec.ramp, Bound::NonNegative, "s")?;
        let wind = &spec.wind;
        require("speed", wind.speed, Bound::NonNegative, "m/s")?;
        require("height", wind.height, Bound::Positive, "m")?;
        require("heading_deg", wind.heading, Bound::Finite, "rad")?;
        match wind.profile {
            WindProfile::PowerLaw(exponent) => {
                require("PowerLaw", exponent, Bound::NonNegative, "")?;
            }
            WindProfile::Logarithmic(roughness) => {
                require("Logarithmic", roughness, Bound::Positive, "m")?;
                if roughness >= wind.height {
                    return Err(AirError::RoughnessAboveReference { roughness, height: wind.height });
                }
            }
        }
        let gusts = Gusts::new(&wind.gusts)?;
        Ok(Self { spec, direction: Vec3::new(wind.heading.cos(), wind.heading.sin(), 0.0), gusts })
    }

    /// The spec it was built from.
    pub fn spec(&self) -> &AirSpec {
        &self.spec
    }

    /// ρ_a \[kg/m³].
    pub fn density(&self) -> f64 {
        self.spec.density
    }

    /// `e`: the unit vector the wind blows along.
    pub fn direction(&self) -> &Vec3 {
        &self.direction
    }

    /// The realised gusts.
    pub fn gusts(&self) -> &Gusts {
        &self.gusts
    }

    /// `U(z)` [m/s] at height `height` \[m] above the still water level (module docs).
    pub fn mean_speed(&self, height: f64) -> f64 {
        let wind = &self.spec.wind;
        if height <= 0.0 {
            return 0.0;
        }
        match wind.profile {
            WindProfile::PowerLaw(exponent) => wind.speed * (height / wind.height).powf(exponent),
            WindProfile::Logarithmic(roughness) if height > roughness => {
                wind.speed * (height / roughness).ln() / (wind.height / roughness).ln()
            }
            WindProfile::Logarithmic(_) => 0.0,
        }
    }

    /// The ramp `r(t)` (0 to 1) at `time` \[s].
    pub fn ramp(&self, time: f64) -> f64 {
        if time >= self.spec.ramp {
            1.0
        } else if time <= 0.0 {
            0.0
        } else {
            0.5 * (1.0 - (std::f64::consts::PI * time / self.spec.ramp).cos())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn air(profile: WindProfile) -> Air {
        Air::new(AirSpec {
            density: AIR_DENSITY,
            wind: WindSpec { speed: 20.0, height: 10.0, heading: 0.5, profile, gusts: GustSpec::Steady },
            ramp: 10.0,
        })
        .expect("valid air")
    }

    #[test]
    fn the_profiles_give_the_reference_speed_at_the_reference_height_and_none_at_the_water() {
        let power = air(WindProfile::PowerLaw(0.11));
        assert!((power.mean_speed(10.0) - 20.0).abs() < 1e-12);
        assert!((power.mean_speed(90.0) - 20.0 * 9.0_f64.powf(0.11)).abs() < 1e-12);
        assert_eq!(power.mean_speed(-1.0), 0.0);
        let log = air(WindProfile::Logarithmic(2e-4));
        assert!((log.mean_speed(10.0) - 20.0).abs() < 1e-12);
        assert!((log.mean_speed(100.0) - 20.0 * (100.0f64 / 2e-4).ln() / (10.0f64 / 2e-4).ln()).abs() < 1e-12);
        assert_eq!(log.mean_speed(1e-4), 0.0);
        assert!((power.direction() - Vec3::new(0.5f64.cos(), 0.5f64.sin(), 0.0)).norm() < 1e-15);
        assert_eq!((power.ramp(0.0), power.ramp(10.0)), (0.0, 1.0));
        assert!((power.ramp(5.0) - 0.5).abs() < 1e-15);
    }

    #[test]
    fn bad_air_is_refused_naming_the_field() {
        let spec = *air(WindProfile::PowerLaw(0.11)).spec();
        let refused = |spec: AirSpec| Air::new(spec).expect_err("bad").to_string();
        assert_eq!(refused(AirSpec { density: 0.0, ..spec }), "density must be > 0 kg/m³, got 0");
        let wind = |wind: WindSpec| AirSpec { wind, ..spec };
        assert_eq!(refused(wind(WindSpec { speed: -1.0, ..spec.wind })), "speed must be ≥ 0 m/s, got -1");
        assert!(
            refused(wind(WindSpec { profile: WindProfile::Logarithmic(20.0), ..spec.wind }))
                .contains("roughness z₀ = 20 m must lie below the reference height 10 m")
        );
    }
}
