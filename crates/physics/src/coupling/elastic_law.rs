//! Elastic laws of the spring-damper coupling (PHYSICS.md §2 \[4946]–\[4951]).
//!
//! Every law gives, at the distance `x` \[m] between the ends, the elastic force on end 1
//! `f_e(x) = k_eff(x)(x − x0)` \[N] (positive = tension, pulling the ends together), the tangent
//! stiffness `k(x) = df_e/dx` [N/m] and the potential `V(x)` \[J] with `dV/dx = f_e`. The force is
//! computed directly, never as `k_eff · (x − x0)`, so there is no 0/0 at `x = x0`; `k_eff` is
//! offered for display, and at `x0` it is the tangent stiffness, as PHYSICS.md §2 prescribes.

use crate::parameter::{Bound, ParameterError, require};
use crate::table::{Extrapolation, Table};

/// An elastic law `f_e(x)`.
#[derive(Debug, Clone, PartialEq)]
pub enum ElasticLaw {
    /// `f_e = k (x − x0)`.
    Linear { stiffness: f64, rest_length: f64 },
    /// `k_eff = a + b s + c s²`, `s = x − x0`, so `f_e = a s + b s² + c s³` \[4950]–\[4951].
    /// Units: a [N/m], b [N/m²], c [N/m³].
    Polynomial { a: f64, b: f64, c: f64, rest_length: f64 },
    /// `f_e(x)` read from a table of (x \[m], f \[N]) \[4947]; beyond the table the end
    /// segment's stiffness holds. The rest length is where the curve crosses zero.
    ForceCurve { curve: Table },
    /// `f_e(x) = ∫_{x0}^{x} k(ξ) dξ` with `k(ξ)` a table of (ξ \[m], k [N/m]) \[4948]; beyond the
    /// table the end stiffness holds.
    StiffnessCurve { stiffness: Table, rest_length: f64 },
    /// `f_e(x) = f_r + ∫_{x_r}^{x} k(ξ) dξ` \[4949], for springs whose rest length lies outside
    /// the operating range: `f_r` \[N] is the force measured at the reference length `x_r` \[m].
    /// `rest_length` only serves `k_eff`.
    ReferenceForce { stiffness: Table, reference_length: f64, reference_force: f64, rest_length: f64 },
}

impl ElasticLaw {
    /// A force curve from (x, f) points, extended linearly.
    ///
    /// # Errors
    /// Points that are not a table, at field `points`.
    pub fn force_curve(points: Vec<(f64, f64)>) -> Result<Self, ParameterError> {
        let curve = Table::new(points, Extrapolation::Linear)
            .map_err(|source| ParameterError::Table { field: "points", source })?;
        Ok(Self::ForceCurve { curve })
    }

    /// A stiffness table from (ξ, k) points, extended with constant end stiffness.
    ///
    /// # Errors
    /// Points that are not a table, at field `points`.
    pub fn stiffness_table(points: Vec<(f64, f64)>) -> Result<Table, ParameterError> {
        Table::new(points, Extrapolation::Constant).map_err(|source| ParameterError::Table { field: "points", source })
    }

    /// Checks the law's numbers (its tables were checked when they were made): a linear
    /// stiffness `k` [N/m] ≥ 0, rest and reference lengths \[m] ≥ 0, the other coefficients
    /// finite. [`super::SpringDamper::new`] calls it: a law is checked where its spring is built.
    ///
    /// # Errors
    /// The first number out of its range, named by its field.
    pub fn check(&self) -> Result<(), ParameterError> {
        let rest = |x0: f64| require("rest_length", x0, Bound::NonNegative, "m").map(drop);
        match self {
            Self::Linear { stiffness, rest_length } => {
                require("stiffness", *stiffness, Bound::NonNegative, "N/m")?;
                rest(*rest_length)
            }
            Self::Polynomial { a, b, c, rest_length } => {
                require("a", *a, Bound::Finite, "N/m")?;
                require("b", *b, Bound::Finite, "N/m²")?;
                require("c", *c, Bound::Finite, "N/m³")?;
                rest(*rest_length)
            }
            Self::ForceCurve { .. } => Ok(()),
            Self::StiffnessCurve { rest_length, .. } => rest(*rest_length),
            Self::ReferenceForce { reference_length, reference_force, rest_length, .. } => {
                require("reference_length", *reference_length, Bound::NonNegative, "m")?;
                require("reference_force", *reference_force, Bound::Finite, "N")?;
                require("rest_length", *rest_length, Bound::Finite, "m").map(drop)
            }
        }
    }

