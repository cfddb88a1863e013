//! A floating body's RAOs measured in the time domain (PHYSICS.md §9, "Closed forms and
//! checks"): the world run in one small regular wave and the settled motion of the body's
//! reference point P fitted, the counterpart of [`crate::rao`]'s frequency-domain solve.
//!
//! The world keeps everything its scene gave it (couplings, other bodies, current, integrator)
//! but its sea, replaced at t = 0 by one Airy wave (§6) of amplitude `a` \[m], period `T` \[s],
//! heading β and phase 0, ramped in over `T_r` \[s]. The run lasts `t_end` \[s]; over its last
//! `t_w = max(3 T, 40 s)`, which must start after the ramp, each of P's six coordinates
//! `q = (x_P − x_P(0), θ)` (θ the rotation vector of `R R(0)ᵀ`, world axes \[m, rad]) is fitted
//! after every world step by linear least squares with
//! `c₀ + c₁ (t − t_m) + A cos ωt + B sin ωt` (`t_m` the window's middle: the constant and the
//! drift take the mean offset and what is left of a slow transient), and
//!
//! `ξ = (A − iB) / (a e^{−i(k e·x₀ + φ)})` \[m/m, rad/m]
//!
//! the complex amplitude of `q` over the wave's at P's initial horizontal position `x₀`
//! (§6: `η = a cos(k e·x − ωt + φ)`): WAMIT's convention `q = Re{a ξ e^{iωt}}`, as
//! [`crate::rao::LinearModel::rao`] gives it.
//!
//! Written on nalgebra's Cholesky factorisation of the 4 × 4 normal equations, accumulated as
//! the run goes (no samples kept): a least-squares crate would want the samples as a matrix.

use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require};
use crate::potential::ComplexVector6;
use crate::rao::LinearModel;
use crate::water::{WaterSpec, WaveSpec};
use crate::world::{EditError, StepError, World};
use nalgebra::{Complex, Matrix4, Vector4};
use std::f64::consts::TAU;

/// The fitted window is at least this many wave periods…
pub const WINDOW_PERIODS: f64 = 3.0;

/// …and at least this long \[s].
pub const WINDOW_LEAST: f64 = 40.0;

/// A run lasts at least this long \[s] unless told otherwise.
pub const LEAST_DURATION: f64 = 300.0;

/// How an RAO is measured: the wave's amplitude, its ramp and the run's length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegularWaveRun {
    /// `a` \[m].
    amplitude: f64,
    /// `T_r` \[s].
    ramp: f64,
    /// `t_end` \[s]; `None` for [`RegularWaveRun::duration`]'s default.
    duration: Option<f64>,
}

/// Why a regular-wave run gave no RAO.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TimeDomainError {
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    #[error(
        "a run of {duration} s is too short for T = {period} s: it needs the ramp ({ramp} s) and then \
         max(3 T, 40 s) = {window} s to fit, {needed} s in all"
    )]
    TooShort { period: f64, duration: f64, ramp: f64, window: f64, needed: f64 },
    #[error("the regular wave is refused: {0}")]
    Wave(EditError),
    #[error(transparent)]
    Step(#[from] StepError),
    #[error("the settled motion is not finite: the run diverged")]
    NotFinite,
}

impl RegularWaveRun {
    /// Waves of `amplitude` \[m] > 0 ramped over `ramp` \[s] ≥ 0, runs of `duration` \[s] > 0
    /// (`None`: [`RegularWaveRun::duration`]'s default).
    ///
    /// # Errors
    /// A value out of its range.
    pub fn new(amplitude: f64, ramp: f64, duration: Option<f64>) -> Result<Self, ParameterError> {
        Ok(Self {
            amplitude: require("amplitude", amplitude, Bound::Positive, "m")?,
            ramp: require("ramp", ramp, Bound::NonNegative, "s")?,
            duration: duration.map(|d| require("duration", d, Bound::Positive, "s")).transpose()?,
        })
    }

    /// `a` \[m].
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }

    /// `T_r` \[s].
    pub fn ramp(&self) -> f64 {
        self.ramp
    }

    /// `t_w = max(3 T, 40 s)` \[s] for period `period` \[s].
    pub fn window(period: f64) -> f64 {
        (WINDOW_PERIODS * period).max(WINDOW_LEAST)
    }

    /// `t_end` \[s] at period `period` \[s]: the one given, or `max(300 s, T_r + 2 t_w)` (the
    /// transient's time to die out at least the window's length).
    pub fn duration(&self, period: f64) -> f64 {
        self.duration.unwrap_or_else(|| LEAST_DURATION.max(self.ramp + 2.0 * Self::window(period)))
    }

    /// Whether a run at `period` \[s] > 0 fits its window after the ramp.
    ///
    /// # Errors
    /// A period out of range, or a run too short.
    pub fn check(&self, period: f64) -> Result<(), TimeDomainError> {
        let period = require("period", period, Bound::Positive, "s")?;
        let (duration, window) = (self.duration(period), Self::window(period));
        if duration - window < self.ramp {
            return Err(TimeDomainError::TooShort {
                period,
                duration,
                ramp: self.ramp,
                window,
                needed: self.ramp + window,
            });
        }
        Ok(())
    }

    /// `ξ` of `model`'s body at period `period` \[s] for waves travelling toward `heading`
    /// \[rad], from a run of `world` (built from the same system as `model`, at t = 0).
    ///
    /// # Errors
    /// A run too short, a wave the water refuses (too steep, a heading outside the body's file),
    /// a run that diverges.
    pub fn measure(
        &self,
        mut world: World,
        model: &LinearModel,
        period: f64,
        heading: f64,
    ) -> Result<ComplexVector6, TimeDomainError> {
        self.check(period)?;
        let scene_water = world.system().water().map(|stage| *stage.water.spec()).unwrap_or_default();
        let waves = WaveSpec::Regular { height: 2.0 * self.amplitude, period, heading, phase: 0.0 };
        world
            .replace_water(WaterSpec { waves, ramp: Some(self.ramp), ..scene_water })
            .map_err(TimeDomainError::Wave)?;
        let index = model.body();
        let start = world.state(index);
        let origin = start.position + model.arm(&start.frame());
        let (end, window) = (self.duration(period), Self::window(period));
        let mut fit = HarmonicFit::new(TAU / period, end - 0.5 * window);
        while world.time() < end - 0.5 * world.dt() {
            world.step()?;
            if world.time() >= end - window {
                let state = world.state(index);
                let translation = state.position + model.arm(&state.frame()) - origin;
                let turn = (state.orientation * start.orientation.inverse()).scaled_axis();
                fit.add(world.time(), [translation.x, translation.y, translation.z, turn.x, turn.y, turn.z]);
            }
        }
        let wave = wave_at(&world, &origin).ok_or(TimeDomainError::NotFinite)?;
        let motion = fit.amplitudes().ok_or(TimeDomainError::NotFinite)?;
        let xi = motion / wave;
        if xi.iter().all(|x| x.re.is_finite() && x.im.is_finite()) { Ok(xi) } else { Err(TimeDomainError::NotFinite) }
    }
}

