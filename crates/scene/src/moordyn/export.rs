//! A scene's lines, anchors, connection points and the bodies they attach to as a MoorDyn v2
//! input file (`tether export moordyn`): the inverse of [`super::mapping`], so that importing an
//! export gives back the same lines.
//!
//! | Tether | MoorDyn |
//! |---|---|
//! | `Catenary` (dynamic) | a line and a line type of its λ0, d = √(4 A_d/π) (a steel rod's when A_d = 0, [`bearing_diameter`]), EA = D L, BA or −ζ, C_dn, C_an, C_dt, C_at |
//! | `Catenary` (quasi-static) | the same with `segments` (the export's flag) and the coefficients a line switched to dynamic gets ([`LumpedMassSpec::wire`]) |
//! | world end | a Fixed point (one per position) |
//! | body with its rotation held, translation free | a Free point (the mapping's point mass, inverted) |
//! | kinematic (or partly fixed) / free / fixed body | a Coupled / Free / Fixed body, its reference the master node, with Body points |
//!
//! Spring-dampers and contacts have no MoorDyn counterpart and are listed in the file's title
//! as left out.

use super::mapping::STEP;
use crate::file::{BodyDef, CouplingDef, EndDef, SceneFile, ShapeDef, SupportDef};
use crate::line_model::LineModelDef;
use std::fmt::Write as _;
use tether_physics::body::RigidBody;
use tether_physics::coupling::lumped_line::discrete::bearing_diameter;
use tether_physics::coupling::{InternalDamping, LumpedMassSpec};
use tether_physics::math::{Rotation, Vec3};

/// The segments a quasi-static line is written with when the export is not told (the
/// `--segments` flag): 20, MoorDyn's examples' usual count for a mooring line.
pub const DEFAULT_SEGMENTS: u32 = 20;

/// One line as MoorDyn sees it.
struct LineRow {
    type_index: usize,
    ends: [usize; 2],
    length: f64,
    segments: u32,
    /// `v_s` \[m/s] of its seabed friction ([`tether_physics::coupling::LumpedMassSpec::friction_speed`]).
    friction_speed: f64,
}

/// A MoorDyn line type: the values a line's row takes from its type.
#[derive(Debug, Clone, PartialEq)]
struct TypeRow {
    name: String,
    values: [f64; 9],
}

/// A MoorDyn point: its type word and position (relative to its body for `Body<n>`), mass,
/// volume, CdA, Ca.
#[derive(Debug, Clone, PartialEq)]
struct PointRow {
    kind: String,
    position: [f64; 3],
    values: [f64; 4],
    /// What it stands for: a world position, or a body by index with a point on it.
    key: PointKey,
}

#[derive(Debug, Clone, PartialEq)]
enum PointKey {
    World([u64; 3]),
    PointMass(usize),
    OnBody(usize, [u64; 3]),
}

