//! Catenaries: `world/couplings/<name>` holds the line along its solved shape, 32 segments in 8
//! bands coloured by tension (blue: the lowest tension along the line, red: the highest) every
//! frame, its width static; a dynamic line (PHYSICS.md §8) is drawn through its nodes, banded
//! the same way by its segments' tensions. `plots/catenary` holds the end tensions of every
//! line, series `<name> end1` and `<name> end2` \[N], and for a dynamic line, in the same plot,
//! `plots/catenary/quasi-static/<name>` the quasi-static catenary's for the same end positions,
//! `<name> end1 quasi-static` and `<name> end2 quasi-static`: its dynamic amplification. Each
//! entity keeps its number of series for the whole recording (the viewer warns when it varies),
//! so a line switched to dynamic while it runs adds an entity rather than series.
//!
//! A band is one strip of 4 segments with one colour: 40 points and 8 colours a frame, 576 bytes
//! with the row's index, where 32 two-point strips took 1,116 — the file writer compresses every
//! byte, and a line's tension changes smoothly along it.

use super::{Settings, Track, f32x3, send_chunk};
use crate::columns::{colors, column, plot, strips};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::lumped_line::LineRun;
use tether_physics::coupling::{CouplingKind, LineModel};
use tether_physics::math::Vec3;
use tether_physics::world::World;

/// Segments a line is drawn with.
const SEGMENTS: usize = 32;

/// Colour bands along a line, each a strip of `SEGMENTS / BANDS` segments.
const BANDS: usize = 8;

/// One catenary's buffered frames.
struct Line {
    /// Coupling index in the world.
    index: usize,
    /// Where a dynamic line's quasi-static end tensions go (`None`: a quasi-static line).
    quasi_static_plot: Option<String>,
    /// The quasi-static end tensions \[N], frame-major (`end1`, `end2` of each frame).
    quasi_static: Vec<f64>,
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
            .filter_map(|(index, coupling)| match &coupling.kind {
                CouplingKind::Catenary(line) => Some((index, coupling, line.model() != LineModel::QuasiStatic)),
                CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => None,
            })
            .map(|(index, coupling, dynamic)| Line {
                index,
                quasi_static_plot: dynamic.then(|| paths::quasi_static_plot(&coupling.name)),
                quasi_static: Vec::new(),
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
        for line in &self.lines {
            if let Some(plot) = &line.quasi_static_plot {
                let name = &world.couplings()[line.index].name;
                let names = [format!("{name} end1 quasi-static"), format!("{name} end2 quasi-static")];
                stream.log_static(plot.as_str(), &rerun::SeriesLines::new().with_names(names))?;
            }
        }
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        let mut bytes = 0;
        for line in &mut self.lines {
            let forces = &world.coupling_forces()[line.index];
            let points_before = line.points.len();
            let run = world.evaluation().line_run(line.index);
            let mut quasi_static = None;
            let (strips, (t1, t2)) = match (run, world.line_state(line.index)) {
                (Some(run), _) if run.nodes().is_some() => {
                    quasi_static = Some(quasi_static_tensions(world, &world.couplings()[line.index], forces));
                    (bands(&nodes_with_tensions(run), line), (forces.f1.norm(), forces.f2.norm()))
                }
                (_, Some(state)) => (bands(&state.sample(SEGMENTS), line), state.end_tensions()),
                // Not solved yet: the chord, and the forces at the ends.
                (_, None) => {
                    line.points.extend([f32x3(&forces.point1), f32x3(&forces.point2)]);
                    line.points_per_strip.push(2);
                    line.colors.push(rerun::Color::from_rgb(60, 90, 255));
                    (1, (forces.f1.norm(), forces.f2.norm()))
                }
            };
            line.strips_per_frame.push(strips);
            self.end_tensions.extend([t1, t2]);
            if line.quasi_static_plot.is_some() {
                // Before the first evaluation, the dynamic line's own ends stand in.
                line.quasi_static.extend(quasi_static.unwrap_or([t1, t2]));
            }
            let series = if line.quasi_static_plot.is_some() { 4 } else { 2 };
            bytes += (line.points.len() - points_before) * 3 * 4 + strips * (4 + 4) + series * 8;
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
            if let Some(path) = &line.quasi_static_plot {
                let tensions = plot(std::mem::take(&mut line.quasi_static), 2);
                send_chunk(stream, path, frames.columns(), vec![tensions], sent)?;
            }
        }
        let tensions = plot(std::mem::take(&mut self.end_tensions), 2 * self.lines.len());
        send_chunk(stream, paths::CATENARY_PLOT, frames.columns(), vec![tensions], sent)
    }
}

/// A dynamic line's nodes, each with the mean tension of its segments \[m, N].
fn nodes_with_tensions(run: &LineRun) -> Vec<(Vec3, f64)> {
    let (Some(nodes), tensions) = (run.nodes(), run.tensions()) else { return Vec::new() };
    let last = tensions.len().saturating_sub(1);
    nodes
        .positions
        .iter()
        .enumerate()
        .map(|(i, point)| (*point, 0.5 * (tensions[i.saturating_sub(1).min(last)] + tensions[i.min(last)])))
        .collect()
}

/// The end tensions \[N] of `coupling`, a dynamic line, as the quasi-static catenary would
/// have them at the same end positions (those of `forces`); zeros if it cannot be solved.
fn quasi_static_tensions(
    world: &World,
    coupling: &tether_physics::coupling::Coupling,
    forces: &tether_physics::coupling::CouplingForces,
) -> [f64; 2] {
    let CouplingKind::Catenary(line) = &coupling.kind else { return [0.0; 2] };
    let quasi_static = line.clone().with_model(LineModel::QuasiStatic);
    quasi_static
        .solve(&forces.point1, &forces.point2, world.system().surroundings(), None)
        .map_or([0.0; 2], |state| state.end_tensions().into())
}

/// Appends the bands of the line through `points` (each with its tension) to `line`, each
/// coloured by its mean tension on a blue → red ramp between the lowest and highest tension
/// along the line; returns how many.
fn bands(points: &[(Vec3, f64)], line: &mut Line) -> usize {
    if points.len() < 2 {
        return 0;
    }
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
