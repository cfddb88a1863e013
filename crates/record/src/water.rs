//! The water of a run in the recording (PHYSICS.md §6), hooked into the [`crate::Recorder`]:
//!
//! - `world/water/surface`: the sea surface each frame, a square grid of [`GRID`]² vertices at
//!   the elevation the waves give there, around the floating bodies (static when the water is
//!   still);
//! - `world/water/seabed`: the seabed plane at `z_w − h` under the same square, static, when the
//!   water has a depth;
//! - `world/water/forces/<body>`: the water's force on each floating body as an arrow from G,
//!   one body radius long when it equals the body's weight;
//! - `plots/water/<body>/motion`: the wave elevation at the body and its heave (the height of G
//!   above its start) [m];
//! - `plots/water/<body>/angles`: its roll and pitch (the turn since t = 0 about the world x and
//!   y axes) [deg].

use crate::paths;
use rerun::RecordingStream;
use tether_physics::math::{Rotation, Vec3};
use tether_physics::water::WaterStage;
use tether_physics::water::waves::SeaInstant;
use tether_physics::world::World;

/// Vertices along each side of the surface grid.
pub const GRID: usize = 40;

/// What the recorder keeps of the water: the grid's square, each floating body's start.
pub struct WaterRecorder {
    /// Centre `(x, y)` [m] and half side [m] of the square the surface covers.
    center: [f64; 2],
    half: f64,
    /// Height of G [m] and orientation of each floating body at t = 0.
    starts: Vec<(f64, Rotation)>,
    /// Triangles of the grid (static).
    triangles: Vec<[u32; 3]>,
}

impl WaterRecorder {
    /// The water of `world`, if it has water: logs the static parts.
    pub fn new(stream: &RecordingStream, world: &World) -> Result<Option<Self>, rerun::RecordingStreamError> {
        let Some(stage) = world.system().water() else { return Ok(None) };
        let (center, half) = square(world, stage);
        let starts = stage.floating.iter().map(|f| (world.state(f.body).position.z, world.state(f.body).orientation)).collect();
        let recorder = Self { center, half, starts, triangles: grid_triangles() };
        if let Some(seabed) = stage.water.seabed() {
            let corners = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|[a, b]| [(center[0] + a * half) as f32, (center[1] + b * half) as f32, seabed as f32]);
            stream.log_static(
                paths::SEABED,
                &rerun::Mesh3D::new(corners).with_triangle_indices([rerun::datatypes::UVec3D::new(0, 1, 2), rerun::datatypes::UVec3D::new(0, 2, 3)]).with_albedo_factor(rerun::datatypes::Rgba32::from_rgb(150, 130, 100)),
            )?;
        }
        for floating in &stage.floating {
            let name = &world.bodies()[floating.body].name;
            stream.log_static(paths::water_plot(name, "motion"), &rerun::SeriesLines::new().with_names(["elevation", "heave"]))?;
            stream.log_static(paths::water_plot(name, "angles"), &rerun::SeriesLines::new().with_names(["roll", "pitch"]))?;
        }
        Ok(Some(recorder))
    }

    /// Logs the surface, the force arrows and the plots at the world's current time.
    pub fn log_frame(&self, stream: &RecordingStream, world: &World) -> Result<(), rerun::RecordingStreamError> {
        let Some(stage) = world.system().water() else { return Ok(()) };
        let water = &stage.water;
        let time = world.time();
        let mut instant = SeaInstant::default();
        water.sea().instant(time, &mut instant);
        let ramp = water.ramp(time);
        let elevation = |x: f64, y: f64| if water.sea().is_calm() { 0.0 } else { ramp * water.sea().pressure_head(&instant, x, y, water.level()) };
        let vertices: Vec<[f32; 3]> = (0..GRID * GRID)
            .map(|n| {
                let (x, y) = self.grid_point(n);
                [x as f32, y as f32, (water.level() + elevation(x, y)) as f32]
            })
            .collect();
        stream.log(
            paths::WATER_SURFACE,
            &rerun::Mesh3D::new(vertices)
                .with_triangle_indices(self.triangles.iter().map(|&[a, b, c]| rerun::datatypes::UVec3D::new(a, b, c)))
                .with_albedo_factor(rerun::datatypes::Rgba32::from_unmultiplied_rgba(40, 110, 190, 150)),
        )?;
        for (floating, (start_height, start_turn)) in stage.floating.iter().zip(&self.starts) {
            let body = &world.bodies()[floating.body];
            let state = world.state(floating.body);
            if let Some(record) = world.water_forces().iter().find(|r| r.body == floating.body) {
                let weight = body.mass() * world.gravity().norm().max(1.0);
                let arrow = record.total().force * (floating.hull.bounding_radius() / weight);
                stream.log(paths::water_force(&body.name), &rerun::Arrows3D::from_vectors([f32x3(&arrow)]).with_origins([f32x3(&state.position)]).with_colors([rerun::Color::from_rgb(40, 160, 230)]))?;
            }
            let (x, y) = (state.position.x, state.position.y);
            stream.log(paths::water_plot(&body.name, "motion"), &rerun::Scalars::new([elevation(x, y), state.position.z - start_height]))?;
            let (roll, pitch, _) = (state.orientation * start_turn.inverse()).euler_angles();
            stream.log(paths::water_plot(&body.name, "angles"), &rerun::Scalars::new([roll.to_degrees(), pitch.to_degrees()]))?;
        }
        Ok(())
    }

    /// `(x, y)` [m] of grid vertex `n` (row-major).
    fn grid_point(&self, n: usize) -> (f64, f64) {
        let step = 2.0 * self.half / (GRID - 1) as f64;
        let (i, j) = (n % GRID, n / GRID);
        (self.center[0] - self.half + i as f64 * step, self.center[1] - self.half + j as f64 * step)
    }
}

/// The square the surface covers: centred on the floating bodies at t = 0, wide enough for them
/// and their couplings' ends and for two of the longest waves (at least 20 m across).
fn square(world: &World, stage: &WaterStage) -> ([f64; 2], f64) {
    let points: Vec<Vec3> = stage.floating.iter().map(|f| world.state(f.body).position).chain(world.coupling_forces().iter().flat_map(|f| [f.point1, f.point2])).collect();
    let (low, high) = tether_physics::math::bounding_box(points.iter().copied());
    let center = if low.x.is_finite() { [(low.x + high.x) / 2.0, (low.y + high.y) / 2.0] } else { [0.0, 0.0] };
    let extent = if low.x.is_finite() { 0.5 * (high.x - low.x).max(high.y - low.y) } else { 0.0 };
    let reach = stage.floating.iter().map(|f| f.hull.bounding_radius()).fold(0.0, f64::max);
    let longest = stage.water.sea().components().iter().map(|c| std::f64::consts::TAU / c.wave_number).fold(0.0, f64::max);
    (center, (extent + 3.0 * reach).max(longest).max(10.0))
}

/// Two triangles per grid square, counter-clockwise seen from above.
fn grid_triangles() -> Vec<[u32; 3]> {
    let index = |i: usize, j: usize| (j * GRID + i) as u32;
    (0..GRID - 1).flat_map(|j| (0..GRID - 1).flat_map(move |i| [[index(i, j), index(i + 1, j), index(i + 1, j + 1)], [index(i, j), index(i + 1, j + 1), index(i, j + 1)]])).collect()
}

fn f32x3(v: &Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}
