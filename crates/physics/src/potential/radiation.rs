//! A body's radiation memory in the time domain (PHYSICS.md §9, "Radiation memory in the
//! integrators"): `F_r(t) = −∫₀ᵗ K(t − τ) q̇(τ) dτ` [N, N·m] at any evaluation an integrator
//! asks for, by the fitted state space or by the direct convolution (the reference).
//!
//! The memory keeps what it was at the last *accepted* step (`t_c`, `q̇_c`, and the states or the
//! history of `q̇`). An evaluation at `t ≥ t_c` with velocity `q̇` starts again from it, `q̇`
//! taken linear from `q̇_c` to `q̇` over `[t_c, t]`: the states advanced exactly
//! ([`RadiationStateSpace::advance`]), or the convolution summed by the trapezoid rule over the
//! accepted samples and this one. A Runge–Kutta stage or a rejected adaptive step therefore
//! leaves no trace; the world commits the last evaluation when it accepts a step
//! ([`RadiationRun::commit`]), as it does for the dynamic lines.

use super::coefficients::Vector6;
use super::kernel::SampledKernel;
use super::state_space::RadiationStateSpace;
use std::collections::VecDeque;

/// How the radiation force is evaluated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RadiationMethod {
    /// The state space fitted to `K(t)`: `O(states)` per evaluation.
    #[default]
    StateSpace,
    /// The direct convolution over the history of `q̇`: `O(t_K/Δt)` per evaluation and pair, the
    /// reference the state space is tested against.
    Convolution,
}

/// A body's radiation model, built once.
#[derive(Debug, Clone, PartialEq)]
pub enum Radiation {
    StateSpace(RadiationStateSpace),
    Convolution(SampledKernel),
}

/// The memory at one instant: time \[s], `q̇` \[m/s, rad/s], the states (state space only).
#[derive(Debug, Clone, PartialEq, Default)]
struct Sample {
    time: f64,
    velocity: Vector6,
    states: Vec<f64>,
}

/// A body's radiation memory over a run (kept with the evaluation's buffers).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RadiationRun {
    /// At the last accepted step (`None` before the first evaluation: the body at rest before).
    committed: Option<Sample>,
    /// At the last evaluation.
    current: Sample,
    /// Convolution: the accepted `(t, q̇)` within `t_K` of the last, oldest first.
    history: VecDeque<(f64, Vector6)>,
}

impl RadiationRun {
    /// `F_r` at time `time` \[s] for the velocity `velocity` of the reference point (see the
    /// module docs); kept as the current sample.
    pub fn force(&mut self, radiation: &Radiation, time: f64, velocity: &Vector6) -> Vector6 {
        let committed = self.committed.get_or_insert_with(|| Sample {
            time,
            velocity: Vector6::zeros(),
            states: vec![0.0; state_count(radiation)],
        });
        let h = (time - committed.time).max(0.0);
        self.current.time = time;
        self.current.velocity = *velocity;
        match radiation {
            Radiation::StateSpace(model) => {
                self.current.states.resize(committed.states.len(), 0.0);
                model.advance(&committed.states, &committed.velocity, velocity, h, &mut self.current.states);
                model.force(&self.current.states)
            }
            Radiation::Convolution(kernel) => -convolve(kernel, &self.history, time, velocity),
        }
    }

    /// Keeps the last evaluation as the start of the next interval (the world calls it when it
    /// accepts an integrator step).
    pub fn commit(&mut self, radiation: &Radiation) {
        let Some(committed) = &mut self.committed else { return };
        committed.clone_from(&self.current);
        if let Radiation::Convolution(kernel) = radiation {
            if self.history.back().is_some_and(|(t, _)| *t >= committed.time) {
                self.history.pop_back(); // the same instant evaluated again: keep the last
            }
            self.history.push_back((committed.time, committed.velocity));
            let horizon = kernel.duration() + kernel.step();
            while self.history.len() > 1 && self.history[1].0 < committed.time - horizon {
                self.history.pop_front();
            }
        }
    }
}

/// The number of states of `radiation` (none for the convolution).
fn state_count(radiation: &Radiation) -> usize {
    match radiation {
        Radiation::StateSpace(model) => model.state_count(),
        Radiation::Convolution(_) => 0,
    }
}

/// `∫ K(t − τ) q̇(τ) dτ` over the samples of `history` followed by `(t, q̇)`: on each interval
/// `[τ_a, τ_b]` the trapezoid `½ (τ_b − τ_a) (K(t − τ_a) q̇_a + K(t − τ_b) q̇_b)`, `K` linear
/// between its samples and 0 beyond `t_K`; before the first sample the body was at rest.
fn convolve(kernel: &SampledKernel, history: &VecDeque<(f64, Vector6)>, time: f64, velocity: &Vector6) -> Vector6 {
    let mut sum = Vector6::zeros();
    let mut next = (time, kernel.at(0.0) * velocity);
    for (tau, v) in history.iter().rev() {
        let weighted = kernel.at(time - tau) * v;
        sum += (next.1 + weighted) * (0.5 * (next.0 - tau));
        next = (*tau, weighted);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::potential::coefficients::Matrix6;
    use crate::potential::state_space::FitSettings;

    /// `K(t) = k e^{−t/τ}` (one real pole) and `q̇ = v` constant from t = 0: `F = −k τ v (1 −
    /// e^{−t/τ})`; both methods, evaluated at stages that are then thrown away, give it (the
    /// state space to round-off, the convolution to its trapezoid rule's `(Δt/τ)²/12`).
    #[test]
    fn both_methods_give_the_closed_form_and_forget_uncommitted_evaluations() {
        let (k, tau) = (2.0e3, 1.5);
        let kernel = SampledKernel::sample(0.01, 20.0, |t| Matrix6::identity() * k * (-t / tau).exp());
        let fit = RadiationStateSpace::fit(&kernel, 2.0, FitSettings::new(1e-5, 4).expect("valid")).expect("one pole");
        let v = Vector6::new(0.5, 0.0, -1.0, 0.0, 0.02, 0.0);
        for radiation in [Radiation::StateSpace(fit), Radiation::Convolution(kernel)] {
            let mut run = RadiationRun::default();
            run.force(&radiation, 0.0, &v);
            run.commit(&radiation);
            let dt = 0.01;
            for n in 1..=500 {
                let t = n as f64 * dt;
                // A stage that a rejected step leaves behind: a wild velocity, never committed.
                run.force(&radiation, t - 0.5 * dt, &(v * 100.0));
                let force = run.force(&radiation, t, &v);
                run.commit(&radiation);
                let exact = -v * (k * tau * (1.0 - (-t / tau).exp()));
                let error = (force - exact).norm() / exact.norm();
                assert!(error < 1e-5, "{radiation:?} t = {t}: {force} vs {exact}");
            }
        }
    }
}
