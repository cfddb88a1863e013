//! Boundary meshes: the closed triangle mesh a contact sees of a body (PHYSICS.md §4).
//!
//! A [`BoundaryMesh`] is fixed in the body's principal frame (origin G) \[m]. Each face keeps
//! what the contact force needs, computed once: area `a_f` \[m²], centroid `r_f` \[m] and unit
//! outward normal. The triangles are checked and wound outward by [`OutwardMesh`], as a hull's
//! are (a mesh wound inwards is turned over, judged by the sign of its enclosed volume).
//!
//! [`Surface`] is the same boundary as an opposing surface for another body's faces: parry's
//! triangle mesh with its bounding-volume hierarchy answers "how far is this point from the
//! boundary, on which side, and what is the normal there".

mod check;
pub mod primitives;

pub use check::{MAX_EXTENT, MIN_THICKNESS, MeshError, OutwardMesh, TurnedOver};
pub(crate) use check::{double_area_normal, signed_volume};

use crate::body::{RigidBody, Shape};
use crate::math::{Vec3, bounding_box};
use parry3d_f64::math::Point;
use parry3d_f64::query::PointQueryWithLocation as _;
use parry3d_f64::shape::{TriMesh, TriMeshFlags};

/// One face of a boundary mesh, principal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Face {
    /// `r_f` \[m].
    pub centroid: Vec3,
    /// Unit outward normal.
    pub normal: Vec3,
    /// `a_f` \[m²].
    pub area: f64,
}

/// Up to this many faces share a bounding ball in a [`FaceGroup`].
pub const GROUP_SIZE: usize = 8;

/// Consecutive faces that lie close together (a part of a median split of the centroids), and
/// the ball around their centroids: whatever
/// is out of range of the ball is out of range of every face in it. The centroids are also
/// kept lane by lane, so that [`FaceGroup::below`] tests the whole group at once (the compiler
/// turns its loop into vector instructions).
#[derive(Debug, Clone, PartialEq)]
pub struct FaceGroup {
    /// Centre of the ball \[m].
    pub center: Vec3,
    /// Radius of the ball \[m].
    pub radius: f64,
    /// Index of the group's first face in [`BoundaryMesh::faces`].
    pub first: usize,
    /// Centroid coordinates, one lane per face; unused lanes are masked out by `lanes`.
    x: [f64; GROUP_SIZE],
    y: [f64; GROUP_SIZE],
    z: [f64; GROUP_SIZE],
    /// Bit i set when lane i holds a face.
    lanes: u32,
}

impl FaceGroup {
    fn new(first: usize, faces: &[Face]) -> Self {
        let center = faces.iter().map(|f| f.centroid).sum::<Vec3>() / faces.len() as f64;
        let radius = faces.iter().map(|f| (f.centroid - center).norm()).fold(0.0, f64::max);
        let lane = |axis: usize| std::array::from_fn(|i| faces.get(i).map_or(0.0, |f| f.centroid[axis]));
        Self { center, radius, first, x: lane(0), y: lane(1), z: lane(2), lanes: (1 << faces.len()) - 1 }
    }

    /// The group's faces, a range of [`BoundaryMesh::faces`].
    pub fn faces(&self) -> std::ops::Range<usize> {
        self.first..self.first + self.lanes.count_ones() as usize
    }

    /// Bit i set for each face i of the group with `offset + direction·r_f < limit` \[m].
    #[inline]
    pub fn below(&self, offset: f64, direction: &Vec3, limit: f64) -> u32 {
        let distances: [f64; GROUP_SIZE] = std::array::from_fn(|i| {
            offset + direction.x * self.x[i] + direction.y * self.y[i] + direction.z * self.z[i]
        });
        let bits = distances.iter().enumerate().fold(0, |bits, (i, d)| if *d < limit { bits | 1 << i } else { bits });
        bits & self.lanes
    }
}

/// A body's boundary as faces, principal frame.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundaryMesh {
    /// Vertices \[m].
    vertices: Vec<Vec3>,
    /// Counter-clockwise seen from outside.
    triangles: Vec<[u32; 3]>,
    /// Ordered group by group.
    faces: Vec<Face>,
    groups: Vec<FaceGroup>,
    /// `max |v|` over the vertices [m]: the boundary lies in the ball of this radius about G.
    bounding_radius: f64,
}

