//! A sweep's results once every case has a row: the rows gathered from the run files in case
//! order — by an index of where each row is, not the rows themselves — and written out as
//! `results.csv`, `results.parquet`, `summary.md` and the charts. A run of the whole sweep does
//! this when its last case is done; `tether sweep merge` does it for shards.

use super::SweepError;
use super::parquet::ParquetTable;
use super::plan::Plan;
use super::plots;
use super::store::{self, Store};
use super::summary::Summary;
use super::table::{Columns, Row};
use crate::runner::Runner;
use std::fs::File;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// Where each case's row is.
pub struct Rows {
    columns: Columns,
    files: Vec<PathBuf>,
    /// (case, file, position), sorted by case, one per case (a case run twice — a shard and a
    /// resumed whole run — keeps its first row: the results are the same).
    index: Vec<(usize, usize, csv::Position)>,
}

impl Rows {
    /// Indexes the rows of every run file in `store`.
    ///
    /// # Errors
    /// A run file that cannot be read, or a row not of this sweep.
    pub fn gather(store: &Store, columns: &Columns) -> Result<Self, SweepError> {
        let files = store.run_files()?;
        let mut index = Vec::new();
        for (file, path) in files.iter().enumerate() {
            store::for_each_row(path, columns, |row, position| {
                index.push((row.case, file, position));
                Ok(())
            })?;
        }
        index.sort_by_key(|(case, file, position)| (*case, *file, position.byte()));
        index.dedup_by_key(|(case, _, _)| *case);
        Ok(Self { columns: columns.clone(), files, index })
    }

    /// Number of cases with a row.
    pub fn len(&self) -> usize {
        self.index.len()
    }

    pub fn is_empty(&self) -> bool {
        self.index.is_empty()
    }

    /// The cases below `cases` with no row, in order.
    pub fn missing(&self, cases: usize) -> Vec<usize> {
        let mut have = self.index.iter().map(|(case, _, _)| *case).peekable();
        (0..cases)
            .filter(|&case| {
                while have.next_if(|&c| c < case).is_some() {}
                have.peek() != Some(&case)
            })
            .collect()
    }

    /// Calls `each` with every row, in case order, reading them one at a time.
    ///
    /// # Errors
    /// A file that cannot be read again, or the first error of `each`.
    pub fn for_each(&self, mut each: impl FnMut(Row) -> Result<(), SweepError>) -> Result<(), SweepError> {
        let mut readers = Vec::with_capacity(self.files.len());
        for path in &self.files {
            let file = File::open(path).map_err(|e| store::io(path, "cannot open", &e))?;
            let mut reader = csv::Reader::from_reader(file);
            reader.headers().map_err(|e| read_error(path, &e))?;
            readers.push(reader);
        }
        let mut record = csv::StringRecord::new();
        for (_, file, position) in &self.index {
            let (reader, path) = (&mut readers[*file], &self.files[*file]);
            // Rows of one run are mostly in case order: seek only when the next is elsewhere.
            if reader.position().byte() != position.byte() {
                reader.seek(position.clone()).map_err(|e| read_error(path, &e))?;
            }
            reader.read_record(&mut record).map_err(|e| read_error(path, &e))?;
            each(
                self.columns
                    .parse(&record)
                    .map_err(|m| SweepError::Directory(format!("{}:{}: {m}", path.display(), position.line())))?,
            )?;
        }
        Ok(())
    }
}

fn read_error(path: &Path, error: &csv::Error) -> SweepError {
    SweepError::Io { path: path.display().to_string(), message: format!("cannot read it again: {error}") }
}

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
