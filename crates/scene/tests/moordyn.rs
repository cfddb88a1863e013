//! MoorDyn input files in and out (issue 32; docs/moordyn-files.md): MoorDyn's own files import
//! or are refused in one line, the mapping's numbers, OpenFAST's v1 layout, the free point's
//! closed form, bad input at its line, and export → import giving back the same lines.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use tether_physics::coupling::lumped_line::discrete::{STEEL_DENSITY, bearing_diameter};
use tether_physics::coupling::{InternalDamping, LumpedMassSpec};
use tether_physics::statics::{Settings, equilibrium};
use tether_scene::file::{CouplingDef, EndDef, SceneFile, SupportDef};
use tether_scene::line_model::LineModelDef;
use tether_scene::moordyn::{self, export};
use tether_scene::{Scene, SceneError};
use tether_test_support::{here, repo, scene_files};

fn input(name: &str) -> PathBuf {
    repo("validation/moordyn/inputs").join(name)
}

fn load(path: &Path) -> Result<Scene, SceneError> {
    tether_scene::load(path)
}

fn import_text(text: &str, label: &str) -> Result<Scene, String> {
    moordyn::load(text, Path::new(label)).map_err(|e| e.to_string())
}

/// The one-line error of a file that must be refused.
fn refusal(text: &str, label: &str) -> String {
    match import_text(text, label) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(error) => error,
    }
}

/// What a kept file gives: (bodies, lines) of its scene, or the start of its one-line refusal.
type Outcome = Result<(usize, usize), &'static str>;

/// Check 1: each file kept from MoorDyn's repository imports, or is refused with the one line
/// that names what Tether does not model, at its line.
#[test]
fn moordyns_own_files_import_or_are_refused_in_one_line() {
    let outcomes: [(&str, Outcome); 19] = [
        ("IEA-15-240-RWT-UMaineSemi_MoorDyn_v1.dat", Ok((3, 3))),
        ("WD0050_Chain.txt", Ok((1, 1))),
        ("WD0200_Chain.txt", Ok((1, 1))),
        ("lines.txt", Ok((3, 3))),
        ("example_lines.txt", Ok((3, 3))),
        ("example_body.txt", Ok((1, 3))),
        ("body_tests_bodyDrag.txt", Ok((1, 1))),
        ("pendulum.txt", Ok((1, 1))),
        ("time_schemes.txt", Ok((1, 1))),
        ("lifting.txt", Ok((1, 1))),
        ("polyester_simple.txt", Ok((1, 1))),
        ("local_euler_hanging.txt", Ok((3, 2))),
        (
            "tripod.txt",
            Err("tripod.txt:44:1: line 1: bending stiffness EI = 93212594.98 N·m² of type \"nodeFloat\" acts over"),
        ),
        (
            "seafloor.txt",
            Err("seafloor.txt:23:1: option Mooring/3D_seafloor/seafloor_profile_3d.txt SeafloorFile: a 3-D seafloor"),
        ),
        ("wavekin_wave_1.txt", Err("wavekin_wave_1.txt:28:1: option 1 WaveKin: wave kinematics")),
        ("wavekin_current_1.txt", Err("wavekin_current_1.txt:28:1: option 1 WaveKin: wave kinematics")),
        ("BodiesAndRods.dat", Err("BodiesAndRods.dat:19:1: rods are not modelled by Tether")),
        ("body_tests_pinnedBody.txt", Err("body_tests_pinnedBody.txt:17:1: rods are not modelled by Tether")),
        ("body_tests_orbitalBody.txt", Err("body_tests_orbitalBody.txt:20:1: rods are not modelled by Tether")),
    ];
    for (name, expected) in outcomes {
        match (load(&input(name)), expected) {
            (Ok(scene), Ok((bodies, lines))) => {
                assert_eq!((scene.world.bodies().len(), scene.world.couplings().len()), (bodies, lines), "{name}");
            }
            (Err(error), Err(start)) => {
                let line = error.to_string();
                assert!(line.contains(start) && !line.contains('\n'), "{name}: {line}");
            }
            (Ok(_), Err(start)) => panic!("{name} imported, expected {start}"),
            (Err(error), Ok(_)) => panic!("{name}: {error}"),
        }
    }
}

