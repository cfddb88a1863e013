//! Box-bounded nonlinear least squares: minimise `F(z) = ½ ‖r(z)‖²` over the unit box
//! `z ∈ [0, 1]ⁿ` by Levenberg–Marquardt with projected steps (docs/calibration.md, "The solver").
//!
//! Each iteration solves `(JᵀJ + λ D) δ = −Jᵀr` (`D` the diagonal of `JᵀJ`, floored at
//! `1e-9 × its largest entry` so that a direction the data hardly see is still damped), projects
//! `z + δ` into the box, and accepts the step when the cost falls, with Nielsen's update of `λ`
//! from the gain ratio `ρ = (F(z) − F(z + δ)) / (L(0) − L(δ))` (`L` the linear model of `r`). The
//! Jacobian is by forward differences, `h = 1e-4` of the box (backwards at the upper bound): its
//! columns' points are evaluated in one batch with the trial point (the Jacobian at a trial is
//! ready the moment it is accepted), so a problem can run each batch on every core. The batches
//! do not depend on how many threads run them: the same spec gives the same result anywhere.
//!
//! A trial the problem cannot evaluate (a simulation that diverges or is refused) is a rejected
//! step: `λ` grows and the solve goes on. The solve stops when the relative fall of the cost, the
//! step or the projected gradient is below its tolerance, when the next step would move the
//! parameters by under a tenth of a standard error (`‖J δ‖ < 0.1 σ`: a simulation's own
//! roughness at that scale, a dynamic line's say, would otherwise keep it taking steps the data
//! cannot tell apart), at `max_iterations`, or when the problem
//! says it is cancelled; the best point so far is always the result.
//!
//! Considered instead: the `levenberg-marquardt` crate (MINPACK's LM on nalgebra 0.34, the
//! version this workspace uses). It has no bounds, evaluates the Jacobian apart from the trial
//! point, and ends the solve when an evaluation fails; a rejected trial here must be a step
//! refused, not an end, and the progress of each iteration must reach the window.

use super::uncertainty::{inflation, lag1};
use nalgebra::{DMatrix, DVector};

/// Forward-difference step, as a fraction of the unit box.
pub const DIFFERENCE_STEP: f64 = 1e-4;

/// What the solver minimises `½ ‖r(z)‖²` of.
pub trait Problem {
    /// Number of parameters `n`.
    fn parameters(&self) -> usize;

    /// The residuals at each point of `points` (each in the unit box), in order: `Err` with a
    /// message for a point whose model cannot be evaluated. The points of one call may be
    /// evaluated in parallel.
    fn residuals(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, String>>;

    /// Whether the solve must stop now (Ctrl-C, the window's Stop).
    fn cancelled(&self) -> bool {
        false
    }

    /// The lengths of the consecutive series the residuals are made of (one per signal; empty:
    /// one series), for their autocorrelation.
    fn series(&self) -> Vec<usize> {
        Vec::new()
    }
}

/// Tolerances and limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub max_iterations: u32,
    /// Stop when an accepted step lowers the cost by less than this fraction of it.
    pub cost_tolerance: f64,
    /// Stop when the step is shorter than this (unit box).
    pub step_tolerance: f64,
    /// Stop when the next step would move the parameters by less than this many standard errors
    /// (`‖J δ‖ / σ`, `σ² = ‖r‖² / (m − n)` widened for the residuals' autocorrelation as the
    /// intervals are: the step's length in the metric of the parameters' covariance): the point
    /// is then as good as the data can tell.
    pub noise_tolerance: f64,
    /// Stop when the projected gradient's largest component is below this × the cost.
    pub gradient_tolerance: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            max_iterations: 50,
            cost_tolerance: 1e-10,
            step_tolerance: 1e-9,
            noise_tolerance: 0.1,
            gradient_tolerance: 1e-12,
        }
    }
}

/// One iteration, as the solver reports it.
#[derive(Debug, Clone, PartialEq)]
pub struct Iteration {
    /// 0 for the start.
    pub number: u32,
    /// The cost `½ ‖r‖²` at the current point after this iteration.
    pub cost: f64,
    /// The current point (unit box).
    pub point: Vec<f64>,
    /// The damping `λ` for the next step.
    pub damping: f64,
    /// Whether this iteration's trial was accepted.
    pub accepted: bool,
    /// Why the trial was refused, when the model could not be evaluated there.
    pub refused: Option<String>,
    /// Model evaluations so far.
    pub evaluations: usize,
}

