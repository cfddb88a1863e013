//! The contact law of one face (PHYSICS.md §4, seed [4958] and [4965]).
//!
//! Within the range `d < d0` of the opposing boundary, with penetration `x = d0 − d` [m] and
//! its rate `ẋ = −ḋ` [m/s]:
//! - normal force `f_n = max(0, a (k1 x + k2 ẋ))` [N] along the opposing boundary's normal. The
//!   clamp at zero makes the model purely repulsive: a face leaving fast is not pulled back
//!   (no adhesion), so the force drops to zero before the face is out of range;
//! - friction `f_t = −μ f_n tanh(k_t |v_t|) v_t/|v_t|` [N], `v_t` the sliding velocity of the
//!   face relative to the opposing boundary (kinetic friction, regularised at rest: a face
//!   under a tangential load `F < μ f_n` creeps at `v_t = atanh(F/(μ f_n))/k_t`);
//! - penalty energy `½ a k1 x²` [J]; power dissipated `(f_n − a k1 x) ẋ + μ f_n tanh(k_t|v_t|) |v_t|`
//!   [W] ≥ 0 (damping, the clamp, and friction).

use crate::physics::Vec3;

/// Contact parameters (PHYSICS.md §4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// `k1`: normal stiffness per unit face area [N/m³] (N/m for each m² in contact).
    pub stiffness: f64,
    /// `k2`: normal damping per unit face area [N·s/m³].
    pub damping: f64,
    /// `d0`: distance at which the contact starts to push [m].
    pub range: f64,
    /// `μ`: friction coefficient [-].
    pub friction: f64,
    /// `k_t`: sharpness of the tanh friction law [s/m].
    pub friction_sharpness: f64,
}

/// What the law gives for one face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceContact {
    /// `f_n + f_t` [N], in the axes of `normal`.
    pub force: Vec3,
    /// `|f_n|` [N].
    pub normal_force: f64,
    /// `f_t` [N].
    pub friction: Vec3,
    /// `½ a k1 x²` [J].
    pub potential: f64,
    /// Power dissipated [W] ≥ 0.
    pub dissipated_power: f64,
}

impl ContactLaw {
    /// The force on a face of area `area` [m²] at distance `distance` [m] < d0 from the opposing
    /// boundary, whose unit normal there is `normal` (pointing towards the face), moving at
    /// `relative_velocity` [m/s] relative to the boundary (same axes as `normal`).
    #[inline]
    pub fn face_force(&self, area: f64, distance: f64, normal: &Vec3, relative_velocity: &Vec3) -> FaceContact {
        let penetration = self.range - distance;
        let approach = -normal.dot(relative_velocity);
        let elastic = area * self.stiffness * penetration;
        let normal_force = (elastic + area * self.damping * approach).max(0.0);
        let sliding = relative_velocity + normal * approach;
        let slip = sliding.norm();
        let (friction, friction_power) = if slip > 0.0 && self.friction > 0.0 && normal_force > 0.0 {
            // μ f_n tanh(k_t |v_t|)/|v_t|, the friction force per unit sliding speed.
            let per_slip = self.friction * normal_force * tanh_over(self.friction_sharpness * slip, slip);
            (sliding * -per_slip, per_slip * slip * slip)
        } else {
            (Vec3::zeros(), 0.0)
        };
        FaceContact {
            force: normal * normal_force + friction,
            normal_force,
            friction,
            potential: 0.5 * elastic * penetration,
            dissipated_power: (normal_force - elastic) * approach + friction_power,
        }
    }
}

/// `tanh(x)/y` for `x ≥ 0`, `y > 0`, as `(1 − e)/((1 + e) y)`, `e = exp(−2x)`: `tanh x` to
/// within 3e-16 (absolute; the friction force is then within 3e-16 μ f_n of the law's, below the
/// round-off of summing the faces) with one division, at a third of the cost of `tanh(x)/y` or of
/// an `expm1` form, which matters once per face in contact.
#[inline]
fn tanh_over(x: f64, y: f64) -> f64 {
    let e = (-2.0 * x).exp();
    (1.0 - e) / ((1.0 + e) * y)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const LAW: ContactLaw = ContactLaw { stiffness: 1e6, damping: 2e3, range: 0.01, friction: 0.4, friction_sharpness: 50.0 };

    #[test]
    fn force_potential_and_dissipation_follow_the_formulas() {
        let n = Vec3::z();
        // 2 mm into the range, approaching at 0.1 m/s, sliding at 0.03 m/s along x.
        let c = LAW.face_force(0.5, 0.008, &n, &Vec3::new(0.03, 0.0, -0.1));
        let normal = 0.5 * (1e6 * 0.002 + 2e3 * 0.1);
        assert_relative_eq!(c.normal_force, normal, epsilon = 1e-9);
        assert_relative_eq!(c.friction, Vec3::new(-0.4 * normal * (50.0_f64 * 0.03).tanh(), 0.0, 0.0), epsilon = 1e-9);
        assert_relative_eq!(c.potential, 0.5 * 0.5 * 1e6 * 0.002 * 0.002, epsilon = 1e-12);
        let damping_power = 0.5 * 2e3 * 0.1 * 0.1;
        assert_relative_eq!(c.dissipated_power, damping_power + 0.4 * normal * (1.5_f64).tanh() * 0.03, epsilon = 1e-9);
    }

    #[test]
    fn the_tanh_shortcut_agrees_with_the_library() {
        // 10⁵ points spread evenly in log x over [1e-12, 50], and the ends.
        let sweep = (0..100_000).map(|i| 1e-12 * (50e12_f64).powf(f64::from(i) / 99_999.0));
        for x in sweep.chain([0.0, 19.1, 40.0, 1e300]) {
            assert!((tanh_over(x, 1.0) - x.tanh()).abs() <= 3e-16, "tanh {x}: {} against {}", tanh_over(x, 1.0), x.tanh());
            for y in [1e-9, 0.37, 2e4] {
                assert_relative_eq!(tanh_over(x, y) * y, tanh_over(x, 1.0), max_relative = 3e-16);
            }
        }
    }

    #[test]
    fn a_fast_retreating_face_is_not_pulled_back_and_dissipates_the_released_energy() {
        // Elastic 0.5·1e6·0.002 = 1000 N, damping −0.5·2e3·2 = −2000 N: clamped to zero.
        let c = LAW.face_force(0.5, 0.008, &Vec3::z(), &Vec3::new(1.0, 0.0, 2.0));
        assert_eq!(c.normal_force, 0.0);
        assert_eq!(c.force, Vec3::zeros(), "no friction without a normal force");
        // The penalty energy released at 2 m/s is dissipated: −(−1000 N)(2 m/s) … ≥ 0.
        assert_relative_eq!(c.dissipated_power, 1000.0 * 2.0, epsilon = 1e-9);
    }
}
