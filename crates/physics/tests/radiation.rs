//! The radiation kernel and its two evaluations (PHYSICS.md §9, "Closed forms and checks"; issue
//! 33, check 1): the kernel of a tabulated `B(ω)` against its closed form, the state-space fit
//! within its stated error, and the state-space and convolution forces on the same `q̇(t)`.

use nalgebra::Complex;
use std::f64::consts::PI;
use tether_physics::potential::kernel::kernel_from_damping;
use tether_physics::potential::{
    Coefficients, CoefficientsData, ComplexVector6, Convolution, Excitation, FitSettings, Matrix6, RadiationStateSpace,
    SampledKernel, Vector6,
};

/// `B(ω) = b e^{−(ω/ω_c)²}` ↔ `K(t) = (b ω_c/√π) e^{−(ω_c t)²/4}`.
fn gaussian_kernel(b: f64, omega_c: f64, t: f64) -> f64 {
    b * omega_c / PI.sqrt() * (-(omega_c * t).powi(2) / 4.0).exp()
}

/// `B(ω) = b (ω/ω_c)² e^{−(ω/ω_c)²}` (nothing at ω = 0, as a body's) ↔
/// `K(t) = (b ω_c/√π) e^{−(ω_c t)²/4} (½ − (ω_c t)²/4)`: minus the second derivative of the
/// Gaussian's kernel over `ω_c²`.
fn vanishing_damping(b: f64, omega_c: f64, omega: f64) -> f64 {
    let x = omega / omega_c;
    b * x * x * (-x * x).exp()
}
fn vanishing_kernel(b: f64, omega_c: f64, t: f64) -> f64 {
    gaussian_kernel(b, omega_c, t) * (0.5 - (omega_c * t).powi(2) / 4.0)
}

#[test]
fn the_kernel_of_a_gaussian_damping_is_its_closed_form_to_1e_6() {
    let (b, omega_c) = (2.5e4, 1.3);
    // 12 000 linear pieces to 6 ω_c (e^{−36} beyond): the interpolation error is h²/12 B''.
    let omega: Vec<f64> = (0..=12_000).map(|n| n as f64 * 6.0 * omega_c / 12_000.0).collect();
    let damping: Vec<f64> = omega.iter().map(|w| b * (-(w / omega_c).powi(2)).exp()).collect();
    let peak = gaussian_kernel(b, omega_c, 0.0);
    let (mut worst_of_peak, mut worst_relative) = (0.0_f64, 0.0_f64);
    for n in 0..=600 {
        let t = n as f64 * 0.01;
        let (k, exact) = (kernel_from_damping(&omega, &damping, t), gaussian_kernel(b, omega_c, t));
        worst_of_peak = worst_of_peak.max((k - exact).abs() / peak);
        if exact > 1e-3 * peak {
            worst_relative = worst_relative.max((k / exact - 1.0).abs());
        }
    }
    println!(
        "Gaussian B: |K − K_exact| ≤ {worst_of_peak:.2e} K(0); ≤ {worst_relative:.2e} K_exact where K ≥ 1e-3 K(0)"
    );
    assert!(worst_of_peak < 1e-6, "|K − K_exact| / K(0) up to {worst_of_peak:e}");
    assert!(worst_relative < 1e-6, "|K/K_exact − 1| up to {worst_relative:e} where K ≥ 1e-3 K(0)");
}

/// A body whose damping is the vanishing Gaussian in heave (`b₃₃`) and in the surge–pitch pair
/// (`b₁₅ = b₅₁`, `b₁₁`, `b₅₅`), its added mass constant (only `B` makes the kernel).
fn body(omega_c: f64) -> Coefficients {
    let frequencies: Vec<f64> = (1..=3000).map(|n| n as f64 * 6.0 * omega_c / 3000.0).collect();
    let shape = Matrix6::from_fn(|i, j| match (i, j) {
        (0, 0) => 2.0e5,
        (2, 2) => 1.0e5,
        (4, 4) => 5.0e7,
        (0, 4) | (4, 0) => -1.5e6,
        _ => 0.0,
    });
    let added = Matrix6::identity() * 1.0e4;
    Coefficients::new(CoefficientsData {
        damping: frequencies.iter().map(|&w| shape * vanishing_damping(1.0, omega_c, w)).collect(),
        added_mass: vec![added; frequencies.len()],
        frequencies,
        added_mass_infinite: added,
        added_mass_zero: added,
        excitation: Excitation { frequencies: vec![1.0], headings: vec![0.0], values: vec![ComplexVector6::zeros()] },
        hydrostatic_stiffness: None,
        mean_drift: None,
    })
    .expect("the test body's data are valid")
}

#[test]
fn a_bodys_sampled_kernel_is_the_closed_form_pair_by_pair() {
    let omega_c = 0.9;
    let kernel = SampledKernel::from_damping(&body(omega_c), 0.05, 12.0);
    let peak = vanishing_kernel(1.0, omega_c, 0.0);
    for (n, k) in kernel.values().iter().enumerate() {
        let shape = vanishing_kernel(1.0, omega_c, n as f64 * 0.05);
        for (i, j, b) in [(0, 0, 2.0e5), (2, 2, 1.0e5), (4, 4, 5.0e7), (0, 4, -1.5e6), (4, 0, -1.5e6)] {
            assert!(
                (k[(i, j)] - b * shape).abs() < 1e-5 * b.abs() * peak,
                "K{i}{j}({n}): {} against {}",
                k[(i, j)],
                b * shape
            );
        }
        assert_eq!(k[(1, 1)], 0.0, "a pair without damping has no kernel");
    }
}

