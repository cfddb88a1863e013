//! Turns a parsed [`SceneFile`] into a [`World`]: the one place where scene data becomes
//! simulation state. Checks that need more than one value (names, references, mass properties)
//! are made here; a value's own range is checked by the constructor of its physics type
//! ([`tether_physics::parameter`]), whose error is placed here at the item and field it names,
//! never checked twice.

use super::file::{
    AgainstDef, BodyDef, CouplingDef, EndDef, InertiaDef, LawDef, NodeDef, SceneFile, SeabedContactDef, SeabedDef,
    ShapeDef, SupportDef, Triple, VelocityDef,
};
use super::mesh_file;
use super::source::ItemKind;
use std::path::Path;
use std::sync::Arc;
use tether_physics::body::{BodyState, Harmonic, PrescribedMotion, RigidBody, Shape, Support, VelocityProfile};
use tether_physics::coupling::contact::{ContactLaw, Opposing, Plane};
use tether_physics::coupling::{Catenary, Contact, Coupling, CouplingKind, ElasticLaw, Endpoint, SpringDamper};
use tether_physics::integrator::{Timing, Tolerances};
use tether_physics::mass_properties::{MassError, MassProperties, Node};
use tether_physics::math::{Mat3, Rotation, Vec3};
use tether_physics::mesh::{BoundaryMesh, MeshError, OutwardMesh, Surface};
use tether_physics::parameter::{Bound, ParameterError, require};
use tether_physics::seabed::{Seabed, SeabedError};
use tether_physics::system::{System, SystemError};
use tether_physics::world::{StepError, World};

mod air;
mod water;
pub use air::air_spec;
pub use water::{hydro_spec, water_spec};

/// Where a problem is in the file.
#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// A top-level field.
    Top(&'static str),
    /// An item of a list: its `occurrence`-th `name: "…"`, then optionally a field after it and
    /// a string literal after that.
    Item { kind: ItemKind, name: String, occurrence: usize, field: Option<&'static str>, literal: Option<String> },
    /// A top-level section (`seabed: Seabed(…)`, `water: Water(…)`), then optionally a field in it and a string
    /// literal after that.
    Section { section: &'static str, field: Option<&'static str>, literal: Option<String> },
}

/// A problem found while building, before it is given a line and column.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    pub place: Place,
    pub message: String,
}

/// A world, the bodies it was built from, and what is odd but allowed about it.
pub struct Built {
    pub world: World,
    pub bodies: Bodies,
    pub warnings: Vec<String>,
}

/// A scene's bodies as built, with their boundary meshes (made on first need and shared by the
/// contacts that use them): what a coupling is built against. Kept with a loaded scene, so that
/// a tuned coupling is built again without building every body and reading every mesh file.
#[derive(Debug, Clone)]
pub struct Bodies {
    bodies: Vec<RigidBody>,
    boundaries: Boundaries,
}

impl Bodies {
    /// Builds every body of `file` (mesh files relative to `directory`); warns of a mesh file
    /// wound inwards.
    pub fn build(file: &SceneFile, directory: &Path, warnings: &mut Vec<String>) -> Result<Self, Problem> {
        let mut bodies = Vec::with_capacity(file.bodies.len());
        for (index, def) in file.bodies.iter().enumerate() {
            let at = ItemAt::new(
                ItemKind::Body,
                &def.name,
                file.bodies[..index].iter().filter(|b| b.name == def.name).count(),
            );
            check_name(&at, file.bodies[..index].iter().map(|b| b.name.as_str()))?;
            bodies.push(build_body(def, directory, &at, warnings)?);
        }
        let boundaries = Boundaries::new(bodies.len());
        Ok(Self { bodies, boundaries })
    }

    /// The bodies, in the file's order.
    pub fn bodies(&self) -> &[RigidBody] {
        &self.bodies
    }
}

