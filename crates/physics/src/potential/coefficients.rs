//! A body's frequency-domain potential-flow data (PHYSICS.md §9, "Frequency-domain data"): added
//! mass `A(ω)` and radiation damping `B(ω)` (6 × 6), their limits `A∞` and `A(0)`, and the
//! first-order excitation `X(ω, β)` per unit wave amplitude, all about the body's reference
//! point, in SI units and WAMIT's time convention (`Re{Z e^{+iωt}}`).
//!
//! Units: `A` in kg, kg·m, kg·m² (translation–translation, mixed, rotation–rotation); `B` in
//! kg/s, kg·m/s, kg·m²/s; `X` in N/m and N·m/m; `ω` in rad/s; `β` in rad. Degrees of freedom in
//! the order surge, sway, heave, roll, pitch, yaw.

use super::drift::MeanDrift;
pub use super::tables::CoefficientsError;
use super::tables::{bracket_frequency, check_count, check_finite, check_frequencies, check_headings};
use nalgebra::Complex;

/// 6 × 6 matrix over the body's degrees of freedom (added mass, damping, stiffness).
pub type Matrix6 = nalgebra::Matrix6<f64>;
/// A 6-vector over the body's degrees of freedom (velocities, forces and moments).
pub type Vector6 = nalgebra::Vector6<f64>;
/// A complex 6-vector: an excitation per unit wave amplitude, or a response amplitude.
pub type ComplexVector6 = nalgebra::Vector6<Complex<f64>>;

/// The excitation `X(ω, β)` per unit wave amplitude at its frequencies and headings.
#[derive(Debug, Clone, PartialEq)]
pub struct Excitation {
    /// Frequencies `ω` [rad/s], strictly increasing, > 0.
    pub frequencies: Vec<f64>,
    /// Headings `β` \[rad], strictly increasing: the direction the waves travel to, from +x
    /// toward +y (PHYSICS.md §9, the incident wave `η = Re{a e^{i(ωt − k(x cos β + y sin β))}}`).
    pub headings: Vec<f64>,
    /// `X` [N/m, N·m/m], heading by heading: `values[h * frequencies.len() + f]`.
    pub values: Vec<ComplexVector6>,
}

impl Excitation {
    /// `X(ω_f, β_h)` at a given frequency and heading index.
    pub fn at(&self, heading: usize, frequency: usize) -> ComplexVector6 {
        self.values[heading * self.frequencies.len() + frequency]
    }

    /// `X(ω, β_h)` interpolated linearly in ω (real and imaginary parts) at heading index
    /// `heading`; outside the frequencies, the end value held.
    pub fn interpolate(&self, omega: f64, heading: usize) -> ComplexVector6 {
        let bracket = bracket_frequency(&self.frequencies, omega);
        let (x0, x1) = (self.at(heading, bracket.lower), self.at(heading, bracket.upper));
        if bracket.upper == bracket.lower {
            return x0;
        }
        x0 + (x1 - x0) * Complex::from(bracket.fraction)
    }
}

/// A body's frequency-domain data, checked once ([`Coefficients::new`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Coefficients {
    frequencies: Vec<f64>,
    added_mass: Vec<Matrix6>,
    damping: Vec<Matrix6>,
    added_mass_infinite: Matrix6,
    added_mass_zero: Matrix6,
    excitation: Excitation,
    hydrostatic_stiffness: Option<Matrix6>,
    mean_drift: Option<MeanDrift>,
}

/// What [`Coefficients::new`] is built from: the panel code's data, already in SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct CoefficientsData {
    /// The finite frequencies of `A` and `B` [rad/s].
    pub frequencies: Vec<f64>,
    /// `A(ω)` at each frequency.
    pub added_mass: Vec<Matrix6>,
    /// `B(ω)` at each frequency.
    pub damping: Vec<Matrix6>,
    /// `A∞ = A(ω → ∞)`.
    pub added_mass_infinite: Matrix6,
    /// `A(0)`.
    pub added_mass_zero: Matrix6,
    /// `X(ω, β)`.
    pub excitation: Excitation,
    /// The linear hydrostatic stiffness `C` [N/m, N, N·m/rad] when the panel code gave one.
    pub hydrostatic_stiffness: Option<Matrix6>,
    /// The mean drift coefficients `D(ω, β)` when the panel code gave them (PHYSICS.md §10).
    pub mean_drift: Option<MeanDrift>,
}

