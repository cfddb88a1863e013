//! Static equilibrium (PHYSICS.md §7 "Static equilibrium"; MoorPy's `solveEquilibrium`): the
//! poses at which every free direction of every body ([`super::dofs`]) carries no load, the
//! bodies at rest, under every force source of the system's evaluation (gravity, springs,
//! catenaries, contacts, the water's hydrostatics and its current's drag; any source the
//! evaluation gains later), as the system at rest sees them ([`System::at_rest`]: still water,
//! no added mass), at [`STATIC_TIME`].
//!
//! Newton's method on the loads `r(q)` with the tangent stiffness `K = −∂r/∂q`
//! ([`super::stiffness`]): `(K + λ D) δ = r`, where `D` is the diagonal of `K` (floored, so that
//! a direction without stiffness still moves along its load) and `λ` is 0 while Newton's steps
//! are accepted and grows when they are not (Levenberg–Marquardt's safeguard). A step moves no
//! body further than a trust radius (a quarter of the scene, half a radian at first; doubled
//! after a step cut to it is accepted whole, halved with the step otherwise) and is halved
//! until it is accepted: the loads shrink, or they did work on the way (the potential energy
//! fell, so the bodies settle as they would at rest). The solve stops when every load is below
//! [`Settings::tolerance`] of the scene's force scale (its moment scale for moments).
//!
//! A body that travels beyond [`RUNAWAY`] scene sizes, or turns more than two turns, in the
//! solve's steps has no equilibrium in that direction: the error names it, the direction and the load along it.
//! A system that no `λ` up to [`MAX_DAMPING`] makes solvable has a non-finite stiffness or load:
//! the solve stops with [`EquilibriumError::NoStep`] rather than raise `λ` for ever.

use super::dofs::{Direction, Dof, Dofs, displace_by};
use super::stiffness::{self, STATIC_TIME};
use crate::body::BodyState;
use crate::coupling::CouplingError;
use crate::evaluation::Evaluation;
use crate::math::{Vec3, bounding_box};
use crate::system::System;
use nalgebra::{DMatrix, DVector};

/// A body that goes this many scene sizes from its start has no equilibrium.
pub const RUNAWAY: f64 = 100.0;
/// A body that turns this far [rad] about one axis has none either.
const RUNAWAY_TURN: f64 = 4.0 * std::f64::consts::PI;
/// The first trust radius, in scene sizes (twice as many radians): a step moves no body further.
const FIRST_REACH: f64 = 0.25;
/// Halvings of a step before it is refused.
const MAX_HALVINGS: u32 = 12;
/// The largest damping `λ` tried. `D` is floored at 1e-6 of `K`'s largest diagonal entry of
/// its kind, so at `λ = 1e16` the added `λ D` is ten orders above that entry and the damped
/// matrix of a finite `K` can be solved: a system still unsolvable there has a non-finite entry.
pub const MAX_DAMPING: f64 = 1e16;

/// How the solve stops.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Largest load left, a fraction of the force scale (moments: of the force scale times the
    /// scene size).
    pub tolerance: f64,
    /// Newton iterations before giving up.
    pub max_iterations: u32,
}

impl Default for Settings {
    fn default() -> Self {
        Self { tolerance: 1e-9, max_iterations: 200 }
    }
}

/// A static equilibrium.
#[derive(Debug, Clone)]
pub struct Equilibrium {
    /// The bodies' states, at rest.
    pub states: Vec<BodyState>,
    /// The evaluation at those states: loads, coupling records, solved lines.
    pub evaluation: Evaluation,
    /// `K` \[SI] of every body's six directions there ([`stiffness::tangent`]).
    pub stiffness: DMatrix<f64>,
    /// The directions solved for.
    pub dofs: Dofs,
    /// Newton iterations and force evaluations taken.
    pub iterations: u32,
    pub evaluations: u32,
    /// The largest load left along a free direction \[N] and about one [N·m].
    pub residual_force: f64,
    pub residual_moment: f64,
    /// A free direction along which the equilibrium is unstable (a negative stiffness), if any.
    pub unstable: Option<Dof>,
}

impl Equilibrium {
    /// The 6 × 6 stiffness of body `body` at equilibrium, the others held where they are:
    /// rows and columns x, y, z, roll, pitch, yaw.
    pub fn body_stiffness(&self, body: usize) -> nalgebra::Matrix6<f64> {
        self.stiffness.fixed_view::<6, 6>(6 * body, 6 * body).into_owned()
    }

    /// The load on `dof` at equilibrium (what holds a held direction there, negated) [N or N·m].
    pub fn load(&self, dof: Dof) -> f64 {
        loads(&self.evaluation)[dof.row()]
    }
}

