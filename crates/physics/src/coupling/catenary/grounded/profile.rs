//! The equations of a line lying on the seabed (PHYSICS.md §7), in units of the line: lengths
//! divided by `L_eq`, forces by its submerged weight `W = w L_eq`, compliance `ε = W/EA`.
//!
//! Seen from its *anchor* (the end on the seabed, or end 1 when neither lies on it) the line
//! has up to three parts: a suspended part hanging from the anchor down to touchdown `T1`
//! (none when the anchor lies on the seabed), the grounded part `ℓ_B` from `T1` to `T2`, and a
//! suspended part from `T2` up to the other end. A suspended part meets the bottom
//! tangentially (no vertical force at its touchdown) and carries the horizontal tension `h`;
//! reaching height `z` above the bottom it has the unstretched length `ℓ` with
//!
//! `z = √(h² + ℓ²) − h + ε ℓ²/2`
//!
//! (PHYSICS.md's `Z_F` with `V_F = ℓ`), a quadratic in `ℓ²` solved without cancellation:
//! `ℓ² = 2C/(B + √D)`, `B = 1 + ε(z + h)`, `C = z² + 2zh`, `D = B² − ε² C = 1 + 2ε(z + h) + ε²h²`;
//! its horizontal extent is `ξ = h asinh(ℓ/h) + ε h ℓ`.
//!
//! The grounded part `ℓ_B = 1 − ℓ1 − ℓ2 ≥ 0` lies straight on the bottom. When the anchor lies
//! on the seabed, friction `C_B` per unit weight takes tension off it toward the anchor:
//! `h_A = max(h − C_B ℓ_B, 0)`, and the part stretches by `σ = ε ℓ_B (h − ½ C_B ℓ_B)` while
//! `h ≥ C_B ℓ_B`, else `σ = ε h²/(2 C_B)`. Without friction (or with a suspended anchor, where
//! static friction has no direction to act in and is left out, as MoorPy does) `h_A = h` and
//! `σ = ε h ℓ_B`. The horizontal closure
//!
//! `X(h) = ξ1 + ℓ_B + σ + ξ2 = x`
//!
//! fixes `h`: with `ℓ1 = 0` it is PHYSICS.md's `X_F`. `X` increases with `h` (pulled harder,
//! the touchdown moves toward the anchor and the line straightens), so one bracketed 1-D solve
//! finds it ([`super::solver`]).

/// A line on the seabed seen from its anchor, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Grounding {
    /// Horizontal span from the anchor to the other end, `Δx/L` ≥ 0.
    pub x: f64,
    /// Height of the anchor above the bottom, `/L` ≥ 0 (0: it lies on the bottom).
    pub z1: f64,
    /// Height of the other end above the bottom, `/L` ≥ 0.
    pub z2: f64,
    /// `ε = W/EA` > 0.
    pub epsilon: f64,
    /// `C_B` ≥ 0, acting only when the anchor lies on the bottom.
    pub friction: f64,
}

/// One suspended part at a horizontal tension, with the derivatives the solve and the
/// stiffness need.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Suspended {
    /// `ℓ`, unstretched, ≥ 0 (0 for an end on the bottom).
    pub length: f64,
    /// `ρ = √(h² + ℓ²)`: the tension at the end.
    pub radius: f64,
    /// `∂ℓ/∂h = ℓ/((ρ + h)(1 + ερ))` and `∂ℓ/∂z = ρ/(ℓ(1 + ερ))` (taken as 0 for an end on the
    /// bottom, which the bottom holds).
    pub length_h: f64,
    pub length_z: f64,
    /// `ξ = h asinh(ℓ/h) + ε h ℓ`, and its partial derivatives at fixed `ℓ`:
    /// `ξ_h = asinh(ℓ/h) − ℓ/ρ + ε ℓ`, `ξ_ℓ = h/ρ + ε h`.
    pub extent: f64,
    pub extent_h: f64,
    pub extent_length: f64,
}

