//! The frames a recorder holds before it sends them: each one's simulated time and world step,
//! the recording's two timelines (`sim_time` [s] and `step`).

use rerun::log::TimeColumn;
use std::cell::OnceCell;
use tether_physics::world::World;

/// The recording's timeline of simulated time [s].
pub const SIM_TIME: &str = "sim_time";
/// The recording's timeline of world steps.
pub const STEP: &str = "step";

/// Buffered frames: the instant of each, in the order captured.
#[derive(Debug, Default)]
pub(crate) struct Frames {
    /// Simulated time [s].
    times: Vec<f64>,
    /// World steps since t = 0.
    steps: Vec<i64>,
    /// Both timelines over every buffered frame, built once for all the entities a flush sends
    /// (a clone shares the Arrow buffers).
    columns: OnceCell<[TimeColumn; 2]>,
}

impl Frames {
    /// Adds the world's current instant; returns the new frame's index.
    pub(crate) fn push(&mut self, world: &World) -> usize {
        self.columns.take();
        self.times.push(world.time());
        // Beyond i64::MAX steps (2.9e5 years at 1 µs) the count would not fit: saturate.
        self.steps.push(i64::try_from(world.steps()).unwrap_or(i64::MAX));
        self.times.len() - 1
    }

    pub(crate) fn len(&self) -> usize {
        self.times.len()
    }

    pub(crate) fn is_empty(&self) -> bool {
        self.times.is_empty()
    }

    pub(crate) fn clear(&mut self) {
        self.times.clear();
        self.steps.clear();
        self.columns.take();
    }

    /// Both timelines over every buffered frame.
    pub(crate) fn columns(&self) -> [TimeColumn; 2] {
        self.columns.get_or_init(|| self.columns_of(0..self.len())).clone()
    }

    /// Both timelines over the buffered frames `frames` (indices, ascending).
    pub(crate) fn columns_of(&self, frames: impl Iterator<Item = usize> + Clone) -> [TimeColumn; 2] {
        [
            TimeColumn::new_duration_secs(SIM_TIME, frames.clone().map(|frame| self.times[frame])),
            TimeColumn::new_sequence(STEP, frames.map(|frame| self.steps[frame])),
        ]
    }
}
