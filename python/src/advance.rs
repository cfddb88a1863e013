//! Stepping a world from Python in slices of about [`SLICE`] of wall time, Python's signal
//! handlers run between them, so that Ctrl-C raises `KeyboardInterrupt` within a fraction of a
//! second. [`advance`] releases the GIL during each slice (other Python threads progress);
//! [`advance_holding_gil`] keeps it, for work that cannot leave the thread's Python state (the
//! recorder, whose tracks are not `Send`).

use crate::errors::{caught, runtime_error};
use pyo3::prelude::*;
use std::time::{Duration, Instant};
use tether_physics::world::World;

/// Wall time of one slice of steps.
const SLICE: Duration = Duration::from_millis(20);

/// The clock is read every this many steps (a reading costs about a tenth of the cheapest
/// scene's step).
const CLOCK_EVERY: u64 = 64;

/// Below this many steps a call keeps the GIL: releasing it costs more than the steps.
const RELEASE_FROM: u64 = 256;

/// Steps `world` `count` times, calling `after(step, world)` after each (step 1 … `count`), the
/// GIL released during each slice.
///
/// # Errors
/// A step that fails (`RuntimeError` with the physics' message: a divergence, a coupling
/// without forces), a panic (`RuntimeError`), or a Python signal handler's exception
/// (`KeyboardInterrupt` on Ctrl-C) between slices; the steps done so far stay done.
pub fn advance(
    py: Python<'_>,
    world: &mut World,
    count: u64,
    mut after: impl FnMut(u64, &World) + Send,
) -> PyResult<()> {
    if count < RELEASE_FROM {
        return advance_holding_gil(py, world, count, after);
    }
    let mut done = 0;
    while done < count {
        py.detach(|| caught(|| slice(world, count, &mut done, &mut after)))
            .and_then(|stepped| stepped)
            .map_err(runtime_error)?;
        py.check_signals()?;
    }
    Ok(())
}

/// As [`advance`], the GIL held throughout.
///
/// # Errors
/// As [`advance`].
pub fn advance_holding_gil(
    py: Python<'_>,
    world: &mut World,
    count: u64,
    mut after: impl FnMut(u64, &World),
) -> PyResult<()> {
    let mut done = 0;
    while done < count {
        caught(|| slice(world, count, &mut done, &mut after)).and_then(|stepped| stepped).map_err(runtime_error)?;
        py.check_signals()?;
    }
    Ok(())
}

/// Steps from `*done` towards `count` for about [`SLICE`].
fn slice(world: &mut World, count: u64, done: &mut u64, after: &mut impl FnMut(u64, &World)) -> Result<(), String> {
    let start = Instant::now();
    while *done < count {
        world.step().map_err(|e| e.to_string())?;
        *done += 1;
        after(*done, world);
        if done.is_multiple_of(CLOCK_EVERY) && start.elapsed() > SLICE {
            break;
        }
    }
    Ok(())
}
