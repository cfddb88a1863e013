//! A sweep's results once every case has a row: the rows in case order ([`Rows`]) written out as
//! `results.csv`, `results.parquet`, `summary.md` and the charts. A run of the whole sweep does
//! this when its last case is done; `tether sweep merge` does it for shards.

use super::error::SweepError;
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
/// a row for every case of `plan`.
///
/// # Errors
/// A file that cannot be written.
pub fn write(plan: &Plan, store: &Store, rows: &Rows, runner: &Runner) -> Result<Written, SweepError> {
    let columns = plan.columns();
    let csv_path = store.path("results.csv");
    let parquet_path = store.path("results.parquet");
    let temporary = |path: &Path| {
        path.with_file_name(format!(
            ".{}.tmp",
            path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned())
        ))
    };
    let mut csv = csv::Writer::from_path(temporary(&csv_path)).map_err(|e| SweepError::Io {
        path: csv_path.display().to_string(),
        message: format!("cannot write it: {e}"),
    })?;
    csv.write_record(columns.header()).map_err(|e| write_error(&csv_path, &e))?;
    let mut parquet = ParquetTable::create(&temporary(&parquet_path), &columns)?;
    let mut summary = Summary::new(&columns);
    rows.for_each(|row| {
        csv.write_record(columns.record(&row)).map_err(|e| write_error(&csv_path, &e))?;
        summary.add(&row);
        parquet.push(row)
    })?;
    csv.flush().map_err(|e| store::io(&csv_path, "cannot write", &e))?;
    drop(csv);
    parquet.finish()?;
    for path in [&csv_path, &parquet_path] {
        std::fs::rename(temporary(path), path).map_err(|e| store::io(path, "cannot write", &e))?;
    }
    let charts = plots::draw(plan, rows, &plots::folder(store.dir()), runner)?;
    let linked: Vec<String> = charts.iter().map(|c| format!("plots/{c}")).collect();
    let summary_path = store.path("summary.md");
    let mut file = File::create(&summary_path).map_err(|e| store::io(&summary_path, "cannot create", &e))?;
    file.write_all(summary.markdown(plan, &linked).as_bytes())
        .map_err(|e| store::io(&summary_path, "cannot write", &e))?;
    Ok(Written {
        statuses: summary.statuses(),
        files: vec![csv_path, parquet_path, summary_path, plots::folder(store.dir())],
        charts: charts.len(),
    })
}

fn write_error(path: &Path, error: &csv::Error) -> SweepError {
    SweepError::Io { path: path.display().to_string(), message: format!("cannot write it: {error}") }
}
