//! `tether._tether`, the native half of the `tether` Python package (PyO3, abi3 for CPython
//! ≥ 3.9): a scene loaded from a file or RON text ([`simulation`]), its parameters read and set
//! by the sweep's parameter paths ([`parameters`]), stepped and run with the GIL released and
//! sampled into flat arrays ([`advance`], [`samples`]), its statics ([`statics`]), a sweep spec
//! run ([`sweep`]), a calibration fit ([`fit`]) and a run recorded to `.rrd` ([`record`]). The
//! Python half (`tether/`) turns the flat arrays into numpy arrays and tables.
//!
//! Every failure is a one-line Python exception ([`errors`]): `ValueError` for input the
//! loader, a validator or a solver refuses (the CLI's own text), `TypeError` for a wrong type,
//! `RuntimeError` for a run that diverges, `KeyboardInterrupt` on Ctrl-C. A Rust panic is
//! caught at the boundary and raised as `RuntimeError`; it never unwinds into the interpreter.

mod advance;
mod background;
mod errors;
mod fit;
mod parameters;
mod record;
mod samples;
mod simulation;
mod statics;
mod sweep;

use pyo3::prelude::*;

/// The native module.
#[pymodule]
fn _tether(module: &Bound<'_, PyModule>) -> PyResult<()> {
    module.add_class::<simulation::Simulation>()?;
    module.add_function(wrap_pyfunction!(sweep::run_sweep, module)?)?;
    module.add_function(wrap_pyfunction!(sweep::read_parquet, module)?)?;
    module.add_function(wrap_pyfunction!(fit::run_fit, module)?)?;
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
