//! What the data say about the fitted parameters: their covariance, 95 % confidence intervals
//! and correlations from the Jacobian at the optimum, and the directions the data cannot
//! determine (docs/calibration.md, "What the intervals mean").
//!
//! With `m` weighted residuals `r` at the optimum, `n` parameters and the Jacobian `J = ∂r/∂θ`:
//! `σ² = ‖r‖² / (m − n)`, `C = σ² (JᵀJ)⁻¹`, and the interval `θ̂_j ± t₀.₉₇₅,ₘ₋ₙ √C_jj`. The
//! inverse is taken through the SVD of the Jacobian in the unit box (`J_z = U S Vᵀ`, each
//! parameter scaled by its bounds' span, or the span of its logarithm): a direction `v_k` is
//! *undetermined* when its 95 % half-width `t σ / s_k` spans more than the whole box, or `s_k` is
//! below `1e-8 s_max` (rounding), or its half-width moves the parameters by more than
//! [`UNDETERMINED_RELATIVE`] of their values (`‖(t σ / s_k) v_kj (dθ_j/dz_j) / θ_j‖ > 0.5`: the
//! data cannot fix that combination to within a factor of about two, however wide the bounds
//! are). Such directions are left out of the covariance, and every
//! parameter that moves along one (`|v_kj| > 0.05`) gets no interval: the data fix only the
//! combinations orthogonal to it, which the report names.
//!
//! The textbook intervals assume independent residuals. Samples of a time series with white
//! measurement noise are; residuals that are mostly model error are correlated, and would make
//! the intervals too narrow. So `σ²` is widened for the residuals' lag-1 autocorrelation `ρ`
//! (within each signal): an AR(1) series of `m` samples carries the information of
//! `m (1 − ρ)/(1 + ρ)` independent ones, so `σ²` is multiplied by `(1 + ρ)/(1 − ρ)` when `ρ > 0`
//! (capped at `ρ = 0.98`). White noise gives `ρ ≈ 0` and the textbook intervals; the report
//! gives `ρ` and the factor.
//!
//! That widening is not enough when the residual is a smooth, periodic model error (another
//! code's run of a driven system): its correlation does not decay like an AR(1) series' but
//! comes back every period. So a second interval is given beside it, [`Correlated`]: the
//! sandwich covariance `C_c = (JᵀJ)⁻¹ (Jᵀ Ω̂ J) (JᵀJ)⁻¹` with `Ω̂` the residual's own
//! autocovariance within each signal (block-diagonal over the signals, the weights as the fit
//! applies them), `Ω̂_tu = k((t − u)/L_s) γ̂_s(t − u)`, `γ̂_s(l) = m/(m − n) · Σ_t r_t r_{t+l} / m_s`,
//! `k(x) = 1 − |x|` (Bartlett) for `|x| < 1`. It is the covariance `θ̂` would have if the model
//! error were a stationary random process with the residual's autocorrelation, independent of the
//! model's sensitivity `J`. The bandwidth `L_s` must cover the residual's correlation length,
//! which for a periodic error is the whole record: see [`bandwidth`]; it is capped at half the
//! record ([`MAX_BANDWIDTH_FRACTION`]). Each parameter's interval takes Student's t at the
//! estimate's Satterthwaite degrees of freedom ([`Correlated::degrees_of_freedom`]): a wide lag
//! window averages few independent stretches of the record, and its variance is less certain.
//!
//! Why this and not the usual alternatives (checked on the driven chain against MoorDyn's
//! records, docs/calibration.md): a Newey–West/Andrews HAC sandwich over the scores
//! `g_t = J_tᵀ r_t` estimates their long-run variance, the spectral density of `g` at frequency 0
//! — which a periodic error leaves at 0, since `Σ g_t = Jᵀr = 0` at the optimum and the scores
//! are periodic: it gave at most 1.8 × the white-noise width at any bandwidth there (a pairs
//! block bootstrap, resampling `(J_t, r_t)` together, estimates the same quantity, at a refit per
//! draw). Resampling the residual's blocks against the fixed model is, linearised, this
//! estimator, without the refits. With white noise `γ̂(l ≥ 1) ≈ 0`, the bandwidth is 1–3 samples
//! and `C_c` is the textbook covariance. No interval from one record can see the part of a model
//! error that is exactly a change of the parameters: the fit absorbs it and the residual keeps
//! no trace of it.

