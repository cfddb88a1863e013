//! Scenes with water (PHYSICS.md §6): what they declare reaches the physics, and every bad value
//! is refused with one line `path:line:col: message` naming the body or the water field.

use tether_test_support as common;

use tether_physics::water::WaveSpec;
use tether_scene as scene;

/// A floating box in a regular wave; the bad cases below edit it.
const GOOD: &str = r#"Scene(
    dt: 0.01,
    water: Water(
        density: 1025.0,
        depth: 30.0,
        current: Current(speed: 0.5, heading_deg: 90.0),
        waves: Regular(height: 1.0, period: 6.0, heading_deg: 45.0),
        ramp: 10.0,
    ),
    bodies: [
        Body(
            name: "box",
            master: Node(position: (0.0, 0.0, 0.0), mass: 1000.0, inertia: Inertia(xx: 100.0, yy: 100.0, zz: 100.0)),
            shape: Box(size: (2.0, 2.0, 1.0)),
            hydro: Hydro(drag: (1.0, 1.0, 1.0), added_mass: (0.5, 0.5, 1.0)),
        ),
    ],
)
"#;

fn assert_error(edit: (&str, &str), expected: &str) {
    common::assert_edit_error(GOOD, edit, expected);
}

#[test]
fn the_good_scene_reaches_the_physics_in_radians() {
    let loaded = common::scene(GOOD);
    let stage = loaded.world.system().water().expect("water");
    match stage.water.spec().waves {
        WaveSpec::Regular { height, period, heading, .. } => {
            assert_eq!((height, period), (1.0, 6.0));
            assert!((heading - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(stage.floating.len(), 1);
    // Projected areas from the mesh: 2 × 1 m across x and y, 2 × 2 m across z.
    assert_eq!(
        stage.floating[0].hydro().drag_areas().map(|a| (a * 1e12).round() / 1e12),
        nalgebra::Vector3::new(2.0, 2.0, 4.0)
    );
}

#[test]
fn a_scene_without_water_has_no_water_stage_and_saves_without_it() {
    let text = GOOD.replace("water: Water(\n        density: 1025.0,\n        depth: 30.0,\n        current: Current(speed: 0.5, heading_deg: 90.0),\n        waves: Regular(height: 1.0, period: 6.0, heading_deg: 45.0),\n        ramp: 10.0,\n    ),\n", "");
    assert!(!text.contains("Water("));
    let loaded = common::scene(&text);
    assert!(loaded.world.system().water().is_none());
    assert!(
        loaded.warnings.iter().any(|w| w.contains("declares hydro but the scene has no water")),
        "{:?}",
        loaded.warnings
    );
    assert!(!scene::to_ron(&loaded.file).unwrap().contains("water"));
}

#[test]
fn a_body_under_the_surface_without_hydro_is_warned_about() {
    let loaded = common::scene(
        &GOOD
            .replace("            hydro: Hydro(drag: (1.0, 1.0, 1.0), added_mass: (0.5, 0.5, 1.0)),\n", "")
            .replace("position: (0.0, 0.0, 0.0)", "position: (0.0, 0.0, -3.0)"),
    );
    assert!(
        loaded.warnings.iter().any(|w| w.contains("body \"box\" starts under the water surface but declares no hydro")),
        "{:?}",
        loaded.warnings
    );
}

#[test]
fn bad_water_is_refused_at_its_field() {
    assert_error(("density: 1025.0", "density: 0.0"), "bad.ron:4:9: water: density must be > 0 kg/m³, got 0");
    assert_error(("depth: 30.0", "depth: -2.0"), "bad.ron:5:9: water: depth must be > 0 m, got -2");
    assert_error(("period: 6.0", "period: 0.0"), "bad.ron:7:37: water: wave period must be > 0 s, got 0");
    // 5 m high at 2 s (λ = 6.2 m): steeper than 1/7.
    assert_error(
        ("height: 1.0, period: 6.0", "height: 5.0, period: 2.0"),
        "bad.ron:7:9: water: the wave is steeper than the breaking limit: H/λ = 5/6.",
    );
    assert_error(
        ("Regular(height: 1.0, period: 6.0, heading_deg: 45.0)", "Jonswap(hs: 1.0, tp: 6.0, gamma: 0.5)"),
        "bad.ron:7:42: water: JONSWAP gamma must be ≥ 1, got 0.5",
    );
    assert_error(("speed: 0.5", "speed: NaN"), "bad.ron:6:36: number must be finite, got NaN");
    assert_error(("ramp: 10.0", "ramp: -1.0"), "bad.ron:8:9: water: ramp must be ≥ 0 s, got -1");
    let deep_power_law = GOOD
        .replace("        depth: 30.0,\n", "")
        .replace("heading_deg: 90.0)", "heading_deg: 90.0, profile: PowerLaw)");
    assert_eq!(
        common::error_of(&deep_power_law),
        "bad.ron:5:57: water: a power-law current needs a depth (it is zero at the seabed)"
    );
}

#[test]
fn bad_coefficients_and_hulls_are_refused_naming_the_body() {
    assert_error(
        ("drag: (1.0, 1.0, 1.0)", "drag: (1.0, -1.0, 1.0)"),
        "bad.ron:15:13: body \"box\": hydro: drag must be finite and ≥ 0 on every axis, got (1, -1, 1)",
    );
    assert_error(
        ("added_mass: (0.5, 0.5, 1.0)", "added_mass: (0.5, 0.5, 1.0), drag_areas: (1.0, 0.0, 1.0)"),
        "bad.ron:15:13: body \"box\": hydro: drag_areas must be finite and > 0 m² on every axis, got (1, 0, 1)",
    );
    let fixture = |name: &str| common::here!(&format!("fixtures/{name}")).display().to_string();
    for (file, expected) in
        [("open_box.obj", "its shape as a hull in water: the mesh is open"), ("flat.obj", "the mesh has zero area")]
    {
        let text = GOOD.replace("Box(size: (2.0, 2.0, 1.0))", &format!("Mesh(file: {:?})", fixture(file)));
        let error = common::error_of(&text);
        assert!(
            error.contains("body \"box\"") && error.contains(expected) && error.starts_with("bad.ron:14:"),
            "{error}"
        );
    }
}

/// Every shipped scene with water loads and runs its first second.
#[test]
fn shipped_water_scenes_run() {
    for name in ["floating_box", "sinking_sphere", "barge_in_waves", "moored_buoy"] {
        let mut loaded = scene::load(&common::repo(&format!("scenes/{name}.ron"))).unwrap_or_else(|e| panic!("{e}"));
        assert!(loaded.world.system().water().is_some(), "{name}");
        while loaded.world.time() < 1.0 {
            loaded.world.step().unwrap_or_else(|e| panic!("{name}: {e}"));
        }
    }
}