/// Builds the world a scene describes; mesh files are looked up relative to `directory`.
pub fn build(file: &SceneFile, directory: &Path) -> Result<Built, Problem> {
    let mut warnings = Vec::new();
    let timing = timing_with_warnings(file, &mut warnings)?;
    require("duration", file.duration, Bound::Positive, "s")
        .map_err(|error| Problem { place: Place::Top("duration"), message: error.to_string() })?;
    let mut bodies = Bodies::build(file, directory, &mut warnings)?;
    let mut states = Vec::with_capacity(file.bodies.len());
    for (def, body) in file.bodies.iter().zip(&bodies.bodies) {
        if let Some(axis) = body.mass_properties.violated_triangle_inequality() {
            warnings.push(format!(
                "body \"{}\": principal moment I{} = {:.6e} kg·m² exceeds the sum of the other two {:?}: no real mass distribution has this inertia",
                def.name,
                axis + 1,
                body.principal_moments()[axis],
                body.principal_moments().as_slice()
            ));
        }
        states.push(initial_state(def, body));
    }
    let mut couplings = Vec::with_capacity(file.couplings.len());
    for (index, def) in file.couplings.iter().enumerate() {
        let at = coupling_at(file, index);
        check_name(&at, file.couplings[..index].iter().map(CouplingDef::name))?;
        couplings.push(build_coupling(def, &mut bodies, &at)?);
    }
    let seabed = match &file.seabed {
        Some(def) => Some(build_seabed(def, file, &mut bodies, &mut couplings)?),
        None => None,
    };
    warn_about_lines(file, &mut warnings);
    let system = System::new(vec3(file.gravity), bodies.bodies.clone(), couplings, states)
        .map_err(|e| system_problem(file, e))?;
    let system = water::add_water(system, file, &bodies.bodies, directory, &mut warnings)?;
    let mut system = air::add_air(system, file, &mut warnings)?;
    if let Some(seabed) = seabed {
        system = system.with_seabed(seabed).map_err(|e| system_problem(file, e))?;
    }
    // Names are unique by now: the coupling at fault is the first of its name.
    let world = World::new(system, timing).map_err(|e| match e {
        StepError::Coupling { coupling, source, .. } => {
            ItemAt::new(ItemKind::Coupling, &coupling, 0).at_name(format!("at t = 0: {source}"))
        }
        other => Problem { place: Place::Top("bodies"), message: other.to_string() },
    })?;
    Ok(Built { world, bodies, warnings })
}

/// The state of a body at t = 0: its initial velocities, and turned by `def.rotation` about its
/// master node.
fn initial_state(def: &BodyDef, body: &RigidBody) -> BodyState {
    let state = body.initial_state(vec3(def.velocity), vec3(def.angular_velocity));
    let turn = Rotation::from_scaled_axis(vec3(def.rotation));
    let master = vec3(def.master.position);
    let spin = state.orientation * state.angular_velocity;
    let orientation = turn * state.orientation;
    BodyState {
        position: master + turn * (state.position - master),
        orientation,
        angular_velocity: orientation.inverse_transform_vector(&spin),
        ..state
    }
}

/// The seabed section: its elevation and line friction, and a contact coupling
/// `seabed.<body>` against its plane for each body listed (added to `couplings`).
fn build_seabed(
    def: &SeabedDef,
    file: &SceneFile,
    built: &mut Bodies,
    couplings: &mut Vec<Coupling>,
) -> Result<Seabed, Problem> {
    let seabed = seabed_of(def, file)?;
    if let Some(contact) = &def.contact {
        couplings.extend(seabed_contacts(contact, &seabed, file, built, &ItemAt::section("seabed"))?);
    }
    Ok(seabed)
}

/// The seabed of `file` (its elevation and line friction; its contacts are couplings), checked
/// as loading checks it, with the same messages (live tuning).
pub fn seabed(file: &SceneFile) -> Result<Seabed, Problem> {
    let Some(def) = &file.seabed else {
        return Err(Problem { place: Place::Top("seabed"), message: "the scene has no seabed".into() });
    };
    seabed_of(def, file)
}

/// The seabed `def` of `file`: its elevation and line friction.
fn seabed_of(def: &SeabedDef, file: &SceneFile) -> Result<Seabed, Problem> {
    let elevation = seabed_elevation(def, file, &ItemAt::section("seabed"))?;
    Seabed::new(elevation, def.line_friction).map_err(seabed_problem)
}

