//! Piecewise-linear tables `y(x)` with exact first and second integrals.
//!
//! Used by the curve-defined elastic laws of PHYSICS.md §2: a force curve `f_e(x)` or a
//! stiffness curve `k(ξ)`. The table is linear between points; outside its range it is
//! continued as chosen by [`Extrapolation`]. Integrals are exact (piecewise quadratic and
//! cubic), so `f_e = ∫k` and the potential `V = ∫f_e` carry no quadrature error and the energy
//! balance of a curve-defined spring is as exact as that of a linear one.

use thiserror::Error;

/// How a table continues beyond its first and last points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Extrapolation {
    /// `y` keeps its end value (a stiffness table: the end stiffness holds).
    Constant,
    /// `y` keeps the slope of its end segment (a force table: the end stiffness holds).
    Linear,
}

/// Why a list of points is not a table.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TableError {
    #[error("a table needs at least 2 points, got {0}")]
    TooFewPoints(usize),
    #[error("table point {index}: x must increase strictly ({previous} then {x})")]
    NotIncreasing { index: usize, previous: f64, x: f64 },
    #[error("table point {index}: ({x}, {y}) is not finite")]
    NotFinite { index: usize, x: f64, y: f64 },
}

/// A linear piece `y(x) = y_a + s (x − x_a)` starting at `x_a`, with the running integrals
/// `Y(x_a) = ∫_{x_first}^{x_a} y` and `YY(x_a) = ∫_{x_first}^{x_a} Y` at its start.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    x_a: f64,
    y_a: f64,
    slope: f64,
    integral_a: f64,
    double_integral_a: f64,
}

impl Piece {
    fn value(&self, x: f64) -> f64 {
        self.y_a + self.slope * (x - self.x_a)
    }
    /// `Y(x) = Y(x_a) + y_a d + s d²/2`, `d = x − x_a`.
    fn integral(&self, x: f64) -> f64 {
        let d = x - self.x_a;
        self.integral_a + d * (self.y_a + 0.5 * self.slope * d)
    }
    /// `YY(x) = YY(x_a) + Y(x_a) d + y_a d²/2 + s d³/6`.
    fn double_integral(&self, x: f64) -> f64 {
        let d = x - self.x_a;
        self.double_integral_a + d * (self.integral_a + d * (0.5 * self.y_a + self.slope * d / 6.0))
    }
}

/// A validated piecewise-linear table (at least two points, x strictly increasing, finite).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    points: Vec<(f64, f64)>,
    /// `pieces[0]` is the left extension, `pieces[i]` (1 ≤ i ≤ n−1) the segment from point
    /// i−1 to i, `pieces[n]` the right extension.
    pieces: Vec<Piece>,
}

impl Table {
    /// Builds a table, checking that the points form one.
    pub fn new(points: Vec<(f64, f64)>, extrapolation: Extrapolation) -> Result<Self, TableError> {
        if points.len() < 2 {
            return Err(TableError::TooFewPoints(points.len()));
        }
        for (index, &(x, y)) in points.iter().enumerate() {
            if !x.is_finite() || !y.is_finite() {
                return Err(TableError::NotFinite { index, x, y });
            }
            if index > 0 && x <= points[index - 1].0 {
                return Err(TableError::NotIncreasing { index, previous: points[index - 1].0, x });
            }
        }
        let pieces = build_pieces(&points, extrapolation);
        Ok(Self { points, pieces })
    }

    /// The points the table was built from.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points
    }

    fn piece(&self, x: f64) -> &Piece {
        // Index of the first point with x_i > x: 0 → left extension, n → right extension.
        let index = self.points.partition_point(|&(xi, _)| xi <= x);
        &self.pieces[index]
    }

    /// `y(x)`.
    pub fn value(&self, x: f64) -> f64 {
        self.piece(x).value(x)
    }

    /// `dy/dx` at `x` (the right-hand slope at a table point).
    pub fn slope(&self, x: f64) -> f64 {
        self.piece(x).slope
    }

    /// `∫_{a}^{b} y(ξ) dξ`, exact.
    pub fn integral(&self, a: f64, b: f64) -> f64 {
        self.antiderivative(b) - self.antiderivative(a)
    }

    /// `Y(x) = ∫_{x_first}^{x} y`, exact.
    pub fn antiderivative(&self, x: f64) -> f64 {
        self.piece(x).integral(x)
    }

    /// `YY(x) = ∫_{x_first}^{x} Y`, exact.
    pub fn second_antiderivative(&self, x: f64) -> f64 {
        self.piece(x).double_integral(x)
    }
}

