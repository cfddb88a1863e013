//! The linear frequency-domain response of a floating body in regular waves (PHYSICS.md §9,
//! "Closed forms and checks"): `q = Re{a ξ e^{iωt}}` with
//! `ξ = [−ω² (M + A(ω)) + iω B(ω) + C]⁻¹ X(ω, β)` per unit wave amplitude (m/m, rad/m), in
//! WAMIT's convention (a phase leads). What `tether rao` will print, and what a time-domain run in
//! small regular waves must settle to.

use super::coefficients::{Coefficients, ComplexVector6, Matrix6};
use nalgebra::Complex;

/// `ξ(ω)` at heading index `heading` of the excitation, `A`, `B` and `X` interpolated linearly
/// in ω; `mass` the body's 6 × 6 rigid-body mass about the reference point \[kg, kg·m, kg·m²],
/// `stiffness` its linear hydrostatic (and mooring) stiffness. `None` where the system is
/// singular (an undamped resonance, or a dof with neither mass nor stiffness).
pub fn response(
    coefficients: &Coefficients,
    mass: &Matrix6,
    stiffness: &Matrix6,
    omega: f64,
    heading: usize,
) -> Option<ComplexVector6> {
    let (added, damping) = coefficients.radiation_at(omega);
    let real = -(mass + added) * omega * omega + stiffness;
    let imaginary = damping * omega;
    let system = real.zip_map(&imaginary, Complex::new);
    system.lu().solve(&coefficients.excitation().interpolate(omega, heading))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::potential::coefficients::{CoefficientsData, Excitation, Vector6};

    /// One dof: heave `m ẍ + b ẋ + c x = Re{X e^{iωt}}` gives `ξ = X/(c − ω²(m + a) + iωb)`.
    #[test]
    fn a_single_dof_is_the_damped_oscillator() {
        let (m, a, b, c, x) = (2.0e3, 5.0e2, 3.0e2, 4.0e4, Complex::new(1.0e4, -2.0e3));
        let heave = |v: f64| Matrix6::from_diagonal(&Vector6::new(1.0, 1.0, v, 1.0, 1.0, 1.0));
        let coefficients = Coefficients::new(CoefficientsData {
            frequencies: vec![1.0, 5.0],
            added_mass: vec![heave(a); 2],
            damping: vec![heave(b); 2],
            added_mass_infinite: heave(a),
            added_mass_zero: heave(a),
            excitation: Excitation {
                frequencies: vec![1.0, 5.0],
                headings: vec![0.0],
                values: vec![ComplexVector6::from_fn(|i, _| if i == 2 { x } else { Complex::ZERO }); 2],
            },
            hydrostatic_stiffness: None,
            mean_drift: None,
        })
        .expect("valid data");
        let omega = 3.0;
        let xi = response(&coefficients, &heave(m), &heave(c), omega, 0).expect("not singular");
        let expected = x / Complex::new(c - omega * omega * (m + a), omega * b);
        assert!((xi[2] - expected).norm() < 1e-12 * expected.norm(), "{} against {expected}", xi[2]);
        assert!(xi[0].norm() == 0.0 && xi[4].norm() == 0.0);
    }
}
