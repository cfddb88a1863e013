//! The code map in `docs/architecture.md` lists every module of the workspace's crates, and nothing that
//! is not there: a module added, moved or removed without its line in the map fails here.
//!
//! The map has one section per crate, headed ``### `DIR/` — name``, whose table rows start with
//! the module's path inside `DIR` in backticks: `water/waves.rs` for a file, `water/` for a
//! folder's `mod.rs`.

use std::collections::BTreeSet;
use std::path::Path;

const SOURCE_DIRS: [&str; 7] = [
    "crates/physics/src",
    "crates/scene/src",
    "crates/record/src",
    "crates/analysis/src",
    "crates/test-support/src",
    "python/src",
    "src",
];

/// Every module under `dir`, named as the map names it.
fn modules(dir: &Path, prefix: &str, found: &mut BTreeSet<String>) {
    let entries = std::fs::read_dir(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    for entry in entries {
        let path = entry.expect("a directory entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).expect("a UTF-8 file name").to_string();
        if path.is_dir() {
            modules(&path, &format!("{prefix}{name}/"), found);
        } else if name == "mod.rs" {
            found.insert(prefix.to_string());
        } else if name.ends_with(".rs") {
            found.insert(format!("{prefix}{name}"));
        }
    }
}

/// The modules the map lists for `dir`: the first backticked word of each table row in its
/// section.
fn mapped(map: &str, dir: &str) -> BTreeSet<String> {
    let heading = format!("### `{dir}/`");
    let start = map.find(&heading).unwrap_or_else(|| panic!("docs/architecture.md has no section {heading}"));
    let section = &map[start + heading.len()..];
    let section = &section[..section.find("\n#").unwrap_or(section.len())];
    section
        .lines()
        .filter_map(|line| line.strip_prefix("| `"))
        .filter_map(|row| row.split_once('`').map(|(module, _)| module.to_string()))
        .collect()
}

#[test]
fn the_code_map_lists_every_module_and_only_those() {
    let repo = std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    );
    let map = std::fs::read_to_string(repo.join("docs/architecture.md")).expect("docs/architecture.md");
    let mut problems = Vec::new();
    for dir in SOURCE_DIRS {
        let mut actual = BTreeSet::new();
        modules(&repo.join(dir), "", &mut actual);
        let listed = mapped(&map, dir);
        assert!(!actual.is_empty(), "{dir}: the sources were read ({} modules)", actual.len());
        problems.extend(actual.difference(&listed).map(|m| format!("{dir}/{m}: not in the code map")));
        problems.extend(listed.difference(&actual).map(|m| format!("{dir}/{m}: in the code map, not in the code")));
    }
    assert!(problems.is_empty(), "docs/architecture.md's code map is out of date:\n{}", problems.join("\n"));
}

/// The relative targets of a Markdown text's links and images: `](target)` and `src="target"`,
/// without their `#fragment`; web addresses and in-page anchors left out.
fn relative_targets(text: &str) -> Vec<String> {
    let links = text.split("](").skip(1).filter_map(|rest| rest.split_once(')').map(|(target, _)| target));
    let images = text.split("src=\"").skip(1).filter_map(|rest| rest.split_once('"').map(|(target, _)| target));
    links
        .chain(images)
        .map(|target| target.split_whitespace().next().unwrap_or_default())
        .map(|target| target.split('#').next().unwrap_or_default().to_string())
        .filter(|target| !target.is_empty() && !target.contains("://") && !target.starts_with("mailto:"))
        .collect()
}

/// Every relative link and image of the README and of `docs/` resolves from the file it is in
/// (issue 35: docs/window.md showed `screenshots/gui_tuning_panel.png`, which is beside the
/// docs folder, not in it).
#[test]
fn every_relative_link_of_the_docs_resolves() {
    let repo = std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    );
    let mut pages = vec![repo.join("README.md")];
    let docs = std::fs::read_dir(repo.join("docs")).expect("docs/");
    pages.extend(
        docs.map(|entry| entry.expect("a directory entry").path()).filter(|p| p.extension().is_some_and(|e| e == "md")),
    );
    let mut checked = 0;
    let mut broken = Vec::new();
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap_or_else(|e| panic!("{}: {e}", page.display()));
        let folder = page.parent().expect("a page in a folder");
        for target in relative_targets(&text) {
            checked += 1;
            if !folder.join(&target).exists() {
                broken.push(format!("{}: {target}", page.display()));
            }
        }
    }
    assert!(checked > 20, "the links were read: {checked}");
    assert!(broken.is_empty(), "links that lead nowhere:\n{}", broken.join("\n"));
}

#[test]
fn link_targets_are_read_from_links_and_images() {
    let text = "see [a](docs/a.md#part), ![b](../shots/b.png \"title\"), <img src=\"c.png\" width=\"3\">, \
                [web](https://example.org/x) and [here](#anchor)";
    assert_eq!(relative_targets(text), ["docs/a.md", "../shots/b.png", "c.png"]);
}
