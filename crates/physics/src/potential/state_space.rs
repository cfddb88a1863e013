//! The radiation force by a state-space approximation fitted to the kernel (PHYSICS.md §9):
//! `ẋ = A_r x + B_r q̇`, `F_r = −C_r x` [N, N·m], so that an evaluation costs `O(states)` and every
//! integrator carries the states like the bodies' own.
//!
//! Each nonzero pair `(i, j)` of the kernel is fitted on its own by a sum of damped modes,
//! `K_ij(t) ≈ Σ e^{σ t} (α cos ωt + β sin ωt)` (`σ < 0`; `ω = 0` for a real pole, whose `β`
//! is unused). The poles come from realisation theory on the sampled kernel: the eigenvalues
//! `z` of the order-`n` ERA system matrix (Kung's SVD of the Hankel matrix of samples,
//! `Φ = Σ^{−½} Uᵀ H₁ V Σ^{−½}`), `σ + iω = ln z / Δt`, keeping the stable ones; the coefficients
//! `α, β` are then fitted to every sample by linear least squares. The order rises from 1 until
//! the fit's relative L2 error over the samples, `‖K − K̂‖ / ‖K‖`, reaches the stated tolerance.
//!
//! A real pole is one state, `ẋ = σ x + q̇_j`, giving `α x`; a complex pair is two,
//! `ẋ₁ = σ x₁ − ω x₂ + q̇_j`, `ẋ₂ = ω x₁ + σ x₂`, giving `α x₁ + β x₂` (their impulse
//! response is `e^{σt}(cos ωt, sin ωt)`); the pair's part of `F_r,i` is minus that.
//!
//! Written here on nalgebra's SVD and Schur decomposition rather than taken from a crate: the
//! crate considered, `deimos_numerics` (its `control::identification::era`), realises
//! discrete-time systems only and brings a whole control toolbox with it; the continuous modes
//! and their least-squares coefficients below are what a body's integrators need, in 100 lines.

use super::coefficients::{Matrix6, Vector6};
use super::kernel::SampledKernel;
use crate::parameter::{Bound, ParameterError, require};
use nalgebra::{Complex, DMatrix, DVector};

/// How a kernel is fitted: the relative L2 error to reach and the highest order to try.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSettings {
    tolerance: f64,
    max_order: u32,
}

/// The highest state-space order a pair may be fitted with.
const ORDER_LIMIT: u32 = 60;

impl FitSettings {
    /// `tolerance` (the relative L2 error, in (0, 1)) and `max_order` (1 to 60 states per pair).
    ///
    /// # Errors
    /// The value out of its range, named as scene files will spell it.
    pub fn new(tolerance: f64, max_order: u32) -> Result<Self, ParameterError> {
        let tolerance = require("fit_error", tolerance, Bound::OpenUnit, "")?;
        if max_order == 0 {
            return Err(ParameterError::TooFew { field: "max_order", value: max_order, least: 1 });
        }
        if max_order > ORDER_LIMIT {
            return Err(ParameterError::TooMany { field: "max_order", value: max_order, most: ORDER_LIMIT });
        }
        Ok(Self { tolerance, max_order })
    }
    /// The relative L2 error the fit must reach.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }
    /// The highest order a pair may be fitted with.
    pub fn max_order(&self) -> u32 {
        self.max_order
    }
}

/// Why a kernel could not be fitted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    #[error(
        "radiation kernel K{i}{j}: no fit of order up to {max_order} reaches the relative error {tolerance:e} \
         (best {best:.3e} at order {order}); raise the order or the tolerance, or sample the kernel finer"
    )]
    NotReached { i: usize, j: usize, tolerance: f64, max_order: u32, best: f64, order: usize },
}

/// One damped mode of a pair's kernel: `e^{σt}(α cos ωt + β sin ωt)`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Mode {
    /// `σ` [1/s], < 0.
    decay: f64,
    /// `ω` [rad/s], ≥ 0; 0 for a real pole (one state).
    frequency: f64,
    /// `α` [the kernel's unit].
    cosine: f64,
    /// `β` [the kernel's unit]; 0 for a real pole.
    sine: f64,
}

