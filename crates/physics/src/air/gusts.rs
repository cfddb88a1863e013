//! The wind's gusts (PHYSICS.md §10): a spectrum `S(f)` [(m/s)²/Hz] at a height, realised as
//! `u(t) = Σ a_n cos(2π f_n t + φ_n)` with `a_n = √(2 S(f_n) Δf_n)` and phases drawn uniformly
//! from the scene's seed (PCG-64, MCG variant, as the waves' in `crate::water::spectrum`: the
//! same seed gives the same wind, bit for bit).
//!
//! - NPD (Frøya; API RP 2A, ISO 19901-1), `U₁₀` the 1-hour mean at 10 m:
//!   `S(f) = 320 (U₁₀/10)² (z/10)^0.45 / (1 + x^n)^{5/(3n)}`,
//!   `x = 172 f (z/10)^{2/3} (U₁₀/10)^{−0.75}`, n = 0.468.
//! - Kaimal (IEC 61400-1), the mean `U(z)`, intensity `I`, integral length `L`:
//!   `S(f) = (I U)² (4 L/U) / (1 + 6 f L/U)^{5/3}`.
//!
//! The frequencies are spaced evenly in log f over [`BAND`] (`f_n` the geometric centre of bin
//! n, `Δf_n` its width), so a few hundred components span the minutes-long periods a moored
//! body's surge answers and the seconds of a rotor's, and the sum repeats never (incommensurate
//! frequencies). The realised variance is `Σ a_n²/2 = Σ S(f_n) Δf_n`, the midpoint rule of
//! `∫ S df` over the band: NPD's spectrum holds 89 % of its variance in it at `U₁₀` = 20 m/s,
//! z = 10 m (`the_band_holds_most_of_the_npd_variance`); the rest is in periods below a second,
//! which a body metres across does not feel coherently (the gusts here are coherent over it).
//!
//! The gusts are fully coherent: every point sees the same phases, its amplitudes those of the
//! spectrum at its own height ([`GustPoint`]).

use rand_pcg::Pcg64Mcg;
use rand_pcg::rand_core::{Rng as _, SeedableRng as _};

/// The band of frequencies realised \[Hz]: from a period of almost three hours to one second.
pub const BAND: (f64, f64) = (1.0e-4, 1.0);

/// The most components a gust spectrum may be realised with.
pub const MAX_COMPONENTS: u32 = 2000;

/// NPD's exponent n.
const NPD_EXPONENT: f64 = 0.468;

/// Gusts that cannot be realised.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GustError {
    #[error("components must be 1 to {MAX_COMPONENTS}, got {0}")]
    Components(u32),
    #[error("Kaimal's {field} must be > 0{unit}, got {value}")]
    Kaimal { field: &'static str, value: f64, unit: &'static str },
}

/// The gusts of a wind (PHYSICS.md §10), realised as a sum of harmonics with seeded phases.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GustSpec {
    /// No gusts: the mean wind alone.
    Steady,
    /// The NPD (Frøya) spectrum of API RP 2A / ISO 19901-1, for the 1-hour mean `U_r` at 10 m.
    Npd { seed: u64, components: u32 },
    /// Kaimal's spectrum with turbulence intensity `intensity` [–] and integral length
    /// `length_scale` \[m] (IEC 61400-1: 340.2 m above 60 m).
    Kaimal { intensity: f64, length_scale: f64, seed: u64, components: u32 },
}

/// The spectrum a gust follows.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GustSpectrum {
    Npd,
    Kaimal { intensity: f64, length_scale: f64 },
}

