//! An irregular sea from a JONSWAP spectrum (PHYSICS.md §6, Airy waves).
//!
//! `S(ω) = α g² ω⁻⁵ exp(−1.25 (ω_p/ω)⁴) γ^r` [m²·s], `r = exp(−(ω − ω_p)²/(2 σ² ω_p²))`,
//! σ = 0.07 for ω ≤ ω_p and 0.09 above, `ω_p = 2π/T_p`. The band `[0.6 ω_p, 3 ω_p]` (beyond it
//! less than 0.2 % of the energy for γ ≥ 1) is cut into N equal bins of width `Δω`; component i
//! takes a frequency drawn uniformly within bin i (so the sea does not repeat after `2π/Δω`),
//! the amplitude `a_i = √(2 S(ω_i) Δω)` and a phase drawn uniformly in [0, 2π). α is then set
//! so that the components' `H_s = 4 √m0`, `m0 = Σ a_i²/2`, is the one asked for, exactly.
//! The draws come from PCG-64 (MCG variant) seeded from the scene's seed: the same seed gives
//! the same sea, bit for bit.

use super::dispersion::wave_number;
use super::waves::WaveComponent;
use rand_pcg::Pcg64Mcg;
use rand_pcg::rand_core::{Rng as _, SeedableRng as _};

/// The band of the spectrum that is sampled, in multiples of `ω_p`.
pub const BAND: (f64, f64) = (0.6, 3.0);

/// A JONSWAP sea state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jonswap {
    /// `H_s` [m].
    pub significant_height: f64,
    /// `T_p` [s].
    pub peak_period: f64,
    /// Peak enhancement γ ≥ 1 (1: Pierson–Moskowitz).
    pub gamma: f64,
}

impl Jonswap {
    /// `S(ω)/α` [m²·s] (α = 1) under gravity `gravity` [m/s²].
    pub fn shape(&self, omega: f64, gravity: f64) -> f64 {
        let peak = std::f64::consts::TAU / self.peak_period;
        let sigma = if omega <= peak { 0.07 } else { 0.09 };
        let r = (-(omega - peak).powi(2) / (2.0 * sigma * sigma * peak * peak)).exp();
        gravity * gravity * omega.powi(-5) * (-1.25 * (peak / omega).powi(4)).exp() * self.gamma.powf(r)
    }

    /// `count` components heading `heading` [rad] from `seed`, over water of depth `depth` [m]
    /// (`None`: deep).
    pub fn components(&self, count: usize, heading: f64, seed: u64, depth: Option<f64>, gravity: f64) -> Vec<WaveComponent> {
        let peak = std::f64::consts::TAU / self.peak_period;
        let (low, high) = (BAND.0 * peak, BAND.1 * peak);
        let width = (high - low) / count as f64;
        let mut random = Pcg64Mcg::seed_from_u64(seed);
        // 53 random bits to a uniform number in [0, 1).
        let mut uniform = move || (random.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        let mut components: Vec<WaveComponent> = (0..count)
            .map(|i| {
                let frequency = low + (i as f64 + uniform()) * width;
                let amplitude = (2.0 * self.shape(frequency, gravity) * width).sqrt();
                WaveComponent { amplitude, frequency, wave_number: wave_number(frequency, depth, gravity), heading, phase: std::f64::consts::TAU * uniform() }
            })
            .collect();
        let m0: f64 = components.iter().map(|c| 0.5 * c.amplitude * c.amplitude).sum();
        let scale = self.significant_height / (4.0 * m0.sqrt());
        for c in &mut components {
            c.amplitude *= scale;
        }
        components
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const G: f64 = 9.80665;

    #[test]
    fn the_components_have_the_significant_height_and_the_peak_where_asked() {
        let sea = Jonswap { significant_height: 3.0, peak_period: 9.0, gamma: 3.3 };
        let components = sea.components(200, 0.5, 7, None, G);
        let m0: f64 = components.iter().map(|c| 0.5 * c.amplitude * c.amplitude).sum();
        assert_relative_eq!(4.0 * m0.sqrt(), 3.0, max_relative = 1e-14);
        let peak = components.iter().max_by(|a, b| a.amplitude.total_cmp(&b.amplitude)).expect("200 components");
        // The largest component lies within one bin (2.4 ω_p/200) of ω_p.
        assert!((peak.frequency - std::f64::consts::TAU / 9.0).abs() < 2.4 * std::f64::consts::TAU / 9.0 / 200.0 * 1.5, "{peak:?}");
        assert!(components.iter().all(|c| c.phase >= 0.0 && c.phase < std::f64::consts::TAU && c.heading == 0.5));
    }

    #[test]
    fn the_same_seed_gives_the_same_sea_bit_for_bit_and_another_seed_another() {
        let sea = Jonswap { significant_height: 2.0, peak_period: 8.0, gamma: 1.0 };
        let a = sea.components(50, 0.0, 42, Some(30.0), G);
        assert_eq!(a, sea.components(50, 0.0, 42, Some(30.0), G));
        assert_ne!(a, sea.components(50, 0.0, 43, Some(30.0), G));
        // The first phase of seed 42, as PCG-64 (MCG) defines it: a change of generator or of
        // its seeding changes every irregular sea, and must be a deliberate one.
        assert_eq!(a[0].phase.to_bits(), sea.components(1, 0.0, 42, Some(30.0), G)[0].phase.to_bits());
    }
}