fn catenary(file: &SceneFile, index: usize) -> (&EndDef, &EndDef, f64, f64, f64, f64, LineModelDef) {
    match &file.couplings[index] {
        CouplingDef::Catenary { end1, end2, mass_per_length, length, stiffness, displaced_area, model, .. } => {
            (end1, end2, *mass_per_length, *length, *stiffness, *displaced_area, *model)
        }
        other => panic!("not a line: {other:?}"),
    }
}

/// The OC3-Hywind file: each line a dynamic catenary with the file's numbers (D = EA/L,
/// A_d = π d²/4), Fixed points world ends, Vessel points kinematic bodies at rest.
#[test]
fn oc3_lines_become_dynamic_catenaries_with_the_files_values() {
    let scene = load(&input("lines.txt")).unwrap();
    let (end1, end2, lambda, length, stiffness, area, model) = catenary(&scene.file, 0);
    assert_eq!(end1, &EndDef::World([853.87, 0.0, -320.0]));
    assert_eq!(end2, &EndDef::Body { body: "point4".into(), point: [0.0; 3] });
    assert_eq!((lambda, length), (77.7066, 902.2));
    assert_eq!(stiffness, 384.243e6 / 902.2);
    assert_eq!(area, PI * 0.09 * 0.09 / 4.0);
    assert_eq!(
        model,
        LineModelDef::Dynamic(LumpedMassSpec {
            segments: 20,
            damping: InternalDamping::Ratio(0.8),
            drag_normal: 1.6,
            drag_tangential: 0.1,
            added_mass_normal: 1.0,
            added_mass_tangential: 0.0,
            seabed_stiffness: 3.0e6,
            seabed_damping: 3.0e5,
            friction_speed: 0.01,
        })
    );
    let fairlead = &scene.file.bodies[0];
    assert_eq!(fairlead.master.position, [5.2, 0.0, -70.0]);
    assert!(matches!(fairlead.support, SupportDef::Kinematic { .. }));
    let water = scene.file.water.as_ref().unwrap();
    assert_eq!((water.density, water.depth), (1025.0, Some(320.0)));
    // The source file is named in the opening comment, the line type kept as a comment.
    assert!(scene.text.starts_with("// Imported by `tether import` from the MoorDyn input file lines.txt."));
    assert!(scene.text.contains("//   main: Diam 0.09 m, Mass/m 77.7066 kg/m, EA 384243000 N, BA/-zeta -0.8"));
    assert!(scene.text.contains(
        "// line 1: type \"main\", 902.2 m, 20 segments, from point 1 (Fixed) to point 4 (Coupled) (file line 19)"
    ));
}

/// OpenFAST's v1 layout (LINE DICTIONARY with Can Cat Cdn Cdt, NODE PROPERTIES with forces,
/// LINE PROPERTIES with the ends after the length, count lines, Echo) reads as the v2 file.
#[test]
fn openfast_v1_file_reads_as_the_same_system_as_v2() {
    let v1 = load(&here!("fixtures/moordyn/oc3_v1.dat")).unwrap();
    let v2 = load(&input("lines.txt")).unwrap();
    assert_eq!(v1.file.couplings, v2.file.couplings);
    assert_eq!(v1.file.bodies, v2.file.bodies);
}

/// A real v1 file: the IEA 15 MW reference turbine's UMaine VolturnUS-S mooring as its
/// repository kept it in 2021 (validation/moordyn/inputs/SOURCES.md): `LINE TYPES` with a count
/// line and v1's columns (Can Cat Cdn Cdt, no EI), `CONNECTION PROPERTIES` with forces, `LINE
/// PROPERTIES` with the ends after the length. Each line gets the file's numbers in v1's order.
#[test]
fn the_iea_15_mw_semis_v1_file_imports_with_its_columns_in_v1_order() {
    let scene = load(&input("IEA-15-240-RWT-UMaineSemi_MoorDyn_v1.dat")).unwrap();
    assert_eq!((scene.world.bodies().len(), scene.world.couplings().len()), (3, 3));
    let (end1, end2, lambda, length, stiffness, area, model) = catenary(&scene.file, 0);
    // Line 1: NodeAnch 2 (Fixed at −837.6, 0, −200), NodeFair 1 (Vessel).
    assert_eq!(end1, &EndDef::World([-837.6, 0.0, -200.0]));
    assert_eq!(end2, &EndDef::Body { body: "point1".into(), point: [0.0; 3] });
    assert_eq!((lambda, length, stiffness, area), (685.0, 850.0, 3.27e9 / 850.0, PI * 0.333 * 0.333 / 4.0));
    let LineModelDef::Dynamic(line) = model else { panic!("{model:?}") };
    // main 0.333 685.00 3.27E+09 -1 | Can 0.82 Cat 0.27 Cdn 1.11 Cdt 0.20.
    assert_eq!(line.segments, 50);
    assert_eq!(line.damping, InternalDamping::Ratio(1.0));
    assert_eq!(
        (line.added_mass_normal, line.added_mass_tangential, line.drag_normal, line.drag_tangential),
        (0.82, 0.27, 1.11, 0.20)
    );
    assert_eq!(scene.file.water.as_ref().unwrap().depth, Some(200.0));
    // Its v2 transcription, which MoorDyn 2.7.2 runs in validation/moordyn/files.py (MoorDyn
    // refuses v1's 9-column types), is the same system.
    let as_v2 = load(&input("IEA-15-240-RWT-UMaineSemi_MoorDyn_v1_as_v2.dat")).unwrap();
    assert_eq!((&as_v2.file.couplings, &as_v2.file.bodies), (&scene.file.couplings, &scene.file.bodies));
}

