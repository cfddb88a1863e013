//! Tether's Rerun adapter: reads a [`World`] and logs it. Nothing in the physics crate knows
//! about it. The entity paths are in [`paths`]; the viewer's layout of a run in [`layout`].
//!
//! Recording layout (timelines `sim_time` [s] and `step`; view coordinates z-up):
//! - `world/bodies/<name>`: temporal `Transform3D` (G and the principal axes);
//!   `…/shape`: static display shape, with a static transform from the principal frame to the
//!   shape; `…/nodes`: static slave nodes (principal frame);
//! - `world/couplings/<name>`: `LineStrips3D` between the ends, each frame; a catenary is drawn
//!   along its solved shape in 32 segments coloured by tension (blue: the lowest tension along
//!   the line, red: the highest);
//! - `plots/energy`: one series each for kinetic, gravity, elastic, dissipated, external_work,
//!   total and balance [J], in one plot;
//! - `plots/tension`: one series per coupling, named after it [N], in one plot (a catenary's
//!   series is its larger end tension);
//! - `plots/catenary/<name>`: a catenary's end tensions, series `end1` and `end2` [N];
//! - `world/contacts/<name>`: a contact's face forces as arrows from the face centroids, those
//!   above a thousandth of the body's weight (`m·max(|g|, 1 m/s²)`), the largest of the frame
//!   one body radius long (the force itself is in `plots/contact/<name>`);
//! - `plots/contact/<name>`: a contact's total normal force `Σ|f_n|` and friction `|Σ f_t|`,
//!   series `normal` and `friction` [N]; its `plots/tension` series is the normal force;
//! - the water, when the scene has some: [`water`];
//! - the seabed and what lies on it, when the scene has one: [`seabed`].

pub mod layout;
pub mod paths;
pub mod seabed;
pub mod water;

use rerun::RecordingStream;
use std::path::Path;
use tether_physics::body::{RigidBody, Shape};
use tether_physics::coupling::catenary::LineState;
use tether_physics::coupling::{Contact, CouplingKind};
use tether_physics::math::{Rotation, Vec3};
use tether_physics::world::World;

/// The Rerun application id of Tether recordings.
pub const APPLICATION_ID: &str = "tether";

/// Logs a world, frame after frame, to a recording stream.
pub struct Recorder {
    stream: RecordingStream,
    body_paths: Vec<String>,
    coupling_paths: Vec<String>,
    /// The water's part, if the scene has water.
    water: Option<water::WaterRecorder>,
    /// The seabed's part, if the scene has a seabed.
    seabed: Option<seabed::SeabedRecorder>,
}

/// Face forces below this fraction of the body's weight are not drawn.
const ARROW_THRESHOLD: f64 = 1e-3;

/// Energy series, in the order logged.
const ENERGY_SERIES: [&str; 7] = ["kinetic", "gravity", "elastic", "dissipated", "external_work", "total", "balance"];

impl Recorder {
    /// A recorder writing to the `.rrd` file `path`; the file is created now, so an unwritable
    /// path fails before any simulation.
    pub fn to_file(path: &Path, world: &World) -> Result<Self, rerun::RecordingStreamError> {
        let stream = rerun::RecordingStreamBuilder::new(APPLICATION_ID).save(path)?;
        Self::new(stream, world)
    }

    /// A recorder writing to the `.rrd` file `path` under application id `application` and
    /// recording id `recording` (a sweep's: one application, one recording per case, so that
    /// several cases open side by side in the viewer); the file is created now.
    pub fn to_file_as(path: &Path, world: &World, application: &str, recording: &str) -> Result<Self, rerun::RecordingStreamError> {
        let application = rerun::ApplicationId::new_or_unknown(application);
        let stream = rerun::RecordingStreamBuilder::new(application).recording_id(recording).save(path)?;
        Self::new(stream, world)
    }

