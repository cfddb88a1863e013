//! A floating body's undamped natural periods at its static equilibrium under potential flow
//! (PHYSICS.md §9, "Natural periods"): the eigenproblem `[K − ω² (M + A)] ξ = 0` about G, world
//! axes, small rotations, with
//! - `M = diag(m E, I_G)` \[kg, kg·m²], the body's mass and inertia about G;
//! - `K`, the 6 × 6 tangent stiffness at the equilibrium (hydrostatics, weight, lines, springs:
//!   [`crate::statics::Equilibrium::body_stiffness`]) \[N/m, N/rad, N·m/m, N·m/rad];
//! - `A = Tᵀ A_P T` the panel code's added mass moved from the reference point P to G
//!   ([`PotentialBody::added_mass_at_center`]), either
//!   - [`AddedMassAt::Infinite`]: `A∞`, what a time-domain model's mass matrix holds without its
//!     radiation memory (the linearisation behind published eigenanalyses such as OC3-Hywind's),
//!   - [`AddedMassAt::Resonance`]: `A(ω_n)` at each mode's own frequency, by fixed-point
//!     iteration (`ω ← ω_n(A(ω))`), what a free decay with the memory shows.
//!
//! `ω² = λ` are the real eigenvalues of `(M + A)⁻¹ K`; a mode's shape `ξ` is the right singular
//! vector of `K − λ (M + A)` with the smallest singular value. Modes without stiffness (a free
//! surge) have no period and are left out.
//!
//! nalgebra's general eigen-decomposition gives eigenvalues only (its symmetric one would need a
//! symmetric `K`, which the lines' stiffness about G need not be), hence the SVD for the shapes.

use crate::body::BodyFrame;
use crate::potential::body::mass_at_center;
use crate::potential::{Matrix6, PotentialBody, Vector6};
use crate::statics::Equilibrium;
use crate::system::System;
use std::f64::consts::TAU;

/// Body `index` of `system`, floating under potential flow, at the static equilibrium `solved`:
/// its modes with `added` (module docs), or `None` for a body without potential flow.
pub fn at_equilibrium(
    system: &System,
    solved: &Equilibrium,
    index: usize,
    added: AddedMassAt,
) -> Option<Vec<NaturalMode>> {
    let floating = system.water()?.floating.iter().find(|f| f.body == index)?;
    let model = &floating.potential.as_ref()?.model;
    let state = &solved.states[index];
    let mass = mass_at_center(&system.bodies()[index], &state.orientation.to_rotation_matrix().into_inner());
    Some(natural_modes(model, &state.frame(), &mass, &solved.body_stiffness(index), added))
}

/// Which added mass the eigenproblem uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum AddedMassAt {
    /// `A∞`.
    Infinite,
    /// `A(ω_n)`, iterated to each mode's frequency.
    Resonance,
}

/// One undamped mode.
#[derive(Debug, Clone, PartialEq)]
pub struct NaturalMode {
    /// `2π/ω_n` \[s].
    pub period: f64,
    /// `ξ` (m and rad), scaled so its largest kinetic share is +1.
    pub shape: Vector6,
    /// The dof (0 surge … 5 yaw) with the largest share `ξ_i Σ_j (M + A)_ij ξ_j` of the mode's
    /// kinetic energy.
    pub dominant: usize,
}

/// Eigenvalues this far below the largest, relative, count as zero (no stiffness).
const ZERO_EIGENVALUE: f64 = 1e-9;
/// The fixed-point iteration stops when `ω` moves by less than this, relative.
const CONVERGED: f64 = 1e-10;
/// And gives up after this many rounds (`A(ω)` varies slowly near a resonance: a few suffice).
const MAX_ROUNDS: usize = 100;

/// The body's undamped modes, longest period first (module docs).
pub fn natural_modes(
    body: &PotentialBody,
    frame: &BodyFrame,
    mass: &Matrix6,
    stiffness: &Matrix6,
    added: AddedMassAt,
) -> Vec<NaturalMode> {
    let infinite = modes(&(mass + body.infinite_added_mass_at_center(frame)), stiffness);
    match added {
        AddedMassAt::Infinite => infinite,
        AddedMassAt::Resonance => {
            let at = |omega: f64| mass + body.added_mass_at_center(frame, &body.coefficients().radiation_at(omega).0);
            infinite.into_iter().map(|mode| at_resonance(mode, &at, stiffness)).collect()
        }
    }
}

