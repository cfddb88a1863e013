//! Statics from Python (PHYSICS.md §7): the equilibrium and offset curves of `tether
//! equilibrium` and `tether offsets`, by the same solver, from the scene's initial poses.

use crate::errors::{caught, finite, value_error};
use pyo3::prelude::*;
use tether_analysis::statics::{data, offsets};
use tether_physics::statics::{Direction, Dof, Dofs, Settings, equilibrium, offsets as curve};
use tether_scene::Scene;

/// An offset curve's table: column names (with units), rows flattened, row count.
pub type Columns = (Vec<String>, Vec<f64>, usize);

/// At most this many offsets, as `tether offsets --steps`.
const MAX_STEPS: u32 = 10_000;

/// `tether equilibrium --json`'s text for `scene`, solved with the GIL released.
pub fn equilibrium_json(py: Python<'_>, scene: &Scene) -> PyResult<String> {
    let system = scene.world.system();
    let start = system.initial_states();
    let solved = py
        .detach(|| caught(|| equilibrium::solve(system, start, &[], &Settings::default())))
        .map_err(crate::errors::runtime_error)?
        .map_err(|e| value_error(format!("{}: {e}", scene.path.display())))?;
    let data = data::equilibrium(system, &solved, start);
    serde_json::to_string(&data).map_err(value_error)
}

/// The offset curve of body `body` along `direction` from its equilibrium to `to` in `steps`,
/// with `tether offsets`' checks (the flags named as the arguments).
pub fn offsets(py: Python<'_>, scene: &Scene, body: &str, direction: &str, to: f64, steps: u32) -> PyResult<Columns> {
    let direction: Direction = direction.parse().map_err(value_error)?;
    let to = finite("to", to)?;
    if to == 0.0 {
        return Err(value_error(format!("`to` must be a non-zero number of {}, got 0", direction.unit())));
    }
    if !(1..=MAX_STEPS).contains(&steps) {
        return Err(value_error(format!("`steps` must be 1 to {MAX_STEPS}, got {steps}")));
    }
    let label = scene.path.display().to_string();
    let system = scene.world.system();
    let names: Vec<&str> = system.bodies().iter().map(|b| b.name.as_str()).collect();
    let Some(index) = names.iter().position(|n| *n == body) else {
        return Err(value_error(format!("{label}: no body \"{body}\" (bodies: {})", names.join(", "))));
    };
    let dof = Dof { body: index, direction };
    if !Dofs::of(system, &[]).free().contains(&dof) {
        return Err(value_error(format!(
            "{label}: body \"{body}\" cannot move in {direction}: its support holds it there"
        )));
    }
    let solved = py
        .detach(|| {
            caught(|| {
                let settings = Settings::default();
                let at_rest = equilibrium::solve(system, system.initial_states(), &[], &settings)?;
                curve::curve(system, &at_rest, dof, to, steps, &settings)
            })
        })
        .map_err(crate::errors::runtime_error)?
        .map_err(|e| value_error(format!("{label}: offset curve of body \"{body}\" in {direction}: {e}")))?;
    let table = offsets::table(system, &solved);
    let rows = table.rows.len();
    Ok((table.columns, table.rows.into_iter().flatten().collect(), rows))
}
