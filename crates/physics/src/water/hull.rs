//! A floating body's hull: its closed, outward boundary mesh in the principal frame, as the
//! water's pressure is integrated over it (PHYSICS.md §6, Pressure on the boundary).
//!
//! The pressure integral is exact only over a closed, outward-oriented surface: the hull's
//! signed volume `V = (1/3) Σ A (n·x_c)` \[m³] must be positive and `|Σ A n|` \[m²] zero up to
//! round-off, or the body is refused (unlike a contact boundary, which is turned over when
//! wound inwards: a hull wound inwards is a modelling mistake worth saying).

use crate::body::RigidBody;
use crate::math::Vec3;
use crate::mesh::shape_in_principal_frame;

/// `|Σ A n|` above this fraction of the total area `Σ A` \[m²] marks an open mesh: a closed
/// one sums to zero exactly but for round-off (about 1e-16 of the area per triangle).
pub const OPEN_TOLERANCE: f64 = 1e-9;

/// A mesh that cannot be a hull.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HullError {
    #[error("the hull has no triangles")]
    NoTriangles,
    #[error("triangle {triangle} refers to vertex {vertex}, but the hull has {count} vertices")]
    VertexOutOfRange { triangle: usize, vertex: u32, count: usize },
    #[error("vertex {vertex} is not a finite point")]
    NotFinite { vertex: usize },
    #[error(
        "the hull is open: its faces' area vectors sum to {gap:.3e} m² (of {area:.3e} m²), not zero; a body in water needs a closed mesh"
    )]
    Open { gap: f64, area: f64 },
    #[error("the hull encloses no volume (a flat or degenerate mesh); a body in water needs a closed mesh")]
    NoVolume,
    #[error(
        "the hull is inside out (its normals point inwards: signed volume {volume:.6e} m³); a body in water needs an outward-oriented mesh"
    )]
    InsideOut { volume: f64 },
}

/// A closed, outward hull in the body's principal frame \[m].
#[derive(Debug, Clone, PartialEq)]
pub struct Hull {
    /// Vertices, principal frame [m].
    vertices: Vec<Vec3>,
    /// Counter-clockwise seen from outside.
    triangles: Vec<[u32; 3]>,
    /// `2 A n` of each triangle: `(b − a) × (c − a)` [m²], principal frame.
    double_area_normals: Vec<Vec3>,
    /// `V` [m³].
    volume: f64,
    /// `Σ A` [m²].
    area: f64,
    /// `max |v|` [m]: the hull lies in this ball about G.
    bounding_radius: f64,
}

impl Hull {
    /// The hull of `vertices` \[m] and `triangles`, checked closed and outward.
    ///
    /// # Errors
    /// No triangles, an index out of range, a non-finite vertex, an open mesh or an inward one.
    pub fn new(vertices: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<Self, HullError> {
        if triangles.is_empty() {
            return Err(HullError::NoTriangles);
        }
        if let Some(vertex) = vertices.iter().position(|v| !v.iter().all(|x| x.is_finite())) {
            return Err(HullError::NotFinite { vertex });
        }
        for (triangle, corners) in triangles.iter().enumerate() {
            if let Some(&vertex) = corners.iter().find(|&&i| i as usize >= vertices.len()) {
                return Err(HullError::VertexOutOfRange { triangle, vertex, count: vertices.len() });
            }
        }
        let corner = |t: &[u32; 3], i: usize| vertices[t[i] as usize];
        let double_area_normals: Vec<Vec3> =
            triangles.iter().map(|t| (corner(t, 1) - corner(t, 0)).cross(&(corner(t, 2) - corner(t, 0)))).collect();
        let area = 0.5 * double_area_normals.iter().map(Vec3::norm).sum::<f64>();
        let gap = 0.5 * double_area_normals.iter().sum::<Vec3>().norm();
        if !(gap <= OPEN_TOLERANCE * area) {
            return Err(HullError::Open { gap, area });
        }
        // (1/3) Σ A n·x_c = (1/6) Σ (2 A n)·(a + b + c)/3.
        let volume = triangles
            .iter()
            .zip(&double_area_normals)
            .map(|(t, n)| n.dot(&(corner(t, 0) + corner(t, 1) + corner(t, 2))))
            .sum::<f64>()
            / 18.0;
        if volume == 0.0 || !(area > 0.0) {
            return Err(HullError::NoVolume);
        }
        if !(volume > 0.0) {
            return Err(HullError::InsideOut { volume });
        }
        let bounding_radius = vertices.iter().map(Vec3::norm).fold(0.0, f64::max);
        Ok(Self { vertices, triangles, double_area_normals, volume, area, bounding_radius })
    }

    /// The hull of `body`'s shape, in its principal frame.
    ///
    /// # Errors
    /// See [`Hull::new`].
    pub fn of_body(body: &RigidBody) -> Result<Self, HullError> {
        let (vertices, triangles) = shape_in_principal_frame(body);
        Self::new(vertices, triangles)
    }

    /// Vertices, principal frame \[m].
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// `2 A n` of each triangle \[m²], principal frame.
    pub fn double_area_normals(&self) -> &[Vec3] {
        &self.double_area_normals
    }

    /// `V` \[m³].
    pub fn volume(&self) -> f64 {
        self.volume
    }

    /// `Σ A` \[m²].
    pub fn area(&self) -> f64 {
        self.area
    }

    /// Radius of the ball about G that holds the hull \[m].
    pub fn bounding_radius(&self) -> f64 {
        self.bounding_radius
    }

    /// `½ Σ A |n·d|` \[m²]: the area the hull shows to a flow along the unit direction `d`
    /// (principal frame), the default drag area across `d`.
    pub fn projected_area(&self, direction: &Vec3) -> f64 {
        0.25 * self.double_area_normals.iter().map(|n| n.dot(direction).abs()).sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use approx::assert_relative_eq;

    #[test]
    fn a_box_hull_has_its_volume_and_projected_areas() {
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(20.0, 10.0, 4.0), &Vec3::zeros(), 3);
        let hull = Hull::new(vertices, triangles).expect("a closed box");
        assert_relative_eq!(hull.volume(), 800.0, max_relative = 1e-14);
        assert_relative_eq!(hull.projected_area(&Vec3::x()), 40.0, max_relative = 1e-14);
        assert_relative_eq!(hull.projected_area(&Vec3::z()), 200.0, max_relative = 1e-14);
    }

    #[test]
    fn open_and_inside_out_hulls_are_refused() {
        let (vertices, mut triangles) = primitives::cuboid(&Vec3::repeat(1.0), &Vec3::zeros(), 1);
        let inward: Vec<[u32; 3]> = triangles.iter().map(|t| [t[0], t[2], t[1]]).collect();
        assert!(matches!(Hull::new(vertices.clone(), inward), Err(HullError::InsideOut { .. })));
        triangles.pop();
        assert!(matches!(Hull::new(vertices, triangles), Err(HullError::Open { .. })));
    }
}