impl Suspended {
    /// The part reaching height `z` ≥ 0 with horizontal tension `h` ≥ 0, compliance `epsilon`.
    #[inline]
    pub fn new(h: f64, z: f64, epsilon: f64) -> Self {
        if !(z > 0.0) {
            // An end on the bottom: nothing hangs, and ξ = 0 whatever h.
            return Self { radius: h, extent_length: 1.0 + epsilon * h, ..Self::default() };
        }
        let b = 1.0 + epsilon * (z + h);
        let d = 1.0 + 2.0 * epsilon * (z + h) + (epsilon * h) * (epsilon * h);
        let squared = 2.0 * z * (z + 2.0 * h) / (b + d.sqrt());
        let length = squared.sqrt();
        // ρ = √(h² + ℓ²) from the part's own equation, without a square root.
        let radius = z + h - 0.5 * epsilon * squared;
        let stiffening = 1.0 + epsilon * radius;
        let (extent, extent_h) = if h > 0.0 {
            // asinh(ℓ/h) = ln(1 + (ℓ + ρ − h)/h), ρ − h = ℓ²/(ρ + h): no cancellation.
            let angle = (length * (1.0 + length / (radius + h)) / h).ln_1p();
            (h * angle + epsilon * h * length, angle - length / radius + epsilon * length)
        } else {
            (0.0, f64::INFINITY)
        };
        Self {
            length,
            radius,
            length_h: length / ((radius + h) * stiffening),
            length_z: radius / (length * stiffening),
            extent,
            extent_h,
            extent_length: h / radius + epsilon * h,
        }
    }

    /// Horizontal offset and height above the bottom of the point at unstretched arc length
    /// `s` from the touchdown, `(h asinh(s/h) + ε h s, s²/(√(h² + s²) + h) + ε s²/2)`, and the
    /// tension there `√(h² + s²)`.
    pub fn point(h: f64, s: f64, epsilon: f64) -> (f64, f64, f64) {
        let radius = h.hypot(s);
        let along = if h > 0.0 { h * (s / h).asinh() + epsilon * h * s } else { 0.0 };
        let sum = radius + h;
        let up = if sum > 0.0 { s * s / sum } else { 0.0 } + 0.5 * epsilon * s * s;
        (along, up, radius)
    }

    /// Potential energy of the part above the bottom, in units of `W L_eq`: its weight times
    /// its height above the bottom, `∫ (√(h² + s²) − h + ε s²/2) ds = ½(ℓρ + h² asinh(ℓ/h)) − hℓ
    /// + εℓ³/6`, plus its strain energy `∫ ε (h² + s²)/2 ds = ε(h²ℓ + ℓ³/3)/2`.
    pub fn potential(&self, h: f64, epsilon: f64) -> f64 {
        let l = self.length;
        let arch = if h > 0.0 { h * h * (l / h).asinh() } else { 0.0 };
        let gravity = 0.5 * (l * self.radius + arch) - h * l + epsilon * l * l * l / 6.0;
        let strain = 0.5 * epsilon * (h * h * l + l * l * l / 3.0);
        gravity + strain
    }
}

/// The line at one horizontal tension `h`: its parts, the closure `X(h)` and its derivatives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Profile {
    /// `h` ≥ 0.
    pub h: f64,
    /// The part hanging from the anchor, and the one hanging from the other end.
    pub first: Suspended,
    pub second: Suspended,
    /// `ℓ_B = 1 − ℓ1 − ℓ2` (negative: the line cannot reach the bottom at this `h`).
    pub grounded: f64,
    /// `C_B` acting on the grounded part (0 unless the anchor lies on the bottom).
    pub friction: f64,
    /// `h_A`: horizontal tension at the anchor.
    pub anchor: f64,
    /// `σ`: stretch of the grounded part.
    pub stretch: f64,
    /// `X(h)` and `∂X/∂h`, `∂X/∂z1`, `∂X/∂z2`.
    pub closure: f64,
    pub closure_h: f64,
    pub closure_z1: f64,
    pub closure_z2: f64,
}

impl Grounding {
    /// The friction that acts: `C_B` when the anchor lies on the bottom, else 0.
    fn acting_friction(&self) -> f64 {
        if self.z1 <= 0.0 { self.friction } else { 0.0 }
    }

