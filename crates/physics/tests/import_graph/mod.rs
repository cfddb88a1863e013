//! A crate's module import graph, read from its sources, and the workspace's crate layers: what
//! every crate's `tests/architecture.rs` checks (they include this file with `#[path]`; it is no
//! test target of its own). From a crate root (`lib.rs`, `main.rs`), the modules are those its
//! `mod name;` declarations reach; every `use` and every `crate::…`/`super::…`/`child::…` path
//! outside test modules is an edge from the module that writes it to the module it names. The
//! graph must have no cycle (docs/architecture.md). How a module naming one of its ancestors
//! counts is the crate's choice of [`Ancestors`].

#![allow(dead_code, reason = "each crate's test uses the part it checks")]

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The workspace's crates from the bottom layer up: each may depend only on those before it.
pub const LAYERS: [&str; 5] = ["tether-physics", "tether-scene", "tether-record", "tether-analysis", "tether"];

/// The folder of the crate whose test runs (`CARGO_MANIFEST_DIR`, which cargo sets for it).
pub fn crate_dir() -> PathBuf {
    PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"))
}

/// The library root (`src/lib.rs`) of the crate whose test runs.
pub fn library_root() -> PathBuf {
    crate_dir().join("src/lib.rs")
}

/// Module → the modules it names.
pub type Graph = BTreeMap<String, BTreeSet<String>>;

/// Whether a module naming an item of one of its ancestors (`super::Item`, `crate::Item`) is an
/// edge of the graph.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ancestors {
    /// It is: a parent module only declares its children and re-exports from them, nothing
    /// imports from it (the physics crate's rule).
    Edges,
    /// It is not: a module's ancestors are its scope (Rust gives it their private items), so a
    /// parent may hold what its children share; circles between modules that are not each
    /// other's ancestors still fail.
    InScope,
}

/// Module path (`crate`, `crate::body::state`) of each source file the crate root `root_file`
/// declares, following its `mod name;` declarations (`name.rs` or `name/mod.rs`).
pub fn modules(root_file: &Path) -> BTreeMap<String, PathBuf> {
    let mut found = BTreeMap::new();
    let mut pending = vec![("crate".to_string(), root_file.to_path_buf())];
    while let Some((module, file)) = pending.pop() {
        let text = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let folder = match file.file_stem().and_then(|s| s.to_str()) {
            Some("mod" | "lib" | "main") => file.parent().map(Path::to_path_buf),
            _ => file.parent().zip(file.file_stem()).map(|(parent, stem)| parent.join(stem)),
        }
        .unwrap_or_else(|| panic!("{} is in a folder", file.display()));
        for child in declared_modules(&code(&text)) {
            let flat = folder.join(format!("{child}.rs"));
            let nested = folder.join(&child).join("mod.rs");
            let path = if flat.exists() { flat } else { nested };
            assert!(
                path.exists(),
                "{module} declares `mod {child};`, which is in neither {child}.rs nor {child}/mod.rs"
            );
            pending.push((format!("{module}::{child}"), path));
        }
        found.insert(module, file);
    }
    found
}

/// The names of the `mod name;` declarations (file modules) in `code`.
fn declared_modules(code: &str) -> Vec<String> {
    code.split(';')
        .filter_map(|statement| {
            let words: Vec<&str> = statement.split_whitespace().collect();
            match words.as_slice() {
                [.., "mod", name] if name.chars().all(|c| c.is_alphanumeric() || c == '_') => Some((*name).to_string()),
                _ => None,
            }
        })
        .collect()
}

/// The code of a file without its `#[cfg(test)]` module and without line comments.
pub fn code(text: &str) -> String {
    let body = text.split("#[cfg(test)]").next().unwrap_or_default();
    body.lines().map(|line| line.split("//").next().unwrap_or_default()).collect::<Vec<_>>().join("\n")
}

