//! Scene files for Tether: RON text → [`SceneFile`] (what the file says) → [`World`] (what runs).
//!
//! Every failure is a [`SceneError`] that prints as one line `path:line:col: message`, naming
//! the body or coupling at fault. Loading never panics.

pub mod air;
pub mod build;
pub mod file;
mod finite;
pub mod line_model;
pub mod mesh_file;
pub mod moordyn;
pub mod pose;
pub mod source;
pub mod spelling;
pub mod wamit;
pub mod water;

use build::{Bodies, Place, Problem};
pub use file::SceneFile;
use source::Source;
use std::path::{Path, PathBuf};
use tether_physics::world::World;

/// A scene file that could not be loaded, with the place of the fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path}:{line}:{col}: {message}")]
pub struct SceneError {
    pub path: String,
    pub line: usize,
    pub col: usize,
    pub message: String,
}

/// A loaded scene: its text, the file's data, the world built from it, the built bodies (to
/// build a tuned coupling against), and warnings.
pub struct Scene {
    pub path: PathBuf,
    /// The text the scene was read from.
    pub text: String,
    pub file: SceneFile,
    pub world: World,
    pub bodies: Bodies,
    pub warnings: Vec<String>,
}

/// Reads and builds the scene at `path`: a RON scene, or a MoorDyn input file converted on the
/// way in ([`moordyn::load`]).
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let text = std::fs::read_to_string(path).map_err(|e| SceneError {
        path: path.display().to_string(),
        line: 1,
        col: 1,
        message: format!("cannot read scene file: {e}"),
    })?;
    if moordyn::is_moordyn(path, &text) {
        return moordyn::load(&text, path);
    }
    parse(&text, path)
}

/// Parses and builds scene text; `path` labels errors and locates mesh files.
pub fn parse(text: &str, path: &Path) -> Result<Scene, SceneError> {
    let source = Source::new(text);
    let label = path.display().to_string();
    // Optional sections (`adaptive: (…)`) are written without `Some(…)`.
    let options = ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME);
    let file: SceneFile = options.from_str(text).map_err(|e| syntax_error(&source, &label, &e))?;
    build_variant(text, path, file)
}

/// Builds `file`, a variant of the scene whose text is `text` at `path`: the same bodies and
/// couplings by name, some values changed (a sweep's case, a value typed into the window). The
/// checks are those of [`parse`]; a problem is placed in `text` at the item and field it
/// concerns, so that the message points at the value the variant changed.
pub fn build_variant(text: &str, path: &Path, file: SceneFile) -> Result<Scene, SceneError> {
    let built =
        build::build(&file, directory(path)).map_err(|p| placed(&Source::new(text), &path.display().to_string(), p))?;
    Ok(Scene {
        path: path.to_path_buf(),
        text: text.to_string(),
        file,
        world: built.world,
        bodies: built.bodies,
        warnings: built.warnings,
    })
}

/// The scene with a fresh world at t = 0 under the time step settings of `scene.file` (`dt`,
/// `integrator`, `adaptive`, `substeps`, changed from the command line): see [`world_with_timing`].
pub fn retime(scene: Scene) -> Result<Scene, SceneError> {
    let world = world_with_timing(&scene, &scene.file)?;
    Ok(Scene { world, ..scene })
}

/// A fresh world at t = 0 of `scene`'s system under the time step settings of `file` (`dt`,
/// `integrator`, `adaptive`, `substeps`; nothing else of it is read), checked as loading checks
/// them; no body or mesh is built again. Errors point at the scene's path.
pub fn world_with_timing(scene: &Scene, file: &SceneFile) -> Result<World, SceneError> {
    let at_path = |message: String| SceneError { path: scene.path.display().to_string(), line: 1, col: 1, message };
    let timing = build::timing(file).map_err(|p| at_path(p.message))?;
    World::new(scene.world.system().clone(), timing).map_err(|e| at_path(e.to_string()))
}

/// Every `.ron` file under `dir` (one level of subfolders too), sorted; empty if there is no
/// such folder: the scenes a folder offers.
pub fn list(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut folders = vec![(dir.to_path_buf(), 0)];
    // Ends: only the top folder's subfolders are pushed (depth 0), never theirs.
    while let Some((folder, depth)) = folders.pop() {
        let Ok(entries) = std::fs::read_dir(&folder) else { continue };
        for path in entries.filter_map(|e| e.ok().map(|e| e.path())) {
            if path.is_dir() && depth == 0 {
                folders.push((path, depth + 1));
            } else if path.extension().is_some_and(|e| e == "ron") {
                files.push(path);
            }
        }
    }
    files.sort();
    files
}

/// The scene as RON text that [`parse`] reads back to the same [`SceneFile`] ("save as" after
/// live tuning). Comments of the original file are not kept.
pub fn to_ron(file: &SceneFile) -> Result<String, ron::Error> {
    let config = ron::ser::PrettyConfig::new().struct_names(true);
    ron::ser::to_string_pretty(file, config).map(|text| text + "\n")
}

/// Rewrites the mesh files of `file` (relative to the scene's folder `from`) so they still load
/// when the scene is written into folder `to`: relative paths stay as they are within the same
/// folder and become absolute otherwise.
pub fn relocate_meshes(file: &mut SceneFile, from: &Path, to: &Path) {
    if from == to {
        return;
    }
    for body in &mut file.bodies {
        if let file::ShapeDef::Mesh { file: mesh, .. } = &mut body.shape
            && Path::new(mesh.as_str()).is_relative()
        {
            let absolute = std::path::absolute(from.join(mesh.as_str())).unwrap_or_else(|_| from.join(mesh.as_str()));
            *mesh = absolute.display().to_string();
        }
    }
}

/// The folder of a scene file, where its mesh files are looked up.
fn directory(path: &Path) -> &Path {
    path.parent().unwrap_or(Path::new("."))
}

/// A parser error, with the body or coupling it falls in when there is one.
fn syntax_error(source: &Source, label: &str, error: &ron::error::SpannedError) -> SceneError {
    let (line, col) = (error.position.line.max(1), error.position.col.max(1));
    let mut message = error.code.to_string();
    if let Some((kind, name)) = source.enclosing_item(source.offset(line, col)) {
        message = format!("{} \"{name}\": {message}", kind.label());
    }
    SceneError { path: label.to_string(), line, col, message }
}

/// A build problem, placed in the text.
fn placed(source: &Source, label: &str, problem: Problem) -> SceneError {
    let offset = match &problem.place {
        Place::Top(field) => source.field(0, field),
        Place::Item { kind, name, occurrence, field, literal } => source.item(*kind, name, *occurrence).map(|item| {
            let at_field = field.and_then(|f| source.field(item, f)).unwrap_or(item);
            literal.as_deref().and_then(|l| source.literal(at_field, l)).unwrap_or(at_field)
        }),
        Place::Section { section, field, literal } => source.field(0, section).map(|start| {
            let at_field = field.and_then(|f| source.field(start, f)).unwrap_or(start);
            literal.as_deref().and_then(|l| source.literal(at_field, l)).unwrap_or(at_field)
        }),
    };
    let (line, col) = source.line_col(offset.unwrap_or(0));
    SceneError { path: label.to_string(), line, col, message: problem.message }
}