    /// The line at horizontal tension `h` ≥ 0.
    #[inline]
    pub fn profile(&self, h: f64) -> Profile {
        let eps = self.epsilon;
        let first = Suspended::new(h, self.z1, eps);
        let second = Suspended::new(h, self.z2, eps);
        let grounded = 1.0 - first.length - second.length;
        let friction = self.acting_friction();
        let lb = grounded.max(0.0);
        let (anchor, stretch, stretch_h) = if friction > 0.0 {
            let anchor = (h - friction * lb).max(0.0);
            let stretch =
                if anchor > 0.0 { eps * lb * (h - 0.5 * friction * lb) } else { eps * h * h / (2.0 * friction) };
            (anchor, stretch, eps * lb.min(h / friction))
        } else {
            (h, eps * h * lb, eps * lb)
        };
        // ∂X/∂ℓ_i at fixed h: the part's extent grows, the grounded part shrinks (with its stretch).
        let slope = |part: &Suspended| part.extent_length - 1.0 - eps * anchor;
        let closure = first.extent + second.extent + lb + stretch;
        let along =
            |part: &Suspended| if part.length > 0.0 { part.extent_h + slope(part) * part.length_h } else { 0.0 };
        Profile {
            h,
            first,
            second,
            grounded,
            friction,
            anchor,
            stretch,
            closure,
            closure_h: along(&first) + along(&second) + stretch_h,
            closure_z1: slope(&first) * first.length_z,
            closure_z2: slope(&second) * second.length_z,
        }
    }
}

/// How the solved line answers a move of its ends: derivatives with respect to `(x, z1, z2)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sensitivity {
    /// `∂h`, `∂ℓ1`, `∂ℓ2`, `∂h_A` by `∂(x, z1, z2)`.
    pub h: [f64; 3],
    pub first: [f64; 3],
    pub second: [f64; 3],
    pub anchor: [f64; 3],
}

impl Profile {
    /// Forces exerted by the line, `(horizontal toward the other end, vertical up)` on the anchor
    /// and `(horizontal toward the anchor, vertical down)` on the other end:
    /// `(h_A, −ℓ1)` and `(h, ℓ2)`.
    pub fn end_forces(&self) -> [(f64, f64); 2] {
        [(self.anchor, -self.first.length), (self.h, self.second.length)]
    }

    /// Whether the line lies on the bottom with no horizontal tension (heaped, or hanging
    /// vertically from both ends).
    pub fn is_slack(&self) -> bool {
        self.h <= 0.0
    }

    /// By implicit differentiation of `X(h; z1, z2) = x`: `dh = (dx − X_z1 dz1 − X_z2 dz2)/X_h`,
    /// then `dℓ_i = ℓ_i,h dh + ℓ_i,z dz_i` and `dh_A = dh − C_B dℓ_B` while `h_A > 0`. A slack
    /// line does not answer a change of span (`dh = 0`).
    pub fn sensitivity(&self) -> Sensitivity {
        let dh = if self.is_slack() || !(self.closure_h > 0.0) {
            [0.0; 3]
        } else {
            [1.0 / self.closure_h, -self.closure_z1 / self.closure_h, -self.closure_z2 / self.closure_h]
        };
        let first = [
            self.first.length_h * dh[0],
            self.first.length_h * dh[1] + self.first.length_z,
            self.first.length_h * dh[2],
        ];
        let second = [
            self.second.length_h * dh[0],
            self.second.length_h * dh[1],
            self.second.length_h * dh[2] + self.second.length_z,
        ];
        let anchor = if self.friction > 0.0 {
            if self.anchor > 0.0 {
                std::array::from_fn(|i| dh[i] + self.friction * (first[i] + second[i]))
            } else {
                [0.0; 3]
            }
        } else {
            dh
        };
        Sensitivity { h: dh, first, second, anchor }
    }

    /// The tension `h` at `to`, predicted to first order from this profile solved at `from`:
    /// `h + (Δx − X_z1 Δz1 − X_z2 Δz2)/X_h`, kept positive (a warm start of [`super::solver`]).
    pub fn predict(&self, from: &Grounding, to: &Grounding) -> f64 {
        if self.is_slack() || !(self.closure_h > 0.0) {
            return self.h;
        }
        let change = (to.x - from.x) - self.closure_z1 * (to.z1 - from.z1) - self.closure_z2 * (to.z2 - from.z2);
        let predicted = self.h + change / self.closure_h;
        if predicted > 0.25 * self.h { predicted } else { 0.25 * self.h }
    }

