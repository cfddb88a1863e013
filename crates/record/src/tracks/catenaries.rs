//! Catenaries: `world/couplings/<name>` holds the line along its solved shape, 32 segments in 8
//! bands coloured by tension (blue: the lowest tension along the line, red: the highest) every
//! frame, its width static; `plots/catenary` holds the end tensions of every line, series
//! `<name> end1` and `<name> end2` [N].
//!
//! A band is one strip of 4 segments with one colour: 40 points and 8 colours a frame, 576 bytes
//! with the row's index, where 32 two-point strips took 1,116 — the file writer compresses every
//! byte, and a line's tension changes smoothly along it.

use super::{Settings, Track, f32x3, send_chunk};
use crate::columns::{colors, column, plot, strips};
use crate::frames::Frames;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::CouplingKind;
use tether_physics::coupling::catenary::LineState;
use tether_physics::world::World;

/// Segments a line is drawn with.
const SEGMENTS: usize = 32;

/// Colour bands along a line, each a strip of `SEGMENTS / BANDS` segments.
const BANDS: usize = 8;

/// One catenary's buffered frames.
struct Line {
    /// Coupling index in the world.
    index: usize,
    path: String,
    /// The strips' points and colours, frame after frame; `points_per_strip` says how many
    /// points each strip has, `strips_per_frame` how many strips each frame has.
    points: Vec<[f32; 3]>,
    points_per_strip: Vec<usize>,
    colors: Vec<rerun::Color>,
    strips_per_frame: Vec<usize>,
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
            .map(|(index, coupling)| Line {
                index,
                path: paths::coupling(coupling),
                points: Vec::new(),
                points_per_strip: Vec::new(),
                colors: Vec::new(),
                strips_per_frame: Vec::new(),
            })
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
            let points_before = line.points.len();
            let (strips, (t1, t2)) = match world.line_state(line.index) {
                Some(state) => (shape(state, line), state.end_tensions()),
                // Not solved yet: the chord, and the forces at the ends.
                None => {
                    line.points.extend([f32x3(&forces.point1), f32x3(&forces.point2)]);
                    line.points_per_strip.push(2);
                    line.colors.push(rerun::Color::from_rgb(60, 90, 255));
                    (1, (forces.f1.norm(), forces.f2.norm()))
                }
            };
            line.strips_per_frame.push(strips);
            self.end_tensions.extend([t1, t2]);
            bytes += (line.points.len() - points_before) * 3 * 4 + strips * (4 + 4) + 2 * 8;
        }
        bytes
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        for line in &mut self.lines {
            let shape = vec![
                column(
                    rerun::LineStrips3D::descriptor_strips(),
                    strips(line.points.drain(..), line.points_per_strip.drain(..)),
                    line.strips_per_frame.iter().copied(),
                ),
                column(
                    rerun::LineStrips3D::descriptor_colors(),
                    colors(line.colors.drain(..)),
                    line.strips_per_frame.iter().copied(),
                ),
            ];
            send_chunk(stream, &line.path, frames.columns(), shape, sent)?;
            line.strips_per_frame.clear();
        }
        let tensions = plot(std::mem::take(&mut self.end_tensions), 2 * self.lines.len());
        send_chunk(stream, paths::CATENARY_PLOT, frames.columns(), vec![tensions], sent)
    }
}

/// Appends the bands of `state`'s shape to `line`, each coloured by its mean tension on a
/// blue → red ramp between the lowest and highest tension along the line; returns how many.
fn shape(state: &LineState, line: &mut Line) -> usize {
    let points = state.sample(SEGMENTS);
    let (low, high) = points.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), (_, t)| (lo.min(*t), hi.max(*t)));
    let span = (high - low).max(f64::MIN_POSITIVE);
    // Neighbouring bands share their end point; the last band takes what SEGMENTS / BANDS leaves.
    let per_band = (points.len() - 1).div_ceil(BANDS).max(1);
    let mut strips = 0;
    for first in (0..points.len() - 1).step_by(per_band) {
        let band = &points[first..(first + per_band + 1).min(points.len())];
        let mean = band.iter().map(|(_, tension)| tension).sum::<f64>() / band.len() as f64;
        let heat = ((mean - low) / span).clamp(0.0, 1.0);
        line.points.extend(band.iter().map(|(point, _)| f32x3(point)));
        line.points_per_strip.push(band.len());
        line.colors.push(rerun::Color::from_rgb((60.0 + 195.0 * heat) as u8, 90, (255.0 - 195.0 * heat) as u8));
        strips += 1;
    }
    strips
}
