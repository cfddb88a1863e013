//! The record crate's modules import one another without a circle, read from the sources by the
//! physics crate's import graph reader (`crates/physics/tests/import_graph/`, shared by every
//! crate's architecture test); a module may name its ancestors' items ([`Ancestors::InScope`]).
//! It depends only on the crates below it (docs/architecture.md).

#[path = "../../physics/tests/import_graph/mod.rs"]
mod import_graph;

use import_graph::Ancestors;

fn root() -> std::path::PathBuf {
    std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join("src/lib.rs")
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    import_graph::assert_no_circle(&root(), Ancestors::InScope, 16);
}

#[test]
fn depends_only_on_the_layers_below() {
    // The recorder logs through the SDK: no window, no command line.
    import_graph::assert_layered(
        "tether-record",
        &std::path::PathBuf::from(
            std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
        )
        .join("Cargo.toml"),
        &root(),
        &["egui", "eframe", "clap"],
    );
}
