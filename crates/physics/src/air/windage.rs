//! A body's wind load (PHYSICS.md §10): `F_i = ½ ρ_a C_i A_i |u_r| u_r,i` along each axis i of the
//! body's reference frame, with the relative air velocity `u_r = (U(z) + r u(t)) e r − v_c` at
//! its wind centre c (U the mean profile, u the gusts, r the ramp, v_c the centre's velocity),
//! acting at c. The body's own motion damps it: to first order a velocity `v` along the wind
//! changes the force by `−ρ_a C A U v` (the aerodynamic damping).
//!
//! The areas `A_i` \[m²] are the body's projected areas normal to its axes; absent, they are its
//! hull's above the still water level at t = 0: `A_i = ½ (Σ |S_f,i| + |L_i|)` over the area
//! vectors `S_f` of the hull's faces above the water (each triangle clipped at the level) and
//! the waterplane's `L = −Σ S_f` that closes them (a closed hull's area vectors sum to zero),
//! which for a convex hull is its silhouette above the water; the centre is the area-weighted
//! centroid of those faces.

use crate::math::{Mat3, Vec3};
use crate::parameter::{Bound, ParameterError, require, require_derived};

/// What a scene says of a body's windage, in its reference frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WindageSpec {
    /// `C_i` [–] ≥ 0 along the reference frame's axes.
    pub coefficients: [f64; 3],
    /// `A_i` \[m²] ≥ 0 normal to the axes; `None`: the hull's above the water.
    pub areas: Option<[f64; 3]>,
    /// The wind centre c in the reference frame \[m]; `None`: the centroid of the hull's part
    /// above the water (with stated areas: G).
    pub center: Option<Vec3>,
}

/// A body's windage, resolved: coefficients times areas per axis of its reference frame, and
/// its centre in its principal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Windage {
    /// `C_i A_i` \[m²] along the reference frame's axes.
    drag_areas: [f64; 3],
    /// The reference frame's axes in the principal frame (columns).
    axes: Mat3,
    /// c in the principal frame \[m].
    center: Vec3,
}

/// The projected areas \[m²] and the centroid (principal frame) of a hull's faces above a level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExposedHull {
    pub areas: [f64; 3],
    pub centroid: Vec3,
}

impl Windage {
    /// `spec` for a body whose reference frame has axes `axes` (columns, in the principal frame)
    /// and origin `origin` (principal frame), with its hull's exposed part `exposed` when the
    /// spec leaves the areas or the centre to it.
    ///
    /// # Errors
    /// A coefficient or area out of its range, naming it.
    pub fn new(spec: &WindageSpec, axes: Mat3, origin: Vec3, exposed: &ExposedHull) -> Result<Self, ParameterError> {
        for c in spec.coefficients {
            require("coefficients", c, Bound::NonNegative, "")?;
        }
        let areas = match spec.areas {
            Some(areas) => {
                for a in areas {
                    require("areas", a, Bound::NonNegative, "m²")?;
                }
                areas
            }
            None => exposed_in_axes(exposed, &axes),
        };
        let center = match (spec.center, spec.areas) {
            (Some(c), _) => origin + axes * c,
            (None, None) => exposed.centroid,
            (None, Some(_)) => Vec3::zeros(),
        };
        let mut drag_areas = [0.0; 3];
        for (i, drag_area) in drag_areas.iter_mut().enumerate() {
            let inputs = [("coefficients", spec.coefficients[i]), ("areas", areas[i])];
            *drag_area = require_derived("C·A", spec.coefficients[i] * areas[i], Bound::NonNegative, "m²", &inputs)?;
        }
        Ok(Self { drag_areas, axes, center })
    }

    /// `C_i A_i` \[m²] along the reference frame's axes.
    pub fn drag_areas(&self) -> [f64; 3] {
        self.drag_areas
    }

    /// The wind centre in the principal frame \[m].
    pub fn center(&self) -> &Vec3 {
        &self.center
    }

    /// The force \[N] on a body turned by `rotation` (principal frame → world) for the relative
    /// air velocity `relative` [m/s] (world axes) at its centre, density `density`.
    pub fn force(&self, rotation: &Mat3, relative: &Vec3, density: f64) -> Vec3 {
        let axes = rotation * self.axes;
        let speed = relative.norm();
        (0..3).fold(Vec3::zeros(), |sum, i| {
            let axis = axes.column(i).into_owned();
            sum + axis * (0.5 * density * self.drag_areas[i] * speed * axis.dot(relative))
        })
    }
}

/// The exposed areas, measured along the principal axes, seen along the reference frame's axes:
/// `A_i = ½ Σ |n·a_i| a`, approximated from the principal-axis sums when the frames differ by
/// a turn (exact when they are aligned, as a mesh's body frames are).
fn exposed_in_axes(exposed: &ExposedHull, axes: &Mat3) -> [f64; 3] {
    [0, 1, 2].map(|i| {
        let a = axes.column(i);
        (0..3).map(|k| a[k].abs() * exposed.areas[k]).sum()
    })
}

