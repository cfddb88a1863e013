//! The faces of a boundary that can be in range of a plane: a Verlet list for face contact.
//!
//! Face f of a body is at distance `d_f = h + n_b·r_f` [m] from a plane (height of G
//! `h = n·(x_G − p)`, plane normal in the body frame `n_b = Rᵀ n`, centroid `r_f`). Since the
//! list was drawn up at `(h₀, n_b₀)`, no distance has changed by more than the *drift*
//! `|h − h₀| + |n_b − n_b₀| r_max` (Cauchy–Schwarz, `r_max` the boundary's bounding radius). A
//! list of the faces with `d_f < d0 + margin` then holds every face in range for as long as the
//! drift stays below the margin, so a body resting on or rolling along a plane tests the few
//! faces around its lowest point rather than culling its whole boundary each step. The list is
//! drawn up again when the drift reaches the margin: the result is exactly that of testing every
//! face, in the same order.

use super::batch::{FaceBatch, LANES};
use crate::math::Vec3;
use crate::mesh::BoundaryMesh;

/// Margin of a list [m]: `d0/2`. Wider lists are longer (more faces evaluated every step);
/// narrower ones are drawn up more often. On chain100 (d0 = 5 mm, 5 cm spheres rolling on the
/// ground) the wider `max(d0, r_max/10)` listed about twice the faces in range.
fn margin(range: f64) -> f64 {
    0.5 * range
}

/// The drift may use this share of the margin: the rest absorbs the round-off of the distances
/// (relative 1e-16), so the list is never short of a face by rounding.
const USABLE_MARGIN: f64 = 0.99;

/// Faces of one boundary that may be in range of one plane.
#[derive(Debug, Clone, Default)]
pub struct Shortlist {
    /// The faces, in the order of [`BoundaryMesh::faces`] (group by group), in batches.
    batches: Vec<FaceBatch>,
    /// `h₀` [m] and `n_b₀` when the list was drawn up.
    height: f64,
    normal: Vec3,
    /// `d0` the list was drawn up for; NaN before the first (so that no list covers).
    range: f64,
}

/// Lists of a boundary are only a cache of its faces: two contacts are equal whatever their
/// lists hold.
impl PartialEq for Shortlist {
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

impl Shortlist {
    /// An empty list that covers nothing, drawn up at first use.
    pub fn new() -> Self {
        Self { range: f64::NAN, ..Self::default() }
    }

    /// The faces of `boundary` that may be in range `range` [m] of a plane at height `height`
    /// [m] with body-frame normal `normal`, in batches: the list, drawn up again if it has
    /// expired.
    #[inline]
    pub fn batches(&mut self, boundary: &BoundaryMesh, height: f64, normal: &Vec3, range: f64) -> &[FaceBatch] {
        let reach = boundary.bounding_radius();
        let margin = margin(range);
        // drift ≤ usable margin, as |Δn_b|² r_max² ≤ (usable margin − |Δh|)² (no square root).
        let turning_allowance = USABLE_MARGIN * margin - (height - self.height).abs();
        let turning = (normal - self.normal).norm_squared() * reach * reach;
        // NaN (no list yet, or a non-finite pose) fails the test and draws one up.
        if !(self.range == range && turning_allowance >= 0.0 && turning <= turning_allowance * turning_allowance) {
            self.draw_up(boundary, height, normal, range, margin);
        }
        &self.batches
    }

