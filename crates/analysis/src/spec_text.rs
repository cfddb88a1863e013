//! A spec file's text — a sweep's, a fit's, a storm's: RON read with the scene files' options,
//! and every problem placed in it as `spec.ron:line:col: message` — and the part every spec
//! shares, the scene values a factor or a parameter sets ([`PathsDef`], each one a
//! [`crate::value_path::ValuePath`]).

use serde::Deserialize;
use std::path::Path;
use tether_scene::source::Source;

/// `"couplings.mooring1.stiffness"` or a list of such paths.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(untagged)]
pub enum PathsDef {
    One(String),
    Many(Vec<String>),
}

impl PathsDef {
    pub fn paths(&self) -> &[String] {
        match self {
            Self::One(path) => std::slice::from_ref(path),
            Self::Many(paths) => paths,
        }
    }
}

/// A problem with a spec file, placed in its text.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path}:{line}:{col}: {message}")]
pub struct SpecError {
    pub path: String,
    pub line: usize,
    pub col: usize,
    pub message: String,
}

/// A spec file's text, to place problems in it.
pub struct SpecText<'a> {
    pub path: &'a Path,
    pub text: &'a str,
}

impl SpecText<'_> {
    /// Parses the spec (a sweep's [`crate::sweep::spec::SpecFile`], or another spec in its style: a fit's).
    ///
    /// # Errors
    /// A syntax error or a value of the wrong type, at its line and column.
    pub fn parse<T: serde::de::DeserializeOwned>(&self) -> Result<T, SpecError> {
        let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
        options.from_str(self.text).map_err(|e| SpecError {
            path: self.path.display().to_string(),
            line: e.position.line.max(1),
            col: e.position.col.max(1),
            message: e.code.to_string(),
        })
    }

    /// `message` placed at the first string literal `"literal"`, or at the first `field:` if
    /// there is no such literal, else at the start of the file.
    pub fn error_at(&self, literal: &str, field: &str, message: impl Into<String>) -> SpecError {
        let source = Source::new(self.text);
        let offset = source.literal(0, literal).or_else(|| source.field(0, field)).unwrap_or(0);
        let (line, col) = source.line_col(offset);
        SpecError { path: self.path.display().to_string(), line, col, message: message.into() }
    }

    /// `message` placed at the first `field:` at or after the string literal `"literal"`.
    pub fn error_after(&self, literal: &str, field: &str, message: impl Into<String>) -> SpecError {
        let source = Source::new(self.text);
        let start = source.literal(0, literal).unwrap_or(0);
        let offset = source.field(start, field).unwrap_or(start);
        let (line, col) = source.line_col(offset);
        SpecError { path: self.path.display().to_string(), line, col, message: message.into() }
    }
}