/// Every path a `use` tree names: `a::{b, c::{d, e}}` → `a::b`, `a::c::d`, `a::c::e`.
pub fn expand(tree: &str) -> Vec<String> {
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
pub fn named_paths(code: &str, children: &[&str]) -> Vec<String> {
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
pub fn target(from: &str, path: &str, known: &BTreeSet<String>) -> Option<String> {
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

/// A cycle of `graph`, if there is one: its modules in order, the first one again at the end.
pub fn cycle(graph: &Graph) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &Graph,
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

/// Every cycle of `graph` one at a time: a cycle found, its last edge taken out, again, until
/// none is left (each circle of modules is reported, not only the first).
pub fn cycles(graph: &Graph) -> Vec<Vec<String>> {
    let mut rest = graph.clone();
    let mut found = Vec::new();
    while let Some(circle) = cycle(&rest) {
        let (from, to) = (&circle[circle.len() - 2], &circle[circle.len() - 1]);
        if let Some(edges) = rest.get_mut(from) {
            edges.remove(to);
        }
        found.push(circle);
    }
    found
}

/// Whether `ancestor` is `module`'s parent, or its parent's, up to the crate root.
fn is_ancestor(ancestor: &str, module: &str) -> bool {
    module.strip_prefix(ancestor).is_some_and(|rest| rest.starts_with("::"))
}

/// The import graph of the crate whose root file is `root_file`, edges to ancestors kept or not.
pub fn import_graph(root_file: &Path, ancestors: Ancestors) -> Graph {
    let files = modules(root_file);
    let known: BTreeSet<String> = files.keys().cloned().collect();
    let mut graph = BTreeMap::new();
    for (module, file) in &files {
        let text = std::fs::read_to_string(file).unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let prefix = format!("{module}::");
        let children: Vec<&str> =
            known.iter().filter_map(|m| m.strip_prefix(&prefix)).filter(|rest| !rest.contains("::")).collect();
        let edges: BTreeSet<String> = named_paths(&code(&text), &children)
            .iter()
            .filter_map(|p| target(module, p, &known))
            .filter(|t| t != module)
            .filter(|t| ancestors == Ancestors::Edges || !is_ancestor(t, module))
            .collect();
        graph.insert(module.clone(), edges);
    }
    graph
}

/// Fails, listing every circle, if a module of the crate rooted at `root_file` imports one that
/// imports it back; `at_least` modules must have been found (the reader reads the crate).
/// `TETHER_PRINT_IMPORTS=1 cargo test -p CRATE --test architecture -- --nocapture` prints the
/// graph.
pub fn assert_no_circle(root_file: &Path, ancestors: Ancestors, at_least: usize) -> Graph {
    let graph = import_graph(root_file, ancestors);
    if std::env::var_os("TETHER_PRINT_IMPORTS").is_some() {
        println!("{}:", root_file.display());
        for (module, edges) in &graph {
            let edges: Vec<&str> = edges.iter().map(|e| e.trim_start_matches("crate::")).collect();
            println!("{} → {}", module.trim_start_matches("crate::"), edges.join(", "));
        }
    }
    assert!(graph.len() >= at_least, "{}: only these modules were found: {:?}", root_file.display(), graph.keys());
    let circles: Vec<String> = cycles(&graph).iter().map(|c| c.join(" → ")).collect();
    assert!(circles.is_empty(), "{}: import circles:\n{}", root_file.display(), circles.join("\n"));
    graph
}

/// The workspace crates (`tether-…`) in the `[dependencies]` of the manifest `cargo_toml`.
pub fn workspace_dependencies(cargo_toml: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(cargo_toml).unwrap_or_else(|e| panic!("{}: {e}", cargo_toml.display()));
    let mut section = "";
    let mut found = Vec::new();
    for line in text.lines().map(str::trim) {
        if line.starts_with('[') {
            section = line;
        } else if section == "[dependencies]" {
            let name = line.split(['=', '.', ' ']).next().unwrap_or_default();
            if LAYERS.contains(&name) {
                found.push(name.to_string());
            }
        }
    }
    found
}

/// Fails if the crate `name` (one of [`LAYERS`]), whose manifest is `cargo_toml`, depends on a
/// workspace crate of its own layer or above, or if its code (`root_file`'s modules) names one
/// of `forbidden` (a library its layer must not know).
pub fn assert_layered(name: &str, cargo_toml: &Path, root_file: &Path, forbidden: &[&str]) {
    let layer = LAYERS.iter().position(|l| *l == name).unwrap_or_else(|| panic!("{name} is not one of {LAYERS:?}"));
    for dependency in workspace_dependencies(cargo_toml) {
        let below = LAYERS[..layer].contains(&dependency.as_str());
        assert!(below, "{name} depends on {dependency}, which is not below it in {LAYERS:?}");
    }
    for (module, file) in modules(root_file) {
        let text = code(&std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{}: {e}", file.display())));
        for word in forbidden {
            assert!(!text.contains(word), "{name}: {module} ({}) names {word}", file.display());
        }
    }
}
