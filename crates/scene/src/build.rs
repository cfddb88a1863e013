//! Turns a parsed [`SceneFile`] into a [`World`]: the one place where scene data becomes
//! simulation state. Every check that needs more than one value (names, references, mass
//! properties, tables) is made here and reported with the item it concerns.

use super::file::{AgainstDef, BodyDef, CouplingDef, EndDef, InertiaDef, LawDef, NodeDef, SceneFile, ShapeDef, SupportDef, Triple, VelocityDef};
use super::mesh_file;
use super::source::ItemKind;
use tether_physics::body::{PrescribedMotion, RigidBody, Shape, Support, VelocityProfile};
use tether_physics::coupling::contact::{ContactLaw, Opposing, Plane};
use tether_physics::coupling::{Catenary, Contact, Coupling, CouplingKind, ElasticLaw, Endpoint, SpringDamper};
use tether_physics::integrator::{Substeps, Timing, Tolerances};
use tether_physics::mass_properties::{MassError, MassProperties, Node};
use tether_physics::math::{Mat3, Vec3};
use tether_physics::mesh::{BoundaryMesh, MeshError, Surface};
use tether_physics::system::System;
use tether_physics::water::Hull;
use tether_physics::world::{StepError, World};
use std::path::Path;
use std::sync::Arc;

mod water;
pub use water::{hydro_spec, water_spec};