/// The fit's stated error (its spectrum's, weighted as `state_space.rs` says) holds against the
/// closed form's; the kernel is sampled at 0.01 s, since `K` linear between samples `Δt` apart
/// has a spectrum off the true one by about `(ωΔt)²/12` (3e-5 at 2 rad/s; 8e-4 at 0.05 s, more
/// than the error to check). Then the state space and the convolution give the same force.
#[test]
fn the_state_space_fit_is_within_its_stated_error_and_the_two_forces_agree_to_1e_3() {
    let omega_c = 0.9;
    let (t_k, step) = (12.0, 0.01);
    let kernel = SampledKernel::from_damping(&body(omega_c), step, t_k);
    let settings = FitSettings::new(1e-4, 30).expect("valid settings");
    let band = 6.0 * omega_c;
    let fit = RadiationStateSpace::fit(&kernel, band, settings).expect("a fit within 1e-4");
    assert_eq!(fit.pairs().len(), 5, "the five nonzero pairs, each fitted");
    // The stated error holds against the closed form's spectrum (a fine Simpson quadrature of
    // `K(t) e^{−iωt}` over 15 s) on a grid 5 × finer than the fit's, weighted as the fit is.
    let closed_form_spectrum = |omega: f64| {
        let term = |t: f64| Complex::from_polar(vanishing_kernel(1.0, omega_c, t), -omega * t);
        tether_test_support::simpson(term, 0.0, 15.0, 15_000)
    };
    let omegas: Vec<f64> = (0..=210).map(|k| k as f64 * band / 210.0).collect();
    let shape: Vec<Complex<f64>> = omegas.iter().map(|&w| closed_form_spectrum(w)).collect();
    let peak = shape.iter().map(|k| k.norm()).fold(0.0, f64::max);
    for pair in fit.pairs() {
        assert!(pair.error <= 1e-4, "K{}{}: stated error {}", pair.i + 1, pair.j + 1, pair.error);
        let scale = kernel.values()[0][(pair.i, pair.j)] / vanishing_kernel(1.0, omega_c, 0.0);
        let (mut diff, mut norm) = (0.0, 0.0);
        for (&w, k) in omegas.iter().zip(&shape) {
            let weight = 1.0 / (scale.abs() * k.norm().max(1e-2 * peak));
            diff += (weight * (pair.spectrum(w) - k * scale)).norm_sqr();
            norm += (weight * k * scale).norm_sqr();
        }
        let error = (diff / norm).sqrt();
        println!(
            "K{}{}: {} states, stated error {:.2e}, against the closed form {error:.2e}",
            pair.i + 1,
            pair.j + 1,
            pair.states(),
            pair.error
        );
        assert!(error <= 1.2e-4, "K{}{}: {error:e} against the closed form", pair.i + 1, pair.j + 1);
    }
    // The same q̇(t) through both: the convolution on the kernel sampled at the run's step,
    // the states by RK4 at the same step.
    let dt = 0.01;
    let mut convolution = Convolution::new(SampledKernel::from_damping(&body(omega_c), dt, t_k));
    let velocity = |t: f64| {
        let ramp = 1.0 - (-t / 3.0).exp();
        Vector6::new(0.4 * (0.7 * t).sin(), 0.3, 0.8 * (1.1 * t + 0.4).sin(), 0.0, 0.05 * (0.5 * t).cos(), 0.0) * ramp
    };
    let mut states = vec![0.0; fit.state_count()];
    let rates = |x: &[f64], t: f64| {
        let mut r = vec![0.0; x.len()];
        fit.rates(x, &velocity(t), &mut r);
        r
    };
    let (mut worst, mut largest) = (0.0_f64, Vector6::zeros());
    for n in 0..=6000 {
        let t = n as f64 * dt;
        let reference = convolution.push(velocity(t));
        let state_space = fit.force(&states);
        worst = worst.max((state_space - reference).amax());
        largest = largest.zip_map(&reference, |l, r| l.max(r.abs()));
        let k1 = rates(&states, t);
        let x2: Vec<f64> = states.iter().zip(&k1).map(|(x, k)| x + 0.5 * dt * k).collect();
        let k2 = rates(&x2, t + 0.5 * dt);
        let x3: Vec<f64> = states.iter().zip(&k2).map(|(x, k)| x + 0.5 * dt * k).collect();
        let k3 = rates(&x3, t + 0.5 * dt);
        let x4: Vec<f64> = states.iter().zip(&k3).map(|(x, k)| x + dt * k).collect();
        let k4 = rates(&x4, t + dt);
        for (s, x) in states.iter_mut().enumerate() {
            *x += dt / 6.0 * (k1[s] + 2.0 * k2[s] + 2.0 * k3[s] + k4[s]);
        }
    }
    let relative = worst / largest.amax();
    println!("state space against convolution over 60 s: {relative:.2e} of the largest force {:.3e}", largest.amax());
    assert!(relative < 1e-3, "{relative:e}");
}
