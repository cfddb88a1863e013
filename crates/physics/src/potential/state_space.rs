//! The radiation force by a state-space approximation fitted to the kernel (PHYSICS.md §9):
//! `ẋ = A_r x + B_r q̇`, `F_r = −C_r x` [N, N·m], so that an evaluation costs `O(states)` and every
//! integrator carries the states like the bodies' own.
//!
//! Each nonzero pair `(i, j)` of the kernel is fitted on its own by a sum of damped modes,
//! `K_ij(t) ≈ Σ e^{σ t} (α cos ωt + β sin ωt)` (`σ < 0`; `ω = 0` for a real pole, whose `β`
//! is unused), in the frequency domain: its spectrum `K̂(iω) = ∫₀^∞ K̂(t) e^{−iωt} dt`, a rational
//! function of relative degree 1, against the kernel's own, `K(iω) = ∫₀^{t_K} K(t) e^{−iωt} dt =
//! B(ω) + iω (A(ω) − A∞)` (the truncated kernel's damping and added mass, Ogilvie's relations, as
//! Perez and Fossen's FDI toolbox fits them), on `ω_k = 0, Δω, …` up to the data's highest
//! frequency, `Δω = π/(2 t_K)`. The fit's error is the weighted relative L2 error
//! `√(Σ w_k² |K̂(iω_k) − K(iω_k)|² / Σ w_k² |K(iω_k)|²)`, `w_k = 1/max(|K(iω_k)|, 10⁻² max|K|)`:
//! each frequency's error relative to the spectrum there, down to 1 % of its peak, so that the
//! low frequencies, where `K(iω)` is small and a slow surge or a moored drift lives, are fitted
//! as closely as the peak (an error weighted by `|K|` alone, or the L2 error of `K(t)` over
//! `[0, t_K]`, leaves `K̂(0)`, the damping at ω → 0, and `A(0) − A∞` loose).
//!
//! The poles are found by vector fitting (Gustavsen and Semlyen 1999, relaxed as in Gustavsen
//! 2006): starting from complex pairs spread over the band (`σ = −ω/100`), each iteration solves
//! the linear least squares `Σ c Φ(iω_k) ≈ (d̃ + Σ c̃ Φ(iω_k)) K(iω_k)` (`Φ` the modes' state
//! responses, `Re Σ_k (d̃ + Σ c̃ Φ) = N` fixing the scale) and moves the poles to the zeros of
//! `d̃ + Σ c̃ Φ(s)`, the eigenvalues of `A − b c̃ᵀ/d̃`; an unstable zero is mirrored into the left
//! half-plane, and none decays slower than `Δω` (a narrower resonance would fall between the
//! fitted frequencies). The residues `α, β` of the iteration's poles are then fitted by the same
//! weighted least squares, and the iteration with the smallest error kept. The order rises
//! from 1 until the error reaches the stated tolerance.
//!
//! A real pole is one state, `ẋ = σ x + q̇_j`, giving `α x`; a complex pair is two,
//! `ẋ₁ = σ x₁ − ω x₂ + q̇_j`, `ẋ₂ = ω x₁ + σ x₂`, giving `α x₁ + β x₂` (their impulse
//! response is `e^{σt}(cos ωt, sin ωt)`); the pair's part of `F_r,i` is minus that.
//!
//! Written here on nalgebra's SVD and eigenvalues rather than taken from a crate: no Rust crate
//! does vector fitting (its implementations are Gustavsen's MATLAB `vectfit3` and scikit-rf's
//! Python `VectorFitting`, for electrical networks); the crate considered for the earlier
//! time-domain realisation, `deimos_numerics` (`control::identification::era`), realises
//! discrete-time systems from samples only and brings a whole control toolbox with it.

use super::coefficients::{Matrix6, Vector6};
use super::kernel::SampledKernel;
use crate::parameter::{Bound, ParameterError, require};
use nalgebra::{Complex, DMatrix, DVector};

