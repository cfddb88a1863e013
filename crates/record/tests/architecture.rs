//! The record crate's modules import one another without a circle, read from the sources by the
//! physics crate's import graph reader (`crates/physics/tests/import_graph/`, shared by every
//! crate's architecture test); a module may name its ancestors' items ([`Ancestors::InScope`]).
//! It depends only on the crates below it (docs/architecture.md).

#[path = "../../physics/tests/import_graph/mod.rs"]
mod import_graph;

use import_graph::Ancestors;

#[test]
fn no_module_imports_one_that_imports_it_back() {
    import_graph::assert_no_circle(&import_graph::library_root(), Ancestors::InScope, 16);
}

#[test]
fn depends_only_on_the_layers_below() {
    // The recorder logs through the SDK: no window, no command line.
    import_graph::assert_layered(
        "tether-record",
        &import_graph::crate_dir().join("Cargo.toml"),
        &import_graph::library_root(),
        &["egui", "eframe", "clap"],
    );
}
