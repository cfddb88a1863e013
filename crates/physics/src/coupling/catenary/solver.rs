//! Solves the catenary's closure equations for the end forces, in every regime.
//!
//! 1. Exactly vertical (`X = 0`): closed forms — taut with end 1 below, taut with end 1 above,
//!    or slack and folded, each end carrying the weight of the part hanging from it.
//! 2. Otherwise a damped Newton iteration on `(ln h, v)` (so `h` stays positive) with a
//!    backtracking line search, from the previous solution (warm) or from a closed-form guess
//!    (the straight elastic line when taut, Peyrot & Goulois' estimate when slack), whichever
//!    fits the ends better.
//! 3. Should Newton stall, a bracketed solve that cannot fail: `Y` increases strictly with `v`
//!    at fixed `h`, and `X` increases strictly with `h` along `Y = Y*` (`dX/dh = det J / Y_v`,
//!    with `J` symmetric positive definite), so nested safeguarded root-finding converges.

use super::equations::{Closure, Evaluation, span};

/// Dimensionless unknowns: `h = H/W`, `v = V1/W`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unknowns {
    pub h: f64,
    pub v: f64,
}

/// A converged solve.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solved {
    pub unknowns: Unknowns,
    /// Newton iterations taken (0 for a closed form).
    pub iterations: u32,
    /// `max(|X − X*|, |Y − Y*|)`, dimensionless (a fraction of `L_eq`).
    pub residual: f64,
}

/// Residual below which a solve has converged (dimensionless, a fraction of `L_eq`).
pub const TOLERANCE: f64 = 1e-12;
const MAX_NEWTON: u32 = 40;

/// Solves `closure` from the optional `warm` start. `None` only for non-finite input.
pub fn solve(closure: &Closure, warm: Option<Unknowns>) -> Option<Solved> {
    if !(closure.x.is_finite() && closure.y.is_finite() && closure.epsilon.is_finite() && closure.epsilon > 0.0) {
        return None;
    }
    if closure.x <= 0.0 {
        return Some(vertical(closure));
    }
    // The closed-form guess costs one evaluation: start from whichever of it and the warm start
    // fits the ends better (after a jump, e.g. a line pulled taut, the guess is far better).
    let guess = cold_guess(closure);
    let guessed = closure.evaluate(guess.h, guess.v);
    let start = match warm.filter(|w| w.h > 0.0 && w.h.is_finite() && w.v.is_finite()) {
        Some(w) => {
            let warmed = closure.evaluate(w.h, w.v);
            if max_abs(warmed.residual) < max_abs(guessed.residual) { (w, warmed) } else { (guess, guessed) }
        }
        None => (guess, guessed),
    };
    newton(closure, start.0, start.1).or_else(|| Some(bracketed(closure)))
}

fn max_abs(r: [f64; 2]) -> f64 {
    r[0].abs().max(r[1].abs())
}

/// Closed forms at `X = 0` (`h = 0`): `Y = |v+1| − |v| + ε(v + ½)`.
fn vertical(closure: &Closure) -> Solved {
    let (y, eps) = (closure.y, closure.epsilon);
    let v = if y >= 1.0 + 0.5 * eps {
        // Taut, end 2 above: the whole line hangs from end 2 and is stretched.
        (y - 1.0) / eps - 0.5
    } else if y <= -1.0 - 0.5 * eps {
        // Taut, end 2 below.
        (y + 1.0) / eps - 0.5
    } else {
        // Slack and folded: Y = (2v + 1)(1 + ε/2).
        0.5 * (y / (1.0 + 0.5 * eps) - 1.0)
    };
    let unknowns = Unknowns { h: 0.0, v };
    Solved { unknowns, iterations: 0, residual: residual_norm(closure, unknowns) }
}

fn residual_norm(closure: &Closure, u: Unknowns) -> f64 {
    let [x, y] = closure.ends(u.h, u.v);
    (x - closure.x).abs().max((y - closure.y).abs())
}

/// A starting point from closed forms: the straight elastic line when the chord is longer than
/// `L_eq`; otherwise Peyrot & Goulois' estimate `λ = √(3((L² − Δy²)/Δx² − 1))`,
/// `H = wΔx/(2λ)`, `V2 = (w/2)(Δy/tanh λ + L)`.
pub fn cold_guess(closure: &Closure) -> Unknowns {
    let (x, y, eps) = (closure.x, closure.y, closure.epsilon);
    let chord = x.hypot(y);
    if chord >= 1.0 {
        // Tension of the straight line (dimensionless), at least the weight's order.
        let tension = ((chord - 1.0) / eps).max(0.5);
        return Unknowns { h: tension * x / chord, v: tension * y / chord - 0.5 };
    }
    let lambda = (3.0 * ((1.0 - y * y) / (x * x) - 1.0)).max(0.0).sqrt().clamp(0.2, 700.0);
    Unknowns { h: x / (2.0 * lambda), v: 0.5 * (y / lambda.tanh() - 1.0) }
}

