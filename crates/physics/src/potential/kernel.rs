//! The radiation kernel (PHYSICS.md §9, Cummins' equation): `K(t) = (2/π) ∫₀^∞ B(ω) cos(ωt) dω`
//! [kg/s², kg·m/s², kg·m²/s² per pair], with `B` linear between its frequencies, sampled at a
//! uniform step over `[0, t_K]`; and the same kernel from the added mass,
//! `K(t) = −(2/π) ∫₀^∞ ω (A(ω) − A∞) sin(ωt) dω`, the check that a file's `A` and `B` agree.
//!
//! Each linear piece is integrated in closed form, so the kernel of a table carries no
//! quadrature error: on a piece of half-width `h` about `ω_m`, with `y = y_m + s u`,
//! `∫_{−h}^{h} y cos((ω_m + u)t) du = 2h [y_m cos(ω_m t) sinc(ht) − s h sin(ω_m t) g(ht)]` and
//! `∫_{−h}^{h} y sin((ω_m + u)t) du = 2h [y_m sin(ω_m t) sinc(ht) + s h cos(ω_m t) g(ht)]`, with
//! `sinc x = sin x / x` and `g(x) = (sin x − x cos x)/x²`, both by their series near 0.

use super::coefficients::{Coefficients, Matrix6};
use nalgebra::Complex;
use std::f64::consts::PI;

/// `sin x / x`, by its series for small `|x|` (where the quotient loses digits).
fn sinc(x: f64) -> f64 {
    if x.abs() < 1e-3 {
        let x2 = x * x;
        1.0 - x2 / 6.0 * (1.0 - x2 / 20.0)
    } else {
        x.sin() / x
    }
}

/// `(sin x − x cos x)/x²`, by its series `x/3 − x³/30 + x⁵/840` for small `|x|`.
fn sine_moment(x: f64) -> f64 {
    if x.abs() < 1e-2 {
        let x2 = x * x;
        x * (1.0 / 3.0 - x2 * (1.0 / 30.0 - x2 / 840.0))
    } else {
        (x.sin() - x * x.cos()) / (x * x)
    }
}

/// Which trigonometric weight a transform integrates against.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Weight {
    Cosine,
    Sine,
}

/// `∫ y(ω) w(ωt) dω` over the table's range, `y` linear between the points `(omega, y)`.
fn transform(omega: &[f64], y: &[f64], t: f64, weight: Weight) -> f64 {
    omega
        .windows(2)
        .zip(y.windows(2))
        .map(|(w, v)| {
            let h = 0.5 * (w[1] - w[0]);
            let (mid, y_mid, slope) = (0.5 * (w[0] + w[1]), 0.5 * (v[0] + v[1]), (v[1] - v[0]) / (w[1] - w[0]));
            let (s, c) = (mid * t).sin_cos();
            let x = h * t;
            2.0 * h
                * match weight {
                    Weight::Cosine => y_mid * c * sinc(x) - slope * h * s * sine_moment(x),
                    Weight::Sine => y_mid * s * sinc(x) + slope * h * c * sine_moment(x),
                }
        })
        .sum()
}

/// `K(t) = (2/π) ∫ B(ω) cos(ωt) dω` [per the pair's unit] of one pair's damping table: `B`
/// linear between the points `(omega, damping)` and taken as nothing outside them.
pub fn kernel_from_damping(omega: &[f64], damping: &[f64], t: f64) -> f64 {
    2.0 / PI * transform(omega, damping, t, Weight::Cosine)
}

/// `K(t) = −(2/π) ∫ ω (A(ω) − A∞) sin(ωt) dω` of one pair, `ω (A − A∞)` linear between the
/// points `(omega, added_mass)` and taken as nothing outside them.
pub fn kernel_from_added_mass(omega: &[f64], added_mass: &[f64], infinite: f64, t: f64) -> f64 {
    let y: Vec<f64> = omega.iter().zip(added_mass).map(|(w, a)| w * (a - infinite)).collect();
    -2.0 / PI * transform(omega, &y, t, Weight::Sine)
}

