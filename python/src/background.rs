//! A long run (a sweep, a fit) on a thread of its own while the caller's thread waits with the
//! GIL released, running Python's signal handlers every [`POLL`]: a Ctrl-C sets the run's
//! cancel flag (the runner's), so the run stops at its next check, and the signal's exception is
//! handed back for the caller to raise or not.

use pyo3::prelude::*;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

/// How often the waiting thread looks at Python's signals.
pub const POLL: Duration = Duration::from_millis(50);

/// Runs `work` on its own thread until it ends; a Ctrl-C (any exception a signal handler
/// raises) on the way sets `cancel` and is returned beside the result.
pub fn run<T: Send + 'static>(
    py: Python<'_>,
    cancel: &Arc<AtomicBool>,
    work: impl FnOnce() -> T + Send + 'static,
) -> (std::thread::Result<T>, Option<PyErr>) {
    let worker = std::thread::spawn(work);
    let mut interrupt = None;
    while !worker.is_finished() {
        py.detach(|| std::thread::sleep(POLL));
        if let Err(signal) = py.check_signals() {
            cancel.store(true, Ordering::SeqCst);
            interrupt = Some(signal);
            break;
        }
    }
    (py.detach(|| worker.join()), interrupt)
}
