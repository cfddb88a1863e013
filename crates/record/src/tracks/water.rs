//! The water of a run (PHYSICS.md §6):
//!
//! - `world/water/surface`: the sea surface, a square grid of [`GRID`]² vertices at the
//!   elevation the waves give there, around the floating bodies, and past the grid a flat skirt
//!   at the still-water level out to [`FAR`] times the grid's half side, so the sea reaches the
//!   view's horizon rather than ending as a square over the seabed; its triangles and colour are
//!   static, its vertices a row at most every [`SURFACE_PERIOD`] of simulated time while there
//!   are waves (a calm sea: a row only when its level changes, the first frame included). The
//!   surface is the costliest entity of a water scene — 12 bytes and one wave evaluation per
//!   vertex and row, per column where the sea heads along x —: this grid and rate keep it below
//!   the physics' cost on the shipped scenes
//!   (`tether record --timing`) while a wave of the shortest period shipped (8 s) is still drawn
//!   with a dozen vertices per length and over 150 rows per period;
//! - `world/water/seabed`: the seabed plane at `z_w − h` under the whole surface, skirt
//!   included (a floor to the horizon), static, when the water has a depth;
//! - `world/water/forces/<body>`: the water's force on each floating body as an arrow from G,
//!   one body radius long when it equals the body's weight (`m·max(|g|, 1 m/s²)`), labelled
//!   `"water force on <body>"`;
//! - `plots/water/<body>/motion`: the wave elevation at the body and its heave (the height of G
//!   above its start) [m];
//! - `plots/water/<body>/angles`: its roll and pitch (the turn since t = 0 about the world x and
//!   y axes) [deg];
//! - `plots/water/<body>/radiation`, `…/excitation`: for a body with potential-flow data
//!   (PHYSICS.md §9), its radiation force and wave excitation as the water stage records them;
//!   `…/drift`: its second-order wave drift, when it has a drift model (§10)
//!   ([`tether_physics::water::WaterForces`]: about G, world axes), six series each — `Fx`, `Fy`,
//!   `Fz` [N], `Mx`, `My`, `Mz` [N·m] — zero while its potential flow is switched off. A body
//!   without potential data has neither: a scene without any records what it recorded before.

use super::{FAR, Settings, Track, f32x3, of_entity, send_chunk};
use crate::columns::{column, flat_floats, floats, plot};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::body::Load;
use tether_physics::math::{Rotation, Vec3};
use tether_physics::water::waves::SeaInstant;
use tether_physics::water_stage::WaterStage;
use tether_physics::world::World;

/// Vertices along each side of the surface grid.
pub const GRID: usize = 24;

/// Vertices of the surface: the grid's, then the skirt's four outer corners.
const VERTICES: usize = GRID * GRID + 4;

/// Simulated time between two rows of a moving surface [s], at least: at most 40 per second
/// (at the default 60 frames per second, every other frame).
pub const SURFACE_PERIOD: f64 = 1.0 / 40.0;

/// Colour of the surface (red, green, blue, alpha), the force arrows (the seabed's:
/// [`super::log_floor`]).
const SURFACE_RGBA: [u8; 4] = [30, 100, 160, 150];
const ARROW_RGB: [u8; 3] = [40, 160, 230];

/// The series of a potential-flow force plot: force and moment about G, world axes.
pub const FORCE_SERIES: [&str; 6] = ["Fx [N]", "Fy [N]", "Fz [N]", "Mx [N·m]", "My [N·m]", "Mz [N·m]"];

/// A floating body: where its plots and arrow go, and its pose at t = 0.
struct Floating {
    body: usize,
    force_path: String,
    /// The arrow's label in the 3D view ("water force on buoy").
    force_label: String,
    motion_path: String,
    angles_path: String,
    /// Its radiation and excitation plots, if it has potential-flow data.
    potential_paths: Option<[String; 2]>,
    /// Its wave drift plot, if it has a drift model (PHYSICS.md §10).
    drift_path: Option<String>,
    /// Height of G [m] and orientation at t = 0.
    start_height: f64,
    start_turn: Rotation,
}

