//! The frames a recorder holds before it sends them: each one's simulated time and world step,
//! the recording's two timelines (`sim_time` [s] and `step`).

use crate::rerun;
use rerun::log::TimeColumn;
use std::cell::OnceCell;
use tether_physics::world::World;

/// The recording's timeline of simulated time \[s].
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

/// When a run of fixed steps logs a frame: at the steps where the simulated time crosses a
/// multiple of `1/log_hz`, so that a run logs `log_hz` frames per simulated second on average
/// whatever its time step (a whole number of steps per frame gave 66.7 frames a second for 60 at
/// dt = 5 ms: 3 steps, not 3.33); every step when the rate asks for more frames than steps; and
/// at the run's last step, so that the recording ends where the run does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameSchedule {
    /// Frames per step, `log_hz · dt`.
    frames_per_step: f64,
    /// The run's last step.
    last_step: u64,
}

impl FrameSchedule {
    /// `log_hz` frames per simulated second [1/s] over a run of `last_step` steps of `dt` \[s].
    pub fn new(log_hz: f64, dt: f64, last_step: u64) -> Self {
        Self { frames_per_step: log_hz * dt, last_step }
    }

    /// Whether a frame is due after step `step` (1, 2, …).
    pub fn is_due(&self, step: u64) -> bool {
        step == self.last_step || self.frames_until(step) > self.frames_until(step.saturating_sub(1))
    }

    /// Frame periods elapsed by step `step`; the tolerance keeps an exact multiple (dt = 1 ms,
    /// 10 Hz: every 100th step) from falling a rounding below it.
    fn frames_until(&self, step: u64) -> f64 {
        (step as f64 * self.frames_per_step + 1e-9).floor()
    }
}

#[cfg(test)]
mod tests {
    use super::FrameSchedule;

    fn frames(log_hz: f64, dt: f64, steps: u64) -> Vec<u64> {
        let schedule = FrameSchedule::new(log_hz, dt, steps);
        (1..=steps).filter(|&step| schedule.is_due(step)).collect()
    }

    #[test]
    fn a_whole_number_of_steps_per_frame_gives_every_nth_step() {
        assert_eq!(frames(10.0, 1e-3, 500), vec![100, 200, 300, 400, 500]);
        assert_eq!(frames(20.0, 1e-3, 200), vec![50, 100, 150, 200]);
        assert_eq!(frames(10.0, 2e-3, 150), vec![50, 100, 150]);
    }

    #[test]
    fn sixty_frames_a_second_at_five_millisecond_steps_is_sixty() {
        // 3.33 steps per frame: steps of 3, 3 and 4, 1200 frames in 20 s (4000 steps).
        let due = frames(60.0, 5e-3, 4000);
        assert_eq!(due.len(), 1200);
        assert_eq!(&due[..4], &[4, 7, 10, 14]);
    }

    #[test]
    fn the_last_step_has_a_frame() {
        // 0.35 s at 1 ms, 10 Hz: frames at 0.1, 0.2, 0.3 s and at the end.
        assert_eq!(frames(10.0, 1e-3, 350), vec![100, 200, 300, 350]);
    }

    #[test]
    fn more_frames_than_steps_is_a_frame_every_step() {
        assert_eq!(frames(1000.0, 5e-3, 5), vec![1, 2, 3, 4, 5]);
    }
}
