//! Helpers shared by the integration tests.
#![allow(dead_code)] // each test binary uses its own subset

pub mod x11;

use std::path::{Path, PathBuf};
use tether_scene::{self as scene, Scene};

/// Path of a file under the repository root.
pub fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// Path of a file under this crate's `tests/`.
pub fn here(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests").join(path)
}

/// Parses scene text (labelled `test.ron`), panicking with the error line if it is bad.
pub fn scene(text: &str) -> Scene {
    scene::parse(text, Path::new("test.ron")).unwrap_or_else(|e| panic!("{e}"))
}

/// Every shipped scene (`.ron` under `scenes/`).
pub fn scene_files() -> Vec<PathBuf> {
    scene::list(&repo("scenes"))
}

/// The scene the GUI tests open, as file text: body `body` (1 kg, released at x = 1.1 m, free
/// only along x) on coupling "spring" to the world origin (k = 100 N/m, x0 = 1 m, no damping),
/// dt = 1 ms.
pub fn spring_scene_text(body: &str) -> String {
    format!(
        r#"Scene(
    gravity: (0.0, 0.0, 0.0),
    dt: 0.001,
    bodies: [Body(name: "{body}", master: Node(position: (1.1, 0.0, 0.0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
        support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
    couplings: [SpringDamper(name: "spring", end1: World((0.0, 0.0, 0.0)), end2: Body(body: "{body}"),
        law: Linear(stiffness: 100.0, rest_length: 1.0), damping: 0.0)],
)
"#
    )
}

/// A one-body oscillator along x: a body of mass `mass` attached to the world origin by a
/// spring with law `law` (RON) and damping `damping`, starting at `x` with speed `v`, free
/// only along x.
pub fn oscillator(law: &str, damping: f64, x: f64, v: f64, dt: f64) -> Scene {
    scene(&format!(
        "Scene(gravity: (0.0, 0.0, 0.0), dt: {dt:e}, bodies: [Body(name: \"m\",
            master: Node(position: ({x:e}, 0.0, 0.0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
            velocity: ({v:e}, 0.0, 0.0),
            support: Fixed(translation: (false, true, true), rotation: true),
            shape: Sphere(radius: 0.1))],
        couplings: [SpringDamper(name: \"s\", end1: World((0.0, 0.0, 0.0)), end2: Body(body: \"m\"), law: {law}, damping: {damping:e})])"
    ))
}

/// A 3 t buoy on three chains of 220 m lying on a seabed 50 m down with friction, a vertical
/// spring for its buoyancy, released 5 m off its rest position.
pub const MOORED_ON_SEABED: &str = include_str!("../fixtures/moored_on_seabed.ron");