    /// `x0` \[m], the length at which the elastic force vanishes (for a force curve: its first
    /// zero crossing, or its first point if it has none).
    pub fn rest_length(&self) -> f64 {
        match self {
            Self::Linear { rest_length, .. }
            | Self::Polynomial { rest_length, .. }
            | Self::StiffnessCurve { rest_length, .. }
            | Self::ReferenceForce { rest_length, .. } => *rest_length,
            Self::ForceCurve { curve } => zero_crossing(curve),
        }
    }

    /// Elastic force on end 1, `f_e(x)` \[N].
    #[inline(always)]
    pub fn force(&self, x: f64) -> f64 {
        match self {
            Self::Linear { stiffness, rest_length } => stiffness * (x - rest_length),
            Self::Polynomial { a, b, c, rest_length } => {
                let s = x - rest_length;
                s * (a + s * (b + s * c))
            }
            Self::ForceCurve { curve } => curve.value(x),
            Self::StiffnessCurve { stiffness, rest_length } => stiffness.integral(*rest_length, x),
            Self::ReferenceForce { stiffness, reference_length, reference_force, .. } => {
                reference_force + stiffness.integral(*reference_length, x)
            }
        }
    }

    /// `(f_e(x), V(x))` [N, J]: [`ElasticLaw::force`] and [`ElasticLaw::potential`] with one
    /// dispatch on the law, for the step.
    #[inline(always)]
    pub fn force_and_potential(&self, x: f64) -> (f64, f64) {
        match self {
            Self::Linear { stiffness, rest_length } => {
                (stiffness * (x - rest_length), 0.5 * stiffness * (x - rest_length).powi(2))
            }
            law => (law.force(x), law.potential(x)),
        }
    }

    /// Tangent stiffness `k(x) = df_e/dx` [N/m].
    pub fn tangent_stiffness(&self, x: f64) -> f64 {
        match self {
            Self::Linear { stiffness, .. } => *stiffness,
            Self::Polynomial { a, b, c, rest_length } => {
                let s = x - rest_length;
                a + s * (2.0 * b + 3.0 * c * s)
            }
            Self::ForceCurve { curve } => curve.slope(x),
            Self::StiffnessCurve { stiffness, .. } | Self::ReferenceForce { stiffness, .. } => stiffness.value(x),
        }
    }

    /// `k_eff(x) = f_e(x)/(x − x0)` [N/m]; the tangent stiffness at `x0` (no 0/0).
    pub fn effective_stiffness(&self, x: f64) -> f64 {
        let x0 = self.rest_length();
        let s = x - x0;
        if s.abs() <= 1e-12 * x0.abs().max(1.0) { self.tangent_stiffness(x0) } else { self.force(x) / s }
    }

    /// Elastic potential `V(x)` \[J], with `dV/dx = f_e`. It is zero at `x0` (at `x_r` for the
    /// reference-force form, at the first point for a force curve without a zero crossing).
    #[inline(always)]
    pub fn potential(&self, x: f64) -> f64 {
        match self {
            Self::Linear { stiffness, rest_length } => 0.5 * stiffness * (x - rest_length).powi(2),
            Self::Polynomial { a, b, c, rest_length } => {
                let s = x - rest_length;
                s * s * (a / 2.0 + s * (b / 3.0 + s * c / 4.0))
            }
            Self::ForceCurve { curve } => curve.integral(zero_crossing(curve), x),
            Self::StiffnessCurve { stiffness, rest_length } => {
                let x0 = *rest_length;
                stiffness.second_antiderivative(x)
                    - stiffness.second_antiderivative(x0)
                    - stiffness.antiderivative(x0) * (x - x0)
            }
            Self::ReferenceForce { stiffness, reference_length, reference_force, .. } => {
                let xr = *reference_length;
                reference_force * (x - xr) + stiffness.second_antiderivative(x)
                    - stiffness.second_antiderivative(xr)
                    - stiffness.antiderivative(xr) * (x - xr)
            }
        }
    }
}