fn build_pieces(points: &[(f64, f64)], extrapolation: Extrapolation) -> Vec<Piece> {
    let n = points.len();
    let segment_slope = |i: usize| (points[i + 1].1 - points[i].1) / (points[i + 1].0 - points[i].0);
    let end_slope = |segment: usize| match extrapolation {
        Extrapolation::Constant => 0.0,
        Extrapolation::Linear => segment_slope(segment),
    };
    let (x_first, y_first) = points[0];
    let mut pieces = Vec::with_capacity(n + 1);
    // Left extension: anchored at the first point, where both integrals are zero by definition.
    pieces.push(Piece { x_a: x_first, y_a: y_first, slope: end_slope(0), integral_a: 0.0, double_integral_a: 0.0 });
    let mut integral_a = 0.0;
    let mut double_integral_a = 0.0;
    for i in 0..n - 1 {
        let piece =
            Piece { x_a: points[i].0, y_a: points[i].1, slope: segment_slope(i), integral_a, double_integral_a };
        integral_a = piece.integral(points[i + 1].0);
        double_integral_a = piece.double_integral(points[i + 1].0);
        pieces.push(piece);
    }
    let (x_last, y_last) = points[n - 1];
    pieces.push(Piece { x_a: x_last, y_a: y_last, slope: end_slope(n - 2), integral_a, double_integral_a });
    pieces
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn table(extrapolation: Extrapolation) -> Table {
        Table::new(vec![(0.0, 1.0), (1.0, 3.0), (3.0, 2.0)], extrapolation).unwrap()
    }

    #[test]
    fn value_and_slope_inside_and_beyond() {
        let t = table(Extrapolation::Constant);
        assert_relative_eq!(t.value(0.5), 2.0);
        assert_relative_eq!(t.value(2.0), 2.5);
        assert_relative_eq!(t.value(-1.0), 1.0);
        assert_relative_eq!(t.value(5.0), 2.0);
        assert_relative_eq!(t.slope(2.0), -0.5);
        let l = table(Extrapolation::Linear);
        assert_relative_eq!(l.value(-1.0), -1.0);
        assert_relative_eq!(l.value(5.0), 1.0);
    }

    #[test]
    fn integrals_match_simpson_on_each_quadratic_piece() {
        // Y is piecewise quadratic, so Simpson's rule on each sub-interval between table
        // points is exact for ∫Y: an independent check of the closed-form double integral.
        let t = table(Extrapolation::Linear);
        let breaks = [-2.0, 0.0, 1.0, 3.0, 4.5];
        let mut yy = t.second_antiderivative(-2.0);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            let m = 0.5 * (a + b);
            let y_int = (b - a) / 6.0 * (t.value(a) + 4.0 * t.value(m) + t.value(b));
            assert_relative_eq!(t.integral(a, b), y_int, epsilon = 1e-14);
            let yy_int = (b - a) / 6.0 * (t.antiderivative(a) + 4.0 * t.antiderivative(m) + t.antiderivative(b));
            yy += yy_int;
            assert_relative_eq!(t.second_antiderivative(b), yy, epsilon = 1e-13);
        }
        // Trapezoids by hand: ∫_0^3 = (1+3)/2·1 + (3+2)/2·2 = 7.
        assert_relative_eq!(t.integral(0.0, 3.0), 7.0);
    }

    #[test]
    fn rejects_bad_points() {
        assert_eq!(Table::new(vec![(0.0, 1.0)], Extrapolation::Constant), Err(TableError::TooFewPoints(1)));
        assert!(matches!(
            Table::new(vec![(0.0, 1.0), (0.0, 2.0)], Extrapolation::Constant),
            Err(TableError::NotIncreasing { index: 1, .. })
        ));
        assert!(matches!(
            Table::new(vec![(0.0, f64::NAN), (1.0, 2.0)], Extrapolation::Constant),
            Err(TableError::NotFinite { index: 0, .. })
        ));
    }
}