impl Coefficients {
    /// Checks the data: at least one frequency, strictly increasing and positive (for `A`, `B`
    /// and for `X`), headings strictly increasing, one matrix per frequency and one `X` per
    /// frequency and heading, every number finite, and `A∞` the limit of `A(ω)`: for each
    /// diagonal term the highest frequency's `A_ii` lies no nearer `A(0)_ii` than `A∞_ii` (relative
    /// to the term's size), which a file with the two limits swapped fails.
    ///
    /// # Errors
    /// The first rule broken, as a [`CoefficientsError`].
    pub fn new(data: CoefficientsData) -> Result<Self, CoefficientsError> {
        check_frequencies("added mass and damping", &data.frequencies)?;
        check_count("added mass", data.added_mass.len(), data.frequencies.len(), "")?;
        check_count("damping", data.damping.len(), data.frequencies.len(), "")?;
        check_finite("added mass", data.added_mass.iter().map(|m| m.iter().all(|v| v.is_finite())))?;
        check_finite("damping", data.damping.iter().map(|m| m.iter().all(|v| v.is_finite())))?;
        check_finite("added mass at ω = ∞", std::iter::once(data.added_mass_infinite.iter().all(|v| v.is_finite())))?;
        check_finite("added mass at ω = 0", std::iter::once(data.added_mass_zero.iter().all(|v| v.is_finite())))?;
        if let Some(c) = &data.hydrostatic_stiffness {
            check_finite("hydrostatic stiffness", std::iter::once(c.iter().all(|v| v.is_finite())))?;
        }
        check_excitation(&data.excitation)?;
        check_limits(&data)?;
        Ok(Self {
            frequencies: data.frequencies,
            added_mass: data.added_mass,
            damping: data.damping,
            added_mass_infinite: data.added_mass_infinite,
            added_mass_zero: data.added_mass_zero,
            excitation: data.excitation,
            hydrostatic_stiffness: data.hydrostatic_stiffness,
            mean_drift: data.mean_drift,
        })
    }

    /// The finite frequencies of `A` and `B` [rad/s], increasing.
    pub fn frequencies(&self) -> &[f64] {
        &self.frequencies
    }
    /// The highest frequency \[rad/s] (the list is not empty: [`Self::new`] refuses an empty one).
    pub fn highest_frequency(&self) -> f64 {
        self.frequencies[self.frequencies.len() - 1]
    }
    /// `A(ω)` at each of [`Self::frequencies`].
    pub fn added_mass(&self) -> &[Matrix6] {
        &self.added_mass
    }
    /// `B(ω)` at each of [`Self::frequencies`].
    pub fn damping(&self) -> &[Matrix6] {
        &self.damping
    }
    /// `A∞`.
    pub fn added_mass_infinite(&self) -> &Matrix6 {
        &self.added_mass_infinite
    }
    /// `A(0)`.
    pub fn added_mass_zero(&self) -> &Matrix6 {
        &self.added_mass_zero
    }
    /// `X(ω, β)`.
    pub fn excitation(&self) -> &Excitation {
        &self.excitation
    }
    /// The panel code's linear hydrostatic stiffness, when it gave one.
    pub fn hydrostatic_stiffness(&self) -> Option<&Matrix6> {
        self.hydrostatic_stiffness.as_ref()
    }
    /// The mean drift coefficients `D(ω, β)`, when the panel code gave them.
    pub fn mean_drift(&self) -> Option<&MeanDrift> {
        self.mean_drift.as_ref()
    }

    /// `A(ω)` and `B(ω)` interpolated linearly in ω: below the first frequency between `A(0)`,
    /// `B(0) = 0` (a three-dimensional body radiates nothing as ω → 0) and the first point; above
    /// the last, the last point held.
    pub fn radiation_at(&self, omega: f64) -> (Matrix6, Matrix6) {
        let n = self.frequencies.len();
        let upper = self.frequencies.partition_point(|&w| w < omega);
        if upper == 0 {
            let s = (omega / self.frequencies[0]).clamp(0.0, 1.0);
            return (self.added_mass_zero + (self.added_mass[0] - self.added_mass_zero) * s, self.damping[0] * s);
        }
        if upper == n {
            return (self.added_mass[n - 1], self.damping[n - 1]);
        }
        let (w0, w1) = (self.frequencies[upper - 1], self.frequencies[upper]);
        let s = (omega - w0) / (w1 - w0);
        let lerp = |m: &[Matrix6]| m[upper - 1] + (m[upper] - m[upper - 1]) * s;
        (lerp(&self.added_mass), lerp(&self.damping))
    }
}

fn check_excitation(excitation: &Excitation) -> Result<(), CoefficientsError> {
    check_frequencies("excitation", &excitation.frequencies)?;
    let headings = &excitation.headings;
    check_headings("excitation", headings)?;
    check_count("excitation", excitation.values.len(), excitation.frequencies.len() * headings.len(), " and heading")?;
    check_finite("excitation", excitation.values.iter().map(|x| x.iter().all(|c| c.re.is_finite() && c.im.is_finite())))
}

/// A diagonal added mass this small against the largest of its kind is noise.
const NOISE: f64 = 1e-3;