/// The water's buffered frames: the surface's vertices at the frames in `surface_frames`; per
/// floating body, frame-major, its force arrow (origin, vector), elevation and heave, roll and
/// pitch; per body with potential-flow data, frame-major, its radiation force and excitation.
pub(super) struct WaterTrack {
    /// Centre `(x, y)` [m] and half side [m] of the square the surface covers.
    center: [f64; 2],
    half: f64,
    floating: Vec<Floating>,
    sea: SeaInstant,
    surface: Vec<f32>,
    surface_frames: Vec<usize>,
    /// The level of the calm surface last buffered or sent [m] (`None`: none yet, or waves).
    calm_level: Option<f64>,
    /// Simulated time of the last surface row [s].
    surface_time: f64,
    arrows: Vec<([f32; 3], [f32; 3])>,
    motion: Vec<[f64; 2]>,
    angles: Vec<[f64; 2]>,
    radiation: Vec<[f64; 6]>,
    excitation: Vec<[f64; 6]>,
    drift: Vec<[f64; 6]>,
}

impl WaterTrack {
    /// The water of `world` (`None` when it has none).
    pub(super) fn new(world: &World) -> Option<Self> {
        let stage = world.system().water()?;
        let (center, half) = square(world, stage);
        let floating = stage
            .floating
            .iter()
            .map(|f| {
                let name = &world.bodies()[f.body()].name;
                let state = world.state(f.body());
                Floating {
                    body: f.body(),
                    force_path: paths::water_force(name),
                    force_label: format!("water force on {name}"),
                    motion_path: paths::water_plot(name, "motion"),
                    angles_path: paths::water_plot(name, "angles"),
                    potential_paths: f.has_potential_data().then(|| {
                        [
                            paths::water_plot(name, paths::RADIATION_PLOT),
                            paths::water_plot(name, paths::EXCITATION_PLOT),
                        ]
                    }),
                    drift_path: crate::layout::has_drift(f).then(|| paths::water_plot(name, paths::DRIFT_PLOT)),
                    start_height: state.position.z,
                    start_turn: state.orientation,
                }
            })
            .collect();
        Some(Self {
            center,
            half,
            floating,
            sea: SeaInstant::default(),
            surface: Vec::new(),
            surface_frames: Vec::new(),
            calm_level: None,
            surface_time: f64::NEG_INFINITY,
            arrows: Vec::new(),
            motion: Vec::new(),
            angles: Vec::new(),
            radiation: Vec::new(),
            excitation: Vec::new(),
            drift: Vec::new(),
        })
    }

    /// Floating bodies (each has an arrow and two plots, two more with potential flow), and the
    /// surface.
    pub(super) fn entities(&self) -> usize {
        1 + 3 * self.floating.len() + 2 * self.potential_plots().count() + self.drift_plots().count()
    }

    /// The wave drift plot of each floating body that has one.
    fn drift_plots(&self) -> impl Iterator<Item = &String> {
        self.floating.iter().filter_map(|f| f.drift_path.as_ref())
    }

    /// The radiation and excitation plots of each floating body that has them.
    fn potential_plots(&self) -> impl Iterator<Item = &[String; 2]> {
        self.floating.iter().filter_map(|f| f.potential_paths.as_ref())
    }

    /// `(x, y)` [m] of grid vertex `n` (row-major).
    fn grid_point(&self, n: usize) -> (f64, f64) {
        let step = 2.0 * self.half / (GRID - 1) as f64;
        let (i, j) = (n % GRID, n / GRID);
        (self.center[0] - self.half + i as f64 * step, self.center[1] - self.half + j as f64 * step)
    }

