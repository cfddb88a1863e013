//! The physics crate's modules import one another without a circle (issue 14), read from the
//! sources by the import graph reader every crate's architecture test shares
//! (`tests/import_graph/`): no module names one that names it back, not even its parent (the
//! strictest rule of the four crates: [`Ancestors::Edges`]); it depends on no other crate of
//! the workspace and names no GUI, viewer or file format.

mod import_graph;

use import_graph::{Ancestors, code, cycle, expand, named_paths, target};
use std::collections::{BTreeMap, BTreeSet};

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = import_graph::assert_no_circle(&import_graph::library_root(), Ancestors::Edges, 30);
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
        &import_graph::crate_dir().join("Cargo.toml"),
        &import_graph::library_root(),
        &["rerun", "egui", "eframe", "ron::", "serde", "tobj", "stl_io", "tether_scene"],
    );
}

/// Nor does any crate it depends on bring a file format in: `cargo tree` of its normal
/// dependencies names no serde (the scene crate spells the physics' types in files, issue 45).
#[test]
fn the_physics_crate_s_normal_dependencies_have_no_serde() {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = std::process::Command::new(cargo)
        .args(["tree", "--offline", "--locked", "-p", "tether-physics", "-e", "normal", "--prefix", "none"])
        .output()
        .expect("cargo runs");
    assert!(out.status.success(), "cargo tree: {}", String::from_utf8_lossy(&out.stderr));
    let tree = String::from_utf8_lossy(&out.stdout);
    assert!(tree.lines().any(|line| line.starts_with("nalgebra ")), "the tree is read:\n{tree}");
    let serde: Vec<&str> = tree.lines().filter(|line| line.starts_with("serde")).collect();
    assert!(serde.is_empty(), "tether-physics depends on {serde:?}:\n{tree}");
}

/// A type whose constructor checks its values (`pub fn new(…) -> Result<Self, …>`) has no public
/// field: a struct literal would skip the check, and the type would hold what it refuses (issue
/// 45). Read from the sources: every struct of a file with such a `new` in an `impl` of it.
#[test]
fn every_type_with_a_checking_constructor_has_no_public_field() {
    let (mut checked, mut open) = (BTreeSet::new(), Vec::new());
    for (module, file) in import_graph::modules(&import_graph::library_root()) {
        let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        // The whole file without its comments (`code` stops at the first `#[cfg(test)]`, which
        // may stand inside an `impl`).
        let text: String =
            text.lines().map(|line| line.split("//").next().unwrap_or_default()).collect::<Vec<_>>().join("\n");
        for name in checking_constructors(&text) {
            let Some(fields) = block_after(&text, &format!("pub struct {name} {{")) else { continue };
            let public: Vec<&str> = fields.lines().map(str::trim).filter(|line| line.starts_with("pub ")).collect();
            if !public.is_empty() {
                open.push(format!("{module}: {name} {public:?}"));
            }
            checked.insert(name);
        }
    }
    assert!(open.is_empty(), "types that check their values in `new` but have public fields:\n{}", open.join("\n"));
    let known = [
        "Timing",
        "Tolerances",
        "Catenary",
        "SpringDamper",
        "ContactLaw",
        "Seabed",
        "LumpedMass",
        "Harmonic",
        "PotentialBody",
        "Water",
    ];
    for name in known {
        assert!(checked.contains(name), "{name} is not among the types read: {checked:?}");
    }
}

/// The names of the types in `code` whose `impl Name {` block has a `pub fn new(…)` that
/// returns a `Result<Self, …>`.
fn checking_constructors(code: &str) -> Vec<String> {
    let mut names = Vec::new();
    for (at, _) in code.match_indices("\nimpl ") {
        let header = &code[at + "\nimpl ".len()..];
        let Some(open) = header.find('{') else { continue };
        let name = header[..open].trim();
        if name.contains(' ') || name.contains('<') {
            continue; // a trait's impl, or a generic one
        }
        let Some(body) = block_after(header, "") else { continue };
        let checks = body.match_indices("pub fn new(").any(|(start, _)| {
            let signature = &body[start..body[start..].find('{').map_or(body.len(), |end| start + end)];
            signature.contains("Result<Self")
        });
        if checks {
            names.push(name.to_string());
        }
    }
    names
}

/// The text between the braces of the block that starts at the first `{` after `opening` in
/// `code` (`opening` empty: the first `{`), if there is one.
fn block_after<'a>(code: &'a str, opening: &str) -> Option<&'a str> {
    let start = code.find(opening)? + opening.len();
    let open = if opening.ends_with('{') { start - 1 } else { start + code[start..].find('{')? };
    let mut depth = 0;
    for (i, c) in code[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(&code[open + 1..open + i]);
                }
            }
            _ => {}
        }
    }
    None
}

/// The crate's top-level rooms (`crate::water`, `crate::potential`, `crate::coupling`, …) import
/// one another without a circle either: each module's imports, its room's, do not lead back to
/// it (issue 45: the water stage, which runs Morison's loads and potential flow together, sits
/// above both rooms, not inside the one the other imports).
#[test]
fn no_room_imports_one_that_imports_it_back() {
    let graph = import_graph::import_graph(&import_graph::library_root(), Ancestors::Edges);
    let room = |module: &str| module.split("::").take(2).collect::<Vec<_>>().join("::");
    let mut rooms: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (module, edges) in &graph {
        let from = room(module);
        let to: BTreeSet<String> =
            edges.iter().map(|edge| room(edge)).filter(|to| *to != from && to != "crate").collect();
        rooms.entry(from).or_default().extend(to);
    }
    assert!(rooms.len() >= 20, "the rooms are read: {rooms:?}");
    let circles = import_graph::cycles(&rooms);
    assert!(circles.is_empty(), "rooms that import one another back: {circles:?}");
}