impl Mode {
    fn is_real(&self) -> bool {
        self.frequency == 0.0
    }
    fn states(&self) -> usize {
        if self.is_real() { 1 } else { 2 }
    }
    fn kernel(&self, t: f64) -> f64 {
        let (s, c) = (self.frequency * t).sin_cos();
        (self.decay * t).exp() * (self.cosine * c + self.sine * s)
    }
}

/// The fit of one pair `(i, j)`: the pair's modes, where its states start, its error.
#[derive(Debug, Clone, PartialEq)]
pub struct PairFit {
    /// The force's degree of freedom (0–5).
    pub i: usize,
    /// The velocity's degree of freedom (0–5).
    pub j: usize,
    /// The fit's relative L2 error over the samples.
    pub error: f64,
    modes: Vec<Mode>,
    first_state: usize,
}

impl PairFit {
    /// The number of states the pair carries.
    pub fn states(&self) -> usize {
        self.modes.iter().map(Mode::states).sum()
    }
    /// `K̂_ij(t)`, the fitted kernel.
    pub fn kernel(&self, t: f64) -> f64 {
        self.modes.iter().map(|m| m.kernel(t)).sum()
    }
}

/// A body's radiation states' equations: one [`PairFit`] per nonzero pair of its kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct RadiationStateSpace {
    pairs: Vec<PairFit>,
    states: usize,
    /// What the fit was asked for.
    settings: FitSettings,
    /// The fitted kernel's truncation `t_K` and sampling step \[s].
    kernel_duration: f64,
    kernel_step: f64,
}

/// A diagonal term peaking below this fraction of the largest of its kind (translations,
/// rotations) is the panel code's numerical noise rather than a kernel: an axisymmetric body's
/// yaw.
const NEGLIGIBLE_DIAGONAL: f64 = 1e-3;

/// A pair peaking below this fraction of `√(peak_ii peak_jj)` of its kept diagonal terms is
/// noise too: the cylinder's surge–sway pair (2e-5 of its diagonal's), the moored buoy's
/// heave–roll pair (4e-3: its mesh's small asymmetry in the panel code's solve), which no
/// order fits, being no sum of modes. A real coupling this weak moves the response by less
/// than it.
const NEGLIGIBLE_PAIR: f64 = 1e-2;

/// The diagonal peaks that are kernels, the others 0 ([`NEGLIGIBLE_DIAGONAL`]).
fn kept_diagonal(peaks: &Matrix6) -> [f64; 6] {
    let largest = |dof: usize| {
        let kind = if dof < 3 { 0..3 } else { 3..6 };
        kind.map(|k| peaks[(k, k)]).fold(0.0, f64::max)
    };
    std::array::from_fn(|i| if peaks[(i, i)] > NEGLIGIBLE_DIAGONAL * largest(i) { peaks[(i, i)] } else { 0.0 })
}

impl RadiationStateSpace {
    /// Fits every pair of `kernel` that is not numerical noise (a diagonal term below 1e-3 of the
    /// largest of its kind, a pair below 1e-2 of `√(K_ii K_jj)`).
    ///
    /// # Errors
    /// [`FitError::NotReached`] for the first pair no order up to the limit fits.
    pub fn fit(kernel: &SampledKernel, settings: FitSettings) -> Result<Self, FitError> {
        let peaks = kernel.peaks();
        let diagonal = kept_diagonal(&peaks);
        let mut pairs = Vec::new();
        let mut states = 0;
        for i in 0..6 {
            for j in 0..6 {
                let scale = (diagonal[i] * diagonal[j]).sqrt();
                if scale == 0.0 || peaks[(i, j)] <= NEGLIGIBLE_PAIR * scale {
                    continue;
                }
                let pair = fit_pair(&kernel.pair(i, j), kernel.step(), settings).map_err(|(best, order)| {
                    FitError::NotReached {
                        i: i + 1,
                        j: j + 1,
                        tolerance: settings.tolerance,
                        max_order: settings.max_order,
                        best,
                        order,
                    }
                })?;
                let fitted = PairFit { i, j, error: pair.1, modes: pair.0, first_state: states };
                states += fitted.states();
                pairs.push(fitted);
            }
        }
        Ok(Self { pairs, states, settings, kernel_duration: kernel.duration(), kernel_step: kernel.step() })
    }

