//! The model side of a fit: the scene run with a set of parameter values, its signals sampled
//! at the record's times, and the weighted residuals `w_s (ŷ_s(t_i + τ) − y_s(t_i))`
//! (docs/calibration.md, "How a fit runs").
//!
//! A run builds the scene with the values by the scene loader (the sweep's way: the values
//! written into the scene's data at their paths), steps it to the last time compared, and keeps
//! every signal after every world step; the model's value at a record's time is the linear
//! interpolation between the two world steps around it. A run that diverges, a coupling that
//! refuses its forces, a value the loader refuses or a signal that is not finite is an `Err`
//! with its message: to the solver, a trial it cannot take.

use super::parameter::{Parameter, Target};
use crate::quantity::{Probe, Quantity, Readings};
use crate::runner::{Runner, Stop, Watch};
use serde_json::Value;
use std::path::PathBuf;
use tether_physics::world::World;
use tether_scene::{Scene, SceneFile};

/// One measured signal in the window, with the model quantity it is and its weight.
#[derive(Debug, Clone, PartialEq)]
pub struct Signal {
    pub column: String,
    pub quantity: Quantity,
    pub unit: &'static str,
    /// The residual's weight [1/unit].
    pub weight: f64,
    /// The record's samples in the window.
    pub times: Vec<f64>,
    pub measured: Vec<f64>,
}

/// The model of a fit: the scene, the parameters and the signals.
#[derive(Debug, Clone)]
pub struct Model {
    pub scene_path: PathBuf,
    pub scene_text: String,
    /// The scene's data, its duration set to cover the window.
    pub base: Value,
    pub parameters: Vec<Parameter>,
    pub signals: Vec<Signal>,
    /// Model time the runs end at \[s].
    pub end_time: f64,
}

/// Every signal of one run, at every world step.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    pub times: Vec<f64>,
    /// `signals.len()` values per time, time-major.
    pub values: Vec<f64>,
    pub signals: usize,
}

impl Model {
    /// The scene file with the parameters at `values` (the time shift sets none).
    ///
    /// # Errors
    /// The loader's reading of the data.
    pub fn scene_file(&self, values: &[f64]) -> Result<SceneFile, String> {
        let mut tree = self.base.clone();
        for (parameter, value) in self.parameters.iter().zip(values) {
            parameter.set(&mut tree, *value);
        }
        serde_json::from_value(tree).map_err(|e| e.to_string())
    }

    /// The scene with the parameters at `values`, built by the loader.
    ///
    /// # Errors
    /// What the loader refuses, placed in the scene's text.
    pub fn scene(&self, values: &[f64]) -> Result<Scene, String> {
        let file = self.scene_file(values)?;
        tether_scene::build_variant(&self.scene_text, &self.scene_path, file).map_err(|e| e.to_string())
    }

    /// The time shift among `values` (0 without one).
    pub fn shift(&self, values: &[f64]) -> f64 {
        self.parameters.iter().zip(values).find(|(p, _)| p.target == Target::TimeShift).map_or(0.0, |(_, v)| *v)
    }

    /// Runs the scene with `values` to [`Model::end_time`].
    ///
    /// # Errors
    /// A scene the loader refuses, a run that diverges or is refused, a signal not finite; the
    /// watch's stop.
    pub fn run(&self, values: &[f64], watch: &Watch<'_>) -> Result<Trajectory, String> {
        let scene = self.scene(values)?;
        self.run_world(scene.world, watch)
    }

    /// Runs `world` to [`Model::end_time`], keeping every signal after every world step.
    ///
    /// # Errors
    /// As [`Model::run`].
    fn run_world(&self, mut world: World, watch: &Watch<'_>) -> Result<Trajectory, String> {
        let probes = self
            .signals
            .iter()
            .map(|s| Probe::find(&world, &s.quantity).map_err(|m| format!("signal \"{}\": {m}", s.column)))
            .collect::<Result<Vec<_>, _>>()?;
        let mut readings = Readings::new(&world, &probes);
        let steps = (self.end_time / world.dt()).ceil() as usize + 1;
        let mut trajectory = Trajectory {
            times: Vec::with_capacity(steps + 1),
            values: Vec::with_capacity((steps + 1) * probes.len()),
            signals: probes.len(),
        };
        let mut take = |world: &World, readings: &mut Readings| -> Result<(), String> {
            readings.update(world);
            trajectory.times.push(world.time());
            for (probe, signal) in probes.iter().zip(&self.signals) {
                let value = readings.value(*probe, world);
                if !value.is_finite() {
                    return Err(format!("signal \"{}\" is {value} at t = {} s", signal.column, world.time()));
                }
                trajectory.values.push(value);
            }
            Ok(())
        };
        take(&world, &mut readings)?;
        let mut count = 0u64;
        while world.time() < self.end_time - 1e-9 * self.end_time.max(1.0) {
            world.step().map_err(|e| e.to_string())?;
            take(&world, &mut readings)?;
            count += 1;
            if count.is_multiple_of(64) {
                match watch.check() {
                    Ok(()) => {}
                    Err(Stop::Cancelled) => return Err("cancelled".into()),
                    Err(Stop::TimedOut) => {
                        return Err(format!("stopped by the run's time limit at t = {} s", world.time()));
                    }
                }
            }
        }
        Ok(trajectory)
    }

