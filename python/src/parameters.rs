//! A scene's parameters by the sweep's paths (`couplings.spring.stiffness`, `dt`,
//! `bodies.buoy.master.mass`): found by the sweep's [`ValuePath`] in the scene's serde data, a
//! new value written as a sweep's factor writes it, and the scene built again by the scene
//! loader, whose checks and `path:line:col: message` text (placed in the scene's own text) are
//! the GUI's and the sweeps'.

use crate::errors::{type_error, value_error};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyString};
use serde_json::Value;
use tether_analysis::value_path::{ValuePath, number_value};
use tether_scene::{Scene, SceneFile};

/// The scene's data, as the sweep addresses it.
pub fn tree(file: &SceneFile) -> PyResult<Value> {
    serde_json::to_value(file).map_err(|e| value_error(format!("the scene's data cannot be addressed: {e}")))
}

/// The value at `path`: a number, a name, a flag, or `None` when the scene leaves it to the
/// loader's default.
pub fn get<'py>(py: Python<'py>, scene: &Scene, path: &str) -> PyResult<Bound<'py, PyAny>> {
    let tree = tree(&scene.file)?;
    let found = ValuePath::find(&tree, path).map_err(value_error)?;
    Ok(match found.get(&tree) {
        Some(Value::Number(n)) => match n.as_i64() {
            Some(whole) => whole.into_pyobject(py)?.into_any(),
            None => PyFloat::new(py, n.as_f64().unwrap_or(f64::NAN)).into_any(),
        },
        Some(Value::Bool(flag)) => PyBool::new(py, *flag).to_owned().into_any(),
        Some(Value::String(text)) => PyString::new(py, text).into_any(),
        _ => py.None().into_bound(py),
    })
}

/// A Python value as scene data: a flag, a name, or a finite number (whole numbers as
/// integers, as the sweep writes them).
pub fn data(path: &str, value: &Bound<'_, PyAny>) -> PyResult<Value> {
    if value.is_instance_of::<PyBool>() {
        return Ok(Value::Bool(value.extract::<bool>()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(Value::String(value.extract::<String>()?));
    }
    let Ok(x) = value.extract::<f64>() else {
        let kind = value.get_type().name().map_or_else(|_| "?".to_string(), |n| n.to_string());
        return Err(type_error(format!("`{path}`: expected a number, a name or a flag, got {kind}")));
    };
    number_value(x).ok_or_else(|| value_error(format!("`{path}` must be a finite number, got {x}")))
}

/// The scene with `value` at `path`, built by the loader (a fresh world at t = 0).
///
/// # Errors
/// An unknown path (the sweep's message), a value of the wrong kind or one the loader refuses
/// (`scene.ron:line:col: message`), or a value that renames a body or coupling.
pub fn set(scene: &Scene, path: &str, value: Value) -> PyResult<Scene> {
    let mut tree = tree(&scene.file)?;
    let found = ValuePath::find(&tree, path).map_err(value_error)?;
    found.set(&mut tree, value);
    let file: SceneFile = serde_json::from_value(tree).map_err(|e| value_error(format!("`{path}`: {e}")))?;
    let built = tether_scene::build_variant(&scene.text, &scene.path, file).map_err(value_error)?;
    if names(&built) != names(scene) {
        return Err(value_error(format!("`{path}`: a parameter changes values, not the names of bodies or couplings")));
    }
    Ok(built)
}

/// Body and coupling names, in order.
pub fn names(scene: &Scene) -> Vec<&str> {
    let world = &scene.world;
    world.bodies().iter().map(|b| b.name.as_str()).chain(world.couplings().iter().map(|c| c.name.as_str())).collect()
}