/// The seabed's height `z_b` [m]: the water's bottom `z_w − h` when the scene has water with a
/// depth (a declared elevation must then agree with it), the declared one in a scene without
/// water. Deep water (no depth) has no bottom for a seabed to be.
fn seabed_elevation(def: &SeabedDef, file: &SceneFile, at: &ItemAt) -> Result<f64, Problem> {
    match (&file.water, def.elevation) {
        (None, Some(elevation)) => Ok(elevation),
        (None, None) => {
            Err(at
                .at_name("the seabed needs an elevation (z_b, m): the scene has no water depth to take it from".into()))
        }
        (Some(water), declared) => {
            let Some(depth) = water.depth else {
                return Err(at.at_name(
                    "the water is deep (no depth): give the water a depth, and the seabed lies there".into(),
                ));
            };
            let bottom = water.level - depth;
            match declared {
                // Agreement to round-off of the sum `z_w − h`.
                Some(elevation) if (elevation - bottom).abs() > 1e-9 * (1.0 + bottom.abs()) => Err(at.at_field(
                    "elevation",
                    format!("the seabed elevation {elevation} m disagrees with the water's bottom (level {} m − depth {depth} m = {bottom} m): leave it out and it lies there", water.level),
                )),
                _ => Ok(bottom),
            }
        }
    }
}

/// A contact coupling against the seabed's plane for each body of `def`.
fn seabed_contacts(
    def: &SeabedContactDef,
    seabed: &Seabed,
    file: &SceneFile,
    built: &mut Bodies,
    at: &ItemAt,
) -> Result<Vec<Coupling>, Problem> {
    let law = ContactLaw::new(def.stiffness, def.damping, def.range, def.friction, def.friction_sharpness)
        .map_err(|e| at.refused(&e))?;
    let up = -vec3(file.gravity).try_normalize(0.0).unwrap_or_else(|| -Vec3::z());
    let plane = Plane { point: up * seabed.elevation(), normal: up };
    let Bodies { bodies, boundaries } = built;
    let mut couplings = Vec::with_capacity(def.bodies.len());
    for (index, name) in def.bodies.iter().enumerate() {
        let body = body_index(name, bodies, "bodies", at)?;
        if def.bodies[..index].contains(name) {
            return Err(at.problem(Some("bodies"), Some(name), format!("body {name:?} is listed twice")));
        }
        let coupling = format!("seabed.{name}");
        if file.couplings.iter().any(|c| c.name() == coupling) {
            return Err(at.problem(
                Some("bodies"),
                Some(name),
                format!("the seabed contact of body {name:?} would be named {coupling:?}, which a coupling already is"),
            ));
        }
        let boundary = boundaries
            .mesh(bodies, body)
            .map_err(|e| at.problem(Some("bodies"), Some(name), format!("boundary of body {name:?}: {e}")))?;
        let expected_area = boundary.area() / 6.0;
        let contact = Contact::new(body, boundary, Opposing::Planes(vec![plane]), law, expected_area)
            .map_err(|e| at.refused(&e))?;
        couplings.push(Coupling { name: coupling, kind: CouplingKind::Contact(contact) });
    }
    Ok(couplings)
}

/// A seabed refused by its constructor, placed at its field; the error names the seabed.
fn seabed_problem(error: SeabedError) -> Problem {
    let place = Place::Section { section: "seabed", field: Some(error.0.field()), literal: None };
    Problem { place, message: error.to_string() }
}