/// MoorDyn's seabed friction below its Coulomb limit is the damper `μ CV |v_h|` per node
/// (FricDamp CV, 200 N·s/m by default); the import gives each line the friction speed
/// `v_s = w l / CV` at which Tether's `μ F_n tanh(|v_h|/v_s)` has that slope on a node resting
/// under its own wet weight `F_n = w l`. WD0050's chain: d 0.252 m, 390 kg/m, 410 m in 41
/// segments, ρ 1025, g 9.80665 (the file's defaults): v_s = 166.16 m/s.
#[test]
fn moordyns_friction_damping_sets_each_lines_friction_speed() {
    let scene = load(&input("WD0050_Chain.txt")).unwrap();
    let (.., model) = catenary(&scene.file, 0);
    let LineModelDef::Dynamic(line) = model else { panic!("{model:?}") };
    let wet = (390.0 - 1025.0 * PI * 0.252 * 0.252 / 4.0) * 9.80665;
    let expected = wet * 10.0 / 200.0;
    assert!((line.friction_speed - expected).abs() < 1e-12 * expected, "{} against {expected}", line.friction_speed);
    assert!((line.friction_speed - 166.16).abs() < 0.01, "{}", line.friction_speed);
    assert!(scene.text.contains("FrictionCoefficient 0.5, FricDamp 200 N·s/m (each line's friction_speed)."));
    assert_eq!(scene.file.seabed.as_ref().unwrap().line_friction, 0.5);
    // FricDamp 0: MoorDyn's friction is nil, and so is the import's.
    let text = std::fs::read_to_string(input("WD0050_Chain.txt")).unwrap();
    let without = import_text(
        &text.replace("0.5                  FrictionCoefficient", "0.5 FrictionCoefficient\n0 FricDamp"),
        "f.txt",
    )
    .unwrap();
    assert_eq!(without.file.seabed.as_ref().unwrap().line_friction, 0.0);
    // A static to dynamic ratio other than 1 is named with its line (Tether's friction has one).
    let scaled = import_text(
        &text.replace("0.5                  FrictionCoefficient", "0.5 FrictionCoefficient\n2 StatDynFricScale"),
        "f.txt",
    )
    .unwrap();
    assert!(
        scaled.text.contains("(file line 28): option 2 StatDynFricScale: Tether's seabed friction has one coefficient"),
        "{}",
        scaled.text
    );
    // A file without friction keeps the default friction speed (it does not matter there).
    let frictionless = load(&input("WD0050_Chain_frictionless.txt")).unwrap();
    let (.., model) = catenary(&frictionless.file, 0);
    assert_eq!(model, LineModelDef::Dynamic(LumpedMassSpec { friction_speed: LumpedMassSpec::FRICTION_SPEED, ..line }));
}

