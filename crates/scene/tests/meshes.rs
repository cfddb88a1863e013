//! Body boundaries from files and the errors a bad mesh or contact declaration gives.

use tether_test_support as common;

use approx::assert_relative_eq;
use std::path::Path;
use tether_physics::coupling::CouplingKind;
use tether_physics::water::hydrostatics::equilibrium_height;
use tether_scene as scene;

/// A scene in `tests/fixtures/` with one body of shape `shape`, resting at z = 2, in contact
/// with the ground.
fn with_shape(shape: &str) -> Result<scene::Scene, scene::SceneError> {
    let text = format!(
        "Scene(dt: 1e-4, bodies: [Body(name: \"m\", master: Node(position: (0.0, 0.0, 2.0), mass: 1.0, inertia: Inertia(xx: 0.2, yy: 0.2, zz: 0.2)), shape: {shape})],
         couplings: [Contact(name: \"ground\", body: \"m\", against: Plane(point: (0.0, 0.0, 0.0), normal: (0.0, 0.0, 1.0)), stiffness: 1e6)])"
    );
    scene::parse(&text, &common::here!("fixtures/scene.ron"))
}

fn boundary_area_and_volume(scene: &scene::Scene) -> (f64, f64) {
    let CouplingKind::Contact(contact) = &scene.world.couplings()[0].kind else { panic!("a contact") };
    (contact.boundary().area(), contact.boundary().volume())
}

#[test]
fn an_obj_cube_with_quads_loads_as_twelve_triangles_scaled() {
    let scene = with_shape("Mesh(file: \"cube.obj\", scale: 2.0)").unwrap_or_else(|e| panic!("{e}"));
    let (area, volume) = boundary_area_and_volume(&scene);
    assert_relative_eq!(area, 24.0, epsilon = 1e-12);
    assert_relative_eq!(volume, 8.0, epsilon = 1e-12);
}

/// The unit cube of `file` centred on G (a 400 kg point at the origin) floating in still water
/// of 1025 kg/m³ (the scene's default).
fn floating(file: &str) -> scene::Scene {
    let text = format!(
        "Scene(dt: 1e-3, water: Water(), bodies: [Body(name: \"m\", master: Node(position: (0.0, 0.0, 0.0), mass: 400.0, inertia: Inertia(xx: 60.0, yy: 70.0, zz: 80.0)),
             shape: Mesh(file: {file:?}, center: (-0.5, -0.5, -0.5)), hydro: Hydro())])"
    );
    scene::parse(&text, &common::here!("fixtures/scene.ron")).unwrap_or_else(|e| panic!("{e}"))
}

/// The one mesh policy: the inward-wound `cube_inward.stl` is turned over with one warning, the
/// same whether the body is in contact or in water; as a contact boundary it encloses the unit
/// cube, and as a hull it floats at the outward `cube.obj`'s draft, the closed form
/// `d = m/(ρ A_wp)` = 400/1025 m under a 1 m² waterplane (G, the centre, `½ − d` above the level).
#[test]
fn an_inward_wound_stl_cube_is_turned_outwards_with_one_warning_for_contact_and_for_water() {
    let shape = "Mesh(file: \"cube_inward.stl\", center: (-0.5, -0.5, -0.5))";
    let in_contact = with_shape(shape).unwrap_or_else(|e| panic!("{e}"));
    let (area, volume) = boundary_area_and_volume(&in_contact);
    assert_relative_eq!(area, 6.0, epsilon = 1e-12);
    assert_relative_eq!(volume, 1.0, epsilon = 1e-12);
    let in_water = floating("cube_inward.stl");
    let warning = "body \"m\": mesh file \"cube_inward.stl\": the mesh is wound inwards (its normals point into the body: signed volume -1.000000e0 m³); it was turned over to point outwards";
    assert_eq!(in_contact.warnings, [warning]);
    assert_eq!(in_water.warnings, [warning]);
    let outward = floating("cube.obj");
    assert!(outward.warnings.is_empty(), "{:?}", outward.warnings);
    let draft = 400.0 / 1025.0;
    for loaded in [&in_water, &outward] {
        let hull = &loaded.world.system().water().expect("water").floating[0].hull();
        assert_relative_eq!(hull.volume(), 1.0, epsilon = 1e-12);
        let turn = loaded.world.system().initial_states()[0].orientation.to_rotation_matrix().into_inner();
        let height = equilibrium_height(hull, &turn, 0.0, 0.0, 0.0, draft).expect("it floats");
        assert_relative_eq!(height, 0.5 - draft, epsilon = 1e-12);
    }
}

#[test]
fn the_shipped_fender_mesh_encloses_a_rounded_cylinder() {
    // r = 0.4 m, straight part 1.6 m: π r² 1.6 + 4/3 π r³ = 1.0723 m³ for the smooth shape; the
    // 24-sided mesh inscribed in it encloses 2 % less.
    let scene = scene::load(&common::repo("scenes/fender.ron")).unwrap_or_else(|e| panic!("{e}"));
    let CouplingKind::Contact(contact) = &scene.world.couplings()[2].kind else { panic!("the quay contact") };
    let volume = contact.boundary().volume();
    assert!(volume > 0.97 * 1.0723 && volume < 1.0723, "fender volume {volume}");
}

