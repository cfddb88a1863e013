//! The scene file written again with fitted values in place: the user's text, comments and
//! layout kept, each fitted number replaced where it stands, and a comment at the top saying what
//! was fitted to what, and when (docs/calibration.md, "The fitted scene").
//!
//! The text is read by a small RON scanner (`Node`: composites with their fields or items, and
//! scalar tokens, each with its byte span; comments and strings skipped) and walked by the
//! value path's steps — a field, an enum's variant (the composite's name), a list's item. A value
//! the scene leaves to its default is inserted as the first field of the innermost composite the
//! text has, its text taken from the fitted scene file serialised by the scene crate.
//! Considered: editing through `ron`'s serde data (loses every comment) and a full RON syntax
//! tree crate (none kept spans and is maintained); the scanner is the part of RON the scene
//! files use.

use crate::value_path::{Step, ValuePath};

/// A value in RON text, with its byte span.
#[derive(Debug, Clone, PartialEq)]
enum Node {
    /// `Name(…)`, `(…)`, `[…]` or `{…}`: `open` at the bracket, `end` past the closing one.
    Composite { name: Option<String>, open: usize, end: usize, fields: Vec<(String, Node)>, items: Vec<Node> },
    /// A number, string, identifier or other token.
    Scalar { start: usize, end: usize },
}

impl Node {
    fn end(&self) -> usize {
        match self {
            Self::Composite { end, .. } | Self::Scalar { end, .. } => *end,
        }
    }
}

struct Scanner<'a> {
    text: &'a [u8],
    at: usize,
}

impl Scanner<'_> {
    /// Skips whitespace and comments (`//…`, nested `/* … */`).
    fn skip(&mut self) {
        loop {
            while self.at < self.text.len() && self.text[self.at].is_ascii_whitespace() {
                self.at += 1;
            }
            if self.text[self.at..].starts_with(b"//") {
                while self.at < self.text.len() && self.text[self.at] != b'\n' {
                    self.at += 1;
                }
            } else if self.text[self.at..].starts_with(b"/*") {
                let mut depth = 0;
                while self.at < self.text.len() {
                    if self.text[self.at..].starts_with(b"/*") {
                        depth += 1;
                        self.at += 2;
                    } else if self.text[self.at..].starts_with(b"*/") {
                        depth -= 1;
                        self.at += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        self.at += 1;
                    }
                }
            } else {
                return;
            }
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip();
        self.text.get(self.at).copied()
    }

    /// One value.
    fn value(&mut self) -> Result<Node, String> {
        let start = {
            self.skip();
            self.at
        };
        match self.peek() {
            None => Err("the file ends where a value belongs".into()),
            Some(b'(' | b'[' | b'{') => self.composite(None),
            Some(b'"') => {
                self.string();
                Ok(Node::Scalar { start, end: self.at })
            }
            Some(_) => {
                while self.at < self.text.len() && is_token(self.text[self.at]) {
                    self.at += 1;
                }
                if self.at == start {
                    return Err(format!("unexpected `{}` at byte {start}", self.text[start] as char));
                }
                let word = String::from_utf8_lossy(&self.text[start..self.at]).into_owned();
                if self.peek() == Some(b'(') && word.chars().next().is_some_and(char::is_alphabetic) {
                    self.composite(Some(word))
                } else {
                    Ok(Node::Scalar { start, end: self.at })
                }
            }
        }
    }

    fn string(&mut self) {
        self.at += 1;
        while self.at < self.text.len() && self.text[self.at] != b'"' {
            if self.text[self.at] == b'\\' {
                self.at += 1;
            }
            self.at += 1;
        }
        self.at += 1;
    }

    /// A bracketed composite; `name` before it.
    fn composite(&mut self, name: Option<String>) -> Result<Node, String> {
        let open = self.at;
        let close = match self.text[open] {
            b'(' => b')',
            b'[' => b']',
            _ => b'}',
        };
        self.at += 1;
        let (mut fields, mut items) = (Vec::new(), Vec::new());
        loop {
            match self.peek() {
                None => return Err("the file ends inside a bracket".into()),
                Some(c) if c == close => {
                    self.at += 1;
                    return Ok(Node::Composite { name, open, end: self.at, fields, items });
                }
                Some(b',') => self.at += 1,
                Some(_) => {
                    let value = self.value()?;
                    if self.peek() == Some(b':') {
                        self.at += 1;
                        let key = match &value {
                            Node::Scalar { start, end } => {
                                String::from_utf8_lossy(&self.text[*start..*end]).into_owned()
                            }
                            Node::Composite { .. } => String::new(),
                        };
                        let inner = self.value()?;
                        fields.push((key, inner));
                    } else {
                        items.push(value);
                    }
                }
            }
        }
    }
}

fn is_token(c: u8) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, b'_' | b'.' | b'-' | b'+')
}

fn parse(text: &str) -> Result<Node, String> {
    Scanner { text: text.as_bytes(), at: 0 }.value()
}