/// Writes the MoorDyn v2 input file of `file` (built into `bodies`), titled with `source`;
/// quasi-static lines get `segments`.
pub fn export(file: &SceneFile, bodies: &[RigidBody], source: &str, segments: u32) -> String {
    let density = file.water.as_ref().map_or(0.0, |w| w.density);
    let mut types: Vec<TypeRow> = Vec::new();
    let mut points: Vec<PointRow> = Vec::new();
    let mut body_ids: Vec<usize> = Vec::new();
    let mut lines = Vec::new();
    let mut left_out = Vec::new();
    let mut seabed = None;
    for coupling in &file.couplings {
        let CouplingDef::Catenary {
            name, end1, end2, mass_per_length, length, stiffness, displaced_area, model, ..
        } = coupling
        else {
            left_out.push(coupling.name().to_string());
            continue;
        };
        let LumpedMassSpec {
            segments: count,
            damping,
            drag_normal,
            drag_tangential,
            added_mass_normal,
            added_mass_tangential,
            seabed_stiffness,
            seabed_damping,
            friction_speed,
        } = match model {
            LineModelDef::QuasiStatic => LumpedMassSpec::wire(segments),
            LineModelDef::Dynamic(line) => *line,
        };
        seabed.get_or_insert((seabed_stiffness, seabed_damping));
        let ba = match damping {
            InternalDamping::Ratio(zeta) => -zeta,
            InternalDamping::Coefficient(ba) => ba,
        };
        // MoorDyn's diameter `d = √(4 A_d/π)`; a dry line is written as the steel rod Tether's
        // seabed bears it on: MoorDyn's lines need `d > 0` (its drag and seabed divide by it),
        // and in water that rod's buoyancy is then counted.
        let diameter = bearing_diameter(*displaced_area, *mass_per_length);
        let values = [
            diameter,
            *mass_per_length,
            stiffness * length,
            ba,
            0.0,
            drag_normal,
            added_mass_normal,
            drag_tangential,
            added_mass_tangential,
        ];
        let type_index = types.iter().position(|t| t.values == values).unwrap_or_else(|| {
            types.push(TypeRow { name: name.replace(char::is_whitespace, "_"), values });
            types.len() - 1
        });
        let ends = [end1, end2].map(|end| point_of(file, bodies, end, &mut points, &mut body_ids));
        lines.push(LineRow { type_index, ends, length: *length, segments: count, friction_speed });
    }
    // A point mass weighs as the file's point: the mapping's end-node mass and hull are taken back.
    for line in &lines {
        for end in line.ends {
            if let PointKey::PointMass(_) = points[end].key {
                let lambda = types[line.type_index].values[1];
                let mass = lambda * line.length / (2.0 * f64::from(line.segments));
                let point = &mut points[end];
                point.values[0] -= mass;
                if density > 0.0 {
                    point.values[1] -= mass / density;
                }
            }
        }
    }
    for point in &mut points {
        if let PointKey::PointMass(body) = point.key {
            let hull = hull_volume(&file.bodies[body]);
            let (mass, volume) = (point.values[0].max(0.0), point.values[1].max(0.0));
            let added = file.bodies[body].hydro.as_ref().map_or(0.0, |h| h.added_mass[0]);
            point.values =
                [clean(mass), clean(volume), point.values[2], if volume > 0.0 { added * hull / volume } else { 0.0 }];
        }
    }
    let mut text = String::new();
    write_title(&mut text, source, &left_out);
    write_types(&mut text, &types);
    write_bodies(&mut text, file, bodies, &body_ids);
    write_points(&mut text, &points);
    write_lines(&mut text, &lines, &types);
    let moordyn_seabed = (LumpedMassSpec::SEABED_STIFFNESS, LumpedMassSpec::SEABED_DAMPING);
    write_options(&mut text, file, &lines, &types, seabed.unwrap_or(moordyn_seabed));
    text
}

/// A value within a few rounding errors of zero is zero (a point's mass less its end nodes').
fn clean(value: f64) -> f64 {
    if value.abs() < 1e-9 { 0.0 } else { value }
}

/// Whether a body is the mapping's point mass: translation free, rotation held.
fn is_point_mass(def: &BodyDef) -> bool {
    def.support == SupportDef::Fixed { translation: (false, false, false), rotation: true }
}

/// What MoorDyn calls a body with `support`: a kinematic body, or one with only some of its
/// motions held (MoorDyn's bodies are wholly free, fixed or coupled), is Coupled — the program
/// driving MoorDyn holds it.
pub fn body_kind(support: &SupportDef) -> &'static str {
    match support {
        SupportDef::Free => "Free",
        SupportDef::Fixed { translation: (true, true, true), rotation: true } => "Fixed",
        SupportDef::Fixed { .. } | SupportDef::Kinematic { .. } => "Coupled",
    }
}

/// The volume of a body's hull when it floats in the water \[m³] (0 for a dry body or a mesh).
fn hull_volume(def: &BodyDef) -> f64 {
    if def.hydro.is_none() {
        return 0.0;
    }
    match &def.shape {
        ShapeDef::Box { size, .. } => size[0] * size[1] * size[2],
        ShapeDef::Sphere { radius, .. } => 4.0 / 3.0 * std::f64::consts::PI * radius.powi(3),
        ShapeDef::Cylinder { radius, length, .. } => std::f64::consts::PI * radius * radius * length,
        ShapeDef::Mesh { .. } => 0.0,
    }
}

fn bits(v: [f64; 3]) -> [u64; 3] {
    v.map(f64::to_bits)
}