fn error(shape: &str) -> String {
    match with_shape(shape) {
        Ok(_) => panic!("{shape} must be refused"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn missing_unknown_and_degenerate_mesh_files_are_errors_at_the_file_name() {
    let missing = error("Mesh(file: \"nowhere.obj\")");
    assert!(missing.starts_with(&format!("{}:1:", common::here!("fixtures/scene.ron").display())), "{missing}");
    assert!(missing.contains("cannot read mesh file") && missing.contains("nowhere.obj"), "{missing}");
    // The column points at the file name.
    let column: usize = missing.split(':').nth(2).and_then(|c| c.parse().ok()).expect("path:line:col");
    let line = "Scene(dt: 1e-4, bodies: [Body(name: \"m\", master: Node(position: (0.0, 0.0, 2.0), mass: 1.0, inertia: Inertia(xx: 0.2, yy: 0.2, zz: 0.2)), shape: Mesh(file: \"nowhere.obj\")";
    assert_eq!(column, line.find("\"nowhere.obj\"").expect("in the text") + 1);
    assert!(error("Mesh(file: \"cube.ply\")").contains("must end in .obj or .stl"));
    assert!(error("Mesh(file: \"flat.obj\")").contains("zero area"));
    assert!(error("Mesh(file: \"scene.ron\")").contains("mesh file"));
    assert!(error("Mesh(file: \"cube.obj\", scale: 0.0)").contains("scale must be > 0"));
    assert!(error("Sphere(radius: 0.1, subdivisions: 9)").contains("subdivisions must be at most 6"));
    assert!(error("Box(size: (1.0, 1.0, 1.0), subdivisions: 0)").contains("subdivisions must be 1 to 64"));
}

fn contact_error(contact: &str) -> String {
    let text = format!(
        "Scene(dt: 1e-4, bodies: [
            Body(name: \"a\", master: Node(position: (0.0, 0.0, 1.0), mass: 1.0, inertia: Inertia(xx: 0.1, yy: 0.1, zz: 0.1)), shape: Sphere(radius: 0.1)),
            Body(name: \"b\", master: Node(position: (1.0, 0.0, 1.0), mass: 1.0, inertia: Inertia(xx: 0.1, yy: 0.1, zz: 0.1)), shape: Sphere(radius: 0.1))],
         couplings: [{contact}])"
    );
    match scene::parse(&text, Path::new("c.ron")) {
        Ok(_) => panic!("{contact} must be refused"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_contact_declarations_are_errors_naming_the_coupling() {
    let plane = "against: Plane(point: (0.0, 0.0, 0.0), normal: (0.0, 0.0, 1.0))";
    for (contact, expected) in [
        ("Contact(name: \"c\", body: \"a\", against: Body(\"a\"), stiffness: 1e6)".to_string(), "cannot be in contact with itself"),
        (format!("Contact(name: \"c\", body: \"z\", {plane}, stiffness: 1e6)"), "unknown body \"z\""),
        ("Contact(name: \"c\", body: \"a\", against: Body(\"y\"), stiffness: 1e6)".to_string(), "unknown body \"y\""),
        (format!("Contact(name: \"c\", body: \"a\", {plane}, stiffness: 0.0)"), "stiffness must be > 0"),
        (format!("Contact(name: \"c\", body: \"a\", {plane}, stiffness: 1e6, damping: -1.0)"), "damping must be ≥ 0"),
        (format!("Contact(name: \"c\", body: \"a\", {plane}, stiffness: 1e6, range: -0.1)"), "range must be ≥ 0"),
        (format!("Contact(name: \"c\", body: \"a\", {plane}, stiffness: 1e6, friction: -0.5)"), "friction must be ≥ 0"),
        (format!("Contact(name: \"c\", body: \"a\", {plane}, stiffness: 1e6, friction_sharpness: 0.0)"), "friction_sharpness must be > 0"),
        (format!("Contact(name: \"c\", body: \"a\", {plane}, stiffness: 1e6, expected_area: 0.0)"), "expected_area must be > 0"),
        ("Contact(name: \"c\", body: \"a\", against: Plane(point: (0.0, 0.0, 0.0), normal: (0.0, 0.0, 0.0)), stiffness: 1e6)".to_string(), "plane normal must not be zero"),
        ("Contact(name: \"c\", body: \"a\", against: DomainBox(min: (0.0, 0.0, 0.0), max: (1.0, -1.0, 1.0)), stiffness: 1e6)".to_string(), "must exceed min"),
    ] {
        let message = error_of(&contact_error(&contact));
        assert!(message.contains("coupling \"c\"") && message.contains(expected), "{contact}: {message}");
    }
}

/// The message after `path:line:col: `, checking the position is there.
fn error_of(full: &str) -> String {
    let mut parts = full.splitn(4, ':');
    let (path, line, col) = (
        parts.next(),
        parts.next().and_then(|l| l.parse::<usize>().ok()),
        parts.next().and_then(|c| c.parse::<usize>().ok()),
    );
    assert!(path == Some("c.ron") && line.is_some() && col.is_some(), "no position in {full}");
    parts.next().unwrap_or_default().to_string()
}