/// A system the scene cannot make, placed at the coupling at fault when there is one.
fn system_problem(file: &SceneFile, error: SystemError) -> Problem {
    match &error {
        SystemError::BelowSeabed { coupling, source } => {
            let field = if source.end == 1 { "end1" } else { "end2" };
            match file.couplings.iter().position(|c| c.name() == coupling) {
                Some(index) => coupling_at(file, index).problem(Some(field), None, source.to_string()),
                None => Problem { place: Place::Top("seabed"), message: error.to_string() },
            }
        }
        SystemError::Line { coupling, source } => line_problem(coupling, source),
        SystemError::UnknownBody { .. } => Problem { place: Place::Top("couplings"), message: error.to_string() },
        SystemError::StateCount { .. } => Problem { place: Place::Top("bodies"), message: error.to_string() },
        // The water's, which neither `System::new` nor `System::with_seabed` (the calls placed
        // here) makes: `water::add_water` places them.
        SystemError::FloatingBody { .. }
        | SystemError::Water(_)
        | SystemError::Hydro { .. }
        | SystemError::NoWater
        | SystemError::Switch { .. }
        | SystemError::Drift { .. } => Problem { place: Place::Top("water"), message: error.to_string() },
        // The air's, which `air::add_air` places.
        SystemError::Air(_) | SystemError::Wind { .. } | SystemError::UnknownWindBody { .. } | SystemError::NoAir => {
            Problem { place: Place::Top("air"), message: error.to_string() }
        }
    }
}

/// A line refused in its surroundings, placed at its field that made the value refused.
fn line_problem(coupling: &str, source: &ParameterError) -> Problem {
    // Names are unique by now: the coupling at fault is the first of its name.
    ItemAt::new(ItemKind::Coupling, coupling, 0).refused(source)
}

/// Warnings about lines: a displaced volume where there is no water to displace; a line that
/// floats (`ρ A_d > λ0`: it arches upward, and nothing stops it at the surface).
fn warn_about_lines(file: &SceneFile, warnings: &mut Vec<String>) {
    for def in &file.couplings {
        let CouplingDef::Catenary { name, displaced_area, mass_per_length, .. } = def else { continue };
        match &file.water {
            None if *displaced_area > 0.0 => warnings.push(format!("coupling {name:?}: displaced_area is ignored in a scene without water (the line weighs λ0 g per metre)")),
            Some(water) if water.density * displaced_area > *mass_per_length => warnings.push(format!(
                "coupling {name:?}: the line floats (ρ A_d = {} kg/m > λ0 = {mass_per_length} kg/m): it arches upward from its ends, and nothing stops it at the water surface",
                water.density * displaced_area
            )),
            _ => {}
        }
    }
}

/// Where coupling `index` of `file` is: its name and how many before it share the name.
fn coupling_at(file: &SceneFile, index: usize) -> ItemAt<'_> {
    let name = file.couplings[index].name();
    ItemAt::new(ItemKind::Coupling, name, file.couplings[..index].iter().filter(|c| c.name() == name).count())
}

/// The time step settings of a scene, checked: `dt` > 0 s, at least one substep, sound
/// adaptive tolerances.
pub fn timing(file: &SceneFile) -> Result<Timing, Problem> {
    timing_with_warnings(file, &mut Vec::new())
}

fn timing_with_warnings(file: &SceneFile, warnings: &mut Vec<String>) -> Result<Timing, Problem> {
    let tolerances = build_tolerances(file, warnings)?;
    Timing::new(file.dt, file.integrator, file.substeps, tolerances)
        .map_err(|error| Problem { place: Place::Top(error.field()), message: error.to_string() })
}

/// Builds coupling `index` of `file` on its own, against the scene's built `bodies`, with the
/// checks and messages of [`build`] (live tuning builds a changed coupling this way before it
/// reaches a running world).
pub fn coupling(file: &SceneFile, index: usize, bodies: &mut Bodies) -> Result<Coupling, Problem> {
    let Some(def) = file.couplings.get(index) else {
        return Err(Problem { place: Place::Top("couplings"), message: format!("the scene has no coupling {index}") });
    };
    build_coupling(def, bodies, &coupling_at(file, index))
}

/// The `adaptive` settings, checked by [`Tolerances::new`]; a warning when the integrator does
/// not use them.
fn build_tolerances(file: &SceneFile, warnings: &mut Vec<String>) -> Result<Tolerances, Problem> {
    let Some(def) = file.adaptive else { return Ok(Tolerances::default()) };
    let tolerances = Tolerances::new(def.rtol, def.atol, def.max_step)
        .map_err(|error| ItemAt::section("adaptive").refused(&error))?;
    if !file.integrator.is_adaptive() {
        warnings
            .push(format!("the adaptive settings are for integrator dopri45; {} ignores them", file.integrator.name()));
    }
    Ok(tolerances)
}