use nalgebra::{DMatrix, DVector};

/// A parameter moving along an undetermined direction by more than this (of a unit vector)
/// has no interval.
const INVOLVED: f64 = 0.05;

/// Singular values below this fraction of the largest are rounding.
const NUMERICAL_RANK: f64 = 1e-8;

/// A direction whose 95 % half-width changes the parameters by more than this fraction of their
/// values is undetermined.
pub const UNDETERMINED_RELATIVE: f64 = 0.5;

/// A lag at which a signal's residual is still correlated by this much (or by `5/√m_s`, five
/// times the white-noise spread of a series of `m_s` samples, when larger) lies within its
/// correlation length.
pub const CORRELATED: f64 = 0.2;

/// A signal's lag window spans at most this fraction of its samples: beyond it each lag's
/// autocovariance rests on fewer than half the record, and the window's estimate on too few
/// independent stretches of it.
pub const MAX_BANDWIDTH_FRACTION: f64 = 0.5;

/// The intervals for a residual that is correlated model error (the module's doc): the
/// sandwich covariance over the residual's own autocorrelation.
#[derive(Debug, Clone, PartialEq)]
pub struct Correlated {
    /// Each signal's Bartlett bandwidth `L_s` \[samples]: lags `|l| < L_s` enter `Ω̂` with the
    /// weight `1 − |l|/L_s` (1: the residual taken as white).
    pub bandwidths: Vec<f64>,
    /// Each parameter's standard error in its own units, `None` when undetermined.
    pub standard_errors: Vec<Option<f64>>,
    /// Each parameter's Satterthwaite degrees of freedom, `ν_j = (tr B)² / tr B²` with `B` the
    /// quadratic form `rᵀ B r` its variance estimate is (taken for white residuals; at most
    /// `m − n`), and `t₀.₉₇₅,ν_j` (`NaN` for both when undetermined).
    pub degrees_of_freedom: Vec<f64>,
    pub t_quantiles: Vec<f64>,
}

/// The statistics of a fit at its optimum.
#[derive(Debug, Clone, PartialEq)]
pub struct Uncertainty {
    /// Residual variance `σ²` (weighted, widened by `inflation²`), and its degrees of freedom
    /// `m − n`.
    pub variance: f64,
    /// The residuals' lag-1 autocorrelation within each signal, and the factor `σ` was widened
    /// by for it, `√((1 + ρ)/(1 − ρ))` (1 when `ρ ≤ 0`).
    pub autocorrelation: f64,
    pub inflation: f64,
    pub degrees_of_freedom: usize,
    /// `t₀.₉₇₅` for those degrees of freedom.
    pub t_quantile: f64,
    /// Each parameter's standard error in its own units, `None` when undetermined.
    pub standard_errors: Vec<Option<f64>>,
    /// Correlations (`NaN` where either parameter is undetermined).
    pub correlation: DMatrix<f64>,
    /// Directions the data cannot determine: unit vectors over the parameters' relative changes
    /// `δθ_j / θ_j` (or `δθ_j` for a parameter at 0).
    pub undetermined: Vec<Vec<f64>>,
    /// The determined directions' 95 % half-widths in the unit box, largest first.
    pub box_half_widths: Vec<f64>,
    /// The standard errors if the residual is correlated model error, beside the ones above.
    pub correlated: Correlated,
}

/// How a parameter maps to the unit box: `dθ/dz` at the optimum, its value, and the size a
/// change of it is measured against (`|θ|`, or its bounds' span for a θ at or near 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scaling {
    pub value: f64,
    pub derivative: f64,
    pub reference: f64,
}

