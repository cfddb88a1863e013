//! `tether sweep SPEC.ron -o DIR [--jobs N] [--shard I/N] [--resume] [--record]
//! [--case-timeout S] [--max-cases N]` and `tether sweep merge DIR`: a scene run over a design of
//! factor values, with a progress bar; the figures of the run (wall time, CPU time of the cases,
//! how busy the threads were, the cost per case beyond its simulation) printed at the end.
//! Ctrl-C or SIGTERM stops any stage — checking the cases, running them, writing the results —
//! within a case's step or a row, keeping every finished row (exit code 130).

use super::flags::positive;
use anyhow::bail;
use clap::{Args, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use std::num::NonZeroUsize;
use std::path::PathBuf;
use std::time::Duration;
use tether_analysis::runner::Runner;
use tether_analysis::sweep::design::DEFAULT_MAX_CASES;
use tether_analysis::sweep::shard::{self, ShardArg};
use tether_analysis::sweep::{self, Options, Plan, Progress, Report, Stage, SweepError};

#[derive(Debug, Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct SweepArgs {
    #[command(subcommand)]
    command: Option<SweepCommand>,
    /// Sweep spec (.ron): the base scene, the factors and their values, the design, the metrics.
    #[arg(required = true)]
    spec: Option<PathBuf>,
    /// Output directory (new or empty, or this sweep's with --resume).
    #[arg(short, long, required = true)]
    output: Option<PathBuf>,
    /// Cases run at once (default: every core).
    #[arg(long)]
    jobs: Option<NonZeroUsize>,
    /// Run the I-th of N disjoint slices of the cases (I from 0), its rows in their own file;
    /// `auto` (or `auto/N`) takes the index from a Slurm job array or a Kubernetes indexed job,
    /// which is also what happens without --shard inside an array's task.
    #[arg(long, value_parser = shard::parse)]
    shard: Option<ShardArg>,
    /// Run only the cases without a row in the output directory.
    #[arg(long)]
    resume: bool,
    /// Write each case's Rerun recording to DIR/recordings/case-N.rrd.
    #[arg(long)]
    record: bool,
    /// Frames per simulated second in the recordings.
    #[arg(long, default_value_t = 60.0, requires = "record")]
    log_hz: f64,
    /// Wall-time limit of one case [s]; a case past it is a row with status timed_out.
    #[arg(long, default_value_t = 600.0)]
    case_timeout: f64,
    /// The most cases the sweep may have (a spec past it is refused with its size before
    /// anything is made).
    #[arg(long, default_value_t = DEFAULT_MAX_CASES)]
    max_cases: usize,
}

#[derive(Debug, Subcommand)]
enum SweepCommand {
    /// Join the rows of a sweep's shards into its results (results.csv, results.parquet,
    /// summary.md, plots/).
    Merge {
        /// The sweep's output directory.
        dir: PathBuf,
        /// Charts drawn at once (default: every core).
        #[arg(long)]
        jobs: Option<NonZeroUsize>,
    },
}

/// How a sweep command ended.
pub enum Outcome {
    Finished,
    Interrupted,
}

pub fn run(args: &SweepArgs) -> anyhow::Result<Outcome> {
    // Installed first: every stage from the planning on stops at the flag.
    let cancel = super::cancel_on_ctrl_c()?;
    if let Some(SweepCommand::Merge { dir, jobs }) = &args.command {
        let runner = Runner::new(jobs.unwrap_or_else(tether_analysis::runner::all_cores)).with_cancel(cancel);
        let written = match sweep::merge(dir, &runner) {
            Err(SweepError::Interrupted(stage)) => return Ok(interrupted(stage)),
            other => other?,
        };
        super::print(&format!(
            "merged {}: {}\nwritten: {}\n",
            dir.display(),
            written.statuses,
            list(&written.files, written.charts)
        ))?;
        return Ok(Outcome::Finished);
    }
    let (Some(spec), Some(output)) = (&args.spec, &args.output) else { bail!("give a sweep spec and -o DIR") };
    positive("--case-timeout", args.case_timeout, "s")?;
    positive("--log-hz", args.log_hz, "Hz")?;
    let shard = shard::resolve(args.shard, &|name| std::env::var(name).ok()).map_err(anyhow::Error::msg)?;
    let plan = Plan::load(spec, args.max_cases)?;
    let runner = Runner::new(args.jobs.unwrap_or_else(tether_analysis::runner::all_cores))
        .with_case_timeout(Duration::from_secs_f64(args.case_timeout))
        .with_cancel(cancel);
    let jobs = runner.jobs();
    let options = Options {
        runner,
        shard: shard.as_ref().map(|(s, _)| *s),
        resume: args.resume,
        record: args.record.then_some(args.log_hz),
    };
    let which = shard.as_ref().map_or_else(String::new, |(s, source)| format!(", shard {s} (from {source})"));
    eprintln!("sweep {}: {} cases ({}){which}, on {jobs} threads", plan.name, plan.cases.len(), plan.design.describe());
    let report = run_with_progress(&plan, output, &options, "cases");
    let report = match report {
        Err(SweepError::Interrupted(stage)) => return Ok(interrupted(stage)),
        other => other?,
    };
    super::print(&describe(&report, output, jobs))?;
    Ok(if report.interrupted { Outcome::Interrupted } else { Outcome::Finished })
}