/// `mode` followed as `A` becomes `A(ω)` at its frequency: each round solves with `at(ω)` and
/// keeps the mode whose shape is closest to the last one's.
fn at_resonance(mut mode: NaturalMode, at: &impl Fn(f64) -> Matrix6, stiffness: &Matrix6) -> NaturalMode {
    for _ in 0..MAX_ROUNDS {
        let inertia = at(TAU / mode.period);
        let Some(next) = modes(&inertia, stiffness).into_iter().max_by(|a, b| {
            overlap(&a.shape, &mode.shape, &inertia).total_cmp(&overlap(&b.shape, &mode.shape, &inertia))
        }) else {
            return mode;
        };
        let moved = (next.period - mode.period).abs() / mode.period;
        mode = next;
        if moved < CONVERGED {
            break;
        }
    }
    mode
}

/// `|aᵀ M b| / √(aᵀ M a · bᵀ M b)`: 1 for the same shape.
fn overlap(a: &Vector6, b: &Vector6, inertia: &Matrix6) -> f64 {
    let product = |x: &Vector6, y: &Vector6| x.dot(&(inertia * y));
    product(a, b).abs() / (product(a, a) * product(b, b)).sqrt()
}

/// The modes of `inertia` and `stiffness` with a positive stiffness, longest period first.
fn modes(inertia: &Matrix6, stiffness: &Matrix6) -> Vec<NaturalMode> {
    let Some(inverse) = inertia.try_inverse() else { return Vec::new() };
    let eigenvalues = (inverse * stiffness).complex_eigenvalues();
    let largest = eigenvalues.iter().map(|l| l.norm()).fold(0.0, f64::max);
    let mut found: Vec<NaturalMode> = eigenvalues
        .iter()
        .filter(|l| l.re > ZERO_EIGENVALUE * largest && l.im.abs() <= ZERO_EIGENVALUE * largest.max(l.re))
        .map(|l| mode(l.re, inertia, stiffness))
        .collect();
    found.sort_by(|a, b| b.period.total_cmp(&a.period));
    found
}

/// The mode of eigenvalue `lambda` = `ω²` \[1/s²].
fn mode(lambda: f64, inertia: &Matrix6, stiffness: &Matrix6) -> NaturalMode {
    let svd = (stiffness - inertia * lambda).svd(false, true);
    // SVD with `compute_v` always returns `v_t`; its row of the smallest singular value.
    let v_t = svd.v_t.expect("v_t was asked for");
    let smallest = svd.singular_values.imin();
    let mut shape: Vector6 = v_t.row(smallest).transpose();
    let kinetic = shape.component_mul(&(inertia * shape));
    let dominant = kinetic.iamax();
    shape /= shape[dominant];
    NaturalMode { period: TAU / lambda.sqrt(), shape, dominant }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two uncoupled springs and masses: the periods `2π √(m/k)`, each mode its own dof.
    #[test]
    fn uncoupled_dofs_give_their_own_periods() {
        let inertia = Matrix6::from_diagonal(&Vector6::new(2.0, 1.0, 3.0, 4.0, 5.0, 6.0));
        let stiffness = Matrix6::from_diagonal(&Vector6::new(8.0, 0.0, 12.0, 1.0, 0.0, 0.0));
        let found = modes(&inertia, &stiffness);
        let expected = [(3, TAU * 2.0), (0, TAU * 0.5), (2, TAU * 0.5)];
        assert_eq!(found.len(), 3);
        for (mode, (dof, period)) in found.iter().zip(expected) {
            if dof != 3 {
                assert!([0, 2].contains(&mode.dominant), "{mode:?}");
            } else {
                assert_eq!(mode.dominant, 3);
            }
            assert!((mode.period - period).abs() < 1e-12 * period, "{mode:?} against {period}");
        }
    }

    /// Two masses `m` joined to the ground and to each other by springs `k` along x and y: the
    /// closed form `ω² = k/m` (in phase) and `3k/m` (out of phase), shapes (1, 1) and (1, −1).
    #[test]
    fn coupled_dofs_give_the_closed_form_modes_and_shapes() {
        let (m, k) = (2.0, 50.0);
        let inertia = Matrix6::identity() * m;
        let mut stiffness = Matrix6::zeros();
        stiffness[(0, 0)] = 2.0 * k;
        stiffness[(1, 1)] = 2.0 * k;
        stiffness[(0, 1)] = -k;
        stiffness[(1, 0)] = -k;
        let found = modes(&inertia, &stiffness);
        assert_eq!(found.len(), 2);
        let periods = [TAU * (m / k).sqrt(), TAU * (m / (3.0 * k)).sqrt()];
        for (mode, (period, other)) in found.iter().zip([(periods[0], 1.0), (periods[1], -1.0)]) {
            assert!((mode.period - period).abs() < 1e-12 * period, "{mode:?}");
            let (big, small) = if mode.dominant == 0 { (0, 1) } else { (1, 0) };
            assert!((mode.shape[big] - 1.0).abs() < 1e-12 && (mode.shape[small] - other).abs() < 1e-9, "{mode:?}");
        }
    }
}