/// `A(ω) = A∞ − (1/ω) ∫₀^{t_K} K(t) sin(ωt) dt` (Ogilvie 1964) at `omega` > 0 \[rad/s], `K` linear
/// between its samples: the added mass the kernel of the damping implies, to set beside the
/// file's (the check of PHYSICS.md §9 that needs no tail of `A` beyond its last frequency).
pub fn added_mass_from_kernel(kernel: &SampledKernel, infinite: &Matrix6, omega: f64) -> Matrix6 {
    let times: Vec<f64> = (0..kernel.values.len()).map(|n| n as f64 * kernel.step).collect();
    Matrix6::from_fn(|i, j| {
        let k: Vec<f64> = kernel.values.iter().map(|m| m[(i, j)]).collect();
        infinite[(i, j)] - transform(&times, &k, omega, Weight::Sine) / omega
    })
}

/// A body's kernel matrices `K(t_n)` at `t_n = n Δt`, `n = 0 … ⌊t_K/Δt⌋`.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledKernel {
    step: f64,
    values: Vec<Matrix6>,
}

impl SampledKernel {
    /// The kernel of `coefficients`' damping, `B(0) = 0` prepended (PHYSICS.md §9), at step
    /// `step` \[s] over `[0, duration]` \[s]. Both must be > 0 (the caller's settings check them).
    pub fn from_damping(coefficients: &Coefficients, step: f64, duration: f64) -> Self {
        let omega: Vec<f64> = std::iter::once(0.0).chain(coefficients.frequencies().iter().copied()).collect();
        Self::sample(step, duration, |t| {
            Matrix6::from_fn(|i, j| {
                let b: Vec<f64> =
                    std::iter::once(0.0).chain(coefficients.damping().iter().map(|m| m[(i, j)])).collect();
                kernel_from_damping(&omega, &b, t)
            })
        })
    }

    /// The kernel of `coefficients`' added mass (the cross-check), `A(0)` prepended at ω = 0.
    pub fn from_added_mass(coefficients: &Coefficients, step: f64, duration: f64) -> Self {
        let omega: Vec<f64> = std::iter::once(0.0).chain(coefficients.frequencies().iter().copied()).collect();
        let infinite = coefficients.added_mass_infinite();
        Self::sample(step, duration, |t| {
            Matrix6::from_fn(|i, j| {
                let a: Vec<f64> = std::iter::once(coefficients.added_mass_zero()[(i, j)])
                    .chain(coefficients.added_mass().iter().map(|m| m[(i, j)]))
                    .collect();
                kernel_from_added_mass(&omega, &a, infinite[(i, j)], t)
            })
        })
    }

    /// Samples `kernel` at `n Δt` over `[0, duration]`.
    pub fn sample(step: f64, duration: f64, kernel: impl Fn(f64) -> Matrix6) -> Self {
        // A count of steps of a finite duration: `as` saturates, and the caller's settings bound it.
        let count = (duration / step).floor() as usize + 1;
        Self { step, values: (0..count).map(|n| kernel(n as f64 * step)).collect() }
    }

    /// `K(t)` linear between the samples, 0 beyond the last (the truncation `t_K`) and for t < 0.
    pub fn at(&self, t: f64) -> Matrix6 {
        let position = t / self.step;
        if !(position >= 0.0) || position > (self.values.len() - 1) as f64 {
            return Matrix6::zeros();
        }
        // 0 ≤ position ≤ len − 1 here: the cast is in range.
        let below = (position.floor() as usize).min(self.values.len() - 1);
        let Some(above) = self.values.get(below + 1) else { return self.values[below] };
        let s = position - below as f64;
        self.values[below] * (1.0 - s) + above * s
    }

    /// The truncation `t_K` \[s]: the time of the last sample.
    pub fn duration(&self) -> f64 {
        (self.values.len() - 1) as f64 * self.step
    }

    /// The sampling step Δt \[s].
    pub fn step(&self) -> f64 {
        self.step
    }
    /// `K(n Δt)`, `n = 0, 1, …`.
    pub fn values(&self) -> &[Matrix6] {
        &self.values
    }
    /// One pair's samples `K_ij(n Δt)`.
    pub fn pair(&self, i: usize, j: usize) -> Vec<f64> {
        self.values.iter().map(|k| k[(i, j)]).collect()
    }
    /// `|K_ii(t_K)| / max_t |K_ii(t)|` per degree of freedom (0 where the kernel is nothing):
    /// how much of the memory the truncation at `t_K` cuts off (PHYSICS.md §9: warn when not
    /// small).
    pub fn truncation(&self) -> [f64; 6] {
        let (peaks, last) = (self.peaks(), self.values.last().copied().unwrap_or_else(Matrix6::zeros));
        std::array::from_fn(|i| if peaks[(i, i)] > 0.0 { last[(i, i)].abs() / peaks[(i, i)] } else { 0.0 })
    }

