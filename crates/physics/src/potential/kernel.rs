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

/// The band over which `A∞` is made consistent with the kernel: the file's frequencies
/// `0 < ω_k ≤ 0.8 ω_max` (PHYSICS.md §9, "A∞ consistent with the band"). Near `ω_max` the
/// kernel's added mass bends away from the file's, `B` being cut to nothing there (the Hilbert
/// transform of a step), which no constant corrects.
pub const CONSISTENT_BAND: f64 = 0.8;

/// `A∞` made consistent with the file's `A(ω)` and the kernel the time domain uses (PHYSICS.md
/// §9, "A∞ consistent with the band"), and Ogilvie's check before and after.
#[derive(Debug, Clone, PartialEq)]
pub struct BandConsistency {
    /// `A∞_eff` [kg, kg·m, kg·m²] about the reference point.
    pub infinite: Matrix6,
    /// `max_{ω_k ≤ 0.8 ω_max} |A_K(ω_k) − A(ω_k)| / max_k |A(ω_k) − A∞|` per pair with the file's
    /// `A∞` in `A_K` (the time domain's added mass before the shift); 0 for a pair the kernel has
    /// not ([`SampledKernel::significant_pairs`]) or whose `A` does not vary.
    pub misfit_file: Matrix6,
    /// The same with `A∞_eff` in `A_K`.
    pub misfit_consistent: Matrix6,
}

impl BandConsistency {
    /// `max_j |A∞_eff,ij − A∞_ij| / √|A∞_ii A∞_jj|` per degree of freedom, against the file's `A∞`
    /// `file`: the largest relative change, couplings included (0 where the file's diagonal is 0).
    pub fn relative_shift(&self, file: &Matrix6) -> [f64; 6] {
        std::array::from_fn(|i| {
            (0..6)
                .map(|j| {
                    let scale = (file[(i, i)] * file[(j, j)]).abs().sqrt();
                    let change = (self.infinite[(i, j)] - file[(i, j)]).abs();
                    if scale > 0.0 { change / scale } else { 0.0 }
                })
                .fold(0.0, f64::max)
        })
    }
}

/// `A∞_eff` (Ogilvie 1964, Kramers–Kronig): the kernel the time domain uses has `B` from the file
/// up to `ω_max` and nothing beyond, so its added mass `A_K(ω) = A∞ − (1/ω) ∫₀^{t_K} K(t) sin(ωt) dt`
/// falls short of the file's `A(ω)` by the omitted tail `(2/π) ∫_{ω_max}^∞ B(ω′)/(ω′² − ω²) dω′`,
/// nearly constant well below `ω_max`. The infinite-frequency added mass that makes the kernel
/// give the file's `A(ω)` over the band is
/// `A∞_eff,ij = mean_{0 < ω_k ≤ 0.8 ω_max} [A_ij(ω_k) + (1/ω_k) ∫₀^{t_K} K_ij(t) sin(ω_k t) dt]`,
/// symmetrised (`½ (Δ + Δᵀ)` of the shift `Δ = A∞_eff − A∞`). Pairs the kernel has not (no
/// damping in the band, or the panel code's noise: [`SampledKernel::significant_pairs`]) keep
/// the file's `A∞`, as they do when no frequency lies in the band.
pub fn consistent_with_band(coefficients: &Coefficients, kernel: &SampledKernel) -> BandConsistency {
    let file = *coefficients.added_mass_infinite();
    let top = CONSISTENT_BAND * coefficients.highest_frequency();
    // `A(ω_k)` and `(1/ω_k) ∫ K sin(ω_k t) dt` at each frequency of the band.
    let band: Vec<(Matrix6, Matrix6)> = coefficients
        .frequencies()
        .iter()
        .zip(coefficients.added_mass())
        .filter(|(w, _)| **w > 0.0 && **w <= top)
        .map(|(&w, a)| (*a, -added_mass_from_kernel(kernel, &Matrix6::zeros(), w)))
        .collect();
    let significant = kernel.significant_pairs();
    let mut shift = Matrix6::zeros();
    if !band.is_empty() {
        let mean = band.iter().fold(Matrix6::zeros(), |sum, (a, s)| sum + a + s) / band.len() as f64;
        shift = Matrix6::from_fn(|i, j| if significant[i][j] { mean[(i, j)] - file[(i, j)] } else { 0.0 });
        shift = (shift + shift.transpose()) * 0.5;
    }
    let infinite = file + shift;
    // The spread of `A − A∞` over all the file's frequencies, per pair: the misfit's scale.
    let span = coefficients
        .added_mass()
        .iter()
        .fold(Matrix6::zeros(), |span, a| span.zip_map(&(a - file), |m, d| m.max(d.abs())));
    let misfit = |infinite: &Matrix6| {
        let worst = band
            .iter()
            .fold(Matrix6::zeros(), |worst, (a, s)| worst.zip_map(&(infinite - s - a), |m, d| m.max(d.abs())));
        let relative = |i: usize, j: usize| {
            if significant[i][j] && span[(i, j)] > 0.0 { worst[(i, j)] / span[(i, j)] } else { 0.0 }
        };
        Matrix6::from_fn(relative)
    };
    BandConsistency { misfit_file: misfit(&file), misfit_consistent: misfit(&infinite), infinite }
}