/// The export writes the `FricDamp` that gives its first line its friction speed, `CV = w l /
/// v_s`, and a `dtM` within the time that damper takes to stop a node, `λ0 l / (μ CV) = λ0 v_s /
/// (μ w)`, beyond which MoorDyn's capped friction chatters
/// (validation/moordyn/friction_step.py): spread_moored_barge's chains (λ0 114.94 kg/m, A_d
/// 0.014698 m², 300 m in 20 segments, μ = 1, v_s = 0.01 m/s) give CV = 1.46915e6 N·s/m (g
/// 9.80665) and a limit of 1.17 ms, under the axial wave's half crossing (1.9 ms).
#[test]
fn the_export_writes_the_friction_damping_and_a_step_it_stays_stable_at() {
    let path = repo("scenes/spread_moored_barge.ron");
    let scene = load(&path).unwrap();
    let text = export::export(&scene.file, scene.bodies.bodies(), "barge", 20);
    let option = |name: &str| -> f64 {
        let row = text.lines().find(|row| row.split_whitespace().nth(1) == Some(name)).unwrap();
        row.split_whitespace().next().unwrap().parse().unwrap()
    };
    let area = PI * bearing_diameter(0.014698, 114.94).powi(2) / 4.0;
    let wet = (114.94 - 1025.0 * area) * 9.80665;
    let damping = option("FricDamp");
    assert!((damping - wet * 15.0 / 0.01).abs() < 1e-9 * damping, "FricDamp {damping}");
    assert!((damping - 1.46915e6).abs() < 10.0, "FricDamp {damping}");
    let limit = 114.94 * 15.0 / (option("FrictionCoefficient") * damping);
    let step = option("dtM");
    assert!(step <= limit && step > 0.9 * limit, "dtM {step} against {limit}");
}

/// A free point: a clump weight (m = 2000 kg, V = 0.5 m³) hanging on a vertical rope (λ0 10
/// kg/m, d 0.05 m, EA 2e6 N, 50 m) from (0, 0, −10). At equilibrium the rope's bottom carries
/// the point's wet weight `T_b = (m − ρV) g` and its top `T_b + w L`; it stretches
/// `(T_b L + w L²/2)/EA`, so the point hangs at `z = −10 − L − (T_b L + w L²/2)/EA` — whatever
/// mass and hull the mapping gave it to carry its lines' end nodes.
#[test]
fn a_free_point_hangs_where_its_wet_weight_stretches_the_line() {
    let scene = load(&here!("fixtures/moordyn/free_point.dat")).unwrap();
    let system = scene.world.system();
    let solved = equilibrium::solve(system, system.initial_states(), &[], &Settings::default()).unwrap();
    let (g, rho, length, ea) = (9.81, 1025.0, 50.0, 2.0e6);
    let wet = (10.0 - rho * PI * 0.05 * 0.05 / 4.0) * g;
    let bottom = (2000.0 - rho * 0.5) * g;
    let expected = -10.0 - length - (bottom * length + wet * length * length / 2.0) / ea;
    let z = solved.states[0].position.z;
    assert!((z - expected).abs() < 1e-6, "z = {z}, closed form {expected}");
    // The import starts it there (MoorDyn's file gave −60 m as a first guess).
    let start = scene.file.bodies[0].master.position[2];
    assert!((start - expected).abs() < 1e-6, "starts at z = {start}, closed form {expected}");
    // Its mass carries the rope's end node, λ0 L/(2N) = 25 kg (MoorDyn's point mass matrix).
    assert_eq!(scene.world.bodies()[0].mass(), 2025.0);
}

/// A point on a body is where MoorDyn puts it: the reference point plus the body's rotation
/// (roll, pitch, yaw) of the point, whatever the centre of gravity.
#[test]
fn points_on_a_turned_body_are_where_moordyn_puts_them() {
    let text = FREE_BODY.replace("BODYROW", "1 Free 10 0 -20 0 0 90 5000 0|0|-1 2000|2000|1000 4 1|1|1 1");
    let scene = import_text(&text, "body.dat").unwrap();
    let forces = &scene.world.coupling_forces()[0];
    // Point (2, 0, 1) turned 90° about z: (0, 2, 1) from (10, 0, −20).
    assert!((forces.point2 - tether_physics::math::Vec3::new(10.0, 2.0, -19.0)).norm() < 1e-12, "{}", forces.point2);
    let body = &scene.world.bodies()[0];
    assert!((body.mass_properties.center_of_mass - tether_physics::math::Vec3::new(10.0, 0.0, -21.0)).norm() < 1e-12);
}

