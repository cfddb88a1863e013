//! A sweep's rows gathered from its run files in case order — by an index of where each row
//! is, not the rows themselves, so that a million rows are read one at a time — for the
//! results, the charts and the window's table.

use super::error::SweepError;
use super::store::{self, Store};
use super::table::{Columns, Row};
use std::fs::File;
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
