//! A read MoorDyn file ([`Input`]) as a Tether scene ([`SceneFile`]): what maps to what
//! (`docs/moordyn-files.md`, "What maps to what").
//!
//! | MoorDyn | Tether |
//! |---|---|
//! | line (type, length, segments) | `Catenary` with a `Dynamic` model: λ0, L, `stiffness` D = EA/L \[N/m], `displaced_area` π d²/4 \[m²], N, BA or ζ, C_dn, C_an, C_dt, C_at, kBot, cBot |
//! | Fixed point, point on a Fixed body | a world end |
//! | Coupled point | a kinematic body at the point, at rest (give it a motion) |
//! | Coupled body, Turbine | a kinematic body at its reference point |
//! | Free body | a free rigid body: mass, CG, inertia, buoyancy and added mass from a box hull of its volume, drag areas |
//! | Free point | a point mass: a body with its rotation held (three degrees of freedom, see `point_mass`) |
//! | g, WtrDnsty, WtrDpth, kBot, cBot, FrictionCoefficient | gravity, `water`, `seabed`, the lines' seabed, `line_friction` |
//! | FricDamp CV | each line's `friction_speed` `v_s = w l / CV` (`friction_speed` below); no friction when CV = 0 |

use super::Located;
use super::input::{Attachment, Body, BodyKind, Input, Line, LineType, Options, Point};
use crate::file::{
    BodyDef, CouplingDef, EndDef, InertiaDef, NodeDef, SceneFile, SeabedDef, ShapeDef, SupportDef, VelocityDef,
};
use crate::line_model::LineModelDef;
use crate::water::{HydroDef, WaterDef, WavesDef};
use std::collections::BTreeMap;
use tether_physics::coupling::{InternalDamping, LumpedMassSpec};
use tether_physics::integrator::{Integrator, Substeps};
use tether_physics::math::{Rotation, Vec3};
use tether_physics::parameter::{Bound, ParameterError, require_derived};

/// The scene's step \[s]: what a recording logs; `substeps: Auto` takes the lines' and the
/// point masses' stable steps under it (MoorDyn's `dtM` is its own integrator's step).
pub const STEP: f64 = 0.01;
/// The scene's duration \[s] (a MoorDyn file has none: its driver sets it).
pub const DURATION: f64 = 60.0;

/// The scene and, for each of its bodies and couplings by name, the file line it comes from and
/// a comment saying what it was in the file.
pub struct Mapped {
    pub file: SceneFile,
    pub origins: BTreeMap<String, Origin>,
    pub warnings: Vec<Located>,
}

/// Where a body or coupling of the scene comes from.
#[derive(Debug, Clone, PartialEq)]
pub struct Origin {
    pub line: usize,
    pub comment: String,
}

/// Maps `input` to a scene.
///
/// # Errors
/// What the scene cannot represent: a free point without water to balance its lines' end
/// nodes (see `point_mass`), a free body without mass, bending stiffness that matters.
pub fn map(input: &Input) -> Result<Mapped, Located> {
    let mut warnings = input.warnings.clone();
    let mut origins = BTreeMap::new();
    let water = (input.options.density > 0.0).then_some(WaterDef {
        density: input.options.density,
        level: 0.0,
        depth: Some(input.options.depth),
        current: None,
        waves: WavesDef::Calm,
        ramp: None,
    });
    for line in &input.lines {
        check_derived(line, &input.line_types[line.line_type])?;
        check_bending(line, &input.line_types[line.line_type], &input.options, &mut warnings)?;
    }
    let mut bodies = Vec::new();
    for body in &input.bodies {
        if let Some(def) = body_def(body, input.options.density, &mut warnings)? {
            origins.insert(def.name.clone(), Origin { line: body.line, comment: body_comment(body) });
            bodies.push(def);
        }
    }
    let mut turbines: Vec<usize> = Vec::new();
    for (index, point) in input.points.iter().enumerate() {
        let def = match point.attachment {
            Attachment::Coupled => Some(kinematic(point_name(point), point.position, [0.0; 3], 1.0, [0.1; 3])),
            Attachment::Free => Some(point_mass(input, index)?),
            Attachment::Turbine(n) if !turbines.contains(&n) => {
                turbines.push(n);
                Some(kinematic(format!("turbine{n}"), [0.0; 3], [0.0; 3], 1.0, [0.1; 3]))
            }
            Attachment::Turbine(_) | Attachment::Fixed | Attachment::Body(_) => None,
        };
        if let Some(def) = def {
            origins.insert(def.name.clone(), Origin { line: point.line, comment: point_comment(point) });
            bodies.push(def);
        }
    }
    let couplings = input
        .lines
        .iter()
        .map(|line| {
            let line_type = &input.line_types[line.line_type];
            origins.insert(line_name(line), Origin { line: line.line, comment: line_comment(input, line) });
            line_def(input, line, line_type)
        })
        .collect();
    let file = SceneFile {
        gravity: [0.0, 0.0, -input.options.gravity],
        dt: STEP,
        duration: DURATION,
        integrator: Integrator::default(),
        adaptive: None,
        substeps: Substeps::Auto,
        bodies,
        couplings,
        seabed: Some(SeabedDef {
            elevation: water.is_none().then_some(-input.options.depth),
            // MoorDyn's friction is `μ CV |v_h|` below its Coulomb limit: none when CV = 0.
            line_friction: if input.options.friction_damping > 0.0 { input.options.friction } else { 0.0 },
            contact: None,
        }),
        water,
        air: None,
    };
    Ok(Mapped { file, origins, warnings })
}

