//! The scene's air and the bodies it loads into the system (PHYSICS.md §10), each problem placed
//! at the field at fault: the air section's, or the body's `windage`/`rotor`.

use super::{ItemAt, Place, Problem};
use crate::air::wind_load_spec;
use crate::file::SceneFile;
use crate::source::ItemKind;
use tether_physics::air::{Air, AirError, AirSpec, GustError, WindLoadError, WindLoadSpec};
use tether_physics::system::{System, SystemError};

/// `system` (its water already added) in the air of `file`, loading each body that declares a
/// windage or a rotor (unchanged without air); warns of a body's windage or rotor without air,
/// and of air that loads no body.
pub fn add_air(system: System, file: &SceneFile, warnings: &mut Vec<String>) -> Result<System, Problem> {
    let loads = wind_loads(file);
    let Some(def) = &file.air else {
        for &(index, _) in &loads {
            warnings.push(format!(
                "body \"{}\" declares windage or a rotor but the scene has no air: it feels none",
                file.bodies[index].name
            ));
        }
        return Ok(system);
    };
    if loads.is_empty() {
        warnings.push("the scene has air but no body declares windage or a rotor: the wind loads nothing".into());
    }
    let water_ramp = system.water().map_or(0.0, |stage| stage.water.ramp_time());
    system.with_air(def.spec(water_ramp), loads).map_err(placed)
}

/// The air of `file` and the bodies it loads (PHYSICS.md §10), the air checked as loading
/// checks it, with the same messages (live tuning: the bodies' windage and rotors were checked
/// when the scene was loaded, and the world checks them again).
pub fn air_spec(file: &SceneFile) -> Result<(AirSpec, Vec<(usize, WindLoadSpec)>), Problem> {
    let Some(def) = &file.air else {
        return Err(Problem { place: Place::Top("air"), message: "the scene has no air".into() });
    };
    let water_ramp = match &file.water {
        Some(_) => super::water::water(file)?.ramp_time(),
        None => 0.0,
    };
    let spec = def.spec(water_ramp);
    Air::new(spec).map_err(|error| placed(SystemError::Air(error)))?;
    Ok((spec, wind_loads(file)))
}

/// Each body that declares a windage or a rotor, with its loads' spec.
fn wind_loads(file: &SceneFile) -> Vec<(usize, WindLoadSpec)> {
    let loads = file.bodies.iter().map(|b| wind_load_spec(b.windage.as_ref(), b.rotor.as_ref()));
    loads.enumerate().filter_map(|(index, spec)| spec.map(|spec| (index, spec))).collect()
}

/// Where `error` is in the file, and its message.
fn placed(error: SystemError) -> Problem {
    match error {
        SystemError::Air(air) => {
            let field = match &air {
                AirError::Parameter(parameter) => parameter.field(),
                AirError::Gusts(GustError::Components(_) | GustError::Kaimal { .. }) => "gusts",
                AirError::RoughnessAboveReference { .. } => "Logarithmic",
            };
            Problem {
                place: Place::Section { section: "air", field: Some(field), literal: None },
                message: format!("air: {air}"),
            }
        }
        SystemError::Wind { body, source } => {
            // Body names are unique by now: the body at fault is the first of its name.
            let field = match source {
                WindLoadError::Windage(_) | WindLoadError::NoHull(_) => "windage",
                WindLoadError::Rotor(_) => "rotor",
            };
            ItemAt::new(ItemKind::Body, &body, 0).at_field(field, source.to_string())
        }
        other => Problem { place: Place::Top("air"), message: other.to_string() },
    }
}
