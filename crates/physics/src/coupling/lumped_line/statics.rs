//! A dynamic line at rest in its discrete static equilibrium (PHYSICS.md §8 "Initial state").
//!
//! The interior nodes start where the §3/§7 catenary through the same ends puts the same
//! unstretched arc lengths `s_i = i L/N` (the seabed frictionless for this solve), and Newton
//! moves them until the static forces on each (segments, wet weight, seabed) vanish. The
//! stiffness `S = −∂F/∂r` is block tridiagonal: a taut segment joins its nodes by
//! `K = (EA/l) qqᵀ + (T/l_s)(E − qqᵀ)` (a slack one, which carries nothing, by its axial
//! part, the stiffness it will have once Newton pulls it taut), the seabed adds
//! `k_b d l_i ẑẑᵀ` under a node that touches it; each Newton step `S Δr = F` is one O(N)
//! block-Thomas solve, shortened by halves until it lowers the line's potential energy (which
//! the equilibrium minimises) or its largest residual force.

use super::discrete::Discrete;
use super::nodes::{self, LineNodes, NodeForces};
use crate::coupling::catenary::Catenary;
use crate::math::{Mat3, Vec3};
use crate::surroundings::Surroundings;

/// Newton iterations before the solve gives its best shape.
pub const MAX_ITERATIONS: usize = 200;

/// Residual, a fraction of the line's force scale `λ0 g L + max T`, at which the solve stops.
pub const TOLERANCE: f64 = 1e-10;

/// The solved shape: the nodes at rest, and how the solve went.
#[derive(Debug, Clone, PartialEq)]
pub struct Equilibrium {
    pub nodes: LineNodes,
    pub iterations: usize,
    /// The largest static force left on an interior node \[N].
    pub residual: f64,
}

/// The line `line` (constants `discrete`) at rest between `p1` and `p2` \[m] at `time` \[s].
/// Never fails for finite ends: past [`MAX_ITERATIONS`] it gives the best shape it found.
pub fn solve(
    line: &Catenary,
    discrete: &Discrete,
    surroundings: &Surroundings,
    p1: &Vec3,
    p2: &Vec3,
    time: f64,
) -> Equilibrium {
    let mut nodes = LineNodes::at_rest(time, first_guess(line, discrete.segments, surroundings, p1, p2));
    let n = discrete.segments;
    let mut forces = NodeForces::default();
    nodes::evaluate(discrete, &nodes, &[], &mut forces);
    let scale = line.mass_per_length() * discrete.gravity.norm() * line.length() + 1e-6 * discrete.ea;
    let mut residual = largest(&forces, n);
    let mut iterations = 0;
    let mut trial = nodes.clone();
    let mut trial_forces = NodeForces::default();
    'newton: while iterations < MAX_ITERATIONS && residual > TOLERANCE * (scale + max_tension(&forces)) {
        iterations += 1;
        let step = newton_step(discrete, &nodes, &forces);
        // Backtracking on the potential energy, which the equilibrium minimises: the step is
        // a descent direction (S is positive definite), so some fraction of it lowers it.
        let mut fraction = 1.0;
        loop {
            for (i, delta) in step.iter().enumerate() {
                trial.positions[i + 1] = nodes.positions[i + 1] + delta * fraction;
            }
            nodes::evaluate(discrete, &trial, &[], &mut trial_forces);
            if trial_forces.potential <= forces.potential || largest(&trial_forces, n) < residual {
                break;
            }
            fraction *= 0.5;
            if fraction < 1e-12 {
                break 'newton;
            }
        }
        std::mem::swap(&mut nodes, &mut trial);
        std::mem::swap(&mut forces, &mut trial_forces);
        trial.positions.clone_from(&nodes.positions);
        residual = largest(&forces, n);
    }
    Equilibrium { nodes, iterations, residual }
}

