//! The application's modules import one another without a circle — the library (`src/lib.rs`)
//! and the command line (`src/main.rs`) each — read from the sources by the physics crate's
//! import graph reader (`crates/physics/tests/import_graph/`, shared by every crate's
//! architecture test); a module may name its ancestors' items ([`Ancestors::InScope`]). The
//! application is the top layer: any crate of the workspace is below it.

#[path = "../crates/physics/tests/import_graph/mod.rs"]
mod import_graph;

use import_graph::Ancestors;

fn source(file: &str) -> std::path::PathBuf {
    std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join("src")
    .join(file)
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    import_graph::assert_no_circle(&source("lib.rs"), Ancestors::InScope, 40);
    import_graph::assert_no_circle(&source("main.rs"), Ancestors::InScope, 10);
}

/// The sweep's modules keep the stricter rule of the physics crate: its `mod.rs` declares and
/// re-exports, and no module of the sweep imports from it.
#[test]
fn the_sweep_imports_nothing_from_its_parent() {
    let graph = import_graph::import_graph(&source("lib.rs"), Ancestors::Edges);
    let sweep: import_graph::Graph =
        graph.into_iter().filter(|(module, _)| module.starts_with("crate::sweep")).collect();
    assert!(sweep.len() > 10, "{:?}", sweep.keys());
    for (module, edges) in &sweep {
        assert!(!edges.contains("crate::sweep"), "{module} imports from crate::sweep (its mod.rs)");
    }
    let circles = import_graph::cycles(&sweep);
    assert!(circles.is_empty(), "{circles:?}");
}

#[test]
fn the_application_is_the_top_layer() {
    let manifest = std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join("Cargo.toml");
    import_graph::assert_layered("tether", &manifest, &source("lib.rs"), &[]);
    assert_eq!(
        import_graph::workspace_dependencies(&manifest),
        ["tether-physics", "tether-scene", "tether-record"],
        "the application builds on the three library crates"
    );
}