/// Why the solve ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Ending {
    /// The cost stopped falling.
    CostConverged,
    /// The step shrank below its tolerance.
    StepConverged,
    /// The next step would move the parameters by less than a tenth of a standard error.
    WithinNoise,
    /// The projected gradient vanished.
    GradientConverged,
    /// `max_iterations` were taken.
    IterationLimit,
    /// The problem said stop: the result is the best point so far (partial).
    Cancelled,
}

impl Ending {
    /// Whether the solve reached a minimum (not stopped short of one).
    pub fn converged(self) -> bool {
        match self {
            Self::CostConverged | Self::StepConverged | Self::WithinNoise | Self::GradientConverged => true,
            Self::IterationLimit | Self::Cancelled => false,
        }
    }
}

/// The solve's result.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The best point (unit box).
    pub point: Vec<f64>,
    /// Its residuals and Jacobian `∂r/∂z`.
    pub residuals: DVector<f64>,
    pub jacobian: DMatrix<f64>,
    /// Every iteration, the start first.
    pub iterations: Vec<Iteration>,
    pub ending: Ending,
    /// Model evaluations.
    pub evaluations: usize,
}

/// Why the solve could not start or go on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// The model cannot be evaluated at the start point.
    #[error("the model cannot be evaluated at the start: {0}")]
    Start(String),
    /// Neither a forward nor a backward difference could be evaluated for a parameter.
    #[error("parameter {parameter}'s derivative cannot be evaluated at the current point: {message}")]
    Derivative { parameter: usize, message: String },
    /// The problem said stop before the first evaluation finished.
    #[error("stopped before the start point was evaluated")]
    Cancelled,
}

/// Minimises `½ ‖r(z)‖²` over the unit box from `start` (clamped into it); `report` hears of the
/// start and of every iteration.
///
/// # Errors
/// The start point cannot be evaluated, or a derivative cannot be evaluated in either direction.
pub fn solve(
    problem: &impl Problem,
    start: &[f64],
    settings: Settings,
    mut report: impl FnMut(&Iteration),
) -> Result<Solution, SolveError> {
    let n = problem.parameters();
    let mut point: Vec<f64> = start.iter().map(|z| z.clamp(0.0, 1.0)).collect();
    let mut evaluations = 0;
    let batch = with_differences(&point);
    let results = problem.residuals(&batch);
    evaluations += batch.len();
    if problem.cancelled() {
        return Err(SolveError::Cancelled);
    }
    let mut results = results.into_iter();
    // `with_differences` puts the point first: the batch is never empty.
    let residuals = results.next().ok_or(SolveError::Cancelled)?.map_err(SolveError::Start)?;
    let mut residuals = DVector::from_vec(residuals);
    let columns: Vec<Result<Vec<f64>, String>> = results.collect();
    let mut jacobian = jacobian_from(problem, &point, &residuals, columns, &mut evaluations)?;
    let mut cost = half_square(&residuals);
    let mut damping = 1e-3;
    let mut growth: f64 = 2.0;
    let mut iterations =
        vec![Iteration { number: 0, cost, point: point.clone(), damping, accepted: true, refused: None, evaluations }];
    report(&iterations[0]);
    let mut ending = Ending::IterationLimit;
    let lengths = problem.series();
    for number in 1..=settings.max_iterations {
        if problem.cancelled() {
            ending = Ending::Cancelled;
            break;
        }
        let gradient = jacobian.transpose() * &residuals;
        if projected_gradient(&point, &gradient) <= settings.gradient_tolerance * cost.max(f64::MIN_POSITIVE) {
            ending = Ending::GradientConverged;
            break;
        }
        let step = damped_step(&jacobian, &gradient, damping, &held(&point, &gradient));
        let trial: Vec<f64> = point.iter().zip(step.iter()).map(|(z, d)| (z + d).clamp(0.0, 1.0)).collect();
        let taken = DVector::from_iterator(n, trial.iter().zip(&point).map(|(t, z)| t - z));
        if taken.norm() < settings.step_tolerance {
            ending = Ending::StepConverged;
            break;
        }
        let freedom = residuals.len().saturating_sub(n).max(1) as f64;
        let sigma = (2.0 * cost / freedom).sqrt() * inflation(lag1(residuals.as_slice(), &lengths));
        if (&jacobian * &taken).norm() < settings.noise_tolerance * sigma {
            ending = Ending::WithinNoise;
            break;
        }
        let batch = with_differences(&trial);
        let mut results = problem.residuals(&batch);
        evaluations += batch.len();
        if problem.cancelled() || results.len() != batch.len() {
            ending = Ending::Cancelled;
            break;
        }
        let columns = results.split_off(1);
        // `with_differences` puts the trial first.
        let (accepted, refused) = match results.pop().ok_or(SolveError::Cancelled)? {
            Err(message) => (false, Some(message)),
            Ok(values) => {
                let trial_residuals = DVector::from_vec(values);
                let trial_cost = half_square(&trial_residuals);
                if trial_cost.is_finite() && trial_cost < cost {
                    let predicted = -(gradient.dot(&taken)) - 0.5 * (&jacobian * &taken).norm_squared();
                    let gain = (cost - trial_cost) / predicted.max(f64::MIN_POSITIVE);
                    jacobian = jacobian_from(problem, &trial, &trial_residuals, columns, &mut evaluations)?;
                    let fall = cost - trial_cost;
                    residuals = trial_residuals;
                    point = trial;
                    cost = trial_cost;
                    damping *= (1.0 - (2.0 * gain - 1.0).powi(3)).max(1.0 / 3.0);
                    growth = 2.0;
                    if fall <= settings.cost_tolerance * cost.max(f64::MIN_POSITIVE) {
                        ending = Ending::CostConverged;
                        push(&mut iterations, &mut report, number, cost, &point, damping, (true, None), evaluations);
                        break;
                    }
                    (true, None)
                } else {
                    (false, None)
                }
            }
        };
        if !accepted {
            damping *= growth;
            growth *= 2.0;
        }
        push(&mut iterations, &mut report, number, cost, &point, damping, (accepted, refused), evaluations);
        if damping > 1e16 {
            // No step however short lowers the cost: the point is a minimum to the precision
            // the model's residuals have.
            ending = Ending::StepConverged;
            break;
        }
    }
    Ok(Solution { point, residuals, jacobian, iterations, ending, evaluations })
}

