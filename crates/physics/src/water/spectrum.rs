//! An irregular sea from a JONSWAP spectrum (PHYSICS.md §6, Airy waves).
//!
//! `S(ω) = α g² ω⁻⁵ exp(−1.25 (ω_p/ω)⁴) γ^r` [m²·s], `r = exp(−(ω − ω_p)²/(2 σ² ω_p²))`,
//! σ = 0.07 for ω ≤ ω_p and 0.09 above, `ω_p = 2π/T_p`. The band `[0.6 ω_p, 3 ω_p]` (beyond it
//! less than 0.2 % of the energy for γ ≥ 1) is sampled by N components on a grid of wave
//! numbers `k_i = (m_0 + i) k_0`, i = 0 … N−1, spanning the band's wave numbers, each with its
//! frequency from the dispersion relation, the amplitude `a_i = √(2 S(ω_i) Δω_i)` over its bin
//! `Δω_i = ω(k_{i+½}) − ω(k_{i−½})`, and a phase drawn uniformly in [0, 2π). α is then set so
//! that the components' `H_s = 4 √m0`, `m0 = Σ a_i²/2`, is the one asked for, exactly.
//! The grid makes the sea harmonic in space (every component a power of the first,
//! [`super::waves`]), which makes a vertex's pressure cost two complex products per component
//! instead of a sine, a cosine and an exponential: the sea then repeats every `2π/k_0` along
//! its heading (about twice the longest component's wavelength: 5.6 peak wavelengths for
//! N = 50 in deep water), and never in time (the frequencies are not commensurate).
//! The phases come from PCG-64 (MCG variant) seeded from the scene's seed: the same seed gives
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
    /// `H_s` \[m].
    pub significant_height: f64,
    /// `T_p` \[s].
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

    /// `count` components heading `heading` \[rad] from `seed`, over water of depth `depth` \[m]
    /// (`None`: deep).
    pub fn components(
        &self,
        count: usize,
        heading: f64,
        seed: u64,
        depth: Option<f64>,
        gravity: f64,
    ) -> Vec<WaveComponent> {
        let peak = std::f64::consts::TAU / self.peak_period;
        let (low, high) = (wave_number(BAND.0 * peak, depth, gravity), wave_number(BAND.1 * peak, depth, gravity));
        // The grid's first multiple m_0 ≥ 1 nearest the band's low end, its last at the high end.
        let span = (high - low) / (count.max(2) - 1) as f64;
        let first = (low / span).round().max(1.0);
        let base = high / (first + (count - 1) as f64);
        let frequency = |k: f64| (gravity * k * depth.map_or(1.0, |h| (k * h).tanh())).sqrt();
        let mut random = Pcg64Mcg::seed_from_u64(seed);
        // 53 random bits to a uniform number in [0, 1).
        let mut uniform = move || (random.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64);
        let mut components: Vec<WaveComponent> = (0..count)
            .map(|i| {
                let m = first + i as f64;
                let omega = frequency(m * base);
                let width = frequency((m + 0.5) * base) - frequency((m - 0.5) * base);
                let amplitude = (2.0 * self.shape(omega, gravity) * width).sqrt();
                WaveComponent {
                    amplitude,
                    frequency: omega,
                    wave_number: m * base,
                    heading,
                    phase: std::f64::consts::TAU * uniform(),
                }
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
        // The spectral density a²/(2Δω) peaks at ω_p, within the bin width there (Δω ≈ ω_p/90 at
        // 200 components).
        let density =
            |i: usize| components[i].amplitude.powi(2) / (components[i + 1].frequency - components[i - 1].frequency);
        let peak = (1..199).max_by(|&a, &b| density(a).total_cmp(&density(b))).expect("200 components");
        let omega_p = std::f64::consts::TAU / 9.0;
        assert!((components[peak].frequency - omega_p).abs() < omega_p / 60.0, "{:?}", components[peak]);
        assert!(crate::water::waves::Sea::new(components.clone(), 0.0, None).is_harmonic());
        assert!(components.iter().all(|c| c.phase >= 0.0 && c.phase < std::f64::consts::TAU && c.heading == 0.5));
    }

    #[test]
    fn the_same_seed_gives_the_same_sea_bit_for_bit_and_another_seed_another() {
        let sea = Jonswap { significant_height: 2.0, peak_period: 8.0, gamma: 1.0 };
        let a = sea.components(50, 0.0, 42, Some(30.0), G);
        assert_eq!(a, sea.components(50, 0.0, 42, Some(30.0), G));
        assert_ne!(a, sea.components(50, 0.0, 43, Some(30.0), G));
        // The phases are the generator's first draws whatever the number of components.
        assert_eq!(a[0].phase.to_bits(), sea.components(3, 0.0, 42, Some(30.0), G)[0].phase.to_bits());
    }
}