/// Lag-1 autocorrelation of `residuals`, pairs taken within each of the consecutive series of
/// `lengths` (one series when empty).
pub fn lag1(residuals: &[f64], lengths: &[usize]) -> f64 {
    let (mut product, mut square) = (0.0, 0.0);
    for range in series(residuals.len(), lengths) {
        let r = &residuals[range];
        product += lagged(r, r, 1);
        square += lagged(r, r, 0);
    }
    if square > 0.0 { product / square } else { 0.0 }
}

/// `√((1 + ρ)/(1 − ρ))` for `ρ > 0` (capped at 0.98), else 1: how much wider correlated
/// residuals make `σ`.
pub fn inflation(rho: f64) -> f64 {
    let rho = rho.clamp(0.0, 0.98);
    ((1.0 + rho) / (1.0 - rho)).sqrt()
}

/// The uncertainty of a fit with weighted residuals `residuals` (the consecutive series of
/// `lengths`, one per signal) and Jacobian `jacobian` (`∂r/∂z` in the unit box) at parameters
/// scaled by `scaling`.
pub fn estimate(
    residuals: &DVector<f64>,
    jacobian: &DMatrix<f64>,
    scaling: &[Scaling],
    lengths: &[usize],
) -> Uncertainty {
    let (m, n) = jacobian.shape();
    let degrees_of_freedom = m.saturating_sub(n).max(1);
    let autocorrelation = lag1(residuals.as_slice(), lengths);
    let inflation = inflation(autocorrelation);
    let variance = residuals.norm_squared() / degrees_of_freedom as f64 * inflation * inflation;
    let sigma = variance.sqrt();
    let t = student_t_975(degrees_of_freedom as f64);
    let svd = jacobian.clone().svd(false, true);
    // Computed with `compute_v = true`.
    let v_t = svd.v_t.unwrap_or_else(|| DMatrix::identity(n, n));
    let largest = svd.singular_values.iter().copied().fold(0.0, f64::max);
    let mut determined = Vec::new();
    let mut undetermined = Vec::new();
    let mut box_half_widths = Vec::new();
    for (k, &s) in svd.singular_values.iter().enumerate() {
        let direction: Vec<f64> = v_t.row(k).iter().copied().collect();
        let half_width = if s > 0.0 { t * sigma / s } else { f64::INFINITY };
        let relative = half_width * relative_norm(&direction, scaling);
        if s <= NUMERICAL_RANK * largest || half_width > 1.0 || relative > UNDETERMINED_RELATIVE {
            undetermined.push(direction);
        } else {
            determined.push((s, direction));
            box_half_widths.push(half_width);
        }
    }
    box_half_widths.sort_by(|a, b| b.total_cmp(a));
    // (JᵀJ)⁻¹ in the box over the determined directions, Σ v_k v_kᵀ / s_k², and the covariance
    // σ² times it.
    let mut inverse = DMatrix::zeros(n, n);
    for (s, v) in &determined {
        let v = DVector::from_column_slice(v);
        inverse += (&v * v.transpose()) / (s * s);
    }
    let covariance = &inverse * variance;
    let free = |j: usize| undetermined.iter().all(|v| v[j].abs() <= INVOLVED);
    let correlated = correlated(residuals, jacobian, &inverse, lengths, &free, scaling);
    let standard_errors: Vec<Option<f64>> =
        (0..n).map(|j| free(j).then(|| covariance[(j, j)].sqrt() * scaling[j].derivative.abs())).collect();
    let correlation = DMatrix::from_fn(n, n, |i, j| {
        if free(i) && free(j) {
            let d = (covariance[(i, i)] * covariance[(j, j)]).sqrt();
            if d > 0.0 { covariance[(i, j)] / d } else { f64::NAN }
        } else {
            f64::NAN
        }
    });
    let undetermined = undetermined.iter().map(|v| relative_direction(v, scaling)).collect();
    Uncertainty {
        variance,
        autocorrelation,
        inflation,
        degrees_of_freedom,
        t_quantile: t,
        standard_errors,
        correlation,
        undetermined,
        box_half_widths,
        correlated,
    }
}

