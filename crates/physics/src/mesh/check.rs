//! The one check of a triangle list that a contact boundary ([`super::BoundaryMesh`]) and a
//! water hull ([`crate::water::Hull`]) are both built from (PHYSICS.md §4 and §6, Pressure on
//! the boundary): indices in range, finite vertices within reach, not too thin to query, some
//! area, and wound outward; and the one error of both, [`MeshError`], one message per fault.
//!
//! A mesh wound inwards (signed volume `V = Σ a·(b × c)/6 < 0` [m³]) is turned over, for
//! contact and for water alike, and the turn is reported ([`TurnedOver`]) so that a loader can
//! warn of it: the same mesh gives the same body and the same warning whatever it is used for.

use crate::math::{Vec3, bounding_box};

/// Farthest a vertex may be from the origin \[m]: distances squared must not overflow.
pub const MAX_EXTENT: f64 = 1e12;

/// A boundary thinner than this along an axis \[m] (but not flat) is refused: the distance
/// queries' bounding-volume hierarchy divides by the thickness, which for a subnormal one
/// overflows (a box of size 1e-320 made parry's tree build index out of bounds).
pub const MIN_THICKNESS: f64 = 1e-9;

/// Why a triangle list is not a usable contact boundary or water hull: the one error of both,
/// with one message for each fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshError {
    #[error("the mesh has no triangles")]
    NoTriangles,
    #[error("triangle {triangle} refers to vertex {vertex}, but the mesh has {count} vertices")]
    VertexOutOfRange { triangle: usize, vertex: u32, count: usize },
    #[error("vertex {vertex} is not a finite point")]
    NotFinite { vertex: usize },
    #[error("vertex {vertex} is {distance:e} m from the origin, beyond {MAX_EXTENT:e} m")]
    TooFar { vertex: usize, distance: f64 },
    #[error("the mesh has zero area: every triangle is degenerate")]
    ZeroArea,
    #[error(
        "the mesh is {thickness:e} m thick along axis {axis}: below {MIN_THICKNESS:e} m, too thin to tell its sides apart (a flat mesh has thickness 0)"
    )]
    TooThin { axis: char, thickness: f64 },
    #[error("the mesh cannot be used for distance queries: {0}")]
    Topology(String),
    #[error(
        "the mesh is open: its faces' area vectors sum to {gap:.3e} m² (of {area:.3e} m²), not zero; a body in water needs a closed mesh"
    )]
    Open { gap: f64, area: f64 },
    #[error("the mesh encloses no volume (a flat or degenerate mesh); a body in water needs a closed mesh")]
    NoVolume,
}

/// A mesh found wound inwards and turned over: what a loader warns of, in the words of its
/// `Display`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnedOver {
    /// Signed volume `V` of the mesh as given \[m³], negative.
    pub volume: f64,
}

impl std::fmt::Display for TurnedOver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "the mesh is wound inwards (its normals point into the body: signed volume {:.6e} m³); it was turned over to point outwards",
            self.volume
        )
    }
}

/// A triangle list that passed the check, wound outward (counter-clockwise seen from outside).
#[derive(Debug, Clone, PartialEq)]
pub struct OutwardMesh {
    /// Vertices \[m], as given.
    vertices: Vec<Vec3>,
    /// Triangles (vertex indices), counter-clockwise seen from outside.
    triangles: Vec<[u32; 3]>,
    /// Set when the triangles were given wound inwards and turned over here.
    turned_over: Option<TurnedOver>,
}

impl OutwardMesh {
    /// Vertices \[m], as given.
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    /// Triangles (vertex indices), counter-clockwise seen from outside.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Set when the triangles were given wound inwards and turned over here.
    pub fn turned_over(&self) -> Option<&TurnedOver> {
        self.turned_over.as_ref()
    }

