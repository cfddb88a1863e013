//! The water a scene declares: density, still level, depth, current, waves and their ramp
//! (PHYSICS.md §6, Water and Airy waves), checked, and the pressure and flow it gives.
//!
//! The still-water pressure is `ρ g (z_w − z)` \[Pa]; waves add `p_d` and the current its flow.
//! Both dynamic parts are ramped in over `T_r` \[s] by `½ (1 − cos(π t/T_r))` (1 from `T_r` on).

use super::current::{Current, Profile};
use super::dispersion::wavelength;
use super::spectrum::Jonswap;
use super::waves::{FlowInstant, Sea, WaveComponent};
use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require};

pub use super::current::Profile as CurrentProfile;

/// Waves (angles in radians).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WaveSpec {
    /// Still water.
    Calm,
    /// One Airy wave: height `H` \[m] (crest to trough), period `T` \[s], heading \[rad] (direction
    /// of travel, counter-clockwise from +x), phase `φ` \[rad].
    Regular { height: f64, period: f64, heading: f64, phase: f64 },
    /// A JONSWAP sea ([`super::spectrum`]): `H_s` \[m], `T_p` \[s], γ ≥ 1, heading \[rad], the
    /// number of components and the seed of their phases.
    Jonswap { significant_height: f64, peak_period: f64, gamma: f64, heading: f64, components: u32, seed: u64 },
}

/// A current: surface speed [m/s], heading \[rad], profile.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CurrentSpec {
    pub speed: f64,
    pub heading: f64,
    pub profile: Profile,
}

/// What a scene says about its water (SI units, angles in radians).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaterSpec {
    /// ρ [kg/m³] > 0.
    pub density: f64,
    /// Still-water level `z_w` \[m].
    pub level: f64,
    /// Depth `h` \[m] > 0 (seabed at `z_w − h`); `None` for deep water.
    pub depth: Option<f64>,
    pub current: CurrentSpec,
    pub waves: WaveSpec,
    /// Ramp time `T_r` \[s] ≥ 0; `None` for two wave periods (none for calm water).
    pub ramp: Option<f64>,
}

impl Default for WaterSpec {
    fn default() -> Self {
        Self {
            density: 1025.0,
            level: 0.0,
            depth: None,
            current: CurrentSpec::default(),
            waves: WaveSpec::Calm,
            ramp: None,
        }
    }
}

/// Components of a JONSWAP sea beyond which the scene is taken as a mistake (each costs a
/// sine, a cosine and an exponential per hull vertex per evaluation).
pub const MAX_COMPONENTS: u32 = 1000;

/// The breaking limit of wave steepness `H/λ` (Michell's 0.142 ≈ 1/7).
pub const BREAKING_STEEPNESS: f64 = 1.0 / 7.0;

/// Water that cannot be.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum WaterError {
    /// A number out of its range ([`crate::parameter`]): the value of the spec at `field`.
    #[error("{source}")]
    Parameter { field: WaterField, source: ParameterError },
    #[error("JONSWAP gamma must be ≥ 1, got {0}")]
    Gamma(f64),
    #[error("a JONSWAP sea needs 1 to {MAX_COMPONENTS} components, got {0}")]
    Components(u32),
    #[error("the wave is steeper than the breaking limit: H/λ = {height}/{wavelength:.3} = {steepness:.4} > 1/7")]
    Breaking { height: f64, wavelength: f64, steepness: f64 },
    #[error("a power-law current needs a depth (it is zero at the seabed)")]
    ProfileWithoutDepth,
    #[error("water needs gravity along −z, got ({0}, {1}, {2}) m/s²")]
    Gravity(f64, f64, f64),
}

/// A number of a [`WaterSpec`], to say which one an error is about (a file maps each to its own
/// spelling, by type).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WaterField {
    Density,
    Level,
    Depth,
    CurrentSpeed,
    CurrentHeading,
    Ramp,
    WaveHeight,
    WavePeriod,
    WaveHeading,
    WavePhase,
    SignificantHeight,
    PeakPeriod,
    Gamma,
}