impl BoundaryMesh {
    /// Vertices \[m].
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    /// Counter-clockwise seen from outside.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// A boundary from vertices \[m] and triangles (vertex indices), checked and wound outward by
    /// [`OutwardMesh::new`] (a mesh wound inwards is turned over). Degenerate triangles are kept
    /// for display but give no face.
    ///
    /// # Errors
    /// See [`OutwardMesh::new`].
    pub fn new(vertices: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        let (vertices, triangles) = OutwardMesh::new(vertices, triangles)?.into_parts();
        let mut faces: Vec<Face> = triangles
            .iter()
            .filter_map(|t| {
                let scaled_normal = double_area_normal(&vertices, t);
                let double_area = scaled_normal.norm();
                (double_area > 0.0).then(|| Face {
                    centroid: t.map(|i| vertices[i as usize]).iter().sum::<Vec3>() / 3.0,
                    normal: scaled_normal / double_area,
                    area: 0.5 * double_area,
                })
            })
            .collect();
        let mut groups = Vec::new();
        split_into_groups(&mut faces, 0, &mut groups);
        let bounding_radius = vertices.iter().map(|v| v.norm()).fold(0.0, f64::max);
        Ok(Self { vertices, triangles, faces, groups, bounding_radius })
    }

    /// The faces with positive area.
    pub fn faces(&self) -> &[Face] {
        &self.faces
    }

    /// The faces in groups of neighbours with their bounding balls.
    pub fn groups(&self) -> &[FaceGroup] {
        &self.groups
    }

    /// Radius of the ball about G that holds the boundary \[m].
    pub fn bounding_radius(&self) -> f64 {
        self.bounding_radius
    }

    /// The volume the boundary encloses \[m³] (the body's, for a closed mesh).
    pub fn volume(&self) -> f64 {
        signed_volume(&self.vertices, &self.triangles)
    }

    /// `Σ a_f` \[m²].
    pub fn area(&self) -> f64 {
        self.faces.iter().map(|f| f.area).sum()
    }

    /// The boundary of `body`'s shape, in its principal frame.
    ///
    /// # Errors
    /// A shape mesh that is not a valid boundary (see [`BoundaryMesh::new`]).
    pub fn of_body(body: &RigidBody) -> Result<Self, MeshError> {
        let (vertices, triangles) = shape_in_principal_frame(body);
        Self::new(vertices, triangles)
    }
}

/// The triangles of `body`'s shape (a primitive meshed, or its mesh) with their vertices in the
/// body's principal frame \[m]: what its contact boundary and its hull are built from.
pub fn shape_in_principal_frame(body: &RigidBody) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let (vertices, triangles) = match &body.shape {
        Shape::Box { size, center, subdivisions } => primitives::cuboid(size, center, *subdivisions),
        Shape::Sphere { radius, center, subdivisions } => primitives::icosphere(*radius, center, *subdivisions),
        Shape::Cylinder { radius, length, axis, center } => primitives::cylinder(*radius, *length, axis, center),
        Shape::Mesh { vertices, triangles } => (vertices.clone(), triangles.clone()),
    };
    let to_principal = &body.reference_in_principal;
    (vertices.iter().map(|v| to_principal.transform_point(&(*v).into()).coords).collect(), triangles)
}

/// Splits `faces` (starting at index `first` of the whole list) in place at the median of
/// their centroids along the longest side of their bounds, recursively, until each part holds at
/// most [`GROUP_SIZE`] faces; appends each part as a group. The parts are compact, so their
/// bounding balls are small.
fn split_into_groups(faces: &mut [Face], first: usize, groups: &mut Vec<FaceGroup>) {
    if faces.len() <= GROUP_SIZE {
        groups.push(FaceGroup::new(first, faces));
        return;
    }
    let (low, high) = bounding_box(faces.iter().map(|f| f.centroid));
    let axis = (high - low).imax();
    let middle = faces.len() / 2;
    faces.select_nth_unstable_by(middle, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
    let (lower, upper) = faces.split_at_mut(middle);
    split_into_groups(lower, first, groups);
    split_into_groups(upper, first + middle, groups);
}

/// Where a point is relative to a [`Surface`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfacePoint {
    /// Signed distance to the boundary \[m]: positive outside, negative inside.
    pub distance: f64,
    /// Unit outward normal of the boundary at the nearest point.
    pub normal: Vec3,
}

/// A boundary as an opposing surface: distance and normal queries through a BVH.
#[derive(Clone)]
pub struct Surface {
    mesh: TriMesh,
    /// Bounds of the boundary in its own frame [m].
    low: Vec3,
    high: Vec3,
    /// `max |v|` over the vertices [m].
    reach: f64,
}

impl std::fmt::Debug for Surface {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Surface")
            .field("triangles", &self.mesh.indices().len())
            .field("low", &self.low)
            .field("high", &self.high)
            .finish()
    }
}

impl PartialEq for Surface {
    fn eq(&self, other: &Self) -> bool {
        self.mesh.vertices() == other.mesh.vertices() && self.mesh.indices() == other.mesh.indices()
    }
}

