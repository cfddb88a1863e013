//! The elastic catenary's closure equations in dimensionless form (PHYSICS.md §3).
//!
//! With the line's weight `W = λ0 g L_eq` \[N], the end-1 vertical force `V1 = c sinh u1` and
//! horizontal tension `H = c` \[N], PHYSICS.md's `a, b, c, u1, u2` form becomes Irvine's
//! (`sinh u = V/H`, `V2 = V1 + W`):
//!
//! `Δx = (H/w)(asinh(V2/H) − asinh(V1/H)) + H L/EA`,
//! `Δy = (√(H²+V2²) − √(H²+V1²))/w + (V1+V2) L/(2 EA)`,  `w = λ0 g`, `EA = D L_eq`.
//!
//! Dividing forces by `W` and lengths by `L` (`h = H/W`, `v = V1/W`, `X = Δx/L`, `Y = Δy/L`,
//! `ε = W/EA = λ0 g / D`):
//!
//! `X = span(h, v, v+1) + ε h`,  `Y = rise(h, v, v+1) + ε (v + ½)`.
//!
//! Both are written without cancellation ([`span`], [`rise`]), so they hold from millimetre to
//! kilometre spans, slack to stretched, and down to `h = 0` (a vertical line).

/// `√(h² + v²)`, without `hypot`'s cost where the squares cannot overflow.
#[inline]
fn radius(h: f64, v: f64) -> f64 {
    if h.abs().max(v.abs()) < 1e150 { (h * h + v * v).sqrt() } else { h.hypot(v) }
}

/// `h (asinh(b/h) − asinh(a/h))` for `a ≤ b`: the horizontal extent of the inextensible line
/// between vertical forces `a` and `b` (in units of W and L). Zero at `h = 0`.
pub fn span(h: f64, a: f64, b: f64) -> f64 {
    span_with_radii(h, a, b, radius(h, a), radius(h, b))
}

/// [`span`] with `r_a = √(h² + a²)` and `r_b = √(h² + b²)` already known.
///
/// Same-sign `a, b` use `ln(1 + ((b + r_b) − (a + r_a))/(a + r_a))` with
/// `r_b − r_a = (b² − a²)/(r_a + r_b)`: no difference of large logarithms.
fn span_with_radii(h: f64, a: f64, b: f64, ra: f64, rb: f64) -> f64 {
    if h <= 0.0 {
        0.0
    } else if a >= 0.0 {
        let growth = (b - a) * (1.0 + (b + a) / (ra + rb));
        h * (growth / (a + ra)).ln_1p()
    } else if b <= 0.0 {
        // Mirror: asinh(b/h) − asinh(a/h) = asinh(−a/h) − asinh(−b/h).
        let growth = (b - a) * (1.0 - (b + a) / (ra + rb));
        h * (growth / (-b + rb)).ln_1p()
    } else {
        h * ((b / h).asinh() + (-a / h).asinh())
    }
}

/// `√(h² + b²) − √(h² + a²) = (b² − a²)/(r_a + r_b)`: the vertical extent of the inextensible
/// line between vertical forces `a` and `b`.
pub fn rise(h: f64, a: f64, b: f64) -> f64 {
    rise_with_radii(a, b, radius(h, a), radius(h, b))
}

fn rise_with_radii(a: f64, b: f64, ra: f64, rb: f64) -> f64 {
    let sum = ra + rb;
    if sum > 0.0 { (b - a) * (b + a) / sum } else { 0.0 }
}

/// A point `(h, v)` of the dimensionless unknowns with its residual and Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluation {
    /// `X(h, v) − X*`, `Y(h, v) − Y*`.
    pub residual: [f64; 2],
    /// `∂(X, Y)/∂(h, v)`, rows X and Y. Symmetric and positive definite for `h > 0`.
    pub jacobian: [[f64; 2]; 2],
}

