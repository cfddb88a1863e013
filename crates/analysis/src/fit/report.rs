//! A fit's result for people (a table of the fitted values with their intervals, the
//! correlations, the undetermined combinations, each signal's RMS before and after) and for
//! programs (`--json`: all of it, the iterations too).

use super::model::Model;
use super::run::Outcome;
use serde_json::{Value, json};
use std::fmt::Write as _;

/// The undetermined direction `v` over the parameters' relative changes, as people read it:
/// `+0.71 δk1/k1 − 0.71 δk2/k2`.
pub fn combination(model: &Model, direction: &[f64]) -> String {
    let mut text = String::new();
    for (p, c) in model.parameters.iter().zip(direction) {
        if c.abs() < 0.005 {
            continue;
        }
        let sign = if *c < 0.0 { "−" } else { "+" };
        let _ = write!(text, "{}{sign}{:.2} δ{}/{}", if text.is_empty() { "" } else { " " }, c.abs(), p.name, p.name);
    }
    text
}

/// The table of the fit, as `tether fit` prints it.
pub fn text(model: &Model, outcome: &Outcome) -> String {
    let mut out = String::new();
    let state = if outcome.partial() {
        format!("PARTIAL ({}): the best point so far", ending_text(outcome))
    } else {
        format!("converged ({})", ending_text(outcome))
    };
    let _ = writeln!(
        out,
        "fit {state}: {} iterations, {} model runs, {:.2} s wall",
        outcome.iterations.last().map_or(0, |i| i.iteration),
        outcome.runs,
        outcome.wall_seconds
    );
    let first = outcome.iterations.first().map_or(f64::NAN, |i| i.cost);
    let last = outcome.iterations.last().map_or(f64::NAN, |i| i.cost);
    let _ = writeln!(out, "cost ½‖r‖²: {first:.6e} → {last:.6e}");
    let _ = writeln!(out, "\n| parameter | start | fitted | 95 % interval | ± | 95 % if correlated | ± |");
    let _ = writeln!(out, "|---|---|---|---|---|---|---|");
    let cells = |interval: Option<(f64, f64)>, value: f64| match interval {
        Some((lo, hi)) => (
            format!("{} … {}", number(lo), number(hi)),
            if value != 0.0 { format!("{:.3} %", 100.0 * (hi - value) / value.abs()) } else { "–".into() },
        ),
        None => ("not determined by the data".into(), "–".into()),
    };
    for p in &outcome.parameters {
        let (interval, relative) = cells(p.interval, p.value);
        let (correlated, correlated_relative) = match p.interval {
            Some(_) => cells(p.correlated_interval, p.value),
            None => ("–".into(), "–".into()),
        };
        let bound = if p.at_bound { " (at its bound)" } else { "" };
        let _ = writeln!(
            out,
            "| {} | {} | {}{bound} | {interval} | {relative} | {correlated} | {correlated_relative} |",
            p.name,
            number(p.start),
            number(p.value)
        );
    }
    if outcome.parameters.len() > 1 {
        let _ = writeln!(out, "\ncorrelations:");
        for (i, p) in outcome.parameters.iter().enumerate() {
            let row: Vec<String> = (0..outcome.parameters.len())
                .map(|j| {
                    let r = outcome.uncertainty.correlation[(i, j)];
                    if r.is_nan() { "    –".into() } else { format!("{r:+.3}") }
                })
                .collect();
            let _ = writeln!(out, "  {:<32} {}", p.name, row.join("  "));
        }
    }
    for direction in &outcome.uncertainty.undetermined {
        let _ = writeln!(
            out,
            "\nnot identifiable: the data do not determine {} (relative changes; a change along it leaves the fit within its noise); only the combinations orthogonal to it are determined",
            combination(model, direction)
        );
    }
    let u = &outcome.uncertainty;
    let _ = writeln!(
        out,
        "\nresidual σ (weighted) {:.4e} over {} degrees of freedom; lag-1 autocorrelation of the residuals {:.3}{}",
        u.variance.sqrt() / u.inflation,
        u.degrees_of_freedom,
        u.autocorrelation,
        if u.inflation > 1.05 {
            format!(
                " (correlated: the residual is partly model error, not noise alone; the intervals are widened ×{:.2} for it)",
                u.inflation
            )
        } else {
            String::new()
        }
    );
    let windows: Vec<String> = u
        .correlated
        .bandwidths
        .iter()
        .zip(&outcome.signals)
        .map(|(l, s)| format!("{} of {} samples", number(l.round()), s.samples))
        .collect();
    let mut freedom: Vec<String> =
        u.correlated.degrees_of_freedom.iter().filter(|nu| nu.is_finite()).map(|nu| format!("{nu:.0}")).collect();
    freedom.dedup();
    let _ = writeln!(
        out,
        "\"if correlated\": the interval if the residual is model error, correlated as its own autocorrelation says (a sandwich covariance over a Bartlett lag window of {}; t at {} degrees of freedom); the first takes the residual as white noise{}",
        windows.join(", "),
        if freedom.is_empty() { "–".into() } else { freedom.join(", ") },
        if u.inflation > 1.05 { ", widened for its lag-1 autocorrelation" } else { "" }
    );
    let _ = writeln!(out, "\n| signal | samples | weight | RMS at start | RMS fitted |");
    let _ = writeln!(out, "|---|---|---|---|---|");
    for s in &outcome.signals {
        let _ = writeln!(
            out,
            "| {} | {} | {} /{} | {} {} | {} {} |",
            s.column,
            s.samples,
            number(s.weight),
            s.unit,
            number(s.rms_start),
            s.unit,
            number(s.rms_fitted),
            s.unit
        );
    }
    out
}

