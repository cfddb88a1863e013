//! Turns a parsed [`SceneFile`] into a [`World`]: the one place where scene data becomes
//! simulation state. Every check that needs more than one value (names, references, mass
//! properties, tables) is made here and reported with the item it concerns.

use super::file::{BodyDef, CouplingDef, EndDef, InertiaDef, LawDef, NodeDef, SceneFile, ShapeDef, SupportDef, Triple, VelocityDef};
use super::source::ItemKind;
use crate::physics::body::{PrescribedMotion, RigidBody, Shape, Support, VelocityProfile};
use crate::physics::coupling::{Catenary, Coupling, CouplingKind, ElasticLaw, Endpoint, SpringDamper};
use crate::physics::mass_properties::{MassProperties, Node};
use crate::physics::integrator::{Substeps, Timing};
use crate::physics::world::{StepError, World};
use crate::physics::{Mat3, Vec3};

/// Where a problem is in the file.
#[derive(Debug, Clone, PartialEq)]
pub enum Place {
    /// A top-level field.
    Top(&'static str),
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

/// A world and what is odd but allowed about it.
pub struct Built {
    pub world: World,
    pub warnings: Vec<String>,
}

/// Builds the world a scene describes.
pub fn build(file: &SceneFile) -> Result<Built, Problem> {
    let timing = timing(file)?;
    if !(file.duration > 0.0) {
        return Err(Problem { place: Place::Top("duration"), message: format!("duration must be > 0 s, got {}", file.duration) });
    }
    let mut warnings = Vec::new();
    let mut bodies = Vec::with_capacity(file.bodies.len());
    let mut states = Vec::with_capacity(file.bodies.len());
    for (index, def) in file.bodies.iter().enumerate() {
        let at = ItemAt::new(ItemKind::Body, &def.name, file.bodies[..index].iter().filter(|b| b.name == def.name).count());
        check_name(&at, file.bodies[..index].iter().map(|b| b.name.as_str()))?;
        let body = build_body(def, &at)?;
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
        bodies.push(body);
    }
    let mut couplings = Vec::with_capacity(file.couplings.len());
    for (index, def) in file.couplings.iter().enumerate() {
        let name = def.name();
        let at = ItemAt::new(ItemKind::Coupling, name, file.couplings[..index].iter().filter(|c| c.name() == name).count());
        check_name(&at, file.couplings[..index].iter().map(CouplingDef::name))?;
        couplings.push(build_coupling(def, &bodies, &at)?);
    }
    // Names are unique by now: the coupling at fault is the first of its name.
    let world = World::new(vec3(file.gravity), bodies, couplings, states, timing).map_err(|e| match e {
        StepError::Coupling { coupling, source, .. } => ItemAt::new(ItemKind::Coupling, &coupling, 0).at_name(format!("at t = 0: {source}")),
        other => Problem { place: Place::Top("bodies"), message: other.to_string() },
    })?;
    Ok(Built { world, warnings })
}

/// The time step settings of a scene, checked: `dt` > 0 s, at least one substep.
pub fn timing(file: &SceneFile) -> Result<Timing, Problem> {
    if !(file.dt > 0.0 && file.dt.is_finite()) {
        return Err(Problem { place: Place::Top("dt"), message: format!("time step dt must be > 0 s, got {}", file.dt) });
    }
    if file.substeps == Substeps::Fixed(0) {
        return Err(Problem { place: Place::Top("substeps"), message: "substeps must be at least 1".into() });
    }
    Ok(Timing { dt: file.dt, integrator: file.integrator, substeps: file.substeps })
}

/// Builds coupling `index` of `file` on its own, with the checks and messages of [`build`]
/// (live tuning builds a changed coupling this way before it reaches a running world). The
/// bodies are built again to resolve the ends; their own problems are reported too.
pub fn coupling(file: &SceneFile, index: usize) -> Result<Coupling, Problem> {
    let Some(def) = file.couplings.get(index) else {
        return Err(Problem { place: Place::Top("couplings"), message: format!("the scene has no coupling {index}") });
    };
    let mut bodies = Vec::with_capacity(file.bodies.len());
    for (i, body) in file.bodies.iter().enumerate() {
        let occurrence = file.bodies[..i].iter().filter(|b| b.name == body.name).count();
        bodies.push(build_body(body, &ItemAt::new(ItemKind::Body, &body.name, occurrence))?);
    }
    let occurrence = file.couplings[..index].iter().filter(|c| c.name() == def.name()).count();
    build_coupling(def, &bodies, &ItemAt::new(ItemKind::Coupling, def.name(), occurrence))
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

fn build_body(def: &BodyDef, at: &ItemAt) -> Result<RigidBody, Problem> {
    let slaves: Vec<Node> = def.slaves.iter().map(node).collect();
    let mass_properties = MassProperties::from_nodes(&node(&def.master), &slaves).map_err(|e| {
        let field = match e {
            crate::physics::mass_properties::MassError::NotPositiveDefinite(_) | crate::physics::mass_properties::MassError::NotFinite { .. } => "inertia",
            _ => "mass",
        };
        at.at_field(field, e.to_string())
    })?;
    let support = build_support(&def.support, at)?;
    let shape = build_shape(&def.shape, at)?;
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

fn build_shape(def: &ShapeDef, at: &ItemAt) -> Result<Shape, Problem> {
    let positive = |field: &'static str, value: f64| {
        if value > 0.0 { Ok(()) } else { Err(at.at_field(field, format!("shape {field} must be > 0 m, got {value}"))) }
    };
    Ok(match def {
        ShapeDef::Box { size, center } => {
            for s in size {
                positive("size", *s)?;
            }
            Shape::Box { size: vec3(*size), center: vec3(*center) }
        }
        ShapeDef::Sphere { radius, center } => {
            positive("radius", *radius)?;
            Shape::Sphere { radius: *radius, center: vec3(*center) }
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
    })
}

fn build_end(def: &EndDef, bodies: &[RigidBody], at: &ItemAt) -> Result<Endpoint, Problem> {
    Ok(match def {
        EndDef::World(p) => Endpoint::World(vec3(*p)),
        EndDef::Body { body, point } => {
            let Some(index) = bodies.iter().position(|b| &b.name == body) else {
                let known: Vec<&str> = bodies.iter().map(|b| b.name.as_str()).collect();
                return Err(at.problem(Some("body"), Some(body), format!("unknown body {body:?} (bodies: {})", known.join(", "))));
            };
            Endpoint::on_body(index, bodies[index].principal_point(&vec3(*point)))
        }
    })
}

fn build_coupling(def: &CouplingDef, bodies: &[RigidBody], at: &ItemAt) -> Result<Coupling, Problem> {
    let [end1, end2] = def.ends();
    let ends = (build_end(end1, bodies, at)?, build_end(end2, bodies, at)?);
    if end1 == end2 {
        return Err(at.at_field("end2", "both ends are the same point: the coupling has no direction".into()));
    }
    let kind = match def {
        CouplingDef::SpringDamper { law, damping, .. } => {
            if !(*damping >= 0.0) {
                return Err(at.at_field("damping", format!("damping must be ≥ 0 N·s/m, got {damping}")));
            }
            CouplingKind::SpringDamper(SpringDamper::new(ends.0, ends.1, build_law(law, at)?, *damping))
        }
        CouplingDef::Catenary { mass_per_length, length, stiffness, .. } => {
            if !(*mass_per_length >= 0.0) {
                return Err(at.at_field("mass_per_length", format!("mass_per_length must be ≥ 0 kg/m, got {mass_per_length}")));
            }
            if !(*length > 0.0) {
                return Err(at.at_field("length", format!("length must be > 0 m, got {length}")));
            }
            if !(*stiffness > 0.0) {
                return Err(at.at_field("stiffness", format!("stiffness must be > 0 N/m, got {stiffness}")));
            }
            CouplingKind::Catenary(Catenary::new(ends.0, ends.1, *mass_per_length, *length, *stiffness))
        }
    };
    Ok(Coupling { name: def.name().to_string(), kind })
}

fn build_law(def: &LawDef, at: &ItemAt) -> Result<ElasticLaw, Problem> {
    let non_negative = |field: &'static str, value: f64, unit: &str| {
        if value >= 0.0 { Ok(value) } else { Err(at.at_field(field, format!("{field} must be ≥ 0 {unit}, got {value}"))) }
    };
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
