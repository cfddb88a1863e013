//! The physics crate's modules import one another without a circle (issue 14), read from the
//! sources by the import graph reader every crate's architecture test shares
//! (`tests/import_graph/`): no module names one that names it back, not even its parent (the
//! strictest rule of the four crates: [`Ancestors::Edges`]); it depends on no other crate of
//! the workspace and names no GUI, viewer or file format.

mod import_graph;

use import_graph::{Ancestors, code, cycle, expand, named_paths, target};
use std::collections::{BTreeMap, BTreeSet};

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join("src/lib.rs")
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = import_graph::assert_no_circle(&root(), Ancestors::Edges, 30);
    // The root only declares modules: nothing imports from it.
    for (module, edges) in &graph {
        assert!(!edges.contains("crate"), "{module} imports from the crate root");
    }
}

#[test]
fn the_graph_reader_sees_a_planted_circle() {
    let known: BTreeSet<String> = ["crate", "crate::a", "crate::a::b"].map(String::from).into();
    let paths_a = named_paths(&code("pub use b::Thing;\nfn f() -> Thing { todo!() }"), &["b"]);
    let paths_b =
        named_paths(&code("use super::{Other, b::Thing};\n#[cfg(test)]\nmod tests { use crate::a::Y; }"), &[]);
    let edges = |from: &str, paths: &[String]| {
        paths.iter().filter_map(|p| target(from, p, &known)).filter(|t| t != from).collect::<BTreeSet<String>>()
    };
    assert_eq!(edges("crate::a", &paths_a), ["crate::a::b".to_string()].into(), "a names its child b");
    let graph: BTreeMap<String, BTreeSet<String>> = [
        ("crate::a".to_string(), edges("crate::a", &paths_a)),
        ("crate::a::b".to_string(), edges("crate::a::b", &paths_b)),
    ]
    .into();
    assert_eq!(graph["crate::a::b"], ["crate::a".to_string()].into(), "b names its parent's item: {graph:?}");
    assert_eq!(cycle(&graph), Some(["crate::a", "crate::a::b", "crate::a"].map(String::from).to_vec()));
    assert_eq!(import_graph::cycles(&graph).len(), 1, "taking the circle's last edge out leaves none: {graph:?}");
    assert_eq!(
        expand("crate::x::{a, b::{c, d as e}, self}"),
        ["crate::x::a", "crate::x::b::c", "crate::x::b::d", "crate::x"]
    );
}

/// The bottom layer: no workspace crate among its dependencies (the scene crate is a
/// dev-dependency only), no GUI, viewer or file format named in its code.
#[test]
fn the_physics_crate_names_no_gui_viewer_or_file_format() {
    import_graph::assert_layered(
        "tether-physics",
        &std::path::PathBuf::from(
            std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
        )
        .join("Cargo.toml"),
        &root(),
        &["rerun", "egui", "eframe", "ron::", "tobj", "stl_io", "tether_scene"],
    );
}
