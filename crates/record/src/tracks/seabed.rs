//! The seabed and what lies on it (PHYSICS.md §7), for a scene with a seabed:
//!
//! - `world/seabed/plane`: the bottom, static, under the bodies and the coupling ends and out to
//!   the horizon, when the scene declares a seabed without water (the [`super::water`] track
//!   draws it at the water's depth, [`super::log_floor`] both);
//! - `world/seabed/grounded/<line>`: the part of each catenary lying on the bottom, every frame,
//!   a thick sand-coloured strip over the line's own drawing (none while the line hangs free);
//! - `world/seabed/touchdowns/<line>`: where its suspended parts meet the bottom, as points;
//! - `plots/seabed`: every line's grounded length `L_B` [m], a series named after the line (its
//!   anchor and fairlead tensions are in `plots/catenary`).

use super::{Settings, Track, f32x3, send_chunk};
use crate::columns::{column, floats, plot, strips};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::catenary::{LineEnd, LineState};
use tether_physics::coupling::{CouplingKind, LineModel};
use tether_physics::math::Vec3;
use tether_physics::world::World;

/// Sand, for what lies on the bottom; red for the touchdowns (the bottom itself:
/// [`super::log_floor`]).
const SAND_RGB: [u8; 3] = [214, 170, 80];
const TOUCHDOWN_RGB: [u8; 3] = [230, 60, 40];

/// One line's buffered frames.
struct Line {
    /// Coupling index in the world.
    index: usize,
    grounded_path: String,
    touchdowns_path: String,
    /// The grounded segment of each frame that has one, and how many (0 or 1) each frame has.
    grounded: Vec<[[f32; 3]; 2]>,
    grounded_per_frame: Vec<usize>,
    /// The touchdowns of each frame, and how many (0 to 2) each frame has.
    touchdowns: Vec<[f32; 3]>,
    touchdowns_per_frame: Vec<usize>,
}

/// The world's catenaries on its seabed, and their grounded lengths frame-major (frame f, line
/// l at `f × lines + l`).
pub(super) struct SeabedTrack {
    lines: Vec<Line>,
    grounded_lengths: Vec<f64>,
}

impl SeabedTrack {
    /// The seabed of `world` (`None` without one).
    pub(super) fn new(world: &World) -> Option<Self> {
        world.system().seabed()?;
        let lines = world
            .couplings()
            .iter()
            .enumerate()
            .filter(|(_, coupling)| matches!(coupling.kind, CouplingKind::Catenary(_)))
            .map(|(index, coupling)| Line {
                index,
                grounded_path: paths::grounded_line(&coupling.name),
                touchdowns_path: paths::touchdowns(&coupling.name),
                grounded: Vec::new(),
                grounded_per_frame: Vec::new(),
                touchdowns: Vec::new(),
                touchdowns_per_frame: Vec::new(),
            })
            .collect();
        Some(Self { lines, grounded_lengths: Vec::new() })
    }

    /// Entities: two per line, the plot, the plane.
    pub(super) fn entities(&self) -> usize {
        2 * self.lines.len() + 2
    }
}

