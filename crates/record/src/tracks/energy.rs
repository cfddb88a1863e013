//! Energy: `plots/energy` holds the energy balance (PHYSICS.md §5) [J], series `kinetic`,
//! `gravity`, `elastic`, `dissipated`, `external_work`, `total` and `balance`, in one plot.

use super::{Settings, Track, send_chunk};
use crate::columns::plot;
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::world::World;

/// Energy series, in the order logged.
const SERIES: [&str; 7] = ["kinetic", "gravity", "elastic", "dissipated", "external_work", "total", "balance"];

/// The energies, frame-major (frame f, series s at `7 f + s`).
#[derive(Default)]
pub(super) struct EnergyPlot {
    energies: Vec<f64>,
}

impl Track for EnergyPlot {
    fn log_static(&self, stream: &RecordingStream, _world: &World) -> Result<(), RecordError> {
        stream.log_static(paths::ENERGY, &rerun::SeriesLines::new().with_names(SERIES))?;
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        let energy = world.energy();
        self.energies.extend([
            energy.kinetic,
            energy.gravity,
            energy.elastic,
            energy.dissipated,
            energy.external_work,
            energy.total(),
            energy.balance(),
        ]);
        SERIES.len() * 8
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        let energies = plot(std::mem::take(&mut self.energies), SERIES.len());
        send_chunk(stream, paths::ENERGY, frames.columns(), vec![energies], sent)
    }
}