/// The index of the MoorDyn point an end is on, adding it (and its body) when new.
fn point_of(
    file: &SceneFile,
    bodies: &[RigidBody],
    end: &EndDef,
    points: &mut Vec<PointRow>,
    body_ids: &mut Vec<usize>,
) -> usize {
    let (key, row) = match end {
        EndDef::World(position) => (
            PointKey::World(bits(*position)),
            PointRow {
                kind: "Fixed".into(),
                position: *position,
                values: [0.0; 4],
                key: PointKey::World(bits(*position)),
            },
        ),
        EndDef::Body { body, point } => {
            // Ends name bodies the build checked exist; an unknown one is written at the origin.
            let index = file.bodies.iter().position(|b| &b.name == body).unwrap_or(0);
            let def = &file.bodies[index];
            if is_point_mass(def) {
                let at: [f64; 3] = (Vec3::from(def.master.position) + Vec3::from(*point)).into();
                let hydro = def.hydro.as_ref();
                let cda = hydro.map_or(0.0, |h| h.drag[0] * h.drag_areas.map_or(0.0, |a| a[0]));
                let key = PointKey::PointMass(index);
                let mass = bodies.get(index).map_or(def.master.mass, RigidBody::mass);
                (
                    key.clone(),
                    PointRow { kind: "Free".into(), position: at, values: [mass, hull_volume(def), cda, 0.0], key },
                )
            } else {
                if !body_ids.contains(&index) {
                    body_ids.push(index);
                }
                let id = body_ids.iter().position(|b| *b == index).map_or(1, |p| p + 1);
                let key = PointKey::OnBody(index, bits(*point));
                (key.clone(), PointRow { kind: format!("Body{id}"), position: *point, values: [0.0; 4], key })
            }
        }
    };
    points.iter().position(|p| p.key == key).unwrap_or_else(|| {
        points.push(row);
        points.len() - 1
    })
}

fn write_title(text: &mut String, source: &str, left_out: &[String]) {
    let _ = writeln!(text, "--------------------- MoorDyn Input File ------------------------------------");
    let _ = writeln!(text, "Written by `tether export moordyn` from {source} (MoorDyn v2 format, SI units)");
    if !left_out.is_empty() {
        let _ = writeln!(text, "Not written (no MoorDyn counterpart): {}", left_out.join(", "));
    }
}

fn write_types(text: &mut String, types: &[TypeRow]) {
    let _ = writeln!(text, "---------------------- LINE TYPES ------------------------------------------");
    let _ = writeln!(text, "TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx");
    let _ = writeln!(text, "(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)");
    for t in types {
        let values: Vec<String> = t.values.iter().map(|v| format!("{v:?}")).collect();
        let _ = writeln!(text, "{} {}", t.name, values.join(" "));
    }
}

/// Roll, pitch, yaw \[deg] of a rotation (MoorDyn's convention, see [`super::mapping`]).
fn angles(rotation: &[f64; 3]) -> [f64; 3] {
    let (roll, pitch, yaw) = Rotation::from_scaled_axis(Vec3::from(*rotation)).euler_angles();
    [roll, pitch, yaw].map(f64::to_degrees)
}

fn write_bodies(text: &mut String, file: &SceneFile, bodies: &[RigidBody], body_ids: &[usize]) {
    if body_ids.is_empty() {
        return;
    }
    let _ = writeln!(text, "---------------------- BODIES ----------------------------------------------");
    let _ = writeln!(text, "ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*");
    let _ = writeln!(text, "(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)");
    for (id, index) in body_ids.iter().enumerate() {
        let def = &file.bodies[*index];
        let kind = body_kind(&def.support);
        let turn = Rotation::from_scaled_axis(Vec3::from(def.rotation));
        let (cg, inertia, mass) = bodies.get(*index).map_or(([0.0; 3], [1.0; 3], def.master.mass), |body| {
            let mass_properties = &body.mass_properties;
            let cg = turn.inverse() * (mass_properties.center_of_mass - Vec3::from(def.master.position));
            let local = turn.to_rotation_matrix().matrix().transpose()
                * mass_properties.inertia_about_g
                * turn.to_rotation_matrix().matrix();
            (cg.into(), [local[(0, 0)], local[(1, 1)], local[(2, 2)]], body.mass())
        });
        let hydro = def.hydro.as_ref();
        let cda = hydro.map_or([0.0; 3], |h| {
            let areas = h.drag_areas.unwrap_or([0.0; 3]);
            [h.drag[0] * areas[0], h.drag[1] * areas[1], h.drag[2] * areas[2]]
        });
        let ca = hydro.map_or([0.0; 3], |h| h.added_mass);
        let [x, y, z] = def.master.position;
        let [r, p, w] = angles(&def.rotation);
        let _ = writeln!(
            text,
            "{} {kind} {x:?} {y:?} {z:?} {r:?} {p:?} {w:?} {mass:?} {:?}|{:?}|{:?} {:?}|{:?}|{:?} {:?} {:?}|{:?}|{:?} {:?}|{:?}|{:?}",
            id + 1,
            cg[0],
            cg[1],
            cg[2],
            inertia[0],
            inertia[1],
            inertia[2],
            hull_volume(def),
            cda[0],
            cda[1],
            cda[2],
            ca[0],
            ca[1],
            ca[2]
        );
    }
}

