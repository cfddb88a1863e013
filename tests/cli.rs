//! The `tether` command line, run as a user runs it.

mod common;

use approx::assert_relative_eq;
use std::process::{Command, Output};
use tether_physics::coupling::{Catenary, Endpoint};
use tether_physics::math::Vec3;

const G: f64 = 9.80665;

fn tether(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tether")).args(args).output().unwrap()
}

#[test]
fn check_passes_on_every_shipped_scene() {
    for file in common::scene_files() {
        let out = tether(&["check", file.to_str().unwrap()]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success(), "{}: {}", file.display(), String::from_utf8_lossy(&out.stderr));
        assert!(stdout.contains(": ok — ") && stdout.contains("initial energy"), "{stdout}");
    }
}

#[test]
fn check_prints_mass_properties_of_the_t_handle() {
    let out = tether(&["check", common::repo("scenes/t_handle.ron").to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("mass               4.000000 kg"), "{stdout}");
    assert!(stdout.contains("principal moments  (1.000000, 2.000000, 3.000000) kg·m²"), "{stdout}");
    // E = ½ (1·0.05² + 2·1²) = 1.00125 J.
    assert!(stdout.contains("kinetic 1.001250 J"), "{stdout}");
}

#[test]
fn a_bad_scene_exits_1_with_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.ron");
    std::fs::write(&path, "Scene(dt: -1.0, bodies: [])").unwrap();
    let out = tether(&["check", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.trim(), format!("error: {}:1:7: dt must be > 0 s, got -1", path.display()));
}

/// The one mesh policy reaches the user one way: `tether check` on the inward-wound cube as a
/// contact boundary and as a hull in water passes both times, with the same one warning on stderr.
#[test]
fn check_warns_alike_of_an_inward_mesh_in_contact_and_in_water() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(common::repo("crates/scene/tests/fixtures/cube_inward.stl"), dir.path().join("cube.stl")).unwrap();
    let body = "Body(name: \"m\", master: Node(position: (0.0, 0.0, 2.0), mass: 400.0, inertia: Inertia(xx: 60.0, yy: 70.0, zz: 80.0)),
        shape: Mesh(file: \"cube.stl\", center: (-0.5, -0.5, -0.5))";
    let in_contact = format!(
        "Scene(dt: 1e-4, bodies: [{body})], couplings: [Contact(name: \"ground\", body: \"m\",
            against: Plane(point: (0.0, 0.0, 0.0), normal: (0.0, 0.0, 1.0)), stiffness: 1e6)])"
    );
    let in_water = format!("Scene(dt: 1e-3, water: Water(), bodies: [{body}, hydro: Hydro())])");
    for (name, text) in [("contact.ron", in_contact), ("water.ron", in_water)] {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        let out = tether(&["check", path.to_str().unwrap()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{name}: {stderr}");
        assert_eq!(
            stderr.trim(),
            format!(
                "warning: {}: body \"m\": mesh file \"cube.stl\": the mesh is wound inwards (its normals point into the body: signed volume -1.000000e0 m³); it was turned over to point outwards",
                path.display()
            )
        );
    }
}

#[test]
fn record_refuses_bad_flags_and_unwritable_paths_before_running() {
    let scene = common::repo("scenes/spring_mass.ron");
    let scene = scene.to_str().unwrap();
    let out = tether(&["record", scene, "-o", "/tmp/x.rrd", "--duration=-1"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--duration must be > 0 s, got -1"));
    let out = tether(&["record", scene, "-o", "/tmp/x.rrd", "--log-hz", "0"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--log-hz must be > 0 Hz, got 0"));
    let out = tether(&["record", scene, "-o", "/no/such/dir/x.rrd"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("cannot write /no/such/dir/x.rrd"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Face arrows asked for a contact the scene does not have, or over a time span that ends
/// before it starts, are refused before anything is written, in one line naming what is wrong.
#[test]
fn record_refuses_face_arrows_of_unknown_contacts() {
    let dir = tempfile::tempdir().unwrap();
    let out_path = dir.path().join("x.rrd");
    let out_path = out_path.to_str().unwrap();
    let scene = common::repo("scenes/fender.ron");
    let scene = scene.to_str().unwrap();
    let out = tether(&["record", scene, "-o", out_path, "--face-arrows", "quay,pier"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.trim(), "error: no contact named \"pier\" to draw face arrows for (contacts: quay, hull)");
    let out = tether(&[
        "record",
        scene,
        "-o",
        out_path,
        "--face-arrows",
        "all",
        "--face-arrows-from",
        "3",
        "--face-arrows-until",
        "1",
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("--face-arrows-until (1 s) is before --face-arrows-from (3 s)"),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!std::path::Path::new(out_path).exists(), "nothing written");
}

/// One spring per elastic law, each from the world origin to a fixed body 1.2 m away on x:
/// the JSON forces are the closed forms.
#[test]
fn forces_json_gives_every_law_its_closed_form() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("laws.ron");
    let laws = [
        ("linear", "Linear(stiffness: 250.0, rest_length: 1.0)", 250.0 * 0.2),
        (
            "polynomial",
            "Polynomial(a: 100.0, b: 20.0, c: 4000.0, rest_length: 1.0)",
            100.0 * 0.2 + 20.0 * 0.04 + 4000.0 * 0.008,
        ),
        ("force_curve", "ForceCurve(points: [(0.5, -80.0), (1.0, 0.0), (1.4, 100.0)])", 50.0),
        // k = 100 + 400(ξ − 1) on [1, 1.5]: ∫_1^1.2 = 0.2·(100 + 180)/2 = 28.
        ("stiffness_curve", "StiffnessCurve(points: [(1.0, 100.0), (1.5, 300.0)], rest_length: 1.0)", 28.0),
        // f_r = 10 N at x_r = 1.1, plus ∫_1.1^1.2 = 0.1·(140 + 180)/2 = 16.
        (
            "reference_force",
            "ReferenceForce(points: [(1.0, 100.0), (1.5, 300.0)], reference_length: 1.1, reference_force: 10.0, rest_length: 3.0)",
            26.0,
        ),
    ];
    let couplings: Vec<String> = laws
        .iter()
        .map(|(name, law, _)| format!("SpringDamper(name: \"{name}\", end1: World((0.0, 0.0, 0.0)), end2: Body(body: \"b\"), law: {law}, damping: 7.0)"))
        .collect();
    std::fs::write(
        &path,
        format!(
            "Scene(dt: 0.001, bodies: [Body(name: \"b\", master: Node(position: (1.2, 0.0, 0.0), mass: 2.0, inertia: Inertia(xx: 1, yy: 1, zz: 1)),
              velocity: (0.5, 0.0, 0.0), support: Fixed(translation: (true, true, true), rotation: true), shape: Sphere(radius: 0.1))],
              couplings: [{}])",
            couplings.join(",\n")
        ),
    )
    .unwrap();
    let out = tether(&["forces", path.to_str().unwrap(), "--json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut total = 0.0;
    for (coupling, (name, _, elastic)) in json["couplings"].as_array().unwrap().iter().zip(&laws) {
        assert_eq!(coupling["name"], *name);
        assert_eq!(coupling["kind"], "spring_damper");
        // Fixed bodies do not move: the damper sees ẋ = 0 even with an initial velocity set.
        let tension = elastic;
        assert_relative_eq!(coupling["f1"][0].as_f64().unwrap(), *tension, max_relative = 1e-12);
        assert_relative_eq!(coupling["f2"][0].as_f64().unwrap(), -tension, max_relative = 1e-12);
        assert_eq!(coupling["f1"][1].as_f64().unwrap(), 0.0);
        total -= tension;
    }
    let body = &json["bodies"][0];
    assert_eq!(body["name"], "b");
    assert_relative_eq!(body["force"][0].as_f64().unwrap(), total, max_relative = 1e-12);
    assert_relative_eq!(body["force"][2].as_f64().unwrap(), -2.0 * 9.80665, max_relative = 1e-12);
    assert_eq!(body["moment"], serde_json::json!([0.0, 0.0, 0.0]));
}

#[test]
fn estimate_contact_prints_the_formulas_values() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_tether"))
        .args([
            "estimate-contact",
            "--mass",
            "1",
            "--area",
            "0.01",
            "--speed",
            "1",
            "--d0",
            "0.001",
            "--dmin",
            "-0.002",
            "--zeta",
            "0.1",
            "--dt",
            "0.002",
        ])
        .output()
        .expect("tether runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    // k1 = 1·1²/(0.01·0.003²) = 1.111111e7, k2 = 0.2·√(1·k1/0.01) = 6.666667e3, τ = (π/2)(0.003/1).
    for expected in
        ["k1  = 1.111111e7", "k2  = 6.666667e3", "τ   = 4.712389e-3", "τ/10 = 4.712389e-4", "substeps: Fixed(5)"]
    {
        assert!(text.contains(expected), "missing {expected:?} in\n{text}");
    }
    let refused = std::process::Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["estimate-contact", "--mass", "1", "--area", "0.01", "--speed", "1", "--d0", "0.001", "--dmin", "0.002"])
        .output()
        .expect("tether runs");
    assert_eq!(refused.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("must be below d0"));
}

/// `tether forces --json` gives a dynamic line's nodes (the static start MoorDyn's node positions
/// are compared with in validation/moordyn/files.py): N + 1 of them from end 1 to end 2, the
/// segments adding up to the line's length stretched by at most its largest tension over EA
/// (chain_forced_surge: 40 segments of 250 m, EA = 1.107e8 N, end tensions under 42 kN); a
/// quasi-static line has none.
#[test]
fn forces_json_gives_a_dynamic_lines_nodes() {
    let out = tether(&["forces", common::repo("scenes/chain_forced_surge.ron").to_str().unwrap(), "--json"]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let nodes: Vec<Vec3> = json["couplings"][0]["nodes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| Vec3::new(n[0].as_f64().unwrap(), n[1].as_f64().unwrap(), n[2].as_f64().unwrap()))
        .collect();
    assert_eq!(nodes.len(), 41);
    assert_eq!((nodes[0], nodes[40]), (Vec3::new(-237.0, 0.0, -50.0), Vec3::new(0.0, 0.0, -1.0)));
    let stretched: f64 = nodes.windows(2).map(|w| (w[1] - w[0]).norm()).sum();
    assert!(stretched > 250.0 * (1.0 - 1e-4) && stretched < 250.0 * (1.0 + 42.0e3 / 1.107e8), "{stretched}");
    let quasi_static = tether(&["forces", common::repo("scenes/sagging_chain.ron").to_str().unwrap(), "--json"]);
    let json: serde_json::Value = serde_json::from_slice(&quasi_static.stdout).unwrap();
    assert!(json["couplings"][0].get("nodes").is_none());
}

/// `tether forces --json` reports a catenary's horizontal tension and parameters u1, u2.
#[test]
fn forces_json_reports_the_catenary_solution() {
    let scene = common::repo("scenes/sagging_chain.ron");
    let out = tether(&["forces", scene.to_str().unwrap(), "--json"]);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let chain = &json["couplings"][0];
    assert_eq!(chain["name"], "chain");
    assert_eq!(chain["kind"], "catenary");
    // Ends (2, 0, 0) and (18, 0, 0): level, span 16 m, L = 30 m, λ0 = 20 kg/m, D = 1e6 N/m.
    let line = Catenary::new(Endpoint::World(Vec3::zeros()), Endpoint::World(Vec3::zeros()), 20.0, 30.0, 1e6)
        .expect("a valid line");
    let s = line
        .solve(
            &Vec3::new(2.0, 0.0, 0.0),
            &Vec3::new(18.0, 0.0, 0.0),
            &tether_physics::surroundings::Surroundings::dry(Vec3::new(0.0, 0.0, -G)),
            None,
        )
        .unwrap();
    let h = chain["horizontal_tension"].as_f64().unwrap();
    assert_relative_eq!(h, s.horizontal_tension, max_relative = 1e-12);
    let (u1, u2) = (chain["u1"].as_f64().unwrap(), chain["u2"].as_f64().unwrap());
    // Level ends: symmetric, u1 = −u2, and c (sinh u2 − sinh u1) = W.
    assert_relative_eq!(u1, -u2, max_relative = 1e-9);
    assert_relative_eq!(h * (u2.sinh() - u1.sinh()), 20.0 * G * 30.0, max_relative = 1e-9);
    let f1: Vec<f64> = chain["f1"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
    assert_relative_eq!(f1[0], h, max_relative = 1e-12);
    assert_relative_eq!(f1[2], h * u1.sinh(), max_relative = 1e-9);
}

/// `chain_forced_surge`'s chain as a quasi-static catenary: its first transverse period is
/// `2 (L − L_B) / √(T̄ / (λ0 + ρ A_d))` from the catenary's own state, 1.39 times shorter than the
/// fairlead's 10 s — and the drag at the fairlead's `2 · 2π/10` m/s on the 0.0648 m chain is
/// `½ · 1025 · 2.4 · 0.0648 · 1.2566² / (22.41 · g)` = 0.573 of its wet weight — so `tether check`
/// suggests `Dynamic`, with the numbers; driven at a tenth of the amplitude over 200 s it holds;
/// the dynamic line gets no hint.
#[test]
fn check_says_when_a_quasi_static_line_is_likely_wrong() {
    let text = std::fs::read_to_string(common::repo("scenes/chain_forced_surge.ron")).unwrap();
    let start = text.find("model: Dynamic(").unwrap();
    let end = start + text[start..].find("),\n        ),").unwrap() + 1;
    let quasi_static = format!("{}model: QuasiStatic{}", &text[..start], &text[end..]);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("chain_qs.ron");
    std::fs::write(&path, &quasi_static).unwrap();

    let scene = tether_scene::parse(&quasi_static, &path).unwrap();
    let state = scene.world.line_state(0).unwrap();
    let (t1, t2) = state.end_tensions();
    let speed = (0.5 * (t1 + t2) / (25.79 + 1025.0 * 0.003298)).sqrt();
    let period = 2.0 * (250.0 - state.grounded_length()) / speed;
    let measures = tether::line_hint::measures(&scene.world, 0).expect("a driven quasi-static line");
    assert_relative_eq!(measures.transverse_period, period, max_relative = 1e-12);
    assert!((7.0..7.5).contains(&period), "T₁ = {period} s");
    let wet_weight = (25.79 - 1025.0 * 0.003298) * scene.world.gravity().norm();
    let diameter = (4.0 * 0.003298 / std::f64::consts::PI).sqrt();
    let drag = 0.5 * 1025.0 * 2.4 * diameter * (0.4 * std::f64::consts::PI).powi(2) / wet_weight;
    assert_relative_eq!(measures.drag_ratio.unwrap(), drag, max_relative = 1e-12);
    assert_relative_eq!(drag, 0.5727, max_relative = 1e-3);
    assert!(measures.suggests_dynamic());
    let out = tether(&["check", path.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let hint = format!("hint: likely wrong quasi-static: try Dynamic: first transverse period T₁ = {period:.3} s");
    assert!(stdout.contains(&hint), "{stdout}");

    let slow = quasi_static.replace(
        "Harmonic(amplitude: (2.0, 0.0, 0.0), period: 10.0)",
        "Harmonic(amplitude: (0.2, 0.0, 0.0), period: 200.0)",
    );
    let slow = tether_scene::parse(&slow, &path).unwrap();
    let measures = tether::line_hint::measures(&slow.world, 0).unwrap();
    assert!(!measures.suggests_dynamic(), "{measures}");
    assert!(measures.to_string().starts_with("quasi-static holds"), "{measures}");

    let dynamic = tether(&["check", common::repo("scenes/chain_forced_surge.ron").to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&dynamic.stdout);
    assert!(!stdout.contains("transverse period"), "{stdout}");
}

/// Issue 32: `tether import` writes the commented RON scene, which loads to the same scene as
/// the MoorDyn file itself (`check` reads it directly), and prints the time the import and the
/// build took; `tether export moordyn` writes a file that imports back.
#[test]
fn import_and_export_moordyn_files() {
    let dir = tempfile::tempdir().unwrap();
    let source = common::repo("validation/moordyn/inputs/lines.txt");
    let scene = dir.path().join("lines.ron");
    let out = tether(&["import", source.to_str().unwrap(), "-o", scene.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("3 bodies, 3 lines → wrote") && stdout.contains("import and build"), "{stdout}");
    let imported = tether_scene::load(&scene).unwrap();
    let direct = tether_scene::load(&source).unwrap();
    assert_eq!(imported.file, direct.file);
    let checked = tether(&["check", source.to_str().unwrap()]);
    assert!(String::from_utf8_lossy(&checked.stdout).contains("lines.txt: ok — 3 bodies, 3 couplings"));
    let exported = dir.path().join("lines.dat");
    let out = tether(&["export", "moordyn", scene.to_str().unwrap(), "-o", exported.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let back = tether_scene::load(&exported).unwrap();
    assert_eq!(back.file.couplings.len(), 3);
    // A real v1 file (OpenFAST's layout of 2021, the IEA 15 MW semi): `check` prints it.
    let v1 = common::repo("validation/moordyn/inputs/IEA-15-240-RWT-UMaineSemi_MoorDyn_v1.dat");
    let checked = tether(&["check", v1.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&checked.stdout);
    assert!(checked.status.success() && stdout.contains("_v1.dat: ok — 3 bodies, 3 couplings"), "{stdout}");
}

/// Issue 32, check 6: a bad MoorDyn file is one line with its line and column, exit 1, and
/// `import` writes nothing.
#[test]
fn a_bad_moordyn_file_exits_1_with_one_line_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(common::repo("validation/moordyn/inputs/lines.txt")).unwrap();
    let bad = dir.path().join("bad.txt");
    std::fs::write(&bad, text.replace("1     main       1        4", "1     chain      1        4")).unwrap();
    let scene = dir.path().join("bad.ron");
    let out = tether(&["import", bad.to_str().unwrap(), "-o", scene.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        stderr.trim(),
        format!("error: {}:19:7: line 1: no line type \"chain\" (the file's types: main)", bad.display())
    );
    assert!(!scene.exists());
}

/// Issue 48: a MoorDyn file with its line type's EA set to 10³⁰⁸ — finite, so accepted by its
/// column, but making the line's BA infinite — was checked "ok" with `BA = inf N·s` and an axial
/// step of 0 s; `check` refuses it in one line at the line's row, exit 1, naming BA and the value
/// that made it.
#[test]
fn check_refuses_a_moordyn_file_whose_derived_values_overflow() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(common::repo("validation/moordyn/inputs/lines.txt")).unwrap();
    let bad = dir.path().join("bad.txt");
    std::fs::write(&bad, text.replacen("384.243E6", "1e308", 1)).unwrap();
    let out = tether(&["check", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(out.stdout.is_empty(), "{}", String::from_utf8_lossy(&out.stdout));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(
        stderr.trim(),
        format!(
            "error: {}:19:1: as imported: coupling \"line1\": BA = ζ l √(EA λ0) must be finite, got inf (from stiffness = 1.1084016847705608e305)",
            bad.display()
        )
    );
}

/// Runs `tether rao` on the cylinder fixture at the periods `2π/ω` of `omegas` and returns its
/// CSV rows (period, ω, then amplitude and phase per dof).
fn cylinder_rao(omegas: &[f64]) -> Vec<Vec<f64>> {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("rao.csv");
    let periods: Vec<String> = omegas.iter().map(|w| format!("{:e}", std::f64::consts::TAU / w)).collect();
    let out = tether(&[
        "rao",
        "tests/fixtures/rao/cylinder.ron",
        "--body",
        "cylinder",
        "--periods",
        &periods.join(","),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("heave [m/m]") && stdout.contains("pitch [deg/m]"), "{stdout}");
    let text = std::fs::read_to_string(&csv).unwrap();
    text.lines().skip(1).map(|line| line.split(',').map(|v| v.parse().unwrap()).collect()).collect()
}

/// `tether rao` prints the frequency-domain solve of the library, `potential::response`, from
/// the same files, the fixture's mass (Capytaine's, diagonal about G) and the mesh's stiffness
/// (its closed form checked in crates/physics/tests/potential_flow.rs): heave at T = 8 s to 1e-9.
#[test]
fn rao_prints_the_frequency_domain_solve() {
    let omega = std::f64::consts::TAU / 8.0;
    let row = &cylinder_rao(&[omega])[0];
    let loaded = tether_scene::load(std::path::Path::new("tests/fixtures/rao/cylinder.ron")).unwrap();
    let model = tether_physics::rao::LinearModel::new(loaded.world.system(), "cylinder").unwrap();
    let m = 1.7388715338e5;
    let mass = tether_physics::potential::Matrix6::from_diagonal(&tether_physics::potential::Vector6::new(
        m,
        m,
        m,
        9.1290755523e5,
        9.1290755523e5,
        7.8249219019e5,
    ));
    let xi = tether_physics::potential::response::response(model.coefficients(), &mass, model.stiffness(), omega, 0)
        .unwrap();
    println!("heave {} ∠{}° (CLI), {} ∠{}° (response)", row[6], row[7], xi[2].norm(), xi[2].arg().to_degrees());
    assert_relative_eq!(row[6], xi[2].norm(), max_relative = 1e-9);
    assert!((row[7] - xi[2].arg().to_degrees()).abs() < 1e-7);
}

/// Against Capytaine's own RAO of the same cylinder (`capytaine.post_pro.rao`,
/// validation/potential-flow/cylinder/cylinder_rao.csv, same mass, its stiffness 0.4 % above the
/// 32-sided mesh's): surge, heave and pitch within 3 % in amplitude and 3° in phase at six
/// frequencies from 0.3 to 2.5 rad/s (measured: 2.1 % at most, heave at 1 rad/s). Not at the
/// heave (1.1–1.15 rad/s) and pitch (1.3 rad/s) resonances, where the stiffness's 0.4 % moves the
/// peak (−7 % at 1.15, +3.1 % in surge at 1.25).
#[test]
fn rao_agrees_with_capytaines() {
    let text = std::fs::read_to_string("validation/potential-flow/cylinder/cylinder_rao.csv").unwrap();
    let capytaine: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("omega"))
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    let omegas = [0.3, 0.5, 0.8, 1.0, 1.6, 2.5];
    let rows = cylinder_rao(&omegas);
    for (omega, row) in omegas.iter().zip(&rows) {
        let theirs = capytaine.iter().find(|r| (r[0] - omega).abs() < 1e-9).unwrap();
        // (column in the CLI's CSV, column in Capytaine's, scale of the CLI's amplitude to theirs)
        for (name, ours, their, scale) in
            [("surge", 2, 1, 1.0), ("heave", 6, 3, 1.0), ("pitch", 10, 5, 1.0_f64.to_radians())]
        {
            let amplitude = row[ours] * scale / theirs[their] - 1.0;
            let phase = (row[ours + 1] - theirs[their + 1] + 540.0) % 360.0 - 180.0;
            println!("ω {omega}: {name} {:+.2} %, {phase:+.2}°", 100.0 * amplitude);
            assert!(amplitude.abs() < 0.03 && phase.abs() < 3.0, "ω {omega} {name}: {amplitude}, {phase}°");
        }
    }
}

/// An unknown body, a body without potential data and a scene without water: one line each.
#[test]
fn rao_refuses_what_has_no_rao_with_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let dry = dir.path().join("dry.ron");
    std::fs::write(
        &dry,
        "Scene(dt: 0.01, bodies: [Body(name: \"b\", master: Node(position: (0.0, 0.0, 0.0), mass: 1.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)), shape: Box(size: (1.0, 1.0, 1.0)))])",
    )
    .unwrap();
    let fixture = "tests/fixtures/rao/cylinder.ron";
    for (scene, body, expected) in [
        (fixture, "nobody", "no body named \"nobody\" (bodies: cylinder, block)"),
        (fixture, "block", "body \"block\" has no potential-flow data"),
        (dry.to_str().unwrap(), "b", "the scene has no water"),
    ] {
        let out = tether(&["rao", scene, "--body", body]);
        assert_eq!(out.status.code(), Some(1));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
        assert!(stderr.contains(scene) && stderr.contains(expected), "{stderr}");
    }
}

/// Issue 33: `tether rao --time-domain` measures the RAOs from regular-wave runs of the scene
/// (0.05 m waves ramped over 60 s, fitted over the end of 300 s) and prints them beside the
/// frequency-domain solve: on the cylinder at rest (validation/potential-flow/cylinder.ron) at
/// 4, 8 and 17 s, surge, heave and pitch agree within 2 % in amplitude and 3° in phase
/// (measured: 1.50 % and 0.36° at most, surge at 4 s); the CSV carries both.
#[test]
fn rao_time_domain_agrees_with_the_frequency_domain_solve() {
    let dir = tempfile::tempdir().unwrap();
    let csv = dir.path().join("rao.csv");
    let scene = "validation/potential-flow/cylinder.ron";
    let args = ["rao", scene, "--body", "cylinder", "--time-domain", "--periods", "4,8,17", "--csv"];
    let out = tether(&[&args[..], &[csv.to_str().unwrap()]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("time − frequency") && stdout.contains("largest differences"), "{stdout}");
    assert!(out.stderr.is_empty(), "at rest, no warning: {}", String::from_utf8_lossy(&out.stderr));
    let text = std::fs::read_to_string(&csv).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    assert_eq!(header.len(), 26, "{header:?}");
    let rows: Vec<Vec<f64>> =
        text.lines().skip(1).map(|line| line.split(',').map(|v| v.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), 3);
    for row in &rows {
        // (name, column of the frequency domain's amplitude; the time domain's is 12 further)
        for (name, column) in [("surge", 2), ("heave", 6), ("pitch", 10)] {
            assert_eq!(header[column + 12], header[column].replacen('_', "_td_", 1));
            let (fd, td) = ((row[column], row[column + 1]), (row[column + 12], row[column + 13]));
            let amplitude = td.0 / fd.0 - 1.0;
            let phase = (td.1 - fd.1 + 540.0) % 360.0 - 180.0;
            println!("T = {} s {name}: time domain {:+.2} %, {phase:+.2}°", row[0], 100.0 * amplitude);
            assert!(amplitude.abs() < 0.02 && phase.abs() < 3.0, "T = {} s {name}: {amplitude}, {phase}°", row[0]);
        }
    }
}

/// `tether rao --plot` draws the RAOs it prints: a PNG, the cylinder's surge, heave and pitch
/// drawn with the same amplitudes and phases as the solve (`rao_chart::Responses`, sorted by
/// period) and its sway, roll and yaw in head seas left out and named; a phase that wraps is cut
/// there rather than drawn across the chart.
#[test]
fn rao_plot_draws_the_responses_and_names_what_it_leaves_out() {
    use tether_analysis::rao_chart::{Responses, polar, unwrapped_pieces};
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("rao.png");
    let fixture = "tests/fixtures/rao/cylinder.ron";
    let out = tether(&["rao", fixture, "--body", "cylinder", "--periods", "8,4,17", "--plot", png.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("rao.png (sway, roll, yaw left out: below 1e-3 of their kind's largest)"), "{stdout}");
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert!(bytes.len() > 20_000, "a chart with text and curves: {} bytes", bytes.len());

    let loaded = tether_scene::load(std::path::Path::new(fixture)).unwrap();
    let model = tether_physics::rao::LinearModel::new(loaded.world.system(), "cylinder").unwrap();
    let omegas: Vec<f64> = [8.0, 4.0, 17.0].iter().map(|t| std::f64::consts::TAU / t).collect();
    let rows = model.rao(&omegas, 0);
    let responses = Responses::new(&rows, None);
    assert_eq!(responses.omitted, [1, 3, 5]);
    assert_eq!(responses.drawn.iter().map(|c| c.dof).collect::<Vec<_>>(), [0, 2, 4]);
    let printed = cylinder_rao(&omegas);
    for curve in &responses.drawn {
        let periods: Vec<f64> = curve.frequency_domain.iter().map(|p| p.0).collect();
        for (period, expected) in periods.iter().zip([4.0, 8.0, 17.0]) {
            assert_relative_eq!(*period, expected, max_relative = 1e-12);
        }
        assert!(curve.time_domain.is_empty());
        for &(period, amplitude, phase) in &curve.frequency_domain {
            let row = printed.iter().find(|r| (r[0] - period).abs() < 1e-9).unwrap();
            assert_relative_eq!(amplitude, row[2 + 2 * curve.dof], max_relative = 1e-9);
            assert_relative_eq!(phase, row[3 + 2 * curve.dof], epsilon = 1e-7);
            let xi = rows.iter().find(|r| (std::f64::consts::TAU / r.omega - period).abs() < 1e-9).unwrap();
            assert_eq!(polar(&xi.response.unwrap())[curve.dof], (amplitude, phase));
        }
    }
    let wrapping = [(1.0, 170.0), (2.0, 178.0), (3.0, -175.0), (4.0, -160.0), (5.0, 10.0)];
    assert_eq!(unwrapped_pieces(&wrapping), [vec![(1.0, 170.0), (2.0, 178.0)], wrapping[2..].to_vec()]);
}

/// Bad `--time-domain` settings are one line each before any run: a run too short for its
/// period, a zero amplitude, a run setting without `--time-domain`, a zero period; a run that
/// diverges (the cylinder held by a spring whose stable step is 1.2 ms, run at 20 ms) names its
/// period.
#[test]
fn rao_time_domain_refuses_bad_settings_and_names_a_diverging_period() {
    let scene = "validation/potential-flow/cylinder.ron";
    let dir = tempfile::tempdir().unwrap();
    let stiff = dir.path().join("stiff.ron");
    let file = common::repo("validation/potential-flow/cylinder/cylinder");
    let text = std::fs::read_to_string(scene).unwrap().replace("\"cylinder/cylinder\"", &format!("{file:?}")).replace(
        "couplings: [],",
        "couplings: [SpringDamper(name: \"stiff\", end1: World((-10.0, 0.0, -4.0)), end2: Body(body: \"cylinder\"),
            law: Linear(stiffness: 1e12, rest_length: 10.0))],",
    );
    std::fs::write(&stiff, text).unwrap();
    let stiff = stiff.to_str().unwrap();
    for (scene, flags, expected) in [
        (
            scene,
            &["--time-domain", "--periods", "30", "--duration", "100"][..],
            "--time-domain: a run of 100 s is too short for T = 30 s: it needs the ramp (60 s) and then max(3 T, 40 s) = 90 s to fit, 150 s in all",
        ),
        (scene, &["--time-domain", "--amplitude", "0"], "--time-domain: amplitude must be > 0 m, got 0"),
        (scene, &["--ramp", "10"], "--ramp sets the regular-wave runs: it needs --time-domain"),
        (scene, &["--time-domain", "--periods", "8,0"], "--periods must be > 0 s, got 0"),
        (stiff, &["--time-domain", "--periods", "8"], "the run at T = 8.000 s: the simulation diverged at t = "),
    ] {
        let out = tether(&[&["rao", scene, "--body", "cylinder"][..], flags].concat());
        assert_eq!(out.status.code(), Some(1), "{flags:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
        assert!(stderr.contains(expected), "{flags:?}: {stderr}");
        assert!(out.stdout.is_empty(), "{flags:?}: nothing printed before the error");
    }
}

/// Issue 33: `tether check` prints each potential-flow body's radiation model. The state space
/// (validation/potential-flow/cylinder.ron, the default fit): what it was fitted to (the
/// kernel's spectrum over the file's band, 0 to 5 rad/s), its total states, the sum of its
/// pairs' as the library fitted them, and its worst pair's error, the library's to the printed
/// digits and below the scene's `fit_error`; each pair on its own. The direct convolution: its
/// kernel's length and step and the samples summed per evaluation, `t_K/Δt + 1`.
#[test]
fn check_prints_the_radiation_fit_of_each_potential_flow_body() {
    let scene = "validation/potential-flow/cylinder.ron";
    let out = tether(&["check", scene]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let loaded = tether_scene::load(std::path::Path::new(scene)).unwrap();
    let stage = loaded.world.system().water().unwrap();
    let model = &stage.floating[0].potential().as_ref().unwrap().model();
    let tether_physics::potential::Radiation::StateSpace(fit) = model.radiation() else { panic!("the default method") };
    // The A∞ the time domain's mass holds (PHYSICS.md §9): the cylinder's pitch and surge shifted
    // by the band's damping tail, its heave not.
    let consistency = model.band_consistency();
    let shifts = consistency.relative_shift(model.coefficients().added_mass_infinite());
    assert!(!model.infinite_is_the_files() && shifts[4] > 0.02 && shifts[2] < 1e-3, "{shifts:?}");
    let infinite = format!(
        "  A∞: made consistent with the band (the largest change from the file's per dof: surge {:.2} %, sway {:.2} %, heave {:.2} %, roll {:.2} %, pitch {:.2} %, yaw {:.2} %); the time domain's added mass within {:.2} % of the file's A(ω) (was {:.2} %)",
        100.0 * shifts[0],
        100.0 * shifts[1],
        100.0 * shifts[2],
        100.0 * shifts[3],
        100.0 * shifts[4],
        100.0 * shifts[5],
        100.0 * consistency.misfit_consistent.max(),
        100.0 * consistency.misfit_file.max()
    );
    assert!(stdout.contains(&infinite), "{infinite} in {stdout}");
    let line = stdout.lines().find(|l| l.contains("radiation: state space")).unwrap_or_else(|| panic!("{stdout}"));
    println!("{line}");
    let fitted_to =
        "fitted to the spectrum B(ω) + iω(A(ω) − A∞) of K(t) (over 60 s every 0.05 s) from 0 to 5.0000 rad/s";
    assert!(line.contains(fitted_to) && (fit.band() - 5.0).abs() < 1e-6, "{line}");
    // "…: N states over P pairs, worst error E (Kij) (…); fit_error F, max_order M"
    let number_before = |tag: &str| -> f64 {
        let head = &line[..line.find(tag).unwrap_or_else(|| panic!("{tag:?} in {line}"))];
        head.split_whitespace().last().unwrap().trim_end_matches(',').parse().unwrap()
    };
    let number_after = |tag: &str| -> f64 {
        let tail = &line[line.find(tag).unwrap_or_else(|| panic!("{tag:?} in {line}")) + tag.len()..];
        tail.split_whitespace().next().unwrap().trim_end_matches([',', ';']).parse().unwrap()
    };
    let states: usize = fit.pairs().iter().map(|p| p.states()).sum();
    let worst = fit.pairs().iter().map(|p| p.error).fold(0.0, f64::max);
    assert_eq!(number_before(" states over") as usize, states);
    assert_eq!(number_before(" pairs,") as usize, fit.pairs().len());
    assert_relative_eq!(number_after("worst error "), worst, max_relative = 1e-3);
    let fit_error = number_after("fit_error ");
    assert_eq!(fit_error, 1e-2, "the scene's default");
    assert!(number_after("worst error ") < fit_error);
    for pair in fit.pairs() {
        let printed = format!("K{}{} {:>2} states {:.2e}", pair.i + 1, pair.j + 1, pair.states(), pair.error);
        assert!(stdout.contains(&printed), "{printed} in {stdout}");
    }
    // The same body by direct convolution.
    let dir = tempfile::tempdir().unwrap();
    let convolution = dir.path().join("convolution.ron");
    let file = common::repo("validation/potential-flow/cylinder/cylinder");
    let text = std::fs::read_to_string(scene).unwrap().replace(
        "file: \"cylinder/cylinder\"",
        &format!("file: {file:?}, radiation: Convolution, kernel_duration: 30.0"),
    );
    std::fs::write(&convolution, text).unwrap();
    let out = tether(&["check", convolution.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains(
            "radiation: direct convolution with K(t) sampled over 30 s every 0.05 s: about 1501 velocity samples"
        ),
        "{stdout}"
    );
    // Which hydrostatics run: the mesh's by default, the .hst's (its C33, C44, C55 as read) when
    // the scene asks for them.
    assert!(stdout.contains("hydrostatics: the still water's pressure on the mesh at its actual pose"), "{stdout}");
    let linear = dir.path().join("linear.ron");
    let text = std::fs::read_to_string(scene)
        .unwrap()
        .replace("file: \"cylinder/cylinder\"", &format!("file: {file:?}, hydrostatics: Linear"));
    std::fs::write(&linear, text).unwrap();
    let out = tether(&["check", linear.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    let c = *tether_scene::load(&linear).unwrap().world.system().water().unwrap().floating[0]
        .potential()
        .as_ref()
        .unwrap()
        .model()
        .coefficients()
        .hydrostatic_stiffness()
        .unwrap();
    let printed = format!(
        "hydrostatics: linear from the .hst, about the reference point and the pose at t = 0: C33 {:.6e} N/m, C44 {:.6e} N·m/rad, C55 {:.6e} N·m/rad",
        c[(2, 2)],
        c[(3, 3)],
        c[(4, 4)]
    );
    assert!(stdout.contains(&printed), "{printed} in {stdout}");
}

/// A body not at rest at t = 0 is warned of, with the force left on it: the tests' fixture
/// carries Capytaine's mass ρπR²T, heavier than the 32-sided mesh displaces at the 6 m draft by
/// `ρ T (π R² − 16 R² sin(π/16))` = 1115.2 kg, 10 936 N (0.64 % of its weight), to 1 N.
#[test]
fn rao_warns_when_the_body_is_not_at_rest() {
    let out = tether(&["rao", "tests/fixtures/rao/cylinder.ron", "--body", "cylinder", "--periods", "8"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stderr = String::from_utf8_lossy(&out.stderr);
    let (rho, g, radius, draft) = (1025.0, 9.80665, 3.0, 6.0);
    let excess = rho
        * draft
        * (std::f64::consts::PI * radius * radius - 16.0 * radius * radius * (std::f64::consts::PI / 16.0).sin());
    let expected = excess * g;
    let printed: f64 = stderr
        .split(" leave ")
        .nth(1)
        .and_then(|tail| tail.split(" N on it").next())
        .unwrap_or_else(|| panic!("{stderr}"))
        .parse()
        .unwrap();
    println!("{stderr}expected {expected:.1} N");
    assert!(stderr.starts_with("warning: tests/fixtures/rao/cylinder.ron: body \"cylinder\" is not at rest at t = 0"));
    assert!((printed - expected).abs() < 1.0, "{printed} vs {expected}");
}

/// `tether rao --natural-periods` on OC3-Hywind: each printed mode is the library's
/// (`natural_periods::at_equilibrium`, to the printed 1e-3 s), and the pitch period with `A∞` is
/// within 1.5 % of the published 29.15 s (the eigenanalysis the definition reports; measured
/// +0.81 %, docs/oc3-hywind.md).
#[test]
fn rao_prints_the_natural_periods_at_the_equilibrium() {
    use tether_physics::natural_periods::{AddedMassAt, at_equilibrium};
    use tether_physics::statics::{Settings, equilibrium};
    let out = tether(&["rao", "scenes/oc3_hywind.ron", "--body", "spar", "--periods", "30", "--natural-periods"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let scene = tether_scene::load(&common::repo("scenes/oc3_hywind.ron")).unwrap();
    let system = scene.world.system();
    let solved = equilibrium::solve(system, system.initial_states(), &[], &Settings::default()).unwrap();
    let modes = |added| at_equilibrium(system, &solved, 0, added).expect("potential flow");
    let (resonant, infinite) = (modes(AddedMassAt::Resonance), modes(AddedMassAt::Infinite));
    let rows: Vec<Vec<&str>> =
        stdout.lines().skip_while(|l| !l.starts_with("mode")).skip(1).map(|l| l.split_whitespace().collect()).collect();
    println!("{stdout}");
    assert_eq!(rows.len(), resonant.len(), "one row per mode");
    for (row, mode) in rows.iter().zip(&resonant) {
        let printed: f64 = row[1].parse().unwrap();
        assert!((printed - mode.period).abs() <= 5e-4, "{row:?} against {mode:?}");
    }
    let pitch = rows.iter().find(|r| r[0] == "pitch").expect("a pitch mode");
    let with_infinite: f64 = pitch[2].parse().unwrap();
    let library = infinite.iter().find(|m| m.dominant == 4).expect("pitch with A∞").period;
    assert!((with_infinite - library).abs() <= 5e-4, "{with_infinite} against {library}");
    assert!((with_infinite / 29.155 - 1.0).abs() < 0.015, "{with_infinite}");
}

/// Issue 47: the scene the window opens by default is right by its own hint — no line of it is
/// a quasi-static one the hint says is likely wrong (its chains are dynamic) — while the same
/// buoy on catenaries, `moored_buoy`, is flagged on every chain (T₁ ≈ 9.4 s against the wave's
/// 8 s), which is why the default is the dynamic one.
#[test]
fn the_default_scene_is_right_by_its_own_line_hint() {
    let flagged = |scene: &str| {
        let world = tether_scene::load(&common::repo(scene)).unwrap().world;
        (0..world.couplings().len())
            .filter(|&index| tether::line_hint::measures(&world, index).is_some_and(|m| m.suggests_dynamic()))
            .count()
    };
    let help = String::from_utf8_lossy(&tether(&["gui", "--help"]).stdout).into_owned();
    assert!(help.contains("default: scenes/buoy_on_dynamic_chains.ron"), "{help}");
    assert_eq!(flagged("scenes/buoy_on_dynamic_chains.ron"), 0, "the default scene flags nothing");
    assert_eq!(flagged("scenes/moored_buoy.ron"), 3, "the quasi-static buoy flags its three chains");
}