    /// Buffers the surface at `frame` (simulated time `time`) if it moved and
    /// [`SURFACE_PERIOD`] has passed since the last row (`elevation`: the waves' at `(x, y)`
    /// [m], the same at every `y` when `ignores_y`: then summed once per column,
    /// [`tether_physics::water::waves::Sea::elevation_ignores_y`]); returns the bytes.
    fn capture_surface(
        &mut self,
        level: f64,
        (calm, ignores_y): (bool, bool),
        (time, frame): (f64, usize),
        elevation: impl Fn(f64, f64) -> f64,
    ) -> usize {
        let unchanged = if calm { self.calm_level == Some(level) } else { time - self.surface_time < SURFACE_PERIOD };
        if unchanged {
            return 0;
        }
        self.calm_level = calm.then_some(level);
        self.surface_time = time;
        let first_row = self.surface.len();
        for n in 0..GRID * GRID {
            let (x, y) = self.grid_point(n);
            // Grid point n is column n % GRID of row n / GRID; its height the third of its floats.
            let height = if ignores_y && n >= GRID {
                self.surface[first_row + 3 * (n % GRID) + 2]
            } else {
                (level + elevation(x, y)) as f32
            };
            self.surface.extend([x as f32, y as f32, height]);
        }
        for [x, y] in super::square_corners(self.center, FAR * self.half) {
            self.surface.extend([x as f32, y as f32, level as f32]);
        }
        self.surface_frames.push(frame);
        VERTICES * 3 * 4
    }
}

