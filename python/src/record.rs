//! A run recorded to a Rerun `.rrd` file through the recorder crate (the SDK, no viewer), as
//! `tether record` writes it: a frame at the start, then at the steps the [`FrameSchedule`]
//! makes due, the file's footer written at the end, or at a Ctrl-C or a divergence (the
//! recording then holds everything up to there). The GIL stays held (the recorder is not
//! `Send`); Python signal handlers run between slices of steps.

use crate::advance::advance_holding_gil;
use crate::errors::value_error;
use pyo3::prelude::*;
use std::path::Path;
use tether_physics::world::World;
use tether_record::{FaceArrows, FrameSchedule, Recorder};

/// Records `steps` steps of `world` to `path` at `log_hz` frames per simulated second.
///
/// # Errors
/// A file that cannot be written (`ValueError`), a divergence (`RuntimeError`), Ctrl-C
/// (`KeyboardInterrupt`), each after the recording was finished up to there.
pub fn record(py: Python<'_>, world: &mut World, path: &Path, steps: u64, log_hz: f64) -> PyResult<()> {
    let failed = |e: tether_record::RecordError| value_error(format!("cannot write {}: {e}", path.display()));
    let mut recorder = Recorder::to_file(path, world, &FaceArrows::default()).map_err(failed)?;
    recorder.log_frame(world).map_err(failed)?;
    let schedule = FrameSchedule::new(log_hz, world.dt(), steps);
    let mut logged = Ok(());
    let ran = advance_holding_gil(py, world, steps, |step, world| {
        if logged.is_ok() && schedule.is_due(step) {
            logged = recorder.log_frame(world);
        }
    });
    let finished = recorder.finish();
    ran?;
    logged.map_err(failed)?;
    finished.map(drop).map_err(failed)
}