fn ending_text(outcome: &Outcome) -> &'static str {
    use super::solver::Ending;
    match outcome.ending {
        Ending::CostConverged => "the cost stopped falling",
        Ending::StepConverged => "the step vanished",
        Ending::WithinNoise => "the next step is under a tenth of a standard error",
        Ending::GradientConverged => "the gradient vanished",
        Ending::IterationLimit => "out of iterations",
        Ending::Cancelled => "stopped by Ctrl-C",
    }
}

/// A number with 6 significant digits.
pub fn number(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor();
    if (-3.0..6.0).contains(&magnitude) {
        let decimals = (5.0 - magnitude).max(0.0) as usize;
        let text = format!("{x:.decimals$}");
        if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.').to_string() } else { text }
    } else {
        format!("{x:.5e}")
    }
}

/// Everything, for `--json`.
pub fn json(model: &Model, outcome: &Outcome, files: &[(String, String)]) -> Value {
    let n = outcome.parameters.len();
    let correlation: Vec<Vec<Value>> =
        (0..n).map(|i| (0..n).map(|j| finite(outcome.uncertainty.correlation[(i, j)])).collect()).collect();
    json!({
        "status": if outcome.partial() { "partial" } else { "converged" },
        "ending": outcome.ending,
        "parameters": outcome.parameters.iter().map(|p| json!({
            "name": p.name,
            "start": p.start,
            "value": p.value,
            "standard_error": p.standard_error,
            "interval_95": p.interval.map(|(lo, hi)| [lo, hi]),
            "standard_error_correlated": p.correlated_standard_error,
            "interval_95_correlated": p.correlated_interval.map(|(lo, hi)| [lo, hi]),
            "determined": p.standard_error.is_some(),
            "at_bound": p.at_bound,
        })).collect::<Vec<_>>(),
        "correlation": correlation,
        "undetermined": outcome.uncertainty.undetermined.iter().map(|d| json!({
            "relative_direction": d,
            "reads": combination(model, d),
        })).collect::<Vec<_>>(),
        "residual_sigma": outcome.uncertainty.variance.sqrt() / outcome.uncertainty.inflation,
        "degrees_of_freedom": outcome.uncertainty.degrees_of_freedom,
        "t_quantile_975": outcome.uncertainty.t_quantile,
        "residual_lag1_autocorrelation": outcome.uncertainty.autocorrelation,
        "interval_widening": outcome.uncertainty.inflation,
        "correlated": json!({
            "bandwidth_samples": outcome.uncertainty.correlated.bandwidths,
            "degrees_of_freedom": outcome.uncertainty.correlated.degrees_of_freedom.iter().map(|nu| finite(*nu)).collect::<Vec<_>>(),
            "t_quantile_975": outcome.uncertainty.correlated.t_quantiles.iter().map(|t| finite(*t)).collect::<Vec<_>>(),
        }),
        "iterations": outcome.iterations.iter().map(|i| json!({
            "iteration": i.iteration,
            "cost": i.cost,
            "values": i.values,
            "accepted": i.accepted,
            "refused": i.refused,
            "runs": i.runs,
        })).collect::<Vec<_>>(),
        "signals": outcome.signals.iter().map(|s| json!({
            "column": s.column,
            "unit": s.unit,
            "weight": s.weight,
            "samples": s.samples,
            "rms_start": s.rms_start,
            "rms_fitted": s.rms_fitted,
        })).collect::<Vec<_>>(),
        "runs": outcome.runs,
        "wall_seconds": outcome.wall_seconds,
        "files": files.iter().map(|(what, path)| json!({"what": what, "path": path})).collect::<Vec<_>>(),
    })
}

/// A JSON number, or null for NaN.
fn finite(x: f64) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn numbers_for_people() {
        assert_eq!(number(100.0), "100");
        assert_eq!(number(0.0123456789), "0.0123457");
        assert_eq!(number(2.4), "2.4");
        assert_eq!(number(1.234e7), "1.23400e7");
        assert_eq!(number(-0.5), "-0.5");
    }
}