/// `A∞` must be the limit of `A(ω)`: for no diagonal term may the highest frequency's value be
/// nearer `A(0)` than `A∞`, by more than 1 % of the term's size. Terms below [`NOISE`] of the
/// largest of their kind (translations, rotations) are the panel code's round-off (an
/// axisymmetric body's yaw: 3e-5 of its roll in Capytaine's files for the moored buoy) and are
/// not judged, as the radiation fit gives them no state.
fn check_limits(data: &CoefficientsData) -> Result<(), CoefficientsError> {
    let last = data.frequencies.len() - 1;
    let highest = &data.added_mass[last];
    let size = |dof: usize| {
        let (a_inf, a_zero, a_high) =
            (data.added_mass_infinite[(dof, dof)], data.added_mass_zero[(dof, dof)], highest[(dof, dof)]);
        a_inf.abs().max(a_zero.abs()).max(a_high.abs())
    };
    for dof in 0..6 {
        let kind = if dof < 3 { 0..3 } else { 3..6 };
        let largest = kind.map(size).fold(0.0, f64::max);
        if size(dof) <= NOISE * largest {
            continue;
        }
        let (a_inf, a_zero, a_high) =
            (data.added_mass_infinite[(dof, dof)], data.added_mass_zero[(dof, dof)], highest[(dof, dof)]);
        if (a_high - a_inf).abs() > (a_high - a_zero).abs() + 0.01 * size(dof) {
            return Err(CoefficientsError::SwappedLimits {
                dof: dof + 1,
                at_infinity: a_inf,
                at_zero: a_zero,
                highest: a_high,
                omega: data.frequencies[last],
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data() -> CoefficientsData {
        let heave = |a: f64| Matrix6::from_diagonal(&Vector6::new(1.0, 1.0, a, 1.0, 1.0, 1.0));
        CoefficientsData {
            frequencies: vec![0.5, 1.0, 2.0],
            added_mass: vec![heave(9.0), heave(7.0), heave(5.5)],
            damping: vec![heave(1.0), heave(3.0), heave(0.5)],
            added_mass_infinite: heave(5.0),
            added_mass_zero: heave(10.0),
            excitation: Excitation {
                frequencies: vec![1.0],
                headings: vec![0.0],
                values: vec![ComplexVector6::repeat(Complex::new(1.0, -1.0))],
            },
            hydrostatic_stiffness: None,
            mean_drift: None,
        }
    }

    #[test]
    fn radiation_is_linear_between_frequencies_and_from_zero_below_the_first() {
        let c = Coefficients::new(data()).expect("valid data");
        let (a, b) = c.radiation_at(1.5);
        assert!((a[(2, 2)] - 6.25).abs() < 1e-12 && (b[(2, 2)] - 1.75).abs() < 1e-12);
        let (a, b) = c.radiation_at(0.25);
        assert!((a[(2, 2)] - 9.5).abs() < 1e-12 && (b[(2, 2)] - 0.5).abs() < 1e-12);
        let (a, b) = c.radiation_at(5.0);
        assert!((a[(2, 2)] - 5.5).abs() < 1e-12 && (b[(2, 2)] - 0.5).abs() < 1e-12);
    }

    #[test]
    fn swapped_limits_are_refused_with_the_reason() {
        let mut swapped = data();
        std::mem::swap(&mut swapped.added_mass_infinite, &mut swapped.added_mass_zero);
        let error = Coefficients::new(swapped).expect_err("swapped limits");
        assert!(matches!(error, CoefficientsError::SwappedLimits { dof: 3, .. }), "{error}");
        assert!(error.to_string().contains("Capytaine PR #855"), "{error}");
    }

    /// The moored buoy's yaw in Capytaine's files: A66 3e-5 of A44, its limits in the wrong order
    /// by noise; below [`NOISE`] it is not judged, above it it would be.
    #[test]
    fn a_noise_sized_term_in_the_wrong_order_is_not_judged() {
        let yaw = |d: &mut CoefficientsData, infinite: f64, zero: f64, highest: f64| {
            d.added_mass_infinite[(5, 5)] = infinite;
            d.added_mass_zero[(5, 5)] = zero;
            d.added_mass[2][(5, 5)] = highest;
        };
        let mut noise = data();
        yaw(&mut noise, 1.91e-5, 2.13e-5, 2.22e-5);
        assert!(Coefficients::new(noise).is_ok());
        let mut real = data();
        yaw(&mut real, 1.91e-2, 2.13e-2, 2.22e-2);
        assert!(matches!(Coefficients::new(real), Err(CoefficientsError::SwappedLimits { dof: 6, .. })));
    }

    #[test]
    fn equal_limits_are_accepted() {
        let mut equal = data();
        equal.added_mass_zero = equal.added_mass_infinite;
        equal.added_mass = vec![equal.added_mass_infinite; 3];
        assert!(Coefficients::new(equal).is_ok());
    }

    #[test]
    fn bad_values_are_refused() {
        let mut d = data();
        d.frequencies[1] = 0.4;
        assert!(matches!(Coefficients::new(d), Err(CoefficientsError::FrequencyOrder { index: 1, .. })));
        let mut d = data();
        d.damping[2][(0, 1)] = f64::NAN;
        assert!(matches!(Coefficients::new(d), Err(CoefficientsError::NotFinite { what: "damping", index: 2 })));
        let mut d = data();
        d.added_mass.pop();
        assert!(matches!(Coefficients::new(d), Err(CoefficientsError::Count { expected: 3, count: 2, .. })));
        let mut d = data();
        d.excitation.headings = vec![0.0, 0.0];
        assert!(matches!(Coefficients::new(d), Err(CoefficientsError::HeadingOrder { what: "excitation", .. })));
    }
}
