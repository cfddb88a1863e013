//! A calibration run from Python, as `tether fit SPEC` runs it (the same setup, solver, report
//! and files): the spec read from a file, or made by the Python half as RON text and read by
//! [`Setup::from_text`]. Hands back the report's JSON (`tether fit --json`'s) with the table
//! `tether fit` prints, and each signal's record and model at the record's times as flat `f64`
//! bytes for numpy.
//!
//! The fit runs on its own thread while the caller's thread waits with the GIL released,
//! running Python's signal handlers ([`crate::background`]). Ctrl-C sets the runner's cancel flag: the
//! solver stops at the best point so far, which is returned as the result, said to be partial
//! (ending `Cancelled`), as the command line writes it; only a Ctrl-C before the start point
//! was evaluated raises `KeyboardInterrupt`, there being no result yet.

use crate::background;
use crate::errors::{caught, runtime_error, value_error};
use crate::samples::bytes;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use tether_analysis::fit::output::{self, utc_now};
use tether_analysis::fit::report;
use tether_analysis::fit::run::{self, Outcome, RunError};
use tether_analysis::fit::setup::Setup;
use tether_analysis::fit::solver::SolveError;
use tether_analysis::runner::Runner;

/// Fits the spec at `spec` (or the spec `text`, labelled `spec`, its paths relative to `spec`'s
/// folder) on `jobs` threads (None: every core). `output`: a folder for the command line's files
/// (the report, a chart per signal, the fitted run's recording, `report.json`); `write_scene`:
/// where the fitted scene is written. Returns `{"report": JSON text, "table": the printed
/// table, "spec": the spec's text, "signals": [{"times", "measured", "start", "fitted"}: float64
/// bytes], "interrupted": Ctrl-C stopped it}`.
#[pyfunction]
#[pyo3(signature = (spec, text = None, jobs = None, output = None, write_scene = None))]
pub fn run_fit<'py>(
    py: Python<'py>,
    spec: PathBuf,
    text: Option<String>,
    jobs: Option<usize>,
    output: Option<PathBuf>,
    write_scene: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let jobs = match jobs {
        None => tether_analysis::runner::all_cores(),
        Some(jobs) => NonZeroUsize::new(jobs).ok_or_else(|| value_error("`jobs` must be at least 1"))?,
    };
    let setup = py
        .detach(|| {
            caught(|| match &text {
                None => Setup::load(&spec),
                Some(text) => Setup::from_text(&spec, text),
            })
        })
        .map_err(runtime_error)?
        .map_err(value_error)?;
    // Where the files go is checked before the fit, not found unwritable after it.
    if let Some(dir) = &output {
        std::fs::create_dir_all(dir).map_err(|e| value_error(format!("cannot write {}: {e}", dir.display())))?;
    }
    if let Some(path) = &write_scene {
        let folder = path.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
        if !folder.is_dir() {
            return Err(value_error(format!("cannot write {}: no folder {}", path.display(), folder.display())));
        }
    }
    let cancel = Arc::new(AtomicBool::new(false));
    let runner = Runner::new(jobs).with_cancel(Arc::clone(&cancel));
    let (joined, interrupt) =
        background::run(py, &cancel, move || caught(|| fit_and_write(setup, &runner, output, write_scene)));
    let done = joined.map_err(|_| runtime_error("the fit's thread stopped unexpectedly"))?.map_err(runtime_error)?;
    let interrupted = interrupt.is_some();
    let done = match (done, interrupt) {
        (Ok(done), _) => done,
        (Err(Failure::Run(RunError::Solve(SolveError::Cancelled))), Some(signal)) => return Err(signal),
        (Err(Failure::Run(e)), _) => return Err(runtime_error(e)),
        (Err(Failure::Write(message)), _) => return Err(value_error(message)),
    };
    let dict = PyDict::new(py);
    dict.set_item("report", done.report)?;
    dict.set_item("table", done.table)?;
    dict.set_item("spec", &done.setup.spec_text)?;
    dict.set_item("interrupted", interrupted)?;
    let signals = PyList::empty(py);
    for (signal, fit) in done.setup.model.signals.iter().zip(&done.outcome.signals) {
        let arrays = PyDict::new(py);
        arrays.set_item("times", bytes(py, &signal.times))?;
        arrays.set_item("measured", bytes(py, &signal.measured))?;
        arrays.set_item("start", bytes(py, &fit.start))?;
        arrays.set_item("fitted", bytes(py, &fit.fitted))?;
        signals.append(arrays)?;
    }
    dict.set_item("signals", signals)?;
    Ok(dict)
}

/// A finished fit and what it wrote.
struct Done {
    setup: Setup,
    outcome: Outcome,
    /// `report::json`'s text, listing the files written, and `report::text`.
    report: String,
    table: String,
}

/// Why a fit gave no result.
enum Failure {
    Run(RunError),
    /// A file that cannot be written (the message names it).
    Write(String),
}

/// The fit, then the command line's files in `output` and the fitted scene at `write_scene`.
fn fit_and_write(
    setup: Setup,
    runner: &Runner,
    output: Option<PathBuf>,
    write_scene: Option<PathBuf>,
) -> Result<Done, Failure> {
    let outcome = run::fit(&setup, runner, |_| {}).map_err(Failure::Run)?;
    let mut files = match &output {
        Some(dir) => output::write_results(&setup, &outcome, dir).map_err(Failure::Write)?,
        None => Vec::new(),
    };
    if let Some(path) = write_scene {
        let text = output::fitted_scene(&setup, &outcome, &utc_now()).map_err(Failure::Write)?;
        // As the command line: a fitted scene the loader refuses is a bug, not a file.
        tether_scene::parse(&text, &path)
            .map_err(|e| Failure::Write(format!("the fitted scene does not load: {e}")))?;
        std::fs::write(&path, text).map_err(|e| Failure::Write(format!("cannot write {}: {e}", path.display())))?;
        files.push(("fitted scene".into(), path));
    }
    if let Some(dir) = &output {
        let json = output::write_json(&setup, &outcome, &files, dir).map_err(Failure::Write)?;
        files.push(("report (JSON)".into(), json));
    }
    let listed: Vec<(String, String)> = files.iter().map(|(w, p)| (w.clone(), p.display().to_string())).collect();
    let report = report::json(&setup.model, &outcome, &listed).to_string();
    let table = report::text(&setup.model, &outcome);
    Ok(Done { setup, outcome, report, table })
}
