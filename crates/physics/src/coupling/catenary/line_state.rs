//! The solved line at one instant (PHYSICS.md §3, §7): what its ends feel, its energy, its
//! tangent stiffness and its shape, free or lying on the seabed.

use super::equations::{Closure, rise, span};
use super::grounded::{Grounding, Profile};
use super::solver::Unknowns;
use crate::math::{Mat3, Vec3};

/// One of a line's two ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineEnd {
    First,
    Second,
}

/// The part of a line on the seabed (PHYSICS.md §7), seen from its anchor: the end that lies
/// on the bottom (friction acts there), or end 1 when neither does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ground {
    pub anchor: LineEnd,
    /// The ends' heights and span in units of the line, as solved.
    pub grounding: Grounding,
    /// The solved profile, in units of the line (lengths / `L_eq`, forces / `W`).
    pub profile: Profile,
    /// `z_b` \[m], along the line's upward unit vector.
    pub seabed: f64,
}

/// The solved line at one instant, world frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineState {
    /// End 1 \[m].
    pub origin: Vec3,
    /// Horizontal unit vector from end 1 toward end 2 (for a weightless line: along the chord),
    /// and the line's upward unit vector (against its submerged weight).
    pub e_x: Vec3,
    pub e_y: Vec3,
    /// Horizontal span `Δx` \[m] ≥ 0 and rise `Δy` \[m] of end 2 over end 1.
    pub span: f64,
    pub rise: f64,
    /// `H` \[N] ≥ 0 (of the suspended parts, for a grounded line) and `V1` \[N] (vertical force of
    /// the line on end 1, up positive).
    pub horizontal_tension: f64,
    pub vertical1: f64,
    /// Submerged weight `W = w L_eq` \[N], `L_eq` \[m] and `EA` \[N].
    pub weight: f64,
    pub length: f64,
    pub axial_stiffness: f64,
    /// Newton iterations of the solve (0 for a closed form or an exact warm start).
    pub iterations: u32,
    /// Closure residual of the solve, a fraction of `L_eq`.
    pub residual: f64,
    /// The part on the seabed, when the line lies on it.
    pub ground: Option<Ground>,
}

/// `∂f_i/∂p_j` [N/m]: how the force on end i changes as end j moves (`[i][j]`, world axes).
pub type EndStiffness = [[Mat3; 2]; 2];

impl LineState {
    /// `V2` \[N]: the line pulls end 2 down by `V2` (`V1 + W` for a free line).
    pub fn vertical2(&self) -> f64 {
        -self.end_forces().1.dot(&self.e_y)
    }

    /// End 2 \[m].
    pub fn end2(&self) -> Vec3 {
        self.origin + self.e_x * self.span + self.e_y * self.rise
    }

    /// Forces exerted by the line on end 1 and end 2 \[N].
    pub fn end_forces(&self) -> (Vec3, Vec3) {
        let Some(ground) = &self.ground else {
            let f1 = self.e_x * self.horizontal_tension + self.e_y * self.vertical1;
            let f2 = -self.e_x * self.horizontal_tension - self.e_y * (self.vertical1 + self.weight);
            return (f1, f2);
        };
        let along = self.anchor_direction(ground);
        let [(anchor_h, anchor_v), (other_h, other_v)] = ground.profile.end_forces();
        let at_anchor = (along * anchor_h + self.e_y * anchor_v) * self.weight;
        let at_other = -(along * other_h + self.e_y * other_v) * self.weight;
        match ground.anchor {
            LineEnd::First => (at_anchor, at_other),
            LineEnd::Second => (at_other, at_anchor),
        }
    }

    /// Tensions at end 1 and end 2 \[N].
    pub fn end_tensions(&self) -> (f64, f64) {
        if self.ground.is_none() {
            return (
                self.horizontal_tension.hypot(self.vertical1),
                self.horizontal_tension.hypot(self.vertical1 + self.weight),
            );
        }
        let (f1, f2) = self.end_forces();
        (f1.norm(), f2.norm())
    }

    /// `u1 = asinh(V1/H1)`, `u2 = asinh(V2/H2)` of PHYSICS.md's parametric form, from each end's
    /// horizontal and vertical force (±∞ where `H` = 0).
    pub fn parameters(&self) -> (f64, f64) {
        let (f1, f2) = self.end_forces();
        let u = |h: f64, v: f64| if h > 0.0 { (v / h).asinh() } else { f64::INFINITY.copysign(v) };
        (u(f1.dot(&self.e_x), f1.dot(&self.e_y)), u(-f2.dot(&self.e_x), -f2.dot(&self.e_y)))
    }

    /// `L_B` \[m]: the length lying on the seabed (0 for a free line).
    pub fn grounded_length(&self) -> f64 {
        self.ground.map_or(0.0, |g| g.profile.grounded.max(0.0) * self.length)
    }

