//! Spring-damper coupling (PHYSICS.md §2, seed 000 [4944]–[4946]).
//!
//! `x = |x2 − x1|` [m], `d = (x2 − x1)/x`, `ẋ = (v2 − v1)·d` [m/s] (positive when the ends
//! separate). Scalar force `f1 = f_e(x) + k_d ẋ` [N] with the [`ElasticLaw`] `f_e`; the vector
//! `f1 d` acts on end 1 and `−f1 d` on end 2, so a stretched spring pulls the ends together.
//! Dissipated power `k_d ẋ²` [W]; stored energy `V(x)` [J].

use super::{BodyFrame, CouplingForces, ElasticLaw, Endpoint, Load};
use crate::physics::Vec3;

/// Below this distance [m] the ends count as coincident: the direction is undefined.
const COINCIDENT: f64 = 1e-12;

/// A spring and a parallel linear damper between two ends.
#[derive(Debug, Clone, PartialEq)]
pub struct SpringDamper {
    pub end1: Endpoint,
    pub end2: Endpoint,
    pub law: ElasticLaw,
    /// `k_d` [N·s/m] ≥ 0.
    pub damping: f64,
    /// Last well-defined direction `d`, used while the ends coincide (zero before any).
    direction: Vec3,
}

impl SpringDamper {
    pub fn new(end1: Endpoint, end2: Endpoint, law: ElasticLaw, damping: f64) -> Self {
        Self { end1, end2, law, damping, direction: Vec3::zeros() }
    }

    /// Length `x` [m] and unit direction `d` from end 1 to end 2. When the ends coincide the
    /// last direction is kept, so a compressed spring keeps pushing the way it did; with no
    /// history the direction is zero and so is the force.
    fn length_and_direction(&mut self, separation: &Vec3) -> (f64, Vec3) {
        let length = separation.norm();
        if length > COINCIDENT {
            self.direction = separation * length.recip();
        }
        (length, self.direction)
    }

    /// Forces at the kinematics `frames` (seed [4944]–[4945]), added to the end bodies' `loads`
    /// and written to `out`.
    #[inline]
    pub fn apply(&mut self, frames: &[BodyFrame], loads: &mut [Load], out: &mut CouplingForces) {
        let (end1, end2) = (self.end1.motion(frames), self.end2.motion(frames));
        let (length, direction) = self.length_and_direction(&(end2.position - end1.position));
        let rate = (end2.velocity - end1.velocity).dot(&direction);
        let damping_force = self.damping * rate;
        let tension = self.law.force(length) + damping_force;
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
        };
    }

    /// `V(x)` [J].
    pub fn potential_energy(&self, frames: &[BodyFrame]) -> f64 {
        let length = (self.end2.motion(frames).position - self.end1.motion(frames).position).norm();
        self.law.potential(length)
    }
}
