//! Spring-damper coupling (PHYSICS.md §2 \[4944]–\[4946]).
//!
//! `x = |x2 − x1|` \[m], `d = (x2 − x1)/x`, `ẋ = (v2 − v1)·d` [m/s] (positive when the ends
//! separate). Scalar force `f1 = f_e(x) + k_d ẋ` \[N] with the [`ElasticLaw`] `f_e`; the vector
//! `f1 d` acts on end 1 and `−f1 d` on end 2, so a stretched spring pulls the ends together.
//! Dissipated power `k_d ẋ²` \[W]; stored energy `V(x)` \[J].

use super::elastic_law::ElasticLaw;
use super::ends::Endpoint;
use super::forces::CouplingForces;
use crate::body::{BodyFrame, Load};
use crate::math::{Mat3, Vec3};
use crate::parameter::{Bound, ParameterError, require};

/// Below this distance [m] the ends count as coincident: the direction is undefined.
const COINCIDENT: f64 = 1e-12;

/// A spring and a parallel linear damper between two ends, built by [`SpringDamper::new`],
/// which checks its values.
#[derive(Debug, Clone, PartialEq)]
pub struct SpringDamper {
    end1: Endpoint,
    end2: Endpoint,
    law: ElasticLaw,
    damping: f64,
}

/// What a spring remembers: its last well-defined direction `d`, used while the ends coincide
/// (zero before any).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpringCache {
    direction: Vec3,
}

impl SpringCache {
    /// Length `x` [m] and unit direction `d` from end 1 to end 2. When the ends coincide the
    /// last direction is kept, so a compressed spring keeps pushing the way it did; with no
    /// history the direction is zero and so is the force.
    #[inline(always)]
    fn length_and_direction(&mut self, separation: &Vec3) -> (f64, Vec3) {
        let length = separation.norm();
        if length > COINCIDENT {
            self.direction = separation * length.recip();
        }
        (length, self.direction)
    }
}

impl SpringDamper {
    /// A spring of elastic `law` and damper `damping` k_d [N·s/m] ≥ 0 between two ends.
    ///
    /// # Errors
    /// A damping or a law coefficient out of its range ([`ElasticLaw::check`]), named by its field.
    pub fn new(end1: Endpoint, end2: Endpoint, law: ElasticLaw, damping: f64) -> Result<Self, ParameterError> {
        law.check()?;
        Ok(Self { end1, end2, law, damping: require("damping", damping, Bound::NonNegative, "N·s/m")? })
    }

    pub fn end1(&self) -> Endpoint {
        self.end1
    }

    pub fn end2(&self) -> Endpoint {
        self.end2
    }

    pub fn law(&self) -> &ElasticLaw {
        &self.law
    }

    /// `k_d` [N·s/m] ≥ 0.
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// Forces at the kinematics `frames` (PHYSICS.md §2 \[4944]–\[4945]), added to the end bodies' `loads`
    /// and written to `out`; `cache` keeps the direction for when the ends meet.
    #[inline(always)]
    pub fn apply(&self, cache: &mut SpringCache, frames: &[BodyFrame], loads: &mut [Load], out: &mut CouplingForces) {
        let (end1, end2) = (self.end1.motion(frames), self.end2.motion(frames));
        let (length, direction) = cache.length_and_direction(&(end2.position - end1.position));
        let rate = (end2.velocity - end1.velocity).dot(&direction);
        let damping_force = self.damping * rate;
        let (elastic_force, potential) = self.law.force_and_potential(length);
        let tension = elastic_force + damping_force;
        let f1 = direction * tension;
        end1.apply(&f1, loads);
        end2.apply(&-f1, loads);
        *out = CouplingForces {
            point1: end1.position,
            point2: end2.position,
            f1,
            f2: -f1,
            tension,
            dissipated_power: damping_force * rate,
            held_power: 0.0,
            potential,
        };
    }

    /// Tangent stiffness of the spring at rest (no damper force) at the kinematics `frames`:
    /// `K = ∂(f_e d)/∂p2 = k(x) d dᵀ + (f_e/x)(E − d dᵀ)` [N/m] (the spring turns with its ends),
    /// as the blocks `∂f_i/∂p_j = [[−K, K], [K, −K]]`; zero while the ends coincide.
    pub fn end_stiffness(&self, frames: &[BodyFrame]) -> [[Mat3; 2]; 2] {
        let separation = self.end2.motion(frames).position - self.end1.motion(frames).position;
        let length = separation.norm();
        if length <= COINCIDENT {
            return [[Mat3::zeros(); 2]; 2];
        }
        let d = separation / length;
        let along = d * d.transpose();
        let k =
            along * self.law.tangent_stiffness(length) + (Mat3::identity() - along) * (self.law.force(length) / length);
        [[-k, k], [k, -k]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Mat3;

    fn frame_at(position: Vec3) -> BodyFrame {
        BodyFrame {
            position,
            rotation: Mat3::identity(),
            velocity: Vec3::new(0.3, 0.0, 0.0),
            angular_velocity: Vec3::zeros(),
        }
    }

    #[test]
    fn coincident_ends_give_finite_forces_and_keep_the_last_direction() {
        let law = ElasticLaw::Linear { stiffness: 100.0, rest_length: 0.5 };
        // A valid law and damping: the constructor accepts them.
        let spring = SpringDamper::new(Endpoint::World(Vec3::zeros()), Endpoint::Center { body: 0 }, law, 2.0).unwrap();
        let mut cache = SpringCache::default();
        let mut loads = [Load::default()];
        let mut out = CouplingForces::default();
        // Never separated: no direction, no force, no NaN.
        spring.apply(&mut cache, &[frame_at(Vec3::zeros())], &mut loads, &mut out);
        assert_eq!(out.f1, Vec3::zeros());
        assert!(out.tension.is_finite() && out.dissipated_power.is_finite());
        // Separated along +x, then coincident again: the compressed spring keeps pushing along x.
        spring.apply(&mut cache, &[frame_at(Vec3::new(0.2, 0.0, 0.0))], &mut loads, &mut out);
        spring.apply(&mut cache, &[frame_at(Vec3::zeros())], &mut loads, &mut out);
        // f_e(0) = 100·(0 − 0.5) = −50 N, damping 2·(0.3·1) = 0.6 N: f1 = −49.4 x̂ (pushes end 1 away).
        assert!((out.f1 - Vec3::new(-49.4, 0.0, 0.0)).norm() < 1e-12, "{:?}", out.f1);
        assert!(out.f1.iter().all(|c| c.is_finite()));
    }
}
