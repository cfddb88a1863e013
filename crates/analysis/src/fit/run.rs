//! A fit run: the solver ([`super::solver`]) on the model's residuals, each batch of runs on
//! the runner's threads, then the statistics at the optimum ([`super::uncertainty`]) and what
//! the report needs (docs/calibration.md, "What a fit returns").

use super::model::{Model, Trajectory};
use super::parameter::Parameter;
use super::setup::Setup;
use super::solver::{self, DIFFERENCE_STEP, Ending, Iteration, Problem, Settings, SolveError};
use super::uncertainty::{self, Uncertainty};
use crate::runner::Runner;
use std::time::Instant;

/// Where a fit is, after each iteration (the window moves its knobs to `values`).
#[derive(Debug, Clone, PartialEq)]
pub struct Progress {
    pub iteration: u32,
    /// `½ ‖r‖²` at `values`.
    pub cost: f64,
    /// The current parameter values, in the spec's order.
    pub values: Vec<f64>,
    /// Whether this iteration's trial was taken; why it could not be run, if it could not.
    pub accepted: bool,
    pub refused: Option<String>,
    /// Model runs so far (runs that differ only in the time shift counted once each).
    pub runs: usize,
}

/// A fitted parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Fitted {
    pub name: String,
    pub start: f64,
    pub value: f64,
    /// Its standard error and 95 % interval, `None` when the data cannot determine it: the
    /// textbook ones for white residuals, widened for their lag-1 autocorrelation
    /// ([`Uncertainty::inflation`]).
    pub standard_error: Option<f64>,
    pub interval: Option<(f64, f64)>,
    /// The same if the residual is correlated model error (the sandwich covariance over the
    /// residual's autocorrelation, [`super::uncertainty::Correlated`]): `θ̂ ± t₀.₉₇₅,ν √C_c,jj`.
    pub correlated_standard_error: Option<f64>,
    pub correlated_interval: Option<(f64, f64)>,
    /// On one of its bounds at the optimum (the interval then says what the data allow, not
    /// where the minimum is).
    pub at_bound: bool,
}

/// How well one signal agrees.
#[derive(Debug, Clone, PartialEq)]
pub struct SignalFit {
    pub column: String,
    pub unit: &'static str,
    pub weight: f64,
    pub samples: usize,
    /// RMS of model − record [unit], at the start and at the optimum.
    pub rms_start: f64,
    pub rms_fitted: f64,
    /// The model at the record's times, at the start and at the optimum.
    pub start: Vec<f64>,
    pub fitted: Vec<f64>,
}

/// What a fit gives.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub parameters: Vec<Fitted>,
    pub uncertainty: Uncertainty,
    pub iterations: Vec<Progress>,
    pub signals: Vec<SignalFit>,
    pub ending: Ending,
    /// Model runs, and the wall time of the whole fit \[s].
    pub runs: usize,
    pub wall_seconds: f64,
    /// The fitted run, every signal at every world step.
    pub trajectory: Trajectory,
    pub values: Vec<f64>,
}

impl Outcome {
    /// Whether the fit stopped short of a minimum (cancelled, or out of iterations).
    pub fn partial(&self) -> bool {
        !self.ending.converged()
    }
}

/// Why a fit stopped without a result.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    Solve(#[from] SolveError),
}

/// The model as the solver's problem, in the unit box.
struct Residuals<'a> {
    model: &'a Model,
    runner: &'a Runner,
    runs: std::cell::Cell<usize>,
}

impl Residuals<'_> {
    fn values(&self, point: &[f64]) -> Vec<f64> {
        self.model.parameters.iter().zip(point).map(|(p, z)| p.value(*z)).collect()
    }
}

impl Problem for Residuals<'_> {
    fn parameters(&self) -> usize {
        self.model.parameters.len()
    }

    fn residuals(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, String>> {
        let batch: Vec<Vec<f64>> = points.iter().map(|z| self.values(z)).collect();
        let (results, runs) = self.model.evaluate(&batch, self.runner);
        self.runs.set(self.runs.get() + runs);
        results
    }

    fn cancelled(&self) -> bool {
        self.runner.cancelled()
    }

    fn series(&self) -> Vec<usize> {
        self.model.signals.iter().map(|s| s.times.len()).collect()
    }
}

