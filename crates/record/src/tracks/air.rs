//! The air's forces (PHYSICS.md §10): per wind-loaded body, `plots/air/<body>`, its windage's
//! and its rotor's force along x and y and their moment about G's z, as the air stage records
//! them (about G, world axes).

use super::{Settings, Track, of_entity, send_chunk};
use crate::columns::plot;
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::world::World;

/// The series of an air plot.
pub const AIR_SERIES: [&str; 6] =
    ["windage Fx [N]", "windage Fy [N]", "windage Mz [N·m]", "rotor Fx [N]", "rotor Fy [N]", "rotor My [N·m]"];

/// The air's buffered frames: per wind-loaded body, frame-major, its six series.
pub(super) struct AirTrack {
    bodies: Vec<(usize, String)>,
    values: Vec<[f64; 6]>,
}

impl AirTrack {
    /// The air of `world` (`None` when it has none, or it loads no body).
    pub(super) fn new(world: &World) -> Option<Self> {
        let stage = world.system().air()?;
        let bodies: Vec<_> =
            stage.bodies().iter().map(|b| (b.body(), paths::air_plot(&world.bodies()[b.body()].name))).collect();
        (!bodies.is_empty()).then_some(Self { bodies, values: Vec::new() })
    }

    /// One plot per wind-loaded body.
    pub(super) fn entities(&self) -> usize {
        self.bodies.len()
    }
}

impl Track for AirTrack {
    fn log_static(&self, stream: &RecordingStream, _world: &World) -> Result<(), RecordError> {
        for (_, path) in &self.bodies {
            stream.log_static(path.as_str(), &rerun::SeriesLines::new().with_names(AIR_SERIES))?;
        }
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        for (body, _) in &self.bodies {
            // A body the stage has no record of (none evaluated yet) bears no wind.
            let record = world.air_forces().iter().find(|r| r.body == *body).copied().unwrap_or_default();
            let (w, r) = (&record.windage, &record.rotor);
            self.values.push([w.force.x, w.force.y, w.moment.z, r.force.x, r.force.y, r.moment.y]);
        }
        self.bodies.len() * 6 * 8
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        let count = self.bodies.len();
        for (index, (_, path)) in self.bodies.iter().enumerate() {
            let values = of_entity(&self.values, index, count).flatten().collect();
            send_chunk(stream, path, frames.columns(), vec![plot(values, 6)], sent)?;
        }
        self.values.clear();
        Ok(())
    }
}