impl GustSpectrum {
    /// `S(f)` [(m/s)²/Hz] at frequency `f` \[Hz] and height `z` \[m], for the reference wind
    /// `u10` [m/s] at 10 m (NPD) or the mean `mean` [m/s] at the height (Kaimal).
    pub fn density(&self, f: f64, z: f64, u10: f64, mean: f64) -> f64 {
        match *self {
            Self::Npd => {
                let x = 172.0 * f * (z / 10.0).powf(2.0 / 3.0) * (u10 / 10.0).powf(-0.75);
                320.0 * (u10 / 10.0).powi(2) * (z / 10.0).powf(0.45)
                    / (1.0 + x.powf(NPD_EXPONENT)).powf(5.0 / (3.0 * NPD_EXPONENT))
            }
            Self::Kaimal { intensity, length_scale } => {
                if mean <= 0.0 {
                    return 0.0;
                }
                let sigma = intensity * mean;
                sigma * sigma * 4.0 * length_scale / mean / (1.0 + 6.0 * f * length_scale / mean).powf(5.0 / 3.0)
            }
        }
    }
}

/// A gust realisation: its spectrum, frequencies \[Hz] (and angular, rad/s), bin widths \[Hz]
/// and phases \[rad]; none for a steady wind.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Gusts {
    spectrum: Option<GustSpectrum>,
    frequencies: Vec<f64>,
    angular: Vec<f64>,
    widths: Vec<f64>,
    phases: Vec<f64>,
}

impl Gusts {
    /// The realisation of `spec` (module docs).
    ///
    /// # Errors
    /// A component count out of range, or a Kaimal parameter that is not positive.
    pub fn new(spec: &GustSpec) -> Result<Self, GustError> {
        let (spectrum, seed, components) = match *spec {
            GustSpec::Steady => return Ok(Self::default()),
            GustSpec::Npd { seed, components } => (GustSpectrum::Npd, seed, components),
            GustSpec::Kaimal { intensity, length_scale, seed, components } => {
                for (field, value, unit) in [("intensity", intensity, ""), ("length_scale", length_scale, " m")] {
                    if !(value.is_finite() && value > 0.0) {
                        return Err(GustError::Kaimal { field, value, unit });
                    }
                }
                (GustSpectrum::Kaimal { intensity, length_scale }, seed, components)
            }
        };
        if components == 0 || components > MAX_COMPONENTS {
            return Err(GustError::Components(components));
        }
        let count = components as usize;
        let ratio = (BAND.1 / BAND.0).powf(1.0 / count as f64);
        let edge = |n: usize| BAND.0 * ratio.powi(n as i32);
        let frequencies: Vec<f64> = (0..count).map(|n| (edge(n) * edge(n + 1)).sqrt()).collect();
        let widths = (0..count).map(|n| edge(n + 1) - edge(n)).collect();
        let mut random = Pcg64Mcg::seed_from_u64(seed);
        // 53 random bits to a uniform number in [0, 1).
        let phases = (0..count)
            .map(|_| std::f64::consts::TAU * ((random.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)))
            .collect();
        let angular = frequencies.iter().map(|f| std::f64::consts::TAU * f).collect();
        Ok(Self { spectrum: Some(spectrum), frequencies, angular, widths, phases })
    }

    /// Whether there are no gusts (a steady wind).
    pub fn is_steady(&self) -> bool {
        self.spectrum.is_none()
    }

    /// The realised frequencies \[Hz].
    pub fn frequencies(&self) -> &[f64] {
        &self.frequencies
    }

    /// The gusts at height `z` \[m] of a wind `u10` [m/s] at 10 m whose mean there is `mean`.
    pub fn at(&self, z: f64, u10: f64, mean: f64) -> GustPoint {
        let Some(spectrum) = self.spectrum else { return GustPoint::default() };
        if z <= 0.0 {
            // No wind at or below the water: every amplitude 0.
            return GustPoint { amplitudes: vec![0.0; self.frequencies.len()] };
        }
        let amplitudes = self
            .frequencies
            .iter()
            .zip(&self.widths)
            .map(|(&f, &width)| (2.0 * spectrum.density(f, z, u10, mean) * width).sqrt())
            .collect();
        GustPoint { amplitudes }
    }

    /// `u(t)` [m/s] at `point` and `time` \[s], before the ramp.
    pub fn speed(&self, point: &GustPoint, time: f64) -> f64 {
        self.speeds(&[point], time)[0]
    }