const FREE_BODY: &str = "--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.0648 25.79 1.1e8 -0.8 0 2.4 1 1.15 0.5
--- BODIES ---
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca*
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
BODYROW
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed 100 0 -50 0 0 0 0
2 Body1 2 0 1 0 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 2 100 10 -
--- OPTIONS ---
50 WtrDpth
--- need this line ---
";

/// Check 6: bad input is one line with the file's line (and column), and nothing is built.
#[test]
fn bad_input_is_refused_at_its_line() {
    let good = FREE_BODY.replace("BODYROW", "1 Free 10 0 -20 0 0 0 5000 0 2000 4 1 1");
    assert!(import_text(&good, "good.dat").is_ok());
    let cases = [
        ("--- OPTIONS ---", "--- WIND ---", "bad.dat:18:5: unknown section \"WIND\""),
        (
            "1 chain 1 2 100 10 -",
            "1 rope 1 2 100 10 -",
            "bad.dat:17:3: line 1: no line type \"rope\" (the file's types: chain)",
        ),
        ("1 chain 1 2 100 10 -", "1 chain 1 7 100 10 -", "bad.dat:17:11: line 1: no point 7 (the file has 2 points)"),
        ("2 Body1 2 0 1", "2 Body2 2 0 1", "bad.dat:13:3: point 2 is attached to body 2 but the file has 1 bodies"),
        ("1 Fixed 100 0 -50", "1 Fixed 1OO 0 -50", "bad.dat:12:9: X: expected a number, found \"1OO\""),
        (
            "1 chain 1 2 100 10 -",
            "1 chain 1 2 -100 10 -",
            "bad.dat:17:13: line 1: the unstretched length must be > 0 m, found -100",
        ),
        (
            "1 chain 1 2 100 10 -",
            "1 chain 1 2 100 -10 -",
            "bad.dat:17:17: NumSegs: expected a whole number ≥ 1, found \"-10\"",
        ),
        (
            "1 chain 1 2 100 10 -",
            "1 chain 1 2 100 0 -",
            "bad.dat:17:17: NumSegs: expected a whole number ≥ 1, found \"0\"",
        ),
        (
            "chain 0.0648 25.79 1.1e8 -0.8",
            "chain 0.0648 25.79 ea.dat -0.8",
            "bad.dat:4:20: line type \"chain\": EA \"ea.dat\" is a nonlinear",
        ),
        (
            "1 chain 1 2 100 10 -",
            "1 chain 1 2 100",
            "bad.dat:17:16: NumSegs missing: the row has 5 fields, NumSegs is field 6",
        ),
    ];
    for (from, to, expected) in cases {
        let error = refusal(&good.replacen(from, to, 1), "bad.dat");
        assert!(error.starts_with(expected) && !error.contains('\n'), "{to}: {error}");
    }
    // A file that ends early: before its LINES section.
    let early = &good[..good.find("--- LINES ---").unwrap()];
    let error = refusal(early, "bad.dat");
    assert_eq!(error, "bad.dat:13:1: the file ends without a LINES section");
    // A value the physics refuses is reported at the file's line of the line it is in.
    let error = refusal(&good.replace("-0.8 0 2.4", "-1.5 0 2.4"), "bad.dat");
    assert!(error.starts_with("bad.dat:17:1: as imported: coupling \"line1\""), "{error}");
}