impl Track for SeabedTrack {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        let water_draws_it = world.system().water().is_some_and(|stage| stage.water.seabed().is_some());
        if let (Some(seabed), false) = (world.system().seabed(), water_draws_it) {
            log_plane(stream, world, seabed.elevation())?;
        }
        let [r, g, b] = SAND_RGB;
        let sand = rerun::LineStrips3D::update_fields()
            .with_colors([rerun::Color::from_rgb(r, g, b)])
            .with_radii([rerun::Radius::new_ui_points(5.0)]);
        let [r, g, b] = TOUCHDOWN_RGB;
        let marks = rerun::Points3D::update_fields()
            .with_colors([rerun::Color::from_rgb(r, g, b)])
            .with_radii([rerun::Radius::new_ui_points(7.0)]);
        for line in &self.lines {
            stream.log_static(line.grounded_path.as_str(), &sand)?;
            stream.log_static(line.touchdowns_path.as_str(), &marks)?;
        }
        if !self.lines.is_empty() {
            let names = self.lines.iter().map(|line| world.couplings()[line.index].name.as_str());
            stream.log_static(paths::SEABED_PLOT, &rerun::SeriesLines::new().with_names(names))?;
        }
        Ok(())
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        let mut bytes = 0;
        for line in &mut self.lines {
            let state = world.line_state(line.index);
            let touchdowns = state.map(LineState::touchdowns).unwrap_or_default();
            let grounded = state.and_then(|state| grounded_part(state, &touchdowns));
            line.grounded.extend(grounded.map(|[a, b]| [f32x3(&a), f32x3(&b)]));
            line.grounded_per_frame.push(usize::from(grounded.is_some()));
            line.touchdowns.extend(touchdowns.iter().map(f32x3));
            line.touchdowns_per_frame.push(touchdowns.len());
            self.grounded_lengths.push(grounded_length(world, line.index, state));
            bytes += usize::from(grounded.is_some()) * 2 * 3 * 4 + touchdowns.len() * 3 * 4 + 8;
        }
        bytes
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        for line in &mut self.lines {
            let segments = line.grounded.len();
            let grounded = strips(line.grounded.drain(..).flatten(), std::iter::repeat_n(2, segments));
            let grounded =
                column(rerun::LineStrips3D::descriptor_strips(), grounded, line.grounded_per_frame.iter().copied());
            send_chunk(stream, &line.grounded_path, frames.columns(), vec![grounded], sent)?;
            let touchdowns = column(
                rerun::Points3D::descriptor_positions(),
                floats(line.touchdowns.drain(..)),
                line.touchdowns_per_frame.iter().copied(),
            );
            send_chunk(stream, &line.touchdowns_path, frames.columns(), vec![touchdowns], sent)?;
            line.grounded_per_frame.clear();
            line.touchdowns_per_frame.clear();
        }
        if !self.lines.is_empty() {
            // Frame-major, a value per line: the scalars' rows as they are.
            let lengths = plot(std::mem::take(&mut self.grounded_lengths), self.lines.len());
            send_chunk(stream, paths::SEABED_PLOT, frames.columns(), vec![lengths], sent)?;
        }
        Ok(())
    }
}

/// The grounded part of a line as a straight segment on the bottom (it lies straight, in the
/// line's vertical plane): between two touchdowns (a grounded middle), from the end on the
/// bottom to the one touchdown, or the whole line; none for a line that hangs free.
fn grounded_part(state: &LineState, touchdowns: &[Vec3]) -> Option<[Vec3; 2]> {
    let ground = state.ground.as_ref()?;
    if state.grounded_length() <= 0.0 {
        return None;
    }
    let on_bottom = |p: Vec3| p - state.e_y * (p.dot(&state.e_y) - ground.seabed);
    let anchor = on_bottom(match ground.anchor {
        LineEnd::First => state.origin,
        LineEnd::Second => state.end2(),
    });
    Some(match touchdowns {
        [a, b] => [*a, *b],
        [touchdown] => [anchor, *touchdown],
        _ => [on_bottom(state.origin), on_bottom(state.end2())],
    })
}

/// A square of the bottom under every coupling end and body, 20 % wider (at least 20 m), and
/// [`super::FAR`] times that: a floor to the horizon.
fn log_plane(stream: &RecordingStream, world: &World, elevation: f64) -> Result<(), RecordError> {
    let points = world
        .coupling_forces()
        .iter()
        .flat_map(|f| [f.point1, f.point2])
        .chain((0..world.bodies().len()).map(|i| world.state(i).position));
    let (low, high) = tether_physics::math::bounding_box(points);
    let (center, half) = if low.x.is_finite() {
        ([(low.x + high.x) / 2.0, (low.y + high.y) / 2.0], (0.6 * (high.x - low.x).max(high.y - low.y)).max(10.0))
    } else {
        ([0.0, 0.0], 10.0)
    };
    super::log_floor(stream, paths::SEABED_PLANE, (center, super::FAR * half), elevation)
}

/// Line `index`'s grounded length `L_B` \[m]: a dynamic line's from its nodes (the segments on
/// the seabed), a quasi-static one's from its solved shape `state`; 0 before either exists.
fn grounded_length(world: &World, index: usize, state: Option<&LineState>) -> f64 {
    let nodes = world.evaluation().line_run(index).and_then(|run| run.nodes());
    let dynamic = match &world.couplings()[index].kind {
        CouplingKind::Catenary(line) => match line.model() {
            LineModel::Dynamic(model) => Some(line.length() / f64::from(model.segments())),
            LineModel::QuasiStatic => None,
        },
        CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => None,
    };
    let up = -world.gravity().try_normalize(0.0).unwrap_or_else(|| -Vec3::z());
    match (nodes, dynamic, world.system().seabed()) {
        (Some(nodes), Some(segment), Some(seabed)) => nodes.grounded_length(seabed, &up, segment),
        _ => state.map_or(0.0, LineState::grounded_length),
    }
}
