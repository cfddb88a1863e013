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

use nalgebra::{DMatrix, DVector};

/// A parameter moving along an undetermined direction by more than this (of a unit vector)
/// has no interval.
const INVOLVED: f64 = 0.05;

/// Singular values below this fraction of the largest are rounding.
const NUMERICAL_RANK: f64 = 1e-8;

/// A direction whose 95 % half-width changes the parameters by more than this fraction of their
/// values is undetermined.
pub const UNDETERMINED_RELATIVE: f64 = 0.5;

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
    let whole = [residuals.len()];
    let lengths = if lengths.is_empty() { &whole[..] } else { lengths };
    let (mut product, mut square, mut offset) = (0.0, 0.0, 0);
    for &length in lengths {
        let r = &residuals[offset..(offset + length).min(residuals.len())];
        product += r.windows(2).map(|w| w[0] * w[1]).sum::<f64>();
        square += r.iter().map(|x| x * x).sum::<f64>();
        offset += length;
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
    // Covariance in the box over the determined directions: σ² Σ v_k v_kᵀ / s_k².
    let mut covariance = DMatrix::zeros(n, n);
    for (s, v) in &determined {
        let v = DVector::from_column_slice(v);
        covariance += (&v * v.transpose()) * (variance / (s * s));
    }
    let free = |j: usize| undetermined.iter().all(|v| v[j].abs() <= INVOLVED);
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
    }
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
    }
}