/// The name of MoorDyn line `id` in the scene.
pub fn line_name(line: &Line) -> String {
    format!("line{}", line.id)
}

fn point_name(point: &Point) -> String {
    format!("point{}", point.id)
}

fn body_name(id: usize) -> String {
    format!("body{id}")
}

/// What the scene takes from a line and its type, derived here, checked finite (and `D` > 0)
/// before it is written: a value the file's own checks let through (`EA` of 10³⁰⁸ N over a
/// metre, a `Diam` of 10³⁰⁸ m) is refused at the row it comes from, naming it. The stiffness
/// `D = EA/UnstrLen` [N/m] and half a segment's mass `Mass/m UnstrLen/(2 NumSegs)` \[kg] (what
/// a free point takes from each line ending on it, [`end_node_mass`]) at the line's row; the
/// displaced area `π Diam²/4` \[m²] at its type's.
fn check_derived(line: &Line, line_type: &LineType) -> Result<(), Located> {
    let at_line = |e: ParameterError| Located { line: line.line, col: 1, message: format!("line {}: {e}", line.id) };
    let inputs = [("EA", line_type.axial_stiffness), ("UnstrLen", line.length)];
    require_derived("the stiffness D = EA/UnstrLen", stiffness(line, line_type), Bound::Positive, "N/m", &inputs)
        .map_err(at_line)?;
    let half = line_type.mass_per_length * line.length / (2.0 * f64::from(line.segments));
    let inputs =
        [("Mass/m", line_type.mass_per_length), ("UnstrLen", line.length), ("NumSegs", f64::from(line.segments))];
    require_derived("an end node's mass Mass/m UnstrLen/(2 NumSegs)", half, Bound::Finite, "kg", &inputs)
        .map_err(at_line)?;
    require_derived(
        "the displaced area π Diam²/4",
        area(line_type),
        Bound::Finite,
        "m²",
        &[("Diam", line_type.diameter)],
    )
    .map_err(|e| Located {
        line: line_type.line,
        col: 1,
        message: format!("line type \"{}\": {e}", line_type.name),
    })?;
    Ok(())
}

/// A line's stiffness `D = EA/L` [N/m] (PHYSICS.md §3: `EA = D L_eq`).
fn stiffness(line: &Line, line_type: &LineType) -> f64 {
    line_type.axial_stiffness / line.length
}

/// A line type's displaced area `A_d = π d²/4` \[m²] (PHYSICS.md §8 "Discretisation").
fn area(line_type: &LineType) -> f64 {
    std::f64::consts::PI * line_type.diameter * line_type.diameter / 4.0
}

