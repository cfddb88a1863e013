//! Running a sweep into its directory, and merging shards.
//!
//! A run: checks the directory can take the sweep (touching nothing), builds every case it
//! will run (a value the loader refuses stops everything here, named), writes the manifest,
//! then runs its cases on the runner's threads, appending each row to its run file as the case
//! finishes. A run of the whole sweep (not a shard) then writes the results; a shard leaves that
//! to `tether sweep merge`. A Ctrl-C or SIGTERM (the runner's cancel flag) stops each stage —
//! checking, running, writing — within a case's step or a row, keeping every finished row.

use super::case::{self, CaseError, Ending, Outcome, Recording, Status};
use super::error::{Stage, SweepError};
use super::plan::Plan;
use super::results::{self, Written};
use super::rows::Rows;
use super::shard::Shard;
use super::store::{self, Manifest, Store};
use super::table::Row;
use crate::runner::{Runner, process_cpu_seconds};
use std::path::Path;
use std::time::{Duration, Instant};

/// How a sweep runs.
#[derive(Debug, Clone)]
pub struct Options {
    /// Threads, the case time limit, the cancel flag.
    pub runner: Runner,
    /// The slice of the cases to run (`None`: all of them).
    pub shard: Option<Shard>,
    /// Run only the cases without a row (else a directory with rows of this run's cases is
    /// refused).
    pub resume: bool,
    /// Record each case at this many frames per simulated second.
    pub record: Option<f64>,
}

/// Where a run is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Progress {
    /// Cases this run has finished, and of those, failed.
    pub done: usize,
    pub failed: usize,
    /// Cases this run has to run.
    pub total: usize,
}

/// What a run did.
#[derive(Debug)]
pub struct Report {
    /// Cases of the sweep, of this run's slice, and of the slice that had a row already.
    pub cases: usize,
    pub slice: usize,
    pub skipped: usize,
    /// Cases this run finished, per status.
    pub ran: usize,
    pub statuses: Vec<(Status, usize)>,
    /// Wall time building every case's scene to check it, running the cases, and writing the
    /// results.
    pub checking: Duration,
    pub running: Duration,
    pub writing: Duration,
    /// CPU time of the cases' simulations (from t = 0 to their end) \[s].
    pub case_cpu_seconds: f64,
    /// CPU time of the whole process while it checked and ran the cases \[s]: less the
    /// simulations', what the cases cost beyond them, whatever else the machine runs.
    pub process_cpu_seconds: f64,
    /// The results, when this run completed the sweep.
    pub written: Option<Written>,
    /// Whether Ctrl-C or SIGTERM stopped it (while running or writing).
    pub interrupted: bool,
}