/// The water of a system: its spec, and what is derived from it once (the sea's components, the
/// current, the ramp time, g).
#[derive(Debug, Clone, PartialEq)]
pub struct Water {
    spec: WaterSpec,
    /// `|g|` [m/s²].
    gravity: f64,
    sea: Sea,
    current: Current,
    /// `T_r` [s].
    ramp: f64,
}

impl Water {
    /// The water `spec` under `gravity` [m/s²], which must point down (−z).
    ///
    /// # Errors
    /// A value out of its range, a wave steeper than [`BREAKING_STEEPNESS`], a power-law current
    /// in deep water, or gravity that does not point down.
    pub fn new(spec: WaterSpec, gravity: &Vec3) -> Result<Self, WaterError> {
        if !(gravity.x == 0.0 && gravity.y == 0.0 && gravity.z < 0.0 && gravity.z.is_finite()) {
            return Err(WaterError::Gravity(gravity.x, gravity.y, gravity.z));
        }
        let g = -gravity.z;
        check(&spec)?;
        let components = components(&spec, g)?;
        let ramp = spec.ramp.unwrap_or_else(|| 2.0 * peak_period(&spec.waves).unwrap_or(0.0));
        let sea = Sea::new(components, spec.level, spec.depth);
        let current =
            Current::new(spec.current.speed, spec.current.heading, spec.current.profile, spec.level, spec.depth);
        Ok(Self { spec, gravity: g, sea, current, ramp })
    }

    pub fn spec(&self) -> &WaterSpec {
        &self.spec
    }

    /// ρ [kg/m³].
    pub fn density(&self) -> f64 {
        self.spec.density
    }

    /// Still-water level `z_w` \[m].
    pub fn level(&self) -> f64 {
        self.spec.level
    }

    /// Depth `h` \[m], `None` for deep water.
    pub fn depth(&self) -> Option<f64> {
        self.spec.depth
    }

    /// The seabed's height `z_b = z_w − h` \[m], if the water has a depth.
    pub fn seabed(&self) -> Option<f64> {
        self.spec.depth.map(|h| self.spec.level - h)
    }

    /// `|g|` [m/s²].
    pub fn gravity(&self) -> f64 {
        self.gravity
    }

    /// `ρ g` [N/m³].
    pub fn specific_weight(&self) -> f64 {
        self.spec.density * self.gravity
    }

    pub fn sea(&self) -> &Sea {
        &self.sea
    }

    /// Ramp time `T_r` \[s].
    pub fn ramp_time(&self) -> f64 {
        self.ramp
    }

    /// Whether the water is still: no wave and no current.
    pub fn is_still(&self) -> bool {
        self.sea.is_calm() && self.current.is_still()
    }

    /// `½ (1 − cos(π t/T_r))` before `T_r`, 1 after.
    pub fn ramp(&self, time: f64) -> f64 {
        if time >= self.ramp {
            1.0
        } else if time <= 0.0 {
            0.0
        } else {
            0.5 * (1.0 - (std::f64::consts::PI * time / self.ramp).cos())
        }
    }

    /// `|U_s| + Σ ω a` [m/s]: no water moves faster (the waves' orbital speed is largest at the
    /// surface, `ω a` per component).
    pub fn peak_flow_speed(&self) -> f64 {
        self.spec.current.speed + self.sea.components().iter().map(|c| c.frequency * c.amplitude).sum::<f64>()
    }

    /// The surface elevation \[m] above the still level at `(x, y)` and `time` \[s], ramped.
    pub fn elevation(&self, x: f64, y: f64, time: f64) -> f64 {
        if self.sea.is_calm() { 0.0 } else { self.ramp(time) * self.sea.elevation(x, y, time) }
    }

    /// Velocity [m/s] and acceleration [m/s²] of the water at `point` and `time` \[s]: waves and
    /// current, ramped.
    pub fn flow(&self, point: &Vec3, time: f64) -> (Vec3, Vec3) {
        let ramp = self.ramp(time);
        if ramp == 0.0 {
            return (Vec3::zeros(), Vec3::zeros());
        }
        let (waves, acceleration) =
            if self.sea.is_calm() { (Vec3::zeros(), Vec3::zeros()) } else { self.sea.kinematics(point, time) };
        ((waves + self.current.velocity(point.z)) * ramp, acceleration * ramp)
    }