/// Why there is no equilibrium.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EquilibriumError {
    #[error("no static equilibrium: body \"{body}\" has no restoring force in {direction}: it went {travel:.4e} {unit} from its start under a load of {load:.4e} {load_unit} along it", unit = direction.unit(), load_unit = direction.load_unit())]
    Unreachable { body: String, direction: Direction, travel: f64, load: f64 },
    #[error("coupling \"{coupling}\" cannot give its forces during the static solve: {source}")]
    Forces { coupling: String, source: CouplingError },
    #[error("the static solve did not converge in {iterations} iterations: body \"{body}\" still carries {load:.4e} {load_unit} in {direction}", load_unit = direction.load_unit())]
    NotConverged { iterations: u32, body: String, direction: Direction, load: f64 },
    #[error(
        "the static solve found no step at iteration {iteration}: the tangent stiffness or the loads are not finite (no damping λ up to {MAX_DAMPING:e} makes (K + λD) δ = r solvable)"
    )]
    NoStep { iteration: u32 },
}

/// The static equilibrium of `system` from the poses of `start` (velocities are ignored), with
/// the directions `held` held where they start.
///
/// # Errors
/// A body with no restoring force along a load, a coupling without forces, or no convergence.
pub fn solve(
    system: &System,
    start: &[BodyState],
    held: &[Dof],
    settings: &Settings,
) -> Result<Equilibrium, EquilibriumError> {
    let at_rest = system.at_rest();
    let system: &System = &at_rest;
    let dofs = Dofs::of(system, held);
    let mut states: Vec<BodyState> =
        start.iter().map(|s| BodyState { velocity: Vec3::zeros(), angular_velocity: Vec3::zeros(), ..*s }).collect();
    let mut evaluation = Evaluation::new(states.len(), system.couplings());
    let mut evaluations = 0;
    let mut evaluate = |states: &[BodyState], evaluation: &mut Evaluation| {
        evaluations += 1;
        system.evaluate(states, evaluation, STATIC_TIME).map(|_| ()).map_err(|e| EquilibriumError::Forces {
            coupling: system.couplings()[e.coupling].name.clone(),
            source: e.source,
        })
    };
    evaluate(&states, &mut evaluation)?;
    let scale = Scale::of(system, &states, &evaluation);
    let mut residual = free_loads(&evaluation, &dofs);
    let mut lambda = 0.0;
    let mut iterations = 0;
    let mut travelled = DVector::zeros(dofs.len());
    let mut reach = FIRST_REACH;
    // Ends: at most `settings.max_iterations` passes.
    while !scale.converged(&residual, &dofs, settings.tolerance) {
        if iterations == settings.max_iterations {
            return Err(not_converged(system, &dofs, &residual, &scale, iterations));
        }
        iterations += 1;
        let k = restricted(&stiffness::tangent(system, &evaluation), &dofs);
        let Some((step, used)) = newton_step(&k, &residual, lambda, &scale, &dofs) else {
            return Err(EquilibriumError::NoStep { iteration: iterations });
        };
        lambda = used;
        let (step, cut) = scale.limited(step, &dofs, reach);
        let mut halvings = 0;
        // Ends: each pass is accepted or halves the step, and past MAX_HALVINGS it is refused.
        loop {
            let mut trial_states = states.clone();
            move_bodies(&mut trial_states, &dofs, &step, 0.5f64.powi(halvings as i32));
            let mut trial = evaluation.clone();
            let accepted = evaluate(&trial_states, &mut trial).is_ok() && {
                let trial_residual = free_loads(&trial, &dofs);
                let work = 0.5 * (&residual + &trial_residual).dot(&step) * 0.5f64.powi(halvings as i32);
                let accept = scale.merit(&trial_residual, &dofs) < scale.merit(&residual, &dofs) || work > 0.0;
                if accept {
                    residual = trial_residual;
                }
                accept
            };
            if accepted {
                states = trial_states;
                evaluation = trial;
                travelled += &step * 0.5f64.powi(halvings as i32);
                lambda = if halvings == 0 { 0.25 * lambda } else { lambda };
                reach = if halvings == 0 && cut {
                    (2.0 * reach).min(2.0 * RUNAWAY)
                } else {
                    reach * 0.5f64.powi(halvings as i32)
                };
                break;
            }
            halvings += 1;
            if halvings > MAX_HALVINGS {
                lambda = (10.0 * lambda).clamp(1e-6, MAX_DAMPING);
                break;
            }
        }
        if let Some(error) = runaway(system, &travelled, &dofs, &residual, &scale) {
            return Err(error);
        }
    }
    let stiffness = stiffness::tangent(system, &evaluation);
    let unstable = least_stable(&restricted(&stiffness, &dofs), &dofs);
    let (residual_force, residual_moment) = largest(&residual, &dofs);
    Ok(Equilibrium {
        states,
        evaluation,
        stiffness,
        dofs,
        iterations,
        evaluations,
        residual_force,
        residual_moment,
        unstable,
    })
}

