//! The catalogue of a scene's tunable numbers (docs/window.md, docs/calibration.md): for each,
//! the knob group it is edited in ([`KnobId`]), its value path (the sweep's), its label as the
//! window shows it, its unit and its value. One table serves the window's Fit panel, the sweeps'
//! and fits' value paths, and Python's `Simulation.parameters()`; each field's path, label and
//! unit are written once, in [`fields`], which the window's knobs are drawn from too.
//!
//! The matches over the scene's coupling kinds, elastic laws, line models and waves are
//! exhaustive: a new kind does not compile until it says what can be tuned in it.

pub mod fields;

use fields::Field;
use tether_physics::coupling::InternalDamping;
use tether_scene::SceneFile;
use tether_scene::air::{AirDef, GustsDef};
use tether_scene::file::{CouplingDef, LawDef};
use tether_scene::line_model::LineModelDef;
use tether_scene::water::{HydroDef, WaterDef, WavesDef};

/// A knob group of a scene, and which of its knobs: where a tuned value is checked and applied.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnobId {
    /// Coupling `index`'s parameters.
    Coupling(usize),
    Water,
    /// Body `index`'s coefficients in the water.
    Hydro(usize),
    Seabed,
    Air,
}

/// A number of the scene that can be tuned: the knob it is edited in, its value path (the
/// sweep's, `couplings.spring.law.stiffness`), what the window calls it, its unit and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    pub knob: KnobId,
    pub path: String,
    /// `spring: stiffness k`.
    pub label: String,
    pub unit: &'static str,
    pub value: f64,
}

/// The tunable numbers of `file`: every number the window's panels tune (a
/// spring's law and damping, a line's λ0, L_eq, D, A_d and a dynamic line's damping, drag and
/// added mass, a contact's law; the waves, current and density; each floating body's drag,
/// added mass and linear damping). Counts (a line's segments) are left out.
pub fn parameters(file: &SceneFile) -> Vec<Parameter> {
    let mut found = Vec::new();
    for (index, def) in file.couplings.iter().enumerate() {
        let mut section = Section::new(&mut found, KnobId::Coupling(index), "couplings", def.name());
        coupling_values(&mut section, def);
    }
    if let Some(water) = &file.water {
        water_values(
            &mut Section { found: &mut found, knob: KnobId::Water, path: "water".into(), name: "water" },
            water,
        );
    }
    for (index, body) in file.bodies.iter().enumerate() {
        if let Some(hydro) = &body.hydro {
            hydro_values(&mut Section::new(&mut found, KnobId::Hydro(index), "bodies", &body.name), hydro);
        }
    }
    if let Some(seabed) = &file.seabed {
        let mut section = Section { found: &mut found, knob: KnobId::Seabed, path: "seabed".into(), name: "seabed" };
        section.add(&fields::LINE_FRICTION, seabed.line_friction);
    }
    if let Some(air) = &file.air {
        air_values(&mut Section { found: &mut found, knob: KnobId::Air, path: "air".into(), name: "air" }, air);
    }
    found
}

/// Where the values found go, and the knob, path and name they are found under.
struct Section<'a> {
    found: &'a mut Vec<Parameter>,
    knob: KnobId,
    path: String,
    name: &'a str,
}

impl<'a> Section<'a> {
    fn new(found: &'a mut Vec<Parameter>, knob: KnobId, list: &str, name: &'a str) -> Self {
        Self { found, knob, path: format!("{list}.{name}"), name }
    }

    fn add(&mut self, field: &Field, value: f64) {
        self.push(field.path, field.label, field.unit, value);
    }

    /// A field indexed below its own path (a body axis, a table's point): `(path, label)`.
    fn add_indexed(&mut self, (path, label): (String, String), unit: &'static str, value: f64) {
        self.push(&path, &label, unit, value);
    }

    fn push(&mut self, path: &str, label: &str, unit: &'static str, value: f64) {
        self.found.push(Parameter {
            knob: self.knob,
            path: format!("{}.{path}", self.path),
            label: format!("{}: {label}", self.name),
            unit,
            value,
        });
    }
}

