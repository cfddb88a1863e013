//! Every shipped scene loads; every bad scene is refused with `path:line:col: message`.

use tether_test_support as common;

use std::path::Path;
use tether_scene as scene;

#[test]
fn every_shipped_scene_loads() {
    let files = common::scene_files();
    assert!(files.len() >= 5, "{files:?}");
    for file in files {
        let scene = scene::load(&file).unwrap_or_else(|e| panic!("{e}"));
        assert!(!scene.world.bodies().is_empty(), "{}", file.display());
        assert!(scene.world.energy().total().is_finite());
    }
}

#[test]
fn bench_chain_is_as_specified() {
    let scene = scene::load(&common::repo("scenes/bench/chain100_air.ron")).unwrap();
    let world = &scene.world;
    assert_eq!(world.bodies().len(), 100);
    assert_eq!(world.couplings().len(), 101);
    assert_eq!(world.dt(), 0.002);
    for (i, body) in world.bodies().iter().enumerate() {
        assert_eq!(body.mass(), 1.0);
        approx::assert_relative_eq!(
            body.principal_moments(),
            nalgebra::Vector3::repeat(0.4 * 0.05 * 0.05),
            epsilon = 1e-15
        );
        let x = 15.0 * (i + 1) as f64 / 101.0;
        approx::assert_relative_eq!(
            body.mass_properties.center_of_mass,
            nalgebra::Vector3::new(x, 0.0, 30.0),
            epsilon = 1e-12
        );
    }
}

/// A valid scene with one body and one spring; the bad cases below edit it.
const GOOD: &str = r#"Scene(
    dt: 0.001,
    bodies: [
        Body(
            name: "box",
            master: Node(position: (0.0, 0.0, 1.0), mass: 2.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
            shape: Box(size: (1.0, 1.0, 1.0)),
        ),
        Body(
            name: "ball",
            master: Node(position: (1.0, 0.0, 1.0), mass: 1.0, inertia: Inertia(xx: 0.1, yy: 0.1, zz: 0.1)),
            shape: Sphere(radius: 0.1),
        ),
    ],
    couplings: [
        SpringDamper(
            name: "link",
            end1: Body(body: "box"),
            end2: Body(body: "ball"),
            law: StiffnessCurve(points: [(0.5, 10.0), (1.0, 20.0)], rest_length: 1.0),
        ),
    ],
)
"#;

fn assert_error(edit: (&str, &str), expected: &str) {
    common::assert_edit_error(GOOD, edit, expected);
}

#[test]
fn the_good_scene_is_good() {
    common::scene(GOOD);
}

#[test]
fn syntax_error() {
    assert_error(("mass: 2.0,", "mass: 2.0"), "bad.ron:6:63: body \"box\": Expected comma");
}

#[test]
fn unknown_field() {
    assert_error(
        ("mass: 2.0,", "mass: 2.0, colour: 3,"),
        "bad.ron:6:70: body \"box\": Unexpected field named `colour` in `Node`",
    );
}

#[test]
fn unknown_body_in_a_coupling() {
    assert_error(
        ("end2: Body(body: \"ball\")", "end2: Body(body: \"bal\")"),
        "bad.ron:19:30: coupling \"link\": unknown body \"bal\" (bodies: box, ball)",
    );
}

#[test]
fn duplicate_body_name() {
    assert_error(("name: \"ball\"", "name: \"box\""), "bad.ron:10:19: body \"box\": duplicate body name");
}

#[test]
fn non_positive_mass() {
    assert_error(("mass: 1.0,", "mass: 0.0,"), "bad.ron:11:53: body \"ball\": total mass must be > 0 kg, got 0 kg");
    assert_error(
        ("mass: 1.0,", "mass: -1.0,"),
        "bad.ron:11:53: body \"ball\": the master node has negative mass -1 kg",
    );
}

#[test]
fn inertia_not_positive_definite() {
    assert_error(
        ("inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)", "inertia: Inertia(xx: 1.0, yy: 1.0, zz: -3.0)"),
        "bad.ron:6:64: body \"box\": inertia tensor about G is not positive definite",
    );
}

#[test]
fn zero_time_step() {
    assert_error(("dt: 0.001", "dt: 0.0"), "bad.ron:2:5: dt must be > 0 s, got 0");
}

#[test]
fn non_monotonic_table() {
    assert_error(
        ("(0.5, 10.0), (1.0, 20.0)", "(0.5, 10.0), (0.4, 20.0)"),
        "bad.ron:20:33: coupling \"link\": points: table point 1: x must increase strictly (0.5 then 0.4)",
    );
}

#[test]
fn table_with_one_point() {
    assert_error(
        ("(0.5, 10.0), (1.0, 20.0)", "(0.5, 10.0)"),
        "bad.ron:20:33: coupling \"link\": points: a table needs at least 2 points, got 1",
    );
}

#[test]
fn nan_and_infinite_values() {
    assert_error(("mass: 1.0,", "mass: NaN,"), "bad.ron:11:62: body \"ball\": number must be finite, got NaN");
    assert_error(
        ("rest_length: 1.0", "rest_length: inf"),
        "bad.ron:20:85: coupling \"link\": number must be finite, got inf",
    );
    assert_error(("mass: 1.0,", "mass: 1e999,"), "bad.ron:11:64: body \"ball\": number must be finite, got inf");
}

#[test]
fn same_point_of_the_same_body() {
    assert_error(
        ("end2: Body(body: \"ball\")", "end2: Body(body: \"box\")"),
        "bad.ron:19:13: coupling \"link\": both ends are the same point",
    );
}

#[test]
fn missing_file_is_an_error_not_a_panic() {
    let error = scene::load(Path::new("no/such/scene.ron")).err().unwrap().to_string();
    assert!(error.starts_with("no/such/scene.ron:1:1: cannot read scene file"), "{error}");
}

/// The box driven harmonically: `support` with `motion` in its `Harmonic(…)`, on line 7.
fn harmonic(motion: &str) -> (&'static str, String) {
    let edit =
        format!("support: Kinematic(velocity: Harmonic({motion})),\n            shape: Box(size: (1.0, 1.0, 1.0)),");
    ("shape: Box(size: (1.0, 1.0, 1.0)),", edit)
}

#[test]
fn harmonic_motion_with_a_bad_value() {
    let good = GOOD.replacen(harmonic("").0, &harmonic("amplitude: (2.0, 0.0, 0.0), period: 10.0").1, 1);
    common::scene(&good);
    let cases = [
        ("amplitude: (2.0, 0.0, 0.0), period: 0.0", "bad.ron:7:79: body \"box\": period must be > 0 s, got 0"),
        ("amplitude: (2.0, 0.0, 0.0), period: -10", "bad.ron:7:79: body \"box\": period must be > 0 s, got -10"),
        ("amplitude: (2.0, NaN, 0.0), period: 10.0", "bad.ron:7:77: body \"box\": number must be finite, got NaN"),
        (
            "amplitude: (2.0, 0.0, 0.0), period: 10.0, phase: (0.0, 0.0, inf)",
            "bad.ron:7:115: body \"box\": number must be finite, got inf",
        ),
        (
            "amplitude: (2.0, 0.0, 0.0)",
            "bad.ron:7:77: body \"box\": Unexpected missing field named `period` in `Harmonic`",
        ),
    ];
    for (motion, expected) in cases {
        let (from, to) = harmonic(motion);
        assert_error((from, &to), expected);
    }
}
