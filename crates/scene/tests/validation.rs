//! One validation path: a value is checked once, by the constructor of its physics type, and
//! every way of setting it — the scene file, a knob in the window (which builds the edited
//! coupling with `build::coupling`), a sweep case (which builds the edited scene data with
//! `build_variant`), the physics called directly — reads the same one-line message for the same
//! bad value, naming the coupling (or section) and the field.

use tether_test_support as common;

use std::path::Path;
use tether_physics::coupling::{ElasticLaw, Endpoint, SpringDamper};
use tether_physics::integrator::{Integrator, Substeps, Timing, Tolerances};
use tether_physics::math::Vec3;
use tether_physics::seabed::Seabed;
use tether_scene::file::{CouplingDef, LawDef};
use tether_scene::{self as scene, build};

/// A ball hung from the world by spring "link", over a seabed.
const GOOD: &str = r#"Scene(
    dt: 0.001,
    bodies: [
        Body(
            name: "ball",
            master: Node(position: (0.0, 0.0, -1.0), mass: 1.0, inertia: Inertia(xx: 0.1, yy: 0.1, zz: 0.1)),
            shape: Sphere(radius: 0.1),
        ),
    ],
    couplings: [
        SpringDamper(
            name: "link",
            end1: World((0.0, 0.0, 0.0)),
            end2: Body(body: "ball"),
            law: Linear(stiffness: 100.0, rest_length: 0.5),
            damping: 1.0,
        ),
    ],
    seabed: Seabed(elevation: -10.0, line_friction: 0.5),
)
"#;

/// The negative stiffness every path below sets, and the message each must give.
const STIFFNESS: f64 = -5.0;
const MESSAGE: &str = "coupling \"link\": stiffness must be ≥ 0 N/m, got -5";
/// Where the file path places it: the `stiffness` of "link".
const AT: &str = "bad.ron:15:25: ";

/// The good scene's data with the spring's stiffness set to `stiffness`, as a knob or a
/// sweep's factor sets it.
fn with_stiffness(stiffness: f64) -> scene::SceneFile {
    let mut file = common::scene(GOOD).file;
    let CouplingDef::SpringDamper { law: LawDef::Linear { stiffness: k, .. }, .. } = &mut file.couplings[0] else {
        panic!("the good scene's coupling is a linear spring")
    };
    *k = stiffness;
    file
}

#[test]
fn a_negative_stiffness_reads_the_same_from_the_file_a_knob_and_a_sweep_case() {
    // The scene file.
    let from_file = common::error_of(&GOOD.replace("stiffness: 100.0", "stiffness: -5.0"));
    assert_eq!(from_file, format!("{AT}{MESSAGE}"));
    // A knob in the window: the panel builds the edited coupling against the loaded bodies.
    let mut loaded = common::scene(GOOD);
    let from_knob = build::coupling(&with_stiffness(STIFFNESS), 0, &mut loaded.bodies).unwrap_err();
    assert_eq!(from_knob.message, MESSAGE);
    // A sweep case: the scene data with the factor's value, built as a variant of the text.
    let from_case = scene::build_variant(GOOD, Path::new("bad.ron"), with_stiffness(STIFFNESS)).err().unwrap();
    assert_eq!(from_case.to_string(), format!("{AT}{MESSAGE}"));
    // The physics itself: the constructor whose message the others carry, without the name.
    let law = ElasticLaw::Linear { stiffness: STIFFNESS, rest_length: 0.5 };
    let from_physics = SpringDamper::new(Endpoint::World(Vec3::zeros()), Endpoint::Center { body: 0 }, law, 1.0);
    let error = from_physics.unwrap_err();
    assert_eq!((error.field(), error.to_string()), ("stiffness", "stiffness must be ≥ 0 N/m, got -5".to_string()));
    assert!(MESSAGE.ends_with(&error.to_string()));
}

#[test]
fn a_negative_line_friction_reads_the_same_from_the_file_and_the_seabed_knob() {
    let from_file = common::error_of(&GOOD.replace("line_friction: 0.5", "line_friction: -0.1"));
    let message = "seabed: line_friction must be ≥ 0, got -0.1";
    assert_eq!(from_file, format!("bad.ron:19:38: {message}"));
    // The window's seabed knob builds the seabed with the running elevation.
    assert_eq!(Seabed::new(-10.0, -0.1).unwrap_err().to_string(), message);
}

