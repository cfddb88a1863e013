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

/// The one-line error of scene text labelled `bad.ron`, panicking if the text is accepted.
pub fn error_of(text: &str) -> String {
    match tether_scene::parse(text, Path::new("bad.ron")) {
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
