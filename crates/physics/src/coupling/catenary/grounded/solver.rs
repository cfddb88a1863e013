//! Solves the grounded line's closure `X(h) = x` ([`super::profile`]) for the horizontal
//! tension `h`, in every regime, never failing for finite input.
//!
//! 1. Heaped: when even `h = 0` (both parts hanging vertically, the grounded part straight and
//!    unstrained) spans more than `x`, the grounded part lies slack: `h = 0` exactly.
//! 2. Lifted: when the two parts hanging vertically already use up the whole line, or `X` at
//!    the `h` where `ℓ_B` reaches 0 is still short of `x`, the line does not reach the bottom:
//!    the free catenary holds (PHYSICS.md §3), continuously across the lift-off.
//! 3. Otherwise Newton's method on `t = ln h` (so `h` stays positive), from the warm start or
//!    the parabolic estimate `h ≈ (2 z2)³/(36 (1 − x)²)`, safeguarded by the bracket it keeps:
//!    `X` increases with `h`, so every evaluation moves one side of the bracket; a Newton step
//!    that leaves it, or lands where the line cannot reach the bottom (`ℓ_B < 0`), is replaced
//!    by bisection. It stops when the Newton correction falls below [`STEP_TOLERANCE`] in
//!    `ln h`: with quadratic convergence the tension is then exact to round-off.

use super::profile::{Grounding, Profile};

/// A Newton correction of `ln h` below this ends the solve (relative precision of `h`).
pub const STEP_TOLERANCE: f64 = 1e-12;
/// Newton steps change `h` by at most a factor `e²` each.
const MAX_STEP: f64 = 2.0;
/// Evaluations before the bisection alone has certainly collapsed the bracket.
const MAX_ITERATIONS: u32 = 200;

/// What the solve found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outcome {
    /// The line lies on the bottom with this profile.
    Grounded(Solved),
    /// The line does not reach the bottom: it hangs freely.
    Lifted,
}

/// A converged grounded solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solved {
    pub profile: Profile,
    /// Evaluations after the first (0 for a heaped line).
    pub iterations: u32,
    /// `|X(h) − x|`, dimensionless (a fraction of `L_eq`).
    pub residual: f64,
}

/// Solves `grounding` from the optional warm start `warm` (a previous `h`). `None` only for
/// non-finite or meaningless input (ε ≤ 0, a negative height or friction).
pub fn solve(grounding: &Grounding, warm: Option<f64>) -> Option<Outcome> {
    let Grounding { x, z1, z2, epsilon, friction } = *grounding;
    let finite = [x, z1, z2, epsilon, friction].iter().all(|v| v.is_finite());
    if !(finite && epsilon > 0.0 && z1 >= 0.0 && z2 >= 0.0 && friction >= 0.0 && x >= 0.0) {
        return None;
    }
    let hanging = grounding.profile(0.0);
    if hanging.grounded <= 0.0 {
        return Some(Outcome::Lifted);
    }
    if x <= hanging.closure {
        let residual = 0.0;
        return Some(Outcome::Grounded(Solved { profile: hanging, iterations: 0, residual }));
    }
    let start = warm.filter(|h| *h > 0.0 && h.is_finite()).unwrap_or_else(|| guess(grounding));
    Some(bracketed_newton(grounding, start.ln()))
}

/// The parabolic estimate of a line grounded at its anchor: `X ≈ 1 − (2 z2)^{3/2}/(6 √h)`; for
/// a span beyond the line's length, the tension that stretches it there.
fn guess(grounding: &Grounding) -> f64 {
    let Grounding { x, z2, epsilon, .. } = *grounding;
    if x < 1.0 {
        let lift = 2.0 * z2.max(1e-6);
        (lift * lift * lift / (36.0 * (1.0 - x) * (1.0 - x))).max(1e-6)
    } else {
        (x - 1.0) / epsilon + 1.0
    }
}

/// One side of the bracket in `t = ln h`.
#[derive(Debug, Clone, Copy)]
struct Side {
    t: f64,
    /// The side above the root because the line cannot reach the bottom there (`ℓ_B < 0`).
    unreachable: bool,
}