/// Runs `plan` into `dir`; `progress` hears of each case as it finishes.
///
/// # Errors
/// A directory that holds another sweep or rows of this run's cases (without `resume`); a
/// value or case the loader refuses; a file that cannot be written; an interruption while
/// the cases are checked.
pub fn run(
    plan: &Plan,
    dir: &Path,
    options: &Options,
    mut progress: impl FnMut(Progress),
) -> Result<Report, SweepError> {
    let start = Instant::now();
    let cpu_start = process_cpu_seconds();
    let store = Store::new(dir);
    let columns = plan.columns();
    let manifest = Manifest::new(
        &plan.name,
        (&plan.spec_path, &plan.spec_text),
        (&plan.scene_path, &plan.scene_text),
        plan.cases.len(),
        columns.clone(),
    );
    let done = store.check(&manifest)?;
    let in_slice = |case: usize| options.shard.is_none_or(|s| s.contains(case));
    let slice = (0..plan.cases.len()).filter(|&c| in_slice(c)).count();
    let skipped = (0..plan.cases.len()).filter(|&c| in_slice(c) && done[c]).count();
    if skipped > 0 && !options.resume {
        let whose = options.shard.map_or_else(|| "this sweep's".to_string(), |s| format!("shard {s}'s"));
        return Err(SweepError::Directory(format!(
            "{} already holds rows for {skipped} of {whose} {slice} cases: pass --resume to run only the cases without one (nothing was overwritten)",
            dir.display()
        )));
    }
    let to_run = || (0..plan.cases.len()).filter(|&c| in_slice(c) && !done[c]);
    plan.check_factors(&options.runner)?;
    plan.check_cases(&options.runner, to_run())?;
    let checking = start.elapsed();
    store.create(&manifest)?;
    if options.record.is_some() {
        let folder = store.path(store::RECORDINGS);
        std::fs::create_dir_all(&folder).map_err(|e| store::io(&folder, "cannot create", &e))?;
    }
    let file_name = options.shard.map_or_else(|| store::ALL.to_string(), |s| s.file_name());
    let mut run_file = store.open_run(&file_name, &columns)?;
    let total = slice - skipped;
    let mut state = Progress { done: 0, failed: 0, total };
    let mut statuses: Vec<(Status, usize)> = Status::ALL.iter().map(|&s| (s, 0)).collect();
    let mut case_cpu_seconds = 0.0;
    options.runner.run(
        to_run(),
        |&case, watch| {
            let values = plan.values(case);
            let recording = options.record.map(|log_hz| Recording {
                path: store.path(store::RECORDINGS).join(format!("case-{case}.rrd")),
                application: &plan.name,
                id: format!("case-{case}"),
                log_hz,
            });
            let outcome = match plan.scene(&values) {
                Ok(scene) => {
                    let duration = scene.file.duration;
                    case::run(scene.world, duration, &plan.metrics, plan.settle_band, watch, recording.as_ref())
                }
                // Checked before the run: the loader refuses nothing now, but if it did, the
                // row would say so.
                Err(message) => Ok(refused(message)),
            };
            (values, outcome)
        },
        |case, (values, outcome)| {
            let outcome = match outcome {
                Ok(outcome) => outcome,
                Err(CaseError::Cancelled) => return Ok(()),
                Err(CaseError::Recording(message)) => {
                    return Err(SweepError::Io { path: format!("case {case}"), message });
                }
            };
            let row = Row::new(case, values, outcome, columns.metrics.len());
            run_file.append(&row)?;
            case_cpu_seconds += row.ending.cpu_seconds;
            if let Some(count) = statuses.iter_mut().find(|(s, _)| *s == row.ending.status) {
                count.1 += 1;
            }
            state.done += 1;
            state.failed += usize::from(row.ending.status != Status::Ok);
            progress(state);
            Ok(())
        },
    )?;
    let stopped_running = options.runner.cancelled();
    if stopped_running {
        // Every finished row is in the run file; what follows only reports it.
        crate::interrupt::finishing();
    }
    let running = start.elapsed() - checking;
    let process_cpu_seconds = process_cpu_seconds() - cpu_start;
    let (written, stopped_writing) = if options.shard.is_none() && !stopped_running {
        match complete(plan, &store, &options.runner) {
            // Every row is kept: the report says it was interrupted, --resume writes them.
            Err(SweepError::Interrupted(Stage::Writing)) => (None, true),
            other => (other?, false),
        }
    } else {
        (None, false)
    };
    statuses.retain(|(_, n)| *n > 0);
    let writing = start.elapsed() - checking - running;
    Ok(Report {
        cases: plan.cases.len(),
        slice,
        skipped,
        ran: state.done,
        statuses,
        checking,
        running,
        writing,
        case_cpu_seconds,
        process_cpu_seconds,
        written,
        interrupted: stopped_running || stopped_writing,
    })
}

/// A row for a case whose scene the loader refused.
fn refused(message: String) -> Outcome {
    let ending =
        Ending { status: Status::Refused, message, end_time: 0.0, steps: 0, rejected_steps: 0, cpu_seconds: 0.0 };
    Outcome { ending, metrics: None }
}

/// Writes the results if every case has a row.
fn complete(plan: &Plan, store: &Store, runner: &Runner) -> Result<Option<Written>, SweepError> {
    let rows = Rows::gather(store, &plan.columns())?;
    if rows.len() < plan.cases.len() {
        return Ok(None);
    }
    results::write(plan, store, &rows, runner).map(Some)
}

/// Joins the rows of every run file of the sweep in `dir` into its results.
///
/// # Errors
/// No sweep in `dir`, cases without a row (listed), a file that cannot be read or written.
pub fn merge(dir: &Path, runner: &Runner) -> Result<Written, SweepError> {
    let store = Store::new(dir);
    let Some(manifest) = store.manifest()? else {
        return Err(SweepError::Directory(format!(
            "{} holds no sweep (no {}): give the directory a sweep was run into with -o",
            dir.display(),
            store::MANIFEST
        )));
    };
    let plan = Plan::from_text(
        &manifest.spec_path,
        manifest.spec_text.clone(),
        Some((manifest.scene_path.clone(), manifest.scene_text.clone())),
    )?;
    let rows = Rows::gather(&store, &manifest.columns)?;
    let missing = rows.missing(manifest.cases);
    if !missing.is_empty() {
        let shown: Vec<String> = missing.iter().take(10).map(ToString::to_string).collect();
        let more = if missing.len() > 10 { ", …" } else { "" };
        return Err(SweepError::Incomplete(format!(
            "{}: {} of {} cases have no row yet (cases {}{more}): wait for the shards still running, or run the missing ones with --resume (the same --shard, or none for all)",
            dir.display(),
            missing.len(),
            manifest.cases,
            shown.join(", ")
        )));
    }
    results::write(&plan, &store, &rows, runner)
}