/// Bending stiffness, which Tether's lines do not have, is left out with a warning when it
/// acts over less than a segment — its length scale `(EI/|w|)^(1/3)` \[m] (w the line's wet
/// weight per length [N/m]) is shorter than the segment `L/N` — and refused otherwise.
fn check_bending(
    line: &Line,
    line_type: &LineType,
    options: &Options,
    warnings: &mut Vec<Located>,
) -> Result<(), Located> {
    if line_type.bending_stiffness == 0.0 {
        return Ok(());
    }
    let area = std::f64::consts::PI * line_type.diameter.powi(2) / 4.0;
    let weight = ((line_type.mass_per_length - options.density * area) * options.gravity).abs();
    let reach = (line_type.bending_stiffness / weight).cbrt();
    let segment = line.length / f64::from(line.segments);
    let located = |message: String| Located { line: line.line, col: 1, message };
    if reach.is_finite() && reach < segment {
        warnings.push(located(format!(
            "line {}: bending stiffness EI = {} N·m² of type \"{}\" left out (it acts over {reach:.3} m, less than a segment of {segment:.3} m)",
            line.id, line_type.bending_stiffness, line_type.name
        )));
        Ok(())
    } else {
        Err(located(format!(
            "line {}: bending stiffness EI = {} N·m² of type \"{}\" acts over {reach:.3} m, more than a segment of {segment:.3} m, and Tether's lines have none (refused)",
            line.id, line_type.bending_stiffness, line_type.name
        )))
    }
}

/// A line: a catenary coupling with the file's dynamic model.
fn line_def(input: &Input, line: &Line, line_type: &LineType) -> CouplingDef {
    CouplingDef::Catenary {
        name: line_name(line),
        end1: end_def(input, line.end_a),
        end2: end_def(input, line.end_b),
        mass_per_length: line_type.mass_per_length,
        length: line.length,
        stiffness: stiffness(line, line_type),
        displaced_area: area(line_type),
        breaking_load: None,
        model: LineModelDef::Dynamic(LumpedMassSpec {
            segments: line.segments,
            damping: if line_type.damping < 0.0 {
                InternalDamping::Ratio(-line_type.damping)
            } else {
                InternalDamping::Coefficient(line_type.damping)
            },
            drag_normal: line_type.drag_normal,
            drag_tangential: line_type.drag_tangential,
            added_mass_normal: line_type.added_mass_normal,
            added_mass_tangential: line_type.added_mass_tangential,
            seabed_stiffness: input.options.seabed_stiffness,
            seabed_damping: input.options.seabed_damping,
            friction_speed: friction_speed(input, line, line_type),
        }),
    }
}

/// The friction speed `v_s` \[m/s] that gives a line MoorDyn's seabed friction (PHYSICS.md §8).
///
/// MoorDyn (`Line.cpp`, and MoorDyn-F's `MoorDyn_Line.f90` alike) pushes a grounded node sliding
/// at `v_h` back with `min(μ CV |v_h|, μ F_n)`: a damper of `μ CV` \[N·s/m] per node, whatever its
/// load, capped at Coulomb's limit (`CV` = `FricDamp`, 200 N·s/m unless the file says). Tether's
/// is `μ F_n tanh(|v_h|/v_s)`, of slope `μ F_n / v_s` at rest. The two slopes are equal on a
/// node lying on the seabed under its own wet weight, `F_n = w l` (w the wet weight per length,
/// l the segment), when `v_s = w l / CV`; both then reach the same Coulomb limit. A line that
/// floats (w ≤ 0), or a file without friction, keeps the default `v_s` (its friction is nil or
/// its value does not matter).
fn friction_speed(input: &Input, line: &Line, line_type: &LineType) -> f64 {
    let options = &input.options;
    let wet = (line_type.mass_per_length - options.density * area(line_type)) * options.gravity;
    let speed = wet * line.length / f64::from(line.segments) / options.friction_damping;
    if options.friction > 0.0 && speed.is_finite() && speed > 0.0 { speed } else { LumpedMassSpec::FRICTION_SPEED }
}

/// Where a line end is: the world, a point body, or a point on a body.
fn end_def(input: &Input, index: usize) -> EndDef {
    let point = &input.points[index];
    match point.attachment {
        Attachment::Fixed => EndDef::World(point.position),
        Attachment::Free | Attachment::Coupled => EndDef::Body { body: point_name(point), point: [0.0; 3] },
        Attachment::Turbine(n) => EndDef::Body { body: format!("turbine{n}"), point: point.position },
        Attachment::Body(n) => {
            let body = &input.bodies[n - 1];
            let relative = Vec3::from(point.position);
            match body.kind {
                BodyKind::Fixed => EndDef::World((Vec3::from(body.position) + rotation(body) * relative).into()),
                BodyKind::Free | BodyKind::Coupled => EndDef::Body {
                    body: body_name(body.id),
                    point: (relative - Vec3::from(body.center_of_gravity)).into(),
                },
            }
        }
    }
}

