//! Storm statistics of mooring design (API RP 2SK, DNV-OS-E301): the largest value of one
//! quantity — a line's tension, an offset — in each of N seeds (independent realisations) of a
//! 3-hour storm, fitted with a Gumbel (type I extreme value) distribution, and the design numbers
//! read from the fit: the most probable maximum (MPM) and a quantile such as the 90 % one. The
//! procedure and the choice of number are in docs/design-loads.md; the formulas are PHYSICS.md
//! §10.
//!
//! # The distribution
//!
//! With location μ and scale β > 0, and `z = (x − μ)/β`:
//!
//! | | formula |
//! |---|---|
//! | distribution function | `F(x) = exp(−exp(−z))` |
//! | density | `f(x) = (1/β) e^(−z) exp(−e^(−z))` |
//! | mean, standard deviation | `μ + γ β`, `π β / √6` (γ = 0.5772…, Euler–Mascheroni) |
//! | mode (the most probable maximum) | `μ`, where `F(μ) = 1/e ≈ 0.368` |
//! | quantile of probability p | `x_p = μ − β ln(−ln p)` |
//!
//! # The two fits
//!
//! From maxima `x₁ … xₙ` with mean `x̄` and sample standard deviation `s` (divisor n − 1):
//!
//! - **moments** ([`Gumbel::by_moments`]): the mean and standard deviation above set equal to the
//!   sample's, `β = s √6 / π`, `μ = x̄ − γ β`;
//! - **maximum likelihood** ([`Gumbel::by_maximum_likelihood`]): the log-likelihood
//!   `ℓ(μ, β) = −n ln β − Σ zᵢ − Σ e^(−zᵢ)` is stationary in μ where
//!   `μ = −β ln((1/n) Σ e^(−xᵢ/β))`, and, with that μ, in β where
//!   `β = x̄ − Σ xᵢ e^(−xᵢ/β) / Σ e^(−xᵢ/β)` (the profile equation, one unknown, solved by a
//!   safeguarded Newton iteration started from the moments' β).
//!
//! The two agree for large samples; for the 7 to 20 seeds of practice they differ by a per cent
//! or two of β, and maximum likelihood is the more efficient (the smaller scatter from one set of
//! seeds to another, asymptotically). Both are checked against `scipy.stats.gumbel_r` by this
//! module's tests, with the numbers of `validation/storm/gumbel_reference.py`.
//!
//! # The Gaussian check
//!
//! [`gaussian_most_probable_maximum`]: the closed-form MPM `σ √(2 ln N)` of a narrow-band
//! Gaussian process about its mean, against which a fit to a linear (Gaussian) response is
//! checked.
//!
//! # Units
//!
//! The maxima are in any one unit (N, kN, m, rad): the location, the scale, the MPM and the
//! quantiles come out in that unit; probabilities and `F` are dimensionless. In the Gaussian
//! formula σ is in the unit of the process and N is a count.

use std::f64::consts::PI;

/// The Euler–Mascheroni constant γ: the mean of the standard Gumbel distribution.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// The relative change of the scale at which the maximum-likelihood iteration stops: once a
/// Newton step moves β by less than this, β is right to about its square (Newton converges
/// quadratically); once bisection has narrowed the bracket to it, to this.
const SCALE_TOLERANCE: f64 = 1e-12;

/// The most iterations of the maximum-likelihood solve. From the moments' β it takes 3 or 4 on
/// the tests' storm maxima (Newton's steps); every iteration shrinks the bracket of the root,
/// bisecting it whenever Newton would leave it or slow down, and 100 bisections alone narrow the
/// first bracket, (0, mean excess], by 2⁻¹⁰⁰ ≈ 10⁻³⁰.
const MAX_ITERATIONS: usize = 100;

