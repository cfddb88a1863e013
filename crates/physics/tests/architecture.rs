//! The physics crate's modules import one another without a circle (issue 14): read from the
//! sources, every `use` and every `crate::…`/`super::…` path outside test modules is an edge
//! from the module that writes it to the module it names; the graph must have no cycle, and the
//! physics crate must not name the GUI, the viewer or a file format.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Module path (`crate`, `crate::body::state`) of each source file.
fn modules(root: &Path) -> BTreeMap<String, PathBuf> {
    let mut found = BTreeMap::new();
    let mut folders = vec![root.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("the source folder reads") {
            let path = entry.expect("a folder entry").path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            let relative = path.strip_prefix(root).expect("under the root").with_extension("");
            let mut parts: Vec<String> = relative.iter().map(|p| p.to_string_lossy().into_owned()).collect();
            if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
                parts.pop();
            }
            let name = std::iter::once("crate".to_string()).chain(parts).collect::<Vec<_>>().join("::");
            found.insert(name, path);
        }
    }
    found
}

/// The code of a file without its `#[cfg(test)]` module and without line comments.
fn code(text: &str) -> String {
    let body = text.split("#[cfg(test)]").next().unwrap_or_default();
    body.lines().map(|line| line.split("//").next().unwrap_or_default()).collect::<Vec<_>>().join("\n")
}

/// Every path a `use` tree names: `a::{b, c::{d, e}}` → `a::b`, `a::c::d`, `a::c::e`.
fn expand(tree: &str) -> Vec<String> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        return vec![tree.split(" as ").next().unwrap_or_default().trim().to_string()];
    };
    let prefix = tree[..open].trim_end_matches("::").trim();
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let (mut items, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                items.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    items.push(&inner[start..]);
    items
        .into_iter()
        .filter(|item| !item.trim().is_empty())
        .flat_map(expand)
        .map(|path| if path == "self" { prefix.to_string() } else { format!("{prefix}::{path}") })
        .collect()
}

/// The paths a module's code names: its `use` trees, and the paths inline that start with
/// `crate::`, `super::` or one of the module's `children` (`leapfrog::Leapfrog` in `integrator`).
fn named_paths(code: &str, children: &[&str]) -> Vec<String> {
    let mut paths = Vec::new();
    for statement in code.split(';') {
        let statement = statement.trim();
        let tree = statement
            .strip_prefix("pub use ")
            .or_else(|| statement.strip_prefix("pub(crate) use "))
            .or_else(|| statement.strip_prefix("use "));
        if let Some(tree) = tree {
            let child = |path: &String| children.iter().any(|c| path.split("::").next() == Some(c));
            paths
                .extend(expand(tree).into_iter().map(|path| if child(&path) { format!("self::{path}") } else { path }));
        }
    }
    let bytes = code.as_bytes();
    let starts: Vec<String> = ["crate", "super"].iter().chain(children).map(|s| format!("{s}::")).collect();
    for start in &starts {
        let mut from = 0;
        while let Some(at) = code[from..].find(start) {
            let begin = from + at;
            let boundary = begin == 0
                || !(bytes[begin - 1].is_ascii_alphanumeric() || bytes[begin - 1] == b'_' || bytes[begin - 1] == b':');
            let end = code[begin..]
                .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                .map_or(code.len(), |e| begin + e);
            if boundary {
                let path = code[begin..end].trim_end_matches(':');
                let relative = !path.starts_with("crate::") && !path.starts_with("super::");
                paths.push(if relative { format!("self::{path}") } else { path.to_string() });
            }
            from = end.max(begin + start.len());
        }
    }
    paths
}

/// The module a path names from module `from`: `super` and `crate` resolved, then as deep as
/// the segments go through known modules.
fn target(from: &str, path: &str, known: &BTreeSet<String>) -> Option<String> {
    let mut segments = path.split("::").filter(|s| !s.is_empty()).peekable();
    let mut current: Vec<&str> = match segments.peek() {
        Some(&"crate") => {
            segments.next();
            vec!["crate"]
        }
        Some(&"super" | &"self") => from.split("::").collect(),
        _ => return None,
    };
    while let Some(&segment) = segments.peek() {
        match segment {
            "super" => {
                current.pop();
            }
            "self" => {}
            _ => break,
        }
        segments.next();
    }
    for segment in segments {
        let deeper = format!("{}::{segment}", current.join("::"));
        if !known.contains(&deeper) {
            break;
        }
        current.push(segment);
    }
    Some(current.join("::"))
}

