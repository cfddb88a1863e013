//! Faces against a plane four at a time: the face law (PHYSICS.md §4) in vector instructions.
//!
//! A [`FaceBatch`] holds up to [`LANES`] faces lane by lane (centroid coordinates and area in
//! the body's principal frame). Every lane runs the same scalar code, [`ContactLaw::face_force`],
//! which the compiler turns into vector instructions: [`accumulate`], the step's sums, is inlined
//! into the couplings stage, which is built for AVX-512 and AVX2 as well (four lanes per
//! instruction, chosen at run time by what the processor has), and otherwise, like
//! [`FaceBatch::contacts`] for display, uses the SSE2 every x86-64 has. A face out of range is
//! given zero area rather than skipped, and the lane sums keep each component's four lanes side
//! by side, so that the whole batch, law and sums, runs in vector instructions with no branch
//! (its instruction count: docs/speed.md, "The contact batch"). Lanes are independent and IEEE
//! arithmetic is the same in vector and scalar form (no fused multiply–add is introduced), so
//! each face's contact is that of the face-by-face evaluation, bit for bit.

use super::law::{ContactLaw, FaceContact};
use crate::math::Vec3;
use crate::mesh::Face;

/// Faces per batch.
pub const LANES: usize = 4;

/// Up to [`LANES`] faces, lane by lane; unused lanes are masked out by `lanes`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FaceBatch {
    /// Index of each lane's face in [`crate::mesh::BoundaryMesh::faces`].
    pub index: [usize; LANES],
    /// Centroid `r_f` [m] and area `a_f` [m²].
    x: [f64; LANES],
    y: [f64; LANES],
    z: [f64; LANES],
    area: [f64; LANES],
    /// Bit i set when lane i holds a face.
    pub(super) lanes: u32,
}

/// What a step needs of the faces in contact, summed in the frame they were evaluated in.
#[derive(Debug, Clone, Copy, Default)]
pub struct Accumulated {
    /// `Σ f_f` [N].
    pub force: Vec3,
    /// `Σ r_f × f_f` [N·m].
    pub moment: Vec3,
    /// `Σ |f_n|` [N].
    pub normal: f64,
    /// `Σ f_t` [N], summed face by face against a body (against planes, the step leaves it to
    /// [`super::normals::NormalForces`]).
    pub friction: Vec3,
    pub potential: f64,
    pub dissipated_power: f64,
}

impl Accumulated {
    /// Adds face contact `contact` at `centroid`.
    #[inline]
    pub fn add(&mut self, centroid: &Vec3, contact: &FaceContact) {
        self.force += contact.force;
        self.moment += centroid.cross(&contact.force);
        self.normal += contact.normal_force;
        self.friction += contact.friction;
        self.potential += contact.potential;
        self.dissipated_power += contact.dissipated_power;
    }
}

/// A plane as the faces of one body see it, in the body's principal frame.
#[derive(Debug, Clone, Copy)]
pub struct PlaneView {
    /// Height of G above the plane `h = n·(x_G − p)` [m].
    pub height: f64,
    /// The plane's normal `n_b = Rᵀ n`.
    pub normal: Vec3,
    /// Velocity of G `Rᵀ v` [m/s].
    pub velocity: Vec3,
    /// Angular velocity ω [rad/s].
    pub spin: Vec3,
}

impl FaceBatch {
    /// The faces `chunk` (at most [`LANES`] indices into `faces`), lane by lane in order.
    pub fn of(faces: &[Face], chunk: &[usize]) -> Self {
        let face = |lane: usize| chunk.get(lane).map(|&i| &faces[i]);
        let coordinate = |axis: usize| std::array::from_fn(|lane| face(lane).map_or(0.0, |f| f.centroid[axis]));
        Self {
            index: std::array::from_fn(|lane| chunk.get(lane).copied().unwrap_or(0)),
            x: coordinate(0),
            y: coordinate(1),
            z: coordinate(2),
            area: std::array::from_fn(|lane| face(lane).map_or(0.0, |f| f.area)),
            lanes: (1 << chunk.len()) - 1,
        }
    }