/// Locates problems in one item, or in a top-level section.
struct ItemAt<'a> {
    kind: ItemKind,
    name: &'a str,
    occurrence: usize,
    /// The section the problems are in, instead of an item.
    section: Option<&'static str>,
}

impl<'a> ItemAt<'a> {
    fn new(kind: ItemKind, name: &'a str, occurrence: usize) -> Self {
        Self { kind, name, occurrence, section: None }
    }

    /// Problems in the top-level section `section`.
    fn section(section: &'static str) -> Self {
        Self { kind: ItemKind::Coupling, name: section, occurrence: 0, section: Some(section) }
    }

    fn problem(&self, field: Option<&'static str>, literal: Option<&str>, message: String) -> Problem {
        if let Some(section) = self.section {
            return Problem {
                place: Place::Section { section, field, literal: literal.map(str::to_string) },
                message: format!("{section}: {message}"),
            };
        }
        Problem {
            place: Place::Item {
                kind: self.kind,
                name: self.name.to_string(),
                occurrence: self.occurrence,
                field,
                literal: literal.map(str::to_string),
            },
            // Debug formatting quotes the name and escapes what would break the one-line error.
            message: format!("{} {:?}: {message}", self.kind.label(), self.name),
        }
    }

    fn at_field(&self, field: &'static str, message: String) -> Problem {
        self.problem(Some(field), None, message)
    }

    fn at_name(&self, message: String) -> Problem {
        self.problem(None, None, message)
    }

    /// A value refused by the constructor of its physics type, placed at its field.
    fn refused(&self, error: &ParameterError) -> Problem {
        self.at_field(error.field(), error.to_string())
    }

    /// `value` if it is within `bound` ([`require`]), else the problem at `field`.
    fn require(&self, field: &'static str, value: f64, bound: Bound, unit: &'static str) -> Result<f64, Problem> {
        require(field, value, bound, unit).map_err(|error| self.refused(&error))
    }
}

/// Names become entity paths and CLI arguments: non-empty, letters, digits, `_`, `-`, `.`; unique.
fn check_name<'n>(at: &ItemAt, earlier: impl Iterator<Item = &'n str>) -> Result<(), Problem> {
    let valid = !at.name.is_empty() && at.name.chars().all(|c| c.is_alphanumeric() || "_-.".contains(c));
    if !valid {
        return Err(at.at_name("name must be non-empty and use only letters, digits, '_', '-' and '.'".into()));
    }
    if earlier.into_iter().any(|n| n == at.name) {
        return Err(at.at_name(format!("duplicate {} name", at.kind.label())));
    }
    Ok(())
}

fn vec3(t: Triple) -> Vec3 {
    Vec3::new(t[0], t[1], t[2])
}

fn tensor(i: &InertiaDef) -> Mat3 {
    Mat3::new(i.xx, i.xy, i.xz, i.xy, i.yy, i.yz, i.xz, i.yz, i.zz)
}

fn node(def: &NodeDef) -> Node {
    Node { position: vec3(def.position), mass: def.mass, inertia: tensor(&def.inertia) }
}

fn build_body(def: &BodyDef, directory: &Path, at: &ItemAt, warnings: &mut Vec<String>) -> Result<RigidBody, Problem> {
    let slaves: Vec<Node> = def.slaves.iter().map(node).collect();
    let mass_properties = MassProperties::from_nodes(&node(&def.master), &slaves).map_err(|e| {
        let field = match e {
            MassError::NotPositiveDefinite(_) | MassError::NotFinite { .. } => "inertia",
            MassError::NonPositiveMass(_) | MassError::NegativeNodeMass { .. } => "mass",
        };
        at.at_field(field, e.to_string())
    })?;
    let support = build_support(&def.support, at)?;
    let shape = build_shape(&def.shape, directory, at, warnings)?;
    let slave_positions: Vec<Vec3> = slaves.iter().map(|n| n.position).collect();
    Ok(RigidBody::new(def.name.clone(), mass_properties, vec3(def.master.position), &slave_positions, support, shape))
}