/// Damped Newton on `(ln h, v)` from `start`, whose evaluation is `evaluation`; `None` if it
/// does not converge.
fn newton(closure: &Closure, start: Unknowns, mut evaluation: Evaluation) -> Option<Solved> {
    let (mut log_h, mut v) = (start.h.ln(), start.v);
    let mut merit = norm2(evaluation.residual);
    for iteration in 0..MAX_NEWTON {
        let h = log_h.exp();
        let residual = max_abs(evaluation.residual);
        if residual <= TOLERANCE {
            return Some(Solved { unknowns: Unknowns { h, v }, iterations: iteration, residual });
        }
        // Columns for ln h are h × the columns for h.
        let j = evaluation.jacobian;
        let (a, b, c, d) = (j[0][0] * h, j[0][1], j[1][0] * h, j[1][1]);
        let det = a * d - b * c;
        if !(det.abs() > 0.0) || !det.is_finite() {
            return None;
        }
        let [rx, ry] = evaluation.residual;
        let mut step_log_h = -(d * rx - b * ry) / det;
        let mut step_v = -(a * ry - c * rx) / det;
        // No more than a factor e² on h per iteration keeps exp() in range.
        let limit = (2.0 / step_log_h.abs()).min(1.0);
        step_log_h *= limit;
        step_v *= limit;
        let mut scale = 1.0;
        // Ends: `scale` halves each refused pass, and below 1e-10 the solve gives up.
        loop {
            let (trial_log_h, trial_v) = (log_h + scale * step_log_h, v + scale * step_v);
            let trial = closure.evaluate(trial_log_h.exp(), trial_v);
            let trial_merit = norm2(trial.residual);
            // Armijo's sufficient decrease; a step cut to the e² limit, or already short, needs
            // only some decrease (the residual can be flat in ln h until the stretch takes over).
            let short = limit < 1.0 || scale < 1e-3;
            if trial_merit <= (1.0 - 1e-4 * scale) * merit || (short && trial_merit < merit) {
                log_h = trial_log_h;
                v = trial_v;
                evaluation = trial;
                merit = trial_merit;
                break;
            }
            scale *= 0.5;
            if scale < 1e-10 {
                return None;
            }
        }
    }
    None
}

fn norm2(r: [f64; 2]) -> f64 {
    r[0] * r[0] + r[1] * r[1]
}

/// The solve that cannot fail: `v(h)` from `Y` (monotone in v) inside a monotone solve of `X`
/// in `ln h`, both by bisection safeguarded with secant steps, to full precision.
fn bracketed(closure: &Closure) -> Solved {
    let v_of = |h: f64| -> f64 {
        let f = |v: f64| closure.ends(h, v)[1] - closure.y;
        monotone_root(f, -0.5)
    };
    let g = |log_h: f64| -> f64 {
        let h = log_h.exp();
        span(h, v_of(h), v_of(h) + 1.0) + closure.epsilon * h - closure.x
    };
    let log_h = monotone_root(g, cold_guess(closure).h.ln());
    let h = log_h.exp();
    let unknowns = Unknowns { h, v: v_of(h) };
    Solved { unknowns, iterations: MAX_NEWTON, residual: residual_norm(closure, unknowns) }
}

/// Root of an increasing function `f`, bracketed outward from `guess`, then bisected with
/// secant steps to the last bit.
fn monotone_root(f: impl Fn(f64) -> f64, guess: f64) -> f64 {
    let f0 = f(guess);
    if f0 == 0.0 {
        return guess;
    }
    // Expand the bracket geometrically on the side where the root lies.
    let direction = if f0 < 0.0 { 1.0 } else { -1.0 };
    let (mut near, mut far) = (guess, guess);
    let mut width = 1.0;
    for _ in 0..2000 {
        far = near + direction * width;
        if f(far).signum() != f0.signum() {
            break;
        }
        near = far;
        width *= 2.0;
    }
    let (mut lo, mut hi) = if direction > 0.0 { (near, far) } else { (far, near) };
    let (mut f_lo, mut f_hi) = (f(lo), f(hi));
    for _ in 0..200 {
        let secant = lo - f_lo * (hi - lo) / (f_hi - f_lo);
        let mid = 0.5 * (lo + hi);
        // Secant where it stays well inside the bracket, else bisection.
        let x = if secant.is_finite() && secant > lo + 0.1 * (hi - lo) && secant < hi - 0.1 * (hi - lo) {
            secant
        } else {
            mid
        };
        if x <= lo || x >= hi {
            break;
        }
        let fx = f(x);
        if fx == 0.0 {
            return x;
        }
        if fx < 0.0 {
            lo = x;
            f_lo = fx;
        } else {
            hi = x;
            f_hi = fx;
        }
    }
    if f_lo.abs() < f_hi.abs() { lo } else { hi }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn vertical_closed_forms() {
        let eps = 0.01;
        // Taut: end 2 is 1.1 L above end 1, so the line stretches by 0.1 L under its mean tension.
        let taut = solve(&Closure { x: 0.0, y: 1.1, epsilon: eps }, None).unwrap();
        assert_relative_eq!(taut.unknowns.v, 0.1 / eps - 0.5, max_relative = 1e-14);
        // Folded, ends level: each end carries half the weight.
        let folded = solve(&Closure { x: 0.0, y: 0.0, epsilon: eps }, None).unwrap();
        assert_relative_eq!(folded.unknowns.v, -0.5);
        assert!(taut.residual < 1e-14 && folded.residual < 1e-14);
    }

    #[test]
    fn the_bracketed_solve_agrees_with_newton() {
        for &(x, y, eps) in &[(0.8_f64, 0.1_f64, 1e-3_f64), (0.3, -0.6, 0.1), (1.05, 0.2, 1e-2), (0.01, 0.5, 1e-4)] {
            let closure = Closure { x, y, epsilon: eps };
            let newton = solve(&closure, None).unwrap();
            let safe = bracketed(&closure);
            assert!(safe.residual < 1e-12, "{closure:?}: {safe:?}");
            assert_relative_eq!(safe.unknowns.h, newton.unknowns.h, max_relative = 1e-9);
            assert_relative_eq!(safe.unknowns.v, newton.unknowns.v, max_relative = 1e-9, epsilon = 1e-12);
        }
    }
}
