//! Elastic quasi-static catenary coupling (PHYSICS.md §3, seed 000 [4952]–[4955]).
//!
//! A line of mass per length `λ0` [kg/m], unstretched length `L_eq` [m] and stiffness `D` [N/m]
//! (`EA = D L_eq` [N]) hangs between two ends in the vertical plane of gravity:
//! `e_y = −ĝ`, `e_x` the horizontal unit vector from end 1 toward end 2. With the horizontal
//! tension `H` and the vertical force at end 1 `V1` solved from the end positions
//! ([`solver`]), the forces exerted by the line are
//! `f1 = H e_x + V1 e_y`, `f2 = −H e_x − V2 e_y`, `V2 = V1 + W`, `W = λ0 g L_eq` [N]
//! (PHYSICS.md writes `H = c`, `V1 = c sinh u1`, `V2 = c sinh u2`).
//!
//! A massless line (or one in zero gravity) is a straight elastic rope: tension
//! `T = D max(0, x − L_eq)` [N], pulling only when stretched.

pub mod equations;
pub mod solver;

use super::ends::Endpoint;
use super::forces::CouplingForces;
use crate::body::{BodyFrame, Load};
use crate::math::{Mat3, Vec3};
use equations::{Closure, rise, span};
use solver::Unknowns;

/// A catenary line between two ends.
#[derive(Debug, Clone, PartialEq)]
pub struct Catenary {
    pub end1: Endpoint,
    pub end2: Endpoint,
    /// `λ0` [kg/m] ≥ 0.
    pub mass_per_length: f64,
    /// `L_eq` [m] > 0.
    pub length: f64,
    /// `D` [N/m] > 0: the stiffness of the whole line, `EA = D L_eq`.
    pub stiffness: f64,
}

/// What a line remembers: its last solution, the warm start of the next solve (and what the
/// recorder draws and the stable time step reads).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CatenaryCache {
    pub last: Option<LineState>,
}

/// A catenary solve that failed: only non-finite end positions (a diverged simulation) do this.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("the catenary has no solution for span {span} m, rise {rise} m (non-finite end positions?)")]
pub struct CatenaryError {
    pub span: f64,
    pub rise: f64,
}

/// The solved line at one instant, world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineState {
    /// End 1 [m].
    pub origin: Vec3,
    /// Horizontal unit vector from end 1 toward end 2 (for a weightless line: along the chord),
    /// and the upward unit vector.
    pub e_x: Vec3,
    pub e_y: Vec3,
    /// Horizontal span `Δx` [m] ≥ 0 and rise `Δy` [m] of end 2 over end 1.
    pub span: f64,
    pub rise: f64,
    /// `H` [N] ≥ 0 and `V1` [N] (vertical force of the line on end 1, up positive).
    pub horizontal_tension: f64,
    pub vertical1: f64,
    /// `W = λ0 g L_eq` [N], `L_eq` [m] and `EA` [N].
    pub weight: f64,
    pub length: f64,
    pub axial_stiffness: f64,
    /// Newton iterations of the solve (0 for a closed form or an exact warm start).
    pub iterations: u32,
    /// Closure residual of the solve, a fraction of `L_eq`.
    pub residual: f64,
}

impl LineState {
    /// `V2 = V1 + W` [N].
    pub fn vertical2(&self) -> f64 {
        self.vertical1 + self.weight
    }

    /// Forces exerted by the line on end 1 and end 2 [N].
    pub fn end_forces(&self) -> (Vec3, Vec3) {
        let f1 = self.e_x * self.horizontal_tension + self.e_y * self.vertical1;
        let f2 = -self.e_x * self.horizontal_tension - self.e_y * self.vertical2();
        (f1, f2)
    }

    /// Tensions at end 1 and end 2, `√(H² + V²)` [N].
    pub fn end_tensions(&self) -> (f64, f64) {
        (self.horizontal_tension.hypot(self.vertical1), self.horizontal_tension.hypot(self.vertical2()))
    }

    /// `u1 = asinh(V1/H)`, `u2 = asinh(V2/H)` of PHYSICS.md's parametric form (±∞ for a
    /// vertical line, where `H = 0`).
    pub fn parameters(&self) -> (f64, f64) {
        let h = self.horizontal_tension;
        let u = |v: f64| if h > 0.0 { (v / h).asinh() } else { f64::INFINITY.copysign(v) };
        (u(self.vertical1), u(self.vertical2()))
    }