/// Fits `setup` on `runner`'s threads; `progress` hears of the start and of every iteration.
/// Stopping the runner (Ctrl-C) ends the fit at the best point so far, said to be partial.
///
/// # Errors
/// The model cannot be run at the start, or a derivative in neither direction.
pub fn fit(setup: &Setup, runner: &Runner, mut progress: impl FnMut(&Progress)) -> Result<Outcome, RunError> {
    let started = Instant::now();
    let model = &setup.model;
    let problem = Residuals { model, runner, runs: std::cell::Cell::new(0) };
    let start: Vec<f64> = model.parameters.iter().map(|p| p.unit(p.start)).collect();
    let settings = Settings { max_iterations: setup.max_iterations, ..Settings::default() };
    let mut iterations = Vec::new();
    let solution = solver::solve(&problem, &start, settings, |it: &Iteration| {
        let step = Progress {
            iteration: it.number,
            cost: it.cost,
            values: problem.values(&it.point),
            accepted: it.accepted,
            refused: it.refused.clone(),
            runs: problem.runs.get(),
        };
        progress(&step);
        iterations.push(step);
    })?;
    let values = problem.values(&solution.point);
    let scaling: Vec<_> = model.parameters.iter().zip(&solution.point).map(|(p, z)| p.scaling(*z)).collect();
    // A point on a bound has no other side within the box to difference from: the forward
    // Jacobian stands there.
    let inside = solution.point.iter().all(|z| *z > DIFFERENCE_STEP && *z < 1.0 - DIFFERENCE_STEP);
    let jacobian = if inside && !runner.cancelled() {
        solver::central_jacobian(&problem, &solution).unwrap_or_else(|_| solution.jacobian.clone())
    } else {
        solution.jacobian.clone()
    };
    let uncertainty = uncertainty::estimate(&solution.residuals, &jacobian, &scaling, &problem.series());
    let parameters = fitted(&model.parameters, &solution.point, &values, &uncertainty);
    // The start and the optimum run once more, side by side, for the report's curves (the
    // solver keeps residuals, not runs); both ran before, so they run again.
    let start_values: Vec<f64> = model.parameters.iter().map(|p| p.start).collect();
    // After a Ctrl-C too (a partial fit is still reported): on threads of their own, without
    // the cancelled flag.
    let mut runs = model.runs(&[&start_values, &values], &Runner::new(runner.jobs())).into_iter();
    let mut next = || runs.next().unwrap_or_else(|| Err("cancelled".into())).map_err(SolveError::Start);
    let (start_run, trajectory) = (next()?, next()?);
    let signals = signal_fits(model, (&start_run, model.shift(&start_values)), (&trajectory, model.shift(&values)));
    Ok(Outcome {
        parameters,
        uncertainty,
        iterations,
        signals,
        ending: solution.ending,
        runs: problem.runs.get() + 2,
        wall_seconds: started.elapsed().as_secs_f64(),
        trajectory,
        values,
    })
}

fn fitted(parameters: &[Parameter], point: &[f64], values: &[f64], uncertainty: &Uncertainty) -> Vec<Fitted> {
    parameters
        .iter()
        .zip(point)
        .zip(values)
        .zip(&uncertainty.standard_errors)
        .enumerate()
        .map(|(j, (((p, z), value), error))| {
            let correlated = uncertainty.correlated.standard_errors[j];
            let t = uncertainty.correlated.t_quantiles[j];
            Fitted {
                name: p.name.clone(),
                start: p.start,
                value: *value,
                standard_error: *error,
                interval: error.map(|e| (value - uncertainty.t_quantile * e, value + uncertainty.t_quantile * e)),
                correlated_standard_error: correlated,
                correlated_interval: correlated.map(|e| (value - t * e, value + t * e)),
                at_bound: *z <= 0.0 || *z >= 1.0,
            }
        })
        .collect()
}

fn signal_fits(model: &Model, start: (&Trajectory, f64), fitted: (&Trajectory, f64)) -> Vec<SignalFit> {
    let before = model.sample(start.0, start.1);
    let after = model.sample(fitted.0, fitted.1);
    let rms = |model: &[f64], measured: &[f64]| {
        (model.iter().zip(measured).map(|(m, y)| (m - y).powi(2)).sum::<f64>() / measured.len() as f64).sqrt()
    };
    model
        .signals
        .iter()
        .zip(before)
        .zip(after)
        .map(|((signal, before), after)| SignalFit {
            column: signal.column.clone(),
            unit: signal.unit,
            weight: signal.weight,
            samples: signal.times.len(),
            rms_start: rms(&before, &signal.measured),
            rms_fitted: rms(&after, &signal.measured),
            start: before,
            fitted: after,
        })
        .collect()
}
