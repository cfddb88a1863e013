//! Helpers shared by the physics crate's integration tests: worlds described as scene text.
#![allow(dead_code)] // each test binary uses its own subset

use std::path::{Path, PathBuf};
use tether_scene::{self as scene, Scene};

/// Path of a file under the repository root.
pub fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(path)
}

/// Parses scene text (labelled `test.ron`), panicking with the error line if it is bad.
pub fn scene(text: &str) -> Scene {
    scene::parse(text, Path::new("test.ron")).unwrap_or_else(|e| panic!("{e}"))
}

/// Every shipped scene (`.ron` under `scenes/`).
pub fn scene_files() -> Vec<PathBuf> {
    scene::list(&repo("scenes"))
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