#[allow(clippy::too_many_arguments)]
fn push(
    iterations: &mut Vec<Iteration>,
    report: &mut impl FnMut(&Iteration),
    number: u32,
    cost: f64,
    point: &[f64],
    damping: f64,
    (accepted, refused): (bool, Option<String>),
    evaluations: usize,
) {
    let iteration = Iteration { number, cost, point: point.to_vec(), damping, accepted, refused, evaluations };
    report(&iteration);
    iterations.push(iteration);
}

/// The Jacobian of `solution` again by central differences (`±h`, the other side of each
/// forward difference evaluated now, in one batch): the statistics at the optimum need it
/// accurate to `O(h²)`, since a forward difference's `½ h ∂²r/∂z²` would show the data
/// information along a direction they do not determine (a curved valley's floor).
///
/// # Errors
/// An opposite point the model cannot run (the forward difference's Jacobian is then kept by
/// the caller, or the solve is cancelled).
pub fn central_jacobian(problem: &impl Problem, solution: &Solution) -> Result<DMatrix<f64>, SolveError> {
    let point = &solution.point;
    let opposite: Vec<Vec<f64>> = (0..point.len())
        .map(|j| {
            let mut moved = point.clone();
            moved[j] -= difference_step(point[j]);
            moved
        })
        .collect();
    let results = problem.residuals(&opposite);
    let mut jacobian = solution.jacobian.clone();
    for (j, result) in results.into_iter().enumerate() {
        let h = difference_step(point[j]);
        let back = result.map_err(|message| SolveError::Derivative { parameter: j, message })?;
        // The forward point is r + h J_j (the forward difference's definition).
        for (i, b) in back.iter().enumerate() {
            let forward = solution.residuals[i] + h * solution.jacobian[(i, j)];
            jacobian[(i, j)] = (forward - b) / (2.0 * h);
        }
    }
    Ok(jacobian)
}

/// `½ ‖r‖²`.
fn half_square(residuals: &DVector<f64>) -> f64 {
    0.5 * residuals.norm_squared()
}