    /// A recorder on an existing stream; logs the static scene (view coordinates, shapes, nodes).
    pub fn new(stream: RecordingStream, world: &World) -> Result<Self, rerun::RecordingStreamError> {
        stream.log_static(paths::WORLD, &rerun::ViewCoordinates::RIGHT_HAND_Z_UP())?;
        let body_paths: Vec<String> = world.bodies().iter().map(|b| paths::body(&b.name)).collect();
        for body in world.bodies() {
            log_static_body(&stream, body)?;
        }
        stream.log_static(paths::ENERGY, &rerun::SeriesLines::new().with_names(ENERGY_SERIES))?;
        if !world.couplings().is_empty() {
            stream.log_static(paths::TENSION, &rerun::SeriesLines::new().with_names(world.couplings().iter().map(|c| c.name.as_str())))?;
        }
        for coupling in world.couplings() {
            match coupling.kind {
                CouplingKind::Catenary(_) => stream.log_static(paths::catenary_plot(&coupling.name), &rerun::SeriesLines::new().with_names(["end1", "end2"]))?,
                CouplingKind::Contact(_) => stream.log_static(paths::contact_plot(&coupling.name), &rerun::SeriesLines::new().with_names(["normal", "friction"]))?,
                CouplingKind::SpringDamper(_) => {}
            }
        }
        let coupling_paths = world.couplings().iter().map(paths::coupling).collect();
        let water = water::WaterRecorder::new(&stream, world)?;
        let seabed = seabed::SeabedRecorder::new(&stream, world)?;
        Ok(Self { stream, body_paths, coupling_paths, water, seabed })
    }

    /// Logs the world's current state at its `sim_time` and `step`.
    pub fn log_frame(&self, world: &World) -> Result<(), rerun::RecordingStreamError> {
        self.stream.set_duration_secs("sim_time", world.time());
        self.stream.set_time_sequence("step", world.steps() as i64);
        for (index, path) in self.body_paths.iter().enumerate() {
            let state = world.state(index);
            self.stream.log(path.as_str(), &pose(&state.position, &state.orientation))?;
        }
        let each = self.coupling_paths.iter().zip(world.coupling_forces()).zip(world.couplings()).enumerate();
        for (index, ((path, forces), coupling)) in each {
            match &coupling.kind {
                CouplingKind::Catenary(_) if let Some(state) = world.line_state(index) => {
                    self.stream.log(path.as_str(), &catenary_strips(state))?;
                    let (t1, t2) = state.end_tensions();
                    self.stream.log(paths::catenary_plot(&coupling.name), &rerun::Scalars::new([t1, t2]))?;
                }
                CouplingKind::Contact(contact) => {
                    self.stream.log(path.as_str(), &face_arrows(world, contact))?;
                    let totals = contact.totals(world.frames());
                    self.stream.log(paths::contact_plot(&coupling.name), &rerun::Scalars::new([totals.normal, totals.friction]))?;
                }
                _ => self.stream.log(path.as_str(), &rerun::LineStrips3D::new([[f32x3(&forces.point1), f32x3(&forces.point2)]]))?,
            }
        }
        if !world.couplings().is_empty() {
            self.stream.log(paths::TENSION, &rerun::Scalars::new(world.coupling_forces().iter().map(|f| f.tension)))?;
        }
        let energy = world.energy();
        let values = [energy.kinetic, energy.gravity, energy.elastic, energy.dissipated, energy.external_work, energy.total(), energy.balance()];
        self.stream.log(paths::ENERGY, &rerun::Scalars::new(values))?;
        if let Some(water) = &self.water {
            water.log_frame(&self.stream, world)?;
        }
        if let Some(seabed) = &self.seabed {
            seabed.log_frame(&self.stream, world)?;
        }
        Ok(())
    }

    /// Flushes everything to the sink and closes the stream (writes the `.rrd` footer).
    pub fn finish(self) -> Result<(), rerun::sink::SinkFlushError> {
        self.stream.flush_blocking()
    }
}

/// A contact's face forces above the threshold, as world arrows from the face centroids, the
/// largest one body radius long.
fn face_arrows(world: &World, contact: &Contact) -> rerun::Arrows3D {
    let body = &world.bodies()[contact.body];
    let weight = body.mass() * world.gravity().norm().max(1.0);
    let faces: Vec<_> = contact.active_faces(world.frames()).into_iter().filter(|face| face.force.norm() > ARROW_THRESHOLD * weight).collect();
    let largest = faces.iter().map(|face| face.force.norm()).fold(0.0, f64::max);
    let scale = contact.boundary.bounding_radius() / largest.max(f64::MIN_POSITIVE);
    let frame = &world.frames()[contact.body];
    let (origins, vectors): (Vec<[f32; 3]>, Vec<[f32; 3]>) =
        faces.iter().map(|face| (f32x3(&(frame.position + frame.rotation * face.centroid)), f32x3(&(frame.rotation * face.force * scale)))).unzip();
    rerun::Arrows3D::from_vectors(vectors).with_origins(origins).with_colors([rerun::Color::from_rgb(230, 120, 40)])
}