/// Where a path's value is in the text: its token's span, or the composite a missing field goes
/// into and the index of the first step the text lacks.
enum Found<'n> {
    Value { start: usize, end: usize },
    Missing { composite: &'n Node, from_step: usize },
}

fn find<'n>(root: &'n Node, steps: &[Step], into_variant: bool) -> Result<Found<'n>, String> {
    let mut node = root;
    let mut k = 0;
    while k < steps.len() {
        node = through_some(node);
        let Node::Composite { name, fields, items, .. } = node else {
            return Err("the path goes inside a single value".into());
        };
        match &steps[k] {
            Step::Key(key) if name.as_deref() == Some(key.as_str()) => {}
            Step::Key(key) => match fields.iter().find(|(f, _)| f == key) {
                Some((_, value)) => node = value,
                None => return Ok(Found::Missing { composite: node, from_step: k }),
            },
            Step::Index(i) => node = items.get(*i).ok_or_else(|| format!("the text has no item {i} there"))?,
        }
        k += 1;
    }
    node = through_some(node);
    match node {
        Node::Scalar { start, end } => Ok(Found::Value { start: *start, end: *end }),
        Node::Composite { items, .. } if into_variant && items.len() == 1 => match &items[0] {
            Node::Scalar { start, end } => Ok(Found::Value { start: *start, end: *end }),
            Node::Composite { .. } => Err("the path ends at a composite value".into()),
        },
        Node::Composite { .. } => Err("the path ends at a composite value".into()),
    }
}

/// `Some(x)` read as `x` (the scene data do not show the option).
fn through_some(node: &Node) -> &Node {
    match node {
        Node::Composite { name: Some(name), items, fields, .. }
            if name == "Some" && items.len() == 1 && fields.is_empty() =>
        {
            &items[0]
        }
        other => other,
    }
}

/// One fitted value to write.
pub struct Edit<'a> {
    pub path: &'a ValuePath,
    pub value: f64,
}

/// `text` (a scene file) with each edit's value written at its path, `header` (comment lines,
/// each starting `// `) at the top in place of any header an earlier fit wrote; `fitted_ron` is
/// the fitted scene file as the scene crate serialises it, from which a value the text leaves to
/// its default is taken.
///
/// # Errors
/// A text the scanner cannot read, or a path it cannot place.
pub fn write(text: &str, edits: &[Edit<'_>], header: &str, fitted_ron: &str) -> Result<String, String> {
    let root = parse(text)?;
    // Read only when a value must be inserted.
    let generated = std::cell::OnceCell::new();
    // Replacements as (start, end, new text), applied from the back.
    let mut changes: Vec<(usize, usize, String)> = Vec::new();
    for edit in edits {
        let steps = edit.path.steps();
        let number = number(edit.value);
        match find(&root, steps, edit.path.into_variant()).map_err(|m| format!("`{}`: {m}", edit.path.text))? {
            Found::Value { start, end } => {
                // An integer literal (a count) stays one.
                let is_integer = text[start..end].bytes().all(|b| b.is_ascii_digit() || b == b'-' || b == b'+');
                let written = if is_integer { format!("{}", edit.value.round() as i64) } else { number };
                changes.push((start, end, written));
            }
            Found::Missing { composite, from_step } => {
                let Step::Key(key) = &steps[from_step] else {
                    return Err(format!("`{}`: the text lacks a list item", edit.path.text));
                };
                // The fitted file has every value, so the missing field's text is there.
                let generated = match generated.get() {
                    Some(node) => node,
                    None => {
                        let node = parse(fitted_ron)?;
                        generated.get_or_init(|| node)
                    }
                };
                let inserted = subtree_text(generated, &steps[..=from_step], fitted_ron)
                    .ok_or_else(|| format!("`{}`: no value to insert", edit.path.text))?;
                let Node::Composite { open, .. } = composite else { continue };
                let indent = field_indent(text, composite);
                changes.push((open + 1, open + 1, format!("{indent}{key}: {inserted},")));
            }
        }
    }
    changes.sort_by_key(|c| std::cmp::Reverse(c.0));
    let mut out = text.to_string();
    for (start, end, new) in changes {
        out.replace_range(start..end, &new);
    }
    Ok(format!("{header}{}", without_old_header(&out)))
}

/// The text of the composite at `steps` in the generated file.
fn subtree_text(root: &Node, steps: &[Step], text: &str) -> Option<String> {
    let mut node = root;
    for step in steps {
        node = through_some(node);
        let Node::Composite { name, fields, items, .. } = node else { return None };
        match step {
            Step::Key(key) if name.as_deref() == Some(key.as_str()) => {}
            Step::Key(key) => node = &fields.iter().find(|(f, _)| f == key)?.1,
            Step::Index(i) => node = items.get(*i)?,
        }
    }
    let start = match node {
        Node::Composite { name: Some(name), open, .. } => open - name.len(),
        Node::Composite { open, .. } => *open,
        Node::Scalar { start, .. } => *start,
    };
    Some(text[start..node.end()].to_string())
}

/// What goes before a field inserted first in `composite`: a new line and the indent of its
/// first field when the composite spans lines, else nothing.
fn field_indent(text: &str, composite: &Node) -> String {
    let Node::Composite { open, end, .. } = composite else { return String::new() };
    let inside = &text[open + 1..end - 1];
    match inside.find('\n') {
        Some(newline) => {
            let rest = &inside[newline + 1..];
            let indent: String = rest.chars().take_while(|c| *c == ' ' || *c == '\t').collect();
            format!("\n{indent}")
        }
        None => String::new(),
    }
}

/// The header comment lines a fit writes start with this.
pub const HEADER_MARK: &str = "// Fitted by `tether fit`";

/// `text` without the header an earlier fit wrote (its lines start with `// ` after a
/// [`HEADER_MARK`] line, up to the first line that does not).
fn without_old_header(text: &str) -> &str {
    if !text.starts_with(HEADER_MARK) {
        return text;
    }
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        if !line.starts_with("//   ") && !line.starts_with(HEADER_MARK) {
            break;
        }
        offset += line.len();
    }
    &text[offset..]
}