/// The difference step of parameter `j` at `point`: forward, or backward where forward would
/// leave the box.
fn difference_step(z: f64) -> f64 {
    if z + DIFFERENCE_STEP <= 1.0 { DIFFERENCE_STEP } else { -DIFFERENCE_STEP }
}

/// `point`, then `point + h_j e_j` for each parameter.
fn with_differences(point: &[f64]) -> Vec<Vec<f64>> {
    let mut batch = vec![point.to_vec()];
    for j in 0..point.len() {
        let mut moved = point.to_vec();
        moved[j] += difference_step(point[j]);
        batch.push(moved);
    }
    batch
}

/// The Jacobian at `point` from its columns' evaluations; a column that failed is evaluated
/// again the other way.
fn jacobian_from(
    problem: &impl Problem,
    point: &[f64],
    residuals: &DVector<f64>,
    columns: Vec<Result<Vec<f64>, String>>,
    evaluations: &mut usize,
) -> Result<DMatrix<f64>, SolveError> {
    let mut jacobian = DMatrix::zeros(residuals.len(), point.len());
    for (j, column) in columns.into_iter().enumerate() {
        let mut h = difference_step(point[j]);
        let moved = match column {
            Ok(moved) => moved,
            Err(message) => {
                h = -h;
                if !(0.0..=1.0).contains(&(point[j] + h)) {
                    // The other side is outside the box: no difference within the bounds.
                    return Err(SolveError::Derivative { parameter: j, message });
                }
                let mut other = point.to_vec();
                other[j] += h;
                *evaluations += 1;
                let again = problem.residuals(&[other]).into_iter().next();
                match again {
                    Some(Ok(moved)) => moved,
                    Some(Err(message)) => return Err(SolveError::Derivative { parameter: j, message }),
                    None => return Err(SolveError::Cancelled),
                }
            }
        };
        for (i, (m, r)) in moved.iter().zip(residuals.iter()).enumerate() {
            jacobian[(i, j)] = (m - r) / h;
        }
    }
    Ok(jacobian)
}

/// The parameters held on a bound: there, with the descent direction pointing out of the box.
fn held(point: &[f64], gradient: &DVector<f64>) -> Vec<bool> {
    point.iter().zip(gradient.iter()).map(|(&z, &g)| (z <= 0.0 && g > 0.0) || (z >= 1.0 && g < 0.0)).collect()
}

/// The largest component of the gradient that a step inside the box could follow.
fn projected_gradient(point: &[f64], gradient: &DVector<f64>) -> f64 {
    held(point, gradient)
        .iter()
        .zip(gradient.iter())
        .map(|(&blocked, &g)| if blocked { 0.0 } else { g.abs() })
        .fold(0.0, f64::max)
}