/// Segments of a catenary's shape, each coloured by its tension on a blue → red ramp between
/// the lowest and highest tension along the line.
fn catenary_strips(state: &LineState) -> rerun::LineStrips3D {
    let points = state.sample(32);
    let (low, high) = points.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), (_, t)| (lo.min(*t), hi.max(*t)));
    let span = (high - low).max(f64::MIN_POSITIVE);
    let segments = points.windows(2).map(|pair| [f32x3(&pair[0].0), f32x3(&pair[1].0)]);
    let colors = points.windows(2).map(|pair| {
        let heat = ((0.5 * (pair[0].1 + pair[1].1) - low) / span).clamp(0.0, 1.0);
        rerun::Color::from_rgb((60.0 + 195.0 * heat) as u8, 90, (255.0 - 195.0 * heat) as u8)
    });
    rerun::LineStrips3D::new(segments).with_colors(colors.collect::<Vec<_>>()).with_radii([rerun::Radius::new_ui_points(2.5)])
}

fn f32x3(v: &Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn pose(translation: &Vec3, rotation: &Rotation) -> rerun::Transform3D {
    let q = rotation.quaternion();
    rerun::Transform3D::from_translation_rotation(
        f32x3(translation),
        rerun::Quaternion::from_xyzw([q.i as f32, q.j as f32, q.k as f32, q.w as f32]),
    )
}

/// Static shape (placed in the principal frame) and slave nodes of a body.
fn log_static_body(stream: &RecordingStream, body: &RigidBody) -> Result<(), rerun::RecordingStreamError> {
    let shape_path = paths::body_shape(&body.name);
    let to_principal = body.reference_in_principal;
    let (center, axis_rotation) = match &body.shape {
        Shape::Box { center, .. } | Shape::Sphere { center, .. } => (*center, Rotation::identity()),
        // The vertices are already in the reference frame.
        Shape::Mesh { .. } => (Vec3::zeros(), Rotation::identity()),
        Shape::Cylinder { center, axis, .. } => {
            // Rerun's cylinders lie along z: turn z onto the axis.
            (*center, Rotation::rotation_between(&Vec3::z(), axis).unwrap_or_else(|| Rotation::from_axis_angle(&Vec3::x_axis(), std::f64::consts::PI)))
        }
    };
    let placement = to_principal * nalgebra::Isometry3::from_parts(center.into(), axis_rotation);
    stream.log_static(shape_path.as_str(), &pose(&placement.translation.vector, &placement.rotation))?;
    let color = rerun::Color::from_rgb(120, 160, 210);
    let solid = rerun::components::FillMode::Solid;
    match &body.shape {
        Shape::Box { size, .. } => {
            stream.log_static(shape_path.as_str(), &rerun::Boxes3D::from_half_sizes([f32x3(&(size * 0.5))]).with_colors([color]).with_fill_mode(solid))?
        }
        Shape::Sphere { radius, .. } => {
            stream.log_static(shape_path.as_str(), &rerun::Ellipsoids3D::from_radii([*radius as f32]).with_colors([color]).with_fill_mode(solid))?
        }
        Shape::Cylinder { radius, length, .. } => stream.log_static(
            shape_path.as_str(),
            &rerun::Cylinders3D::from_lengths_and_radii([*length as f32], [*radius as f32]).with_colors([color]).with_fill_mode(solid),
        )?,
        Shape::Mesh { vertices, triangles } => stream.log_static(
            shape_path.as_str(),
            &rerun::Mesh3D::new(vertices.iter().map(f32x3)).with_triangle_indices(triangles.iter().map(|&[a, b, c]| rerun::datatypes::UVec3D::new(a, b, c))).with_albedo_factor(rerun::datatypes::Rgba32::from_rgb(120, 160, 210)),
        )?,
    }
    if !body.slave_nodes.is_empty() {
        stream.log_static(paths::body_nodes(&body.name), &rerun::Points3D::new(body.slave_nodes.iter().map(f32x3)))?;
    }
    Ok(())
}
