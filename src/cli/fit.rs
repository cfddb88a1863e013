//! `tether fit SPEC.ron [-o DIR] [--jobs N] [--json] [--scene-out PATH | --in-place]`: the
//! scene's parameters fitted to a measured record (docs/calibration.md). Prints each iteration's
//! cost, then the fitted values with their 95 % intervals, the correlations, what the data
//! cannot determine and each signal's RMS before and after; writes the report, a chart per
//! signal, the recording of the fitted run and the fitted scene. Ctrl-C stops at the best point
//! so far, which is written as the result, said to be partial (exit code 130).

use anyhow::Context as _;
use clap::Args;
use std::num::NonZeroUsize;
use std::path::PathBuf;
use tether_analysis::fit::output::{self, utc_now};
use tether_analysis::fit::report;
use tether_analysis::fit::run::{self, Progress};
use tether_analysis::fit::setup::Setup;
use tether_analysis::runner::Runner;

#[derive(Debug, Args)]
pub struct FitArgs {
    /// Fit spec (.ron): the scene, the record, the signals, the parameters with their bounds.
    spec: PathBuf,
    /// Output directory for the report, the charts and the fitted run's recording (default:
    /// `<spec stem>-fit` beside the spec).
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Runs at once (default: every core).
    #[arg(long)]
    jobs: Option<NonZeroUsize>,
    /// Print the result as JSON (all of it: values, intervals, correlations, iterations,
    /// signals, files) instead of the table.
    #[arg(long)]
    json: bool,
    /// Where the fitted scene is written (default: `<scene stem>.fitted.ron` beside the scene).
    #[arg(long, conflicts_with = "in_place")]
    scene_out: Option<PathBuf>,
    /// Write the fitted values into the scene file itself.
    #[arg(long)]
    in_place: bool,
}

/// How a fit ended.
pub enum Outcome {
    Finished,
    Interrupted,
}

pub fn run(args: &FitArgs) -> anyhow::Result<Outcome> {
    let cancel = super::cancel_on_ctrl_c()?;
    let setup = Setup::load(&args.spec)?;
    let runner = Runner::new(args.jobs.unwrap_or_else(tether_analysis::runner::all_cores)).with_cancel(cancel);
    let names: Vec<&str> = setup.model.parameters.iter().map(|p| p.name.as_str()).collect();
    let samples: usize = setup.model.signals.iter().map(|s| s.times.len()).sum();
    eprintln!(
        "fit {}: {} parameter(s) ({}) to {} samples of {} signal(s) from {}, on {} threads",
        args.spec.display(),
        names.len(),
        names.join(", "),
        samples,
        setup.model.signals.len(),
        setup.record_path.display(),
        runner.jobs()
    );
    let quiet = args.json;
    let outcome = run::fit(&setup, &runner, |p: &Progress| {
        if !quiet {
            eprintln!("{}", progress_line(p));
        }
    })?;
    if outcome.ending == tether_analysis::fit::solver::Ending::Cancelled {
        // The best point's report, charts and scene are written below (no further run).
        tether_analysis::interrupt::finishing();
    }
    let dir = args.output.clone().unwrap_or_else(|| {
        let stem = args.spec.file_stem().map_or_else(|| "fit".into(), |s| s.to_string_lossy().into_owned());
        args.spec.with_file_name(format!("{stem}-fit"))
    });
    let mut files = output::write_results(&setup, &outcome, &dir).map_err(anyhow::Error::msg)?;
    let scene_path = if args.in_place {
        setup.model.scene_path.clone()
    } else {
        args.scene_out.clone().unwrap_or_else(|| {
            let stem =
                setup.model.scene_path.file_stem().map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
            setup.model.scene_path.with_file_name(format!("{stem}.fitted.ron"))
        })
    };
    let text = output::fitted_scene(&setup, &outcome, &utc_now()).map_err(anyhow::Error::msg)?;
    // The written scene must load: a fitted value the loader refuses is a bug, not a file.
    tether_scene::parse(&text, &scene_path).context("the fitted scene does not load")?;
    std::fs::write(&scene_path, text).with_context(|| format!("writing {}", scene_path.display()))?;
    files.push(("fitted scene".into(), scene_path));
    let json_path = output::write_json(&setup, &outcome, &files, &dir).map_err(anyhow::Error::msg)?;
    files.push(("report (JSON)".into(), json_path.clone()));
    if args.json {
        super::print(&std::fs::read_to_string(&json_path).context("reading the JSON report back")?)?;
    } else {
        let mut text = report::text(&setup.model, &outcome);
        text += "\nwritten:\n";
        for (what, path) in &files {
            text += &format!("  {what}: {}\n", path.display());
        }
        super::print(&text)?;
    }
    Ok(if outcome.ending == tether_analysis::fit::solver::Ending::Cancelled {
        Outcome::Interrupted
    } else {
        Outcome::Finished
    })
}

/// `iteration 3: cost 1.234e-2, k = 100.2, c = 0.99 (4 runs)`, or the refused trial.
fn progress_line(p: &Progress) -> String {
    let values: Vec<String> = p.values.iter().map(|v| report::number(*v)).collect();
    let state = match (&p.refused, p.accepted) {
        (Some(why), _) => format!("trial refused ({why})"),
        (None, true) => "accepted".into(),
        (None, false) => "trial rejected (the cost rose)".into(),
    };
    format!("iteration {}: cost {:.6e}, values [{}], {state}, {} runs", p.iteration, p.cost, values.join(", "), p.runs)
}