    /// `max_{t ≥ from} |K_ii(t) − K'_ii(t)| / max_t |K_ii(t)|` per degree of freedom against
    /// `other` sampled alike (0 where this kernel is nothing): the check of a file's `A` against
    /// its `B` (PHYSICS.md §9). The kernel from `A` misses its value near `t = 0`, which lies in
    /// the tail of `ω (A − A∞)` beyond the last frequency: `from` \[s] leaves that out.
    pub fn disagreement(&self, other: &Self, from: f64) -> [f64; 6] {
        let peaks = self.peaks();
        let skip = (from / self.step).ceil() as usize;
        std::array::from_fn(|i| {
            let pairs = self.values.iter().zip(&other.values).skip(skip);
            let worst = pairs.map(|(a, b)| (a[(i, i)] - b[(i, i)]).abs()).fold(0.0, f64::max);
            if peaks[(i, i)] > 0.0 { worst / peaks[(i, i)] } else { 0.0 }
        })
    }

    /// `K_ij(iω) = ∫₀^{t_K} K_ij(t) e^{−iωt} dt` of one pair at each of `omegas` \[rad/s], `K`
    /// linear between its samples: `B(ω) + iω (A(ω) − A∞)` of the truncated kernel (Ogilvie's
    /// relations), what the state space is fitted to.
    pub fn spectrum(&self, i: usize, j: usize, omegas: &[f64]) -> Vec<Complex<f64>> {
        let times: Vec<f64> = (0..self.values.len()).map(|n| n as f64 * self.step).collect();
        let k = self.pair(i, j);
        omegas
            .iter()
            .map(|&w| Complex::new(transform(&times, &k, w, Weight::Cosine), -transform(&times, &k, w, Weight::Sine)))
            .collect()
    }

    /// The largest `|K_ij(t)|` over the samples, per pair.
    pub fn peaks(&self) -> Matrix6 {
        self.values.iter().fold(Matrix6::zeros(), |peak, k| peak.zip_map(k, |p, v| p.max(v.abs())))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn truncation_and_disagreement_are_relative_to_the_peak() {
        let kernel = SampledKernel::sample(1.0, 4.0, |t| Matrix6::identity() * (8.0 - t));
        let other = SampledKernel::sample(1.0, 4.0, |t| Matrix6::identity() * (8.0 - t + 0.1 * t));
        assert_eq!(kernel.truncation()[2], 0.5);
        assert!((kernel.disagreement(&other, 0.0)[0] - 0.05).abs() < 1e-15);
        assert!((kernel.disagreement(&other, 4.0)[0] - 0.05).abs() < 1e-15);
        assert!((kernel.disagreement(&other, 1.0)[0] - 0.05).abs() < 1e-15);
        let nothing = SampledKernel::sample(1.0, 4.0, |_| Matrix6::zeros());
        assert_eq!((nothing.truncation()[5], nothing.disagreement(&kernel, 0.0)[5]), (0.0, 0.0));
    }

    /// A linear piece against its transform by a fine midpoint rule.
    #[test]
    fn one_piece_matches_a_fine_quadrature_for_small_and_large_t() {
        let (omega, y) = ([0.3, 1.7], [2.0, -0.5]);
        for t in [0.0, 1e-4, 0.01, 0.7, 5.0, 40.0] {
            let n = 200_000;
            let h = (omega[1] - omega[0]) / n as f64;
            let (mut cos, mut sin) = (0.0, 0.0);
            for k in 0..n {
                let w = omega[0] + (k as f64 + 0.5) * h;
                let v = y[0] + (y[1] - y[0]) * (w - omega[0]) / (omega[1] - omega[0]);
                cos += v * (w * t).cos() * h;
                sin += v * (w * t).sin() * h;
            }
            let exact_cos = transform(&omega, &y, t, Weight::Cosine);
            let exact_sin = transform(&omega, &y, t, Weight::Sine);
            assert!((exact_cos - cos).abs() < 1e-9, "t = {t}: {exact_cos} against {cos}");
            assert!((exact_sin - sin).abs() < 1e-9, "t = {t}: {exact_sin} against {sin}");
        }
    }
}