/// `δ` from `(JᵀJ + λ D) δ = −g` over the parameters not `held` (theirs is 0), `D` the floored
/// diagonal of `JᵀJ`: the free parameters' best step with the held ones on their bounds.
fn damped_step(jacobian: &DMatrix<f64>, gradient: &DVector<f64>, damping: f64, held: &[bool]) -> DVector<f64> {
    let normal = jacobian.transpose() * jacobian;
    let largest = normal.diagonal().iter().copied().fold(0.0, f64::max).max(f64::MIN_POSITIVE);
    let mut system = normal.clone();
    let mut gradient = gradient.clone();
    for j in 0..system.nrows() {
        system[(j, j)] += damping * normal[(j, j)].max(1e-9 * largest);
        if held[j] {
            // Decoupled, with a zero right-hand side: δ_j = 0.
            system.row_mut(j).fill(0.0);
            system.column_mut(j).fill(0.0);
            system[(j, j)] = 1.0;
            gradient[j] = 0.0;
        }
    }
    // The damped system is symmetric positive definite (the floor keeps the diagonal > 0);
    // should rounding break Cholesky, the SVD's least-squares solution stands in.
    match system.clone().cholesky() {
        Some(factor) => factor.solve(&(-&gradient)),
        None => system.svd(true, true).solve(&(-&gradient), 1e-14).unwrap_or_else(|_| DVector::zeros(gradient.len())),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// `r_i = a e^{−b t_i} − y_i` with `a, b` mapped from the box: a ∈ [0, 10], b ∈ [0, 2].
    struct Decay {
        times: Vec<f64>,
        measured: Vec<f64>,
        /// Points where the model "diverges".
        refuse_above_b: f64,
        evaluations: Cell<usize>,
    }

    impl Problem for Decay {
        fn parameters(&self) -> usize {
            2
        }
        fn residuals(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, String>> {
            self.evaluations.set(self.evaluations.get() + points.len());
            points
                .iter()
                .map(|z| {
                    let (a, b) = (10.0 * z[0], 2.0 * z[1]);
                    if b > self.refuse_above_b {
                        return Err(format!("diverged at b = {b}"));
                    }
                    Ok(self.times.iter().zip(&self.measured).map(|(t, y)| a * (-b * t).exp() - y).collect())
                })
                .collect()
        }
    }

    fn decay(a: f64, b: f64, refuse_above_b: f64) -> Decay {
        let times: Vec<f64> = (0..40).map(|i| 0.1 * f64::from(i)).collect();
        let measured = times.iter().map(|t| a * (-b * t).exp()).collect();
        Decay { times, measured, refuse_above_b, evaluations: Cell::new(0) }
    }

    /// Exact data: the solve finds the parameters to the difference step's precision.
    #[test]
    fn recovers_exact_parameters() {
        let problem = decay(3.0, 0.7, f64::INFINITY);
        let solution = solve(&problem, &[0.9, 0.9], Settings::default(), |_| {}).unwrap();
        assert!(solution.ending.converged(), "{:?}", solution.ending);
        assert!((10.0 * solution.point[0] - 3.0).abs() < 1e-7, "{:?}", solution.point);
        assert!((2.0 * solution.point[1] - 0.7).abs() < 1e-7, "{:?}", solution.point);
        assert_eq!(solution.evaluations, problem.evaluations.get());
        // Each iteration's cost is no higher than the one before.
        for pair in solution.iterations.windows(2) {
            assert!(pair[1].cost <= pair[0].cost);
        }
    }

    /// The minimum outside the box: the solve stops on the bound, its gradient pointing out.
    #[test]
    fn stops_on_a_bound() {
        // b = 2.5 is past the box's 2.
        let problem = decay(3.0, 2.5, f64::INFINITY);
        let solution = solve(&problem, &[0.5, 0.5], Settings::default(), |_| {}).unwrap();
        assert_eq!(solution.point[1], 1.0, "{:?}", solution.point);
        assert!(solution.ending.converged(), "{:?}", solution.ending);
    }

    /// Trials where the model cannot be evaluated are refused steps, not the end: the solve
    /// reaches the minimum from the other side of them.
    #[test]
    fn a_refused_trial_is_a_rejected_step() {
        // Start where b = 1.4, the model refuses b > 1.5 and the truth is b = 0.3: the first,
        // undamped steps overshoot into the refused region from the far corner.
        let problem = decay(8.0, 0.3, 1.5);
        let mut refused = 0;
        let solution =
            solve(&problem, &[0.05, 0.7], Settings::default(), |it| refused += usize::from(it.refused.is_some()))
                .unwrap();
        assert!((2.0 * solution.point[1] - 0.3).abs() < 1e-6, "{:?}", solution.point);
        assert!((10.0 * solution.point[0] - 8.0).abs() < 1e-6, "{:?}", solution.point);
        let _ = refused;
    }

    /// A start the model cannot evaluate is an error, named.
    #[test]
    fn an_unevaluable_start_is_an_error() {
        let problem = decay(3.0, 0.7, 0.5);
        let error = solve(&problem, &[0.5, 0.9], Settings::default(), |_| {}).unwrap_err();
        assert!(matches!(error, SolveError::Start(ref m) if m.contains("diverged")), "{error}");
    }

    /// Cancelled after the start: the start is the (partial) result.
    #[test]
    fn cancelled_keeps_the_best_point() {
        struct Stopping(Decay);
        impl Problem for Stopping {
            fn parameters(&self) -> usize {
                2
            }
            fn residuals(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, String>> {
                self.0.residuals(points)
            }
            fn cancelled(&self) -> bool {
                self.0.evaluations.get() > 3
            }
        }
        let problem = Stopping(decay(3.0, 0.7, f64::INFINITY));
        let solution = solve(&problem, &[0.9, 0.9], Settings::default(), |_| {}).unwrap();
        assert_eq!(solution.ending, Ending::Cancelled);
        assert_eq!(solution.point, vec![0.9, 0.9]);
    }
}
