//! Pressure integrated over a hull's wet surface: hydrostatics and Froude–Krylov (PHYSICS.md §6,
//! Pressure on the boundary).
//!
//! Each triangle (outward `n`, area `A`) with vertex pressures `p1, p2, p3` \[Pa] is clipped at
//! the zero line of the linear interpolant of p: one wet vertex leaves a triangle, two a
//! quadrilateral (two triangles), three the whole. On each wet triangle, exactly for linear p:
//! `F = −n A (p1 + p2 + p3)/3` \[N] and `∫ p r dA = (A/12) [(p1 + p2 + p3)(r1 + r2 + r3) +
//! p1 r1 + p2 r2 + p3 r3]` [N·m], `r` from G, so that the moment about G is `M = n × ∫ p r dA`.
//! In still water p is linear in z, so this is exact for any closed mesh: `F = ρ g V_sub ẑ`
//! through the centre of buoyancy.
//!
//! The integration runs in the principal frame, where the hull's vertices and `2 A n` are
//! constants; only the vertex pressures change, each worked out once per evaluation by the
//! caller.

use super::hull::Hull;
use crate::math::Vec3;

/// A corner of a wet part: the point `t` of the way from corner `from` to corner `to` of the
/// triangle (`t = 0`: corner `from` itself).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EdgePoint {
    pub from: usize,
    pub to: usize,
    pub t: f64,
}

impl EdgePoint {
    const fn corner(index: usize) -> Self {
        Self { from: index, to: index, t: 0.0 }
    }

    /// The point on the edge between `from` (wet, `p_from > 0`) and `to` (dry) where the
    /// interpolated pressure is zero.
    fn crossing(p: &[f64; 3], from: usize, to: usize) -> Self {
        Self { from, to, t: p[from] / (p[from] - p[to]) }
    }

    /// The linear interpolant of the corner values `values` here.
    #[inline(always)]
    pub fn of<T>(&self, values: &[T; 3]) -> T
    where
        T: Copy + std::ops::Add<Output = T> + std::ops::Sub<Output = T> + std::ops::Mul<f64, Output = T>,
    {
        values[self.from] + (values[self.to] - values[self.from]) * self.t
    }
}

/// The wet parts (`p > 0`) of a triangle with corner pressures `p`, each given to `each` as the
/// fraction of the triangle's area it covers and its corners, in the triangle's orientation.
#[inline(always)]
pub fn wet_parts(p: &[f64; 3], mut each: impl FnMut(f64, [EdgePoint; 3])) {
    let wet = [p[0] > 0.0, p[1] > 0.0, p[2] > 0.0];
    match wet.iter().filter(|&&w| w).count() {
        3 => each(1.0, [EdgePoint::corner(0), EdgePoint::corner(1), EdgePoint::corner(2)]),
        1 => {
            // Corners a (the wet one), b, c in the triangle's cyclic order.
            let a = wet.iter().position(|&w| w).unwrap_or(0);
            let (b, c) = ((a + 1) % 3, (a + 2) % 3);
            let (ab, ac) = (EdgePoint::crossing(p, a, b), EdgePoint::crossing(p, a, c));
            each(ab.t * ac.t, [EdgePoint::corner(a), ab, ac]);
        }
        2 => {
            // Corners a, b (wet) and c (the dry one) in cyclic order: the quadrilateral
            // a, b, bc, ac as the triangles (a, b, bc) and (a, bc, ac).
            let c = wet.iter().position(|&w| !w).unwrap_or(2);
            let (a, b) = ((c + 1) % 3, (c + 2) % 3);
            let (bc, ac) = (EdgePoint::crossing(p, b, c), EdgePoint::crossing(p, a, c));
            each(bc.t, [EdgePoint::corner(a), EdgePoint::corner(b), bc]);
            each((1.0 - bc.t) * ac.t, [EdgePoint::corner(a), bc, ac]);
        }
        _ => {}
    }
}

/// What the pressure gives over a hull, principal frame.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PressureIntegral {
    /// `−∫ p n dA` \[N].
    pub force: Vec3,
    /// `∫ r × (−p n) dA` about G [N·m].
    pub moment: Vec3,
    /// `∫_wet (z_w − z) n dA` \[m³]: the submerged volume is `−ẑ·` this (exact in still water).
    pub head_flux: Vec3,
    /// `∫_wet n dA` \[m²]: the waterplane area is `−ẑ·` this (exact for a flat cut).
    pub wet_normal: Vec3,
}