/// How a kernel is fitted: the weighted relative error of its spectrum to reach (module docs)
/// and the highest order to try.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitSettings {
    tolerance: f64,
    max_order: u32,
}

/// The highest state-space order a pair may be fitted with.
const ORDER_LIMIT: u32 = 60;

impl FitSettings {
    /// `tolerance` (the weighted relative L2 error of the spectrum, in (0, 1)) and `max_order`
    /// (1 to 60 states per pair).
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
    /// The weighted relative L2 error of the spectrum the fit must reach.
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
        "radiation kernel K{i}{j}: no fit of order up to {max_order} reaches the relative error {tolerance:e} of its spectrum \
         (best {best:.3e} at order {order}); raise the order or the tolerance"
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
    /// The fit's weighted relative L2 error over the spectrum (module docs).
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
    /// `K̂_ij(iω) = ∫₀^∞ K̂_ij(t) e^{−iωt} dt`, the fitted kernel's spectrum at `omega` \[rad/s].
    pub fn spectrum(&self, omega: f64) -> Complex<f64> {
        fitted_spectrum(&self.modes, omega)
    }
}

/// A body's radiation states' equations: one [`PairFit`] per nonzero pair of its kernel.
#[derive(Debug, Clone, PartialEq)]
pub struct RadiationStateSpace {
    pairs: Vec<PairFit>,
    states: usize,
    /// What the fit was asked for.
    settings: FitSettings,
    /// The highest frequency fitted \[rad/s].
    band: f64,
    /// The fitted kernel's truncation `t_K` and sampling step \[s].
    kernel_duration: f64,
    kernel_step: f64,
}

/// `0, Δω, 2Δω, …` up to `band` \[rad/s], `Δω ≤ π/(2 t_K)`: half the spacing that resolves the
/// spectrum of a kernel `t_K` long; two frequencies at least.
fn frequency_grid(duration: f64, band: f64) -> Vec<f64> {
    let spacing = std::f64::consts::PI / (2.0 * duration);
    // A count of a finite band over a positive spacing (the caller's settings bound both).
    let count = (band / spacing).ceil().max(1.0) as usize;
    (0..=count).map(|k| band * k as f64 / count as f64).collect()
}