    /// The same water with its sea summed component by component, as before the harmonic sums
    /// (a component of zero amplitude heading across the others makes it not harmonic).
    #[cfg(test)]
    pub(crate) fn summed_by_component(&self) -> Self {
        let mut components = self.sea.components().to_vec();
        let across = components.first().map_or(0.0, |c| c.heading) + std::f64::consts::FRAC_PI_2;
        components.push(WaveComponent {
            amplitude: 0.0,
            frequency: 1.0,
            wave_number: 0.1,
            heading: across,
            phase: 0.0,
        });
        Self { sea: Sea::new(components, self.spec.level, self.spec.depth), ..self.clone() }
    }

    /// The waves' flow at `time` \[s] into `instant`, for [`Water::flow_at`] at many points.
    pub fn flow_instant(&self, time: f64, instant: &mut FlowInstant) {
        self.sea.flow_instant(time, instant);
    }

    /// [`Water::flow`] at `point` at the time of `instant` ([`Water::flow_instant`]): the same
    /// velocity and acceleration to round-off, the waves' sum taken by powers of one complex
    /// number where the sea is harmonic ([`super::waves`]).
    #[inline(always)]
    pub fn flow_at(&self, instant: &FlowInstant, point: &Vec3) -> (Vec3, Vec3) {
        let ramp = self.ramp(instant.time());
        if ramp == 0.0 {
            return (Vec3::zeros(), Vec3::zeros());
        }
        let (waves, acceleration) =
            if self.sea.is_calm() { (Vec3::zeros(), Vec3::zeros()) } else { self.sea.kinematics_at(instant, point) };
        ((waves + self.current.velocity(point.z)) * ramp, acceleration * ramp)
    }
}

/// Every number finite and in its range.
fn check(spec: &WaterSpec) -> Result<(), WaterError> {
    use WaterField as F;
    let require = |field: WaterField, name, value, bound, unit| {
        require(name, value, bound, unit).map_err(|source| WaterError::Parameter { field, source })
    };
    require(F::Density, "density", spec.density, Bound::Positive, "kg/m³")?;
    require(F::Level, "level", spec.level, Bound::Finite, "m")?;
    if let Some(depth) = spec.depth {
        require(F::Depth, "depth", depth, Bound::Positive, "m")?;
    }
    require(F::CurrentSpeed, "current speed", spec.current.speed, Bound::NonNegative, "m/s")?;
    require(F::CurrentHeading, "current heading", spec.current.heading, Bound::Finite, "rad")?;
    if spec.current.profile.needs_depth() && spec.depth.is_none() {
        return Err(WaterError::ProfileWithoutDepth);
    }
    if let Some(ramp) = spec.ramp {
        require(F::Ramp, "ramp", ramp, Bound::NonNegative, "s")?;
    }
    match spec.waves {
        WaveSpec::Calm => {}
        WaveSpec::Regular { height, period, heading, phase } => {
            require(F::WaveHeight, "wave height", height, Bound::NonNegative, "m")?;
            require(F::WavePeriod, "wave period", period, Bound::Positive, "s")?;
            require(F::WaveHeading, "wave heading", heading, Bound::Finite, "rad")?;
            require(F::WavePhase, "wave phase", phase, Bound::Finite, "rad")?;
        }
        WaveSpec::Jonswap { significant_height, peak_period, gamma, heading, components, .. } => {
            require(F::SignificantHeight, "significant wave height", significant_height, Bound::NonNegative, "m")?;
            require(F::PeakPeriod, "peak period", peak_period, Bound::Positive, "s")?;
            require(F::Gamma, "gamma", gamma, Bound::Finite, "")?;
            if !(gamma >= 1.0) {
                return Err(WaterError::Gamma(gamma));
            }
            require(F::WaveHeading, "wave heading", heading, Bound::Finite, "rad")?;
            if !(1..=MAX_COMPONENTS).contains(&components) {
                return Err(WaterError::Components(components));
            }
        }
    }
    Ok(())
}

