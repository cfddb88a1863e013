//! A MoorDyn input file's text cut into sections of whitespace-separated fields, each field
//! with its line and column, as MoorDyn itself reads it (`MoorDyn2.cpp`, `findStartOfSection`):
//! a line containing `---` opens the section its words name; every other non-blank line
//! belongs to the section above it; the lines before the first section (the title, OpenFAST's
//! `Echo` flag) are free text.

use super::Located;

/// The sections a MoorDyn file may hold, in MoorDyn v2's spellings and v1's (OpenFAST).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SectionKind {
    /// `LINE TYPES` (v2) or `LINE DICTIONARY` (v1).
    LineTypes,
    /// `ROD TYPES` / `ROD DICTIONARY`.
    RodTypes,
    /// `BODIES` / `BODY LIST` / `BODY PROPERTIES`.
    Bodies,
    /// `RODS` / `ROD LIST` / `ROD PROPERTIES`.
    Rods,
    /// `POINTS` / `POINT LIST` / `POINT PROPERTIES` (v2), `CONNECTION PROPERTIES` /
    /// `NODE PROPERTIES` (v1).
    Points,
    /// `LINES` / `LINE LIST` (v2), `LINE PROPERTIES` (v1).
    Lines,
    /// `OPTIONS` / `SOLVER OPTIONS`.
    Options,
    /// `OUTPUTS` / `OUTPUT` / `OUTLIST`.
    Outputs,
    /// `FAILURE`: lines that break.
    Failure,
    /// `SYROPE IC`: a synthetic rope's initial state.
    SyropeInitial,
}

/// Section titles, most specific first (a title is recognised by the first name it contains).
const TITLES: [(&str, SectionKind); 19] = [
    ("LINE TYPES", SectionKind::LineTypes),
    ("LINE DICTIONARY", SectionKind::LineTypes),
    ("ROD TYPES", SectionKind::RodTypes),
    ("ROD DICTIONARY", SectionKind::RodTypes),
    ("BODY LIST", SectionKind::Bodies),
    ("BODY PROPERTIES", SectionKind::Bodies),
    ("BODIES", SectionKind::Bodies),
    ("ROD LIST", SectionKind::Rods),
    ("ROD PROPERTIES", SectionKind::Rods),
    ("RODS", SectionKind::Rods),
    ("POINT LIST", SectionKind::Points),
    ("POINT PROPERTIES", SectionKind::Points),
    ("CONNECTION PROPERTIES", SectionKind::Points),
    ("NODE PROPERTIES", SectionKind::Points),
    ("POINTS", SectionKind::Points),
    ("LINE LIST", SectionKind::Lines),
    ("LINE PROPERTIES", SectionKind::Lines),
    ("LINES", SectionKind::Lines),
    ("OPTIONS", SectionKind::Options),
];

/// Titles of the sections without a table of their own, after [`TITLES`].
const OTHER_TITLES: [(&str, SectionKind); 4] = [
    ("OUTPUT", SectionKind::Outputs),
    ("OUTLIST", SectionKind::Outputs),
    ("FAILURE", SectionKind::Failure),
    ("SYROPE IC", SectionKind::SyropeInitial),
];

/// One whitespace-separated field: its text, 1-based line and column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Field<'a> {
    pub text: &'a str,
    pub line: usize,
    pub col: usize,
}

/// The fields of one line of a section.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Row<'a> {
    pub line: usize,
    pub fields: Vec<Field<'a>>,
}

/// A section: its kind, the title's line and what the file wrote as its title, and its rows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Section<'a> {
    pub kind: SectionKind,
    pub title: String,
    pub line: usize,
    pub rows: Vec<Row<'a>>,
}

/// The sections of `text`, in the file's order; the number of its last line.
///
/// # Errors
/// A `---` line naming no section MoorDyn knows (other than the file's opening banner and its
/// closing `need this line`).
pub fn sections(text: &str) -> Result<(Vec<Section<'_>>, usize), Located> {
    let mut sections: Vec<Section> = Vec::new();
    let mut inside = false;
    let mut last = 1;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        last = line;
        if raw.contains("---") {
            let title = title_of(raw);
            inside = false;
            if title.is_empty() || title.contains("MOORDYN") || title.contains("NEED THIS LINE") {
                continue;
            }
            let kind = kind_of(&title).ok_or_else(|| Located {
                line,
                col: raw.find(|c: char| c.is_alphanumeric()).map_or(1, |c| c + 1),
                message: format!("unknown section \"{title}\" (MoorDyn's sections: LINE TYPES, ROD TYPES, BODIES, RODS, POINTS, LINES, OPTIONS, OUTPUTS, FAILURE)"),
            })?;
            sections.push(Section { kind, title, line, rows: Vec::new() });
            inside = true;
        } else if inside && let Some(section) = sections.last_mut() {
            let fields = fields(raw, line);
            if !fields.is_empty() {
                section.rows.push(Row { line, fields });
            }
        }
    }
    Ok((sections, last))
}

/// Whether `raw` is a `---` line titling a MoorDyn section or MoorDyn's opening banner.
pub fn is_title(raw: &str) -> bool {
    raw.contains("---") && {
        let title = title_of(raw);
        title.contains("MOORDYN") || kind_of(&title).is_some()
    }
}

/// A title line's words, upper case, single-spaced, without its dashes.
fn title_of(raw: &str) -> String {
    raw.replace('-', " ").split_whitespace().collect::<Vec<_>>().join(" ").to_uppercase()
}

fn kind_of(title: &str) -> Option<SectionKind> {
    TITLES.iter().chain(OTHER_TITLES.iter()).find(|(name, _)| title.contains(name)).map(|(_, kind)| *kind)
}

/// The whitespace-separated fields of `raw`, with their columns.
fn fields(raw: &str, line: usize) -> Vec<Field<'_>> {
    let mut found = Vec::new();
    let mut start = None;
    for (offset, c) in raw.char_indices().chain(std::iter::once((raw.len(), ' '))) {
        match (c.is_whitespace(), start) {
            (true, Some(begin)) => {
                found.push(Field { text: &raw[begin..offset], line, col: raw[..begin].chars().count() + 1 });
                start = None;
            }
            (false, None) => start = Some(offset),
            (true, None) | (false, Some(_)) => {}
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn titles_open_sections_and_banners_do_not() {
        let text = "--- MoorDyn Input File ---\ntitle words\n---- LINE DICTIONARY ----\n1 NTypes\nx y\n--- SOLVER OPTIONS ---\n0.1 dtM\n--- need this line ---\n";
        let (found, last) = sections(text).unwrap();
        assert_eq!(last, 8);
        assert_eq!(found.iter().map(|s| s.kind).collect::<Vec<_>>(), [SectionKind::LineTypes, SectionKind::Options]);
        assert_eq!(found[0].rows.len(), 2);
        assert_eq!(found[1].rows[0].fields[1], Field { text: "dtM", line: 7, col: 5 });
    }

    #[test]
    fn an_unknown_title_is_refused_at_its_line() {
        let error = sections("--- LINES ---\n--- WIND TURBINES ---\n").unwrap_err();
        assert_eq!((error.line, error.col), (2, 5));
        assert!(error.message.starts_with("unknown section \"WIND TURBINES\""), "{}", error.message);
    }
}