fn coupling_values(section: &mut Section, def: &CouplingDef) {
    match def {
        CouplingDef::SpringDamper { law, damping, .. } => {
            law_values(section, law);
            section.add(&fields::SPRING_DAMPING, *damping);
        }
        CouplingDef::Catenary { mass_per_length, length, stiffness, displaced_area, model, .. } => {
            section.add(&fields::MASS_PER_LENGTH, *mass_per_length);
            section.add(&fields::LENGTH, *length);
            section.add(&fields::LINE_STIFFNESS, *stiffness);
            section.add(&fields::DISPLACED_AREA, *displaced_area);
            match model {
                LineModelDef::QuasiStatic => {}
                LineModelDef::Dynamic(line) => {
                    match line.damping {
                        InternalDamping::Ratio(zeta) => section.add(&fields::DAMPING_RATIO, zeta),
                        InternalDamping::Coefficient(ba) => section.add(&fields::DAMPING_BA, ba),
                    }
                    section.add(&fields::DRAG_NORMAL, line.drag_normal);
                    section.add(&fields::DRAG_TANGENTIAL, line.drag_tangential);
                    section.add(&fields::ADDED_MASS_NORMAL, line.added_mass_normal);
                    section.add(&fields::ADDED_MASS_TANGENTIAL, line.added_mass_tangential);
                }
            }
        }
        CouplingDef::Contact { stiffness, damping, range, friction, friction_sharpness, expected_area, .. } => {
            section.add(&fields::CONTACT_STIFFNESS, *stiffness);
            section.add(&fields::CONTACT_DAMPING, *damping);
            section.add(&fields::RANGE, *range);
            section.add(&fields::FRICTION, *friction);
            section.add(&fields::FRICTION_SHARPNESS, *friction_sharpness);
            if let Some(area) = expected_area {
                section.add(&fields::EXPECTED_AREA, *area);
            }
        }
    }
}

fn law_values(section: &mut Section, law: &LawDef) {
    let points = |section: &mut Section, points: &[(f64, f64)], field: &Field| {
        for (row, (_, y)) in points.iter().enumerate() {
            section.add_indexed(field.point(row), field.unit, *y);
        }
    };
    match law {
        LawDef::Linear { stiffness, rest_length } => {
            section.add(&fields::LAW_STIFFNESS, *stiffness);
            section.add(&fields::LAW_REST_LENGTH, *rest_length);
        }
        LawDef::Polynomial { a, b, c, rest_length } => {
            section.add(&fields::LAW_A, *a);
            section.add(&fields::LAW_B, *b);
            section.add(&fields::LAW_C, *c);
            section.add(&fields::LAW_REST_LENGTH, *rest_length);
        }
        LawDef::ForceCurve { points: table } => points(section, table, &fields::FORCE_CURVE_F),
        LawDef::StiffnessCurve { points: table, rest_length } => {
            points(section, table, &fields::STIFFNESS_CURVE_K);
            section.add(&fields::LAW_REST_LENGTH, *rest_length);
        }
        LawDef::ReferenceForce { points: table, reference_length, reference_force, rest_length } => {
            points(section, table, &fields::STIFFNESS_CURVE_K);
            section.add(&fields::LAW_REFERENCE_LENGTH, *reference_length);
            section.add(&fields::LAW_REFERENCE_FORCE, *reference_force);
            section.add(&fields::LAW_REST_LENGTH, *rest_length);
        }
    }
}

