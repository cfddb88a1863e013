//! The `seabed` section, a line's displaced area and a body's initial rotation (PHYSICS.md §7): what
//! they build, and a one-line `path:line:col` error naming the item for each bad value.

use tether_test_support as common;

use approx::assert_relative_eq;
use std::path::Path;
use tether_physics::coupling::CouplingKind;
use tether_scene as scene;

/// A block on the seabed 40 m down, a buoy held by a chain anchored on the bottom.
const MOORED: &str = r#"Scene(
    dt: 0.002,
    bodies: [
        Body(
            name: "buoy",
            master: Node(position: (60.0, 0.0, 0.0), mass: 3000.0, inertia: Inertia(xx: 1750.0, yy: 1750.0, zz: 1500.0)),
            shape: Cylinder(radius: 1.0, length: 2.0),
        ),
        Body(
            name: "block",
            master: Node(position: (-5.0, 0.0, -39.5), mass: 2000.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
            shape: Box(size: (1.0, 1.0, 1.0)),
        ),
    ],
    couplings: [
        Catenary(
            name: "chain",
            end1: World((0.0, 0.0, -40.0)),
            end2: Body(body: "buoy", point: (0.0, 0.0, -1.0)),
            mass_per_length: 50.0,
            length: 100.0,
            stiffness: 5e6,
            displaced_area: 0.0064,
        ),
    ],
    seabed: Seabed(
        elevation: -40.0,
        line_friction: 0.6,
        contact: SeabedContact(bodies: ["block"], stiffness: 2e5, damping: 1000.0, range: 0.01, friction: 0.5),
    ),
)
"#;

fn assert_error(edit: (&str, &str), expected: &str) {
    assert!(MOORED.contains(edit.0), "edit target {:?} missing", edit.0);
    let error = common::error_of(&MOORED.replacen(edit.0, edit.1, 1));
    assert_eq!(error, expected);
}

#[test]
fn a_chain_anchored_on_the_seabed_lies_on_it_and_a_block_touches_it() {
    let loaded = common::scene(MOORED);
    assert!(loaded.warnings.iter().any(|w| w.contains("displaced_area is ignored")), "{:?}", loaded.warnings);
    let world = &loaded.world;
    let line = world.line_state(0).expect("a catenary");
    assert!(line.grounded_length() > 20.0, "L_B = {}", line.grounded_length());
    assert_eq!(world.system().seabed().map(|s| (s.elevation(), s.line_friction())), Some((-40.0, 0.6)));
    let contact = &world.couplings()[1];
    assert_eq!(contact.name, "seabed.block");
    assert!(matches!(contact.kind, CouplingKind::Contact(_)));
}

#[test]
fn a_body_starts_turned_by_its_rotation_about_its_master_node() {
    let turned =
        MOORED.replacen("name: \"buoy\",", "name: \"buoy\",\n            rotation: (0.0, 0.0, 1.5707963267948966),", 1);
    let world = common::scene(&turned).world;
    // The fairlead 1 m below the master node stays there; a point 1 m along x goes to y.
    let state = world.state(0);
    assert_relative_eq!(state.position, nalgebra::Vector3::new(60.0, 0.0, 0.0), epsilon = 1e-12);
    let body = &world.bodies()[0];
    let along_x = state.point(&body.principal_point(&nalgebra::Vector3::new(1.0, 0.0, 0.0)));
    assert_relative_eq!(along_x, nalgebra::Vector3::new(60.0, 1.0, 0.0), epsilon = 1e-12);
}

#[test]
fn the_seabed_section_round_trips_through_ron() {
    let turned = MOORED.replacen("name: \"buoy\",", "name: \"buoy\",\n            rotation: (0.1, 0.0, 0.2),", 1);
    let loaded = common::scene(&turned);
    let text = scene::to_ron(&loaded.file).unwrap();
    let again = scene::parse(&text, Path::new("saved.ron")).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(again.file, loaded.file);
    assert_eq!(again.world.couplings(), loaded.world.couplings());
}

#[test]
fn a_seabed_needs_an_elevation_without_water() {
    assert_error(
        ("        elevation: -40.0,\n", ""),
        "bad.ron:26:5: seabed: the seabed needs an elevation (z_b, m): the scene has no water depth to take it from",
    );
}