impl Surface {
    /// The opposing surface of `boundary` (its vertices' frame).
    ///
    /// # Errors
    /// A mesh parry cannot orient (needed for the inside test).
    pub fn new(boundary: &BoundaryMesh) -> Result<Self, MeshError> {
        let vertices: Vec<Point<f64>> = boundary.vertices.iter().map(|v| Point::from(*v)).collect();
        let mesh = TriMesh::with_flags(
            vertices,
            boundary.triangles.clone(),
            TriMeshFlags::ORIENTED | TriMeshFlags::MERGE_DUPLICATE_VERTICES,
        )
        .map_err(|e| MeshError::Topology(format!("{e:?}")))?;
        let aabb = mesh.local_aabb();
        Ok(Self { mesh, low: aabb.mins.coords, high: aabb.maxs.coords, reach: boundary.bounding_radius() })
    }

    /// Radius of the ball about the frame's origin that holds the surface \[m].
    pub fn bounding_radius(&self) -> f64 {
        self.reach
    }

    /// Whether `point` \[m] is within `margin` \[m] of the surface's bounding box; never for a
    /// non-finite point (whose NaN the componentwise maximum would drop).
    pub fn near_bounds(&self, point: &Vec3, margin: f64) -> bool {
        let outside_box = (self.low - point).sup(&(point - self.high)).sup(&Vec3::zeros());
        point.iter().all(|x| x.is_finite()) && outside_box.norm_squared() <= margin * margin
    }

    /// The boundary's point nearest to `point` (surface frame) \[m], if `point` is within `range`
    /// of the boundary's bounding box; `None` means farther than `range` from the boundary.
    pub fn nearest(&self, point: &Vec3, range: f64) -> Option<SurfacePoint> {
        if !self.near_bounds(point, range) {
            return None;
        }
        let query = Point::from(*point);
        let (projection, (triangle, _)) = self.mesh.project_local_point_and_get_location(&query, false);
        let offset = point - projection.point.coords;
        let gap = offset.norm();
        let sign = if projection.is_inside { -1.0 } else { 1.0 };
        // On the boundary itself the offset has no direction: the face's normal is the normal.
        let normal = match (offset * sign).try_normalize(1e-12 * (1.0 + point.norm())) {
            Some(n) => n,
            None => self.mesh.triangle(triangle).normal().map_or(Vec3::z(), |n| n.into_inner()),
        };
        Some(SurfacePoint { distance: sign * gap, normal })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn a_box_has_its_area_and_outward_normals_even_when_wound_inwards() {
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(1.0, 2.0, 3.0), &Vec3::zeros(), 1);
        let inward: Vec<[u32; 3]> = triangles.iter().map(|t| [t[0], t[2], t[1]]).collect();
        for triangles in [triangles, inward] {
            let mesh = BoundaryMesh::new(vertices.clone(), triangles).expect("a box is a valid mesh");
            assert_relative_eq!(mesh.area(), 2.0 * (2.0 + 6.0 + 3.0), epsilon = 1e-12);
            for face in mesh.faces() {
                assert!(
                    face.normal.dot(&face.centroid) > 0.0,
                    "normal {:?} at {:?} points inwards",
                    face.normal,
                    face.centroid
                );
            }
        }
    }

    #[test]
    fn a_box_too_thin_to_query_is_refused_and_one_just_thick_enough_is_queried() {
        let thin = primitives::cuboid(&Vec3::new(1e-320, 0.3, 0.3), &Vec3::zeros(), 1);
        assert!(matches!(BoundaryMesh::new(thin.0, thin.1), Err(MeshError::TooThin { axis: 'x', .. })));
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(2.0 * MIN_THICKNESS, 0.3, 0.3), &Vec3::zeros(), 1);
        let surface = Surface::new(&BoundaryMesh::new(vertices, triangles).expect("thick enough")).expect("closed box");
        let above = surface.nearest(&Vec3::new(0.0, 0.0, 0.16), 0.1).expect("within range");
        assert_relative_eq!(above.distance, 0.01, epsilon = 1e-12);
    }

    #[test]
    fn signed_distance_to_a_box_surface() {
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(2.0, 2.0, 2.0), &Vec3::zeros(), 2);
        let surface = Surface::new(&BoundaryMesh::new(vertices, triangles).expect("valid")).expect("closed box");
        let outside = surface.nearest(&Vec3::new(0.2, -0.3, 1.25), 1.0).expect("within range");
        assert_relative_eq!(outside.distance, 0.25, epsilon = 1e-12);
        assert_relative_eq!(outside.normal, Vec3::z(), epsilon = 1e-12);
        let inside = surface.nearest(&Vec3::new(0.95, 0.1, -0.2), 1.0).expect("inside");
        assert_relative_eq!(inside.distance, -0.05, epsilon = 1e-12);
        assert_relative_eq!(inside.normal, Vec3::x(), epsilon = 1e-12);
        assert!(surface.nearest(&Vec3::new(0.0, 0.0, 3.0), 1.0).is_none());
        // A NaN point is out of range, not a query (parry's would panic).
        assert!(surface.nearest(&Vec3::new(f64::NAN, 0.0, 0.0), 1.0).is_none());
        assert!(surface.nearest(&Vec3::new(0.0, f64::INFINITY, 0.0), f64::INFINITY).is_none());
    }
}
