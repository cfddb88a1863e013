//! `tether equilibrium` and `tether offsets` (PHYSICS.md §7), run as a user runs them.

mod common;

use approx::assert_relative_eq;
use std::path::Path;
use std::process::{Command, Output};

fn tether(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tether")).args(args).output().unwrap()
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

fn stdout(out: &Output) -> String {
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn equilibrium_prints_poses_tensions_and_stiffness_and_writes_the_scene_at_rest() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "moored.ron", common::MOORED_ON_SEABED);
    let at_rest = dir.path().join("at_rest.ron");
    let text = stdout(&tether(&["equilibrium", &scene, "--write", at_rest.to_str().unwrap()]));
    assert!(text.contains("static equilibrium in "), "{text}");
    assert!(text.contains("body \"buoy\"") && text.contains("stiffness at equilibrium"), "{text}");
    assert!(
        text.contains("coupling \"m1\" (catenary): tension 0.000000e0 N at end 1"),
        "friction holds the anchors: {text}"
    );
    assert!(text.contains("on the seabed: grounded length L_B 144.7"), "{text}");
    // The scene written at equilibrium is at equilibrium: no Newton step, and the loaded world
    // puts the buoy where the report says.
    let again = stdout(&tether(&["equilibrium", at_rest.to_str().unwrap()]));
    assert!(again.contains("static equilibrium in 0 Newton iterations"), "{again}");
    let loaded = tether_scene::load(&at_rest).unwrap();
    let centre = loaded.world.state(0).position;
    let printed = format!("centre of mass  ({:.6}, {:.6}, {:.6}) m", centre.x + 0.0, centre.y + 0.0, centre.z + 0.0);
    assert!(text.contains(&printed), "{printed} in\n{text}");
    assert_eq!(loaded.world.state(0).velocity.norm(), 0.0);
}

#[test]
fn an_unreachable_equilibrium_is_one_line_naming_the_body_and_direction() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(
        dir.path(),
        "rock.ron",
        "Scene(dt: 0.01, bodies: [Body(name: \"rock\", master: Node(position: (0.0, 0.0, 0.0), mass: 10.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)), shape: Sphere(radius: 0.1))])",
    );
    let out = tether(&["equilibrium", &scene]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("no static equilibrium: body \"rock\" has no restoring force in z"), "{stderr}");
}

#[test]
fn offsets_print_and_write_the_restoring_force_curve() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "moored.ron", common::MOORED_ON_SEABED);
    let output = dir.path().join("curve");
    let text = stdout(&tether(&[
        "offsets",
        &scene,
        "--body",
        "buoy",
        "--direction",
        "x",
        "--to",
        "20",
        "--steps",
        "8",
        "-o",
        output.to_str().unwrap(),
    ]));
    assert!(text.contains("restoring [N]"), "{text}");
    let csv = std::fs::read_to_string(output.with_extension("csv")).unwrap();
    let rows: Vec<Vec<f64>> = csv.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect();
    assert_eq!(rows.len(), 9);
    assert_relative_eq!(rows[8][0], 20.0);
    assert!(rows[0][2].abs() < 1e-3, "no restoring force at equilibrium: {}", rows[0][2]);
    assert!(rows.windows(2).all(|w| w[1][2] > w[0][2]), "the restoring force grows with the offset");
    let png = std::fs::read(output.with_extension("png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
}

#[test]
fn offsets_refuse_bad_flags_with_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "moored.ron", common::MOORED_ON_SEABED);
    for (flags, expected) in [
        (vec!["--body", "bouy", "--direction", "x", "--to", "5"], "no body \"bouy\" (bodies: buoy)"),
        (vec!["--body", "buoy", "--direction", "x", "--to", "0"], "--to must be a non-zero number of m, got 0"),
        (
            vec!["--body", "buoy", "--direction", "yaw", "--to", "0.1", "--steps", "0"],
            "--steps must be 1 to 10000, got 0",
        ),
    ] {
        let out = tether(&[&["offsets", scene.as_str()][..], &flags].concat());
        assert_eq!(out.status.code(), Some(1));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(expected) && stderr.lines().count() == 1, "{stderr}");
    }
}

#[test]
fn check_reports_the_grounded_length_and_touchdown() {
    let dir = tempfile::tempdir().unwrap();
    let scene = write(dir.path(), "moored.ron", common::MOORED_ON_SEABED);
    let text = stdout(&tether(&["check", &scene]));
    assert!(text.contains("seabed at z_b = -50 m, line friction C_B = 0.5"), "{text}");
    assert!(text.contains("on the seabed: L_B = "), "{text}");
}