/// A cycle of `graph`, if there is one.
fn cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        state: &mut BTreeMap<String, u8>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        state.insert(node.to_string(), 1);
        stack.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            match state.get(next.as_str()).copied().unwrap_or(0) {
                1 => {
                    let start = stack.iter().position(|n| n == next).unwrap_or(0);
                    return Some(stack[start..].iter().cloned().chain([next.clone()]).collect());
                }
                0 => {
                    if let Some(found) = visit(next, graph, state, stack) {
                        return Some(found);
                    }
                }
                _ => {}
            }
        }
        stack.pop();
        state.insert(node.to_string(), 2);
        None
    }
    let mut state = BTreeMap::new();
    graph
        .keys()
        .find_map(|node| if state.contains_key(node) { None } else { visit(node, graph, &mut state, &mut Vec::new()) })
}

/// The import graph of the physics crate.
fn import_graph() -> BTreeMap<String, BTreeSet<String>> {
    let files = modules(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    let known: BTreeSet<String> = files.keys().cloned().collect();
    let mut graph = BTreeMap::new();
    for (module, file) in &files {
        let text = std::fs::read_to_string(file).expect("a source file reads");
        let prefix = format!("{module}::");
        let children: Vec<&str> =
            known.iter().filter_map(|m| m.strip_prefix(&prefix)).filter(|rest| !rest.contains("::")).collect();
        let edges: BTreeSet<String> = named_paths(&code(&text), &children)
            .iter()
            .filter_map(|p| target(module, p, &known))
            .filter(|t| t != module)
            .collect();
        graph.insert(module.clone(), edges);
    }
    graph
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = import_graph();
    // `TETHER_PRINT_IMPORTS=1 cargo test -p tether-physics --test architecture -- --nocapture`
    // prints the graph (docs/architecture.md shows it).
    if std::env::var_os("TETHER_PRINT_IMPORTS").is_some() {
        for (module, edges) in &graph {
            let edges: Vec<&str> = edges.iter().map(|e| e.trim_start_matches("crate::")).collect();
            println!("{} → {}", module.trim_start_matches("crate::"), edges.join(", "));
        }
    }
    assert!(graph.len() > 30, "the physics crate's modules were found: {:?}", graph.keys());
    if let Some(found) = cycle(&graph) {
        panic!("import circle: {}", found.join(" → "));
    }
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
    assert_eq!(graph_edges_of_a(&paths_a, &known), ["crate::a::b".to_string()].into(), "a names its child b");
    let graph: BTreeMap<String, BTreeSet<String>> = [
        ("crate::a".to_string(), edges("crate::a", &paths_a)),
        ("crate::a::b".to_string(), edges("crate::a::b", &paths_b)),
    ]
    .into();
    assert_eq!(graph["crate::a::b"], ["crate::a".to_string()].into(), "b names its parent's item: {graph:?}");
    assert!(cycle(&graph).is_some(), "{graph:?}");
    assert_eq!(
        expand("crate::x::{a, b::{c, d as e}, self}"),
        ["crate::x::a", "crate::x::b::c", "crate::x::b::d", "crate::x"]
    );
}

/// The edges of module `crate::a` for `paths`.
fn graph_edges_of_a(paths: &[String], known: &BTreeSet<String>) -> BTreeSet<String> {
    paths.iter().filter_map(|p| target("crate::a", p, known)).filter(|t| t != "crate::a").collect()
}

#[test]
fn the_physics_crate_names_no_gui_viewer_or_file_format() {
    let files = modules(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src"));
    for (module, file) in files {
        let text = code(&std::fs::read_to_string(&file).expect("a source file reads"));
        for forbidden in ["rerun", "egui", "eframe", "ron::", "tobj", "stl_io"] {
            assert!(!text.contains(forbidden), "{module} ({}) names {forbidden}", file.display());
        }
    }
}