/// The force and length scales of a scene: the weight of the bodies that move, the largest
/// coupling force and the largest load on a body (the environment's: a wind may be the only
/// load); the size of the box around the bodies and the coupling ends (at least 1 m).
#[derive(Debug, Clone, Copy)]
struct Scale {
    force: f64,
    length: f64,
}

impl Scale {
    fn of(system: &System, states: &[BodyState], evaluation: &Evaluation) -> Self {
        let weight: f64 =
            system.bodies().iter().filter(|b| !b.is_kinematic()).map(|b| b.mass() * system.gravity().norm()).sum();
        let largest = evaluation.forces().iter().map(|f| f.f1.norm().max(f.f2.norm())).fold(0.0, f64::max);
        let load = evaluation.loads().iter().map(|l| l.force.norm()).fold(0.0, f64::max);
        let ends = evaluation.forces().iter().flat_map(|f| [f.point1, f.point2]);
        let (low, high) = bounding_box(states.iter().map(|s| s.position).chain(ends));
        let size = if low.x.is_finite() { (high - low).norm() } else { 0.0 };
        Self { force: weight.max(largest).max(load).max(1e-6), length: size.max(1.0) }
    }

    /// A load's size against its scale: force, or moment over the length.
    fn relative(&self, load: f64, dof: &Dof) -> f64 {
        if dof.direction.is_rotation() { load / (self.force * self.length) } else { load / self.force }
    }

    fn merit(&self, residual: &DVector<f64>, dofs: &Dofs) -> f64 {
        dofs.free().iter().zip(residual.iter()).map(|(d, r)| self.relative(*r, d).powi(2)).sum()
    }

    fn converged(&self, residual: &DVector<f64>, dofs: &Dofs, tolerance: f64) -> bool {
        dofs.free().iter().zip(residual.iter()).all(|(d, r)| self.relative(*r, d).abs() <= tolerance)
    }

    /// `step` shortened so that no body moves more than `reach` scene sizes or turns more than
    /// `2 reach` radians; and whether it was.
    fn limited(&self, step: DVector<f64>, dofs: &Dofs, reach: f64) -> (DVector<f64>, bool) {
        let largest = dofs
            .free()
            .iter()
            .zip(step.iter())
            .map(
                |(d, s)| {
                    if d.direction.is_rotation() { s.abs() / (2.0 * reach) } else { s.abs() / (reach * self.length) }
                },
            )
            .fold(0.0, f64::max);
        if largest > 1.0 { (step / largest, true) } else { (step, false) }
    }
}

/// The loads along the free directions, from an evaluation's loads on the bodies.
fn free_loads(evaluation: &Evaluation, dofs: &Dofs) -> DVector<f64> {
    let all = loads(evaluation);
    DVector::from_iterator(dofs.len(), dofs.free().iter().map(|d| all[d.row()]))
}

/// Force and moment on each body, six rows per body.
fn loads(evaluation: &Evaluation) -> Vec<f64> {
    evaluation
        .loads()
        .iter()
        .flat_map(|l| [l.force.x, l.force.y, l.force.z, l.moment.x, l.moment.y, l.moment.z])
        .collect()
}

/// `K` on the free directions.
fn restricted(k: &DMatrix<f64>, dofs: &Dofs) -> DMatrix<f64> {
    let rows: Vec<usize> = dofs.free().iter().map(|d| d.row()).collect();
    DMatrix::from_fn(rows.len(), rows.len(), |i, j| k[(rows[i], rows[j])])
}

/// Solves `(K + λ D) δ = r`, raising `λ` tenfold from `lambda` (from 1e-6 when it is 0) until
/// the system can be solved; returns the step and the `λ` used, or `None` when it cannot be
/// solved at [`MAX_DAMPING`] either (`K` or `r` not finite). `D` is `K`'s diagonal, floored at
/// 1e-6 of its largest entry of each kind (and at the force scale over the scene size when the
/// scene has no stiffness).
fn newton_step(
    k: &DMatrix<f64>,
    residual: &DVector<f64>,
    lambda: f64,
    scale: &Scale,
    dofs: &Dofs,
) -> Option<(DVector<f64>, f64)> {
    let largest = |rotation: bool| {
        dofs.free()
            .iter()
            .enumerate()
            .filter(|(_, d)| d.direction.is_rotation() == rotation)
            .map(|(i, _)| k[(i, i)].abs())
            .fold(0.0, f64::max)
    };
    let floor_translation = (1e-6 * largest(false)).max(1e-6 * scale.force / scale.length);
    let floor_rotation = (1e-6 * largest(true)).max(1e-6 * scale.force * scale.length);
    let diagonal = DVector::from_iterator(
        dofs.len(),
        dofs.free().iter().enumerate().map(|(i, d)| {
            k[(i, i)].abs().max(if d.direction.is_rotation() { floor_rotation } else { floor_translation })
        }),
    );
    let mut lambda = lambda;
    // Ends: λ grows tenfold each pass (at least to 1e-6), and past MAX_DAMPING there is no step.
    loop {
        let mut damped = k.clone();
        for i in 0..dofs.len() {
            damped[(i, i)] += lambda * diagonal[i];
        }
        if let Some(step) = damped.lu().solve(residual).filter(|s| s.iter().all(|x| x.is_finite())) {
            return Some((step, lambda));
        }
        if lambda >= MAX_DAMPING {
            return None;
        }
        lambda = (10.0 * lambda).max(1e-6);
    }
}