fn build_support(def: &SupportDef, at: &ItemAt) -> Result<Support, Problem> {
    Ok(match def {
        SupportDef::Free => Support::Free,
        SupportDef::Fixed { translation: (x, y, z), rotation } => {
            Support::Fixed { translation: [*x, *y, *z], rotation: *rotation }
        }
        SupportDef::Kinematic { velocity, angular_velocity } => {
            let velocity = match velocity {
                VelocityDef::Constant(v) => VelocityProfile::Constant(vec3(*v)),
                VelocityDef::Table(points) => {
                    if points.len() < 2 {
                        return Err(at.at_field(
                            "velocity",
                            format!("a velocity table needs at least 2 points, got {}", points.len()),
                        ));
                    }
                    if let Some(i) = (1..points.len()).find(|&i| points[i].0 <= points[i - 1].0) {
                        return Err(at.at_field(
                            "velocity",
                            format!(
                                "velocity table point {i}: time must increase strictly ({} then {})",
                                points[i - 1].0,
                                points[i].0
                            ),
                        ));
                    }
                    VelocityProfile::Table(points.iter().map(|(t, v)| (*t, vec3(*v))).collect())
                }
                VelocityDef::Harmonic { amplitude, period, phase } => VelocityProfile::Harmonic(
                    Harmonic::new(vec3(*amplitude), *period, vec3(*phase)).map_err(|error| at.refused(&error))?,
                ),
            };
            Support::Kinematic(PrescribedMotion { velocity, angular_velocity: vec3(*angular_velocity) })
        }
    })
}

/// Subdivisions of a sphere's icosphere beyond which the mesh (20·4ⁿ triangles) is too big
/// to be meant: 6 gives 81,920.
const MAX_SUBDIVISIONS: u32 = 6;

/// Squares per box face edge beyond which the mesh (12 n² triangles) is too big to be meant:
/// 64 gives 49,152.
const MAX_BOX_SUBDIVISIONS: u32 = 64;

/// The body's shape. A mesh file is checked once here by [`OutwardMesh::new`], for contact and
/// water alike (whether it is closed, which only a hull needs, is checked when the body enters
/// the water); one wound inwards is turned over, with a warning.
fn build_shape(def: &ShapeDef, directory: &Path, at: &ItemAt, warnings: &mut Vec<String>) -> Result<Shape, Problem> {
    let positive = |field: &'static str, value: f64| at.require(field, value, Bound::Positive, "m").map(|_| ());
    Ok(match def {
        ShapeDef::Box { size, center, subdivisions } => {
            for s in size {
                positive("size", *s)?;
            }
            if !(1..=MAX_BOX_SUBDIVISIONS).contains(subdivisions) {
                return Err(at.at_field(
                    "subdivisions",
                    format!("box subdivisions must be 1 to {MAX_BOX_SUBDIVISIONS}, got {subdivisions}"),
                ));
            }
            Shape::Box { size: vec3(*size), center: vec3(*center), subdivisions: *subdivisions }
        }
        ShapeDef::Sphere { radius, center, subdivisions } => {
            positive("radius", *radius)?;
            if *subdivisions > MAX_SUBDIVISIONS {
                return Err(at.at_field(
                    "subdivisions",
                    format!("subdivisions must be at most {MAX_SUBDIVISIONS}, got {subdivisions}"),
                ));
            }
            Shape::Sphere { radius: *radius, center: vec3(*center), subdivisions: *subdivisions }
        }
        ShapeDef::Cylinder { radius, length, axis, center } => {
            positive("radius", *radius)?;
            positive("length", *length)?;
            let axis = vec3(*axis);
            let Some(axis) = axis.try_normalize(1e-12) else {
                return Err(at.at_field("axis", "cylinder axis must not be zero".into()));
            };
            Shape::Cylinder { radius: *radius, length: *length, axis, center: vec3(*center) }
        }
        ShapeDef::Mesh { file, scale, center } => {
            at.require("scale", *scale, Bound::Positive, "")?;
            let (vertices, triangles) =
                mesh_file::read(&directory.join(file)).map_err(|e| at.problem(Some("file"), Some(file), e))?;
            let vertices: Vec<Vec3> = vertices.iter().map(|v| v * *scale + vec3(*center)).collect();
            let mesh = OutwardMesh::new(vertices, triangles)
                .map_err(|e| at.problem(Some("file"), Some(file), format!("mesh file {file:?}: {e}")))?;
            if let Some(turned_over) = mesh.turned_over() {
                warnings.push(format!("body \"{}\": mesh file {file:?}: {turned_over}", at.name));
            }
            let (vertices, triangles) = mesh.into_parts();
            Shape::Mesh { vertices, triangles }
        }
    })
}