/// The nodes at `s_i = i L/N` on the catenary (PHYSICS.md §3/§7, frictionless seabed) through
/// `p1`, `p2`; on the chord if it cannot be solved.
fn first_guess(line: &Catenary, segments: usize, surroundings: &Surroundings, p1: &Vec3, p2: &Vec3) -> Vec<Vec3> {
    let frictionless =
        Surroundings { seabed: surroundings.seabed.map(crate::seabed::Seabed::frictionless), ..*surroundings };
    let static_line = line.clone().with_model(super::parameters::LineModel::QuasiStatic);
    match static_line.solve(p1, p2, &frictionless, None) {
        Ok(state) => state.sample(segments).into_iter().map(|(point, _)| point).collect(),
        Err(_) => (0..=segments).map(|i| p1 + (p2 - p1) * (i as f64 / segments as f64)).collect(),
    }
}

/// The largest force on an interior node \[N].
fn largest(forces: &NodeForces, n: usize) -> f64 {
    (1..n).map(|i| forces.total[i].norm()).fold(0.0, f64::max)
}

fn max_tension(forces: &NodeForces) -> f64 {
    forces.tensions.iter().fold(0.0, |m, t| m.max(t.abs()))
}

/// `(S + 10⁻¹² s E)⁻¹ F` over the interior nodes, by block Thomas (`s` the largest diagonal
/// entry: the small term keeps a slack line's free directions solvable).
fn newton_step(line: &Discrete, nodes: &LineNodes, forces: &NodeForces) -> Vec<Vec3> {
    let n = line.segments;
    if n < 2 {
        return Vec::new();
    }
    let x = &nodes.positions;
    let segment_stiffness: Vec<Mat3> = (0..n)
        .map(|i| {
            let delta = x[i + 1] - x[i];
            let stretched = delta.norm();
            let strain = stretched / line.segment - 1.0;
            if stretched == 0.0 {
                return Mat3::zeros();
            }
            let q = delta / stretched;
            let qq = q * q.transpose();
            // A slack segment carries nothing, but stretching it would: Newton is told its
            // axial stiffness, so a chord sampled from the smooth catenary (shorter than its
            // arc) is pulled taut in a step instead of crawled out of by the Levenberg term.
            qq * (line.ea / line.segment) + (Mat3::identity() - qq) * (line.ea * strain.max(0.0) / stretched)
        })
        .collect();
    let mut diagonal: Vec<Mat3> = (1..n).map(|i| segment_stiffness[i - 1] + segment_stiffness[i]).collect();
    if let Some(seabed) = &line.seabed {
        for (i, block) in (1..n).zip(diagonal.iter_mut()) {
            if x[i].dot(&line.up) < seabed.elevation() {
                *block +=
                    line.up * line.up.transpose() * (line.parameters.seabed_stiffness() * line.bearing * line.share(i));
            }
        }
    }
    let largest = diagonal.iter().map(|b| b.diagonal().max()).fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let regular = 1e-12 * largest;
    for block in &mut diagonal {
        *block += Mat3::identity() * regular;
    }
    // S(i, i+1) = −K_{i+1} between interior nodes i and i + 1 (1-based node numbers).
    let m = n - 1;
    let mut reduced = diagonal;
    let mut rhs: Vec<Vec3> = (1..n).map(|i| forces.total[i]).collect();
    let mut inverses = Vec::with_capacity(m);
    for j in 0..m {
        if j > 0 {
            let coupling = -segment_stiffness[j];
            let factor: Mat3 = coupling * inverses[j - 1];
            reduced[j] -= factor * coupling;
            let carried = factor * rhs[j - 1];
            rhs[j] -= carried;
        }
        // Positive definite after the regular term; a block that is not (non-finite nodes) gives no step.
        inverses.push(reduced[j].try_inverse().unwrap_or_else(Mat3::zeros));
    }
    let mut step = vec![Vec3::zeros(); m];
    for j in (0..m).rev() {
        let mut right = rhs[j];
        if j + 1 < m {
            right -= -segment_stiffness[j + 1] * step[j + 1];
        }
        step[j] = inverses[j] * right;
    }
    step
}