/// The faces of a hull (`vertices` in the principal frame, `triangles`) above the level `level`
/// \[m] when the body sits with G at `position` turned by `rotation` (principal → world):
/// projected areas along the principal axes and centroid (module docs). Nothing above: zeros.
pub fn exposed_hull(
    vertices: &[Vec3],
    triangles: &[[u32; 3]],
    position: &Vec3,
    rotation: &Mat3,
    level: f64,
) -> ExposedHull {
    let mut areas = [0.0; 3];
    let (mut moment, mut total, mut lid) = (Vec3::zeros(), 0.0, Vec3::zeros());
    for triangle in triangles {
        let corners = triangle.map(|v| vertices[v as usize]);
        let heights = corners.map(|c| (position + rotation * c).z - level);
        let polygon = clip_above(&corners, &heights);
        if polygon.len() < 3 {
            continue;
        }
        let (vector, centroid) = area_of(&polygon);
        lid -= vector;
        for (area, component) in areas.iter_mut().zip(vector.iter()) {
            *area += 0.5 * component.abs();
        }
        let area = vector.norm();
        moment += centroid * area;
        total += area;
    }
    // The waterplane closes the exposed faces: its area vector is minus their sum.
    for (area, lid) in areas.iter_mut().zip(lid.iter()) {
        *area += 0.5 * lid.abs();
    }
    let centroid = if total > 0.0 { moment / total } else { Vec3::zeros() };
    ExposedHull { areas, centroid }
}

/// The part of a triangle where `height ≥ 0` (Sutherland–Hodgman against one plane).
fn clip_above(corners: &[Vec3; 3], heights: &[f64; 3]) -> Vec<Vec3> {
    let mut polygon = Vec::with_capacity(4);
    for i in 0..3 {
        let (a, b) = (i, (i + 1) % 3);
        if heights[a] >= 0.0 {
            polygon.push(corners[a]);
        }
        if (heights[a] >= 0.0) != (heights[b] >= 0.0) {
            let s = heights[a] / (heights[a] - heights[b]);
            polygon.push(corners[a] + (corners[b] - corners[a]) * s);
        }
    }
    polygon
}

/// A planar polygon's area vector `½ Σ p_k × p_{k+1}` \[m²] and its centroid.
fn area_of(polygon: &[Vec3]) -> (Vec3, Vec3) {
    let first = polygon[0];
    let (mut vector, mut moment, mut total) = (Vec3::zeros(), Vec3::zeros(), 0.0);
    for pair in polygon[1..].windows(2) {
        let triangle = (pair[0] - first).cross(&(pair[1] - first)) * 0.5;
        let area = triangle.norm();
        vector += triangle;
        moment += (first + pair[0] + pair[1]) / 3.0 * area;
        total += area;
    }
    (vector, if total > 0.0 { moment / total } else { first })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    /// A 2 × 4 × 6 m box with its centre 1 m below the level: 2 m of it above; seen along x
    /// 4 × 2 m², along y 2 × 2 m², from above 2 × 4 m²; the centroid of its exposed faces.
    #[test]
    fn the_exposed_areas_of_a_box_are_its_silhouette_above_the_water() {
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(2.0, 4.0, 6.0), &Vec3::zeros(), 1);
        let exposed = exposed_hull(&vertices, &triangles, &Vec3::new(0.0, 0.0, -1.0), &Mat3::identity(), 0.0);
        let expected = [8.0, 4.0, 8.0];
        for (got, want) in exposed.areas.iter().zip(expected) {
            assert!((got - want).abs() < 1e-12, "{:?}", exposed.areas);
        }
        // Faces: top 8 m² at z = 3; ±x sides 8 m² each, centred at z = 2; ±y 4 m² each at z = 2.
        let centroid_z = (8.0 * 3.0 + 2.0 * 8.0 * 2.0 + 2.0 * 4.0 * 2.0) / (8.0 + 16.0 + 8.0);
        assert!((exposed.centroid - Vec3::new(0.0, 0.0, centroid_z)).norm() < 1e-12, "{}", exposed.centroid);
    }

    /// `½ ρ C A |u| u` along the wind on an aligned body, and across it none.
    #[test]
    fn the_force_is_the_quadratic_drag_per_axis() {
        let spec = WindageSpec { coefficients: [1.2, 0.8, 0.0], areas: Some([10.0, 20.0, 5.0]), center: None };
        let exposed = ExposedHull { areas: [0.0; 3], centroid: Vec3::zeros() };
        let windage = Windage::new(&spec, Mat3::identity(), Vec3::zeros(), &exposed).expect("valid");
        let force = windage.force(&Mat3::identity(), &Vec3::new(20.0, 0.0, 0.0), 1.225);
        assert!((force - Vec3::new(0.5 * 1.225 * 12.0 * 400.0, 0.0, 0.0)).norm() < 1e-9, "{force}");
        let oblique = windage.force(&Mat3::identity(), &Vec3::new(3.0, 4.0, 0.0), 1.225);
        let expected = Vec3::new(0.5 * 1.225 * 12.0 * 5.0 * 3.0, 0.5 * 1.225 * 16.0 * 5.0 * 4.0, 0.0);
        assert!((oblique - expected).norm() < 1e-9, "{oblique}");
        let error = Windage::new(
            &WindageSpec { areas: Some([-1.0, 0.0, 0.0]), ..spec },
            Mat3::identity(),
            Vec3::zeros(),
            &exposed,
        );
        assert_eq!(error.expect_err("negative").to_string(), "areas must be ≥ 0 m², got -1");
    }
}