/// First `x` where a force curve crosses zero (its first point if it never does).
fn zero_crossing(curve: &Table) -> f64 {
    let points = curve.points();
    for pair in points.windows(2) {
        let ((xa, fa), (xb, fb)) = (pair[0], pair[1]);
        if fa == 0.0 {
            return xa;
        }
        if fa.signum() != fb.signum() {
            return xa + (xb - xa) * fa / (fa - fb);
        }
    }
    let (x_last, f_last) = points[points.len() - 1];
    if f_last == 0.0 { x_last } else { points[0].0 }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn laws() -> Vec<ElasticLaw> {
        let k_table = ElasticLaw::stiffness_table(vec![(0.5, 100.0), (1.0, 300.0), (1.5, 200.0)]).unwrap();
        vec![
            ElasticLaw::Linear { stiffness: 250.0, rest_length: 1.0 },
            ElasticLaw::Polynomial { a: 100.0, b: 20.0, c: 4000.0, rest_length: 1.0 },
            ElasticLaw::force_curve(vec![(0.5, -80.0), (1.0, 0.0), (1.2, 50.0), (2.0, 400.0)]).unwrap(),
            ElasticLaw::StiffnessCurve { stiffness: k_table.clone(), rest_length: 1.0 },
            ElasticLaw::ReferenceForce {
                stiffness: k_table,
                reference_length: 1.2,
                reference_force: 30.0,
                rest_length: 3.0,
            },
        ]
    }

    #[test]
    fn linear_and_polynomial_closed_forms() {
        let linear = &laws()[0];
        assert_relative_eq!(linear.force(1.2), 50.0, epsilon = 1e-12);
        assert_relative_eq!(linear.potential(1.2), 0.5 * 250.0 * 0.04, epsilon = 1e-12);
        let poly = &laws()[1];
        // s = 0.1: f = 100·0.1 + 20·0.01 + 4000·0.001 = 14.2; V = 0.5 + 0.02/3·… by hand:
        assert_relative_eq!(poly.force(1.1), 14.2, epsilon = 1e-12);
        assert_relative_eq!(
            poly.potential(1.1),
            100.0 * 0.01 / 2.0 + 20.0 * 0.001 / 3.0 + 4000.0 * 1e-4 / 4.0,
            epsilon = 1e-12
        );
        assert_relative_eq!(
            poly.tangent_stiffness(1.1),
            100.0 + 2.0 * 20.0 * 0.1 + 3.0 * 4000.0 * 0.01,
            epsilon = 1e-12
        );
        assert_relative_eq!(poly.effective_stiffness(1.1), 100.0 + 20.0 * 0.1 + 4000.0 * 0.01, epsilon = 1e-9);
    }

    #[test]
    fn stiffness_curve_closed_form() {
        // k(ξ) = 100 + 400(ξ − 0.5) on [0.5, 1]: f_e(0.8) = ∫_1^0.8 k = −(k(0.8)+k(1))/2·0.2 = −(220+300)/2·0.2 = −52.
        let law = &laws()[3];
        assert_relative_eq!(law.force(0.8), -52.0, epsilon = 1e-12);
        // Beyond the table (ξ > 1.5) k holds at 200: f_e(2) = ∫_1^1.5 k + 200·0.5 = 125 + 100.
        assert_relative_eq!(law.force(2.0), 225.0, epsilon = 1e-12);
        // Reference form: f_e(1.2) = f_r exactly; f_e(1.0) = 30 − ∫_1^1.2 k = 30 − (300+260)/2·0.2 = −26.
        let reference = &laws()[4];
        assert_relative_eq!(reference.force(1.2), 30.0, epsilon = 1e-12);
        assert_relative_eq!(reference.force(1.0), -26.0, epsilon = 1e-12);
    }

    #[test]
    fn every_law_is_consistent_force_is_dv_dx_and_stiffness_is_df_dx() {
        for law in laws() {
            for &x in &[0.3, 0.7, 0.95, 1.05, 1.33, 1.8, 2.4] {
                let h = 1e-6;
                let dv = (law.potential(x + h) - law.potential(x - h)) / (2.0 * h);
                assert_relative_eq!(dv, law.force(x), epsilon = 1e-6, max_relative = 1e-7);
                let df = (law.force(x + h) - law.force(x - h)) / (2.0 * h);
                assert_relative_eq!(df, law.tangent_stiffness(x), epsilon = 1e-5, max_relative = 1e-6);
                // The step's single dispatch gives the same numbers, bit for bit.
                assert_eq!(law.force_and_potential(x), (law.force(x), law.potential(x)));
            }
        }
    }

    #[test]
    fn effective_stiffness_at_rest_length_is_the_tangent_not_nan() {
        for law in laws() {
            let x0 = law.rest_length();
            let k = law.effective_stiffness(x0);
            assert!(k.is_finite(), "{law:?}");
            assert_relative_eq!(k, law.tangent_stiffness(x0), max_relative = 1e-12);
        }
        assert_relative_eq!(laws()[2].rest_length(), 1.0);
    }
}