    /// Where the suspended parts meet the seabed \[m]: the touchdown of the part hanging from the
    /// end that does not lie on the bottom, and of the anchor's when it is suspended too.
    pub fn touchdowns(&self) -> Vec<Vec3> {
        let Some(ground) = &self.ground else { return Vec::new() };
        let (first, second) = ground.profile.touchdowns();
        let mut points = Vec::with_capacity(2);
        if ground.profile.first.length > 0.0 {
            points.push(self.on_ground(ground, first, 0.0));
        }
        if ground.profile.second.length > 0.0 {
            points.push(self.on_ground(ground, second, 0.0));
        }
        points
    }

    /// The horizontal unit vector from the anchor toward the other end.
    fn anchor_direction(&self, ground: &Ground) -> Vec3 {
        match ground.anchor {
            LineEnd::First => self.e_x,
            LineEnd::Second => -self.e_x,
        }
    }

    /// The anchor's position [m].
    fn anchor_position(&self, ground: &Ground) -> Vec3 {
        match ground.anchor {
            LineEnd::First => self.origin,
            LineEnd::Second => self.end2(),
        }
    }

    /// The world point `along` (units of `L_eq`) from the anchor horizontally, `up` (units of
    /// `L_eq`) above the seabed.
    fn on_ground(&self, ground: &Ground, along: f64, up: f64) -> Vec3 {
        let anchor = self.anchor_position(ground);
        anchor
            + self.anchor_direction(ground) * (along * self.length)
            + self.e_y * (ground.seabed + up * self.length - anchor.dot(&self.e_y))
    }

    /// Dimensionless unknowns of this state (`h = H/W`, `v = V1/W`), the warm start of a free
    /// solve.
    pub(super) fn unknowns(&self) -> Option<Unknowns> {
        (self.weight > 0.0)
            .then(|| Unknowns { h: self.horizontal_tension / self.weight, v: self.vertical1 / self.weight })
    }

