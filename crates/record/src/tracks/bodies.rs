//! Bodies: `world/bodies/<name>` holds the pose of G and the principal axes, every frame;
//! `…/shape` the static display shape, placed in the principal frame by a static transform;
//! `…/nodes` the static slave nodes (principal frame). One entity per body, so that a body is
//! picked and selected in the viewer by its own path.

use super::{Settings, Track, f32x3, of_entity, send_chunk, xyzw};
use crate::columns::{column, floats};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::body::{RigidBody, Shape};
use tether_physics::math::{Rotation, Vec3};
use tether_physics::world::World;

/// Colour of the bodies' shapes: red, green, blue.
const SHAPE_RGB: [u8; 3] = [120, 160, 210];

/// Bytes buffered per body and frame: translation and quaternion in `f32`.
const BYTES_PER_POSE: usize = 7 * 4;

/// The bodies' poses, frame-major (frame f, body b at `f × bodies + b`).
pub(super) struct Bodies {
    paths: Vec<String>,
    translations: Vec<[f32; 3]>,
    rotations: Vec<[f32; 4]>,
}

impl Bodies {
    pub(super) fn new(world: &World) -> Self {
        let paths = world.bodies().iter().map(|body| paths::body(&body.name)).collect();
        Self { paths, translations: Vec::new(), rotations: Vec::new() }
    }
}

impl Track for Bodies {
    fn log_static(&self, stream: &RecordingStream, world: &World) -> Result<(), RecordError> {
        world.bodies().iter().try_for_each(|body| log_static_body(stream, body))
    }

    fn capture(&mut self, world: &World, _frame: usize, _settings: &Settings) -> usize {
        for index in 0..self.paths.len() {
            let state = world.state(index);
            self.translations.push(f32x3(&state.position));
            self.rotations.push(xyzw(&state.orientation));
        }
        self.paths.len() * BYTES_PER_POSE
    }

    fn send(&mut self, stream: &RecordingStream, frames: &Frames, sent: &mut KindStats) -> Result<(), RecordError> {
        let stride = self.paths.len();
        for (index, path) in self.paths.iter().enumerate() {
            let one_each = || std::iter::repeat_n(1, frames.len());
            let pose = vec![
                column(
                    rerun::Transform3D::descriptor_translation(),
                    floats(of_entity(&self.translations, index, stride)),
                    one_each(),
                ),
                column(
                    rerun::Transform3D::descriptor_quaternion(),
                    floats(of_entity(&self.rotations, index, stride)),
                    one_each(),
                ),
            ];
            send_chunk(stream, path, frames.columns(), pose, sent)?;
        }
        self.translations.clear();
        self.rotations.clear();
        Ok(())
    }
}

/// Static shape (placed in the principal frame) and slave nodes of a body.
fn log_static_body(stream: &RecordingStream, body: &RigidBody) -> Result<(), RecordError> {
    let shape_path = paths::body_shape(&body.name);
    let (center, axis_rotation) = match &body.shape {
        Shape::Box { center, .. } | Shape::Sphere { center, .. } => (*center, Rotation::identity()),
        // The vertices are already in the reference frame.
        Shape::Mesh { .. } => (Vec3::zeros(), Rotation::identity()),
        Shape::Cylinder { center, axis, .. } => {
            // Rerun's cylinders lie along z: turn z onto the axis.
            (
                *center,
                Rotation::rotation_between(&Vec3::z(), axis)
                    .unwrap_or_else(|| Rotation::from_axis_angle(&Vec3::x_axis(), std::f64::consts::PI)),
            )
        }
    };
    let placement = body.reference_in_principal * nalgebra::Isometry3::from_parts(center.into(), axis_rotation);
    let transform = rerun::Transform3D::from_translation_rotation(
        f32x3(&placement.translation.vector),
        rerun::Quaternion::from_xyzw(xyzw(&placement.rotation)),
    );
    let solid = rerun::components::FillMode::Solid;
    let [r, g, b] = SHAPE_RGB;
    let color = rerun::Color::from_rgb(r, g, b);
    let shape: Box<dyn rerun::AsComponents> = match &body.shape {
        Shape::Box { size, .. } => {
            Box::new(rerun::Boxes3D::from_half_sizes([f32x3(&(size * 0.5))]).with_colors([color]).with_fill_mode(solid))
        }
        Shape::Sphere { radius, .. } => {
            Box::new(rerun::Ellipsoids3D::from_radii([*radius as f32]).with_colors([color]).with_fill_mode(solid))
        }
        Shape::Cylinder { radius, length, .. } => Box::new(
            rerun::Cylinders3D::from_lengths_and_radii([*length as f32], [*radius as f32])
                .with_colors([color])
                .with_fill_mode(solid),
        ),
        Shape::Mesh { vertices, triangles } => Box::new(
            rerun::Mesh3D::new(vertices.iter().map(f32x3))
                .with_triangle_indices(triangles.iter().map(|&[a, b, c]| rerun::datatypes::UVec3D::new(a, b, c)))
                .with_albedo_factor(rerun::datatypes::Rgba32::from_rgb(r, g, b)),
        ),
    };
    // Shape and placement in one call: one static chunk per body, not two (each chunk costs the
    // file writer an Arrow schema and a footer entry, whatever its size).
    stream.log_static(shape_path.as_str(), &[&transform as &dyn rerun::AsComponents, shape.as_ref()])?;
    if !body.slave_nodes.is_empty() {
        stream.log_static(paths::body_nodes(&body.name), &rerun::Points3D::new(body.slave_nodes.iter().map(f32x3)))?;
    }
    Ok(())
}