    /// Dimensionless unknowns of this state (`h = H/W`, `v = V1/W`), the warm start.
    fn unknowns(&self) -> Option<Unknowns> {
        (self.weight > 0.0).then(|| Unknowns { h: self.horizontal_tension / self.weight, v: self.vertical1 / self.weight })
    }

    /// `count + 1` points evenly spaced along the unstretched line from end 1 to end 2, with
    /// the tension there [m, N]. With `s` the unstretched arc length and `τ = V1 + w s` the
    /// vertical force (`w = W/L_eq`): `x(s) = (H/w)(asinh(τ/H) − asinh(V1/H)) + H s/EA`,
    /// `y(s) = (√(H²+τ²) − √(H²+V1²))/w + (τ² − V1²)/(2 w EA)`, `T = √(H² + τ²)`.
    pub fn sample(&self, count: usize) -> Vec<(Vec3, f64)> {
        let count = count.max(1);
        if self.weight <= 0.0 {
            let tension = self.horizontal_tension;
            return (0..=count).map(|i| (self.origin + self.e_x * (self.span * i as f64 / count as f64), tension)).collect();
        }
        let (h, v) = (self.horizontal_tension / self.weight, self.vertical1 / self.weight);
        let eps = self.weight / self.axial_stiffness;
        (0..=count)
            .map(|i| {
                let sigma = i as f64 / count as f64;
                let t = v + sigma;
                let x = span(h, v, t) + eps * h * sigma;
                let y = rise(h, v, t) + 0.5 * eps * (t * t - v * v);
                (self.origin + (self.e_x * x + self.e_y * y) * self.length, self.weight * h.hypot(t))
            })
            .collect()
    }

    /// Potential energy of the line [J]: weight (heights along `e_y`, zero at the world origin)
    /// plus elastic strain. Integrating `∫ w y ds` and `∫ T²/(2EA) ds` over the solved shape
    /// and using the closure equations, in units of `W L_eq`:
    /// `U = y1/L + v2 Y − (v2 r2 − v1 r1)/2 + h X/2 − ε (v2³ − v1³)/6`, `r_i = √(h² + v_i²)`.
    /// For a weightless rope, `½ D (x − L_eq)²` when stretched. Its gradient with respect to the
    /// end positions is minus the end forces.
    pub fn potential_energy(&self) -> f64 {
        if self.weight <= 0.0 {
            let stretch = (self.span - self.length).max(0.0);
            return 0.5 * self.axial_stiffness / self.length * stretch * stretch;
        }
        let (w, l) = (self.weight, self.length);
        let (h, v1) = (self.horizontal_tension / w, self.vertical1 / w);
        let v2 = v1 + 1.0;
        let (x, y, eps) = (self.span / l, self.rise / l, w / self.axial_stiffness);
        let (r1, r2) = (h.hypot(v1), h.hypot(v2));
        let cubes = (v2 - v1) * (v2 * v2 + v2 * v1 + v1 * v1);
        w * l * (self.origin.dot(&self.e_y) / l + v2 * y - 0.5 * (v2 * r2 - v1 * r1) + 0.5 * h * x - eps * cubes / 6.0)
    }

    /// Tangent stiffness `K = ∂f1/∂p2` [N/m] (so `∂f1/∂p1 = −K`, `∂f2/∂p2 = −K`): in the plane,
    /// `∂(H, V1)/∂(Δx, Δy) = (W/L) J⁻¹` with `J` the closure Jacobian; out of the plane the line
    /// turns about the vertical, `H/Δx`.
    pub fn tangent_stiffness(&self) -> Mat3 {
        if self.weight <= 0.0 {
            let x = self.span;
            let stretch = x - self.length;
            if stretch <= 0.0 || x <= 0.0 {
                return Mat3::zeros();
            }
            let d = self.e_x;
            let along = self.axial_stiffness / self.length;
            let tension = along * stretch;
            return d * d.transpose() * along + (Mat3::identity() - d * d.transpose()) * (tension / x);
        }
        let (w, l) = (self.weight, self.length);
        let closure = Closure { x: self.span / l, y: self.rise / l, epsilon: w / self.axial_stiffness };
        let j = closure.evaluate((self.horizontal_tension / w).max(f64::MIN_POSITIVE), self.vertical1 / w).jacobian;
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        let scale = w / l / det;
        let (h_x, h_y, v_x, v_y) = (j[1][1] * scale, -j[0][1] * scale, -j[1][0] * scale, j[0][0] * scale);
        let e_z = self.e_x.cross(&self.e_y);
        let turning = if self.span > 0.0 { self.horizontal_tension / self.span } else { h_x };
        self.e_x * (self.e_x * h_x + self.e_y * h_y).transpose()
            + self.e_y * (self.e_x * v_x + self.e_y * v_y).transpose()
            + e_z * e_z.transpose() * turning
    }
}

