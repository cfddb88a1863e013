//! MoorDyn input files in and out (`docs/moordyn-files.md`): a MoorDyn v2 or v1 (OpenFAST)
//! input file read into a scene ([`import`], [`load`]), and a scene's lines written as a
//! MoorDyn v2 file ([`export::export`]).
//!
//! The reader is hand-written: no Rust crate reads MoorDyn files (crates.io has none; MoorDyn
//! itself is C++ with a Python wrapper, and MoorPy's reader is Python), and the format is a
//! few whitespace-separated tables under `---` titles, which [`reader`] cuts as MoorDyn's own
//! `findStartOfSection` does; a parser generator (nom, pest) would add a grammar for what is a
//! table. Stages: [`reader`] (text → sections of fields with line and column) → [`input`]
//! (typed, checked, with what Tether cannot model refused or warned of) → [`mapping`] (a
//! [`SceneFile`](crate::SceneFile)) → [`settle`] (free points and bodies at static equilibrium)
//! → [`ron_text`] (readable RON) → the scene loader, whose
//! errors are reported at the MoorDyn file's line.

pub mod export;
pub mod input;
pub mod mapping;
pub mod reader;
pub mod ron_text;
pub mod settle;

use crate::{Scene, SceneError};
use std::path::Path;

/// A problem at a line and column of a MoorDyn file (1-based), before the file's path is added.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Located {
    pub line: usize,
    pub col: usize,
    pub message: String,
}

impl Located {
    fn at(self, path: &Path) -> SceneError {
        SceneError { path: path.display().to_string(), line: self.line, col: self.col, message: self.message }
    }
}

/// A MoorDyn file read as a scene: its RON text (what `tether import` writes), the map from that
/// text's lines to the file's, and the warnings, each `line N: …` of the file.
pub struct Imported {
    pub written: ron_text::Written,
    pub warnings: Vec<String>,
}

/// Whether the file at `path` with `text` is a MoorDyn input file rather than a RON scene: not
/// named `.ron`, and one of its `---` lines is MoorDyn's banner or titles one of its sections.
pub fn is_moordyn(path: &Path, text: &str) -> bool {
    path.extension().is_none_or(|e| e != "ron") && text.lines().any(reader::is_title)
}

/// Reads the MoorDyn file `text` (at `path`, which labels errors) into commented RON.
///
/// # Errors
/// The first problem of the file, `path:line:col: message`.
pub fn import(text: &str, path: &Path) -> Result<Imported, SceneError> {
    let (sections, last) = reader::sections(text).map_err(|e| e.at(path))?;
    let input = input::read(&sections, last).map_err(|e| e.at(path))?;
    let mut mapped = mapping::map(&input).map_err(|e| e.at(path))?;
    mapped.file = settle::settle(mapped.file, &mut mapped.warnings);
    let name = path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned());
    let written = ron_text::write(&input, &mapped, &name).map_err(|e| SceneError {
        path: path.display().to_string(),
        line: 1,
        col: 1,
        message: format!("cannot write the imported scene as RON: {e}"),
    })?;
    let warnings = mapped.warnings.iter().map(|w| format!("line {}: {}", w.line, w.message)).collect();
    Ok(Imported { written, warnings })
}

/// Reads the MoorDyn file `text` at `path` and builds its scene; the scene's text is the
/// imported RON. A value the physics refuses (a damping ratio above 1, …) is reported at the
/// line of the MoorDyn file the body or line comes from.
///
/// # Errors
/// As [`import`], then the scene's build.
pub fn load(text: &str, path: &Path) -> Result<Scene, SceneError> {
    let imported = import(text, path)?;
    let mut scene = crate::parse(&imported.written.text, path).map_err(|error| SceneError {
        line: ron_text::file_line(&imported.written, error.line),
        col: 1,
        message: format!("as imported: {}", error.message),
        ..error
    })?;
    scene.warnings.splice(0..0, imported.warnings);
    Ok(scene)
}