/// MoorDyn's body orientation: roll, pitch, yaw \[deg] about the world's x, y, z, applied in
/// that order (`R = R_z(yaw) R_y(pitch) R_x(roll)`).
fn rotation(body: &Body) -> Rotation {
    let [roll, pitch, yaw] = body.angles_deg.map(f64::to_radians);
    Rotation::from_euler_angles(roll, pitch, yaw)
}

/// A kinematic body at rest at `position`, a sphere of 0.5 m on screen.
fn kinematic(name: String, position: [f64; 3], rotation: [f64; 3], mass: f64, inertia: [f64; 3]) -> BodyDef {
    BodyDef {
        name,
        master: NodeDef {
            position,
            mass,
            inertia: InertiaDef { xx: inertia[0], yy: inertia[1], zz: inertia[2], ..InertiaDef::default() },
        },
        slaves: Vec::new(),
        velocity: [0.0; 3],
        angular_velocity: [0.0; 3],
        rotation,
        support: SupportDef::Kinematic { velocity: VelocityDef::Constant([0.0; 3]), angular_velocity: [0.0; 3] },
        shape: ShapeDef::Sphere { radius: 0.5, center: [0.0; 3], subdivisions: 2 },
        hydro: None,
        windage: None,
        rotor: None,
    }
}

/// A body of the file: its master node at the centre of gravity (so that the file's inertia,
/// about the CG, is the node's own), turned by the file's angles. A fixed body is no body: its
/// points are world ends.
fn body_def(body: &Body, density: f64, warnings: &mut Vec<Located>) -> Result<Option<BodyDef>, Located> {
    let turn = rotation(body);
    let master = Vec3::from(body.position) + turn * Vec3::from(body.center_of_gravity);
    let rotation_vector: [f64; 3] = turn.scaled_axis().into();
    let name = body_name(body.id);
    match body.kind {
        BodyKind::Fixed => Ok(None),
        BodyKind::Coupled => {
            let mass = if body.mass > 0.0 { body.mass } else { 1.0 };
            let inertia = body.inertia.map(|i| if i > 0.0 { i } else { 0.1 });
            Ok(Some(kinematic(name, master.into(), rotation_vector, mass, inertia)))
        }
        BodyKind::Free => {
            if body.mass <= 0.0 || body.inertia.iter().any(|i| *i <= 0.0) {
                return Err(Located {
                    line: body.line,
                    col: 1,
                    message: format!("free body {}: mass and moments of inertia must be > 0", body.id),
                });
            }
            let center = (-Vec3::from(body.center_of_gravity)).into();
            let (shape, hydro) = if body.volume > 0.0 && density > 0.0 {
                let drag = body.drag_area[..3].iter().map(|a| if *a > 0.0 { 1.0 } else { 0.0 }).collect::<Vec<_>>();
                let areas = body.drag_area[..3].iter().map(|a| if *a > 0.0 { *a } else { 1.0 }).collect::<Vec<_>>();
                (
                    hull(body.volume, center),
                    Some(HydroDef {
                        drag: [drag[0], drag[1], drag[2]],
                        drag_areas: Some([areas[0], areas[1], areas[2]]),
                        added_mass: body.added_mass,
                        drag_center: Some(center),
                        ..HydroDef::default()
                    }),
                )
            } else {
                if body.drag_area.iter().any(|a| *a > 0.0) || body.added_mass.iter().any(|a| *a > 0.0) {
                    warnings.push(Located {
                        line: body.line,
                        col: 1,
                        message: format!("body {}: drag and added mass ignored: it has no volume in water", body.id),
                    });
                }
                (ShapeDef::Sphere { radius: 0.5, center, subdivisions: 2 }, None)
            };
            Ok(Some(BodyDef {
                name,
                master: NodeDef {
                    position: master.into(),
                    mass: body.mass,
                    inertia: InertiaDef {
                        xx: body.inertia[0],
                        yy: body.inertia[1],
                        zz: body.inertia[2],
                        ..InertiaDef::default()
                    },
                },
                slaves: Vec::new(),
                velocity: [0.0; 3],
                angular_velocity: [0.0; 3],
                rotation: rotation_vector,
                support: SupportDef::Free,
                shape,
                hydro,
                windage: None,
                rotor: None,
            }))
        }
    }
}