/// Where a problem is in the file.
#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// A top-level field.
    Top(&'static str),
    /// A field of a top-level section (`water: Water(... depth: ...)`), or the section itself.
    Section { section: &'static str, field: &'static str },
    /// An item of a list: its `occurrence`-th `name: "…"`, then optionally a field after it and
    /// a string literal after that.
    Item { kind: ItemKind, name: String, occurrence: usize, field: Option<&'static str>, literal: Option<String> },
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
    /// Builds every body of `file` (mesh files relative to `directory`).
    pub fn build(file: &SceneFile, directory: &Path) -> Result<Self, Problem> {
        let mut bodies = Vec::with_capacity(file.bodies.len());
        for (index, def) in file.bodies.iter().enumerate() {
            let at = ItemAt::new(ItemKind::Body, &def.name, file.bodies[..index].iter().filter(|b| b.name == def.name).count());
            check_name(&at, file.bodies[..index].iter().map(|b| b.name.as_str()))?;
            let in_water = file.water.is_some() && def.hydro.is_some();
            bodies.push(build_body(def, directory, &at, in_water)?);
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
    if !(file.duration > 0.0) {
        return Err(Problem { place: Place::Top("duration"), message: format!("duration must be > 0 s, got {}", file.duration) });
    }
    let mut bodies = Bodies::build(file, directory)?;
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
        states.push(body.initial_state(vec3(def.velocity), vec3(def.angular_velocity)));
    }
    let mut couplings = Vec::with_capacity(file.couplings.len());
    for (index, def) in file.couplings.iter().enumerate() {
        let at = coupling_at(file, index);
        check_name(&at, file.couplings[..index].iter().map(CouplingDef::name))?;
        couplings.push(build_coupling(def, &mut bodies, &at)?);
    }
    let system = System::new(vec3(file.gravity), bodies.bodies.clone(), couplings, states).map_err(|e| Problem { place: Place::Top("couplings"), message: e.to_string() })?;
    let system = water::add_water(system, file, &bodies.bodies, &mut warnings)?;
    // Names are unique by now: the coupling at fault is the first of its name.
    let world = World::new(system, timing).map_err(|e| match e {
        StepError::Coupling { coupling, source, .. } => ItemAt::new(ItemKind::Coupling, &coupling, 0).at_name(format!("at t = 0: {source}")),
        other => Problem { place: Place::Top("bodies"), message: other.to_string() },
    })?;
    Ok(Built { world, bodies, warnings })
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
    if !(file.dt > 0.0 && file.dt.is_finite()) {
        return Err(Problem { place: Place::Top("dt"), message: format!("time step dt must be > 0 s, got {}", file.dt) });
    }
    if file.substeps == Substeps::Fixed(0) {
        return Err(Problem { place: Place::Top("substeps"), message: "substeps must be at least 1".into() });
    }
    let tolerances = build_tolerances(file, warnings)?;
    Ok(Timing { dt: file.dt, integrator: file.integrator, substeps: file.substeps, tolerances })
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

/// The `adaptive` settings, checked; a warning when the integrator does not use them.
fn build_tolerances(file: &SceneFile, warnings: &mut Vec<String>) -> Result<Tolerances, Problem> {
    let Some(def) = file.adaptive else { return Ok(Tolerances::default()) };
    if !(def.rtol > 0.0 && def.rtol < 1.0) {
        return Err(Problem { place: Place::Top("rtol"), message: format!("adaptive rtol must be > 0 and < 1, got {}", def.rtol) });
    }
    if !(def.atol > 0.0) {
        return Err(Problem { place: Place::Top("atol"), message: format!("adaptive atol must be > 0, got {}", def.atol) });
    }
    if let Some(max_step) = def.max_step.filter(|m| !(*m > 0.0)) {
        return Err(Problem { place: Place::Top("max_step"), message: format!("adaptive max_step must be > 0 s, got {max_step}") });
    }
    if !file.integrator.is_adaptive() {
        warnings.push(format!("the adaptive settings are for integrator dopri45; {} ignores them", file.integrator.name()));
    }
    Ok(Tolerances { rtol: def.rtol, atol: def.atol, max_step: def.max_step })
}

/// Locates problems in one item.
struct ItemAt<'a> {
    kind: ItemKind,
    name: &'a str,
    occurrence: usize,
}

impl<'a> ItemAt<'a> {
    fn new(kind: ItemKind, name: &'a str, occurrence: usize) -> Self {
        Self { kind, name, occurrence }
    }

    fn problem(&self, field: Option<&'static str>, literal: Option<&str>, message: String) -> Problem {
        Problem {
            place: Place::Item { kind: self.kind, name: self.name.to_string(), occurrence: self.occurrence, field, literal: literal.map(str::to_string) },
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

    /// `value` if it is within `bound`, else a problem at `field`: "`field` must be > 0 `unit`,
    /// got `value`" (NaN is never within).
    fn require(&self, field: &'static str, value: f64, bound: Bound, unit: &str) -> Result<f64, Problem> {
        let (within, rule) = match bound {
            Bound::Positive => (value > 0.0, "> 0"),
            Bound::NonNegative => (value >= 0.0, "≥ 0"),
        };
        let unit = if unit.is_empty() { String::new() } else { format!(" {unit}") };
        if within { Ok(value) } else { Err(self.at_field(field, format!("{field} must be {rule}{unit}, got {value}"))) }
    }
}

/// The range a number must be in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Bound {
    Positive,
    NonNegative,
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

fn build_body(def: &BodyDef, directory: &Path, at: &ItemAt, in_water: bool) -> Result<RigidBody, Problem> {
    let slaves: Vec<Node> = def.slaves.iter().map(node).collect();
    let mass_properties = MassProperties::from_nodes(&node(&def.master), &slaves).map_err(|e| {
        let field = match e {
            MassError::NotPositiveDefinite(_) | MassError::NotFinite { .. } => "inertia",
            _ => "mass",
        };
        at.at_field(field, e.to_string())
    })?;
    let support = build_support(&def.support, at)?;
    let shape = build_shape(&def.shape, directory, at, in_water)?;
    let slave_positions: Vec<Vec3> = slaves.iter().map(|n| n.position).collect();
    Ok(RigidBody::new(def.name.clone(), mass_properties, vec3(def.master.position), &slave_positions, support, shape))
}

fn build_support(def: &SupportDef, at: &ItemAt) -> Result<Support, Problem> {
    Ok(match def {
        SupportDef::Free => Support::Free,
        SupportDef::Fixed { translation: (x, y, z), rotation } => Support::Fixed { translation: [*x, *y, *z], rotation: *rotation },
        SupportDef::Kinematic { velocity, angular_velocity } => {
            let velocity = match velocity {
                VelocityDef::Constant(v) => VelocityProfile::Constant(vec3(*v)),
                VelocityDef::Table(points) => {
                    if points.len() < 2 {
                        return Err(at.at_field("velocity", format!("a velocity table needs at least 2 points, got {}", points.len())));
                    }
                    if let Some(i) = (1..points.len()).find(|&i| points[i].0 <= points[i - 1].0) {
                        return Err(at.at_field("velocity", format!("velocity table point {i}: time must increase strictly ({} then {})", points[i - 1].0, points[i].0)));
                    }
                    VelocityProfile::Table(points.iter().map(|(t, v)| (*t, vec3(*v))).collect())
                }
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

/// The body's shape; `in_water`: a mesh file must also be a closed, outward hull as written
/// (a contact boundary wound inwards is turned over, a hull is refused).
fn build_shape(def: &ShapeDef, directory: &Path, at: &ItemAt, in_water: bool) -> Result<Shape, Problem> {
    let positive = |field: &'static str, value: f64| at.require(field, value, Bound::Positive, "m").map(|_| ());
    Ok(match def {
        ShapeDef::Box { size, center, subdivisions } => {
            for s in size {
                positive("size", *s)?;
            }
            if !(1..=MAX_BOX_SUBDIVISIONS).contains(subdivisions) {
                return Err(at.at_field("subdivisions", format!("box subdivisions must be 1 to {MAX_BOX_SUBDIVISIONS}, got {subdivisions}")));
            }
            Shape::Box { size: vec3(*size), center: vec3(*center), subdivisions: *subdivisions }
        }
        ShapeDef::Sphere { radius, center, subdivisions } => {
            positive("radius", *radius)?;
            if *subdivisions > MAX_SUBDIVISIONS {
                return Err(at.at_field("subdivisions", format!("subdivisions must be at most {MAX_SUBDIVISIONS}, got {subdivisions}")));
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
            let (vertices, triangles) = mesh_file::read(&directory.join(file)).map_err(|e| at.problem(Some("file"), Some(file), e))?;
            let vertices: Vec<Vec3> = vertices.iter().map(|v| v * *scale + vec3(*center)).collect();
            if in_water {
                Hull::new(vertices.clone(), triangles.clone()).map_err(|e| at.problem(Some("file"), Some(file), format!("mesh file {file:?} as a hull in water: {e}")))?;
            }
            // Checked now, so that a contact can always mesh the body.
            let mesh = BoundaryMesh::new(vertices, triangles).map_err(|e| at.problem(Some("file"), Some(file), format!("mesh file {file:?}: {e}")))?;
            Shape::Mesh { vertices: mesh.vertices, triangles: mesh.triangles }
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
            let damping = at.require("damping", *damping, Bound::NonNegative, "N·s/m")?;
            CouplingKind::SpringDamper(SpringDamper::new(end1, end2, build_law(law, at)?, damping))
        }
        CouplingDef::Catenary { end1, end2, mass_per_length, length, stiffness, .. } => {
            let (end1, end2) = build_ends(end1, end2, bodies, at)?;
            let mass_per_length = at.require("mass_per_length", *mass_per_length, Bound::NonNegative, "kg/m")?;
            let length = at.require("length", *length, Bound::Positive, "m")?;
            let stiffness = at.require("stiffness", *stiffness, Bound::Positive, "N/m")?;
            CouplingKind::Catenary(Catenary::new(end1, end2, mass_per_length, length, stiffness))
        }
        CouplingDef::Contact { body, against, stiffness, damping, range, friction, friction_sharpness, expected_area, .. } => {
            let law = build_contact_law(*stiffness, *damping, *range, *friction, *friction_sharpness, at)?;
            let index = body_index(body, bodies, "body", at)?;
            let mesh_problem = |e: MeshError| at.at_field("body", format!("boundary of body {body:?}: {e}"));
            let boundary = boundaries.mesh(bodies, index).map_err(mesh_problem)?;
            let against = build_against(against, index, bodies, boundaries, at)?;
            let expected_area = match expected_area {
                Some(area) => at.require("expected_area", *area, Bound::Positive, "m²")?,
                None => boundary.area() / 6.0,
            };
            CouplingKind::Contact(Contact::new(index, boundary, against, law, expected_area))
        }
    };
    Ok(Coupling { name: def.name().to_string(), kind })
}

/// A spring's or a line's two ends, which must differ.
fn build_ends(end1: &EndDef, end2: &EndDef, bodies: &[RigidBody], at: &ItemAt) -> Result<(Endpoint, Endpoint), Problem> {
    if end1 == end2 {
        return Err(at.at_field("end2", "both ends are the same point: the coupling has no direction".into()));
    }
    Ok((build_end(end1, bodies, at)?, build_end(end2, bodies, at)?))
}

fn build_contact_law(stiffness: f64, damping: f64, range: f64, friction: f64, friction_sharpness: f64, at: &ItemAt) -> Result<ContactLaw, Problem> {
    Ok(ContactLaw {
        stiffness: at.require("stiffness", stiffness, Bound::Positive, "N/m³")?,
        damping: at.require("damping", damping, Bound::NonNegative, "N·s/m³")?,
        range: at.require("range", range, Bound::NonNegative, "m")?,
        friction: at.require("friction", friction, Bound::NonNegative, "")?,
        friction_sharpness: at.require("friction_sharpness", friction_sharpness, Bound::Positive, "s/m")?,
    })
}

fn build_against(def: &AgainstDef, body: usize, bodies: &[RigidBody], boundaries: &mut Boundaries, at: &ItemAt) -> Result<Opposing, Problem> {
    Ok(match def {
        AgainstDef::Plane { point, normal } => {
            let Some(normal) = vec3(*normal).try_normalize(1e-12) else {
                return Err(at.at_field("normal", "plane normal must not be zero".into()));
            };
            Opposing::Planes(vec![Plane { point: vec3(*point), normal }])
        }
        AgainstDef::DomainBox { min, max } => {
            if !(0..3).all(|i| min[i] < max[i]) {
                return Err(at.at_field("max", format!("domain box max {max:?} must exceed min {min:?} in every coordinate")));
            }
            Opposing::Planes(Plane::domain_box(&vec3(*min), &vec3(*max)).to_vec())
        }
        AgainstDef::Body(name) => {
            let other = body_index(name, bodies, "against", at)?;
            if other == body {
                return Err(at.problem(Some("against"), Some(name), format!("body {name:?} cannot be in contact with itself")));
            }
            let surface = boundaries.surface(bodies, other).map_err(|e| at.problem(Some("against"), Some(name), format!("boundary of body {name:?}: {e}")))?;
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

fn build_law(def: &LawDef, at: &ItemAt) -> Result<ElasticLaw, Problem> {
    let non_negative = |field: &'static str, value: f64, unit: &str| at.require(field, value, Bound::NonNegative, unit);
    let table = |points: &[(f64, f64)]| ElasticLaw::stiffness_table(points.to_vec()).map_err(|e| at.at_field("points", e.to_string()));
    Ok(match def {
        LawDef::Linear { stiffness, rest_length } => ElasticLaw::Linear {
            stiffness: non_negative("stiffness", *stiffness, "N/m")?,
            rest_length: non_negative("rest_length", *rest_length, "m")?,
        },
        LawDef::Polynomial { a, b, c, rest_length } => {
            ElasticLaw::Polynomial { a: *a, b: *b, c: *c, rest_length: non_negative("rest_length", *rest_length, "m")? }
        }
        LawDef::ForceCurve { points } => ElasticLaw::force_curve(points.clone()).map_err(|e| at.at_field("points", e.to_string()))?,
        LawDef::StiffnessCurve { points, rest_length } => {
            ElasticLaw::StiffnessCurve { stiffness: table(points)?, rest_length: non_negative("rest_length", *rest_length, "m")? }
        }
        LawDef::ReferenceForce { points, reference_length, reference_force, rest_length } => ElasticLaw::ReferenceForce {
            stiffness: table(points)?,
            reference_length: non_negative("reference_length", *reference_length, "m")?,
            reference_force: *reference_force,
            rest_length: *rest_length,
        },
    })
}
