//! Tension: `plots/tension` holds every coupling's tension [N], one series each named after it
//! (positive in tension; a catenary's is its larger end tension, a contact's its normal force).

use super::{Settings, Track, send_chunk};
use crate::columns::plot;
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::world::World;

/// The couplings' tensions, frame-major (frame f, coupling c at `f × couplings + c`).
pub(super) struct TensionPlot {
    couplings: usize,
    tensions: Vec<f64>,
}

impl TensionPlot {
    /// The world's couplings (`None` when it has none).
    pub(super) fn new(world: &World) -> Option<Self> {
        let couplings = world.couplings().len();
        (couplings > 0).then_some(Self { couplings, tensions: Vec::new() })
    }
}

impl Track for TensionPlot {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        stream.log_static(
            paths::TENSION,
            &rerun::SeriesLines::new().with_names(world.couplings().iter().map(|c| c.name.as_str())),
        )?;
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        self.tensions.extend(world.coupling_forces().iter().map(|forces| forces.tension));
        self.couplings * 8
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        send_chunk(
            stream,
            paths::TENSION,
            frames.columns(),
            vec![plot(std::mem::take(&mut self.tensions), self.couplings)],
            sent,
        )
    }
}
