//! `results.parquet`: the results table for dataframe tools (pandas, polars, DuckDB), written
//! with the arrow and parquet crates the recorder's dependencies already build. Columns as in
//! `results.csv`, typed: `case`, `steps`, `rejected_steps` unsigned integers; factors numbers,
//! flags or strings; metrics nullable doubles (null where a failed case has no value), each
//! metric's unit in its field's metadata (`unit`). Rows go out in batches of `BATCH`, so the
//! table is never whole in memory.

use super::error::SweepError;
use super::spec::{Level, LevelKind};
use super::table::{CASE_COLUMN, Columns, OUTCOME_COLUMNS, Row};
use arrow_array::builder::{BooleanBuilder, Float64Builder, StringBuilder};
use arrow_array::{ArrayRef, RecordBatch};
use arrow_schema::{DataType, Field, Schema};
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::properties::WriterProperties;
use std::collections::HashMap;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Rows per record batch (and row group).
const BATCH: usize = 4096;

/// A Parquet results table being written.
pub struct ParquetTable {
    writer: ArrowWriter<File>,
    schema: Arc<Schema>,
    columns: Columns,
    rows: Vec<Row>,
    path: PathBuf,
}

impl ParquetTable {
    /// Creates the file at `path` for a sweep with these columns.
    ///
    /// # Errors
    /// The file cannot be created.
    pub fn create(path: &Path, columns: &Columns) -> Result<Self, SweepError> {
        let schema = Arc::new(schema(columns));
        let file = File::create(path).map_err(|e| super::store::io(path, "cannot create", &e))?;
        let properties = WriterProperties::builder().set_compression(Compression::SNAPPY).build();
        let writer = ArrowWriter::try_new(file, Arc::clone(&schema), Some(properties)).map_err(|e| failed(path, &e))?;
        Ok(Self { writer, schema, columns: columns.clone(), rows: Vec::with_capacity(BATCH), path: path.to_path_buf() })
    }

    /// Adds a row (written with the next full batch).
    ///
    /// # Errors
    /// A batch that cannot be written.
    pub fn push(&mut self, row: Row) -> Result<(), SweepError> {
        self.rows.push(row);
        if self.rows.len() == BATCH { self.flush() } else { Ok(()) }
    }

    /// Writes the last rows and the file's footer.
    ///
    /// # Errors
    /// The file cannot be written.
    pub fn finish(mut self) -> Result<(), SweepError> {
        self.flush()?;
        self.writer.close().map(drop).map_err(|e| failed(&self.path, &e))
    }

    fn flush(&mut self) -> Result<(), SweepError> {
        if self.rows.is_empty() {
            return Ok(());
        }
        let batch = RecordBatch::try_new(Arc::clone(&self.schema), arrays(&self.columns, &self.rows))
            .map_err(|e| failed(&self.path, &e))?;
        self.writer.write(&batch).map_err(|e| failed(&self.path, &e))?;
        self.rows.clear();
        Ok(())
    }
}

fn failed(path: &Path, error: &dyn std::fmt::Display) -> SweepError {
    SweepError::Output { path: path.display().to_string(), message: error.to_string() }
}

/// The table's schema.
fn schema(columns: &Columns) -> Schema {
    let mut fields = vec![Field::new(CASE_COLUMN, DataType::UInt64, false)];
    fields.extend(columns.factors.iter().map(|f| {
        let kind = match f.kind {
            LevelKind::Number => DataType::Float64,
            LevelKind::Flag => DataType::Boolean,
            LevelKind::Text => DataType::Utf8,
        };
        Field::new(&f.name, kind, false)
    }));
    let [status, message, end_time, steps, rejected, cpu] = OUTCOME_COLUMNS;
    fields.extend([
        Field::new(status, DataType::Utf8, false),
        Field::new(message, DataType::Utf8, true),
        Field::new(end_time, DataType::Float64, false).with_metadata(unit("s")),
        Field::new(steps, DataType::UInt64, false),
        Field::new(rejected, DataType::UInt64, false),
        Field::new(cpu, DataType::Float64, false).with_metadata(unit("s")),
    ]);
    fields.extend(
        columns.metrics.iter().map(|m| Field::new(&m.name, DataType::Float64, true).with_metadata(unit(&m.unit))),
    );
    Schema::new(fields)
}

fn unit(unit: &str) -> HashMap<String, String> {
    HashMap::from([("unit".to_string(), unit.to_string())])
}

/// The columns of `rows` as arrays, in the schema's order.
fn arrays(columns: &Columns, rows: &[Row]) -> Vec<ArrayRef> {
    let whole =
        |f: &dyn Fn(&Row) -> u64| -> ArrayRef { Arc::new(rows.iter().map(f).collect::<arrow_array::UInt64Array>()) };
    let real = |f: &dyn Fn(&Row) -> Option<f64>| -> ArrayRef {
        let mut builder = Float64Builder::with_capacity(rows.len());
        rows.iter().for_each(|r| builder.append_option(f(r)));
        Arc::new(builder.finish())
    };
    let mut arrays = vec![whole(&|r| r.case as u64)];
    for (k, factor) in columns.factors.iter().enumerate() {
        arrays.push(match factor.kind {
            LevelKind::Number => real(&|r| r.values[k].number()),
            LevelKind::Flag => {
                let mut builder = BooleanBuilder::with_capacity(rows.len());
                rows.iter().for_each(|r| builder.append_value(matches!(r.values[k], Level::Flag(true))));
                Arc::new(builder.finish())
            }
            LevelKind::Text => {
                let mut builder = StringBuilder::new();
                rows.iter().for_each(|r| builder.append_value(r.values[k].to_string()));
                Arc::new(builder.finish())
            }
        });
    }
    let mut status = StringBuilder::new();
    let mut message = StringBuilder::new();
    for row in rows {
        status.append_value(row.ending.status.name());
        message.append_option((!row.ending.message.is_empty()).then_some(&row.ending.message));
    }
    arrays.push(Arc::new(status.finish()));
    arrays.push(Arc::new(message.finish()));
    arrays.push(real(&|r| Some(r.ending.end_time)));
    arrays.push(whole(&|r| r.ending.steps));
    arrays.push(whole(&|r| r.ending.rejected_steps));
    arrays.push(real(&|r| Some(r.ending.cpu_seconds)));
    for k in 0..columns.metrics.len() {
        arrays.push(real(&|r| r.metrics[k]));
    }
    arrays
}
