//! A floating body's undamped natural periods at its static equilibrium under potential flow
//! (PHYSICS.md §9, "Natural periods"): the eigenproblem `[K − ω² (M + A)] ξ = 0` about G, world
//! axes, small rotations, with
//! - `M = diag(m E, I_G)` \[kg, kg·m²], the body's mass and inertia about G;
//! - `K`, the 6 × 6 tangent stiffness at the equilibrium (hydrostatics, weight, lines, springs:
//!   [`crate::statics::Equilibrium::body_stiffness`]) \[N/m, N/rad, N·m/m, N·m/rad];
//! - `A = Tᵀ A_P T` the panel code's added mass moved from the reference point P to G
//!   ([`PotentialBody::added_mass_at_center`]), either
//!   - [`AddedMassAt::Infinite`]: `A∞` as Tether's time-domain mass holds it, without its
//!     radiation memory (the linearisation behind published eigenanalyses such as OC3-Hywind's):
//!     `A∞_eff`, the file's `A∞` made consistent with its `A(ω)` and the kernel
//!     ([`PotentialBody::infinite_added_mass`]; PHYSICS.md §9, "A∞ consistent with the band"),
//!     which moves OC3-Hywind's periods by 0.1 % or less from the file's `A∞`,
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
    let floating = system.water()?.floating.iter().find(|f| f.body() == index)?;
    let model = &floating.potential()?.model();
    let state = &solved.states[index];
    let mass = mass_at_center(&system.bodies()[index], &state.orientation.to_rotation_matrix().into_inner());
    Some(natural_modes(model, &state.frame(), &mass, &solved.body_stiffness(index), added))
}

/// Which added mass the eigenproblem uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum AddedMassAt {
    /// `A∞` as the time domain's mass holds it: `A∞_eff` ([`PotentialBody::infinite_added_mass`]).
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
/// An eigenvalue whose imaginary part is below this fraction of its real part is real: a
/// repeated eigenvalue splits into such a pair under round-off and the panel code's asymmetry
/// of `A` (the cylinder's roll and pitch: 5.7e-6, `A15` and `A51` 0.8 % apart).
const NEAR_REAL: f64 = 1e-4;
/// Real eigenvalues this close, relative, are one repeated eigenvalue.
const REPEATED: f64 = 1e-4;
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
/// Eigenvalues within [`REPEATED`] of each other are one repeated eigenvalue (roll and pitch of
/// an axisymmetric body), whose shapes span a null space of that dimension: they are taken there
/// one dof at a time ([`repeated_shapes`]), so that each is one mode, not a mixture.
fn modes(inertia: &Matrix6, stiffness: &Matrix6) -> Vec<NaturalMode> {
    let Some(inverse) = inertia.try_inverse() else { return Vec::new() };
    let eigenvalues = (inverse * stiffness).complex_eigenvalues();
    let largest = eigenvalues.iter().map(|l| l.norm()).fold(0.0, f64::max);
    let mut real: Vec<f64> = eigenvalues
        .iter()
        .filter(|l| l.re > ZERO_EIGENVALUE * largest && l.im.abs() <= NEAR_REAL * l.re)
        .map(|l| l.re)
        .collect();
    real.sort_by(f64::total_cmp);
    let mut found = Vec::new();
    let mut first = 0;
    while first < real.len() {
        let count = real[first..].iter().take_while(|&&l| l - real[first] <= REPEATED * real[first]).count();
        let group = &real[first..first + count];
        let shapes = repeated_shapes(group[0], count, inertia, stiffness);
        found.extend(group.iter().zip(shapes).map(|(&lambda, shape)| mode(lambda, shape, inertia)));
        first += count;
    }
    found.sort_by(|a, b| b.period.total_cmp(&a.period));
    found
}

