//! Helpers shared by the application's integration tests: the X server (`x11`), the GUI tests'
//! scene; the helpers every crate's tests share are `tether-test-support`'s, re-exported here.
#![allow(dead_code, unused_imports)] // each test binary uses its own subset

pub mod x11;

pub use tether_test_support::{here, repo, scene_files};

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

/// A 3 t buoy on three chains of 220 m lying on a seabed 50 m down with friction, a vertical
/// spring for its buoyancy, released 5 m off its rest position.
pub const MOORED_ON_SEABED: &str = include_str!("../fixtures/moored_on_seabed.ron");