/// Moves each body by `fraction` of its part of `step`.
fn move_bodies(states: &mut [BodyState], dofs: &Dofs, step: &DVector<f64>, fraction: f64) {
    let mut moves = vec![(Vec3::zeros(), Vec3::zeros()); states.len()];
    for (dof, amount) in dofs.free().iter().zip(step.iter()) {
        let index = dof.direction.index();
        if dof.direction.is_rotation() {
            moves[dof.body].1[index - 3] += fraction * amount;
        } else {
            moves[dof.body].0[index] += fraction * amount;
        }
    }
    for (state, (translation, rotation)) in states.iter_mut().zip(moves) {
        if translation != Vec3::zeros() || rotation != Vec3::zeros() {
            displace_by(state, &translation, &rotation);
        }
    }
}

/// A body gone beyond [`RUNAWAY`] scene sizes, or turned beyond [`RUNAWAY_TURN`], in the steps
/// taken (`travelled`, per free direction): the direction it went furthest in.
fn runaway(
    system: &System,
    travelled: &DVector<f64>,
    dofs: &Dofs,
    residual: &DVector<f64>,
    scale: &Scale,
) -> Option<EquilibriumError> {
    let beyond = |dof: &Dof, t: f64| {
        if dof.direction.is_rotation() { t.abs() / RUNAWAY_TURN } else { t.abs() / (RUNAWAY * scale.length) }
    };
    let (position, dof) = dofs
        .free()
        .iter()
        .enumerate()
        .max_by(|a, b| beyond(a.1, travelled[a.0]).total_cmp(&beyond(b.1, travelled[b.0])))?;
    let gone = travelled[position];
    (beyond(dof, gone) > 1.0).then(|| EquilibriumError::Unreachable {
        body: system.bodies()[dof.body].name.clone(),
        direction: dof.direction,
        travel: gone,
        load: residual[position],
    })
}

fn not_converged(
    system: &System,
    dofs: &Dofs,
    residual: &DVector<f64>,
    scale: &Scale,
    iterations: u32,
) -> EquilibriumError {
    let worst = dofs
        .free()
        .iter()
        .zip(residual.iter())
        .max_by(|a, b| scale.relative(*a.1, a.0).abs().total_cmp(&scale.relative(*b.1, b.0).abs()));
    let (dof, load) = worst.map_or((Dof { body: 0, direction: Direction::X }, 0.0), |(d, r)| (*d, *r));
    EquilibriumError::NotConverged {
        iterations,
        body: system.bodies().get(dof.body).map_or_else(String::new, |b| b.name.clone()),
        direction: dof.direction,
        load,
    }
}

/// The largest load left along a free translation [N] and about a free rotation [N·m].
fn largest(residual: &DVector<f64>, dofs: &Dofs) -> (f64, f64) {
    let of = |rotation: bool| {
        dofs.free()
            .iter()
            .zip(residual.iter())
            .filter(|(d, _)| d.direction.is_rotation() == rotation)
            .map(|(_, r)| r.abs())
            .fold(0.0, f64::max)
    };
    (of(false), of(true))
}

/// The free direction that dominates the most negative eigenvalue of `K`'s symmetric part, if
/// that eigenvalue is negative beyond round-off.
fn least_stable(k: &DMatrix<f64>, dofs: &Dofs) -> Option<Dof> {
    if dofs.is_empty() {
        return None;
    }
    let symmetric = (k + k.transpose()) * 0.5;
    let eigen = symmetric.symmetric_eigen();
    let size = eigen.eigenvalues.iter().map(|e| e.abs()).fold(0.0, f64::max);
    let (index, value) = eigen.eigenvalues.iter().enumerate().min_by(|a, b| a.1.total_cmp(b.1))?;
    if *value >= -1e-9 * size {
        return None;
    }
    let vector = eigen.eigenvectors.column(index);
    let (dominant, _) = vector.iter().enumerate().max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))?;
    Some(dofs.free()[dominant])
}