#[test]
fn negative_line_friction() {
    assert_error(
        ("line_friction: 0.6", "line_friction: -0.1"),
        "bad.ron:28:9: seabed: line_friction must be ≥ 0, got -0.1",
    );
}

#[test]
fn negative_displaced_area() {
    assert_error(
        ("displaced_area: 0.0064", "displaced_area: -0.01"),
        "bad.ron:23:13: coupling \"chain\": displaced_area must be ≥ 0 m², got -0.01",
    );
}

#[test]
fn an_anchor_below_the_seabed() {
    assert_error(
        ("World((0.0, 0.0, -40.0))", "World((0.0, 0.0, -42.5))"),
        "bad.ron:18:13: coupling \"chain\": end 1 is 2.5 m below the seabed (z_b = -40 m): an anchor lies on the seabed or above it",
    );
}

#[test]
fn an_unknown_body_on_the_seabed() {
    assert_error(
        ("bodies: [\"block\"]", "bodies: [\"blok\"]"),
        "bad.ron:29:41: seabed: unknown body \"blok\" (bodies: buoy, block)",
    );
}

#[test]
fn bad_seabed_contact_parameters() {
    assert_error(("stiffness: 2e5", "stiffness: 0.0"), "bad.ron:29:51: seabed: stiffness must be > 0 N/m³, got 0");
    assert_error(
        ("bodies: [\"block\"]", "bodies: [\"block\", \"block\"]"),
        "bad.ron:29:41: seabed: body \"block\" is listed twice",
    );
}

/// `MOORED` in 40 m of water: `water` inserted before the seabed section, its elevation removed.
fn in_water(water: &str) -> String {
    MOORED.replacen(
        "    seabed: Seabed(\n        elevation: -40.0,\n",
        &format!("    water: {water},\n    seabed: Seabed(\n"),
        1,
    )
}

#[test]
fn in_water_the_seabed_lies_at_its_depth_and_the_lines_weigh_what_they_displace_less() {
    let text = in_water("Water(density: 1025.0, depth: 40.0)");
    assert!(!text.contains("elevation"), "{text}");
    let loaded = common::scene(&text);
    let system = loaded.world.system();
    assert_eq!(system.seabed().map(|s| s.elevation()), Some(-40.0));
    assert_eq!(system.surroundings().fluid_density, 1025.0);
    // The same line dry with λ0 − ρ A_d per metre gives the same forces: W = (λ0 − ρ A_d) g.
    let dry =
        common::scene(
            &MOORED
                .replacen("mass_per_length: 50.0", &format!("mass_per_length: {}", 50.0 - 1025.0 * 0.0064), 1)
                .replacen("displaced_area: 0.0064,", "", 1),
        );
    let (wet, reference) = (loaded.world.line_state(0).unwrap(), dry.world.line_state(0).unwrap());
    // Both solved by the same Newton from the same start to round-off of the line's equations.
    assert_relative_eq!(wet.horizontal_tension, reference.horizontal_tension, max_relative = 1e-12);
    assert_relative_eq!(wet.grounded_length(), reference.grounded_length(), max_relative = 1e-12);
    // A declared elevation that agrees with the water's bottom is accepted.
    let agreeing = text.replacen("    seabed: Seabed(\n", "    seabed: Seabed(\n        elevation: -40.0,\n", 1);
    assert_eq!(common::scene(&agreeing).world.system().seabed().map(|s| s.elevation()), Some(-40.0));
}

#[test]
fn a_seabed_that_disagrees_with_the_water_or_has_none_to_lie_under() {
    let text = in_water("Water(depth: 40.0)").replacen(
        "    seabed: Seabed(\n",
        "    seabed: Seabed(\n        elevation: -45.0,\n",
        1,
    );
    assert_eq!(
        common::error_of(&text),
        "bad.ron:28:9: seabed: the seabed elevation -45 m disagrees with the water's bottom (level 0 m − depth 40 m = -40 m): leave it out and it lies there"
    );
    assert_eq!(
        common::error_of(&in_water("Water()")),
        "bad.ron:27:5: seabed: the water is deep (no depth): give the water a depth, and the seabed lies there"
    );
}

