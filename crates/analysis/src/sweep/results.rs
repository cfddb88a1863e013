//! A sweep's results once every case has a row: the rows in case order ([`Rows`]) written out as
//! `results.csv`, `results.parquet`, `summary.md` and the charts. A run of the whole sweep does
//! this when its last case is done; `tether sweep merge` does it for shards.

use super::error::{Stage, SweepError, unless_cancelled};
use super::parquet::ParquetTable;
use super::plan::Plan;
use super::plots;
use super::rows::Rows;
use super::store::{self, Store};
use super::summary::Summary;
use crate::runner::Runner;
use std::fs::File;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// What the outputs say and where they are.
#[derive(Debug)]
pub struct Written {
    /// `38 ok, 2 diverged`.
    pub statuses: String,
    pub files: Vec<PathBuf>,
    /// Number of charts in `plots/`.
    pub charts: usize,
}

/// Writes `results.csv`, `results.parquet`, `summary.md` and `plots/` from `rows`, which hold
/// a row for every case of `plan`. The tables are written to hidden drafts and renamed once
/// the charts are drawn too, so a failed or stopped write leaves no results file half-written.
///
/// # Errors
/// A file that cannot be written; `runner` cancelled (checked at each row and chart).
pub fn write(plan: &Plan, store: &Store, rows: &Rows, runner: &Runner) -> Result<Written, SweepError> {
    let csv_path = store.path("results.csv");
    let parquet_path = store.path("results.parquet");
    let drafts = [draft(&csv_path), draft(&parquet_path)];
    let written = write_drafts(plan, store, rows, runner, &drafts).and_then(|(summary, charts)| {
        for (draft, path) in drafts.iter().zip([&csv_path, &parquet_path]) {
            std::fs::rename(draft, path).map_err(|e| store::io(path, "cannot write", &e))?;
        }
        finish(plan, store, &summary, &charts, vec![csv_path.clone(), parquet_path.clone()])
    });
    if written.is_err() {
        for draft in &drafts {
            // A draft never made (the error came first) is no error of its own.
            let _ = std::fs::remove_file(draft);
        }
    }
    written
}

/// `.results.csv.tmp` next to `results.csv`.
fn draft(path: &Path) -> PathBuf {
    path.with_file_name(format!(
        ".{}.tmp",
        path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned())
    ))
}

/// Writes the tables into `drafts` (CSV, Parquet) and draws the charts; returns the summary and
/// the charts' file names.
fn write_drafts(
    plan: &Plan,
    store: &Store,
    rows: &Rows,
    runner: &Runner,
    drafts: &[PathBuf; 2],
) -> Result<(Summary, Vec<String>), SweepError> {
    let columns = plan.columns();
    let [csv_draft, parquet_draft] = drafts;
    let mut csv = csv::Writer::from_path(csv_draft).map_err(|e| SweepError::Io {
        path: csv_draft.display().to_string(),
        message: format!("cannot write it: {e}"),
    })?;
    csv.write_record(columns.header()).map_err(|e| write_error(csv_draft, &e))?;
    let mut parquet = ParquetTable::create(parquet_draft, &columns)?;
    let mut summary = Summary::new(&columns);
    rows.for_each(|row| {
        unless_cancelled(runner, Stage::Writing)?;
        csv.write_record(columns.record(&row)).map_err(|e| write_error(csv_draft, &e))?;
        summary.add(&row);
        parquet.push(row)
    })?;
    csv.flush().map_err(|e| store::io(csv_draft, "cannot write", &e))?;
    drop(csv);
    parquet.finish()?;
    let charts = plots::draw(plan, rows, &plots::folder(store.dir()), runner)?;
    Ok((summary, charts))
}

/// Writes `summary.md`, linking `charts`; what was written, after the `tables`.
fn finish(
    plan: &Plan,
    store: &Store,
    summary: &Summary,
    charts: &[String],
    tables: Vec<PathBuf>,
) -> Result<Written, SweepError> {
    let linked: Vec<String> = charts.iter().map(|c| format!("plots/{c}")).collect();
    let summary_path = store.path("summary.md");
    let mut file = File::create(&summary_path).map_err(|e| store::io(&summary_path, "cannot create", &e))?;
    file.write_all(summary.markdown(plan, &linked).as_bytes())
        .map_err(|e| store::io(&summary_path, "cannot write", &e))?;
    let mut files = tables;
    files.extend([summary_path, plots::folder(store.dir())]);
    Ok(Written { statuses: summary.statuses(), files, charts: charts.len() })
}

fn write_error(path: &Path, error: &csv::Error) -> SweepError {
    SweepError::Io { path: path.display().to_string(), message: format!("cannot write it: {error}") }
}
