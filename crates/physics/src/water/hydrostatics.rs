//! Still-water hydrostatics of a hull at a pose, and its free-floating equilibrium (PHYSICS.md
//! §6): what `tether check` prints and the stable time step reads.
//!
//! Over the wet part of the hull (clipped at the still level `z_w`, exactly) with the head
//! `h = z_w − z` and the divergence theorem on the volume closed by the flat waterplane:
//! - displaced volume `V = −∫ h n_z dA` \[m³];
//! - centre of buoyancy `∫_V x dV = −∫ x h n_z dA` (x, y), `∫_V (z − z_w) dV = ½ ∫ h² n_z dA`;
//! - waterplane area `A_wp = −∫ n_z dA` \[m²], its centroid `(x_f, y_f)` from `−∫ (x, y) n_z dA`,
//!   its second moments `I_T = −∫ (y − y_f)² n_z dA`, `I_L = −∫ (x − x_f)² n_z dA` \[m⁴] about
//!   the world x and y axes through the centroid;
//! - metacentric heights `GM_T = z_B − z_G + I_T/V` (roll, about x), `GM_L = z_B − z_G + I_L/V`
//!   (pitch, about y) \[m];
//! - natural periods `T = 2π √(M/K)`: heave `(m + a_zz)/(ρ g A_wp)`, roll `(I_xx + J_xx)/(ρ g V
//!   GM_T)`, pitch `(I_yy + J_yy)/(ρ g V GM_L)` with the world-axis inertia and added mass.
//!
//! The integrands are polynomials of the corners' coordinates, integrated exactly per wet
//! triangle: `∫ f g dA = (A/12) [Σ f_i g_i + (Σ f_i)(Σ g_i)]` for linear f, g.

use super::environment::Water;
use super::hull::Hull;
use super::morison::Hydro;
use super::pressure::wet_parts;
use crate::body::{BodyState, RigidBody};
use crate::math::{Mat3, Vec3};

/// A hull's still-water properties at one pose (world axes).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Hydrostatics {
    /// `V` \[m³].
    pub displaced_volume: f64,
    /// Depth of the hull's lowest vertex below the still level \[m].
    pub draft: f64,
    /// The centre of buoyancy \[m] (meaningless when nothing is submerged).
    pub center_of_buoyancy: Vec3,
    /// `A_wp` \[m²].
    pub waterplane_area: f64,
    /// `(x_f, y_f)` \[m].
    pub waterplane_center: [f64; 2],
    /// `I_T`, `I_L` \[m⁴].
    pub waterplane_moments: [f64; 2],
}

impl Hydrostatics {
    /// The properties of `hull` at position `position` \[m] (G) and rotation `rotation`
    /// (principal → world), in still water at level `level` \[m].
    pub fn at(hull: &Hull, position: &Vec3, rotation: &Mat3, level: f64) -> Self {
        let world: Vec<Vec3> = hull.vertices().iter().map(|v| position + rotation * v).collect();
        let heads: Vec<f64> = world.iter().map(|x| level - x.z).collect();
        let (mut volume, mut moment, mut height_moment) = (0.0, Vec3::zeros(), 0.0);
        let (mut area, mut first, mut second) = (0.0, [0.0; 2], [0.0; 2]);
        for (t, double_area_normal) in hull.triangles().iter().zip(hull.double_area_normals()) {
            let [i, j, k] = t.map(|v| v as usize);
            let h = [heads[i], heads[j], heads[k]];
            // `n_z A` of the triangle in the world.
            let n_z = 0.5 * rotation.row(2).dot(&double_area_normal.transpose());
            let x = [world[i], world[j], world[k]];
            wet_parts(&h, |fraction, corners| {
                let a = n_z * fraction;
                let q = corners.map(|c| c.of(&h));
                let y = corners.map(|c| c.of(&x));
                let sum_q = q[0] + q[1] + q[2];
                let sum_y = y[0] + y[1] + y[2];
                volume -= a * sum_q / 3.0;
                moment -= (sum_y * sum_q + y[0] * q[0] + y[1] * q[1] + y[2] * q[2]) * (a / 12.0);
                height_moment += 0.5 * a / 12.0 * (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + sum_q * sum_q);
                area -= a;
                for axis in 0..2 {
                    first[axis] -= a * sum_y[axis] / 3.0;
                    second[axis] -=
                        a / 12.0 * (y[0][axis].powi(2) + y[1][axis].powi(2) + y[2][axis].powi(2) + sum_y[axis].powi(2));
                }
            });
        }
        let draft = heads.iter().copied().fold(f64::NEG_INFINITY, f64::max).max(0.0);
        let center = if volume > 0.0 {
            Vec3::new(moment.x / volume, moment.y / volume, level + height_moment / volume)
        } else {
            *position
        };
        let waterplane_center = if area > 0.0 { [first[0] / area, first[1] / area] } else { [position.x, position.y] };
        // About the axes through the centroid: I_T = ∫y² − A y_f², I_L = ∫x² − A x_f².
        let waterplane_moments =
            [second[1] - area * waterplane_center[1].powi(2), second[0] - area * waterplane_center[0].powi(2)];
        Self {
            displaced_volume: volume.max(0.0),
            draft,
            center_of_buoyancy: center,
            waterplane_area: area.max(0.0),
            waterplane_center,
            waterplane_moments,
        }
    }

    /// `GM_T`, `GM_L` \[m] for the centre of mass at height `z_g` \[m] (0 when nothing floats).
    pub fn metacentric_heights(&self, z_g: f64) -> [f64; 2] {
        if !(self.displaced_volume > 0.0) {
            return [0.0; 2];
        }
        let rise = self.center_of_buoyancy.z - z_g;
        self.waterplane_moments.map(|i| rise + i / self.displaced_volume)
    }
}