impl RadiationStateSpace {
    /// Fits every pair of `kernel` that is not numerical noise (a diagonal term below 1e-3 of the
    /// largest of its kind, a pair below 1e-2 of `√(K_ii K_jj)`:
    /// [`SampledKernel::significant_pairs`]), its spectrum from 0 to `band`
    /// \[rad/s], the panel code's highest frequency (beyond it the kernel's `B` is nothing).
    ///
    /// # Errors
    /// [`FitError::NotReached`] for the first pair no order up to the limit fits.
    pub fn fit(kernel: &SampledKernel, band: f64, settings: FitSettings) -> Result<Self, FitError> {
        let omegas = frequency_grid(kernel.duration(), band);
        let significant = kernel.significant_pairs();
        let mut pairs = Vec::new();
        let mut states = 0;
        for (i, row) in significant.iter().enumerate() {
            for (j, _) in row.iter().enumerate().filter(|(_, kept)| **kept) {
                let spectrum = DVector::from_vec(kernel.spectrum(i, j, &omegas));
                let pair = fit_pair(&omegas, &spectrum, settings).map_err(|(best, order)| FitError::NotReached {
                    i: i + 1,
                    j: j + 1,
                    tolerance: settings.tolerance,
                    max_order: settings.max_order,
                    best,
                    order,
                })?;
                let fitted = PairFit { i, j, error: pair.1, modes: pair.0, first_state: states };
                states += fitted.states();
                pairs.push(fitted);
            }
        }
        Ok(Self { pairs, states, settings, band, kernel_duration: kernel.duration(), kernel_step: kernel.step() })
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
    /// The highest frequency of the fitted spectrum \[rad/s] (from 0).
    pub fn band(&self) -> f64 {
        self.band
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

/// `(σ, ω)` of a mode: `σ < 0` [1/s], `ω ≥ 0` [rad/s] (0 for a real pole).
type Pole = (f64, f64);

/// The relocation iterations of vector fitting at each order; the best of them is kept.
const ITERATIONS: usize = 12;

/// The transfer functions `(x₁/u, x₂/u)` of a mode's states at `s = iω` (module docs):
/// `1/(s − σ)` and 0 for a real pole; `½ (1/(s − λ) + 1/(s − λ̄))` and `(1/(s − λ) − 1/(s − λ̄))/2i`
/// for a pair, the Laplace transforms of `e^{σt} cos ωt` and `e^{σt} sin ωt`.
fn state_responses(pole: Pole, omega: f64) -> (Complex<f64>, Complex<f64>) {
    let s = Complex::new(0.0, omega);
    let (decay, frequency) = pole;
    if frequency == 0.0 {
        return (Complex::from(1.0) / (s - decay), Complex::from(0.0));
    }
    let lambda = Complex::new(decay, frequency);
    let (a, b) = (Complex::from(1.0) / (s - lambda), Complex::from(1.0) / (s - lambda.conj()));
    ((a + b) * 0.5, (a - b) * Complex::new(0.0, -0.5))
}

/// The states of `poles` in order: `(pole, second)` per state, `second` for a pair's `x₂`.
fn states_of(poles: &[Pole]) -> impl Iterator<Item = (Pole, bool)> + '_ {
    poles.iter().flat_map(|&p| {
        let pair = p.1 != 0.0;
        std::iter::once((p, false)).chain(pair.then_some((p, true)))
    })
}

/// The matrix `Φ` of every state's response at every frequency (a row per frequency).
fn responses(poles: &[Pole], omegas: &[f64]) -> DMatrix<Complex<f64>> {
    let columns: Vec<(Pole, bool)> = states_of(poles).collect();
    DMatrix::from_fn(omegas.len(), columns.len(), |r, c| {
        let (pole, second) = columns[c];
        let (x1, x2) = state_responses(pole, omegas[r]);
        if second { x2 } else { x1 }
    })
}

/// The least-squares solution of the complex system `matrix · x = target` for real `x`: each
/// row split into its real and imaginary parts. `None` when the SVD finds no solution.
fn real_least_squares(
    matrix: &DMatrix<Complex<f64>>,
    target: &DVector<Complex<f64>>,
    weights: &[f64],
) -> Option<DVector<f64>> {
    let rows = matrix.nrows();
    let real = DMatrix::from_fn(2 * rows, matrix.ncols(), |r, c| {
        let v = matrix[(r / 2, c)] * weights[r / 2];
        if r % 2 == 0 { v.re } else { v.im }
    });
    let right = DVector::from_fn(2 * rows, |r, _| {
        let v = target[r / 2] * weights[r / 2];
        if r % 2 == 0 { v.re } else { v.im }
    });
    real.svd(true, true).solve(&right, 1e-14).ok()
}

/// The modes with `poles` whose spectrum is nearest `spectrum` at `omegas` in the least-squares
/// sense: their coefficients `α, β` are the output matrix `C_r`.
fn fit_residues(
    poles: &[Pole],
    omegas: &[f64],
    spectrum: &DVector<Complex<f64>>,
    weights: &[f64],
) -> Option<Vec<Mode>> {
    let solution = real_least_squares(&responses(poles, omegas), spectrum, weights)?;
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

/// `K̂(iω)` of `modes`.
fn fitted_spectrum(modes: &[Mode], omega: f64) -> Complex<f64> {
    modes
        .iter()
        .map(|m| {
            let (x1, x2) = state_responses((m.decay, m.frequency), omega);
            x1 * m.cosine + x2 * m.sine
        })
        .sum()
}

/// The fit's error (module docs): `‖w (K̂ − K)‖ / ‖w K‖` over `omegas`.
fn spectrum_error(modes: &[Mode], omegas: &[f64], spectrum: &DVector<Complex<f64>>, weights: &[f64]) -> f64 {
    let misfit: f64 = omegas
        .iter()
        .zip(spectrum.iter())
        .zip(weights)
        .map(|((&w, k), g)| (g * (fitted_spectrum(modes, w) - k)).norm_sqr())
        .sum();
    let norm: f64 = spectrum.iter().zip(weights).map(|(k, g)| (g * k).norm_sqr()).sum();
    (misfit / norm).sqrt()
}

/// The fraction of the spectrum's peak below which a frequency's error is weighted as at it.
const WEIGHT_FLOOR: f64 = 1e-2;

/// `w_k = 1/max(|K(iω_k)|, 10⁻² max|K|)` (module docs).
fn weights_of(spectrum: &DVector<Complex<f64>>) -> Vec<f64> {
    let peak = spectrum.iter().map(|k| k.norm()).fold(0.0, f64::max);
    spectrum.iter().map(|k| 1.0 / k.norm().max(WEIGHT_FLOOR * peak)).collect()
}

/// The starting poles of order `order` over `[0, band]`: complex pairs at `ω_k` evenly spread,
/// `σ_k = −ω_k/100` (Gustavsen and Semlyen's choice), and one real pole for an odd order.
fn starting_poles(order: usize, band: f64) -> Vec<Pole> {
    let pairs = order / 2;
    let mut poles: Vec<Pole> = (0..pairs)
        .map(|k| {
            let w = band * (k as f64 + 0.5) / pairs as f64;
            (-w / 100.0, w)
        })
        .collect();
    if order % 2 == 1 {
        poles.push((-band / (2.0 * (pairs + 1) as f64), 0.0));
    }
    poles
}

/// One relocation of vector fitting (Gustavsen and Semlyen 1999, relaxed as in Gustavsen 2006):
/// the denominator `σ(s) = d̃ + Σ c̃ Φ(s)` of [`relaxed_denominator`], whose zeros are the new
/// poles ([`denominator_zeros`]). `None` when the least squares or the zeros fail.
fn relocate(
    poles: &[Pole],
    omegas: &[f64],
    spectrum: &DVector<Complex<f64>>,
    weights: &[f64],
    slowest: f64,
) -> Option<Vec<Pole>> {
    let (scale, residues) = relaxed_denominator(&responses(poles, omegas), spectrum, weights)?;
    denominator_zeros(poles, &(residues / scale), slowest)
}

/// `d̃` and `c̃` of the real least squares `Σ c Φ(iω_k) ≈ (d̃ + Σ c̃ Φ(iω_k)) K(iω_k)`, weighted
/// by `w_k`, with `Re Σ_k (d̃ + Σ c̃ Φ(iω_k)) = N` (`N` frequencies) fixing the scale; `d̃` kept
/// from 0 (at least 1e-8 in size). The unknowns are `(c, d̃, c̃)`.
fn relaxed_denominator(
    phi: &DMatrix<Complex<f64>>,
    spectrum: &DVector<Complex<f64>>,
    weights: &[f64],
) -> Option<(f64, DVector<f64>)> {
    let (rows, n) = phi.shape();
    let mut matrix = DMatrix::zeros(2 * rows + 1, 2 * n + 1);
    for r in 0..rows {
        let (g, k) = (weights[r], spectrum[r]);
        let mut put = |c: usize, v: Complex<f64>| {
            matrix[(2 * r, c)] = g * v.re;
            matrix[(2 * r + 1, c)] = g * v.im;
        };
        put(n, -k);
        for c in 0..n {
            put(c, phi[(r, c)]);
            put(n + 1 + c, -phi[(r, c)] * k);
        }
    }
    // The constraint's row, scaled as the others: the weighted spectrum's RMS.
    let scale = spectrum.iter().zip(weights).map(|(k, g)| (g * k).norm_sqr()).sum::<f64>().sqrt() / rows as f64;
    matrix[(2 * rows, n)] = scale * rows as f64;
    for c in 0..n {
        matrix[(2 * rows, n + 1 + c)] = scale * phi.column(c).iter().map(|v| v.re).sum::<f64>();
    }
    let mut right = DVector::zeros(2 * rows + 1);
    right[2 * rows] = scale * rows as f64;
    let solution = matrix.svd(true, true).solve(&right, 1e-14).ok()?;
    let d = solution[n];
    Some((if d.abs() < 1e-8 { 1e-8_f64.copysign(d) } else { d }, solution.rows(n + 1, n).into_owned()))
}

/// The zeros of `1 + Σ c Φ(s)` for the modes' poles: the eigenvalues of `A − b cᵀ` (`A`, `b` the
/// modes' own `A_r`, `B_r`, a 1 at each mode's first state), one pole per real zero or
/// conjugate pair, an unstable one mirrored into the left half-plane, none decaying slower than
/// `slowest`. `None` when they do not make as many states (a pair split unevenly by round-off).
fn denominator_zeros(poles: &[Pole], c: &DVector<f64>, slowest: f64) -> Option<Vec<Pole>> {
    let n = c.len();
    let mut system = DMatrix::zeros(n, n);
    let mut s = 0;
    for &(decay, frequency) in poles {
        system[(s, s)] = decay;
        if frequency != 0.0 {
            system[(s, s + 1)] = -frequency;
            system[(s + 1, s)] = frequency;
            system[(s + 1, s + 1)] = decay;
        }
        for (column, value) in c.iter().enumerate() {
            system[(s, column)] -= value;
        }
        s += if frequency == 0.0 { 1 } else { 2 };
    }
    let zeros: Vec<Pole> = system
        .complex_eigenvalues()
        .iter()
        .filter_map(|z| {
            let decay = -z.re.abs().max(slowest);
            let real = z.im.abs() <= 1e-9 * z.norm();
            if real { Some((decay, 0.0)) } else { (z.im > 0.0).then_some((decay, z.im)) }
        })
        .collect();
    let states: usize = zeros.iter().map(|p| if p.1 == 0.0 { 1 } else { 2 }).sum();
    (states == n).then_some(zeros)
}

/// The modes of the lowest order whose error reaches the tolerance, with that error; or the
/// best error and its order when none does. At each order the poles start evenly spread over
/// the band and are relocated [`ITERATIONS`] times; the residues of the best poles are kept.
fn fit_pair(
    omegas: &[f64],
    spectrum: &DVector<Complex<f64>>,
    settings: FitSettings,
) -> Result<(Vec<Mode>, f64), (f64, usize)> {
    let band = omegas.last().copied().unwrap_or(0.0);
    // The grid has at least two frequencies (`frequency_grid`).
    let slowest = omegas[1] - omegas[0];
    let weights = weights_of(spectrum);
    let weights = &weights;
    let mut best = (f64::INFINITY, 0);
    for order in 1..=settings.max_order as usize {
        let mut poles = starting_poles(order, band);
        let mut best_here: Option<(Vec<Mode>, f64)> = None;
        for _ in 0..ITERATIONS {
            let Some(moved) = relocate(&poles, omegas, spectrum, weights, slowest) else { break };
            poles = moved;
            let Some(modes) = fit_residues(&poles, omegas, spectrum, weights) else { break };
            let error = spectrum_error(&modes, omegas, spectrum, weights);
            if best_here.as_ref().is_none_or(|b| error < b.1) {
                best_here = Some((modes, error));
            }
        }
        let Some((modes, error)) = best_here else { continue };
        if error <= settings.tolerance {
            return Ok((modes, error));
        }
        if error < best.0 {
            best = (error, order);
        }
    }
    Err(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A spectrum that is that of two modes, `2 e^{−0.5t} + e^{−0.2t} (0.7 cos 1.3t − 0.4 sin 1.3t)`,
    /// in closed form, `2/(s + 0.5) + (0.7 (s + 0.2) − 0.4 · 1.3)/((s + 0.2)² + 1.3²)`, is fitted
    /// exactly at order 3 (one real pole, one complex pair), and its poles and residues are found.
    #[test]
    fn a_spectrum_of_exact_modes_is_recovered_at_its_own_order() {
        let exact = |w: f64| {
            let s = Complex::new(0.0, w);
            let shifted = s + 0.2;
            Complex::from(2.0) / (s + 0.5) + (shifted * 0.7 - 0.4 * 1.3) / (shifted * shifted + 1.3 * 1.3)
        };
        let omegas = frequency_grid(30.0, 4.0);
        let spectrum = DVector::from_iterator(omegas.len(), omegas.iter().map(|&w| exact(w)));
        let (modes, error) = fit_pair(&omegas, &spectrum, FitSettings::new(1e-9, 10).expect("valid")).expect("a fit");
        assert!(error < 1e-9, "error {error}");
        assert_eq!(modes.iter().map(Mode::states).sum::<usize>(), 3);
        let real = modes.iter().find(|m| m.is_real()).expect("a real pole");
        assert!((real.decay + 0.5).abs() < 1e-7 && (real.cosine - 2.0).abs() < 1e-7, "{real:?}");
        let complex = modes.iter().find(|m| !m.is_real()).expect("a complex pair");
        assert!((complex.decay + 0.2).abs() < 1e-7 && (complex.frequency - 1.3).abs() < 1e-7, "{complex:?}");
        assert!((complex.cosine - 0.7).abs() < 1e-7 && (complex.sine + 0.4).abs() < 1e-7, "{complex:?}");
    }

    /// The weights hold the spectrum where it is small: a kernel like a body's surge, `K(iω)`
    /// vanishing at ω = 0 (`B(0) = 0`) as `iω a` with a peak 100 × larger at 1 rad/s — a complex
    /// pair `k (s/((s + 0.3)² + 1))` — plus 2 % of the peak in a fast real mode, its residues
    /// fitted with the pair's pole alone, which cannot hold both: the weighted fit keeps `K̂(0)`
    /// within 2e-3 of the peak (measured 9.2e-4), an unweighted one (all `w = 1`) misses it by
    /// more than 1e-2 (1.5e-2).
    #[test]
    fn the_weights_hold_the_low_frequencies() {
        let exact = |w: f64| {
            let s = Complex::new(0.0, w);
            let shifted = s + 0.3;
            s * 1.0e3 / (shifted * shifted + 1.0) + Complex::from(0.02 * 1.6e3 * 6.0) / (s + 6.0)
        };
        let omegas = frequency_grid(30.0, 5.0);
        let spectrum = DVector::from_iterator(omegas.len(), omegas.iter().map(|&w| exact(w)));
        let peak = spectrum.iter().map(|k| k.norm()).fold(0.0, f64::max);
        let weights = weights_of(&spectrum);
        let uniform = vec![1.0; omegas.len()];
        let poles = [(-0.3, 1.0)];
        let weighted = fit_residues(&poles, &omegas, &spectrum, &weights).expect("a fit");
        let plain = fit_residues(&poles, &omegas, &spectrum, &uniform).expect("a fit");
        let at_zero = |modes: &[Mode]| (fitted_spectrum(modes, 0.0) - spectrum[0]).norm() / peak;
        println!("K̂(0) − K(0): weighted {:.2e}, unweighted {:.2e} of the peak", at_zero(&weighted), at_zero(&plain));
        assert!(at_zero(&weighted) < 2e-3 && at_zero(&plain) > 1e-2);
    }

    #[test]
    fn settings_out_of_range_are_refused_by_name() {
        assert_eq!(FitSettings::new(0.0, 10).unwrap_err().to_string(), "fit_error must be > 0 and < 1, got 0");
        assert_eq!(FitSettings::new(1e-3, 0).unwrap_err().to_string(), "max_order must be at least 1, got 0");
        assert_eq!(FitSettings::new(1e-3, 61).unwrap_err().to_string(), "max_order must be at most 60, got 61");
    }
}
