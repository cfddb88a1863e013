//! Helpers shared by the integration tests of the physics, scene and application crates: worlds
//! described as scene text, paths into the repository, the one-line errors of bad scene text.
//! (The application's own helpers — the X server, its binary — stay in its `tests/common`.)

use std::path::{Path, PathBuf};
use tether_scene::{self as scene, Scene};

/// Path of a file under the repository root: the workspace (the folder with `Cargo.lock`)
/// holding the test that runs, found when it runs from `CARGO_MANIFEST_DIR` (which cargo sets
/// for a test it runs) or else the working folder. Not `env!`: cargo does not rebuild an
/// unchanged crate for a checkout moved elsewhere (a cached target directory), so a path
/// compiled in can name a checkout that is gone.
pub fn repo(path: &str) -> PathBuf {
    let start = std::env::var_os("CARGO_MANIFEST_DIR").map(PathBuf::from).or_else(|| std::env::current_dir().ok());
    let workspace = start.as_deref().and_then(|dir| dir.ancestors().find(|d| d.join("Cargo.lock").is_file()));
    workspace.expect("a test runs inside the repository (its CARGO_MANIFEST_DIR or working folder)").join(path)
}

/// Path of a file under the `tests/` of the crate whose test runs (`CARGO_MANIFEST_DIR`, which
/// cargo sets for the test it runs: see [`repo`] for why not `env!`).
#[macro_export]
macro_rules! here {
    ($path:expr) => {
        ::std::path::PathBuf::from(
            ::std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
        )
        .join("tests")
        .join($path)
    };
}

/// `∫ f` from `a` to `b` by Simpson's rule on `intervals` (even) intervals, for a value that
/// adds and scales by a real (a real, a complex number).
pub fn simpson<T>(f: impl Fn(f64) -> T, a: f64, b: f64, intervals: u32) -> T
where
    T: Default + std::ops::Add<Output = T> + std::ops::Mul<f64, Output = T>,
{
    assert!(
        intervals >= 2 && intervals.is_multiple_of(2),
        "Simpson's rule takes an even number of intervals, got {intervals}"
    );
    let h = (b - a) / f64::from(intervals);
    let weight = |i: u32| match i {
        0 => 1.0,
        i if i == intervals => 1.0,
        i if !i.is_multiple_of(2) => 4.0,
        _ => 2.0,
    };
    (0..=intervals).fold(T::default(), |sum, i| sum + f(a + f64::from(i) * h) * (weight(i) * h / 3.0))
}

/// Every shipped scene (`.ron` under `scenes/`).
pub fn scene_files() -> Vec<PathBuf> {
    scene::list(&repo("scenes"))
}

/// Parses scene text (labelled `test.ron`), panicking with the error line if it is bad.
pub fn scene(text: &str) -> Scene {
    scene::parse(text, Path::new("test.ron")).unwrap_or_else(|e| panic!("{e}"))
}

/// The one-line error of scene text labelled `bad.ron`, panicking if the text is accepted.
pub fn error_of(text: &str) -> String {
    match scene::parse(text, Path::new("bad.ron")) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// `good` with `edit.0` replaced once by `edit.1` is refused with one line starting `expected`.
pub fn assert_edit_error(good: &str, edit: (&str, &str), expected: &str) {
    assert!(good.contains(edit.0), "edit target {:?} missing", edit.0);
    let error = error_of(&good.replacen(edit.0, edit.1, 1));
    assert!(error.starts_with(expected), "expected {expected:?}…, got {error:?}");
    assert_eq!(error.lines().count(), 1, "{error}");
}

/// A one-body oscillator along x: a body of mass 1 kg attached to the world origin by a spring
/// with law `law` (RON) and damping `damping` [N·s/m], starting at `x` [m] with speed `v` [m/s],
/// free only along x, time step `dt` [s].
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