/// A fitted number as the scene file writes it: 7 significant digits, always with a decimal
/// point or exponent (so RON reads it as a real).
fn number(x: f64) -> String {
    let text = format!("{:.6e}", x);
    // `1.234560e5` → shortest form of the rounded value.
    let rounded: f64 = text.parse().unwrap_or(x);
    let plain = format!("{rounded:?}");
    if plain.len() <= 12 { plain } else { text }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    const SCENE: &str = r#"// A spring.
Scene(
    dt: 0.001, // the step
    bodies: [
        Body(name: "mass", master: Node(position: (1.01, 0.0, 0.0), mass: 1.0)),
    ],
    couplings: [
        SpringDamper(
            name: "spring",
            law: Linear(stiffness: 100.0, rest_length: 1.0), /* k */
            damping: 1.0,
        ),
    ],
    substeps: Fixed(2),
)
"#;

    fn tree() -> serde_json::Value {
        json!({
            "dt": 0.001,
            "bodies": [{"name": "mass", "master": {"position": [1.01, 0.0, 0.0], "mass": 1.0}}],
            "couplings": [{"SpringDamper": {"name": "spring", "law": {"Linear": {"stiffness": 100.0, "rest_length": 1.0}}, "damping": 1.0}}],
            "substeps": {"Fixed": 2},
        })
    }

    #[test]
    fn writes_values_in_place_keeping_comments() {
        let t = tree();
        let paths: Vec<ValuePath> =
            ["couplings.spring.law.stiffness", "couplings.spring.damping", "bodies.mass.master.position.0", "substeps"]
                .iter()
                .map(|p| ValuePath::find(&t, p).unwrap())
                .collect();
        let edits = [
            Edit { path: &paths[0], value: 123.4567891 },
            Edit { path: &paths[1], value: 0.5 },
            Edit { path: &paths[2], value: 1.02 },
            Edit { path: &paths[3], value: 4.0 },
        ];
        let header = format!("{HEADER_MARK} on a date\n//   k = 123.4568\n");
        let out = write(SCENE, &edits, &header, "").unwrap();
        assert!(out.starts_with(&header));
        assert!(out.contains("law: Linear(stiffness: 123.4568, rest_length: 1.0), /* k */"), "{out}");
        assert!(out.contains("damping: 0.5,"), "{out}");
        assert!(out.contains("position: (1.02, 0.0, 0.0)"), "{out}");
        assert!(out.contains("substeps: Fixed(4)"), "{out}");
        assert!(out.contains("dt: 0.001, // the step"), "{out}");
        // Written again: the old header is replaced, not stacked.
        let again = write(&out, &edits, &header, "").unwrap();
        assert_eq!(again.matches(HEADER_MARK).count(), 1, "{again}");
        assert_eq!(again, out);
    }

    #[test]
    fn inserts_a_value_the_text_leaves_to_its_default() {
        let t = tree();
        let path = ValuePath::find(&t, "couplings.spring.end_damping").unwrap();
        let generated = "Scene(couplings: [SpringDamper(name: \"spring\", end_damping: 2.5, damping: 1.0)])";
        let out = write(SCENE, &[Edit { path: &path, value: 2.5 }], "", generated).unwrap();
        assert!(out.contains("SpringDamper(\n            end_damping: 2.5,\n            name: \"spring\","), "{out}");
    }

    #[test]
    fn numbers_keep_seven_digits_and_read_as_reals() {
        assert_eq!(number(100.0), "100.0");
        assert_eq!(number(0.123456789), "0.1234568");
        assert_eq!(number(2.5e-7), "2.5e-7");
        assert_eq!(number(1.234567891e12), "1.234568e12");
    }
}
