//! The application's modules import one another without a circle — the library (`src/lib.rs`)
//! and the command line (`src/main.rs`) each — read from the sources by the physics crate's
//! import graph reader (`crates/physics/tests/import_graph/`, shared by every crate's
//! architecture test); a module may name its ancestors' items ([`Ancestors::InScope`]). The
//! application is the top layer: any crate of the workspace is below it.

#[path = "../crates/physics/tests/import_graph/mod.rs"]
mod import_graph;

use import_graph::Ancestors;

fn source(file: &str) -> std::path::PathBuf {
    import_graph::crate_dir().join("src").join(file)
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    import_graph::assert_no_circle(&source("lib.rs"), Ancestors::InScope, 30);
    import_graph::assert_no_circle(&source("main.rs"), Ancestors::InScope, 10);
}

#[test]
fn the_application_is_the_top_layer() {
    let manifest = import_graph::crate_dir().join("Cargo.toml");
    import_graph::assert_layered("tether", &manifest, &source("lib.rs"), &[]);
    assert_eq!(
        import_graph::workspace_dependencies(&manifest),
        ["tether-physics", "tether-scene", "tether-record", "tether-analysis"],
        "the application builds on the four library crates"
    );
}

/// The Python module is an adapter beside the application, not above it: it builds on the
/// library crates (the analyses among them), so neither the window nor the command line is
/// compiled into the wheel.
#[test]
fn the_python_module_builds_on_the_libraries_not_the_application() {
    let manifest = import_graph::crate_dir().join("python/Cargo.toml");
    assert_eq!(
        import_graph::workspace_dependencies(&manifest),
        ["tether-physics", "tether-scene", "tether-record", "tether-analysis"],
    );
}