/// A cube of `volume` \[m³] centred at `center`: a closed hull whose buoyancy, integrated over
/// its 12 faces, is exactly `ρ g volume` under water.
fn hull(volume: f64, center: [f64; 3]) -> ShapeDef {
    ShapeDef::Box { size: [volume.cbrt(); 3], center, subdivisions: 1 }
}

/// The mass of the end nodes of the lines that end on point `index` \[kg]: half a segment each,
/// `λ0 L / (2N)`, which MoorDyn adds to a free point's mass matrix (`Point::getM6`).
pub fn end_node_mass(input: &Input, index: usize) -> f64 {
    input
        .lines
        .iter()
        .map(|line| {
            let ends = usize::from(line.end_a == index) + usize::from(line.end_b == index);
            let lambda = input.line_types[line.line_type].mass_per_length;
            ends as f64 * lambda * line.length / (2.0 * f64::from(line.segments))
        })
        .sum()
}

/// A free point as a *point mass*: a rigid body with its rotation held (`Fixed(rotation:
/// true)`), so it has the three degrees of freedom of MoorDyn's point and costs what one body
/// costs; a new three-degree-of-freedom kind would save the rotation's few operations per step
/// and add a kind every stage, the recorder and the window must handle.
///
/// Its mass is the file's `m` plus its lines' end nodes' `Σ λ0 L/(2N)`: Tether's line leaves an
/// end node's inertia to the body it ends on and passes the body the node's weight
/// (PHYSICS.md §8, "End nodes"), where MoorDyn's point carries both. The weight that mass adds
/// is given back as buoyancy: the hull is a cube of volume `V + Σ λ0 L/(2N) / ρ`, its added-mass
/// coefficient `C_a V / V_hull`, so that under water the point weighs `(m − ρV) g` and its added
/// mass is `C_a ρ V`, as in MoorDyn. Drag `½ ρ CdA |v_i| v_i` per axis (MoorDyn's is on |v|).
///
/// # Errors
/// A point without water (nothing would balance the weight the end nodes' mass adds), or with
/// no mass at all.
fn point_mass(input: &Input, index: usize) -> Result<BodyDef, Located> {
    let point = &input.points[index];
    let ends = end_node_mass(input, index);
    let mass = point.mass + ends;
    let density = input.options.density;
    let located = |message: String| Located { line: point.line, col: 1, message };
    if mass <= 0.0 {
        return Err(located(format!("free point {}: no mass, and no line ends on it", point.id)));
    }
    if density <= 0.0 && ends > 0.0 {
        return Err(located(format!(
            "free point {}: without water (WtrDnsty 0) Tether cannot give it its lines' end-node mass without their weight twice (refused)",
            point.id
        )));
    }
    let volume = point.volume + ends / density.max(f64::MIN_POSITIVE);
    let side = volume.cbrt();
    let moment = mass * side * side / 6.0;
    check_point(point, mass, volume, moment, &input.options)
        .map_err(|e| located(format!("point {}: {e}", point.id)))?;
    let hydro = (density > 0.0 && volume > 0.0).then(|| HydroDef {
        drag: if point.drag_area > 0.0 { [1.0; 3] } else { [0.0; 3] },
        drag_areas: (point.drag_area > 0.0).then_some([point.drag_area; 3]),
        added_mass: [point.added_mass * point.volume / volume; 3],
        ..HydroDef::default()
    });
    Ok(BodyDef {
        name: point_name(point),
        master: NodeDef {
            position: point.position,
            mass,
            inertia: InertiaDef { xx: moment, yy: moment, zz: moment, ..InertiaDef::default() },
        },
        slaves: Vec::new(),
        velocity: [0.0; 3],
        angular_velocity: [0.0; 3],
        rotation: [0.0; 3],
        support: SupportDef::Fixed { translation: (false, false, false), rotation: true },
        shape: if hydro.is_some() {
            hull(volume, [0.0; 3])
        } else {
            ShapeDef::Sphere { radius: 0.25, center: [0.0; 3], subdivisions: 2 }
        },
        hydro,
        windage: None,
        rotor: None,
    })
}

