//! What a contact's step keeps for its friction (PHYSICS.md §4): the face forces' normal parts
//! summed as vectors, `Σ_f n_f |f_n|` [N], from which plots and recordings find the friction
//! `Σ f_t = Σ f_f − Σ_f n_f |f_n|` (every face's force is `n_f |f_n| + f_t`). The step itself
//! needs neither.

use crate::math::Vec3;

/// `Σ_f n_f |f_n|` [N] in world axes at the last evaluation, kept in pieces so that a contact
/// with one plane in range does no more than keep that plane's normal: `closed` of the planes
/// whose faces are all summed (a second plane in range closes the first), `closed_normal` their
/// `Σ |f_n|`, and the normal `n` of the last plane, whose share is the rest of the contact's
/// `Σ |f_n|`, `n (Σ |f_n| − closed_normal)`. (`closed` and `closed_normal` side by side: the
/// step clears them in one store.)
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[repr(C)]
pub struct NormalForces {
    closed: Vec3,
    closed_normal: f64,
    last_plane: Vec3,
}

impl NormalForces {
    /// Against a body: the whole sum `Σ_f n_f |f_n|` [N] (world axes) and its `Σ |f_n|` [N].
    pub fn summed(vector: Vec3, normal: f64) -> Self {
        Self { closed: vector, closed_normal: normal, last_plane: Vec3::zeros() }
    }

    /// An evaluation against planes begins: nothing closed (with no plane in range, the
    /// friction read is then that of no force, zero, whatever `last_plane` holds).
    #[inline(always)]
    pub fn start(&mut self) {
        (self.closed, self.closed_normal) = (Vec3::zeros(), 0.0);
    }

    /// A plane in range with unit `normal` (world axes) follows the plane of unit normal
    /// `previous`, after the faces of the planes before gave `Σ |f_n|` = `normal_so_far` [N]:
    /// `previous`'s share `N_p` is closed (a corner: two planes in range at once).
    pub fn close(&mut self, previous: &Vec3, normal_so_far: f64) {
        self.closed += previous * (normal_so_far - self.closed_normal);
        self.closed_normal = normal_so_far;
    }

    /// The last plane in range has unit `normal` (world axes).
    #[inline(always)]
    pub fn last_plane(&mut self, normal: &Vec3) {
        self.last_plane = *normal;
    }

    /// `|Σ f_t|` [N] of a contact whose faces gave `Σ f_f` = `force` and `Σ |f_n|` = `normal`
    /// (world axes; the coupling record's `f1` and `tension`).
    pub fn friction(&self, force: &Vec3, normal: f64) -> f64 {
        (force - self.closed - self.last_plane * (normal - self.closed_normal)).norm()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Faces on two walls, x = 0 (normal +x) with `Σ |f_n|` 3 N and y = 0 (normal +y) with 5 N,
    /// and friction (0, 0, 2) N: `Σ f_f` = (3, 5, 2), so `|Σ f_t|` = 2 N.
    #[test]
    fn the_friction_is_the_force_less_each_planes_normal_force() {
        let mut normals = NormalForces::default();
        normals.start();
        normals.close(&Vec3::x(), 3.0);
        normals.last_plane(&Vec3::y());
        assert_eq!(normals.friction(&Vec3::new(3.0, 5.0, 2.0), 8.0), 2.0);
        // Reused for one plane (y = 0 alone, 5 N): nothing of the corner is left.
        normals.start();
        normals.last_plane(&Vec3::y());
        assert_eq!(normals.friction(&Vec3::new(1.0, 5.0, 0.0), 5.0), 1.0);
        // No plane in range: no force, no friction, whatever plane was last.
        normals.start();
        assert_eq!(normals.friction(&Vec3::zeros(), 0.0), 0.0);
        // Against a body: the sum given whole.
        let body = NormalForces::summed(Vec3::new(0.0, 0.0, 4.0), 4.0);
        assert_eq!(body.friction(&Vec3::new(3.0, 0.0, 4.0), 4.0), 3.0);
    }
}