impl Catenary {
    pub fn new(end1: Endpoint, end2: Endpoint, mass_per_length: f64, length: f64, stiffness: f64) -> Self {
        Self { end1, end2, mass_per_length, length, stiffness }
    }

    /// Solves the line for end positions `p1`, `p2` [m] under `gravity` [m/s²], warm-started
    /// from the solution `last` (the previous one of the same line), if any.
    pub fn solve(&self, p1: &Vec3, p2: &Vec3, gravity: &Vec3, last: Option<&LineState>) -> Result<LineState, CatenaryError> {
        let chord = p2 - p1;
        let g = gravity.norm();
        let weight = self.mass_per_length * g * self.length;
        let axial_stiffness = self.stiffness * self.length;
        let straight = |e_x: Vec3, e_y: Vec3, x: f64| {
            let tension = self.stiffness * (x - self.length).max(0.0);
            LineState { origin: *p1, e_x, e_y, span: x, rise: 0.0, horizontal_tension: tension, vertical1: 0.0, weight: 0.0, length: self.length, axial_stiffness, iterations: 0, residual: 0.0 }
        };
        if !(weight > 0.0) {
            let x = chord.norm();
            let e_x = chord.try_normalize(0.0).unwrap_or_else(|| last.map_or(Vec3::x(), |s| s.e_x));
            return Ok(straight(e_x, any_perpendicular(&e_x), x));
        }
        let e_y = -gravity / g;
        let rise = chord.dot(&e_y);
        let horizontal = chord - e_y * rise;
        let span = horizontal.norm();
        let vertical = span <= 1e-14 * self.length;
        let e_x = if vertical { last.map_or_else(|| any_perpendicular(&e_y), |s| s.e_x) } else { horizontal / span };
        let closure = Closure { x: if vertical { 0.0 } else { span / self.length }, y: rise / self.length, epsilon: weight / axial_stiffness };
        let solved = solver::solve(&closure, last.and_then(LineState::unknowns)).ok_or(CatenaryError { span, rise })?;
        Ok(LineState {
            origin: *p1,
            e_x,
            e_y,
            span,
            rise,
            horizontal_tension: solved.unknowns.h * weight,
            vertical1: solved.unknowns.v * weight,
            weight,
            length: self.length,
            axial_stiffness,
            iterations: solved.iterations,
            residual: solved.residual,
        })
    }

    /// Forces at the kinematics `frames` (the line is quasi-static: end velocities do not
    /// enter), added to the end bodies' `loads` and written to `out`; the solution is kept in
    /// `cache` as the next warm start.
    pub fn apply(&self, cache: &mut CatenaryCache, frames: &[BodyFrame], gravity: &Vec3, loads: &mut [Load], out: &mut CouplingForces) -> Result<(), CatenaryError> {
        let (end1, end2) = (self.end1.motion(frames), self.end2.motion(frames));
        let state = self.solve(&end1.position, &end2.position, gravity, cache.last.as_ref())?;
        let (f1, f2) = state.end_forces();
        end1.apply(&f1, loads);
        end2.apply(&f2, loads);
        let (t1, t2) = state.end_tensions();
        *out = CouplingForces {
            point1: end1.position,
            point2: end2.position,
            f1,
            f2,
            tension: t1.max(t2),
            dissipated_power: 0.0,
            potential: state.potential_energy(),
        };
        cache.last = Some(state);
        Ok(())
    }
}

/// A unit vector perpendicular to `axis` (unit).
fn any_perpendicular(axis: &Vec3) -> Vec3 {
    let helper = if axis.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
    (helper - axis * axis.dot(&helper)).normalize()
}