    /// The vertices and the triangles, to build on.
    pub fn into_parts(self) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        (self.vertices, self.triangles)
    }

    /// Checks `vertices` \[m] and `triangles` (vertex indices) and winds them outward.
    ///
    /// # Errors
    /// No triangles, a non-finite vertex, one beyond [`MAX_EXTENT`], a mesh thinner than
    /// [`MIN_THICKNESS`] along an axis (but not flat), an index out of range, or zero total area.
    pub fn new(vertices: Vec<Vec3>, mut triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        if triangles.is_empty() {
            return Err(MeshError::NoTriangles);
        }
        if let Some(vertex) = vertices.iter().position(|v| !v.iter().all(|x| x.is_finite())) {
            return Err(MeshError::NotFinite { vertex });
        }
        if let Some(vertex) = vertices.iter().position(|v| v.amax() > MAX_EXTENT) {
            return Err(MeshError::TooFar { vertex, distance: vertices[vertex].norm() });
        }
        let (low, high) = bounding_box(vertices.iter().copied());
        if let Some(axis) =
            (0..3).find(|&axis| (high[axis] - low[axis]) > 0.0 && high[axis] - low[axis] < MIN_THICKNESS)
        {
            return Err(MeshError::TooThin { axis: ['x', 'y', 'z'][axis], thickness: high[axis] - low[axis] });
        }
        for (triangle, corners) in triangles.iter().enumerate() {
            if let Some(&vertex) = corners.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(MeshError::VertexOutOfRange { triangle, vertex, count: vertices.len() });
            }
        }
        if !triangles.iter().any(|t| double_area_normal(&vertices, t).norm() > 0.0) {
            return Err(MeshError::ZeroArea);
        }
        let volume = signed_volume(&vertices, &triangles);
        let turned_over = (volume < 0.0).then_some(TurnedOver { volume });
        if turned_over.is_some() {
            for t in &mut triangles {
                t.swap(1, 2);
            }
        }
        Ok(Self { vertices, triangles, turned_over })
    }
}

/// `(b − a) × (c − a)` of the triangle (a, b, c) [m²]: twice its area times its unit normal.
/// The indices must be in range.
pub(crate) fn double_area_normal(vertices: &[Vec3], triangle: &[u32; 3]) -> Vec3 {
    let [a, b, c] = triangle.map(|i| vertices[i as usize]);
    (b - a).cross(&(c - a))
}

/// `Σ a·(b × c)/6` over the triangles (a, b, c) [m³]: the enclosed volume of a closed mesh,
/// positive when every triangle is wound counter-clockwise seen from outside. The indices must
/// be in range.
pub(crate) fn signed_volume(vertices: &[Vec3], triangles: &[[u32; 3]]) -> f64 {
    triangles
        .iter()
        .map(|t| vertices[t[0] as usize].dot(&vertices[t[1] as usize].cross(&vertices[t[2] as usize])))
        .sum::<f64>()
        / 6.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use approx::assert_relative_eq;

    #[test]
    fn an_inward_box_is_turned_over_and_reported_with_its_volume() {
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(1.0, 2.0, 3.0), &Vec3::zeros(), 1);
        let inward: Vec<[u32; 3]> = triangles.iter().map(|t| [t[0], t[2], t[1]]).collect();
        let outward = OutwardMesh::new(vertices.clone(), triangles.clone()).expect("a box");
        assert_eq!(outward.turned_over, None);
        let turned = OutwardMesh::new(vertices, inward).expect("a box wound inwards");
        assert_eq!(turned.triangles, triangles);
        let volume = turned.turned_over.expect("reported").volume;
        assert_relative_eq!(volume, -6.0, max_relative = 1e-14);
        assert_eq!(
            turned.turned_over.map(|t| t.to_string()).as_deref(),
            Some(
                "the mesh is wound inwards (its normals point into the body: signed volume -6.000000e0 m³); it was turned over to point outwards"
            )
        );
    }

    #[test]
    fn bad_meshes_are_refused() {
        assert_eq!(OutwardMesh::new(vec![Vec3::zeros()], vec![]), Err(MeshError::NoTriangles));
        let flat = vec![Vec3::zeros(), Vec3::x(), Vec3::x() * 2.0];
        assert_eq!(OutwardMesh::new(flat.clone(), vec![[0, 1, 2]]), Err(MeshError::ZeroArea));
        assert!(matches!(OutwardMesh::new(flat, vec![[0, 1, 3]]), Err(MeshError::VertexOutOfRange { vertex: 3, .. })));
        let nan = vec![Vec3::zeros(), Vec3::x(), Vec3::new(f64::NAN, 0.0, 0.0)];
        assert_eq!(OutwardMesh::new(nan, vec![[0, 1, 2]]), Err(MeshError::NotFinite { vertex: 2 }));
        let far = vec![Vec3::zeros(), Vec3::x(), Vec3::new(0.0, 2.0 * MAX_EXTENT, 0.0)];
        assert!(matches!(OutwardMesh::new(far, vec![[0, 1, 2]]), Err(MeshError::TooFar { vertex: 2, .. })));
        let thin = primitives::cuboid(&Vec3::new(1e-320, 0.3, 0.3), &Vec3::zeros(), 1);
        assert!(matches!(OutwardMesh::new(thin.0, thin.1), Err(MeshError::TooThin { axis: 'x', .. })));
    }
}