fn build_end(def: &EndDef, bodies: &[RigidBody], at: &ItemAt) -> Result<Endpoint, Problem> {
    Ok(match def {
        EndDef::World(p) => Endpoint::World(vec3(*p)),
        EndDef::Body { body, point } => {
            let index = body_index(body, bodies, "body", at)?;
            Endpoint::on_body(index, bodies[index].principal_point(&vec3(*point)))
        }
    })
}

/// The boundary meshes and opposing surfaces of the bodies in contact, built once per body
/// and shared by its contacts (a body in no contact gets none).
#[derive(Debug, Clone)]
struct Boundaries {
    meshes: Vec<Option<Arc<BoundaryMesh>>>,
    surfaces: Vec<Option<Arc<Surface>>>,
}

impl Boundaries {
    fn new(bodies: usize) -> Self {
        Self { meshes: vec![None; bodies], surfaces: vec![None; bodies] }
    }

    fn mesh(&mut self, bodies: &[RigidBody], index: usize) -> Result<Arc<BoundaryMesh>, MeshError> {
        if let Some(mesh) = &self.meshes[index] {
            return Ok(Arc::clone(mesh));
        }
        let mesh = Arc::new(BoundaryMesh::of_body(&bodies[index])?);
        self.meshes[index] = Some(Arc::clone(&mesh));
        Ok(mesh)
    }

    fn surface(&mut self, bodies: &[RigidBody], index: usize) -> Result<Arc<Surface>, MeshError> {
        if let Some(surface) = &self.surfaces[index] {
            return Ok(Arc::clone(surface));
        }
        let surface = Arc::new(Surface::new(self.mesh(bodies, index)?.as_ref())?);
        self.surfaces[index] = Some(Arc::clone(&surface));
        Ok(surface)
    }
}

fn build_coupling(def: &CouplingDef, built: &mut Bodies, at: &ItemAt) -> Result<Coupling, Problem> {
    let Bodies { bodies, boundaries } = built;
    let bodies: &[RigidBody] = bodies;
    let kind = match def {
        CouplingDef::SpringDamper { end1, end2, law, damping, .. } => {
            let (end1, end2) = build_ends(end1, end2, bodies, at)?;
            let law = build_law(law).map_err(|e| at.refused(&e))?;
            CouplingKind::SpringDamper(SpringDamper::new(end1, end2, law, *damping).map_err(|e| at.refused(&e))?)
        }
        CouplingDef::Catenary {
            end1,
            end2,
            mass_per_length,
            length,
            stiffness,
            displaced_area,
            model,
            breaking_load,
            ..
        } => {
            if let Some(load) = breaking_load {
                require("breaking_load", *load, Bound::Positive, "N").map_err(|e| at.refused(&e))?;
            }
            let (end1, end2) = build_ends(end1, end2, bodies, at)?;
            let model = model.build().map_err(|e| at.refused(&e))?;
            let line = Catenary::new(end1, end2, *mass_per_length, *length, *stiffness)
                .and_then(|line| line.with_displaced_area(*displaced_area))
                .map_err(|e| at.refused(&e))?
                .with_model(model);
            CouplingKind::Catenary(line)
        }
        CouplingDef::Contact {
            body,
            against,
            stiffness,
            damping,
            range,
            friction,
            friction_sharpness,
            expected_area,
            ..
        } => {
            let law = ContactLaw::new(*stiffness, *damping, *range, *friction, *friction_sharpness)
                .map_err(|e| at.refused(&e))?;
            let index = body_index(body, bodies, "body", at)?;
            let mesh_problem = |e: MeshError| at.at_field("body", format!("boundary of body {body:?}: {e}"));
            let boundary = boundaries.mesh(bodies, index).map_err(mesh_problem)?;
            let against = build_against(against, index, bodies, boundaries, at)?;
            let expected_area = expected_area.unwrap_or(boundary.area() / 6.0);
            CouplingKind::Contact(
                Contact::new(index, boundary, against, law, expected_area).map_err(|e| at.refused(&e))?,
            )
        }
    };
    Ok(Coupling { name: def.name().to_string(), kind })
}

