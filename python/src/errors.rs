//! The boundary's errors: Rust failures as one-line Python exceptions, and panics caught before
//! they reach the interpreter.

use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// `ValueError(message)`: input refused (the loader's, a validator's or a solver's text).
pub fn value_error(message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(one_line(&message.to_string()))
}

/// `TypeError(message)`: an argument of the wrong type.
pub fn type_error(message: impl std::fmt::Display) -> PyErr {
    PyTypeError::new_err(one_line(&message.to_string()))
}

/// `RuntimeError(message)`: a run that cannot go on (a divergence, a coupling without forces).
pub fn runtime_error(message: impl std::fmt::Display) -> PyErr {
    PyRuntimeError::new_err(one_line(&message.to_string()))
}

/// The message on one line: a Rust error's further lines (a divergence's advice) joined by `; `.
fn one_line(message: &str) -> String {
    let lines: Vec<&str> = message.lines().map(str::trim).filter(|l| !l.is_empty()).collect();
    lines.join("; ")
}

/// Runs `work`, turning a panic into `RuntimeError` (a bug of Tether's, said so) so that no
/// unwind crosses into Python.
pub fn guarded<T>(work: impl FnOnce() -> PyResult<T>) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(work)).unwrap_or_else(|payload| Err(runtime_error(panic_text(payload.as_ref()))))
}

/// Like [`guarded`] for work that holds no Python object (run with the GIL released).
pub fn caught<T>(work: impl FnOnce() -> T) -> Result<T, String> {
    catch_unwind(AssertUnwindSafe(work)).map_err(|payload| panic_text(payload.as_ref()))
}

fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    let what = payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "(no message)".into());
    format!("internal error in Tether (a bug: please report it): {what}")
}

/// `x` if it is a finite number, else `ValueError` naming `name`.
pub fn finite(name: &str, x: f64) -> PyResult<f64> {
    if x.is_finite() { Ok(x) } else { Err(value_error(format!("`{name}` must be a finite number, got {x}"))) }
}
