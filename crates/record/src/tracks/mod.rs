//! The kinds of entity in a recording, one module each: what each logs once when the recording
//! starts, and the columns it buffers frame after frame and sends in one chunk per entity.
//!
//! A new kind is one module implementing [`Track`] and one line in [`for_world`]; its entity
//! paths go in [`crate::paths`].
//!
//! - [`bodies`]: every body's pose, its static shape and slave nodes;
//! - [`boundaries`]: the contacts' planes and the anchors, static;
//! - [`springs`]: the spring-dampers' lines between their ends;
//! - [`catenaries`]: a catenary's shape coloured by tension, and the end tension plot;
//! - [`contacts`]: the contacts' normal force and friction plot;
//! - [`face_arrows`]: a contact's face forces as arrows, where and when asked for;
//! - [`tension`]: every coupling's tension plot;
//! - [`energy`]: the energy balance plot;
//! - [`water`]: the sea surface, the seabed, the water's force on each floating body and its
//!   motion plots;
//! - [`seabed`]: the lines' grounded parts, touchdowns and grounded lengths;
//! - [`air`]: the wind's force on each body it loads.

mod air;
mod bodies;
pub(crate) mod boundaries;
mod catenaries;
mod contacts;
mod energy;
pub mod face_arrows;
mod seabed;
mod springs;
mod tension;
mod water;

use crate::RecordError;
use crate::frames::Frames;
use crate::rerun;
use crate::stats::{KindStats, ROW_INDEX_BYTES};
use face_arrows::DrawnFaces;
use rerun::external::arrow::array::Array as _;
use rerun::log::TimeColumn;
use rerun::{RecordingStream, SerializedComponentColumn};
use tether_physics::math::{Rotation, Vec3};
use tether_physics::world::World;

/// What the user chose to record beyond the default.
#[derive(Debug, Clone, Default)]
pub(crate) struct Settings {
    pub face_arrows: DrawnFaces,
}

/// One kind of entity in a recording.
pub(crate) trait Track {
    /// Logs what does not change in `world` (shapes, series names, colours), once, when the
    /// recording starts (nothing, for a kind that logs its static data with its first rows).
    fn log_static(&self, _stream: &RecordingStream, _world: &World) -> Result<(), RecordError> {
        Ok(())
    }

    /// Buffers the world's current state as frame `frame` of the recorder's [`Frames`];
    /// returns the bytes it buffered.
    fn capture(&mut self, world: &World, frame: usize, settings: &Settings) -> usize;

    /// Sends the buffered frames (their instants in `frames`), one chunk per entity, adds what
    /// it sent to `sent`, and empties its buffers.
    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError>;
}

/// The tracks of a run of `world`, each with its (empty) statistics: only the kinds the world
/// has.
pub(crate) fn for_world(world: &World) -> Vec<(Box<dyn Track>, KindStats)> {
    let mut tracks = Vec::new();
    let mut add = |kind: &'static str, entities: usize, track: Box<dyn Track>| {
        tracks.push((track, KindStats { kind, entities, ..KindStats::default() }))
    };
    add("bodies", world.bodies().len(), Box::new(bodies::Bodies::new(world)));
    if let Some(boundaries) = boundaries::Boundaries::new(world) {
        add("boundaries", boundaries.entities(), Box::new(boundaries));
    }
    if let Some(springs) = springs::Springs::new(world) {
        add("springs", 1, Box::new(springs));
    }
    if let Some(catenaries) = catenaries::Catenaries::new(world) {
        add("catenaries", catenaries.len() + 1, Box::new(catenaries));
    }
    if let Some(contacts) = contacts::ContactPlot::new(world) {
        add("contact plot", 1, Box::new(contacts));
    }
    if let Some(arrows) = face_arrows::FaceArrowTrack::new(world) {
        add("face arrows", arrows.len(), Box::new(arrows));
    }
    if let Some(tension) = tension::TensionPlot::new(world) {
        add("tension plot", 1, Box::new(tension));
    }
    add("energy plot", 1, Box::<energy::EnergyPlot>::default());
    if let Some(water) = water::WaterTrack::new(world) {
        add("water", water.entities(), Box::new(water));
    }
    if let Some(seabed) = seabed::SeabedTrack::new(world) {
        add("seabed", seabed.entities(), Box::new(seabed));
    }
    if let Some(air) = air::AirTrack::new(world) {
        add("air", air.entities(), Box::new(air));
    }
    tracks
}

/// Sends `columns` to entity `path` at the instants `times` (a row each) as one chunk, and adds
/// its rows and Arrow bytes to `sent`.
pub(crate) fn send_chunk(
    stream: &RecordingStream,
    path: &str,
    times: [TimeColumn; 2],
    columns: Vec<SerializedComponentColumn>,
    sent: &mut KindStats,
) -> Result<(), RecordError> {
    let rows = times[0].num_rows() as u64;
    let data: usize = columns
        .iter()
        .map(|column| {
            column
                .list_array
                .to_data()
                .get_slice_memory_size()
                .unwrap_or_else(|_| column.list_array.get_array_memory_size())
        })
        .sum();
    sent.rows += rows;
    sent.bytes += data as u64 + rows * ROW_INDEX_BYTES;
    crate::columns::send(stream, path, times, columns)
}

/// How far the sea surface's flat skirt and the seabed reach, in half sides of what they are
/// drawn around (the surface's wave grid; the bodies and coupling ends): far enough that from
/// any eye the framing chooses their edge lies near the horizon.
pub const FAR: f64 = 25.0;

/// Brown, for the bottom.
const FLOOR_RGB: [u8; 3] = [105, 92, 70];

/// The bottom at `elevation` [m] as a static brown square at entity `path`, centred on `(x, y)`
/// with half side `half` [m] (`(center, half)`): two triangles.
pub(crate) fn log_floor(
    stream: &RecordingStream,
    path: &str,
    (center, half): ([f64; 2], f64),
    elevation: f64,
) -> Result<(), RecordError> {
    let corners = square_corners(center, half).map(|[x, y]| [x as f32, y as f32, elevation as f32]);
    let [r, g, b] = FLOOR_RGB;
    stream.log_static(
        path,
        &rerun::Mesh3D::new(corners)
            .with_triangle_indices([rerun::datatypes::UVec3D::new(0, 1, 2), rerun::datatypes::UVec3D::new(0, 2, 3)])
            .with_albedo_factor(rerun::datatypes::Rgba32::from_rgb(r, g, b)),
    )?;
    Ok(())
}

/// The corners `(x, y)` [m] of the square centred on `center` with half side `half`,
/// counter-clockwise seen from above from `(−, −)`.
pub(crate) fn square_corners(center: [f64; 2], half: f64) -> [[f64; 2]; 4] {
    [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]].map(|[a, b]| [center[0] + a * half, center[1] + b * half])
}

/// A point or vector in single precision, as Rerun draws them.
pub(crate) fn f32x3(v: &Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

/// A rotation as Rerun's quaternion `[x, y, z, w]`, single precision.
pub(crate) fn xyzw(rotation: &Rotation) -> [f32; 4] {
    let q = rotation.quaternion();
    [q.i as f32, q.j as f32, q.k as f32, q.w as f32]
}

/// Rows `entity`, `entity + stride`, … of a frame-major buffer of `stride` entities per frame:
/// one entity's values, frame after frame.
pub(crate) fn of_entity<T: Copy>(buffer: &[T], entity: usize, stride: usize) -> impl Iterator<Item = T> + Clone + '_ {
    buffer.iter().skip(entity).step_by(stride.max(1)).copied()
}
