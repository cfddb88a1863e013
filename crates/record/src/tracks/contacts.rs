//! Contact forces: `plots/contact` holds every contact's total normal force `Σ|f_n|` and friction
//! `|Σ f_t|` [N], series `<name> normal` and `<name> friction`, as the step summed them (the
//! faces are not evaluated again).

use super::{Settings, Track, send_chunk};
use crate::columns::plot;
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::CouplingKind;
use tether_physics::world::World;

/// The contacts' forces, frame-major (frame f, contact c's normal force and friction at
/// `2 (f × contacts + c)` and the next).
pub(super) struct ContactPlot {
    /// Coupling index in the world of each contact.
    contacts: Vec<usize>,
    forces: Vec<f64>,
}

impl ContactPlot {
    /// The world's contacts (`None` when it has none).
    pub(super) fn new(world: &World) -> Option<Self> {
        let contacts: Vec<usize> = world
            .couplings()
            .iter()
            .enumerate()
            .filter(|(_, coupling)| matches!(coupling.kind, CouplingKind::Contact(_)))
            .map(|(index, _)| index)
            .collect();
        (!contacts.is_empty()).then_some(Self { contacts, forces: Vec::new() })
    }
}

impl Track for ContactPlot {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        let names = self.contacts.iter().flat_map(|&index| {
            let name = &world.couplings()[index].name;
            [format!("{name} normal"), format!("{name} friction")]
        });
        stream.log_static(paths::CONTACT_PLOT, &rerun::SeriesLines::new().with_names(names))?;
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        for &index in &self.contacts {
            let forces = world.evaluation().contact_forces(index).unwrap_or_default();
            self.forces.extend([forces.normal, forces.friction]);
        }
        self.contacts.len() * 2 * 8
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        let series = 2 * self.contacts.len();
        send_chunk(
            stream,
            paths::CONTACT_PLOT,
            frames.columns(),
            vec![plot(std::mem::take(&mut self.forces), series)],
            sent,
        )
    }
}