/// The consecutive series of `lengths` within `m` residuals (one series of all when empty); a
/// series running past `m` is cut there.
fn series(m: usize, lengths: &[usize]) -> Vec<std::ops::Range<usize>> {
    let whole = [m];
    let lengths = if lengths.is_empty() { &whole[..] } else { lengths };
    let mut offset = 0;
    lengths
        .iter()
        .map(|&length| {
            let range = offset.min(m)..(offset + length).min(m);
            offset += length;
            range
        })
        .collect()
}

/// `Σ_t x_t y_{t+l}` over the `t` where both exist.
fn lagged(x: &[f64], y: &[f64], l: usize) -> f64 {
    if l >= y.len() {
        return 0.0;
    }
    x.iter().zip(&y[l..]).map(|(a, b)| a * b).sum()
}

/// The Bartlett bandwidth `L` \[samples] of one signal's residual series `r` (`m_s` samples):
/// the larger of
/// - Andrews' (1991) automatic bandwidth for the Bartlett kernel from the lag-1
///   autocorrelation `ρ` (clamped to ±0.98), `1.1447 (α m_s)^{1/3}`,
///   `α = 4ρ² / ((1 − ρ)² (1 + ρ)²)` — the mean-square-optimal window for an AR(1)-like
///   residual, 2–3 samples for white noise;
/// - `2ℓ + 1`, `ℓ` the residual's correlation length: the last lag up to `m_s/2` at which its
///   autocorrelation, `ρ̃(l) = (Σ_t r_t r_{t+l} / (m_s − l)) / (Σ_t r_t² / m_s)` (each lag
///   averaged over the pairs it has), is still at least [`CORRELATED`] (or `5/√(m_s − l)`, five
///   times its white-noise spread, when larger). A periodic model error is correlated again
///   every period, which Andrews' AR(1) summary cannot see; this sees it, and the window then
///   spans the record;
///
/// at least 1 and at most [`MAX_BANDWIDTH_FRACTION`] of `m_s`.
pub fn bandwidth(r: &[f64]) -> f64 {
    let m = r.len();
    let square: f64 = r.iter().map(|x| x * x).sum();
    let cap = (MAX_BANDWIDTH_FRACTION * m as f64).max(1.0);
    if m < 3 || square <= 0.0 {
        return 1.0;
    }
    let rho = (lagged(r, r, 1) / square).clamp(-0.98, 0.98);
    let alpha = 4.0 * rho * rho / ((1.0 - rho).powi(2) * (1.0 + rho).powi(2));
    let andrews = 1.1447 * (alpha * m as f64).cbrt();
    let correlated = |l: usize| {
        let pairs = (m - l) as f64;
        lagged(r, r, l) / pairs >= CORRELATED.max(5.0 / pairs.sqrt()) * square / m as f64
    };
    let length = (1..=m / 2).rev().find(|&l| correlated(l)).unwrap_or(0);
    andrews.max(2.0 * length as f64 + 1.0).clamp(1.0, cap)
}

