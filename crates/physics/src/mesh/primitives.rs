//! Triangle meshes of the primitive shapes, wound counter-clockwise seen from outside \[m].
//!
//! Each returns `(vertices, triangles)` in the frame the shape is declared in.

#![allow(clippy::cast_possible_truncation)] // vertex counts are bounded by the scene's subdivision limits

use crate::math::Vec3;

/// Sides of a cylinder's polygonal cross-section.
pub const CYLINDER_SIDES: u32 = 32;

/// Box with full edge lengths `size`, centred at `center`, each face split into
/// `divisions × divisions` squares of two triangles. A face's contact force acts at its
/// centroid, so a face cannot resist a moment about it: a box resting on two large triangles
/// would rock on their centroids; a grid spreads the support over the face.
pub fn cuboid(size: &Vec3, center: &Vec3, divisions: u32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let n = divisions.max(1);
    let mut vertices = Vec::with_capacity(6 * ((n + 1) * (n + 1)) as usize);
    let mut triangles = Vec::with_capacity(12 * (n * n) as usize);
    for (k, sign) in [0, 1, 2].into_iter().flat_map(|k| [(k, 1.0), (k, -1.0)]) {
        // Tangent axes with e_i × e_j = sign · e_k: counter-clockwise seen from outside.
        let (i, j) = if sign > 0.0 { ((k + 1) % 3, (k + 2) % 3) } else { ((k + 2) % 3, (k + 1) % 3) };
        let first = vertices.len() as u32;
        for b in 0..=n {
            for a in 0..=n {
                let mut v = *center;
                v[k] += sign * 0.5 * size[k];
                v[i] += size[i] * (f64::from(a) / f64::from(n) - 0.5);
                v[j] += size[j] * (f64::from(b) / f64::from(n) - 0.5);
                vertices.push(v);
            }
        }
        let index = |a: u32, b: u32| first + b * (n + 1) + a;
        for b in 0..n {
            for a in 0..n {
                triangles.push([index(a, b), index(a + 1, b), index(a + 1, b + 1)]);
                triangles.push([index(a, b), index(a + 1, b + 1), index(a, b + 1)]);
            }
        }
    }
    (vertices, triangles)
}

/// Icosphere of `radius` centred at `center`: the icosahedron with each triangle split in four
/// `subdivisions` times and projected onto the sphere (20·4ⁿ triangles).
pub fn icosphere(radius: f64, center: &Vec3, subdivisions: u32) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let phi = 0.5 * (1.0 + 5.0_f64.sqrt());
    let mut unit: Vec<Vec3> = [
        (-1.0, phi, 0.0),
        (1.0, phi, 0.0),
        (-1.0, -phi, 0.0),
        (1.0, -phi, 0.0),
        (0.0, -1.0, phi),
        (0.0, 1.0, phi),
        (0.0, -1.0, -phi),
        (0.0, 1.0, -phi),
        (phi, 0.0, -1.0),
        (phi, 0.0, 1.0),
        (-phi, 0.0, -1.0),
        (-phi, 0.0, 1.0),
    ]
    .iter()
    .map(|&(x, y, z)| Vec3::new(x, y, z).normalize())
    .collect();
    let mut triangles: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut midpoints = std::collections::HashMap::new();
        let mut midpoint = |a: u32, b: u32, unit: &mut Vec<Vec3>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                unit.push((unit[a as usize] + unit[b as usize]).normalize());
                (unit.len() - 1) as u32
            })
        };
        triangles = triangles
            .iter()
            .flat_map(|&[a, b, c]| {
                let (ab, bc, ca) = (midpoint(a, b, &mut unit), midpoint(b, c, &mut unit), midpoint(c, a, &mut unit));
                [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
            })
            .collect();
    }
    (unit.iter().map(|u| center + u * radius).collect(), triangles)
}

/// Cylinder of `radius` and `length` along the unit `axis`, centred at `center`:
/// [`CYLINDER_SIDES`] sides and two fan caps.
pub fn cylinder(radius: f64, length: f64, axis: &Vec3, center: &Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
    let n = CYLINDER_SIDES;
    // Any unit vector across the axis, and the one completing a right-handed frame.
    let across = if axis.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
    let u = axis.cross(&across).normalize();
    let v = axis.cross(&u);
    let ring = |height: f64| {
        (0..n).map(move |i| {
            let angle = std::f64::consts::TAU * f64::from(i) / f64::from(n);
            center + axis * height + (u * angle.cos() + v * angle.sin()) * radius
        })
    };
    let half = 0.5 * length;
    // Bottom ring 0..n, top ring n..2n, then the two cap centres.
    let mut vertices: Vec<Vec3> = ring(-half).chain(ring(half)).collect();
    vertices.push(center - axis * half);
    vertices.push(center + axis * half);
    let (bottom, top) = (2 * n, 2 * n + 1);
    let mut triangles = Vec::with_capacity(4 * n as usize);
    for i in 0..n {
        let j = (i + 1) % n;
        triangles.push([i, j, n + j]);
        triangles.push([i, n + j, n + i]);
        triangles.push([bottom, j, i]);
        triangles.push([top, n + i, n + j]);
    }
    (vertices, triangles)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::BoundaryMesh;
    use approx::assert_relative_eq;

    /// Enclosed volume `Σ a·(b×c)/6` [m³]: positive only if every face is wound outwards
    /// consistently.
    fn volume((vertices, triangles): &(Vec<Vec3>, Vec<[u32; 3]>)) -> f64 {
        crate::mesh::signed_volume(vertices, triangles)
    }

    #[test]
    fn primitive_meshes_enclose_their_volume_with_outward_normals() {
        let c = Vec3::new(0.3, -0.2, 0.1);
        assert_relative_eq!(volume(&cuboid(&Vec3::new(1.0, 2.0, 3.0), &c, 3)), 6.0, epsilon = 1e-12);
        // A regular 32-gon prism: ½ n r² sin(2π/n) · L.
        let prism = 0.5 * 32.0 * (std::f64::consts::TAU / 32.0).sin() * 2.0;
        assert_relative_eq!(
            volume(&cylinder(1.0, 2.0, &Vec3::new(1.0, 1.0, 0.0).normalize(), &c)),
            prism,
            epsilon = 1e-12
        );
        // Inscribed icosphere volumes approach 4π/3 from below: 4.0470 m³ (0.966 of it) at
        // two subdivisions.
        let sphere = 4.0 / 3.0 * std::f64::consts::PI;
        let v2 = volume(&icosphere(1.0, &c, 2));
        assert!(v2 < sphere && v2 > 0.96 * sphere, "icosphere volume {v2}");
        for mesh in [
            cuboid(&Vec3::repeat(1.0), &Vec3::zeros(), 2),
            icosphere(1.0, &Vec3::zeros(), 1),
            cylinder(1.0, 1.0, &Vec3::z(), &Vec3::zeros()),
        ] {
            let boundary = BoundaryMesh::new(mesh.0, mesh.1).expect("primitive meshes are valid");
            assert!(boundary.faces().iter().all(|f| f.normal.dot(&f.centroid) > 0.0));
        }
        assert_eq!(icosphere(1.0, &c, 3).1.len(), 20 * 64);
    }
}