/// The lines of a scene as the comparison sees them: the world positions of their ends at
/// t = 0 and whether each end is on the world, a kinematic, a free or a point body.
type LineSummary = (Vec<&'static str>, [f64; 2], [u64; 2], LineModelDef, Vec<[i64; 3]>);

fn lines_of(scene: &Scene) -> Vec<LineSummary> {
    lines_of_world(&scene.file, &scene.world)
}

fn lines_of_world(file: &SceneFile, world: &tether_physics::world::World) -> Vec<LineSummary> {
    file.couplings
        .iter()
        .enumerate()
        .filter_map(|(index, coupling)| {
            let CouplingDef::Catenary { end1, end2, mass_per_length, length, stiffness, displaced_area, model, .. } =
                coupling
            else {
                return None;
            };
            let forces = &world.coupling_forces()[index];
            let kinds = [end1, end2]
                .iter()
                .map(|end| match end {
                    EndDef::World(_) => "Fixed",
                    EndDef::Body { body, .. } => {
                        let def = file.bodies.iter().find(|b| &b.name == body).unwrap();
                        if def.support == (SupportDef::Fixed { translation: (false, false, false), rotation: true }) {
                            "point mass"
                        } else {
                            export::body_kind(&def.support)
                        }
                    }
                })
                .collect();
            Some((
                kinds,
                [*stiffness, *displaced_area],
                [mass_per_length.to_bits(), length.to_bits()],
                *model,
                [forces.point1, forces.point2].iter().map(|p| p.map(|x| (x * 1e9).round() as i64).into()).collect(),
            ))
        })
        .collect()
}

/// Check 4: export then import of every shipped scene with lines gives the same lines — mass
/// per length, length and the dynamic model bit for bit, the end positions to the nanometre and
/// what each end is on; the stiffness and displaced area, which cross the file as EA = D L and
/// d = √(4 A_d/π), to 4 ulp; a dry line (no displaced area) comes back with the steel rod's area
/// the export wrote for it, λ0/7850. Quasi-static lines come back dynamic with the export's
/// segments.
#[test]
fn export_then_import_gives_back_the_same_lines() {
    let mut exported = 0;
    for path in scene_files() {
        let scene = load(&path).unwrap();
        if !scene.file.couplings.iter().any(|c| matches!(c, CouplingDef::Catenary { .. })) {
            continue;
        }
        let text = export::export(&scene.file, scene.bodies.bodies(), &path.display().to_string(), 30);
        let (file, world) = mapped_unsettled(&text);
        assert_same_lines(&lines_of(&scene), &lines_of_world(&file, &world), 30, &path);
        exported += 1;
    }
    assert!(exported >= 5, "{exported} shipped scenes with lines");
}

/// A MoorDyn file read and mapped, and its world, before the import settles its free bodies
/// (the end positions compared are then the file's).
fn mapped_unsettled(text: &str) -> (SceneFile, tether_physics::world::World) {
    let (sections, last) = moordyn::reader::sections(text).unwrap();
    let input = moordyn::input::read(&sections, last).unwrap();
    let file = moordyn::mapping::map(&input).unwrap().file;
    let world = tether_scene::build::build(&file, Path::new(".")).unwrap_or_else(|p| panic!("{}", p.message)).world;
    (file, world)
}

/// Each line the same (module docs of the test above); a quasi-static one dynamic at `segments`.
fn assert_same_lines(before: &[LineSummary], after: &[LineSummary], segments: u32, path: &Path) {
    assert_eq!(before.len(), after.len(), "{}", path.display());
    for (a, b) in before.iter().zip(after) {
        assert_eq!((&a.0, a.2, &a.4), (&b.0, b.2, &b.4), "{}", path.display());
        // The friction speed crosses the file as FricDamp CV = w l / v_s (a few rounding errors).
        let (LineModelDef::Dynamic(before), LineModelDef::Dynamic(after)) =
            (a.3.dynamic_with(if a.3.is_quasi_static() { segments } else { segments_of(&a.3) }), b.3)
        else {
            panic!("{}: not dynamic after import", path.display())
        };
        assert_eq!(after, LumpedMassSpec { friction_speed: after.friction_speed, ..before }, "{}", path.display());
        let (x, y) = (before.friction_speed, after.friction_speed);
        assert!((x - y).abs() <= 16.0 * f64::EPSILON * x, "{}: friction speed {x} → {y}", path.display());
        let mass_per_length = f64::from_bits(a.2[0]);
        let area = if a.1[1] > 0.0 { a.1[1] } else { mass_per_length / STEEL_DENSITY };
        for (x, y) in [a.1[0], area].iter().zip(&b.1) {
            assert!((x - y).abs() <= 4.0 * f64::EPSILON * x.abs(), "{}: {x} → {y}", path.display());
        }
    }
}

fn segments_of(model: &LineModelDef) -> u32 {
    match model {
        LineModelDef::Dynamic(line) => line.segments,
        LineModelDef::QuasiStatic => 0,
    }
}

/// An imported file exported and imported again is the same scene: bodies (point masses
/// included: the export takes back the mass and hull the mapping added) and lines.
#[test]
fn an_imported_file_survives_export_and_import() {
    for path in [input("lines.txt"), here!("fixtures/moordyn/free_point.dat")] {
        let first = load(&path).unwrap();
        let text = export::export(&first.file, first.bodies.bodies(), "first", 20);
        let (file, world) = mapped_unsettled(&text);
        assert_same_lines(&lines_of(&first), &lines_of_world(&file, &world), 20, &path);
        for (a, b) in first.world.bodies().iter().zip(world.bodies()) {
            assert!((a.mass() - b.mass()).abs() < 1e-9 * a.mass(), "{}: {} → {}", path.display(), a.mass(), b.mass());
        }
    }
}

/// Issue 48: a number of a MoorDyn file set to 10³⁰⁸ (or 10⁻³⁰⁸, or 0) that its column's own
/// check accepts but that makes a derived value infinite or zero is refused in one line at its
/// row, naming what overflows and the column (the importer's own values: MoorDyn's names) or
/// the scene's field (the physics' values, as imported).
#[test]
fn a_value_that_overflows_once_derived_is_refused_at_its_row() {
    let lines = std::fs::read_to_string(input("lines.txt")).unwrap();
    let main = "main       0.09    77.7066    384.243E6  -0.8        0          1.6    1.0    0.1     0.0";
    let with_main = |row: &str| lines.replacen(main, row, 1);
    let cases = [
        (
            with_main("main 0.09 77.7066 1e308 -0.8 0 1.6 1.0 0.1 0.0"),
            "bad.txt:19:1: as imported: coupling \"line1\": BA = ζ l √(EA λ0) must be finite, got inf (from stiffness = 1.1084016847705608e305)",
        ),
        (
            with_main("main 0.09 1e308 384.243E6 -0.8 0 1.6 1.0 0.1 0.0"),
            "bad.txt:19:1: line 1: an end node's mass Mass/m UnstrLen/(2 NumSegs) must be finite, got inf (from Mass/m = 1e308)",
        ),
        (
            with_main("main 0.09 1e-308 384.243E6 -0.8 0 1.6 1.0 0.1 0.0"),
            "bad.txt:19:1: as imported: coupling \"line1\": the axial stable step must be > 0 s, got 0 (from mass_per_length = 1e-308)",
        ),
        (
            with_main("main 1e308 77.7066 384.243E6 -0.8 0 1.6 1.0 0.1 0.0"),
            "bad.txt:6:1: line type \"main\": the displaced area π Diam²/4 must be finite, got inf (from Diam = 1e308)",
        ),
        (
            with_main("main 0.09 77.7066 384.243E6 1e308 0 1.6 1.0 0.1 0.0"),
            "bad.txt:19:1: as imported: coupling \"line1\": the axial stable step must be > 0 s, got 0 (from damping = 1e308)",
        ),
        (
            with_main("main 0.09 77.7066 384.243E6 -0.8 0 1e308 1.0 0.1 0.0"),
            "bad.txt:19:1: as imported: coupling \"line1\": a node's drag ½ ρ C_dn d l must be finite, got inf (from drag_normal = 1e308)",
        ),
        (
            lines.replacen("902.2     20", "1e308     20", 1),
            "bad.txt:19:1: line 1: an end node's mass Mass/m UnstrLen/(2 NumSegs) must be finite, got inf (from UnstrLen = 1e308)",
        ),
        (
            lines.replacen("902.2     20", "1e-308     20", 1),
            "bad.txt:19:1: line 1: the stiffness D = EA/UnstrLen must be finite, got inf (from UnstrLen = 1e-308)",
        ),
    ];
    for (text, expected) in &cases {
        assert_eq!(&refusal(text, "bad.txt"), expected);
    }
    // A free point: its weight, drag and added mass, at its row.
    let point = std::fs::read_to_string(here!("fixtures/moordyn/free_point.dat")).unwrap();
    let free = "2 Free 0 0 -60 2000 0.5 0.8 1.0";
    for (row, expected) in [
        (
            "2 Free 0 0 -60 1e308 0.5 0.8 1.0",
            "bad.dat:11:1: point 2: its weight m g must be finite, got inf (from Mass = 1e308)",
        ),
        (
            "2 Free 0 0 -60 2000 0.5 1e308 1.0",
            "bad.dat:11:1: point 2: its drag ½ ρ CdA must be finite, got inf (from CdA = 1e308)",
        ),
        (
            "2 Free 0 0 -60 2000 0.5 0.8 1e308",
            "bad.dat:11:1: point 2: its added mass Ca ρ V must be finite, got inf (from Ca = 1e308)",
        ),
    ] {
        assert_eq!(refusal(&point.replacen(free, row, 1), "bad.dat"), expected);
    }
}