/// A diagonal term of the kernel peaking below this fraction of the largest of its kind
/// (translations, rotations) is the panel code's numerical noise rather than a kernel: an
/// axisymmetric body's yaw.
pub const NEGLIGIBLE_DIAGONAL: f64 = 1e-3;

/// A pair peaking below this fraction of `√(peak_ii peak_jj)` of its kept diagonal terms is
/// noise too: the cylinder's surge–sway pair (2e-5 of its diagonal's), the moored buoy's
/// heave–roll pair (4e-3: its mesh's small asymmetry in the panel code's solve), which no
/// order fits, being no sum of modes. A real coupling this weak moves the response by less
/// than it.
pub const NEGLIGIBLE_PAIR: f64 = 1e-2;

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

    /// The pairs that are kernels rather than the panel code's noise: a diagonal term peaking
    /// above [`NEGLIGIBLE_DIAGONAL`] of the largest of its kind, a pair above [`NEGLIGIBLE_PAIR`]
    /// of `√(peak_ii peak_jj)` of two such terms. What the state space fits and `A∞_eff` shifts.
    pub fn significant_pairs(&self) -> [[bool; 6]; 6] {
        let peaks = self.peaks();
        let largest = |dof: usize| {
            let kind = if dof < 3 { 0..3 } else { 3..6 };
            kind.map(|k| peaks[(k, k)]).fold(0.0, f64::max)
        };
        let diagonal: [f64; 6] =
            std::array::from_fn(|i| if peaks[(i, i)] > NEGLIGIBLE_DIAGONAL * largest(i) { peaks[(i, i)] } else { 0.0 });
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let scale = (diagonal[i] * diagonal[j]).sqrt();
                scale > 0.0 && peaks[(i, j)] > NEGLIGIBLE_PAIR * scale
            })
        })
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

    /// A file whose `A(ω)` is exactly what the kernel of its `B` implies for an `A∞` (Ogilvie's
    /// relation), but whose own ω = ∞ block is off by `δ` in surge, pitch and their coupling, as a
    /// tail of `B` beyond the last frequency makes it: `A∞_eff` is that `A∞` again to round-off,
    /// symmetric, the misfit with it nothing and with the file's `δ / max|A − A∞|`; yaw, with added
    /// mass but no damping, keeps the file's `A∞`; and the relative shift is `δ` over the diagonal.
    #[test]
    fn the_band_consistent_infinite_added_mass_is_the_one_the_kernel_implies() {
        use crate::potential::coefficients::{CoefficientsData, ComplexVector6, Excitation, Vector6};
        let frequencies: Vec<f64> = (1..=30).map(|k| 0.1 * f64::from(k)).collect();
        let scale = Vector6::new(3.0e4, 3.0e4, 2.0e4, 8.0e4, 8.0e4, 0.0);
        let damping_at = |w: f64| {
            let shape = w * w * (-w * w).exp();
            let mut b = Matrix6::from_diagonal(&(scale * shape));
            (b[(0, 4)], b[(4, 0)]) = (2.0e4 * shape, 2.0e4 * shape);
            b
        };
        let truth = Matrix6::from_diagonal(&Vector6::new(5.0e3, 5.0e3, 9.0e3, 2.0e4, 2.0e4, 50.0));
        let damping: Vec<Matrix6> = frequencies.iter().map(|&w| damping_at(w)).collect();
        let with = |added_mass: Vec<Matrix6>, infinite: Matrix6| {
            Coefficients::new(CoefficientsData {
                frequencies: frequencies.clone(),
                added_mass,
                damping: damping.clone(),
                added_mass_infinite: infinite,
                // A(0) − A∞ = (2/π) ∫ B/ω² dω = b/√π for this B; yaw's A(0) apart from its A∞.
                added_mass_zero: truth
                    + Matrix6::from_diagonal(&(scale / PI.sqrt() + Vector6::new(0.0, 0.0, 0.0, 0.0, 0.0, 100.0))),
                excitation: Excitation {
                    frequencies: vec![1.0],
                    headings: vec![0.0],
                    values: vec![ComplexVector6::zeros()],
                },
                hydrostatic_stiffness: None,
                mean_drift: None,
            })
            .expect("valid data")
        };
        let kernel = SampledKernel::from_damping(&with(vec![truth; 30], truth), 0.05, 40.0);
        let added_mass: Vec<Matrix6> =
            frequencies.iter().map(|&w| added_mass_from_kernel(&kernel, &truth, w)).collect();
        let mut offset = Matrix6::zeros();
        (offset[(0, 0)], offset[(4, 4)], offset[(0, 4)], offset[(4, 0)], offset[(5, 5)]) =
            (80.0, 300.0, 120.0, 120.0, 5.0);
        let file = with(added_mass.clone(), truth - offset);
        let consistency = consistent_with_band(&file, &kernel);
        let mut expected = truth;
        expected[(5, 5)] -= offset[(5, 5)];
        println!("A∞_eff − A∞ (true): {:.3e}", (consistency.infinite - expected).abs().max());
        assert!((consistency.infinite - expected).abs().max() < 1e-9 * truth.abs().max(), "{}", consistency.infinite);
        assert_eq!(consistency.infinite, consistency.infinite.transpose());
        let span = |i: usize, j: usize| {
            added_mass.iter().map(|a| (a[(i, j)] - file.added_mass_infinite()[(i, j)]).abs()).fold(0.0, f64::max)
        };
        for (i, j) in [(0, 0), (4, 4), (0, 4), (2, 2)] {
            assert!(consistency.misfit_consistent[(i, j)] < 1e-9, "({i}, {j}): {}", consistency.misfit_consistent);
            let before = offset[(i, j)] / span(i, j);
            assert!((consistency.misfit_file[(i, j)] - before).abs() < 1e-9, "({i}, {j}): {}", consistency.misfit_file);
        }
        assert_eq!((consistency.misfit_file[(5, 5)], consistency.misfit_file[(1, 2)]), (0.0, 0.0));
        let shift = consistency.relative_shift(file.added_mass_infinite());
        let diagonal = |i: usize| file.added_mass_infinite()[(i, i)];
        assert!((shift[0] - 80.0 / diagonal(0)).abs() < 1e-12, "{shift:?}");
        assert!((shift[4] - 300.0 / diagonal(4)).abs() < 1e-12 && shift[5] == 0.0 && shift[2] < 1e-12, "{shift:?}");
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