    /// `count + 1` points evenly spaced along the unstretched line from end 1 to end 2, with
    /// the tension there [m, N]. A free line, with `s` the unstretched arc length and
    /// `τ = V1 + w s` the vertical force (`w = W/L_eq`):
    /// `x(s) = (H/w)(asinh(τ/H) − asinh(V1/H)) + H s/EA`,
    /// `y(s) = (√(H²+τ²) − √(H²+V1²))/w + (τ² − V1²)/(2 w EA)`, `T = √(H² + τ²)`; a grounded
    /// line, its suspended parts from their touchdowns and its grounded part on the seabed
    /// ([`Profile::point`]).
    pub fn sample(&self, count: usize) -> Vec<(Vec3, f64)> {
        let count = count.max(1);
        if self.weight <= 0.0 {
            let tension = self.horizontal_tension;
            return (0..=count)
                .map(|i| (self.origin + self.e_x * (self.span * i as f64 / count as f64), tension))
                .collect();
        }
        let eps = self.weight / self.axial_stiffness;
        if let Some(ground) = &self.ground {
            return (0..=count)
                .map(|i| {
                    let sigma = i as f64 / count as f64;
                    let from_anchor = if ground.anchor == LineEnd::First { sigma } else { 1.0 - sigma };
                    let (along, up, tension) = ground.profile.point(from_anchor, eps);
                    (self.on_ground(ground, along, up), tension * self.weight)
                })
                .collect();
        }
        let (h, v) = (self.horizontal_tension / self.weight, self.vertical1 / self.weight);
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

    /// Height \[m] of the lowest point of the free line along `e_y`: its vertex where the
    /// vertical force vanishes between the ends (`−1 < v1 < 0`, at `rise(h, v1, 0) − ε v1²/2`
    /// below end 1 in units of `L_eq`), else its lower end.
    pub fn lowest_height(&self) -> f64 {
        let (y1, y2) = (self.origin.dot(&self.e_y), self.origin.dot(&self.e_y) + self.rise);
        let ends = y1.min(y2);
        if self.weight <= 0.0 {
            return ends;
        }
        let (h, v1) = (self.horizontal_tension / self.weight, self.vertical1 / self.weight);
        if !(v1 < 0.0 && v1 > -1.0) {
            return ends;
        }
        let eps = self.weight / self.axial_stiffness;
        ends.min(y1 + (rise(h, v1, 0.0) - 0.5 * eps * v1 * v1) * self.length)
    }

    /// Potential energy of the line \[J]: weight (heights along `e_y`, zero at the world origin)
    /// plus elastic strain. Integrating `∫ w y ds` and `∫ T²/(2EA) ds` over the solved shape
    /// and using the closure equations, in units of `W L_eq`:
    /// `U = y1/L + v2 Y − (v2 r2 − v1 r1)/2 + h X/2 − ε (v2³ − v1³)/6`, `r_i = √(h² + v_i²)`.
    /// A grounded line: `W z_b` plus its profile's energy above the bottom
    /// ([`Profile::potential`]). For a weightless rope, `½ D (x − L_eq)²` when stretched. Its
    /// gradient with respect to the end positions is minus the end forces (on the seabed, where
    /// `C_B = 0`: friction makes the grounded line's forces depend on more than its shape).
    pub fn potential_energy(&self) -> f64 {
        if self.weight <= 0.0 {
            let stretch = (self.span - self.length).max(0.0);
            return 0.5 * self.axial_stiffness / self.length * stretch * stretch;
        }
        let (w, l) = (self.weight, self.length);
        let eps = w / self.axial_stiffness;
        if let Some(ground) = &self.ground {
            return w * ground.seabed + w * l * ground.profile.potential(eps);
        }
        let (h, v1) = (self.horizontal_tension / w, self.vertical1 / w);
        let v2 = v1 + 1.0;
        let (x, y) = (self.span / l, self.rise / l);
        let (r1, r2) = (h.hypot(v1), h.hypot(v2));
        let cubes = (v2 - v1) * (v2 * v2 + v2 * v1 + v1 * v1);
        w * l * (self.origin.dot(&self.e_y) / l + v2 * y - 0.5 * (v2 * r2 - v1 * r1) + 0.5 * h * x - eps * cubes / 6.0)
    }

    /// Tangent stiffness of a free line `K = ∂f1/∂p2` [N/m] (so `∂f1/∂p1 = −K`, `∂f2/∂p2 = −K`):
    /// in the plane, `∂(H, V1)/∂(Δx, Δy) = (W/L) J⁻¹` with `J` the closure Jacobian; out of the
    /// plane the line turns about the vertical, `H/Δx`. For a grounded line, `−∂f2/∂p2`, which
    /// [`LineState::end_stiffness`] gives with the other blocks.
    pub fn tangent_stiffness(&self) -> Mat3 {
        if self.ground.is_some() {
            return -self.end_stiffness()[1][1];
        }
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

    /// All four blocks `∂f_i/∂p_j` [N/m]. A free line's forces depend on `p2 − p1` only:
    /// `[[−K, K], [K, −K]]`. A grounded line's depend on the span and on each end's height above
    /// the seabed, which holds the difference: with the anchor's force `W (h_A e' − ℓ1 e_y)`
    /// and the other end's `−W (h e' + ℓ2 e_y)` (`e'` from the anchor toward the other end),
    /// the profile's [`Profile::sensitivity`] to `(x, z1, z2)`, `∂x/∂p = ±e'/L`,
    /// `∂z/∂p = e_y/L`, and the turn of `e'` about the vertical, `∂e'/∂p_other = e_z e_zᵀ/Δx`.
    pub fn end_stiffness(&self) -> EndStiffness {
        let Some(ground) = &self.ground else {
            let k = self.tangent_stiffness();
            return [[-k, k], [k, -k]];
        };
        let along = self.anchor_direction(ground);
        let (w, l) = (self.weight, self.length);
        let sensitivity = ground.profile.sensitivity();
        let e_z = along.cross(&self.e_y);
        let turn = if self.span > 0.0 { e_z * e_z.transpose() / self.span } else { Mat3::zeros() };
        // Gradient with respect to an end's position of a quantity with partials `d` by (x, z1, z2).
        let by_anchor = |d: [f64; 3]| (-along * d[0] + self.e_y * d[1]) / l;
        let by_other = |d: [f64; 3]| (along * d[0] + self.e_y * d[2]) / l;
        let [(anchor_h, _), (other_h, _)] = ground.profile.end_forces();
        let anchor_force = |by: &dyn Fn([f64; 3]) -> Vec3, sign: f64| {
            (along * by(sensitivity.anchor).transpose() - self.e_y * by(sensitivity.first).transpose()
                + turn * (sign * anchor_h))
                * w
        };
        let other_force = |by: &dyn Fn([f64; 3]) -> Vec3, sign: f64| {
            -(along * by(sensitivity.h).transpose()
                + self.e_y * by(sensitivity.second).transpose()
                + turn * (sign * other_h))
                * w
        };
        let (aa, ao) = (anchor_force(&by_anchor, -1.0), anchor_force(&by_other, 1.0));
        let (oa, oo) = (other_force(&by_anchor, -1.0), other_force(&by_other, 1.0));
        match ground.anchor {
            LineEnd::First => [[aa, ao], [oa, oo]],
            LineEnd::Second => [[oo, oa], [ao, aa]],
        }
    }
}