fn bracketed_newton(grounding: &Grounding, mut t: f64) -> Outcome {
    let (mut low, mut high): (Option<Side>, Option<Side>) = (None, None);
    let mut best: Option<Solved> = None;
    for iteration in 0..MAX_ITERATIONS {
        let h = t.exp();
        let profile = grounding.profile(h);
        let next = if profile.grounded < 0.0 {
            high = Some(Side { t, unreachable: true });
            None
        } else {
            let residual = profile.closure - grounding.x;
            let solved = Solved { profile, iterations: iteration, residual: residual.abs() };
            if residual == 0.0 {
                return Outcome::Grounded(solved);
            }
            if residual < 0.0 {
                low = Some(Side { t, unreachable: false });
                best = Some(solved);
            } else {
                high = Some(Side { t, unreachable: false });
                best = Some(solved);
            }
            let step = -residual / (h * profile.closure_h);
            if step.abs() <= STEP_TOLERANCE {
                return Outcome::Grounded(solved);
            }
            step.is_finite().then(|| t + step.clamp(-MAX_STEP, MAX_STEP))
        };
        t = match (low, high, next) {
            (Some(lo), Some(hi), Some(candidate)) if candidate > lo.t && candidate < hi.t => candidate,
            (Some(lo), Some(hi), _) => {
                if hi.t - lo.t <= STEP_TOLERANCE * lo.t.abs().max(1.0) {
                    return collapsed(hi, best);
                }
                0.5 * (lo.t + hi.t)
            }
            (None, _, Some(candidate)) | (_, None, Some(candidate)) => candidate,
            // No Newton step: expand toward the side not yet found.
            (None, _, None) => t - MAX_STEP,
            (_, None, None) => t + MAX_STEP,
        };
    }
    match (low, high) {
        (Some(_), Some(hi)) => collapsed(hi, best),
        _ => best.map_or(Outcome::Lifted, Outcome::Grounded),
    }
}

/// The bracket has closed on the root: on a lift-off if its high side is where the line no
/// longer reaches the bottom, else at the best point found.
fn collapsed(high: Side, best: Option<Solved>) -> Outcome {
    if high.unreachable {
        return Outcome::Lifted;
    }
    best.map_or(Outcome::Lifted, Outcome::Grounded)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn grounded(outcome: Option<Outcome>) -> Solved {
        match outcome {
            Some(Outcome::Grounded(solved)) => solved,
            other => panic!("expected a grounded line, got {other:?}"),
        }
    }

    #[test]
    fn warm_and_cold_starts_agree() {
        let g = Grounding { x: 0.8, z1: 0.0, z2: 0.4, epsilon: 800.0 * 500.0 / 7.51e12, friction: 0.0 };
        let cold = grounded(solve(&g, None));
        let warm = grounded(solve(&g, Some(cold.profile.h * 1.02)));
        // Each stops within STEP_TOLERANCE (1e-12) of the root in ln h.
        assert_relative_eq!(cold.profile.h, warm.profile.h, max_relative = 3e-12);
        // Quadratic convergence from 2 % off: corrections 2e-2, 4e-4, 2e-7, 4e-14 in ln h.
        assert!(warm.iterations <= 3, "{} iterations", warm.iterations);
    }

    #[test]
    fn a_heap_and_a_lifted_line() {
        // Ends 0.3 apart, the anchor on the bottom, the other end 0.2 up: 0.8 hangs or lies.
        let heap = grounded(solve(&Grounding { x: 0.3, z1: 0.0, z2: 0.2, epsilon: 1e-4, friction: 1.0 }, None));
        assert_eq!(heap.profile.h, 0.0);
        assert!(matches!(
            solve(&Grounding { x: 0.95, z1: 0.0, z2: 0.4, epsilon: 1e-4, friction: 0.0 }, None),
            Some(Outcome::Lifted)
        ));
        assert!(matches!(
            solve(&Grounding { x: 0.1, z1: 0.5, z2: 0.6, epsilon: 1e-4, friction: 0.0 }, None),
            Some(Outcome::Lifted)
        ));
        assert!(solve(&Grounding { x: f64::NAN, z1: 0.0, z2: 0.1, epsilon: 1e-4, friction: 0.0 }, None).is_none());
    }
}