/// `count` shapes of the (near) null space of `K − λ (M + A)`, `λ` = `ω²` \[1/s²]: its right
/// singular vectors of the `count` smallest singular values span it; the shapes are then, in
/// turn, the projection (in the kinetic inner product `xᵀ M y`, M symmetrised) of the unit dof
/// that lies most in what is left of the space, and that shape taken out of it.
fn repeated_shapes(lambda: f64, count: usize, inertia: &Matrix6, stiffness: &Matrix6) -> Vec<Vector6> {
    let svd = (stiffness - inertia * lambda).svd(false, true);
    // SVD with `compute_v` always returns `v_t`; its rows of the smallest singular values.
    let v_t = svd.v_t.expect("v_t was asked for");
    let mut order: Vec<usize> = (0..6).collect();
    order.sort_by(|&a, &b| svd.singular_values[a].total_cmp(&svd.singular_values[b]));
    let mut space: Vec<Vector6> = order.iter().take(count).map(|&k| v_t.row(k).transpose()).collect();
    if count == 1 {
        return space;
    }
    let kinetic = (inertia + inertia.transpose()) * 0.5;
    let product = |x: &Vector6, y: &Vector6| x.dot(&(kinetic * y));
    let mut shapes = Vec::with_capacity(count);
    for _ in 0..count {
        // An orthonormal basis of what is left (Gram–Schmidt).
        let basis = space.iter().fold(Vec::<Vector6>::new(), |mut basis, v| {
            let rest = basis.iter().fold(*v, |r, b| r - b * product(b, &r));
            basis.push(rest / product(&rest, &rest).sqrt());
            basis
        });
        // The share of unit dof d in the space, `Σ_b (bᵀ M e_d)² / M_dd`, and its projection there.
        let share = |d: usize| basis.iter().map(|b| (kinetic * b)[d].powi(2)).sum::<f64>() / kinetic[(d, d)];
        let best = (0..6).max_by(|&a, &b| share(a).total_cmp(&share(b))).unwrap_or(0);
        let shape = basis.iter().fold(Vector6::zeros(), |sum, b| sum + b * (kinetic * b)[best]);
        shapes.push(shape);
        // The space less the shape: one of its vectors falls to nothing, the smallest dropped.
        let unit = shape / product(&shape, &shape).sqrt();
        space = basis.iter().map(|b| b - unit * product(&unit, b)).collect();
        space.sort_by(|a, b| product(b, b).total_cmp(&product(a, a)));
        space.truncate(count - shapes.len());
    }
    shapes
}

/// The mode of eigenvalue `lambda` = `ω²` \[1/s²] and shape `shape`.
fn mode(lambda: f64, mut shape: Vector6, inertia: &Matrix6) -> NaturalMode {
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

    /// An axisymmetric free body (the cylinder's case): roll and pitch share one eigenvalue, which
    /// round-off and an added mass asymmetric by 0.4 % (`M15` against `M51`, a panel code's noise)
    /// split into a complex pair. Both modes are found, at `ω² = k m/(m I − M15 M51)`, each its
    /// own: pitch with surge `−M15/m` of it and no roll or sway, roll the mirror image.
    #[test]
    fn a_repeated_eigenvalue_gives_one_mode_per_dof() {
        let (m, inertia, c, k) = (1.7e5, 9.0e5, 7.6e4, 2.3e6);
        let mut mass = Matrix6::from_diagonal(&Vector6::new(m, m, m, inertia, inertia, 7.8e5));
        (mass[(0, 4)], mass[(4, 0)], mass[(1, 3)], mass[(3, 1)]) = (c * 1.004, c, -c * 1.004, -c);
        let stiffness = Matrix6::from_diagonal(&Vector6::new(0.0, 0.0, 2.8e5, k, k, 0.0));
        let found = modes(&mass, &stiffness);
        assert_eq!(found.len(), 3, "{found:?}");
        let lambda = k * m / (m * inertia - c * c * 1.004);
        let (mut roll, mut pitch) = (None, None);
        for mode in found.iter().filter(|mode| mode.dominant != 2) {
            assert!((mode.period - TAU / lambda.sqrt()).abs() < 1e-9 * mode.period, "{mode:?}");
            match mode.dominant {
                3 => roll = Some(mode.shape),
                4 => pitch = Some(mode.shape),
                _ => panic!("{mode:?}"),
            }
        }
        let (roll, pitch) = (roll.expect("a roll mode"), pitch.expect("a pitch mode"));
        assert!((pitch[0] + c * 1.004 / m).abs() < 1e-9 && pitch[1].abs() < 1e-9 && pitch[3].abs() < 1e-9, "{pitch}");
        assert!((roll[1] - c * 1.004 / m).abs() < 1e-9 && roll[0].abs() < 1e-9 && roll[4].abs() < 1e-9, "{roll}");
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