/// Runs `plan` into `output` with a progress bar counting its cases as `unit` ("cases",
/// "seeds"), shown from the first finished one and cleared at the end.
pub(super) fn run_with_progress(
    plan: &Plan,
    output: &std::path::Path,
    options: &Options,
    unit: &str,
) -> Result<Report, SweepError> {
    let bar = ProgressBar::hidden();
    let template = format!("{{elapsed_precise}} [{{bar:40}}] {{pos}}/{{len}} {unit}, {{msg}}, {{eta}} left");
    let report = sweep::run(plan, output, options, |p: Progress| {
        if bar.is_hidden() && bar.length().is_none() {
            bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
            bar.set_style(ProgressStyle::with_template(&template).expect("the template is a valid literal"));
            bar.set_length(p.total as u64);
        }
        bar.set_position(p.done as u64);
        bar.set_message(format!("{} failed", p.failed));
    });
    bar.finish_and_clear();
    report
}

/// Says which stage Ctrl-C or SIGTERM stopped, and what it left.
fn interrupted(stage: Stage) -> Outcome {
    eprintln!("interrupted while {stage}");
    Outcome::Interrupted
}

/// What the run did, in a few lines: the cases by status, the time, where the results are.
fn describe(report: &Report, output: &std::path::Path, jobs: NonZeroUsize) -> String {
    let statuses: Vec<String> = report.statuses.iter().map(|(s, n)| format!("{n} {}", s.name())).collect();
    let mut text = format!(
        "ran {} of {} cases{}: {}\n",
        report.ran,
        report.slice,
        if report.skipped > 0 { format!(" ({} had a row already)", report.skipped) } else { String::new() },
        if statuses.is_empty() { "nothing to run".into() } else { statuses.join(", ") }
    );
    if report.ran > 0 && report.running.as_secs_f64() > 0.0 {
        let threads = jobs.get() as f64;
        text += &format!(
            "{:.2} s checking the cases, {:.2} s running them on {jobs} threads, {:.2} s writing the results\n\
             the simulations took {:.2} s of CPU, the threads {:.0} % busy with them; {:.2} ms of CPU per case went to the rest (building, checking, writing its row)\n",
            report.checking.as_secs_f64(),
            report.running.as_secs_f64(),
            report.writing.as_secs_f64(),
            report.case_cpu_seconds,
            100.0 * report.case_cpu_seconds / (report.running.as_secs_f64() * threads),
            1e3 * (report.process_cpu_seconds - report.case_cpu_seconds) / report.ran as f64
        );
    }
    if report.interrupted {
        text += &format!(
            "interrupted: the finished cases are kept; run again with --resume to finish into {}\n",
            output.display()
        );
    }
    match &report.written {
        Some(written) => text += &format!("written: {}\n", list(&written.files, written.charts)),
        None if !report.interrupted => {
            text += &format!(
                "rows in {}/runs/; when every shard is done: tether sweep merge {}\n",
                output.display(),
                output.display()
            )
        }
        None => {}
    }
    text
}

/// `out/results.csv, out/results.parquet, out/summary.md, out/plots (12 charts)`.
fn list(files: &[PathBuf], charts: usize) -> String {
    let names: Vec<String> = files
        .iter()
        .map(|f| {
            if f.extension().is_none() { format!("{} ({charts} charts)", f.display()) } else { f.display().to_string() }
        })
        .collect();
    names.join(", ")
}