    /// The law at every lane against `plane`, and which lanes hold a face in range
    /// (`d_f < d0`, bit i for lane i); the other lanes are to be ignored (they are given zero
    /// area, as in [`accumulate`]).
    pub fn contacts(&self, law: &ContactLaw, plane: &PlaneView) -> ([FaceContact; LANES], u32) {
        let mut in_range = 0;
        let contacts = std::array::from_fn(|lane| {
            let centroid = self.centroid(lane);
            let distance = plane.height + plane.normal.dot(&centroid);
            let area = if distance < law.range() { self.area[lane] } else { 0.0 };
            in_range |= u32::from(distance < law.range()) << lane;
            let face_velocity = plane.velocity + plane.spin.cross(&centroid);
            law.face_force(area, distance, &plane.normal, &face_velocity)
        });
        (contacts, in_range & self.lanes)
    }

    /// Lane `lane`'s centroid [m].
    #[inline(always)]
    fn centroid(&self, lane: usize) -> Vec3 {
        Vec3::new(self.x[lane], self.y[lane], self.z[lane])
    }
}

/// Adds the faces in range of `batches` against `plane` to `lanes`, lane by lane. One call
/// takes every batch, so that the processor overlaps the batches' chains of square root,
/// exponential and division. Always inlined, so that it is built with the instructions of its
/// caller (the couplings stage's AVX-512 or AVX2 build) and the sums stay in vector registers.
#[inline(always)]
pub fn accumulate(batches: &[FaceBatch], law: &ContactLaw, plane: &PlaneView, lanes: &mut LaneSums) {
    for batch in batches {
        // Each lane runs the same code: one vector instruction for the four. The lane's code is
        // written out here rather than shared with `contacts` through a function returning the
        // contact, which the compiler does not vectorise (docs/speed.md, "Against MuJoCo").
        for lane in 0..LANES {
            let centroid = batch.centroid(lane);
            let distance = plane.height + plane.normal.dot(&centroid);
            let area = if distance < law.range() { batch.area[lane] } else { 0.0 };
            let face_velocity = plane.velocity + plane.spin.cross(&centroid);
            lanes.add(lane, &centroid, &law.face_force(area, distance, &plane.normal, &face_velocity));
        }
    }
}

/// [`Accumulated`] lane by lane, each component's lanes side by side (so that adding four
/// faces' contacts is one vector addition per component).
#[derive(Default)]
pub struct LaneSums {
    force: [[f64; LANES]; 3],
    moment: [[f64; LANES]; 3],
    normal: [f64; LANES],
    potential: [f64; LANES],
    dissipated_power: [f64; LANES],
}

impl LaneSums {
    /// Adds face contact `contact` at `centroid` to lane `lane`.
    #[inline(always)]
    fn add(&mut self, lane: usize, centroid: &Vec3, contact: &FaceContact) {
        let moment = centroid.cross(&contact.force);
        for axis in 0..3 {
            self.force[axis][lane] += contact.force[axis];
            self.moment[axis][lane] += moment[axis];
        }
        self.normal[lane] += contact.normal_force;
        self.potential[lane] += contact.potential;
        self.dissipated_power[lane] += contact.dissipated_power;
    }

    /// `Σ |f_n|` [N] across the lanes so far.
    #[inline(always)]
    pub fn normal(&self) -> f64 {
        lane_sum(&self.normal)
    }

    /// The sums across the lanes (`friction` left at zero: see [`Accumulated::friction`]).
    #[inline(always)]
    pub fn total(&self) -> Accumulated {
        Accumulated {
            force: Vec3::from_fn(|axis, _| lane_sum(&self.force[axis])),
            moment: Vec3::from_fn(|axis, _| lane_sum(&self.moment[axis])),
            normal: lane_sum(&self.normal),
            friction: Vec3::zeros(),
            potential: lane_sum(&self.potential),
            dissipated_power: lane_sum(&self.dissipated_power),
        }
    }
}