/// The height of G \[m] at which `hull`, turned by `rotation`, displaces `volume` \[m³] of still
/// water at level `level` \[m] (horizontal position `x`, `y` \[m] unchanged), to round-off; `None`
/// when `volume` is not within (0, V): the body would sink or has no weight to float.
///
/// Newton on `V_sub(z_G)`, whose slope is `−A_wp`, kept within a shrinking bracket (a bisection
/// step whenever Newton would leave it).
pub fn equilibrium_height(hull: &Hull, rotation: &Mat3, level: f64, x: f64, y: f64, volume: f64) -> Option<f64> {
    if !(volume > 0.0 && volume < hull.volume()) {
        return None;
    }
    let reach = hull.bounding_radius();
    let (mut low, mut high) = (level - reach, level + reach);
    let mut z = level;
    for _ in 0..200 {
        let state = Hydrostatics::at(hull, &Vec3::new(x, y, z), rotation, level);
        let excess = state.displaced_volume - volume;
        if excess.abs() <= 1e-14 * hull.volume() {
            return Some(z);
        }
        // Too much volume under water: the body must rise.
        if excess > 0.0 {
            low = z
        } else {
            high = z
        }
        let newton = z + excess / state.waterplane_area;
        z = if newton > low && newton < high { newton } else { 0.5 * (low + high) };
        if high - low <= 4.0 * f64::EPSILON * (level.abs() + reach) {
            return Some(z);
        }
    }
    Some(z)
}

/// A floating body at its free-floating equilibrium in still water: what `tether check` prints.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FloatingEquilibrium {
    /// Height of G \[m] at equilibrium.
    pub height: f64,
    /// The hydrostatics there.
    pub statics: Hydrostatics,
    /// `GM_T`, `GM_L` \[m].
    pub metacentric_heights: [f64; 2],
    /// Natural periods \[s] of heave, roll and pitch with the added mass and inertia; `None`
    /// where nothing restores (a negative metacentric height: the body capsizes).
    pub periods: [Option<f64>; 3],
}

/// The equilibrium of `body` (its `hull` and coefficients `hydro`, turned as in `state`) in
/// `water` under its weight and a vertical pull `pull` \[N] (the couplings' at t = 0, positive
/// up): heave only, the orientation and horizontal position kept. `None` if it sinks (its hull
/// cannot displace enough) or is pulled out of the water.
pub fn floating_equilibrium(
    body: &RigidBody,
    (hull, hydro): (&Hull, &Hydro),
    water: &Water,
    state: &BodyState,
    pull: f64,
) -> Option<FloatingEquilibrium> {
    let rotation = state.rotation_matrix();
    let volume = (body.mass() * water.gravity() - pull) / water.specific_weight();
    let height = equilibrium_height(hull, &rotation, water.level(), state.position.x, state.position.y, volume)?;
    let statics =
        Hydrostatics::at(hull, &Vec3::new(state.position.x, state.position.y, height), &rotation, water.level());
    let metacentric_heights = statics.metacentric_heights(height);
    let wetted = (statics.displaced_volume / hull.volume()).min(1.0);
    let added = hydro.added_mass(hull.volume(), water.density(), wetted);
    let world = |principal: &Mat3| rotation * principal * rotation.transpose();
    let (mass, inertia) =
        (world(&added.translational), world(&(Mat3::from_diagonal(&body.principal_moments()) + added.rotational)));
    let rho_g = water.specific_weight();
    let period =
        |inertia: f64, stiffness: f64| (stiffness > 0.0).then(|| std::f64::consts::TAU * (inertia / stiffness).sqrt());
    let periods = [
        period(body.mass() + mass[(2, 2)], rho_g * statics.waterplane_area),
        period(inertia[(0, 0)], rho_g * statics.displaced_volume * metacentric_heights[0]),
        period(inertia[(1, 1)], rho_g * statics.displaced_volume * metacentric_heights[1]),
    ];
    Some(FloatingEquilibrium { height, statics, metacentric_heights, periods })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;
    use approx::assert_relative_eq;

    #[test]
    fn the_closed_form_box_floats_at_its_draft_with_its_metacentric_height() {
        // PHYSICS.md §6: 20 × 10 × 4 m, relative density 0.5: d = 2 m, GM_T = 1 + 100/24 − 2.
        let (vertices, triangles) = primitives::cuboid(&Vec3::new(20.0, 10.0, 4.0), &Vec3::zeros(), 2);
        let hull = Hull::new(vertices, triangles).expect("closed");
        let z = equilibrium_height(&hull, &Mat3::identity(), 0.0, 0.0, 0.0, 400.0).expect("floats");
        // The box is wall-sided: the root is found to round-off of the level.
        assert!(z.abs() < 1e-12, "{z}");
        let state = Hydrostatics::at(&hull, &Vec3::new(0.0, 0.0, z), &Mat3::identity(), 0.0);
        assert_relative_eq!(state.displaced_volume, 400.0, max_relative = 1e-13);
        assert_relative_eq!(state.draft, 2.0, max_relative = 1e-12);
        assert_relative_eq!(state.waterplane_area, 200.0, max_relative = 1e-13);
        assert_relative_eq!(state.center_of_buoyancy, Vec3::new(0.0, 0.0, -1.0), epsilon = 1e-12);
        let [gm_t, gm_l] = state.metacentric_heights(0.0);
        assert_relative_eq!(gm_t, 1.0 + 100.0 / 24.0 - 2.0, max_relative = 1e-12);
        assert_relative_eq!(gm_l, 1.0 + 400.0 / 24.0 - 2.0, max_relative = 1e-12);
    }
}
