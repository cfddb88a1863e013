//! Catenaries: `world/couplings/<name>` holds the line along its solved shape, 32 segments
//! coloured by tension (blue: the lowest tension along the line, red: the highest) every frame,
//! its width static; `plots/catenary` holds the end tensions of every line, series
//! `<name> end1` and `<name> end2` [N].

use super::{Settings, Track, f32x3, send_chunk};
use crate::frames::Frames;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::CouplingKind;
use tether_physics::coupling::catenary::LineState;
use tether_physics::world::World;

/// Segments a line is drawn with.
const SEGMENTS: usize = 32;

/// One catenary's buffered frames.
struct Line {
    /// Coupling index in the world.
    index: usize,
    path: String,
    /// Segments and their colours, frame after frame; `segments_per_frame` says how many each
    /// frame has.
    segments: Vec<[[f32; 3]; 2]>,
    colors: Vec<rerun::Color>,
    segments_per_frame: Vec<usize>,
}

/// The world's catenaries and their end tensions, frame-major (frame f, line l's `end1` and
/// `end2` at `2 (f × lines + l)` and the next).
pub(super) struct Catenaries {
    lines: Vec<Line>,
    end_tensions: Vec<f64>,
}

impl Catenaries {
    /// The world's catenaries (`None` when it has none).
    pub(super) fn new(world: &World) -> Option<Self> {
        let lines: Vec<Line> = world
            .couplings()
            .iter()
            .enumerate()
            .filter(|(_, coupling)| matches!(coupling.kind, CouplingKind::Catenary(_)))
            .map(|(index, coupling)| Line { index, path: paths::coupling(coupling), segments: Vec::new(), colors: Vec::new(), segments_per_frame: Vec::new() })
            .collect();
        (!lines.is_empty()).then_some(Self { lines, end_tensions: Vec::new() })
    }

    pub(super) fn len(&self) -> usize {
        self.lines.len()
    }
}

impl Track for Catenaries {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        let width = rerun::LineStrips3D::update_fields().with_radii([rerun::Radius::new_ui_points(2.5)]);
        for line in &self.lines {
            stream.log_static(line.path.as_str(), &width)?;
        }
        let names = self.lines.iter().flat_map(|line| {
            let name = &world.couplings()[line.index].name;
            [format!("{name} end1"), format!("{name} end2")]
        });
        stream.log_static(paths::CATENARY_PLOT, &rerun::SeriesLines::new().with_names(names))?;
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        let mut bytes = 0;
        for line in &mut self.lines {
            let forces = &world.coupling_forces()[line.index];
            let (segments, (t1, t2)) = match world.line_state(line.index) {
                Some(state) => (shape(state, &mut line.segments, &mut line.colors), state.end_tensions()),
                // Not solved yet: the chord, and the forces at the ends.
                None => {
                    line.segments.push([f32x3(&forces.point1), f32x3(&forces.point2)]);
                    line.colors.push(rerun::Color::from_rgb(60, 90, 255));
                    (1, (forces.f1.norm(), forces.f2.norm()))
                }
            };
            line.segments_per_frame.push(segments);
            self.end_tensions.extend([t1, t2]);
            bytes += segments * (2 * 3 * 4 + 4) + 2 * 8;
        }
        bytes
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        for line in &mut self.lines {
            let strips = rerun::LineStrips3D::update_fields().with_strips(line.segments.drain(..)).with_colors(line.colors.drain(..));
            send_chunk(stream, &line.path, frames.columns(), frames.len(), strips.columns(line.segments_per_frame.iter().copied())?, sent)?;
            line.segments_per_frame.clear();
        }
        let series = 2 * self.lines.len();
        let tensions = rerun::Scalars::new(self.end_tensions.drain(..));
        send_chunk(stream, paths::CATENARY_PLOT, frames.columns(), frames.len(), tensions.columns(std::iter::repeat_n(series, frames.len()))?, sent)?;
        Ok(())
    }
}

/// Appends the segments of `state`'s shape and their colours, on a blue → red ramp between the
/// lowest and highest tension along the line; returns how many.
fn shape(state: &LineState, segments: &mut Vec<[[f32; 3]; 2]>, colors: &mut Vec<rerun::Color>) -> usize {
    let points = state.sample(SEGMENTS);
    let (low, high) = points.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), (_, t)| (lo.min(*t), hi.max(*t)));
    let span = (high - low).max(f64::MIN_POSITIVE);
    segments.extend(points.windows(2).map(|pair| [f32x3(&pair[0].0), f32x3(&pair[1].0)]));
    colors.extend(points.windows(2).map(|pair| {
        let heat = ((0.5 * (pair[0].1 + pair[1].1) - low) / span).clamp(0.0, 1.0);
        rerun::Color::from_rgb((60.0 + 195.0 * heat) as u8, 90, (255.0 - 195.0 * heat) as u8)
    }));
    points.len() - 1
}