/// The sum of one component's lanes.
#[inline(always)]
fn lane_sum(lanes: &[f64; LANES]) -> f64 {
    lanes.iter().fold(0.0, |total, value| total + value)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::BoundaryMesh;
    use crate::mesh::primitives;
    use approx::assert_relative_eq;

    /// An icosphere of radius 5 cm with G 43 mm above a plane (d0 = 5 mm), sliding and spinning.
    fn sunk_sphere() -> (BoundaryMesh, ContactLaw, PlaneView) {
        let (vertices, triangles) = primitives::icosphere(0.05, &Vec3::zeros(), 1);
        let boundary = BoundaryMesh::new(vertices, triangles).expect("an icosphere is a valid mesh");
        let law = ContactLaw::new(2e6, 3e4, 0.005, 0.5, 20.0).expect("valid");
        let plane = PlaneView {
            height: 0.043,
            normal: Vec3::new(0.1, -0.2, -1.0).normalize(),
            velocity: Vec3::new(0.03, -0.01, 0.002),
            spin: Vec3::new(0.4, 1.1, -0.3),
        };
        (boundary, law, plane)
    }

    #[test]
    fn batches_give_what_the_face_law_gives_face_by_face() {
        let (boundary, law, plane) = sunk_sphere();
        let faces = boundary.faces();
        // Every face, so that most lanes are out of range, and 81 = 20 batches and one lane.
        let indices: Vec<usize> = (0..faces.len()).chain([7]).collect();
        let batches: Vec<FaceBatch> = indices.chunks(LANES).map(|chunk| FaceBatch::of(faces, chunk)).collect();
        let mut expected = Accumulated::default();
        let mut in_range = 0;
        for (batch, chunk) in batches.iter().zip(indices.chunks(LANES)) {
            let (contacts, lanes) = batch.contacts(&law, &plane);
            for (lane, &index) in chunk.iter().enumerate() {
                let face = &faces[index];
                let distance = plane.height + plane.normal.dot(&face.centroid);
                let one = law.face_force(
                    face.area,
                    distance,
                    &plane.normal,
                    &(plane.velocity + plane.spin.cross(&face.centroid)),
                );
                assert_eq!(lanes & (1 << lane) != 0, distance < law.range());
                if distance < law.range() {
                    assert_eq!(contacts[lane], one, "face {index}: the same arithmetic, bit for bit");
                    expected.add(&face.centroid, &one);
                    in_range += 1;
                }
            }
            assert_eq!(lanes >> chunk.len(), 0, "no unused lane is in range");
        }
        assert!(in_range > 5, "{in_range} faces in range");
        let mut lanes = LaneSums::default();
        accumulate(&batches, &law, &plane, &mut lanes);
        let sums = lanes.total();
        assert_relative_eq!(sums.force, expected.force, max_relative = 1e-14);
        // Σ f_t = Σ f_f − n Σ|f_n| (PHYSICS.md §4, as the contact's friction is found): a
        // difference of sums as large as the normal force, so its round-off is relative to that
        // force (1e-14: a few ulp of each of the ~20 faces' terms).
        let friction = sums.force - plane.normal * lanes.normal();
        assert!(
            expected.friction.norm() > 1e-3 * expected.normal,
            "the sphere slides: friction {}",
            expected.friction.norm()
        );
        assert_relative_eq!(friction, expected.friction, epsilon = 1e-14 * expected.normal);
        assert_relative_eq!(sums.moment, expected.moment, max_relative = 1e-14);
        assert_relative_eq!(sums.normal, expected.normal, max_relative = 1e-14);
        assert_relative_eq!(sums.potential, expected.potential, max_relative = 1e-14);
        assert_relative_eq!(sums.dissipated_power, expected.dissipated_power, max_relative = 1e-14);
    }
}