impl Track for WaterTrack {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        let [r, g, b, a] = SURFACE_RGBA;
        stream.log_static(
            paths::WATER_SURFACE,
            &rerun::Mesh3D::update_fields()
                .with_triangle_indices(
                    grid_triangles().chain(skirt_triangles()).map(|[a, b, c]| rerun::datatypes::UVec3D::new(a, b, c)),
                )
                .with_albedo_factor(rerun::datatypes::Rgba32::from_unmultiplied_rgba(r, g, b, a)),
        )?;
        if let Some(seabed) = world.system().water().and_then(|stage| stage.water.seabed()) {
            super::log_floor(stream, paths::SEABED, (self.center, FAR * self.half), seabed)?;
        }
        let [r, g, b] = ARROW_RGB;
        for floating in &self.floating {
            stream.log_static(
                floating.force_path.as_str(),
                &rerun::Arrows3D::update_fields()
                    .with_colors([rerun::Color::from_rgb(r, g, b)])
                    .with_labels([floating.force_label.as_str()])
                    .with_show_labels(true),
            )?;
            stream.log_static(
                floating.motion_path.as_str(),
                &rerun::SeriesLines::new().with_names(["elevation", "heave"]),
            )?;
            stream
                .log_static(floating.angles_path.as_str(), &rerun::SeriesLines::new().with_names(["roll", "pitch"]))?;
        }
        for path in self.potential_plots().flatten().chain(self.drift_plots()) {
            stream.log_static(path.as_str(), &rerun::SeriesLines::new().with_names(FORCE_SERIES))?;
        }
        Ok(())
    }

    fn capture(&mut self, world: &World, frame: usize, _settings: &Settings) -> usize {
        // The scene's water may be edited live, never removed: a world without it has nothing to
        // add.
        let Some(stage) = world.system().water() else { return 0 };
        let (water, time) = (&stage.water, world.time());
        let calm = water.sea().is_calm();
        let mut sea = std::mem::take(&mut self.sea);
        if !calm {
            water.sea().surface_instant(time, &mut sea);
        }
        let ramp = water.ramp(time);
        let elevation = |x: f64, y: f64| if calm { 0.0 } else { ramp * water.sea().elevation_at(&sea, x, y) };
        let ignores_y = water.sea().elevation_ignores_y();
        let mut bytes = self.capture_surface(water.level(), (calm, ignores_y), (time, frame), elevation);
        for (floating, stage_body) in self.floating.iter().zip(&stage.floating) {
            let body = &world.bodies()[floating.body];
            let state = world.state(floating.body);
            let weight = body.mass() * world.gravity().norm().max(1.0);
            // A body the stage has no record of (none evaluated yet) bears no water force.
            let record = world.water_forces().iter().find(|r| r.body == floating.body).copied().unwrap_or_default();
            let force = record.total().force;
            if floating.potential_paths.is_some() {
                self.radiation.push(six(&record.radiation));
                self.excitation.push(six(&record.excitation));
                bytes += 2 * 6 * 8;
            }
            if floating.drift_path.is_some() {
                self.drift.push(six(&record.drift));
                bytes += 6 * 8;
            }
            self.arrows
                .push((f32x3(&state.position), f32x3(&(force * (stage_body.hull().bounding_radius() / weight)))));
            self.motion.push([elevation(state.position.x, state.position.y), state.position.z - floating.start_height]);
            let (roll, pitch, _) = (state.orientation * floating.start_turn.inverse()).euler_angles();
            self.angles.push([roll.to_degrees(), pitch.to_degrees()]);
            bytes += 2 * 3 * 4 + 4 * 8;
        }
        self.sea = sea;
        bytes
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        if !self.surface_frames.is_empty() {
            let surface = column(
                rerun::Mesh3D::descriptor_vertex_positions(),
                flat_floats::<3>(std::mem::take(&mut self.surface)),
                std::iter::repeat_n(VERTICES, self.surface_frames.len()),
            );
            let times = frames.columns_of(self.surface_frames.iter().copied());
            send_chunk(stream, paths::WATER_SURFACE, times, vec![surface], sent)?;
            self.surface_frames.clear();
        }
        let bodies = self.floating.len();
        let rows = self.arrows.len() / bodies.max(1);
        for (index, floating) in self.floating.iter().enumerate() {
            let arrows = of_entity(&self.arrows, index, bodies);
            let one_each = || std::iter::repeat_n(1, rows);
            let force = vec![
                column(
                    rerun::Arrows3D::descriptor_vectors(),
                    floats(arrows.clone().map(|(_, vector)| vector)),
                    one_each(),
                ),
                column(rerun::Arrows3D::descriptor_origins(), floats(arrows.map(|(origin, _)| origin)), one_each()),
            ];
            send_chunk(stream, &floating.force_path, frames.columns(), force, sent)?;
            for (path, values) in [(&floating.motion_path, &self.motion), (&floating.angles_path, &self.angles)] {
                send_chunk(
                    stream,
                    path,
                    frames.columns(),
                    vec![plot(of_entity(values, index, bodies).flatten().collect(), 2)],
                    sent,
                )?;
            }
        }
        let potential = self.potential_plots().count();
        for (index, paths) in self.potential_plots().enumerate() {
            for (path, values) in paths.iter().zip([&self.radiation, &self.excitation]) {
                let values = of_entity(values, index, potential).flatten().collect();
                send_chunk(stream, path, frames.columns(), vec![plot(values, 6)], sent)?;
            }
        }
        let drifting = self.drift_plots().count();
        for (index, path) in self.drift_plots().enumerate() {
            let values = of_entity(&self.drift, index, drifting).flatten().collect();
            send_chunk(stream, path, frames.columns(), vec![plot(values, 6)], sent)?;
        }
        self.drift.clear();
        self.arrows.clear();
        self.motion.clear();
        self.angles.clear();
        self.radiation.clear();
        self.excitation.clear();
        Ok(())
    }
}

/// A load's force and moment as one row of a force plot ([`FORCE_SERIES`]).
fn six(load: &Load) -> [f64; 6] {
    let (f, m) = (&load.force, &load.moment);
    [f.x, f.y, f.z, m.x, m.y, m.z]
}