/// Why a set of maxima cannot be fitted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExtremesError {
    /// Fewer than two maxima: one fixes a location but no scatter, and the scale measures the
    /// scatter between seeds (the sample standard deviation divides by n − 1; the likelihood
    /// of one maximum grows without bound as β → 0).
    #[error("a Gumbel fit needs at least 2 maxima (one per seed), got {count}")]
    TooFewMaxima {
        /// How many maxima were given.
        count: usize,
    },
    /// A maximum is NaN or infinite (a failed or diverged seed).
    #[error("maximum #{index} is {value}, not a finite number")]
    NotFinite {
        /// Its index in the slice, from 0.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// Every maximum is the same number: no scatter, a scale of zero.
    #[error("all {count} maxima equal {value}: no scatter between seeds, so the Gumbel scale would be 0")]
    AllEqual {
        /// How many maxima there are.
        count: usize,
        /// Their common value.
        value: f64,
    },
}

/// A Gumbel (type I extreme value) distribution, `F(x) = exp(−exp(−(x − μ)/β))`: the
/// distribution of a storm's maximum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gumbel {
    /// μ, the mode, in the unit of the maxima.
    pub location: f64,
    /// β > 0, the spread (a standard deviation of `π β / √6`), in the unit of the maxima.
    pub scale: f64,
}

impl Gumbel {
    /// The fit by moments: `β = s √6 / π` (s the sample standard deviation, divisor n − 1) and
    /// `μ = x̄ − γ β`.
    ///
    /// # Errors
    ///
    /// Fewer than 2 maxima, a maximum NaN or infinite, or all maxima equal ([`ExtremesError`]).
    pub fn by_moments(maxima: &[f64]) -> Result<Gumbel, ExtremesError> {
        check(maxima)?;
        Ok(moments(maxima))
    }

    /// The fit by maximum likelihood: the profile equation
    /// `β = x̄ − Σ xᵢ e^(−xᵢ/β) / Σ e^(−xᵢ/β)` solved to about 1e-12 relative, then
    /// `μ = −β ln((1/n) Σ e^(−xᵢ/β))`, both computed with the exponents shifted by the smallest
    /// maximum, so that the sums of e^(−xᵢ/β) neither overflow nor vanish whatever the maxima's
    /// magnitude.
    ///
    /// # Errors
    ///
    /// Fewer than 2 maxima, a maximum NaN or infinite, or all maxima equal ([`ExtremesError`]).
    pub fn by_maximum_likelihood(maxima: &[f64]) -> Result<Gumbel, ExtremesError> {
        check(maxima)?;
        let lowest = minimum(maxima);
        // The profile equation is unchanged by a shift of the data: solve it on xᵢ − min ≥ 0.
        let excesses: Vec<f64> = maxima.iter().map(|x| x - lowest).collect();
        let scale = likelihood_scale(&excesses, moments(maxima).scale);
        let location = lowest + likelihood_location(&excesses, scale);
        Ok(Gumbel { location, scale })
    }

    /// The most probable maximum (MPM): the mode of the distribution, μ.
    pub fn most_probable_maximum(&self) -> f64 {
        self.location
    }

    /// The value not exceeded with probability `p`: `μ − β ln(−ln p)` (e.g. `p = 0.9`). It is
    /// −∞ at `p = 0`, +∞ at `p = 1`, and NaN outside [0, 1].
    pub fn quantile(&self, p: f64) -> f64 {
        self.location - self.scale * (-p.ln()).ln()
    }

    /// The probability that the maximum is at most `x`: `exp(−exp(−(x − μ)/β))`.
    pub fn cdf(&self, x: f64) -> f64 {
        (-(-(x - self.location) / self.scale).exp()).exp()
    }
}

/// The most probable maximum, above the mean, of a narrow-band Gaussian process of standard
/// deviation `sigma` over `count` zero up-crossings (the storm's duration over the mean
/// zero-crossing period, `N = T / T_z`, e.g. 3 h / 10 s = 1080): `σ √(2 ln N)`.
///
/// A narrow-band Gaussian process has Rayleigh-distributed peaks,
/// `P(A ≤ a) = 1 − exp(−a²/(2σ²))`, one per up-crossing; the largest of N independent ones has
/// the distribution `(1 − exp(−a²/(2σ²)))^N ≈ exp(−N exp(−a²/(2σ²)))`, whose mode is
/// `σ √(2 ln N)` (Longuet-Higgins 1952; Cartwright & Longuet-Higgins 1956, whose broad-band
/// result tends to it when N counts the up-crossings). The exact mode of the largest of N
/// Rayleigh peaks is a little higher: by 0.5 % at N = 1080. In the unit of `sigma`; NaN for
/// `count < 1`.
pub fn gaussian_most_probable_maximum(sigma: f64, count: f64) -> f64 {
    sigma * (2.0 * count.ln()).sqrt()
}