fn water_values(section: &mut Section, water: &WaterDef) {
    match &water.waves {
        WavesDef::Calm => {}
        WavesDef::Regular { height, period, heading_deg, .. } => {
            section.add(&fields::WAVE_HEIGHT, *height);
            section.add(&fields::WAVE_PERIOD, *period);
            section.add(&fields::WAVE_HEADING, *heading_deg);
        }
        WavesDef::Jonswap { hs, tp, heading_deg, .. } => {
            section.add(&fields::SIGNIFICANT_HEIGHT, *hs);
            section.add(&fields::PEAK_PERIOD, *tp);
            section.add(&fields::WAVE_HEADING, *heading_deg);
        }
    }
    if let Some(current) = &water.current {
        section.add(&fields::CURRENT_SPEED, current.speed);
        section.add(&fields::CURRENT_HEADING, current.heading_deg);
    }
    section.add(&fields::WATER_DENSITY, water.density);
}

fn air_values(section: &mut Section, air: &AirDef) {
    section.add(&fields::WIND_SPEED, air.wind.speed);
    section.add(&fields::WIND_HEIGHT, air.wind.height);
    section.add(&fields::WIND_HEADING, air.wind.heading_deg);
    if let GustsDef::Kaimal { intensity, .. } = air.wind.gusts {
        section.add(&fields::TURBULENCE_INTENSITY, intensity);
    }
    section.add(&fields::AIR_DENSITY, air.density);
}

fn hydro_values(section: &mut Section, hydro: &HydroDef) {
    section.path += ".hydro";
    for (field, values) in [
        (&fields::HYDRO_DRAG, hydro.drag),
        (&fields::HYDRO_ADDED_MASS, hydro.added_mass),
        (&fields::HYDRO_LINEAR_DAMPING, hydro.linear_damping),
    ] {
        for (axis, value) in values.iter().enumerate() {
            section.add_indexed(field.axis(axis), field.unit, *value);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::value_path::ValuePath;
    use std::path::Path;

    /// A float in waves on a spring, and a dynamic line, with every kind of value tunable.
    const SCENE: &str = r#"Scene(dt: 0.01, water: Water(depth: 30.0, waves: Regular(height: 1.0, period: 6.0), current: Current(speed: 0.5)),
        bodies: [Body(name: "float", master: Node(position: (0.0, 0.0, 0.0), mass: 1025.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
             shape: Box(size: (2.0, 2.0, 1.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0), linear_damping: (0.0, 0.0, 50.0)))],
        couplings: [
            SpringDamper(name: "spring", end1: World((0.0, 0.0, -5.0)), end2: Body(body: "float"),
                law: ForceCurve(points: [(0.0, 0.0), (1.0, 100.0)]), damping: 2.0),
            Catenary(name: "line", end1: World((20.0, 0.0, -30.0)), end2: Body(body: "float"),
                mass_per_length: 50.0, length: 40.0, stiffness: 1e8,
                model: Dynamic(segments: 10, damping: Ratio(0.8), drag_normal: 1.2)),
        ])"#;

    /// Every parameter's path leads to its value in the scene's data.
    #[test]
    fn every_parameter_path_leads_to_its_value() {
        let file = tether_scene::parse(SCENE, Path::new("float.ron")).unwrap().file;
        let tree = serde_json::to_value(&file).unwrap();
        let found = parameters(&file);
        assert!(found.len() > 20, "{} values", found.len());
        for fittable in &found {
            let path = ValuePath::find(&tree, &fittable.path).unwrap_or_else(|e| panic!("{}: {e}", fittable.label));
            // A value the scene leaves to its default (A_d = 0 is not written) has no number.
            if let Some(value) = path.get(&tree) {
                assert_eq!(value.as_f64(), Some(fittable.value), "{} at {}", fittable.label, fittable.path);
            }
        }
        let labels: Vec<&str> = found.iter().map(|f| f.label.as_str()).collect();
        for expected in ["spring: point 2 f", "line: drag C_dn", "line: damping ratio ζ", "water: current speed"] {
            assert!(labels.contains(&expected), "{expected} in {labels:?}");
        }
        let damping = found.iter().find(|f| f.label == "float: linear damping z").unwrap();
        assert_eq!(
            (damping.knob, damping.path.as_str(), damping.value),
            (KnobId::Hydro(0), "bodies.float.hydro.linear_damping.2", 50.0)
        );
    }
}