/// The closure equations for a dimensionless span `x`, rise `y` and compliance `epsilon`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Closure {
    pub x: f64,
    pub y: f64,
    pub epsilon: f64,
}

impl Closure {
    /// `X(h, v)`, `Y(h, v)`.
    pub fn ends(&self, h: f64, v: f64) -> [f64; 2] {
        let (r1, r2) = (radius(h, v), radius(h, v + 1.0));
        [
            span_with_radii(h, v, v + 1.0, r1, r2) + self.epsilon * h,
            rise_with_radii(v, v + 1.0, r1, r2) + self.epsilon * (v + 0.5),
        ]
    }

    /// Residual and Jacobian at `(h, v)`, `h > 0`:
    /// `X_h = span/h − (v+1)/r2 + v/r1 + ε`, `X_v = Y_h = h(1/r2 − 1/r1)`,
    /// `Y_v = (v+1)/r2 − v/r1 + ε`.
    pub fn evaluate(&self, h: f64, v: f64) -> Evaluation {
        let (r1, r2) = (radius(h, v), radius(h, v + 1.0));
        let extent = span_with_radii(h, v, v + 1.0, r1, r2);
        let residual = [
            extent + self.epsilon * h - self.x,
            rise_with_radii(v, v + 1.0, r1, r2) + self.epsilon * (v + 0.5) - self.y,
        ];
        let (inverse1, inverse2) = (r1.recip(), r2.recip());
        let cross = h * (inverse2 - inverse1);
        let slope_difference = (v + 1.0) * inverse2 - v * inverse1;
        let jacobian =
            [[extent / h - slope_difference + self.epsilon, cross], [cross, slope_difference + self.epsilon]];
        Evaluation { residual, jacobian }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn span_and_rise_match_the_naive_forms_where_those_are_accurate() {
        for &(h, a, b) in &[(0.7_f64, -0.3_f64, 0.7_f64), (2.0, 0.1, 1.1), (0.05, -1.4, -0.4), (3.0, -0.5, 0.5)] {
            let naive_span = h * ((b / h).asinh() - (a / h).asinh());
            let naive_rise = (h * h + b * b).sqrt() - (h * h + a * a).sqrt();
            assert_relative_eq!(span(h, a, b), naive_span, max_relative = 1e-13);
            assert_relative_eq!(rise(h, a, b), naive_rise, max_relative = 1e-13, epsilon = 1e-15);
        }
    }

    #[test]
    fn span_keeps_its_digits_for_a_nearly_straight_taut_line() {
        // h = 1e8: span ≈ 1 − (v² + v + 1/3)/(2h²); the naive difference of asinh loses it all.
        let (h, v) = (1e8, 3.0);
        let expected = 1.0 - (v * v + v + 1.0 / 3.0) / (2.0 * h * h);
        assert_relative_eq!(span(h, v, v + 1.0), expected, max_relative = 1e-15);
    }

    #[test]
    fn jacobian_matches_finite_differences() {
        let closure = Closure { x: 0.0, y: 0.0, epsilon: 0.03 };
        for &(h, v) in &[(0.4, -0.3), (1.5, 0.2), (0.02, -0.9), (5.0, 4.0), (0.3, -2.0)] {
            let e = closure.evaluate(h, v);
            let d = 1e-7;
            let (xp, xm) = (closure.ends(h + d, v), closure.ends(h - d, v));
            let (yp, ym) = (closure.ends(h, v + d), closure.ends(h, v - d));
            for row in 0..2 {
                assert_relative_eq!(
                    e.jacobian[row][0],
                    (xp[row] - xm[row]) / (2.0 * d),
                    max_relative = 1e-6,
                    epsilon = 1e-9
                );
                assert_relative_eq!(
                    e.jacobian[row][1],
                    (yp[row] - ym[row]) / (2.0 * d),
                    max_relative = 1e-6,
                    epsilon = 1e-9
                );
            }
        }
    }
}
