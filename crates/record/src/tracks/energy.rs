//! Energy: the energy balance (PHYSICS.md §5) [J] in two plots, `plots/energy/stored` (series
//! `gravity`, `elastic`, `total`, `balance`) and `plots/energy/moving` (`kinetic`, `dissipated`,
//! `external_work`), so that each plot's legend lists only its own series.

use super::{Settings, Track, send_chunk};
use crate::columns::plot;
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::energy::EnergyReport;
use tether_physics::world::World;

/// The stored energies' series, in the order logged.
const STORED: [&str; 4] = ["gravity", "elastic", "total", "balance"];
/// The moving terms' series, in the order logged.
const MOVING: [&str; 3] = ["kinetic", "dissipated", "external_work"];

/// The energies, frame-major (frame f, series s of `STORED` at `4 f + s`).
#[derive(Default)]
pub(super) struct EnergyPlot {
    stored: Vec<f64>,
    moving: Vec<f64>,
}

impl EnergyPlot {
    fn stored(energy: &EnergyReport) -> [f64; STORED.len()] {
        [energy.gravity, energy.elastic, energy.total(), energy.balance()]
    }

    fn moving(energy: &EnergyReport) -> [f64; MOVING.len()] {
        [energy.kinetic, energy.dissipated, energy.external_work]
    }
}

impl Track for EnergyPlot {
    fn log_static(&self, stream: &RecordingStream, _world: &World) -> Result<(), RecordError> {
        stream.log_static(paths::ENERGY_STORED, &rerun::SeriesLines::new().with_names(STORED))?;
        stream.log_static(paths::ENERGY_MOVING, &rerun::SeriesLines::new().with_names(MOVING))?;
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        let energy = world.energy();
        self.stored.extend(Self::stored(&energy));
        self.moving.extend(Self::moving(&energy));
        (STORED.len() + MOVING.len()) * 8
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        let stored = plot(std::mem::take(&mut self.stored), STORED.len());
        send_chunk(stream, paths::ENERGY_STORED, frames.columns(), vec![stored], sent)?;
        let moving = plot(std::mem::take(&mut self.moving), MOVING.len());
        send_chunk(stream, paths::ENERGY_MOVING, frames.columns(), vec![moving], sent)
    }
}