    /// The model's value of each signal at its record's times shifted by `shift`.
    pub fn sample(&self, trajectory: &Trajectory, shift: f64) -> Vec<Vec<f64>> {
        self.signals
            .iter()
            .enumerate()
            .map(|(s, signal)| signal.times.iter().map(|t| trajectory.at(s, t + shift)).collect())
            .collect()
    }

    /// The weighted residuals of `trajectory` (with the time shift `shift`), signal after signal.
    pub fn residuals(&self, trajectory: &Trajectory, shift: f64) -> Vec<f64> {
        self.sample(trajectory, shift)
            .iter()
            .zip(&self.signals)
            .flat_map(|(model, signal)| model.iter().zip(&signal.measured).map(move |(m, y)| signal.weight * (m - y)))
            .collect()
    }

    /// The runs at each parameter vector of `points`, in order, on `runner`'s threads; a run the
    /// runner stopped before it started (cancelled) is an `Err` saying so.
    pub fn runs(&self, points: &[&[f64]], runner: &Runner) -> Vec<Result<Trajectory, String>> {
        let mut runs: Vec<Option<Result<Trajectory, String>>> = vec![None; points.len()];
        let gathered = runner.run(
            0..points.len(),
            |&k, watch| self.run(points[k], watch),
            |k, run| {
                runs[k] = Some(run);
                Ok::<(), ()>(())
            },
        );
        debug_assert!(gathered.is_ok(), "the gathering closure never fails");
        runs.into_iter().map(|run| run.unwrap_or_else(|| Err("cancelled".into()))).collect()
    }

    /// The residuals at each parameter vector of `batch`, run on `runner`'s threads, and the
    /// number of runs: vectors that differ only in the time shift share one run.
    pub fn evaluate(&self, batch: &[Vec<f64>], runner: &Runner) -> (Vec<Result<Vec<f64>, String>>, usize) {
        let shift_index = self.parameters.iter().position(|p| p.target == Target::TimeShift);
        let physical = |values: &[f64]| -> Vec<u64> {
            values.iter().enumerate().filter(|(i, _)| Some(*i) != shift_index).map(|(_, v)| v.to_bits()).collect()
        };
        // Each distinct run's key and the first vector of the batch that asks for it.
        let mut distinct: Vec<(Vec<u64>, &[f64])> = Vec::new();
        let mut run_of: Vec<usize> = Vec::with_capacity(batch.len());
        for values in batch {
            let key = physical(values);
            let index = distinct.iter().position(|(k, _)| *k == key).unwrap_or_else(|| {
                distinct.push((key, values));
                distinct.len() - 1
            });
            run_of.push(index);
        }
        let points: Vec<&[f64]> = distinct.iter().map(|(_, values)| *values).collect();
        let trajectories = self.runs(&points, runner);
        let results = batch
            .iter()
            .zip(&run_of)
            .map(|(values, &r)| match &trajectories[r] {
                Ok(trajectory) => Ok(self.residuals(trajectory, self.shift(values))),
                Err(message) => Err(message.clone()),
            })
            .collect();
        (results, points.len())
    }
}

impl Trajectory {
    /// Signal `s` at time `t`, linear between the world steps around it (held at the ends).
    pub fn at(&self, s: usize, t: f64) -> f64 {
        let value = |k: usize| self.values[k * self.signals + s];
        let k = self.times.partition_point(|&x| x <= t);
        if k == 0 {
            return value(0);
        }
        if k >= self.times.len() {
            return value(self.times.len() - 1);
        }
        let (t0, t1) = (self.times[k - 1], self.times[k]);
        let f = (t - t0) / (t1 - t0);
        value(k - 1) + f * (value(k) - value(k - 1))
    }

    /// Signal `s` over the run.
    pub fn series(&self, s: usize) -> Vec<f64> {
        self.values.iter().skip(s).step_by(self.signals.max(1)).copied().collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_between_steps_and_holds_at_the_ends() {
        let trajectory =
            Trajectory { times: vec![0.0, 1.0, 2.0], values: vec![0.0, 10.0, 2.0, 20.0, 4.0, 40.0], signals: 2 };
        assert_eq!(trajectory.at(0, 0.5), 1.0);
        assert_eq!(trajectory.at(1, 1.5), 30.0);
        assert_eq!(trajectory.at(0, 1.0), 2.0);
        assert_eq!(trajectory.at(0, -1.0), 0.0);
        assert_eq!(trajectory.at(1, 3.0), 40.0);
        assert_eq!(trajectory.series(1), vec![10.0, 20.0, 40.0]);
    }
}