    /// The number of radiation states the body carries.
    pub fn state_count(&self) -> usize {
        self.states
    }
    /// The fitted pairs: their order and error (what `tether check` prints).
    pub fn pairs(&self) -> &[PairFit] {
        &self.pairs
    }
    /// The error and highest order the fit was asked for.
    pub fn settings(&self) -> FitSettings {
        self.settings
    }
    /// The fitted kernel's truncation `t_K` and sampling step \[s].
    pub fn kernel_sampling(&self) -> (f64, f64) {
        (self.kernel_duration, self.kernel_step)
    }
    /// The fitted kernel matrix `K̂(t)`.
    pub fn kernel(&self, t: f64) -> Matrix6 {
        let mut k = Matrix6::zeros();
        for pair in &self.pairs {
            k[(pair.i, pair.j)] = pair.kernel(t);
        }
        k
    }

    /// `ẋ = A_r x + B_r q̇` into `rates` (both slices [`Self::state_count`] long).
    pub fn rates(&self, states: &[f64], velocity: &Vector6, rates: &mut [f64]) {
        for pair in &self.pairs {
            let input = velocity[pair.j];
            let mut s = pair.first_state;
            for mode in &pair.modes {
                if mode.is_real() {
                    rates[s] = mode.decay * states[s] + input;
                } else {
                    let (x1, x2) = (states[s], states[s + 1]);
                    rates[s] = mode.decay * x1 - mode.frequency * x2 + input;
                    rates[s + 1] = mode.frequency * x1 + mode.decay * x2;
                }
                s += mode.states();
            }
        }
    }

    /// The states `to` at `h` \[s] after `from`, the input `q̇` moving linearly from `v0` to `v1`
    /// over the interval, each mode integrated exactly (PHYSICS.md §9, "Radiation memory in the
    /// integrators"): with `λ = σ + iω` and `z = x₁ + i x₂` (`z = x` for a real pole),
    /// `z(h) = e^{λh} z(0) + (φ₁ − φ₂) q̇_0 + φ₂ q̇_1`, `φ₁ = (e^{λh} − 1)/λ`,
    /// `φ₂ = (φ₁ − h)/(λh)` (their Taylor series where `|λh| < 1e-4`). `h = 0` gives `from`.
    pub fn advance(&self, from: &[f64], v0: &Vector6, v1: &Vector6, h: f64, to: &mut [f64]) {
        for pair in &self.pairs {
            let (u0, u1) = (v0[pair.j], v1[pair.j]);
            let mut s = pair.first_state;
            for mode in &pair.modes {
                let lambda = Complex::new(mode.decay, mode.frequency);
                let start = Complex::new(from[s], if mode.is_real() { 0.0 } else { from[s + 1] });
                let end = exact_linear_input(lambda, h, start, u0, u1);
                to[s] = end.re;
                if !mode.is_real() {
                    to[s + 1] = end.im;
                }
                s += mode.states();
            }
        }
    }

    /// `F_r = −C_r x` [N, N·m].
    pub fn force(&self, states: &[f64]) -> Vector6 {
        let mut force = Vector6::zeros();
        for pair in &self.pairs {
            let mut s = pair.first_state;
            for mode in &pair.modes {
                let output = if mode.is_real() {
                    mode.cosine * states[s]
                } else {
                    mode.cosine * states[s] + mode.sine * states[s + 1]
                };
                force[pair.i] -= output;
                s += mode.states();
            }
        }
        force
    }
}

/// `z(h)` of `ż = λ z + u(t)`, `u` linear from `u0` to `u1` over `[0, h]`, from `z(0) = start`.
fn exact_linear_input(lambda: Complex<f64>, h: f64, start: Complex<f64>, u0: f64, u1: f64) -> Complex<f64> {
    if h == 0.0 {
        return start;
    }
    let z = lambda * h;
    // `φ₁/h = (e^z − 1)/z`, `φ₂/h = (e^z − 1 − z)/z²`, by series where they would cancel.
    let (phi1, phi2) = if z.norm() < 1e-4 {
        (Complex::from(1.0) + z / 2.0 + z * z / 6.0, Complex::from(0.5) + z / 6.0 + z * z / 24.0)
    } else {
        let e = z.exp() - 1.0;
        (e / z, (e - z) / (z * z))
    };
    z.exp() * start + (phi1 - phi2) * (u0 * h) + phi2 * (u1 * h)
}