/// [`Correlated`] for weighted residuals `residuals` (the series of `lengths`), the Jacobian
/// `jacobian` in the unit box and `inverse`, `(JᵀJ)⁻¹` over its determined directions; `free`
/// says which parameters have an interval.
fn correlated(
    residuals: &DVector<f64>,
    jacobian: &DMatrix<f64>,
    inverse: &DMatrix<f64>,
    lengths: &[usize],
    free: &dyn Fn(usize) -> bool,
    scaling: &[Scaling],
) -> Correlated {
    let (m, n) = jacobian.shape();
    let kappa = m as f64 / m.saturating_sub(n).max(1) as f64;
    // The columns of J, and of `a = J (JᵀJ)⁻¹` (θ̂_j − θ_j ≈ Σ_t a_tj e_t for an error e): both
    // matrices are stored by columns.
    let columns: Vec<&[f64]> = jacobian.as_slice().chunks(m.max(1)).collect();
    let a = jacobian * inverse;
    let influence: Vec<&[f64]> = a.as_slice().chunks(m.max(1)).collect();
    let r = residuals.as_slice();
    let mut meat = DMatrix::zeros(n, n);
    // tr B and tr B² of each parameter's variance estimate (without the factor κ, which cancels).
    let (mut trace, mut trace_square) = (vec![0.0; n], vec![0.0; n]);
    let mut bandwidths = Vec::new();
    for range in series(m, lengths) {
        let samples = range.len();
        let part = &r[range.clone()];
        let bandwidth = bandwidth(part);
        bandwidths.push(bandwidth);
        for l in 0..samples {
            let weight = 1.0 - l as f64 / bandwidth;
            if weight <= 0.0 {
                break;
            }
            let gamma = kappa * lagged(part, part, l) / samples as f64;
            for i in 0..n {
                for j in 0..n {
                    // Lag +l gives C_l = Σ_t J_t J_{t+l}ᵀ, lag −l its transpose.
                    let c = lagged(&columns[i][range.clone()], &columns[j][range.clone()], l);
                    meat[(i, j)] += weight * gamma * c;
                    if l > 0 {
                        meat[(j, i)] += weight * gamma * c;
                    }
                }
                let c = lagged(&influence[i][range.clone()], &influence[i][range.clone()], l);
                if l == 0 {
                    trace[i] += c;
                }
                let pairs = if l == 0 { 1.0 } else { 2.0 };
                trace_square[i] += pairs * (samples - l) as f64 * (weight * c / samples as f64).powi(2);
            }
        }
    }
    let covariance = inverse * meat * inverse;
    let freedom = m.saturating_sub(n).max(1) as f64;
    let mut standard_errors = Vec::with_capacity(n);
    let (mut degrees_of_freedom, mut t_quantiles) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for j in 0..n {
        if free(j) {
            standard_errors.push(Some(covariance[(j, j)].max(0.0).sqrt() * scaling[j].derivative.abs()));
            let nu = if trace_square[j] > 0.0 { trace[j] * trace[j] / trace_square[j] } else { freedom };
            let nu = nu.clamp(1.0, freedom);
            degrees_of_freedom.push(nu);
            t_quantiles.push(student_t_975(nu));
        } else {
            standard_errors.push(None);
            degrees_of_freedom.push(f64::NAN);
            t_quantiles.push(f64::NAN);
        }
    }
    Correlated { bandwidths, standard_errors, degrees_of_freedom, t_quantiles }
}

/// `‖v_j (dθ_j/dz_j) / reference_j‖`: how far a unit step along box direction `v` moves the
/// parameters, relative to their sizes.
fn relative_norm(v: &[f64], scaling: &[Scaling]) -> f64 {
    v.iter().zip(scaling).map(|(vj, s)| (vj * s.derivative / s.reference).powi(2)).sum::<f64>().sqrt()
}

/// A box direction as relative changes of the parameters, `δθ_j / θ_j = v_j (dθ/dz) / θ_j`,
/// normalised, its largest component positive.
fn relative_direction(v: &[f64], scaling: &[Scaling]) -> Vec<f64> {
    let raw: Vec<f64> = v.iter().zip(scaling).map(|(vj, s)| vj * s.derivative / s.reference).collect();
    let norm = raw.iter().map(|x| x * x).sum::<f64>().sqrt().max(f64::MIN_POSITIVE);
    let sign = raw.iter().copied().fold(0.0_f64, |a, x| if x.abs() > a.abs() { x } else { a }).signum();
    raw.iter().map(|x| sign * x / norm).collect()
}

