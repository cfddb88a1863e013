//! The scene's water and its floating bodies into the system (PHYSICS.md §6), with each problem
//! placed at the field at fault: the water section's, or the body's `hydro`/`shape`.

use super::{ItemAt, Place, Problem};
use crate::file::SceneFile;
use crate::source::ItemKind;
use crate::water::WaterDef;
use tether_physics::body::RigidBody;
use tether_physics::system::{System, SystemError};
use tether_physics::water::stage::FloatingError;

/// `system` with the water of `file` and its bodies that declare `hydro` in it (unchanged
/// without water); warns of a body under the surface that declares no `hydro`, and of `hydro`
/// without water.
pub fn add_water(system: System, file: &SceneFile, bodies: &[RigidBody], warnings: &mut Vec<String>) -> Result<System, Problem> {
    let Some(def) = &file.water else {
        for body in file.bodies.iter().filter(|b| b.hydro.is_some()) {
            warnings.push(format!("body \"{}\" declares hydro but the scene has no water: it feels none", body.name));
        }
        return Ok(system);
    };
    let spec = def.spec();
    for (body_def, body) in file.bodies.iter().zip(bodies) {
        if body_def.hydro.is_none() && body.mass_properties.center_of_mass.z < def.level {
            warnings.push(format!("body \"{}\" starts under the water surface but declares no hydro: the water does not act on it", body_def.name));
        }
    }
    let floating: Vec<_> = file.bodies.iter().enumerate().filter_map(|(index, b)| b.hydro.as_ref().map(|h| (index, h.spec()))).collect();
    system.with_water(spec, floating).map_err(placed)
}

/// Where `error` is in `file`, and its message.
fn placed(error: SystemError) -> Problem {
    match error {
        SystemError::Water(water) => {
            let field = WaterDef::field_of(&water);
            let place = if field == "water" { Place::Top("water") } else { Place::Section { section: "water", field } };
            Problem { place, message: format!("water: {water}") }
        }
        SystemError::Hydro { body, source } => {
            // Body names are unique by now: the body at fault is the first of its name.
            let at = ItemAt::new(ItemKind::Body, &body, 0);
            let field = match source {
                FloatingError::Hull(_) => "shape",
                FloatingError::Hydro(_) => "hydro",
            };
            at.at_field(field, match source {
                FloatingError::Hull(e) => format!("its shape as a hull in water: {e}"),
                FloatingError::Hydro(e) => format!("hydro: {e}"),
            })
        }
        other => Problem { place: Place::Top("water"), message: other.to_string() },
    }
}
