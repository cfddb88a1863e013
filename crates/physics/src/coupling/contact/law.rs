//! The contact law of one face (PHYSICS.md §4 \[4958] and \[4965]).
//!
//! Within the range `d < d0` of the opposing boundary, with penetration `x = d0 − d` \[m] and
//! its rate `ẋ = −ḋ` [m/s]:
//! - normal force `f_n = max(0, a (k1 x + k2 ẋ))` \[N] along the opposing boundary's normal. The
//!   clamp at zero makes the model purely repulsive: a face leaving fast is not pulled back
//!   (no adhesion), so the force drops to zero before the face is out of range;
//! - friction `f_t = −μ f_n tanh(k_t |v_t|) v_t/|v_t|` \[N], `v_t` the sliding velocity of the
//!   face relative to the opposing boundary (kinetic friction, regularised at rest: a face
//!   under a tangential load `F < μ f_n` creeps at `v_t = atanh(F/(μ f_n))/k_t`);
//! - penalty energy `½ a k1 x²` \[J]; power dissipated `(f_n − a k1 x) ẋ + μ f_n tanh(k_t|v_t|) |v_t|`
//!   \[W] ≥ 0 (damping, the clamp, and friction).

use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require};

/// Contact parameters (PHYSICS.md §4), built by [`ContactLaw::new`], which checks them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    stiffness: f64,
    damping: f64,
    range: f64,
    friction: f64,
    friction_sharpness: f64,
}

/// What the law gives for one face.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FaceContact {
    /// `f_n + f_t` \[N], in the axes of `normal`.
    pub force: Vec3,
    /// `|f_n|` \[N].
    pub normal_force: f64,
    /// `f_t` \[N].
    pub friction: Vec3,
    /// `½ a k1 x²` \[J].
    pub potential: f64,
    /// Power dissipated \[W] ≥ 0.
    pub dissipated_power: f64,
}

impl ContactLaw {
    /// The law of stiffness `k1` [N/m³] > 0, damping `k2` [N·s/m³] ≥ 0, range `d0` \[m] ≥ 0,
    /// friction `μ` [–] ≥ 0 and friction sharpness `k_t` [s/m] > 0.
    ///
    /// # Errors
    /// A value out of its range, named by its field.
    pub fn new(
        stiffness: f64,
        damping: f64,
        range: f64,
        friction: f64,
        friction_sharpness: f64,
    ) -> Result<Self, ParameterError> {
        Ok(Self {
            stiffness: require("stiffness", stiffness, Bound::Positive, "N/m³")?,
            damping: require("damping", damping, Bound::NonNegative, "N·s/m³")?,
            range: require("range", range, Bound::NonNegative, "m")?,
            friction: require("friction", friction, Bound::NonNegative, "")?,
            friction_sharpness: require("friction_sharpness", friction_sharpness, Bound::Positive, "s/m")?,
        })
    }

    /// `k1`: normal stiffness per unit face area [N/m³] (N/m for each m² in contact).
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// `k2`: normal damping per unit face area [N·s/m³].
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// `d0`: distance at which the contact starts to push \[m].
    pub fn range(&self) -> f64 {
        self.range
    }

    /// `μ`: friction coefficient [–].
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// `k_t`: sharpness of the tanh friction law [s/m].
    pub fn friction_sharpness(&self) -> f64 {
        self.friction_sharpness
    }