/// The period the ramp and the steepness are judged by: the wave's, or the sea's peak.
fn peak_period(waves: &WaveSpec) -> Option<f64> {
    match *waves {
        WaveSpec::Calm => None,
        WaveSpec::Regular { period, .. } => Some(period),
        WaveSpec::Jonswap { peak_period, .. } => Some(peak_period),
    }
}

/// The sea's components under gravity `g` [m/s²], refused beyond the breaking limit (for a
/// JONSWAP sea, `H_s` over the wavelength of `T_p`).
fn components(spec: &WaterSpec, g: f64) -> Result<Vec<WaveComponent>, WaterError> {
    let steep = |height: f64, period: f64| {
        let wavelength = wavelength(period, spec.depth, g);
        let steepness = height / wavelength;
        if steepness > BREAKING_STEEPNESS {
            Err(WaterError::Breaking { height, wavelength, steepness })
        } else {
            Ok(())
        }
    };
    Ok(match spec.waves {
        WaveSpec::Calm => Vec::new(),
        WaveSpec::Regular { height, period, heading, phase } => {
            steep(height, period)?;
            let frequency = std::f64::consts::TAU / period;
            let wave_number = super::dispersion::wave_number(frequency, spec.depth, g);
            vec![WaveComponent { amplitude: 0.5 * height, frequency, wave_number, heading, phase }]
        }
        WaveSpec::Jonswap { significant_height, peak_period, gamma, heading, components, seed } => {
            steep(significant_height, peak_period)?;
            Jonswap { significant_height, peak_period, gamma }.components(
                components as usize,
                heading,
                seed,
                spec.depth,
                g,
            )
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOWN: Vec3 = Vec3::new(0.0, 0.0, -9.80665);

    fn with(edit: impl FnOnce(&mut WaterSpec)) -> Result<Water, WaterError> {
        let mut spec = WaterSpec {
            waves: WaveSpec::Regular { height: 2.0, period: 8.0, heading: 0.0, phase: 0.0 },
            ..WaterSpec::default()
        };
        edit(&mut spec);
        Water::new(spec, &DOWN)
    }

    #[test]
    fn bad_water_is_refused_with_the_reason() {
        let refused = |edit: fn(&mut WaterSpec)| with(edit).unwrap_err().to_string();
        assert_eq!(refused(|s| s.density = 0.0), "density must be > 0 kg/m³, got 0");
        assert_eq!(refused(|s| s.depth = Some(-1.0)), "depth must be > 0 m, got -1");
        assert_eq!(refused(|s| s.density = f64::NAN), "density must be > 0 kg/m³, got NaN");
        assert_eq!(refused(|s| s.level = f64::INFINITY), "level must be finite, got inf");
        assert_eq!(
            refused(|s| s.waves = WaveSpec::Regular { height: 2.0, period: 0.0, heading: 0.0, phase: 0.0 }),
            "wave period must be > 0 s, got 0"
        );
        // A 10 m wave of 3 s (λ = 14.05 m deep) breaks.
        assert!(matches!(
            with(|s| s.waves = WaveSpec::Regular { height: 10.0, period: 3.0, heading: 0.0, phase: 0.0 }),
            Err(WaterError::Breaking { .. })
        ));
        let jonswap = WaveSpec::Jonswap {
            significant_height: 2.0,
            peak_period: 8.0,
            gamma: 0.9,
            heading: 0.0,
            components: 10,
            seed: 1,
        };
        assert_eq!(with(|s| s.waves = jonswap), Err(WaterError::Gamma(0.9)));
        assert_eq!(with(|s| s.current.profile = Profile::PowerLaw), Err(WaterError::ProfileWithoutDepth));
        assert_eq!(
            Water::new(WaterSpec::default(), &Vec3::new(1.0, 0.0, -9.8)),
            Err(WaterError::Gravity(1.0, 0.0, -9.8))
        );
    }

    #[test]
    fn the_ramp_starts_at_zero_and_reaches_one_after_two_periods() {
        let water = with(|_| {}).expect("a valid sea");
        assert_eq!(water.ramp_time(), 16.0);
        assert_eq!(water.ramp(0.0), 0.0);
        assert!((water.ramp(8.0) - 0.5).abs() < 1e-15);
        assert_eq!(water.ramp(16.0), 1.0);
    }
}