/// The complex amplitude `a e^{−i(k e·x + φ)}` \[m] of the world's one wave at `point`.
fn wave_at(world: &World, point: &Vec3) -> Option<Complex<f64>> {
    let wave = world.system().water()?.water.sea().components().first().copied()?;
    let along = point.x * wave.heading.cos() + point.y * wave.heading.sin();
    Some(Complex::from_polar(wave.amplitude, -(wave.wave_number * along + wave.phase)))
}

/// The least-squares fit of `c₀ + c₁ (t − t_m) + A cos ωt + B sin ωt` to six signals sampled
/// together, by its normal equations.
struct HarmonicFit {
    /// ω \[rad/s].
    omega: f64,
    /// `t_m` \[s].
    middle: f64,
    /// `Σ φ φᵀ`, φ = (1, t − t_m, cos ωt, sin ωt).
    normal: Matrix4<f64>,
    /// `Σ φ q` per signal.
    right: [Vector4<f64>; 6],
}

impl HarmonicFit {
    fn new(omega: f64, middle: f64) -> Self {
        Self { omega, middle, normal: Matrix4::zeros(), right: [Vector4::zeros(); 6] }
    }

    fn add(&mut self, time: f64, values: [f64; 6]) {
        let (sin, cos) = (self.omega * time).sin_cos();
        let basis = Vector4::new(1.0, time - self.middle, cos, sin);
        self.normal += basis * basis.transpose();
        for (right, value) in self.right.iter_mut().zip(values) {
            *right += basis * value;
        }
    }

    /// `A − iB` per signal; `None` for too few samples or non-finite ones.
    fn amplitudes(&self) -> Option<ComplexVector6> {
        let factor = self.normal.cholesky()?;
        let amplitudes = self.right.map(|right| {
            let c = factor.solve(&right);
            Complex::new(c[2], -c[3])
        });
        Some(ComplexVector6::from(amplitudes))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Signals made of the model exactly give back their amplitudes, whatever the offset and
    /// the drift: `q_d = d + 0.1 d t + Re{Q_d e^{iωt}}`.
    #[test]
    fn the_fit_returns_the_amplitude_of_an_exact_harmonic() {
        let omega = 0.7;
        let expected: [Complex<f64>; 6] =
            std::array::from_fn(|d| Complex::from_polar(1.0 + d as f64, 0.4 * d as f64 - 1.0));
        let mut fit = HarmonicFit::new(omega, 250.0);
        for n in 0..2000 {
            let t = 200.0 + 0.05 * f64::from(n);
            let turn = Complex::from_polar(1.0, omega * t);
            fit.add(t, std::array::from_fn(|d| d as f64 + 0.1 * d as f64 * t + (expected[d] * turn).re));
        }
        let got = fit.amplitudes().expect("enough samples");
        for d in 0..6 {
            assert!((got[d] - expected[d]).norm() < 1e-9, "{d}: {} vs {}", got[d], expected[d]);
        }
    }

    #[test]
    fn too_short_a_run_and_bad_values_are_refused() {
        let run = RegularWaveRun::new(0.05, 60.0, Some(120.0)).expect("valid");
        assert!(run.check(8.0).is_ok());
        let error = run.check(30.0).expect_err("120 s leaves no 90 s window after a 60 s ramp");
        assert_eq!(
            error.to_string(),
            "a run of 120 s is too short for T = 30 s: it needs the ramp (60 s) and then max(3 T, 40 s) = 90 s to fit, 150 s in all"
        );
        assert_eq!(run.check(0.0).expect_err("zero").to_string(), "period must be > 0 s, got 0");
        assert_eq!(
            RegularWaveRun::new(0.0, 60.0, None).expect_err("zero").to_string(),
            "amplitude must be > 0 m, got 0"
        );
        assert_eq!(
            RegularWaveRun::new(0.05, -1.0, None).expect_err("negative").to_string(),
            "ramp must be ≥ 0 s, got -1"
        );
        let default = RegularWaveRun::new(0.05, 60.0, None).expect("valid");
        assert_eq!(default.duration(8.0), 300.0);
        assert_eq!(default.duration(100.0), 660.0);
        assert!(default.check(100.0).is_ok());
    }
}