    /// The force on a face of area `area` \[m²] at distance `distance` \[m] < d0 from the opposing
    /// boundary, whose unit normal there is `normal` (pointing towards the face), moving at
    /// `relative_velocity` [m/s] relative to the boundary (same axes as `normal`).
    #[inline(always)]
    pub fn face_force(&self, area: f64, distance: f64, normal: &Vec3, relative_velocity: &Vec3) -> FaceContact {
        let penetration = self.range - distance;
        let approach = -normal.dot(relative_velocity);
        let elastic = area * self.stiffness * penetration;
        let normal_force = (elastic + area * self.damping * approach).max(0.0);
        let sliding = relative_velocity + normal * approach;
        let slip = sliding.norm();
        // μ f_n tanh(k_t |v_t|)/|v_t|, the friction force per unit sliding speed; none without
        // sliding (where the quotient is 0/0) or without a normal force. Selected rather than
        // branched on, so that faces evaluated side by side run as vector instructions.
        let per_slip = self.friction * normal_force * tanh_over(self.friction_sharpness * slip, slip);
        let per_slip = if slip > 0.0 && normal_force > 0.0 { per_slip } else { 0.0 };
        let friction = sliding * -per_slip;
        let friction_power = per_slip * slip * slip;
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
/// within 5e-16 (absolute; the friction force is then within 5e-16 μ f_n of the law's, below the
/// round-off of summing the faces) with one division and an inlined, branch-free exponential
/// (no library call), so that faces side by side run as vector instructions.
#[inline(always)]
fn tanh_over(x: f64, y: f64) -> f64 {
    // Below −40 (and for NaN), e⁻⁴⁰ = 4.2e-18 already gives tanh = 1 in double precision.
    let e = exp_of_non_positive((-2.0 * x).max(EXP_FLOOR));
    (1.0 - e) / ((1.0 + e) * y)
}

/// Lowest argument of [`exp_of_non_positive`].
const EXP_FLOOR: f64 = -40.0;

/// `eˣ` for `x ∈ [−40, 0]` to 2 ulp, inlined and branch-free: `x = k ln2 + r` with
/// `|r| ≤ ln2/2` (Cody–Waite: `k ln2` in two parts, the first exact), `e^r` from its Taylor
/// series to `r¹³` (remainder < 5e-18 relative) in Estrin's scheme (four levels of products
/// instead of thirteen in sequence), and `2ᵏ` written into the exponent bits.
#[inline(always)]
fn exp_of_non_positive(x: f64) -> f64 {
    const LN2_HIGH: f64 = f64::from_bits(0x3fe6_2e42_fee0_0000); // 0.693 147 180 369 123 816 49: 32 bits
    const LN2_LOW: f64 = 1.908_214_929_270_587_7e-10; // ln 2 − LN2_HIGH
    // Adding 1.5·2⁵² rounds to an integer, which lands in the low bits of the sum (|k| ≤ 58).
    const ROUNDING: f64 = 6_755_399_441_055_744.0;
    // 1/i! for i = 0..=13.
    const C: [f64; 14] = [
        1.0,
        1.0,
        1.0 / 2.0,
        1.0 / 6.0,
        1.0 / 24.0,
        1.0 / 120.0,
        1.0 / 720.0,
        1.0 / 5040.0,
        1.0 / 40_320.0,
        1.0 / 362_880.0,
        1.0 / 3_628_800.0,
        1.0 / 39_916_800.0,
        1.0 / 479_001_600.0,
        1.0 / 6_227_020_800.0,
    ];
    let shifted = x * std::f64::consts::LOG2_E + ROUNDING;
    let k = shifted - ROUNDING;
    let r = (x - k * LN2_HIGH) - k * LN2_LOW;
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let pair = |i: usize| C[i] + C[i + 1] * r;
    let low = (pair(0) + pair(2) * r2) + (pair(4) + pair(6) * r2) * r4;
    let high = (pair(8) + pair(10) * r2) + pair(12) * r4;
    let series = low + high * r8;
    // The low 12 bits of `shifted` hold k (two's complement) over zeros: adding the exponent
    // bias and shifting them to the exponent field gives 2ᵏ, a normal number for k ∈ [−58, 0].
    let power_of_two = f64::from_bits(shifted.to_bits().wrapping_add(1023) << 52);
    series * power_of_two
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const LAW: ContactLaw =
        ContactLaw { stiffness: 1e6, damping: 2e3, range: 0.01, friction: 0.4, friction_sharpness: 50.0 };

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
    fn the_inlined_exponential_agrees_with_the_library() {
        // 10⁵ points evenly over [−40, 0], and the ends and special values.
        let sweep = (0..100_000).map(|i| EXP_FLOOR * f64::from(i) / 99_999.0);
        for x in sweep.chain([0.0, -1e-300, -1e-17, -0.5 * std::f64::consts::LN_2, EXP_FLOOR]) {
            assert_relative_eq!(exp_of_non_positive(x), x.exp(), max_relative = 4.5e-16);
        }
    }

    #[test]
    fn the_tanh_shortcut_agrees_with_the_library() {
        // 10⁵ points spread evenly in log x over [1e-12, 50], and the ends.
        let sweep = (0..100_000).map(|i| 1e-12 * (50e12_f64).powf(f64::from(i) / 99_999.0));
        for x in sweep.chain([0.0, 19.1, 40.0, 1e300]) {
            assert!(
                (tanh_over(x, 1.0) - x.tanh()).abs() <= 5e-16,
                "tanh {x}: {} against {}",
                tanh_over(x, 1.0),
                x.tanh()
            );
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