/// The rows and columns of the Hankel matrix of the realisation.
const HANKEL_SIZE: usize = 100;

/// The modes of the lowest order whose error reaches the tolerance, with that error; or the
/// best error and its order when none does.
///
/// The realisation first sees the kernel's first `2 × HANKEL_SIZE` samples at its own step
/// (its fast modes best). A slowly decaying kernel (a spar's: 60 s at 0.05 s) needs more of its
/// length than that, so when no order reaches the tolerance the Hankel matrix is built again from
/// every 2nd, 4th, … sample, until it spans the whole kernel.
fn fit_pair(samples: &[f64], step: f64, settings: FitSettings) -> Result<(Vec<Mode>, f64), (f64, usize)> {
    let widest = samples.len().div_ceil(2 * HANKEL_SIZE).max(1);
    let mut best = (f64::INFINITY, 0);
    let mut stride = 1;
    loop {
        match fit_pair_with_stride(samples, step, settings, stride) {
            Ok(fit) => return Ok(fit),
            Err(missed) if missed.0 < best.0 => best = missed,
            Err(_) => {}
        }
        if stride >= widest {
            return Err(best);
        }
        stride = (2 * stride).min(widest);
    }
}

/// [`fit_pair`] with the poles realised from every `stride`-th sample.
fn fit_pair_with_stride(
    samples: &[f64],
    step: f64,
    settings: FitSettings,
    stride: usize,
) -> Result<(Vec<Mode>, f64), (f64, usize)> {
    let norm = samples.iter().map(|v| v * v).sum::<f64>().sqrt();
    let sparse: Vec<f64> = samples.iter().step_by(stride).copied().collect();
    let size = (sparse.len() / 2).min(HANKEL_SIZE);
    let hankel = |shift: usize| DMatrix::from_fn(size, size, |r, c| sparse[r + c + shift]);
    let svd = hankel(0).svd(true, true);
    let shifted = hankel(1);
    // `svd(true, true)` was asked for both factors, so both are present.
    let (u, v_t) = (svd.u.as_ref().expect("U requested"), svd.v_t.as_ref().expect("Vᵀ requested"));
    let mut best = (f64::INFINITY, 0);
    let highest = (settings.max_order as usize).min(size);
    for order in 1..=highest {
        let sigma = svd.singular_values.rows(0, order);
        if sigma[order - 1] <= f64::EPSILON * sigma[0] {
            break;
        }
        let root = sigma.map(|s| 1.0 / s.sqrt());
        let phi = DMatrix::from_diagonal(&root)
            * u.columns(0, order).transpose()
            * &shifted
            * v_t.rows(0, order).transpose()
            * DMatrix::from_diagonal(&root);
        let poles = stable_poles(&phi, step * stride as f64);
        let Some(modes) = fit_coefficients(&poles, samples, step) else { continue };
        let error = residual(&modes, samples, step) / norm;
        if error <= settings.tolerance {
            return Ok((modes, error));
        }
        if error < best.0 {
            best = (error, order);
        }
    }
    Err(best)
}

/// The continuous poles `(σ, ω)` of the discrete system matrix `Φ`, `σ + iω = ln z / Δt`, one
/// per conjugate pair (`ω > 0`) or real (`ω = 0`); eigenvalues on or outside the unit circle
/// (not decaying) and on the negative real axis (no real continuous pole) are left out.
fn stable_poles(phi: &DMatrix<f64>, step: f64) -> Vec<(f64, f64)> {
    phi.complex_eigenvalues()
        .iter()
        .filter(|z| z.norm() < 1.0 && z.im >= 0.0)
        .filter_map(|z| {
            let real = z.im <= 1e-12 * z.norm();
            if real && z.re <= 0.0 {
                return None;
            }
            Some((z.norm().ln() / step, if real { 0.0 } else { z.arg() / step }))
        })
        .collect()
}