#[test]
fn a_line_that_floats_is_warned_of() {
    let loaded =
        common::scene(&in_water("Water(depth: 40.0)").replacen("displaced_area: 0.0064", "displaced_area: 0.1", 1));
    let warning = loaded.warnings.iter().find(|w| w.contains("chain")).expect("a warning about the chain");
    assert!(warning.contains("the line floats (ρ A_d = 102.5 kg/m > λ0 = 50 kg/m): it arches upward"), "{warning}");
}

/// Edited water carries the seabed and the lines' weight with it: a deeper bottom moves the
/// seabed down, a denser sea lightens the lines, and a bottom above an anchor is refused with
/// the world unchanged.
#[test]
fn edited_water_moves_the_seabed_and_reweighs_the_lines() {
    let mut world = common::scene(&in_water("Water(density: 1025.0, depth: 40.0)")).world;
    let spec = *world.system().water().expect("water").water.spec();
    world.replace_water(tether_physics::water::WaterSpec { depth: Some(45.0), density: 1030.0, ..spec }).unwrap();
    assert_eq!(world.system().seabed().map(|s| s.elevation()), Some(-45.0));
    assert_eq!(world.system().surroundings().fluid_density, 1030.0);
    let error = world.replace_water(tether_physics::water::WaterSpec { depth: Some(35.0), ..spec }).unwrap_err();
    assert!(error.to_string().contains("coupling \"chain\": end 1 is 5 m below the seabed (z_b = -35 m)"), "{error}");
    assert_eq!(world.system().seabed().map(|s| s.elevation()), Some(-45.0), "unchanged");
}

/// `moored_buoy` (C_B = 1 on its three grounded chains, waves, current, a 5 m push) run for
/// 10 s by `integrator` at `dt`: the size of the balance's drift \[J], and the work booked as
/// dissipated at the end \[J].
fn moored_buoy_drift(integrator: &str, dt: f64) -> (f64, f64) {
    let text = std::fs::read_to_string(common::repo("scenes/moored_buoy.ron")).unwrap();
    let text = text
        .replace("dt: 0.05,", &format!("dt: {dt},"))
        .replace("integrator: rk4,", &format!("integrator: {integrator},"));
    let mut world = common::scene(&text).world;
    let start = world.energy().balance();
    for _ in 0..(10.0 / dt).round() as usize {
        world.step().unwrap();
    }
    ((world.energy().balance() - start).abs(), world.energy().dissipated)
}

/// The seabed friction's work on quasi-static grounded lines is booked, held with the lines'
/// energy (PHYSICS.md §7), so
/// `moored_buoy`'s balance falls as the step halves, at each integrator's order, instead of
/// stalling at the friction's unbooked work: 331.2 J over these 10 s at every step before
/// (0.41 kJ over 60 s). RK4 at 0.2, 0.1, 0.05 s: 0.36 J, 0.035 J, 4e-5 J (at least 2³ per
/// halving; 4e-5 J is 6e-10 of the 63 kJ the push stored); the leapfrog at 10, 5, 2.5 ms:
/// 2.31, 1.17, 0.59 J, first order — the order at which it books every velocity-dependent
/// power, at `v(t − ½dt)` (§5; the same scene without friction drifts 0.067, 0.017, 0.0042 J).
/// Nothing of it is dissipated: `dissipated` stays 0 in every run.
#[test]
fn the_seabed_friction_on_grounded_lines_is_booked() {
    let runs = |integrator: &str, steps: [f64; 3]| -> Vec<f64> {
        let runs = steps.map(|dt| moored_buoy_drift(integrator, dt));
        assert!(runs.iter().all(|&(_, dissipated)| dissipated == 0.0), "{integrator} dissipated: {runs:?}");
        runs.iter().map(|&(drift, _)| drift).collect()
    };
    let rk4 = runs("rk4", [0.2, 0.1, 0.05]);
    assert!(rk4[1] < rk4[0] / 8.0 && rk4[2] < rk4[1] / 8.0, "RK4: {rk4:?}");
    assert!(rk4[2] < 1e-3, "RK4 at 50 ms: {rk4:?}");
    let leapfrog = runs("leapfrog", [0.01, 0.005, 0.0025]);
    for pair in leapfrog.windows(2) {
        let order = (pair[0] / pair[1]).log2();
        assert!((0.9..1.1).contains(&order), "leapfrog: {leapfrog:?}");
    }
    assert!(leapfrog[2] < 1.0, "leapfrog at 2.5 ms: {leapfrog:?}");
}