    /// Potential energy in units of `W L_eq`, heights measured from the bottom: the suspended
    /// parts' ([`Suspended::potential`]) plus the grounded part's strain energy,
    /// `ε h² ℓ_B/2` without friction, `ε (h³ − h_A³)/(6 C_B)` with it.
    pub fn potential(&self, epsilon: f64) -> f64 {
        let lb = self.grounded.max(0.0);
        let strain = if self.friction > 0.0 {
            epsilon * (self.h.powi(3) - self.anchor.powi(3)) / (6.0 * self.friction)
        } else {
            0.5 * epsilon * self.h * self.h * lb
        };
        self.first.potential(self.h, epsilon) + self.second.potential(self.h, epsilon) + strain
    }

    /// Horizontal distances of the touchdowns `T1`, `T2` from the anchor: `ξ1` and `ξ1 + ℓ_B + σ`.
    pub fn touchdowns(&self) -> (f64, f64) {
        (self.first.extent, self.first.extent + self.grounded.max(0.0) + self.stretch)
    }

    /// The point at unstretched arc length `s` ∈ [0, 1] from the anchor: horizontal distance
    /// from the anchor, height above the bottom, tension.
    pub fn point(&self, s: f64, epsilon: f64) -> (f64, f64, f64) {
        let (h, l1, lb) = (self.h, self.first.length, self.grounded.max(0.0));
        let (t1, t2) = self.touchdowns();
        if s <= l1 {
            let (along, up, tension) = Suspended::point(h, l1 - s, epsilon);
            return (t1 - along, up, tension);
        }
        if s <= l1 + lb {
            // From the anchor side of the grounded part: tension rises by C_B per length from
            // h_A (or from 0 where friction has taken it all) to h at T2.
            let u = s - l1;
            if self.friction > 0.0 {
                let tension = (h - self.friction * (lb - u)).max(0.0);
                let stretched = epsilon * (tension * tension - self.anchor * self.anchor) / (2.0 * self.friction);
                return (t1 + u + stretched, 0.0, tension);
            }
            return (t1 + u * (1.0 + epsilon * h), 0.0, h);
        }
        let (along, up, tension) = Suspended::point(h, s - l1 - lb, epsilon);
        (t2 + along, up, tension)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn a_part_reaches_its_height() {
        for &(h, z, eps) in &[(0.3, 0.4, 1e-3), (0.0, 0.2, 0.1), (5.0, 0.01, 1e-9), (1e-6, 0.5, 1e-5), (40.0, 0.9, 0.3)]
        {
            let part = Suspended::new(h, z, eps);
            let l = part.length;
            let reached = (h * h + l * l).sqrt() - h + 0.5 * eps * l * l;
            assert_relative_eq!(reached, z, max_relative = 1e-13);
            let (_, up, _) = Suspended::point(h, l, eps);
            assert_relative_eq!(up, z, max_relative = 1e-13);
        }
    }

    #[test]
    fn closure_derivatives_match_finite_differences() {
        for &(z1, z2, eps, friction) in
            &[(0.0, 0.4, 1e-3, 0.0), (0.0, 0.3, 0.05, 2.0), (0.1, 0.2, 1e-4, 0.0), (0.0, 0.05, 0.2, 0.5)]
        {
            for h in [0.05, 0.3, 1.7] {
                let g = Grounding { x: 0.0, z1, z2, epsilon: eps, friction };
                let p = g.profile(h);
                if p.grounded <= 0.01 {
                    continue; // the line does not reach the bottom at this tension
                }
                let d = 1e-7;
                let fd_h = (g.profile(h + d).closure - g.profile(h - d).closure) / (2.0 * d);
                assert_relative_eq!(p.closure_h, fd_h, max_relative = 1e-6);
                let moved = |dz1: f64, dz2: f64| Grounding { z1: z1 + dz1, z2: z2 + dz2, ..g }.profile(h).closure;
                if z1 > 0.0 {
                    assert_relative_eq!(
                        p.closure_z1,
                        (moved(d, 0.0) - moved(-d, 0.0)) / (2.0 * d),
                        max_relative = 1e-6
                    );
                }
                assert_relative_eq!(p.closure_z2, (moved(0.0, d) - moved(0.0, -d)) / (2.0 * d), max_relative = 1e-6);
            }
        }
    }
}
