//! The seabed of a run in the recording (PHYSICS.md §7), hooked into the [`crate::Recorder`]:
//!
//! - `world/seabed/plane`: the bottom, static, under the lines' ends, when the scene declares a
//!   seabed without water (the [`crate::water`] part draws it at the water's depth);
//! - `world/seabed/grounded/<line>`: the part of each catenary lying on the bottom, each frame,
//!   a thick sand-coloured strip over the line's own drawing (empty while the line hangs free);
//! - `world/seabed/touchdowns/<line>`: where its suspended parts meet the bottom, as points;
//! - `plots/seabed/<line>`: its grounded length `L_B` [m], a series named after the line (the end tensions, anchor and
//!   fairlead, are in `plots/catenary/<line>`).

use crate::paths;
use rerun::RecordingStream;
use tether_physics::coupling::CouplingKind;
use tether_physics::coupling::catenary::{LineEnd, LineState};
use tether_physics::math::Vec3;
use tether_physics::world::World;

/// Sand, for what lies on the bottom (RGB).
const SAND: [u8; 3] = [214, 170, 80];

/// What the recorder keeps of the seabed: the catenaries, by coupling index and name.
pub struct SeabedRecorder {
    lines: Vec<(usize, String)>,
}

impl SeabedRecorder {
    /// The seabed of `world`, if it has one: logs the static parts.
    pub fn new(stream: &RecordingStream, world: &World) -> Result<Option<Self>, rerun::RecordingStreamError> {
        let Some(seabed) = world.system().seabed() else { return Ok(None) };
        let lines: Vec<(usize, String)> = world.couplings().iter().enumerate().filter(|(_, c)| matches!(c.kind, CouplingKind::Catenary(_))).map(|(i, c)| (i, c.name.clone())).collect();
        let water_draws_it = world.system().water().is_some_and(|stage| stage.water.seabed().is_some());
        if !water_draws_it {
            log_plane(stream, world, seabed.elevation)?;
        }
        for (_, name) in &lines {
            stream.log_static(paths::seabed_plot(name), &rerun::SeriesLines::new().with_names([name.as_str()]))?;
        }
        Ok(Some(Self { lines }))
    }

    /// Logs each line's grounded part, touchdowns and grounded length at the world's current time.
    pub fn log_frame(&self, stream: &RecordingStream, world: &World) -> Result<(), rerun::RecordingStreamError> {
        for (index, name) in &self.lines {
            let Some(state) = world.line_state(*index) else { continue };
            let touchdowns = state.touchdowns();
            let grounded = grounded_part(state, &touchdowns);
            stream.log(paths::grounded_line(name), &rerun::LineStrips3D::new(grounded.map(|[a, b]| [[f32x3(&a), f32x3(&b)]]).into_iter().flatten()).with_colors([rerun::Color::from_rgb(SAND[0], SAND[1], SAND[2])]).with_radii([rerun::Radius::new_ui_points(5.0)]))?;
            stream.log(paths::touchdowns(name), &rerun::Points3D::new(touchdowns.iter().map(f32x3)).with_colors([rerun::Color::from_rgb(230, 60, 40)]).with_radii([rerun::Radius::new_ui_points(7.0)]))?;
            stream.log(paths::seabed_plot(name), &rerun::Scalars::new([state.grounded_length()]))?;
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

/// A square of the bottom under every coupling end and body, 20 % wider (at least 20 m).
fn log_plane(stream: &RecordingStream, world: &World, elevation: f64) -> Result<(), rerun::RecordingStreamError> {
    let points = world.coupling_forces().iter().flat_map(|f| [f.point1, f.point2]).chain((0..world.bodies().len()).map(|i| world.state(i).position));
    let (low, high) = tether_physics::math::bounding_box(points);
    let (center, half) = if low.x.is_finite() { ([(low.x + high.x) / 2.0, (low.y + high.y) / 2.0], (0.6 * (high.x - low.x).max(high.y - low.y)).max(10.0)) } else { ([0.0, 0.0], 10.0) };
    let corners = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|[a, b]| [(center[0] + a * half) as f32, (center[1] + b * half) as f32, elevation as f32]);
    stream.log_static(
        paths::SEABED_PLANE,
        &rerun::Mesh3D::new(corners).with_triangle_indices([rerun::datatypes::UVec3D::new(0, 1, 2), rerun::datatypes::UVec3D::new(0, 2, 3)]).with_albedo_factor(rerun::datatypes::Rgba32::from_rgb(150, 130, 100)),
    )
}

fn f32x3(v: &Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}
