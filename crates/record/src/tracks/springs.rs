//! Spring-dampers: `world/springs` holds every spring-damper's line between its ends, one strip
//! each in scene order, every frame; the strips' labels (static, shown on hover) are the
//! couplings' names. One entity for all of them: a chain of a hundred springs costs one row
//! per frame, not a hundred.

use super::{Settings, Track, f32x3, send_chunk};
use crate::columns::{column, strips};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::CouplingKind;
use tether_physics::world::World;

/// Bytes buffered per spring and frame: two ends in `f32`.
const BYTES_PER_LINE: usize = 2 * 3 * 4;

/// The spring-dampers' lines, frame-major (frame f, spring s at `f × springs + s`).
pub(super) struct Springs {
    /// Coupling index in the world of each spring-damper.
    springs: Vec<usize>,
    ends: Vec<[[f32; 3]; 2]>,
}

impl Springs {
    /// The world's spring-dampers (`None` when it has none).
    pub(super) fn new(world: &World) -> Option<Self> {
        let springs: Vec<usize> = world
            .couplings()
            .iter()
            .enumerate()
            .filter(|(_, coupling)| matches!(coupling.kind, CouplingKind::SpringDamper(_)))
            .map(|(index, _)| index)
            .collect();
        (!springs.is_empty()).then_some(Self { springs, ends: Vec::new() })
    }
}

impl Track for Springs {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        let names = self.springs.iter().map(|&index| world.couplings()[index].name.as_str());
        stream.log_static(
            paths::SPRINGS,
            &rerun::LineStrips3D::update_fields().with_labels(names).with_show_labels(false),
        )?;
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        let forces = world.coupling_forces();
        self.ends
            .extend(self.springs.iter().map(|&index| [f32x3(&forces[index].point1), f32x3(&forces[index].point2)]));
        self.springs.len() * BYTES_PER_LINE
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        let lines = strips(self.ends.drain(..).flatten(), std::iter::repeat_n(2, frames.len() * self.springs.len()));
        let lines = column(
            rerun::LineStrips3D::descriptor_strips(),
            lines,
            std::iter::repeat_n(self.springs.len(), frames.len()),
        );
        send_chunk(stream, paths::SPRINGS, frames.columns(), vec![lines], sent)
    }
}