#[test]
fn a_bad_time_step_reads_the_same_from_the_file_the_timing_knobs_and_the_command_line() {
    let message = "dt must be > 0 s, got -0.001";
    let from_file = common::error_of(&GOOD.replace("dt: 0.001", "dt: -0.001"));
    assert_eq!(from_file, format!("bad.ron:2:5: {message}"));
    // The window's timing knobs write the tuned scene data and check it with `build::timing`.
    let loaded = common::scene(GOOD);
    let mut tuned = loaded.file.clone();
    tuned.dt = -0.001;
    assert_eq!(build::timing(&tuned).unwrap_err().message, message);
    // `tether record --dt` writes the flag into the scene data and retimes the loaded world.
    let from_flag = scene::retime(scene::Scene { file: tuned, ..loaded }).err().unwrap();
    assert_eq!(from_flag.message, message);
    // The physics itself.
    let timing = Timing::new(-0.001, Integrator::Leapfrog, Substeps::Fixed(1), Tolerances::default());
    assert_eq!(timing.unwrap_err().to_string(), message);
}

#[test]
fn every_coupling_constructor_names_the_field_it_refuses() {
    use tether_physics::coupling::Catenary;
    use tether_physics::coupling::contact::ContactLaw;
    let ends = (Endpoint::World(Vec3::zeros()), Endpoint::Center { body: 0 });
    let line = |mass, length, stiffness| Catenary::new(ends.0, ends.1, mass, length, stiffness);
    let refused = |error: tether_physics::parameter::ParameterError| error.to_string();
    assert_eq!(refused(line(-1.0, 10.0, 1e6).unwrap_err()), "mass_per_length must be ≥ 0 kg/m, got -1");
    assert_eq!(refused(line(1.0, 0.0, 1e6).unwrap_err()), "length must be > 0 m, got 0");
    assert_eq!(refused(line(1.0, 10.0, f64::NAN).unwrap_err()), "stiffness must be > 0 N/m, got NaN");
    let wet = line(1.0, 10.0, 1e6).unwrap().with_displaced_area(-0.01);
    assert_eq!(refused(wet.unwrap_err()), "displaced_area must be ≥ 0 m², got -0.01");
    assert_eq!(refused(ContactLaw::new(0.0, 0.0, 0.0, 0.0, 1.0).unwrap_err()), "stiffness must be > 0 N/m³, got 0");
    assert_eq!(refused(ContactLaw::new(1e6, 0.0, 0.0, -0.2, 1.0).unwrap_err()), "friction must be ≥ 0, got -0.2");
    assert_eq!(
        refused(ContactLaw::new(1e6, 0.0, 0.0, 0.2, 0.0).unwrap_err()),
        "friction_sharpness must be > 0 s/m, got 0"
    );
    let damper = SpringDamper::new(ends.0, ends.1, ElasticLaw::Linear { stiffness: 1.0, rest_length: 0.0 }, -2.0);
    assert_eq!(refused(damper.unwrap_err()), "damping must be ≥ 0 N·s/m, got -2");
    let table = ElasticLaw::force_curve(vec![(1.0, 0.0)]).unwrap_err();
    assert_eq!((table.field(), refused(table)), ("points", "points: a table needs at least 2 points, got 1".into()));
}

/// Issue 48: a value each check lets through but whose derived quantity overflows — the
/// chain's λ0 of 10³⁰⁸ kg/m, whose submerged weight per length is infinite — is refused in one
/// line at its field, from the file and from a knob (the edited coupling reaching the world);
/// the shipped scene's own values load.
#[test]
fn a_weight_that_overflows_reads_the_same_from_the_file_and_a_knob() {
    let good = std::fs::read_to_string(common::repo("scenes/chain_forced_surge.ron")).unwrap();
    let message = "coupling \"chain\": the submerged weight per length (λ0 − ρ A_d) g must be finite, got inf (from mass_per_length = 1e308)";
    let from_file = common::error_of(&good.replace("mass_per_length: 25.79", "mass_per_length: 1e308"));
    assert_eq!(from_file, format!("bad.ron:31:13: {message}"));
    let mut loaded = common::scene(&good);
    let mut tuned = loaded.file.clone();
    let CouplingDef::Catenary { mass_per_length, .. } = &mut tuned.couplings[0] else {
        panic!("the chain is a catenary")
    };
    *mass_per_length = 1e308;
    let coupling = build::coupling(&tuned, 0, &mut loaded.bodies).expect("its values each in range");
    let from_knob = loaded.world.replace_coupling(0, coupling).unwrap_err();
    assert_eq!(from_knob.to_string(), message);
    // A dynamic constant: a node's drag with C_dn of 10³⁰⁸.
    let error = common::error_of(&good.replace("drag_normal: 2.4", "drag_normal: 1e308"));
    assert_eq!(
        error,
        "bad.ron:40:17: coupling \"chain\": a node's drag ½ ρ C_dn d l must be finite, got inf (from drag_normal = 1e308)"
    );
}