    /// `u(t)` [m/s] at each of `points` (a body's windage and rotor) at `time` \[s], before the
    /// ramp: each component's cosine once for all of them.
    pub fn speeds<const N: usize>(&self, points: &[&GustPoint; N], time: f64) -> [f64; N] {
        let mut speeds = [0.0; N];
        for (n, (w, phi)) in self.angular.iter().zip(&self.phases).enumerate() {
            let c = (w * time + phi).cos();
            for (speed, point) in speeds.iter_mut().zip(points) {
                *speed += point.amplitudes[n] * c;
            }
        }
        speeds
    }
}

/// The gusts' amplitudes at one point [m/s], one per component of the [`Gusts`] that made it
/// (none for a steady wind).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GustPoint {
    amplitudes: Vec<f64>,
}

impl GustPoint {
    /// `Σ a_n²/2` [(m/s)²]: the realised variance.
    pub fn variance(&self) -> f64 {
        self.amplitudes.iter().map(|a| 0.5 * a * a).sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn npd(seed: u64) -> Gusts {
        Gusts::new(&GustSpec::Npd { seed, components: 400 }).expect("valid")
    }

    /// `∫ S df` over `[a, b]` by Simpson's rule in log f (`S f d ln f`), fine enough to be exact
    /// to 1e-6 for these smooth spectra.
    fn integral(spectrum: GustSpectrum, (a, b): (f64, f64), z: f64, u10: f64, mean: f64) -> f64 {
        let n = 20_000;
        let (la, lb) = (a.ln(), b.ln());
        let h = (lb - la) / n as f64;
        (0..=n)
            .map(|i| {
                let f = (la + i as f64 * h).exp();
                let weight = if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                weight * spectrum.density(f, z, u10, mean) * f
            })
            .sum::<f64>()
            * h
            / 3.0
    }

    /// The realised variance is the band's integral of the formula within 0.5 %.
    #[test]
    fn the_realised_variance_is_the_spectrum_integrated_over_the_band() {
        let point = npd(3).at(10.0, 20.0, 20.0);
        let band = integral(GustSpectrum::Npd, BAND, 10.0, 20.0, 20.0);
        assert!((point.variance() / band - 1.0).abs() < 5e-3, "{} against {band}", point.variance());
    }

    /// NPD's variance over the band against its integral to 0 and to 100 Hz.
    #[test]
    fn the_band_holds_most_of_the_npd_variance() {
        let band = integral(GustSpectrum::Npd, BAND, 10.0, 20.0, 20.0);
        let whole = integral(GustSpectrum::Npd, (1e-9, 1e2), 10.0, 20.0, 20.0);
        let share = band / whole;
        assert!((0.885..0.905).contains(&share), "the band holds {share} of the variance");
    }

    #[test]
    fn the_same_seed_gives_the_same_gusts_bit_for_bit() {
        let speed = |seed| {
            let gusts = npd(seed);
            gusts.speed(&gusts.at(10.0, 20.0, 20.0), 123.4)
        };
        assert_eq!(speed(7).to_bits(), speed(7).to_bits());
        assert_ne!(speed(7), speed(8));
    }

    /// Two points at once are each point alone.
    #[test]
    fn the_speeds_of_two_points_are_each_points() {
        let gusts = npd(2);
        let (low, high) = (gusts.at(10.0, 20.0, 20.0), gusts.at(90.0, 20.0, 25.0));
        let [a, b] = gusts.speeds(&[&low, &high], 55.5);
        assert_eq!((a, b), (gusts.speed(&low, 55.5), gusts.speed(&high, 55.5)));
        assert!(a != b);
    }

    #[test]
    fn bad_gusts_are_refused() {
        let error = Gusts::new(&GustSpec::Npd { seed: 1, components: 0 }).expect_err("none");
        assert_eq!(error.to_string(), "components must be 1 to 2000, got 0");
        let kaimal = GustSpec::Kaimal { intensity: -0.1, length_scale: 340.2, seed: 1, components: 10 };
        assert_eq!(Gusts::new(&kaimal).expect_err("negative").to_string(), "Kaimal's intensity must be > 0, got -0.1");
    }
}
