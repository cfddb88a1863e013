//! Mass properties of a rigid body built from a master node and slave nodes (PHYSICS.md §1
//! \[1]–\[10]).
//!
//! `m = m_M + Σ m_i` \[kg]; `x_G = (m_M x_M + Σ m_i x_i)/m` \[m];
//! `I = J^M + m_M(|r_M|² E − r_M r_Mᵀ) + Σ [I^i + m_i(|r_i|² E − r_i r_iᵀ)]` [kg·m²] about G with
//! `r = x − x_G`, in the tensor convention (`I_xy = −Σ m x y`). The principal moments and axes
//! come from nalgebra's symmetric eigen-decomposition.

use crate::math::{Mat3, Rotation, Vec3};
use thiserror::Error;

/// A point mass with an optional own inertia tensor about itself (tensor convention).
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    /// Position in the world at t = 0 \[m].
    pub position: Vec3,
    /// Mass \[kg], ≥ 0.
    pub mass: f64,
    /// Inertia tensor about the node [kg·m²].
    pub inertia: Mat3,
}

/// Why a set of nodes is not a rigid body.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MassError {
    #[error("total mass must be > 0 kg, got {0} kg")]
    NonPositiveMass(f64),
    #[error("{} has negative mass {mass} kg", node_label(*index))]
    NegativeNodeMass { index: usize, mass: f64 },
    #[error(
        "inertia tensor about G is not positive definite (principal moments {0:?} kg·m²): \
         all the mass lies on a point or a line; give the nodes an inertia or spread them"
    )]
    NotPositiveDefinite([f64; 3]),
    #[error("mass properties overflow f64 (mass {mass} kg, inertia {inertia_norm} kg·m²): use smaller numbers")]
    NotFinite { mass: f64, inertia_norm: f64 },
}

/// "the master node" for index 0, "slave node i" (1-based) after it.
fn node_label(index: usize) -> String {
    if index == 0 { "the master node".into() } else { format!("slave node {index}") }
}

/// Mass, centre of mass and principal inertia of a rigid body.
#[derive(Debug, Clone, PartialEq)]
pub struct MassProperties {
    /// `m` \[kg].
    pub mass: f64,
    /// `x_G` at t = 0 \[m].
    pub center_of_mass: Vec3,
    /// Inertia tensor about G in world axes at t = 0 [kg·m²].
    pub inertia_about_g: Mat3,
    /// Principal moments `I1, I2, I3` [kg·m²], ascending.
    pub principal_moments: Vec3,
    /// Rotation from the principal frame to the world at t = 0 (columns = principal axes).
    pub principal_axes: Rotation,
}

impl MassProperties {
    /// Mass properties of master node `master` and slave nodes `slaves` (PHYSICS.md §1 \[1]–\[10]).
    pub fn from_nodes(master: &Node, slaves: &[Node]) -> Result<Self, MassError> {
        let nodes = || std::iter::once(master).chain(slaves.iter());
        if let Some((index, node)) = nodes().enumerate().find(|(_, n)| n.mass < 0.0) {
            return Err(MassError::NegativeNodeMass { index, mass: node.mass });
        }
        let mass: f64 = nodes().map(|n| n.mass).sum();
        if !(mass > 0.0) {
            return Err(MassError::NonPositiveMass(mass));
        }
        // A lone master node is its own centre of mass, exactly (no m·x/m round-off), so that
        // points declared at it are exactly G.
        let center_of_mass =
            if slaves.is_empty() { master.position } else { nodes().map(|n| n.position * n.mass).sum::<Vec3>() / mass };
        let inertia_about_g =
            nodes().map(|n| n.inertia + point_mass_inertia(n.mass, &(n.position - center_of_mass))).sum::<Mat3>();
        if !(mass.is_finite()
            && center_of_mass.iter().all(|x| x.is_finite())
            && inertia_about_g.iter().all(|x| x.is_finite()))
        {
            return Err(MassError::NotFinite { mass, inertia_norm: inertia_about_g.norm() });
        }
        let (principal_moments, principal_axes) = principal_frame(&inertia_about_g)
            .ok_or(MassError::NotFinite { mass, inertia_norm: inertia_about_g.norm() })?;
        if principal_moments.iter().any(|&moment| !(moment > 1e-12 * principal_moments.max().max(f64::MIN_POSITIVE))) {
            return Err(MassError::NotPositiveDefinite(principal_moments.into()));
        }
        Ok(Self { mass, center_of_mass, inertia_about_g, principal_moments, principal_axes })
    }

    /// `Some(i)` where principal moment `i` exceeds the sum of the other two (the triangle
    /// inequality of a real mass distribution fails; PHYSICS.md §1 asks for a warning).
    pub fn violated_triangle_inequality(&self) -> Option<usize> {
        let m = self.principal_moments;
        let sum = m.sum();
        (0..3).find(|&i| m[i] > (sum - m[i]) * (1.0 + 1e-12))
    }
}

/// Parallel-axis term of a point mass `m` at offset `r` from G: `m(|r|² E − r rᵀ)`.
fn point_mass_inertia(mass: f64, r: &Vec3) -> Mat3 {
    mass * (Mat3::identity() * r.norm_squared() - r * r.transpose())
}

