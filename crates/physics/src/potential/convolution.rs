//! The radiation force by direct convolution (PHYSICS.md §9, Cummins' equation):
//! `F_r(t) = −∫_{max(0, t − t_K)}^{t} K(t − τ) q̇(τ) dτ` [N, N·m] over a history of `q̇` sampled at
//! the kernel's step, by the trapezoid rule: `O(t_K/Δt)` per evaluation and per pair. It is the
//! reference the state-space approximation (`super::state_space`) is tested against.

use super::coefficients::Vector6;
use super::kernel::SampledKernel;
use std::collections::VecDeque;

/// A body's radiation memory: its kernel and the velocities `q̇` it has seen, newest first.
#[derive(Debug, Clone)]
pub struct Convolution {
    kernel: SampledKernel,
    history: VecDeque<Vector6>,
}

impl Convolution {
    /// A memory with no history: the body at rest since `t = 0`.
    pub fn new(kernel: SampledKernel) -> Self {
        Self { history: VecDeque::with_capacity(kernel.values().len()), kernel }
    }

    /// Records `q̇(t_n)` (the samples are `Δt` apart, the kernel's step) and returns
    /// `F_r(t_n) = −Δt [½ K_0 q̇_n + Σ_{m=1}^{M−1} K_m q̇_{n−m} + ½ K_M q̇_{n−M}]`,
    /// `M = min(n, ⌊t_K/Δt⌋)` (nothing at `n = 0`).
    pub fn push(&mut self, velocity: Vector6) -> Vector6 {
        let kernel = self.kernel.values();
        if self.history.len() == kernel.len() {
            self.history.pop_back();
        }
        self.history.push_front(velocity);
        let last = self.history.len() - 1;
        if last == 0 {
            return Vector6::zeros(); // at t = 0 the interval is empty
        }
        let sum = self.history.iter().zip(kernel).enumerate().fold(Vector6::zeros(), |sum, (m, (v, k))| {
            let weight = if m == 0 || m == last { 0.5 } else { 1.0 };
            sum + k * v * weight
        });
        -sum * self.kernel.step()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::potential::coefficients::Matrix6;

    /// A constant kernel `K` and a constant velocity `v` since `t = 0`: `F = −K v min(t, t_K)`,
    /// which the trapezoid rule gives exactly.
    #[test]
    fn a_constant_kernel_integrates_the_velocity_exactly_and_forgets_after_t_k() {
        let k = Matrix6::identity() * 3.0;
        let mut memory = Convolution::new(SampledKernel::sample(0.1, 1.0, |_| k));
        let v = Vector6::new(1.0, 0.0, 2.0, 0.0, 0.0, -1.0);
        for n in 0..30 {
            let force = memory.push(v);
            let span = (n as f64 * 0.1).min(1.0);
            assert!((force + k * v * span).norm() < 1e-12, "n = {n}: {force}");
        }
    }
}
