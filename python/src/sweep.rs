//! A sweep spec run from Python, as `tether sweep SPEC -o DIR` runs it (the same plan, runner
//! and results writer), and its `results.parquet` read back as columns for callers without
//! pyarrow.
//!
//! The sweep runs on its own thread while the caller's thread waits with the GIL released,
//! running Python's signal handlers ([`crate::background`]): Ctrl-C sets the runner's cancel flag,
//! which stops the sweep within a case's step (the finished rows are kept), then raises
//! `KeyboardInterrupt`.

use crate::background;
use crate::errors::{caught, runtime_error, value_error};
use arrow_array::RecordBatchReader as _;
use arrow_array::cast::AsArray;
use arrow_array::types::{Float64Type, Int64Type, UInt64Type};
use arrow_schema::DataType;
use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyDict, PyList};
use std::num::NonZeroUsize;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::Duration;
use tether_analysis::runner::Runner;
use tether_analysis::sweep::design::DEFAULT_MAX_CASES;
use tether_analysis::sweep::{self, Options, Plan, SweepError};

/// Runs the sweep spec `spec` into the directory `output` on `jobs` threads (None: every core);
/// returns the path of its `results.parquet`.
#[pyfunction]
#[pyo3(signature = (spec, output, jobs = None, max_cases = None, case_timeout = 600.0))]
pub fn run_sweep(
    py: Python<'_>,
    spec: PathBuf,
    output: PathBuf,
    jobs: Option<usize>,
    max_cases: Option<usize>,
    case_timeout: f64,
) -> PyResult<PathBuf> {
    let jobs = match jobs {
        None => tether_analysis::runner::all_cores(),
        Some(jobs) => NonZeroUsize::new(jobs).ok_or_else(|| value_error("`jobs` must be at least 1"))?,
    };
    if !(case_timeout.is_finite() && case_timeout > 0.0) {
        return Err(value_error(format!("`case_timeout` must be a positive number of seconds, got {case_timeout}")));
    }
    let plan = py
        .detach(|| caught(|| Plan::load(&spec, max_cases.unwrap_or(DEFAULT_MAX_CASES))))
        .map_err(runtime_error)?
        .map_err(value_error)?;
    let cancel = Arc::new(AtomicBool::new(false));
    let runner =
        Runner::new(jobs).with_case_timeout(Duration::from_secs_f64(case_timeout)).with_cancel(Arc::clone(&cancel));
    let options = Options { runner, shard: None, resume: false, record: None };
    let dir = output.clone();
    let (outcome, interrupt) =
        background::run(py, &cancel, move || caught(|| sweep::run(&plan, &dir, &options, |_| {})));
    if let Some(signal) = interrupt {
        return Err(signal);
    }
    let report = outcome
        .map_err(|_| runtime_error("the sweep's thread stopped unexpectedly"))?
        .map_err(runtime_error)?
        .map_err(|e: SweepError| value_error(e))?;
    if report.interrupted || report.written.is_none() {
        return Err(runtime_error(format!(
            "the sweep into {} was interrupted: its results were not written",
            output.display()
        )));
    }
    Ok(output.join("results.parquet"))
}

/// The columns of the Parquet file `path`: `{name: ("f8" | "u8" | "i8" | "?", bytes)}` for
/// numbers (a null as NaN) and flags, `{name: ("str", [text or None, …])}` for strings.
#[pyfunction]
pub fn read_parquet<'py>(py: Python<'py>, path: PathBuf) -> PyResult<Bound<'py, PyDict>> {
    let failed = |e: &dyn std::fmt::Display| value_error(format!("{}: {e}", path.display()));
    let file = std::fs::File::open(&path).map_err(|e| failed(&e))?;
    let reader =
        ParquetRecordBatchReaderBuilder::try_new(file).map_err(|e| failed(&e))?.build().map_err(|e| failed(&e))?;
    let schema = reader.schema();
    let mut columns: Vec<Column> = schema
        .fields()
        .iter()
        .map(|field| match field.data_type() {
            DataType::Float64 => Ok(Column::Float(Vec::new())),
            DataType::UInt64 => Ok(Column::Unsigned(Vec::new())),
            DataType::Int64 => Ok(Column::Signed(Vec::new())),
            DataType::Boolean => Ok(Column::Flag(Vec::new())),
            DataType::Utf8 => Ok(Column::Text(Vec::new())),
            other => {
                Err(failed(&format!("column `{}` has type {other}, which this reader does not read", field.name())))
            }
        })
        .collect::<PyResult<_>>()?;
    for batch in reader {
        let batch = batch.map_err(|e| failed(&e))?;
        for (column, array) in columns.iter_mut().zip(batch.columns()) {
            match column {
                Column::Float(values) => {
                    let array = array.as_primitive::<Float64Type>();
                    values.extend(array.iter().map(|x| x.unwrap_or(f64::NAN)));
                }
                Column::Unsigned(values) => {
                    values.extend(array.as_primitive::<UInt64Type>().iter().map(Option::unwrap_or_default))
                }
                Column::Signed(values) => {
                    values.extend(array.as_primitive::<Int64Type>().iter().map(Option::unwrap_or_default))
                }
                Column::Flag(values) => values.extend(array.as_boolean().iter().map(Option::unwrap_or_default)),
                Column::Text(values) => values.extend(array.as_string::<i32>().iter().map(|s| s.map(str::to_string))),
            }
        }
    }
    let dict = PyDict::new(py);
    for (field, column) in schema.fields().iter().zip(columns) {
        let raw = |bytes: Vec<u8>| PyBytes::new(py, &bytes).into_any();
        let (kind, values) = match column {
            Column::Float(v) => ("f8", raw(v.iter().flat_map(|x| x.to_ne_bytes()).collect())),
            Column::Unsigned(v) => ("u8", raw(v.iter().flat_map(|x| x.to_ne_bytes()).collect())),
            Column::Signed(v) => ("i8", raw(v.iter().flat_map(|x| x.to_ne_bytes()).collect())),
            Column::Flag(v) => ("?", raw(v.iter().map(|&x| u8::from(x)).collect())),
            Column::Text(v) => ("str", PyList::new(py, v)?.into_any()),
        };
        dict.set_item(field.name(), (kind, values))?;
    }
    Ok(dict)
}

/// One column being read.
enum Column {
    Float(Vec<f64>),
    Unsigned(Vec<u64>),
    Signed(Vec<i64>),
    Flag(Vec<bool>),
    Text(Vec<Option<String>>),
}