/// A spring's or a line's two ends, which must differ.
fn build_ends(
    end1: &EndDef,
    end2: &EndDef,
    bodies: &[RigidBody],
    at: &ItemAt,
) -> Result<(Endpoint, Endpoint), Problem> {
    if end1 == end2 {
        return Err(at.at_field("end2", "both ends are the same point: the coupling has no direction".into()));
    }
    Ok((build_end(end1, bodies, at)?, build_end(end2, bodies, at)?))
}

fn build_against(
    def: &AgainstDef,
    body: usize,
    bodies: &[RigidBody],
    boundaries: &mut Boundaries,
    at: &ItemAt,
) -> Result<Opposing, Problem> {
    Ok(match def {
        AgainstDef::Plane { point, normal } => {
            let Some(normal) = vec3(*normal).try_normalize(1e-12) else {
                return Err(at.at_field("normal", "plane normal must not be zero".into()));
            };
            Opposing::Planes(vec![Plane { point: vec3(*point), normal }])
        }
        AgainstDef::DomainBox { min, max } => {
            if !(0..3).all(|i| min[i] < max[i]) {
                return Err(
                    at.at_field("max", format!("domain box max {max:?} must exceed min {min:?} in every coordinate"))
                );
            }
            Opposing::Planes(Plane::domain_box(&vec3(*min), &vec3(*max)).to_vec())
        }
        AgainstDef::Body(name) => {
            let other = body_index(name, bodies, "against", at)?;
            if other == body {
                return Err(at.problem(
                    Some("against"),
                    Some(name),
                    format!("body {name:?} cannot be in contact with itself"),
                ));
            }
            let surface = boundaries
                .surface(bodies, other)
                .map_err(|e| at.problem(Some("against"), Some(name), format!("boundary of body {name:?}: {e}")))?;
            Opposing::Body { body: other, surface }
        }
    })
}

/// The index of body `name`, or a problem at `field` listing the bodies.
fn body_index(name: &str, bodies: &[RigidBody], field: &'static str, at: &ItemAt) -> Result<usize, Problem> {
    bodies.iter().position(|b| b.name == name).ok_or_else(|| {
        let known: Vec<&str> = bodies.iter().map(|b| b.name.as_str()).collect();
        at.problem(Some(field), Some(name), format!("unknown body {name:?} (bodies: {})", known.join(", ")))
    })
}

/// The elastic law of `def`: its tables checked as they are made
/// ([`ElasticLaw::stiffness_table`]), its numbers by [`SpringDamper::new`].
fn build_law(def: &LawDef) -> Result<ElasticLaw, ParameterError> {
    Ok(match def {
        LawDef::Linear { stiffness, rest_length } => {
            ElasticLaw::Linear { stiffness: *stiffness, rest_length: *rest_length }
        }
        LawDef::Polynomial { a, b, c, rest_length } => {
            ElasticLaw::Polynomial { a: *a, b: *b, c: *c, rest_length: *rest_length }
        }
        LawDef::ForceCurve { points } => ElasticLaw::force_curve(points.clone())?,
        LawDef::StiffnessCurve { points, rest_length } => ElasticLaw::StiffnessCurve {
            stiffness: ElasticLaw::stiffness_table(points.clone())?,
            rest_length: *rest_length,
        },
        LawDef::ReferenceForce { points, reference_length, reference_force, rest_length } => {
            ElasticLaw::ReferenceForce {
                stiffness: ElasticLaw::stiffness_table(points.clone())?,
                reference_length: *reference_length,
                reference_force: *reference_force,
                rest_length: *rest_length,
            }
        }
    })
}