fn write_points(text: &mut String, points: &[PointRow]) {
    let _ = writeln!(text, "---------------------- POINTS ----------------------------------------------");
    let _ = writeln!(text, "ID Attachment X Y Z Mass Volume CdA Ca");
    let _ = writeln!(text, "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)");
    for (id, point) in points.iter().enumerate() {
        let [x, y, z] = point.position;
        let [m, v, cda, ca] = point.values;
        let _ = writeln!(text, "{} {} {x:?} {y:?} {z:?} {m:?} {v:?} {cda:?} {ca:?}", id + 1, point.kind);
    }
}

fn write_lines(text: &mut String, lines: &[LineRow], types: &[TypeRow]) {
    let _ = writeln!(text, "---------------------- LINES -----------------------------------------------");
    let _ = writeln!(text, "ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs");
    let _ = writeln!(text, "(#) (name) (#) (#) (m) (-) (-)");
    for (id, line) in lines.iter().enumerate() {
        let _ = writeln!(
            text,
            "{} {} {} {} {:?} {} -",
            id + 1,
            types[line.type_index].name,
            line.ends[0] + 1,
            line.ends[1] + 1,
            line.length,
            line.segments
        );
    }
}

/// MoorDyn's internal step `dtM` \[s]: half the time the axial wave takes to cross the shortest
/// segment, `l √(λ0/EA)`, no longer than the scene's step, nor than the time `λ0 l / (μ CV)` its
/// seabed friction's damper `friction_damper` = μ CV \[N·s/m] takes to stop a node's slide
/// (longer steps make MoorDyn's capped friction chatter: validation/moordyn/friction_step.py).
fn moordyn_step(lines: &[LineRow], types: &[TypeRow], friction_damper: f64) -> f64 {
    let limit = lines
        .iter()
        .map(|line| {
            let values = &types[line.type_index].values;
            let segment = line.length / f64::from(line.segments);
            let crossing = 0.5 * segment * (values[1] / values[2]).sqrt();
            let friction = values[1] * segment / friction_damper;
            crossing.min(friction)
        })
        .fold(0.5 * STEP, f64::min);
    // Two significant digits, rounded down.
    let scale = 10f64.powi(limit.log10().floor() as i32 - 1);
    (limit / scale).floor() * scale
}

/// MoorDyn's `FricDamp` CV \[N·s/m] that gives the first line its friction speed: `CV = w l /
/// v_s` (the inverse of the import's `friction_speed`, `super::mapping`); one value for the file,
/// as MoorDyn has. None for a file whose first line floats.
fn friction_damping(lines: &[LineRow], types: &[TypeRow], density: f64, gravity: f64) -> Option<f64> {
    let line = lines.first()?;
    let [diameter, mass_per_length, ..] = types[line.type_index].values;
    let area = std::f64::consts::PI * diameter * diameter / 4.0;
    let wet = (mass_per_length - density * area) * gravity;
    let damping = wet * line.length / f64::from(line.segments) / line.friction_speed;
    (damping.is_finite() && damping > 0.0).then_some(damping)
}

fn write_options(text: &mut String, file: &SceneFile, lines: &[LineRow], types: &[TypeRow], seabed: (f64, f64)) {
    let water = file.water.as_ref();
    let depth = water
        .and_then(|w| w.depth)
        .or_else(|| file.seabed.as_ref().and_then(|s| s.elevation).map(|z| -z))
        .unwrap_or(10_000.0);
    let friction = file.seabed.as_ref().map_or(0.0, |s| s.line_friction);
    let gravity = -file.gravity[2];
    let damping = friction_damping(lines, types, water.map_or(0.0, |w| w.density), gravity);
    let damper = friction * damping.unwrap_or(0.0);
    let _ = writeln!(text, "---------------------- OPTIONS ---------------------------------------------");
    let _ = writeln!(text, "{:?} dtM - MoorDyn's time step (s)", moordyn_step(lines, types, damper));
    let _ = writeln!(text, "{:?} g - gravity (m/s^2)", -file.gravity[2]);
    let _ = writeln!(text, "{:?} WtrDnsty - water density (kg/m^3)", water.map_or(0.0, |w| w.density));
    let _ = writeln!(text, "{depth:?} WtrDpth - water depth (m)");
    let _ = writeln!(text, "{:?} kBot - bottom stiffness (Pa/m)", seabed.0);
    let _ = writeln!(text, "{:?} cBot - bottom damping (Pa-s/m)", seabed.1);
    let _ = writeln!(text, "{friction:?} FrictionCoefficient - seabed friction (-)");
    if let Some(damping) = damping {
        let _ = writeln!(text, "{damping:?} FricDamp - seabed friction's damping below its Coulomb limit (N-s/m)");
    }
    let _ = writeln!(text, "0 writeLog - no log file");
    let _ = writeln!(text, "------------------------- need this line ----------------------------------");
}
