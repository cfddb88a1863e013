//! The analysis crate's modules import one another without a circle, read from the sources by
//! the physics crate's import graph reader (`crates/physics/tests/import_graph/`, shared by every
//! crate's architecture test); a module may name its ancestors' items ([`Ancestors::InScope`]),
//! except in the sweep, which keeps the physics crate's stricter rule. It depends only on the
//! crates below it, and presents nothing: no window, no command line (docs/architecture.md).

#[path = "../../physics/tests/import_graph/mod.rs"]
mod import_graph;

use import_graph::Ancestors;

#[test]
fn no_module_imports_one_that_imports_it_back() {
    import_graph::assert_no_circle(&import_graph::library_root(), Ancestors::InScope, 55);
}

/// The sweep's modules keep the stricter rule of the physics crate: its `mod.rs` declares and
/// re-exports, and no module of the sweep imports from it.
#[test]
fn the_sweep_imports_nothing_from_its_parent() {
    let graph = import_graph::import_graph(&import_graph::library_root(), Ancestors::Edges);
    let sweep: import_graph::Graph =
        graph.into_iter().filter(|(module, _)| module.starts_with("crate::sweep")).collect();
    assert!(sweep.len() > 10, "{:?}", sweep.keys());
    for (module, edges) in &sweep {
        assert!(!edges.contains("crate::sweep"), "{module} imports from crate::sweep (its mod.rs)");
    }
    let circles = import_graph::cycles(&sweep);
    assert!(circles.is_empty(), "{circles:?}");
}

/// What the sweep, the fit and the storm share — a scene value's path, a spec's text, the
/// engine of many runs, the quantities — sits below them: none of those rooms imports a sweep,
/// fit or storm module.
#[test]
fn the_shared_rooms_import_no_analysis_built_on_them() {
    let graph = import_graph::import_graph(&import_graph::library_root(), Ancestors::Edges);
    let shared = ["crate::value_path", "crate::spec_text", "crate::runner", "crate::quantity", "crate::interrupt"];
    let analyses = ["crate::sweep", "crate::fit", "crate::storm", "crate::study", "crate::statics"];
    for room in shared {
        let edges = graph.get(room).unwrap_or_else(|| panic!("{room} is a module: {:?}", graph.keys()));
        for edge in edges {
            assert!(!analyses.iter().any(|a| edge.starts_with(a)), "{room} imports {edge}, an analysis built on it");
        }
    }
}

#[test]
fn depends_only_on_the_layers_below() {
    import_graph::assert_layered(
        "tether-analysis",
        &import_graph::crate_dir().join("Cargo.toml"),
        &import_graph::library_root(),
        &["egui", "eframe", "clap", "rerun::"],
    );
    assert_eq!(
        import_graph::workspace_dependencies(&import_graph::crate_dir().join("Cargo.toml")),
        ["tether-physics", "tether-scene", "tether-record"],
        "the analyses build on the three library crates below them"
    );
}