/// The 97.5 % quantile of Student's t with `nu` degrees of freedom (Hill's expansion about the
/// normal quantile 1.959964, Algorithm 396; exact to 1e-4 for `nu ≥ 3`, and `nu = 1, 2` in
/// closed form). Considered: `statrs` (its inverse CDF by bisection), a dependency for one number.
pub fn student_t_975(nu: f64) -> f64 {
    const Z: f64 = 1.959_963_984_540_054;
    if nu <= 1.0 {
        return 12.706_204_736_174_7;
    }
    if nu <= 2.0 {
        return 4.302_652_729_749_464;
    }
    let z2 = Z * Z;
    let g1 = (z2 + 1.0) * Z / 4.0;
    let g2 = ((5.0 * z2 + 16.0) * z2 + 3.0) * Z / 96.0;
    let g3 = (((3.0 * z2 + 19.0) * z2 + 17.0) * z2 - 15.0) * Z / 384.0;
    let g4 = ((((79.0 * z2 + 776.0) * z2 + 1482.0) * z2 - 1920.0) * z2 - 945.0) * Z / 92160.0;
    Z + g1 / nu + g2 / nu.powi(2) + g3 / nu.powi(3) + g4 / nu.powi(4)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An AR(1) series with ρ = 0.5 is widened by √3; pairs are not taken across signals.
    #[test]
    fn correlated_residuals_widen_sigma() {
        let series: Vec<f64> = (0..2000).map(|i| 0.5_f64.powi(i % 40)).collect();
        let rho = lag1(&series, &[]);
        // Each block 1, ½, ¼, …: Σ r_k r_{k+1} = ½ Σ r_k² but for the last term.
        assert!((rho - 0.5).abs() < 1e-3, "{rho}");
        // Two signals of one sample each: no pair.
        assert_eq!(lag1(&[1.0, 1.0], &[1, 1]), 0.0);
        assert!((inflation(0.5) - 3f64.sqrt()).abs() < 1e-12);
        assert_eq!(inflation(-0.3), 1.0);
    }

    /// Against tabulated quantiles (any statistics table).
    #[test]
    fn student_t_quantiles() {
        for (nu, t) in [(3.0, 3.182446), (5.0, 2.570582), (10.0, 2.228139), (30.0, 2.042272), (1000.0, 1.962339)] {
            assert!((student_t_975(nu) - t).abs() < 2e-3 * t, "nu = {nu}: {} vs {t}", student_t_975(nu));
        }
        assert!((student_t_975(20.0) - 2.085963).abs() < 1e-4);
    }

    /// Linear regression `y = a + b x` with known noise: the covariance is the textbook one.
    #[test]
    fn linear_regression_covariance() {
        let x: Vec<f64> = (0..20).map(f64::from).collect();
        // Residuals with a known sum of squares, orthogonal to the columns (1, x) is not needed:
        // σ² = ‖r‖²/(m − n) whatever they are.
        // Alternating residuals: ρ < 0, so σ is not widened.
        let residuals = DVector::from_fn(20, |i, _| if i % 2 == 0 { 0.1 } else { -0.1 });
        let jacobian = DMatrix::from_fn(20, 2, |i, j| if j == 0 { 1.0 } else { x[i] });
        // Sizes large against the errors: no direction undetermined by the relative rule.
        let unit = [Scaling { value: 100.0, derivative: 1.0, reference: 100.0 }; 2];
        let u = estimate(&residuals, &jacobian, &unit, &[]);
        assert_eq!(u.inflation, 1.0);
        let variance = 0.2 / 18.0;
        assert!((u.variance - variance).abs() < 1e-15);
        // (JᵀJ)⁻¹ for (1, x): Sxx = Σ(x − x̄)² = 665; var(b) = σ²/Sxx; var(a) = σ² Σx²/(m Sxx).
        let sxx = 665.0;
        let var_b = variance / sxx;
        let var_a = variance * 2470.0 / (20.0 * sxx);
        assert!((u.standard_errors[1].unwrap() - var_b.sqrt()).abs() < 1e-12);
        assert!((u.standard_errors[0].unwrap() - var_a.sqrt()).abs() < 1e-12);
        // corr(a, b) = −x̄ / √(Σx²/m).
        let expected = -9.5 / (2470.0_f64 / 20.0).sqrt();
        assert!((u.correlation[(0, 1)] - expected).abs() < 1e-12);
        assert!(u.undetermined.is_empty());
    }

    /// A standard normal draw (Box–Muller) from `rng`.
    fn normal(rng: &mut rand_chacha::ChaCha8Rng) -> f64 {
        use rand::Rng as _;
        let u1: f64 = rng.random::<f64>().max(f64::MIN_POSITIVE);
        let u2: f64 = rng.random();
        (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
    }

    /// `y = a + b x` over 2 × 500 samples of white noise, in two signals: a lag window of 1–3
    /// samples each, and the correlated standard errors within 10 % of the textbook ones.
    #[test]
    fn white_noise_keeps_the_textbook_intervals() {
        use rand::SeedableRng as _;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let m = 1000;
        let residuals = DVector::from_fn(m, |_, _| 0.01 * normal(&mut rng));
        let jacobian = DMatrix::from_fn(m, 2, |i, j| if j == 0 { 1.0 } else { (i % 500) as f64 / 500.0 });
        let unit = [Scaling { value: 100.0, derivative: 1.0, reference: 100.0 }; 2];
        let u = estimate(&residuals, &jacobian, &unit, &[500, 500]);
        assert_eq!(u.correlated.bandwidths.len(), 2);
        for l in &u.correlated.bandwidths {
            assert!((1.0..=3.5).contains(l), "{:?}", u.correlated.bandwidths);
        }
        for j in 0..2 {
            let (white, correlated) = (u.standard_errors[j].unwrap(), u.correlated.standard_errors[j].unwrap());
            assert!((correlated / white - 1.0).abs() < 0.1, "{j}: {correlated} against {white}");
            assert!(u.correlated.degrees_of_freedom[j] > 300.0, "{:?}", u.correlated.degrees_of_freedom);
        }
    }

    /// Series of one sample each have a window of 1: `Ω̂ = diag(r_t² m/(m − n))`, White's
    /// heteroskedasticity-consistent covariance (HC1), to rounding.
    #[test]
    fn one_sample_series_give_whites_covariance() {
        let x: Vec<f64> = (0..20).map(f64::from).collect();
        let residuals = DVector::from_fn(20, |i, _| [0.1, -0.2, 0.05, 0.0, 0.15][i % 5]);
        let jacobian = DMatrix::from_fn(20, 2, |i, j| if j == 0 { 1.0 } else { x[i] });
        // Full rank (x takes 20 values): the inverse exists.
        let inverse = (jacobian.transpose() * &jacobian).try_inverse().unwrap();
        let unit = [Scaling { value: 100.0, derivative: 1.0, reference: 100.0 }; 2];
        let c = correlated(&residuals, &jacobian, &inverse, &[1; 20], &|_| true, &unit);
        assert_eq!(c.bandwidths, vec![1.0; 20]);
        let omega = DMatrix::from_diagonal(&residuals.map(|r| r * r * 20.0 / 18.0));
        let white = &inverse * (jacobian.transpose() * omega * &jacobian) * &inverse;
        for j in 0..2 {
            let se = c.standard_errors[j].unwrap();
            assert!((se - white[(j, j)].sqrt()).abs() < 1e-12 * se, "{j}: {se}");
        }
    }

    /// The mean of an AR(1) series with ρ = 0.8 (4,000 samples): its variance is
    /// `(1 + ρ)/(1 − ρ) = 9` times the white-noise one, and the correlated standard error finds
    /// about √9 = 3 × the textbook one (the Bartlett window's bias at Andrews' bandwidth, 49
    /// samples, takes about 5 % off).
    #[test]
    fn an_ar1_residual_is_widened_by_its_long_run_variance() {
        use rand::SeedableRng as _;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        let m = 4000;
        let mut e = vec![0.0; m];
        for t in 1..m {
            e[t] = 0.8 * e[t - 1] + normal(&mut rng);
        }
        let mean = e.iter().sum::<f64>() / m as f64;
        let residuals = DVector::from_iterator(m, e.iter().map(|x| x - mean));
        let jacobian = DMatrix::from_element(m, 1, 1.0);
        let unit = [Scaling { value: 1e3, derivative: 1.0, reference: 1e3 }];
        let u = estimate(&residuals, &jacobian, &unit, &[]);
        let l = u.correlated.bandwidths[0];
        assert!((40.0..60.0).contains(&l), "{l}");
        let ratio = u.correlated.standard_errors[0].unwrap() / (u.standard_errors[0].unwrap() / u.inflation);
        assert!((2.6..3.3).contains(&ratio), "{ratio}");
    }

    /// A periodic model error (10 periods of 40 samples, two harmonics) with as much white
    /// noise, against a sensitivity at the same period: the residual's correlation comes back
    /// every period, so the window spans half the record (200 samples), and the interval is
    /// over twice as wide as the AR(1)-widened one; the error the fit takes up, `Jᵀe / JᵀJ`,
    /// lies inside it and outside the AR(1) one. (At this phase of the error against `J`; where
    /// the error lies nearly along `J` the fit absorbs it and the residual does not show it: over
    /// all phases this interval holds the truth about half the time here, the AR(1) one a fifth.)
    #[test]
    fn a_periodic_error_widens_the_window_to_the_record() {
        use rand::SeedableRng as _;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let m = 400;
        let phase = |t: usize| 2.0 * std::f64::consts::PI * t as f64 / 40.0;
        let sensitivity = DMatrix::from_fn(m, 1, |t, _| phase(t).sin() + 0.3 * (2.0 * phase(t)).cos());
        let error = DVector::from_fn(m, |t, _| {
            0.01 * (phase(t) + 0.8).cos() + 0.005 * (2.0 * phase(t) + 1.0).sin() + 0.01 * normal(&mut rng)
        });
        // The fit takes up the error's part along J (Jᵀr = 0 at the optimum).
        let taken = sensitivity.column(0).dot(&error) / sensitivity.column(0).norm_squared();
        let residuals = &error - sensitivity.column(0) * taken;
        let unit = [Scaling { value: 10.0, derivative: 1.0, reference: 10.0 }];
        let u = estimate(&residuals, &sensitivity, &unit, &[]);
        assert_eq!(u.correlated.bandwidths, vec![200.0]);
        let widened = u.t_quantile * u.standard_errors[0].unwrap();
        let correlated = u.correlated.t_quantiles[0] * u.correlated.standard_errors[0].unwrap();
        assert!(correlated > 2.0 * widened, "{correlated} against {widened}");
        assert!(taken.abs() < correlated && taken.abs() > widened, "{taken}: {correlated}, {widened}");
    }

    /// Two columns in a fixed ratio: one direction undetermined, named, both without intervals.
    #[test]
    fn collinear_columns_are_undetermined() {
        let residuals = DVector::from_element(30, 0.01);
        let jacobian = DMatrix::from_fn(30, 2, |i, j| {
            let c = (f64::from(i as u32) * 0.3).sin();
            if j == 0 { c } else { 2.0 * c }
        });
        let unit = [Scaling { value: 1.0, derivative: 1.0, reference: 1.0 }; 2];
        let u = estimate(&residuals, &jacobian, &unit, &[30]);
        assert_eq!(u.undetermined.len(), 1);
        // The null direction of (1, 2) columns is (2, −1)/√5.
        let v = &u.undetermined[0];
        assert!((v[0] - 2.0 / 5f64.sqrt()).abs() < 1e-9 && (v[1] + 1.0 / 5f64.sqrt()).abs() < 1e-9, "{v:?}");
        assert_eq!(u.standard_errors, vec![None, None]);
        assert_eq!(u.correlated.standard_errors, vec![None, None]);
    }
}