/// `α, β` of every pole fitted to the samples by least squares; `None` when the poles give no
/// column.
fn fit_coefficients(poles: &[(f64, f64)], samples: &[f64], step: f64) -> Option<Vec<Mode>> {
    let columns: usize = poles.iter().map(|&(_, w)| if w == 0.0 { 1 } else { 2 }).sum();
    if columns == 0 {
        return None;
    }
    let mut basis = DMatrix::zeros(samples.len(), columns);
    for (n, mut row) in basis.row_iter_mut().enumerate() {
        let t = n as f64 * step;
        let mut c = 0;
        for &(decay, frequency) in poles {
            let envelope = (decay * t).exp();
            row[c] = envelope * (frequency * t).cos();
            if frequency != 0.0 {
                row[c + 1] = envelope * (frequency * t).sin();
                c += 1;
            }
            c += 1;
        }
    }
    let solution = basis.svd(true, true).solve(&DVector::from_column_slice(samples), 1e-14).ok()?;
    let mut c = 0;
    let modes = poles
        .iter()
        .map(|&(decay, frequency)| {
            let cosine = solution[c];
            let sine = if frequency == 0.0 { 0.0 } else { solution[c + 1] };
            c += if frequency == 0.0 { 1 } else { 2 };
            Mode { decay, frequency, cosine, sine }
        })
        .collect();
    Some(modes)
}

/// `‖K − K̂‖` over the samples.
fn residual(modes: &[Mode], samples: &[f64], step: f64) -> f64 {
    samples
        .iter()
        .enumerate()
        .map(|(n, v)| {
            let t = n as f64 * step;
            let fitted: f64 = modes.iter().map(|m| m.kernel(t)).sum();
            (v - fitted).powi(2)
        })
        .sum::<f64>()
        .sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A kernel that is a sum of two modes is realised exactly by order 3 (one real pole, one
    /// complex pair), and its poles are found.
    #[test]
    fn a_kernel_of_exact_modes_is_recovered_at_its_own_order() {
        let step = 0.1;
        let exact =
            |t: f64| 2.0 * (-0.5 * t).exp() + (-0.2 * t).exp() * (0.7 * (1.3 * t).cos() - 0.4 * (1.3 * t).sin());
        let samples: Vec<f64> = (0..300).map(|n| exact(n as f64 * step)).collect();
        let (modes, error) = fit_pair(&samples, step, FitSettings::new(1e-9, 10).expect("valid")).expect("a fit");
        assert!(error < 1e-9, "error {error}");
        assert_eq!(modes.iter().map(Mode::states).sum::<usize>(), 3);
        let complex = modes.iter().find(|m| !m.is_real()).expect("a complex pair");
        assert!((complex.decay + 0.2).abs() < 1e-7 && (complex.frequency - 1.3).abs() < 1e-7, "{complex:?}");
        assert!((complex.cosine - 0.7).abs() < 1e-7 && (complex.sine + 0.4).abs() < 1e-7, "{complex:?}");
    }

    /// A kernel like a spar's: a slow mode (its period 21 s, 60 s of kernel) beside a fast one
    /// and the ringing of `B` cut at 5 rad/s (`sin 5t / (1 + t)`, no finite sum of modes), sampled
    /// at 0.01 s. Its first 200 samples (2 s) show the realisation too little of the slow mode,
    /// so the fit at the kernel's own step misses the tolerance; the strided Hankel matrix
    /// reaches it.
    #[test]
    fn a_slowly_decaying_finely_sampled_kernel_is_fitted_from_the_strided_hankel_matrix() {
        let step = 0.01;
        let exact =
            |t: f64| (-0.05 * t).exp() * (0.3 * t).cos() + 3.0 * (-2.0 * t).exp() + 0.05 * (5.0 * t).sin() / (1.0 + t);
        let samples: Vec<f64> = (0..6000).map(|n| exact(n as f64 * step)).collect();
        let settings = FitSettings::new(2e-2, 30).expect("valid");
        let missed = fit_pair_with_stride(&samples, step, settings, 1);
        let (_, error) = fit_pair(&samples, step, settings).expect("a fit");
        println!("stride 1: {missed:?}; strided: {error:e}");
        assert!(missed.is_err(), "{missed:?}");
        assert!(error <= 2e-2, "error {error}");
    }

    #[test]
    fn settings_out_of_range_are_refused_by_name() {
        assert_eq!(FitSettings::new(0.0, 10).unwrap_err().to_string(), "fit_error must be > 0 and < 1, got 0");
        assert_eq!(FitSettings::new(1e-3, 0).unwrap_err().to_string(), "max_order must be at least 1, got 0");
        assert_eq!(FitSettings::new(1e-3, 61).unwrap_err().to_string(), "max_order must be at most 60, got 61");
    }
}