/// Integrates the vertex pressures `pressures` \[Pa] over `hull`'s wet surface, with the vertex
/// heads below the still level `heads` = `z_w − z` \[m] for the submerged volume.
#[inline(always)]
pub fn integrate(hull: &Hull, pressures: &[f64], heads: &[f64]) -> PressureIntegral {
    let mut total = PressureIntegral::default();
    let vertices = hull.vertices();
    for (t, double_area_normal) in hull.triangles().iter().zip(hull.double_area_normals()) {
        let [i, j, k] = t.map(|v| v as usize);
        let p = [pressures[i], pressures[j], pressures[k]];
        if p[0] <= 0.0 && p[1] <= 0.0 && p[2] <= 0.0 {
            continue;
        }
        let (r, h) = ([vertices[i], vertices[j], vertices[k]], [heads[i], heads[j], heads[k]]);
        // Per unit triangle area: ∫p/A, ∫p r/A, ∫h/A, wet fraction.
        let (mut mean_p, mut first_moment, mut mean_h, mut wet) = (0.0, Vec3::zeros(), 0.0, 0.0);
        wet_parts(&p, |fraction, corners| {
            let q = corners.map(|c| c.of(&p));
            let y = corners.map(|c| c.of(&r));
            let sum_q = q[0] + q[1] + q[2];
            mean_p += fraction * sum_q / 3.0;
            first_moment +=
                ((y[0] + y[1] + y[2]) * sum_q + y[0] * q[0] + y[1] * q[1] + y[2] * q[2]) * (fraction / 12.0);
            mean_h += fraction * corners.iter().map(|c| c.of(&h)).sum::<f64>() / 3.0;
            wet += fraction;
        });
        let area_normal = double_area_normal * 0.5;
        total.force -= area_normal * mean_p;
        total.moment += area_normal.cross(&first_moment);
        total.head_flux += area_normal * mean_h;
        total.wet_normal += area_normal * wet;
    }
    total
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use approx::assert_relative_eq;

    #[test]
    fn wet_parts_cover_the_wet_area_of_a_linear_field() {
        // p = 1 − x on the triangle (0,0), (2,0), (0,1): wet where x < 1, area 1 − 1/4 = 3/4 of 1.
        let corners = [Vec3::new(0.0, 0.0, 0.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 1.0, 0.0)];
        let p = corners.map(|c| 1.0 - c.x);
        let mut area = 0.0;
        wet_parts(&p, |fraction, points| {
            let y = points.map(|c| c.of(&corners));
            // Each part keeps the triangle's orientation (+z).
            assert!((y[1] - y[0]).cross(&(y[2] - y[0])).z > 0.0);
            area += fraction;
        });
        assert_relative_eq!(area, 0.75, epsilon = 1e-15);
    }

    #[test]
    fn a_box_half_under_still_water_gets_its_buoyancy_through_its_centre_of_buoyancy() {
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(20.0, 10.0, 4.0), &Vec3::zeros(), 2);
        let hull = Hull::new(vertices, triangles).expect("closed");
        // G 0.5 m below the still level, box heeled: p = ρ g (z_w − z).
        let (rho_g, rotation) = (1025.0 * 9.80665, nalgebra::Rotation3::from_euler_angles(0.1, -0.05, 0.3));
        let z = |r: &Vec3| -0.5 + (rotation * r).z;
        let heads: Vec<f64> = hull.vertices().iter().map(|r| -z(r)).collect();
        let pressures: Vec<f64> = heads.iter().map(|h| rho_g * h).collect();
        let result = integrate(&hull, &pressures, &heads);
        let up = rotation.transpose() * Vec3::z();
        let submerged = -up.dot(&result.head_flux);
        // Buoyancy ρ g V_sub straight up, to round-off of sums over 96 faces.
        assert_relative_eq!(result.force, up * (rho_g * submerged), epsilon = 1e-9 * rho_g * submerged);
        // Through the centre of buoyancy, which the hydrostatics find by other integrals.
        let statics =
            crate::water::hydrostatics::Hydrostatics::at(&hull, &Vec3::new(0.0, 0.0, -0.5), rotation.matrix(), 0.0);
        assert_relative_eq!(submerged, statics.displaced_volume, max_relative = 1e-12);
        let arm = rotation.transpose() * (statics.center_of_buoyancy - Vec3::new(0.0, 0.0, -0.5));
        assert_relative_eq!(result.moment, arm.cross(&result.force), epsilon = 1e-9 * rho_g * submerged);
    }
}
