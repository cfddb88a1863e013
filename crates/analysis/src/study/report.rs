//! The study's tables: CSV for tools, Markdown for people (also what `tether study` prints).

use super::{Measures, Outcome, Run, Setting, Study};
use std::fmt::Write as _;

/// The step column: `dt 1.0e-3 s` or `rtol 1e-6`.
fn setting(run: &Run) -> String {
    match run.setting {
        Setting::Step(dt) => format!("dt {dt:.1e} s"),
        Setting::Tolerance(rtol) => format!("rtol {rtol:.0e}"),
    }
}

/// One line about a finished run, for progress output.
pub fn describe(run: &Run) -> String {
    match &run.outcome {
        Outcome::Finished(m) => format!(
            "{:<10} {:<14} position error {:.2e} m, orientation {:.2e} rad, energy {:.2e}, {:.2e} CPU s/s, {} steps",
            run.integrator.name(),
            setting(run),
            m.position_error_max,
            m.orientation_error_max,
            m.energy_error,
            m.cpu_per_second,
            m.steps + m.rejected
        ),
        Outcome::Failed { time, .. } => {
            format!("{:<10} {:<14} diverged at t = {time:.4} s", run.integrator.name(), setting(run))
        }
    }
}

/// CSV, one row per run; empty measures for a run that failed, with its message.
pub fn csv(study: &Study) -> String {
    let mut out = String::from(
        "integrator,dt_s,rtol,position_error_end_m,position_error_max_m,orientation_error_end_rad,orientation_error_max_rad,energy_error,cpu_s_per_simulated_s,steps,rejected_steps,status\n",
    );
    for run in &study.runs {
        let (dt, rtol) = match run.setting {
            Setting::Step(dt) => (format!("{dt:e}"), String::new()),
            Setting::Tolerance(rtol) => (String::new(), format!("{rtol:e}")),
        };
        let _ = match &run.outcome {
            Outcome::Finished(m) => writeln!(
                out,
                "{},{dt},{rtol},{:e},{:e},{:e},{:e},{:e},{:e},{},{},ok",
                run.integrator.name(),
                m.position_error_end,
                m.position_error_max,
                m.orientation_error_end,
                m.orientation_error_max,
                m.energy_error,
                m.cpu_per_second,
                m.steps,
                m.rejected
            ),
            Outcome::Failed { time, message } => {
                writeln!(
                    out,
                    "{},{dt},{rtol},,,,,,,,,\"diverged at t = {time} s: {}\"",
                    run.integrator.name(),
                    message.replace('"', "'")
                )
            }
        };
    }
    out
}

/// The Markdown table with a heading that says what was measured against what.
pub fn markdown(study: &Study) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "## Integrator study: {} ({} s simulated)\n", study.scene, study.duration);
    let _ = writeln!(
        out,
        "Errors against {}, sampled every {:e} s; energy error = largest energy-balance drift / {:.3e} J (the largest kinetic + elastic energy of the reference); CPU = thread CPU seconds per simulated second.\n",
        study.reference.describe(),
        study.sample_interval,
        study.energy_budget
    );
    out.push_str("| integrator | step | position error end / max [m] | orientation error end / max [rad] | energy error | CPU s / s | steps (rejected) |\n");
    out.push_str("|---|---|---|---|---|---|---|\n");
    for run in &study.runs {
        let _ = match &run.outcome {
            Outcome::Finished(m) => writeln!(
                out,
                "| {} | {} | {} / {} | {} / {} | {} | {} | {} |",
                run.integrator.name(),
                setting(run),
                number(m.position_error_end),
                number(m.position_error_max),
                number(m.orientation_error_end),
                number(m.orientation_error_max),
                number(m.energy_error),
                number(m.cpu_per_second),
                steps(m)
            ),
            Outcome::Failed { time, .. } => {
                writeln!(out, "| {} | {} | diverged at t = {time:.4} s | | | | |", run.integrator.name(), setting(run))
            }
        };
    }
    out
}

/// `1.23e-4`, or `0` for an exact result.
fn number(value: f64) -> String {
    if value == 0.0 { "0".into() } else { format!("{value:.2e}") }
}

/// `12345` or `12345 (67)` with the rejected steps.
fn steps(m: &Measures) -> String {
    if m.rejected > 0 { format!("{} ({})", m.steps, m.rejected) } else { m.steps.to_string() }
}
