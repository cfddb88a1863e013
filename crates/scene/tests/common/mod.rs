//! Helpers shared by the scene crate's integration tests.
#![allow(dead_code)] // each test binary uses its own subset

use std::path::{Path, PathBuf};

/// Path of a file under the repository root.
pub fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(path)
}

/// Path of a file under this crate's `tests/`.
pub fn here(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests").join(path)
}

/// Every shipped scene (`.ron` under `scenes/`).
pub fn scene_files() -> Vec<PathBuf> {
    tether_scene::list(&repo("scenes"))
}

/// Parses scene text (labelled `test.ron`), panicking with the error line if it is bad.
pub fn scene(text: &str) -> tether_scene::Scene {
    tether_scene::parse(text, Path::new("test.ron")).unwrap_or_else(|e| panic!("{e}"))
}