/// Principal moments (ascending) and a proper rotation whose columns are the principal axes;
/// `None` if the (finite) tensor cannot be diagonalised in 1000 sweeps.
fn principal_frame(inertia: &Mat3) -> Option<(Vec3, Rotation)> {
    let eigen = nalgebra::SymmetricEigen::try_new(*inertia, f64::EPSILON, 1000)?;
    let mut order = [0usize, 1, 2];
    order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
    let moments = Vec3::new(eigen.eigenvalues[order[0]], eigen.eigenvalues[order[1]], eigen.eigenvalues[order[2]]);
    let axis = |i: usize| eigen.eigenvectors.column(order[i]).into_owned();
    let (e1, e2) = (axis(0), axis(1));
    // Third axis from the cross product: the frame is right-handed whatever signs the solver chose.
    let e3 = e1.cross(&e2);
    let rotation = nalgebra::Rotation3::from_matrix_unchecked(Mat3::from_columns(&[e1, e2, e3]));
    Some((moments, Rotation::from_rotation_matrix(&rotation)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn point(x: f64, y: f64, z: f64, mass: f64) -> Node {
        Node { position: Vec3::new(x, y, z), mass, inertia: Mat3::zeros() }
    }

    #[test]
    fn cube_of_eight_masses_around_a_master_with_added_inertia() {
        let master =
            Node { position: Vec3::zeros(), mass: 2.0, inertia: Mat3::from_diagonal(&Vec3::new(0.1, 0.2, 0.3)) };
        let mut slaves = Vec::new();
        for sx in [-0.5, 0.5] {
            for sy in [-0.5, 0.5] {
                for sz in [-0.5, 0.5] {
                    slaves.push(point(sx, sy, sz, 1.0));
                }
            }
        }
        let p = MassProperties::from_nodes(&master, &slaves).unwrap();
        assert_relative_eq!(p.mass, 10.0);
        assert_relative_eq!(p.center_of_mass, Vec3::zeros(), epsilon = 1e-15);
        assert_relative_eq!(p.inertia_about_g, Mat3::from_diagonal(&Vec3::new(4.1, 4.2, 4.3)), epsilon = 1e-14);
        assert_relative_eq!(p.principal_moments, Vec3::new(4.1, 4.2, 4.3), epsilon = 1e-13);
    }

    #[test]
    fn four_masses_give_the_full_tensor_and_principal_moments() {
        let master = point(0.0, 0.0, 0.0, 1.0);
        let slaves = [point(1.0, 0.0, 0.0, 2.0), point(0.0, 1.0, 0.0, 3.0), point(0.0, 0.0, 1.0, 4.0)];
        let p = MassProperties::from_nodes(&master, &slaves).unwrap();
        assert_relative_eq!(p.center_of_mass, Vec3::new(0.2, 0.3, 0.4), epsilon = 1e-15);
        let expected = Mat3::new(4.5, 0.6, 0.8, 0.6, 4.0, 1.2, 0.8, 1.2, 3.7);
        assert_relative_eq!(p.inertia_about_g, expected, epsilon = 1e-13);
        assert_relative_eq!(p.principal_moments, Vec3::new(2.6131850997, 3.7840131593, 5.8028017409), epsilon = 1e-9);
        // The axes diagonalise the tensor: Rᵀ I R = diag(I1, I2, I3), and R is proper.
        let r = p.principal_axes.to_rotation_matrix().into_inner();
        assert_relative_eq!(r.transpose() * expected * r, Mat3::from_diagonal(&p.principal_moments), epsilon = 1e-12);
        assert_relative_eq!(r.determinant(), 1.0, epsilon = 1e-14);
        assert_eq!(p.violated_triangle_inequality(), None);
    }

    #[test]
    fn rejects_zero_mass_negative_mass_and_a_line_of_masses() {
        assert_eq!(MassProperties::from_nodes(&point(0.0, 0.0, 0.0, 0.0), &[]), Err(MassError::NonPositiveMass(0.0)));
        assert!(matches!(
            MassProperties::from_nodes(&point(0.0, 0.0, 0.0, 1.0), &[point(1.0, 0.0, 0.0, -2.0)]),
            Err(MassError::NegativeNodeMass { index: 1, .. })
        ));
        let line = MassProperties::from_nodes(&point(0.0, 0.0, 0.0, 1.0), &[point(1.0, 0.0, 0.0, 1.0)]);
        assert!(matches!(line, Err(MassError::NotPositiveDefinite(_))), "{line:?}");
    }

    #[test]
    fn overflowing_numbers_are_an_error_not_a_hang() {
        let far = MassProperties::from_nodes(&point(0.0, 0.0, 0.0, 1e300), &[point(1e200, 0.0, 0.0, 1e300)]);
        assert!(matches!(far, Err(MassError::NotFinite { .. })), "{far:?}");
    }

    #[test]
    fn flat_plate_is_on_the_triangle_limit_and_a_rod_with_a_fat_master_violates_it() {
        // A thin square of 4 masses: I3 = I1 + I2 exactly, allowed.
        let plate = MassProperties::from_nodes(
            &point(1.0, 1.0, 0.0, 1.0),
            &[point(-1.0, 1.0, 0.0, 1.0), point(1.0, -1.0, 0.0, 1.0), point(-1.0, -1.0, 0.0, 1.0)],
        )
        .unwrap();
        assert_eq!(plate.violated_triangle_inequality(), None);
        let odd = Node { position: Vec3::zeros(), mass: 1.0, inertia: Mat3::from_diagonal(&Vec3::new(0.1, 0.1, 1.0)) };
        let p = MassProperties::from_nodes(&odd, &[]).unwrap();
        assert_eq!(p.violated_triangle_inequality(), Some(2));
    }
}
