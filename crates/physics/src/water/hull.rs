//! A floating body's hull: its closed, outward boundary mesh in the principal frame, as the
//! water's pressure is integrated over it (PHYSICS.md §6, Pressure on the boundary).
//!
//! The pressure integral is exact only over a closed, outward-oriented surface. The triangles
//! are checked and wound outward by [`OutwardMesh`], as a contact boundary's are (a mesh wound
//! inwards is turned over, and a loader warns of it); then `|Σ A n|` \[m²] must be zero up to
//! round-off and the signed volume `V = (1/3) Σ A (n·x_c)` \[m³] positive, or the body is refused.

use crate::body::RigidBody;
use crate::math::Vec3;
use crate::mesh::{MeshError, OutwardMesh, double_area_normal, shape_in_principal_frame};

/// `|Σ A n|` above this fraction of the total area `Σ A` \[m²] marks an open mesh: a closed
/// one sums to zero exactly but for round-off (about 1e-16 of the area per triangle).
pub const OPEN_TOLERANCE: f64 = 1e-9;

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
    /// The hull of `vertices` \[m] and `triangles`, checked and wound outward by
    /// [`OutwardMesh::new`], then checked closed.
    ///
    /// # Errors
    /// Those of [`OutwardMesh::new`], an open mesh, or one that encloses no volume.
    pub fn new(vertices: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<Self, MeshError> {
        let (vertices, triangles) = OutwardMesh::new(vertices, triangles)?.into_parts();
        let corner = |t: &[u32; 3], i: usize| vertices[t[i] as usize];
        let double_area_normals: Vec<Vec3> = triangles.iter().map(|t| double_area_normal(&vertices, t)).collect();
        let area = 0.5 * double_area_normals.iter().map(Vec3::norm).sum::<f64>();
        let gap = 0.5 * double_area_normals.iter().sum::<Vec3>().norm();
        if !(gap <= OPEN_TOLERANCE * area) {
            return Err(MeshError::Open { gap, area });
        }
        // (1/3) Σ A n·x_c = (1/6) Σ (2 A n)·(a + b + c)/3.
        let volume = triangles
            .iter()
            .zip(&double_area_normals)
            .map(|(t, n)| n.dot(&(corner(t, 0) + corner(t, 1) + corner(t, 2))))
            .sum::<f64>()
            / 18.0;
        // Not negative: the mesh is wound outward.
        if !(volume > 0.0) {
            return Err(MeshError::NoVolume);
        }
        let bounding_radius = vertices.iter().map(Vec3::norm).fold(0.0, f64::max);
        Ok(Self { vertices, triangles, double_area_normals, volume, area, bounding_radius })
    }

    /// The hull of `body`'s shape, in its principal frame.
    ///
    /// # Errors
    /// See [`Hull::new`].
    pub fn of_body(body: &RigidBody) -> Result<Self, MeshError> {
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

    /// A unit cube wound inwards is turned over to the outward cube's hull, which floats at the
    /// closed-form draft `d = m/(ρ A_wp)`: 400 kg in water of 1025 kg/m³ under a 1 m² waterplane
    /// displaces 0.390244 m³, so G (the cube's centre) rests `½ − d` above the still level.
    #[test]
    fn an_inward_hull_is_turned_over_and_floats_at_the_outward_ones_draft() {
        use crate::water::hydrostatics::equilibrium_height;
        let (vertices, triangles) = primitives::cuboid(&Vec3::repeat(1.0), &Vec3::zeros(), 2);
        let inward: Vec<[u32; 3]> = triangles.iter().map(|t| [t[0], t[2], t[1]]).collect();
        let outward_hull = Hull::new(vertices.clone(), triangles).expect("a closed box");
        let turned_hull = Hull::new(vertices, inward).expect("a closed box wound inwards");
        assert_eq!(turned_hull, outward_hull);
        let draft = 400.0 / 1025.0;
        for hull in [&outward_hull, &turned_hull] {
            assert_relative_eq!(hull.volume(), 1.0, max_relative = 1e-14);
            let height = equilibrium_height(hull, &crate::math::Mat3::identity(), 0.0, 0.0, 0.0, draft)
                .expect("lighter than the water it can displace");
            assert_relative_eq!(height, 0.5 - draft, epsilon = 1e-12);
        }
    }

    #[test]
    fn open_and_flat_hulls_are_refused() {
        let (vertices, mut triangles) = primitives::cuboid(&Vec3::repeat(1.0), &Vec3::zeros(), 1);
        triangles.pop();
        assert!(matches!(Hull::new(vertices, triangles), Err(MeshError::Open { .. })));
        // A square and the same square wound the other way: closed, but it encloses nothing.
        let square = vec![Vec3::zeros(), Vec3::x(), Vec3::new(1.0, 1.0, 0.0), Vec3::y()];
        let both_sides = vec![[0, 1, 2], [0, 2, 3], [0, 2, 1], [0, 3, 2]];
        assert_eq!(Hull::new(square, both_sides), Err(MeshError::NoVolume));
    }
}