    /// The faces with `d_f < range + margin`, found by culling the boundary's groups, packed
    /// [`LANES`] to a batch in the list's own storage (drawing up allocates nothing once the list
    /// has held its longest).
    fn draw_up(&mut self, boundary: &BoundaryMesh, height: f64, normal: &Vec3, range: f64, margin: f64) {
        let limit = range + margin;
        let (mut chunk, mut filled) = ([0; LANES], 0);
        self.batches.clear();
        for group in boundary.groups() {
            if height + normal.dot(&group.center) - group.radius >= limit {
                continue;
            }
            let mut in_range = group.below(height, normal, limit);
            // Ends: each pass clears the lowest set bit.
            while in_range != 0 {
                chunk[filled] = group.first + in_range.trailing_zeros() as usize;
                in_range &= in_range - 1;
                filled += 1;
                if filled == LANES {
                    self.batches.push(FaceBatch::of(boundary.faces(), &chunk));
                    filled = 0;
                }
            }
        }
        if filled > 0 {
            self.batches.push(FaceBatch::of(boundary.faces(), &chunk[..filled]));
        }
        (self.height, self.normal, self.range) = (height, *normal, range);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Rotation;
    use crate::mesh::primitives;
    use proptest::prelude::*;

    /// The faces of a list, in order.
    fn listed(batches: &[FaceBatch]) -> Vec<usize> {
        batches.iter().flat_map(|batch| batch.index.iter().take(batch.lanes.count_ones() as usize).copied()).collect()
    }

    /// The faces with `h + n_b·r_f < range`, every face tested.
    fn in_range_by_testing_all(boundary: &BoundaryMesh, height: f64, normal: &Vec3, range: f64) -> Vec<usize> {
        (0..boundary.faces().len()).filter(|&i| height + normal.dot(&boundary.faces()[i].centroid) < range).collect()
    }

    proptest! {
        /// Along a random walk of a sphere's pose near a plane, small steps (that keep a list)
        /// and jumps (that expire it) alike, the list holds every face in range.
        #[test]
        fn the_list_holds_every_face_in_range(moves in prop::collection::vec((-0.004..0.004_f64, prop::array::uniform3(-0.08..0.08_f64), 0..6_u8), 1..60)) {
            let (vertices, triangles) = primitives::icosphere(0.05, &Vec3::zeros(), 1);
            let boundary = BoundaryMesh::new(vertices, triangles).expect("an icosphere is a valid mesh");
            let range = 0.005;
            let mut list = Shortlist::new();
            let (mut height, mut orientation) = (0.047, Rotation::identity());
            for (lift, turn, jump) in moves {
                // One move in six is a jump of ten times the size.
                let scale = if jump == 0 { 10.0 } else { 1.0 };
                height += scale * lift;
                orientation *= Rotation::from_scaled_axis(Vec3::from(turn) * scale);
                let normal = orientation.inverse_transform_vector(&Vec3::z());
                let listed = listed(list.batches(&boundary, height, &normal, range));
                for face in in_range_by_testing_all(&boundary, height, &normal, range) {
                    prop_assert!(listed.contains(&face), "face {face} in range at h = {height} is not on the list {listed:?}");
                }
            }
        }
    }

    #[test]
    fn a_resting_sphere_keeps_its_list_and_tests_few_faces() {
        let (vertices, triangles) = primitives::icosphere(0.05, &Vec3::zeros(), 1);
        let boundary = BoundaryMesh::new(vertices, triangles).expect("an icosphere is a valid mesh");
        let mut list = Shortlist::new();
        let first = list.batches(&boundary, 0.049, &Vec3::z(), 0.005).to_vec();
        let listed = listed(&first).len();
        // Within d0 + margin = 7.5 mm of the lowest point: the faces around it, not the 80.
        assert!(listed > 0 && listed <= 12, "{listed} faces listed");
        // 1 mm lower and turned 0.02 rad: drift 1 mm + 1 mm < 0.99 × 2.5 mm, the same list.
        let turned = Rotation::from_scaled_axis(Vec3::new(0.02, 0.0, 0.0)).inverse_transform_vector(&Vec3::z());
        assert_eq!(list.batches(&boundary, 0.048, &turned, 0.005), first);
        assert_eq!(list.height, 0.049, "kept, not drawn up again");
        // A longer range expires it.
        list.batches(&boundary, 0.048, &turned, 0.006);
        assert_eq!(list.range, 0.006);
    }
}