/// Refuses what cannot be fitted: fewer than 2 maxima, a value not finite, no scatter.
fn check(maxima: &[f64]) -> Result<(), ExtremesError> {
    if maxima.len() < 2 {
        return Err(ExtremesError::TooFewMaxima { count: maxima.len() });
    }
    if let Some((index, &value)) = maxima.iter().enumerate().find(|(_, x)| !x.is_finite()) {
        return Err(ExtremesError::NotFinite { index, value });
    }
    let first = maxima[0]; // the length is at least 2, checked above
    if maxima.iter().all(|&x| x == first) {
        return Err(ExtremesError::AllEqual { count: maxima.len(), value: first });
    }
    Ok(())
}

/// The moment fit of maxima already checked.
fn moments(maxima: &[f64]) -> Gumbel {
    let scale = sample_standard_deviation(maxima) * 6.0_f64.sqrt() / PI;
    Gumbel { location: mean(maxima) - EULER_GAMMA * scale, scale }
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// The sample standard deviation, divisor n − 1, in two passes (no cancellation).
fn sample_standard_deviation(values: &[f64]) -> f64 {
    let centre = mean(values);
    let squares: f64 = values.iter().map(|x| (x - centre).powi(2)).sum();
    (squares / (values.len() - 1) as f64).sqrt()
}

fn minimum(values: &[f64]) -> f64 {
    values.iter().copied().fold(f64::INFINITY, f64::min)
}

/// The root β of the profile equation `g(β) = d̄ − Σ dᵢ wᵢ / Σ wᵢ − β = 0`, `wᵢ = e^(−dᵢ/β)`, for
/// excesses `dᵢ = xᵢ − min x ≥ 0` not all zero, started from `start`.
///
/// g is strictly decreasing (`g′ = −1 − Var_w(d)/β² < 0`), positive as β → 0 (the weighted mean
/// tends to min d = 0, so g → d̄ > 0) and at most 0 at `β = d̄` (the weighted mean is ≥ 0): one
/// root, in (0, d̄]. Newton's step is taken when it stays in the bracket and at least halves the
/// step before it, the bracket is bisected otherwise (Numerical Recipes' `rtsafe`).
fn likelihood_scale(excesses: &[f64], start: f64) -> f64 {
    let (mut low, mut high) = (0.0, mean(excesses));
    let mut scale = if start > low && start < high { start } else { 0.5 * high };
    let mut last_step = f64::INFINITY; // the first Newton step is taken if it stays in the bracket
    for _ in 0..MAX_ITERATIONS {
        let (residual, slope) = profile(excesses, scale);
        if residual == 0.0 {
            return scale;
        }
        if residual > 0.0 {
            low = scale;
        } else {
            high = scale;
        }
        let newton = scale - residual / slope;
        let next = if newton > low && newton <= high && (newton - scale).abs() < 0.5 * last_step {
            newton
        } else {
            0.5 * (low + high)
        };
        last_step = (next - scale).abs();
        scale = next;
        if last_step <= SCALE_TOLERANCE * scale || high - low <= SCALE_TOLERANCE * scale {
            break;
        }
    }
    scale
}

/// The profile equation's residual `g(β)` and slope `g′(β) = −1 − Var_w(d)/β²`, with the
/// weights `wᵢ = e^(−dᵢ/β)` in (0, 1] for excesses `dᵢ ≥ 0` (the smallest has weight 1, so the
/// sums never vanish).
fn profile(excesses: &[f64], scale: f64) -> (f64, f64) {
    let weights: Vec<f64> = excesses.iter().map(|d| (-d / scale).exp()).collect();
    let total: f64 = weights.iter().sum();
    let weighted_mean = excesses.iter().zip(&weights).map(|(d, w)| d * w).sum::<f64>() / total;
    let weighted_variance =
        excesses.iter().zip(&weights).map(|(d, w)| w * (d - weighted_mean).powi(2)).sum::<f64>() / total;
    let residual = mean(excesses) - weighted_mean - scale;
    let slope = -1.0 - weighted_variance / (scale * scale);
    (residual, slope)
}

/// The location, less the smallest maximum, that maximises the likelihood at scale β:
/// `−β ln((1/n) Σ e^(−dᵢ/β))` for excesses `dᵢ ≥ 0` (the sum is at least 1: no underflow).
fn likelihood_location(excesses: &[f64], scale: f64) -> f64 {
    let total: f64 = excesses.iter().map(|d| (-d / scale).exp()).sum();
    -scale * (total / excesses.len() as f64).ln()
}

// The tests unwrap the fits of valid maxima: an error there is the test's failure.
#[cfg(test)]
mod tests {
    use super::*;

    /// The largest fairlead tension of each of 10 seeds of a 3-hour storm [kN]
    /// (`TENSIONS_10` of validation/storm/gumbel_reference.py).
    const TENSIONS_10: [f64; 10] = [1843.2, 1921.7, 1788.4, 2012.9, 1867.5, 1955.1, 1899.8, 2086.3, 1812.6, 1934.0];
    /// Another line, 7 seeds [kN] (`TENSIONS_7` of the same script).
    const TENSIONS_7: [f64; 7] = [412.5, 398.1, 455.7, 431.2, 389.9, 470.3, 420.8];

    /// What scipy gives for one set of maxima and one fit.
    struct Reference {
        location: f64,
        scale: f64,
        /// `gumbel_r.ppf(0.9, μ, β)`.
        quantile_90: f64,
        /// The median of the maxima, and `gumbel_r.cdf` of it.
        median: f64,
        cdf_at_median: f64,
    }

    // The numbers below are printed by validation/storm/gumbel_reference.py (scipy 1.17.1,
    // numpy 2.4.6): maximum likelihood is `scipy.stats.gumbel_r.fit(x)`, which solves the
    // profile equation with root_scalar to 1e-14 and which the script checks against its own
    // brentq solve (to 1e-12) and the log-likelihood's gradient; moments use ddof=1.
    const LIKELIHOOD_10: Reference = Reference {
        location: 1870.981176585767,
        scale: 72.00962175196706,
        quantile_90: 2033.029276628521,
        median: 1910.75,
        cdf_at_median: 0.5623442550145424,
    };
    const MOMENTS_10: Reference = Reference {
        location: 1871.061397795161,
        scale: 71.18414260612352,
        quantile_90: 2031.251866538731,
        median: 1910.75,
        cdf_at_median: 0.564050676836174,
    };
    const LIKELIHOOD_7: Reference = Reference {
        location: 412.4998283660449,
        scale: 22.32263513230314,
        quantile_90: 462.7339571272968,
        median: 420.8,
        cdf_at_median: 0.5018404171171508,
    };
    const MOMENTS_7: Reference = Reference {
        location: 412.3008516827519,
        scale: 22.866926730929627,
        quantile_90: 463.7598364740835,
        median: 420.8,
        cdf_at_median: 0.5017888795970276,
    };

    /// Agreement with scipy, relative: the fits agree to ~3e-15 (the β of maximum likelihood) or
    /// exactly; 1e-12 leaves room for another platform's `exp` and `ln`.
    const RELATIVE: f64 = 1e-12;

    fn assert_close(actual: f64, expected: f64, relative: f64, what: &str) {
        let error = (actual - expected).abs() / expected.abs();
        assert!(error <= relative, "{what}: {actual} against {expected}, {error:.2e} relative");
    }

    fn assert_matches(fit: &Gumbel, reference: &Reference, what: &str) {
        assert_close(fit.location, reference.location, RELATIVE, &format!("{what}: location"));
        assert_close(fit.scale, reference.scale, RELATIVE, &format!("{what}: scale"));
        assert_close(fit.most_probable_maximum(), reference.location, RELATIVE, &format!("{what}: MPM"));
        assert_close(fit.quantile(0.9), reference.quantile_90, RELATIVE, &format!("{what}: 90 % quantile"));
        assert_close(fit.cdf(reference.median), reference.cdf_at_median, RELATIVE, &format!("{what}: cdf"));
    }

    #[test]
    fn maximum_likelihood_matches_scipy() {
        assert_matches(&Gumbel::by_maximum_likelihood(&TENSIONS_10).unwrap(), &LIKELIHOOD_10, "10 seeds");
        assert_matches(&Gumbel::by_maximum_likelihood(&TENSIONS_7).unwrap(), &LIKELIHOOD_7, "7 seeds");
    }

    #[test]
    fn moments_match_scipy() {
        assert_matches(&Gumbel::by_moments(&TENSIONS_10).unwrap(), &MOMENTS_10, "10 seeds");
        assert_matches(&Gumbel::by_moments(&TENSIONS_7).unwrap(), &MOMENTS_7, "7 seeds");
    }

    /// Maxima at the quantiles `p_i = (i − 0.5)/n` of a known Gumbel: a sample without noise,
    /// from which both fits recover μ and β within 1 %.
    #[test]
    fn both_fits_recover_a_known_distribution() {
        let truth = Gumbel { location: 1500.0, scale: 80.0 };
        let n = 2000;
        let maxima: Vec<f64> = (1..=n).map(|i| truth.quantile((i as f64 - 0.5) / n as f64)).collect();
        for (fit, what) in [
            (Gumbel::by_moments(&maxima).unwrap(), "moments"),
            (Gumbel::by_maximum_likelihood(&maxima).unwrap(), "maximum likelihood"),
        ] {
            assert_close(fit.location, truth.location, 0.01, &format!("{what}: location"));
            assert_close(fit.scale, truth.scale, 0.01, &format!("{what}: scale"));
        }
    }

    /// Maxima a million times their scatter away from zero (e^(−x/β) would underflow to 0 for
    /// every one): the likelihood fit moves with them and keeps its scale.
    #[test]
    fn maximum_likelihood_is_stable_far_from_zero() {
        let offset = 1e7;
        let shifted: Vec<f64> = TENSIONS_10.iter().map(|x| x + offset).collect();
        let fit = Gumbel::by_maximum_likelihood(&shifted).unwrap();
        assert_close(fit.location, LIKELIHOOD_10.location + offset, 1e-12, "location");
        assert_close(fit.scale, LIKELIHOOD_10.scale, 1e-6, "scale");
        let negated: Vec<f64> = TENSIONS_10.iter().map(|x| x - offset).collect();
        let fit = Gumbel::by_maximum_likelihood(&negated).unwrap();
        assert_close(fit.location, LIKELIHOOD_10.location - offset, 1e-12, "location");
        assert_close(fit.scale, LIKELIHOOD_10.scale, 1e-6, "scale");
    }

    /// Two maxima are enough, and so are maxima with one far outlier (weights that underflow).
    #[test]
    fn maximum_likelihood_solves_small_and_lopsided_samples() {
        for maxima in [vec![100.0, 101.0], [vec![0.0; 1999], vec![1.0]].concat()] {
            let fit = Gumbel::by_maximum_likelihood(&maxima).unwrap();
            let excesses: Vec<f64> = maxima.iter().map(|x| x - minimum(&maxima)).collect();
            let (residual, _) = profile(&excesses, fit.scale);
            assert!(fit.scale > 0.0 && residual.abs() <= 1e-12 * fit.scale, "{fit:?}: residual {residual:e}");
        }
    }

    #[test]
    fn quantile_and_cdf_are_inverses() {
        let gumbel = Gumbel { location: 1870.0, scale: 72.0 };
        for p in [1e-6, 0.1, 0.5, 0.9, 0.99, 1.0 - 1e-9] {
            assert_close(gumbel.cdf(gumbel.quantile(p)), p, 1e-9, &format!("p = {p}"));
        }
        assert_close(gumbel.cdf(gumbel.most_probable_maximum()), (-1.0_f64).exp(), 1e-15, "F(mode) = 1/e");
        assert_eq!(gumbel.quantile(0.0), f64::NEG_INFINITY);
        assert_eq!(gumbel.quantile(1.0), f64::INFINITY);
        assert!(gumbel.quantile(1.5).is_nan() && gumbel.quantile(-0.1).is_nan());
    }

    #[test]
    fn refuses_what_cannot_be_fitted() {
        type Fit = fn(&[f64]) -> Result<Gumbel, ExtremesError>;
        for fit in [Gumbel::by_moments as Fit, Gumbel::by_maximum_likelihood as Fit] {
            assert_eq!(fit(&[]), Err(ExtremesError::TooFewMaxima { count: 0 }));
            assert_eq!(fit(&[1843.2]), Err(ExtremesError::TooFewMaxima { count: 1 }));
            assert_eq!(
                fit(&[1.0, 2.0, f64::INFINITY, f64::NAN]),
                Err(ExtremesError::NotFinite { index: 2, value: f64::INFINITY })
            );
            assert!(
                matches!(fit(&[1.0, f64::NAN]), Err(ExtremesError::NotFinite { index: 1, value }) if value.is_nan())
            );
            assert_eq!(fit(&[5.0, 5.0, 5.0]), Err(ExtremesError::AllEqual { count: 3, value: 5.0 }));
        }
    }

    #[test]
    fn error_messages_are_one_line_and_name_the_value() {
        let messages = [
            (ExtremesError::TooFewMaxima { count: 1 }, "got 1"),
            (ExtremesError::NotFinite { index: 3, value: f64::NAN }, "#3 is NaN"),
            (ExtremesError::NotFinite { index: 0, value: f64::NEG_INFINITY }, "#0 is -inf"),
            (ExtremesError::AllEqual { count: 4, value: 1843.2 }, "all 4 maxima equal 1843.2"),
        ];
        for (error, expected) in messages {
            let message = error.to_string();
            assert!(message.contains(expected) && !message.contains('\n'), "{message}");
        }
    }

    /// `σ √(2 ln N)` against its closed form, and against the exact mode of the largest of N
    /// Rayleigh peaks, found by golden-section search of its log-density
    /// `(N − 1) ln(1 − e^(−a²/2)) + ln a − a²/2` (σ = 1): a little above, by 0.52 % at N = 1080.
    #[test]
    fn gaussian_most_probable_maximum_is_the_rayleigh_mode() {
        assert_close(gaussian_most_probable_maximum(2.0, 1000.0), 2.0 * (2.0 * 1000.0_f64.ln()).sqrt(), 1e-15, "σ = 2");
        assert_eq!(gaussian_most_probable_maximum(1.0, 1.0), 0.0);
        assert!(gaussian_most_probable_maximum(1.0, 0.5).is_nan());
        let count = 1080.0;
        let log_density = |a: f64| (count - 1.0) * (-(-a * a / 2.0).exp()).ln_1p() + a.ln() - a * a / 2.0;
        let exact = golden_section_maximum(log_density, 1.0, 8.0);
        let closed = gaussian_most_probable_maximum(1.0, count);
        assert!(closed < exact, "{closed} against {exact}");
        assert_close(closed, exact, 0.006, "N = 1080");
    }

    /// The maximiser of a unimodal `f` on [a, b], to 1e-12.
    fn golden_section_maximum(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
        let ratio = (5.0_f64.sqrt() - 1.0) / 2.0;
        while b - a > 1e-12 {
            let (c, d) = (b - ratio * (b - a), a + ratio * (b - a));
            if f(c) > f(d) {
                b = d;
            } else {
                a = c;
            }
        }
        0.5 * (a + b)
    }
}