/// The square the surface covers: centred on the floating bodies at t = 0, wide enough for them
/// and their couplings' ends and for two of the longest waves (at least 20 m across).
fn square(world: &World, stage: &WaterStage) -> ([f64; 2], f64) {
    let points: Vec<Vec3> = stage
        .floating
        .iter()
        .map(|f| world.state(f.body()).position)
        .chain(world.coupling_forces().iter().flat_map(|f| [f.point1, f.point2]))
        .collect();
    let (low, high) = tether_physics::math::bounding_box(points.iter().copied());
    let center = if low.x.is_finite() { [(low.x + high.x) / 2.0, (low.y + high.y) / 2.0] } else { [0.0, 0.0] };
    let extent = if low.x.is_finite() { 0.5 * (high.x - low.x).max(high.y - low.y) } else { 0.0 };
    let reach = stage.floating.iter().map(|f| f.hull().bounding_radius()).fold(0.0, f64::max);
    let longest =
        stage.water.sea().components().iter().map(|c| std::f64::consts::TAU / c.wave_number).fold(0.0, f64::max);
    (center, (extent + 3.0 * reach).max(longest).max(10.0))
}

/// Two triangles per grid square, counter-clockwise seen from above.
fn grid_triangles() -> impl Iterator<Item = [u32; 3]> {
    let index = |i: usize, j: usize| (j * GRID + i) as u32;
    (0..GRID - 1).flat_map(move |j| {
        (0..GRID - 1).flat_map(move |i| {
            [[index(i, j), index(i + 1, j), index(i + 1, j + 1)], [index(i, j), index(i + 1, j + 1), index(i, j + 1)]]
        })
    })
}

/// The skirt from the grid's edge to its four outer corners (vertices `GRID²` to `GRID² + 3`,
/// counter-clockwise from `(−, −)`), counter-clockwise seen from above: per side, a fan from
/// the outer corner at its start over the side's grid vertices, closed by the triangle of that
/// corner, the next, and the side's last grid vertex.
fn skirt_triangles() -> impl Iterator<Item = [u32; 3]> {
    let last = GRID - 1;
    let index = |(i, j): (usize, usize)| (j * GRID + i) as u32;
    let corner = |k: usize| (GRID * GRID + k % 4) as u32;
    // Grid vertex k of each side, walking counter-clockwise seen from above: y = min, x = max,
    // y = max, x = min.
    let side = move |s: usize, k: usize| match s {
        0 => (k, 0),
        1 => (last, k),
        2 => (last - k, last),
        _ => (0, last - k),
    };
    (0..4).flat_map(move |s| {
        (0..last).map(move |k| [corner(s), index(side(s, k + 1)), index(side(s, k))]).chain(std::iter::once([
            corner(s),
            corner(s + 1),
            index(side(s, last)),
        ]))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid's and the skirt's triangles tile the far square once: every one counter-clockwise
    /// seen from above, their areas summing to the square's (a gap or an overlap would not).
    #[test]
    fn the_surface_and_its_skirt_tile_the_far_square() {
        let half = 10.0;
        let step = 2.0 * half / (GRID - 1) as f64;
        let far = FAR * half;
        let mut vertices: Vec<[f64; 2]> =
            (0..GRID * GRID).map(|n| [-half + (n % GRID) as f64 * step, -half + (n / GRID) as f64 * step]).collect();
        vertices.extend([[-far, -far], [far, -far], [far, far], [-far, far]]);
        let mut total = 0.0;
        for [a, b, c] in grid_triangles().chain(skirt_triangles()) {
            let [a, b, c] = [a, b, c].map(|i| vertices[i as usize]);
            let area = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
            assert!(area > 0.0, "triangle {a:?} {b:?} {c:?} is counter-clockwise seen from above: {area}");
            total += area;
        }
        let square = (2.0 * far) * (2.0 * far);
        assert!((total - square).abs() <= 1e-9 * square, "{total} m² against the square's {square} m²");
    }
}
