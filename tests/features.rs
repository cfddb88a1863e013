//! `cargo build` and `cargo test` build each dependency with the same features, so README's two
//! commands build the viewer stack once: every package the tests share with the
//! application has the same feature list in both builds (`cargo tree` resolves them as cargo
//! does; dev-dependencies turn features on only when tests are built).

use std::collections::{BTreeMap, BTreeSet};
use std::process::Command;

/// Feature lists of every package the workspace builds, by `name version` (a package built for
/// the host too, as a build dependency, can have two), with or without the dev-dependencies.
fn features(with_tests: bool) -> BTreeMap<String, BTreeSet<String>> {
    let edges = if with_tests { "normal,build,dev" } else { "normal,build" };
    let out = Command::new(env!("CARGO"))
        .args(["tree", "--workspace", "--locked", "--offline", "--prefix", "none", "-e", edges, "-f", "{p}|{f}"])
        .current_dir(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"))
        .output()
        .expect("cargo runs");
    assert!(out.status.success(), "cargo tree: {}", String::from_utf8_lossy(&out.stderr));
    let mut found: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let Some((package, features)) = line.split_once('|') else { continue };
        // `name vX.Y.Z (path)`: the name and version identify the package.
        let id: Vec<&str> = package.split_whitespace().take(2).collect();
        found.entry(id.join(" ")).or_default().insert(features.trim_end_matches(" (*)").trim().to_string());
    }
    found
}

#[test]
fn the_tests_build_every_shared_dependency_with_the_applications_features() {
    let (build, test) = (features(false), features(true));
    assert!(build.len() > 500, "the application's dependency graph was read: {} packages", build.len());
    let parted: Vec<String> = build
        .iter()
        .filter_map(|(package, f)| {
            test.get(package).filter(|t| *t != f).map(|t| format!("{package}: build {f:?} test {t:?}"))
        })
        .collect();
    assert!(parted.is_empty(), "features differ between `cargo build` and `cargo test`:\n{}", parted.join("\n"));
}
