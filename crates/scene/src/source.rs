//! Finds where things are in a scene file's text, so every error carries `line:col`.
//!
//! Syntax and value errors get their position from the RON parser. Errors found after parsing
//! (a duplicate name, an unknown body, a non-positive mass) are placed by finding the item's
//! `name: "…"` in the text, then the offending field after it.

/// The text of a scene file.
pub struct Source<'a> {
    text: &'a str,
}

/// Which list an item is in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ItemKind {
    Body,
    Coupling,
}

impl ItemKind {
    pub fn label(self) -> &'static str {
        match self {
            Self::Body => "body",
            Self::Coupling => "coupling",
        }
    }

    fn list(self) -> &'static str {
        match self {
            Self::Body => "bodies",
            Self::Coupling => "couplings",
        }
    }
}

impl<'a> Source<'a> {
    pub fn new(text: &'a str) -> Self {
        Self { text }
    }

    /// 1-based line and column of byte `offset`.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let before = &self.text[..offset.min(self.text.len())];
        let line = before.matches('\n').count() + 1;
        let col = before.rfind('\n').map_or(before.chars().count(), |nl| before[nl + 1..].chars().count()) + 1;
        (line, col)
    }

    /// Byte offset of 1-based `line`, `col`.
    pub fn offset(&self, line: usize, col: usize) -> usize {
        let line_start: usize = self.text.split_inclusive('\n').take(line.saturating_sub(1)).map(str::len).sum();
        let rest = &self.text[line_start.min(self.text.len())..];
        line_start + rest.char_indices().nth(col.saturating_sub(1)).map_or(rest.len(), |(i, _)| i)
    }

    /// Offset of the `occurrence`-th (0-based) `name: "<name>"` of the `kind` list.
    pub fn item(&self, kind: ItemKind, name: &str, occurrence: usize) -> Option<usize> {
        let list_start = self.field(0, kind.list())?;
        let literal = format!("\"{name}\"");
        let mut found = 0;
        let mut from = list_start;
        // Ends: each pass moves `from` past the literal it found.
        while let Some(at) = self.text[from..].find(&literal).map(|i| i + from) {
            if self.is_name_field(at) {
                if found == occurrence {
                    return Some(at);
                }
                found += 1;
            }
            from = at + literal.len();
        }
        None
    }

    fn is_name_field(&self, literal_at: usize) -> bool {
        let before = self.text[..literal_at].trim_end();
        before.strip_suffix(':').is_some_and(|b| b.trim_end().ends_with("name"))
    }

    /// Offset of the first `field:` at or after `from` (a whole identifier followed by a colon).
    pub fn field(&self, from: usize, field: &str) -> Option<usize> {
        let mut search = from;
        // Ends: each pass moves `search` past the word it found.
        while let Some(at) = self.text[search..].find(field).map(|i| i + search) {
            let end = at + field.len();
            let starts_word = at == 0 || !is_ident(self.text[..at].chars().next_back());
            let ends_word = !is_ident(self.text[end..].chars().next());
            if starts_word && ends_word && self.text[end..].trim_start().starts_with(':') {
                return Some(at);
            }
            search = end;
        }
        None
    }

    /// Offset of the first string literal `"value"` at or after `from`.
    pub fn literal(&self, from: usize, value: &str) -> Option<usize> {
        self.text[from..].find(&format!("\"{value}\"")).map(|i| i + from)
    }

    /// The body or coupling whose `name: "…"` comes last before `offset`, for messages.
    pub fn enclosing_item(&self, offset: usize) -> Option<(ItemKind, String)> {
        let before = &self.text[..offset.min(self.text.len())];
        let mut search_end = before.len();
        // Ends: each pass ends the search before the `name` it found.
        while let Some(at) = before[..search_end].rfind("name") {
            search_end = at;
            let rest = before[at + 4..].trim_start();
            let Some(rest) = rest.strip_prefix(':') else { continue };
            let Some(rest) = rest.trim_start().strip_prefix('"') else { continue };
            let Some(end) = rest.find('"') else { continue };
            // A broken file can pair quotes across lines: only a real name is quoted back.
            let name = &rest[..end];
            if name.is_empty() || !name.chars().all(|c| c.is_alphanumeric() || "_-.".contains(c)) {
                continue;
            }
            let kind = match (before[..at].rfind("bodies"), before[..at].rfind("couplings")) {
                (Some(b), Some(c)) if c > b => ItemKind::Coupling,
                (None, Some(_)) => ItemKind::Coupling,
                _ => ItemKind::Body,
            };
            return Some((kind, name.to_string()));
        }
        None
    }
}

fn is_ident(c: Option<char>) -> bool {
    c.is_some_and(|c| c.is_alphanumeric() || c == '_')
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "Scene(\n  dt: 0.1,\n  bodies: [\n    Body(name: \"a\", master: Node(mass: 1.0)),\n    Body(name: \"a\"),\n  ],\n  couplings: [ SpringDamper(name: \"s\", end1: Body(body: \"a\")) ],\n)";

    #[test]
    fn finds_items_fields_and_positions() {
        let s = Source::new(TEXT);
        let second = s.item(ItemKind::Body, "a", 1).unwrap();
        assert_eq!(s.line_col(second), (5, 16));
        let first = s.item(ItemKind::Body, "a", 0).unwrap();
        assert_eq!(s.line_col(s.field(first, "mass").unwrap()), (4, 34));
        assert_eq!(s.line_col(s.field(0, "dt").unwrap()), (2, 3));
        let coupling = s.item(ItemKind::Coupling, "s", 0).unwrap();
        assert_eq!(s.line_col(s.literal(coupling + 3, "a").unwrap()), (7, 57));
        assert_eq!(s.offset(5, 16), second);
        assert_eq!(s.enclosing_item(s.offset(7, 60)), Some((ItemKind::Coupling, "s".into())));
        assert_eq!(s.enclosing_item(s.offset(4, 40)), Some((ItemKind::Body, "a".into())));
    }
}