/// What a free point's body takes from it, derived in [`point_mass`], checked finite: its mass
/// `m + Σ λ0 L/(2N)` \[kg], weight `m g` \[N], hull volume `V_hull` \[m³] and buoyancy `ρ g
/// V_hull` \[N], moment of inertia `m s²/6` [kg·m²] (`s` the hull's side), drag `½ ρ CdA` [kg/m]
/// and added mass `Ca ρ V` \[kg], each named with the column (or option) that made it.
fn check_point(point: &Point, mass: f64, volume: f64, moment: f64, options: &Options) -> Result<(), ParameterError> {
    let (g, density) = (options.gravity, options.density);
    let inputs = [
        ("Mass", point.mass),
        ("Volume", point.volume),
        ("g", g),
        ("WtrDnsty", density),
        ("CdA", point.drag_area),
        ("Ca", point.added_mass),
    ];
    require_derived("its mass with its lines' end nodes", mass, Bound::Finite, "kg", &inputs[..1])?;
    require_derived("its weight m g", mass * g, Bound::Finite, "N", &inputs[..3])?;
    require_derived("its moment of inertia m s²/6", moment, Bound::Finite, "kg·m²", &inputs[..2])?;
    if density > 0.0 {
        require_derived("its hull's volume", volume, Bound::Finite, "m³", &inputs[..4])?;
        require_derived("its buoyancy ρ g V", density * g * volume, Bound::Finite, "N", &inputs[..4])?;
        let drag = 0.5 * density * point.drag_area;
        require_derived("its drag ½ ρ CdA", drag, Bound::Finite, "kg/m", &[inputs[3], inputs[4]])?;
        let added = point.added_mass * density * point.volume;
        require_derived("its added mass Ca ρ V", added, Bound::Finite, "kg", &[inputs[1], inputs[3], inputs[5]])?;
    }
    Ok(())
}

fn point_comment(point: &Point) -> String {
    let what = match point.attachment {
        Attachment::Coupled => {
            "Coupled point: kinematic, at rest here; give it the motion of what drives it".to_string()
        }
        Attachment::Free => format!(
            "Free point: mass {} kg, volume {} m³, CdA {} m², Ca {} (point mass: mass and hull include its lines' end nodes)",
            point.mass, point.volume, point.drag_area, point.added_mass
        ),
        Attachment::Turbine(n) => format!("Turbine{n}: kinematic, its points relative to its reference"),
        Attachment::Fixed | Attachment::Body(_) => String::new(),
    };
    format!("point {}: {what}", point.id)
}

fn body_comment(body: &Body) -> String {
    let kind = match body.kind {
        BodyKind::Free => "Free",
        BodyKind::Coupled => "Coupled: kinematic, at rest here; give it the motion of what drives it",
        BodyKind::Fixed => "Fixed",
    };
    format!(
        "body {} ({kind}): reference ({}, {}, {}) m, angles ({}, {}, {})°, mass {} kg, CG ({}, {}, {}) m, volume {} m³",
        body.id,
        body.position[0],
        body.position[1],
        body.position[2],
        body.angles_deg[0],
        body.angles_deg[1],
        body.angles_deg[2],
        body.mass,
        body.center_of_gravity[0],
        body.center_of_gravity[1],
        body.center_of_gravity[2],
        body.volume
    )
}

fn line_comment(input: &Input, line: &Line) -> String {
    let end = |index: usize| {
        let point = &input.points[index];
        let kind = match point.attachment {
            Attachment::Fixed => "Fixed".to_string(),
            Attachment::Free => "Free".to_string(),
            Attachment::Coupled => "Coupled".to_string(),
            Attachment::Body(n) => format!("Body{n}"),
            Attachment::Turbine(n) => format!("Turbine{n}"),
        };
        format!("point {} ({kind})", point.id)
    };
    format!(
        "line {}: type \"{}\", {} m, {} segments, from {} to {}",
        line.id,
        input.line_types[line.line_type].name,
        line.length,
        line.segments,
        end(line.end_a),
        end(line.end_b)
    )
}
