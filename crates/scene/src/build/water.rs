//! The scene's water and its floating bodies into the system (PHYSICS.md §6), with each problem
//! placed at the field at fault: the water section's, or the body's `hydro`/`shape`.

use super::{Bodies, ItemAt, Place, Problem};
use crate::file::SceneFile;
use crate::source::ItemKind;
use crate::wamit::Scale;
use crate::water::WaterDef;
use std::path::Path;
use tether_physics::body::RigidBody;
use tether_physics::math::Vec3;
use tether_physics::potential::{FitSettings, PotentialSpec};
use tether_physics::system::{System, SystemError};
use tether_physics::water::morison::HydroSpec;
use tether_physics::water::stage::FloatingError;
use tether_physics::water::{Hull, Hydro, Water, WaterSpec};

/// `system` with the water of `file` and its bodies that declare `hydro` in it (unchanged
/// without water), their potential-flow files read relative to `directory`; warns of a body
/// under the surface that declares no `hydro`, and of `hydro` without water; refuses potential
/// flow without water.
pub fn add_water(
    system: System,
    file: &SceneFile,
    bodies: &[RigidBody],
    directory: &Path,
    warnings: &mut Vec<String>,
) -> Result<System, Problem> {
    let Some(def) = &file.water else {
        if let Some(body) = file.bodies.iter().find(|b| b.hydro.as_ref().is_some_and(|h| h.potential.is_some())) {
            let at = ItemAt::new(ItemKind::Body, &body.name, 0);
            return Err(at.at_field("potential", "potential flow needs water: the scene has none".into()));
        }
        for body in file.bodies.iter().filter(|b| b.hydro.is_some()) {
            warnings.push(format!("body \"{}\" declares hydro but the scene has no water: it feels none", body.name));
        }
        return Ok(system);
    };
    let spec = def.spec();
    for (body_def, body) in file.bodies.iter().zip(bodies) {
        if body_def.hydro.is_none() && !body.is_kinematic() && body.mass_properties.center_of_mass.z < def.level {
            warnings.push(format!(
                "body \"{}\" starts under the water surface but declares no hydro: the water does not act on it",
                body_def.name
            ));
        }
    }
    let floating: Vec<_> =
        file.bodies.iter().enumerate().filter_map(|(index, b)| b.hydro.as_ref().map(|h| (index, h.spec()))).collect();
    let mut system = system.with_water(spec, floating).map_err(placed)?;
    let gravity = Vec3::new(file.gravity[0], file.gravity[1], file.gravity[2]).norm();
    let scale = |length| Scale { density: spec.density, gravity, length };
    for (index, body_def) in file.bodies.iter().enumerate() {
        let Some(wamit) = body_def.hydro.as_ref().and_then(|h| h.potential.as_ref()) else { continue };
        let at = ItemAt::new(ItemKind::Body, &body_def.name, 0);
        let coefficients = crate::wamit::read(&directory.join(&wamit.file), scale(wamit.length))
            .map_err(|e| at.problem(Some("potential"), Some(&wamit.file), e.to_string()))?;
        let fit = FitSettings::new(wamit.fit_error, wamit.max_order)
            .map_err(|e| at.problem(Some("potential"), None, format!("hydro: potential: {e}")))?;
        let spec = PotentialSpec {
            coefficients,
            reference: Vec3::new(wamit.reference[0], wamit.reference[1], wamit.reference[2]),
            method: wamit.radiation,
            fit,
            kernel_duration: wamit.kernel_duration,
            kernel_step: wamit.kernel_step,
        };
        system = system.with_potential_flow(index, spec).map_err(placed)?;
    }
    Ok(system)
}

/// Where `error` is in `file`, and its message.
fn placed(error: SystemError) -> Problem {
    match error {
        SystemError::Water(water) => {
            let field = WaterDef::field_of(&water);
            let place = if field == "water" {
                Place::Top("water")
            } else {
                Place::Section { section: "water", field: Some(field), literal: None }
            };
            Problem { place, message: format!("water: {water}") }
        }
        SystemError::Hydro { body, source } => {
            // Body names are unique by now: the body at fault is the first of its name.
            let at = ItemAt::new(ItemKind::Body, &body, 0);
            let field = match source {
                FloatingError::Hull(_) => "shape",
                FloatingError::Hydro(_) => "hydro",
                FloatingError::Potential(_) | FloatingError::Heading(_) => "potential",
            };
            at.at_field(field, source.to_string())
        }
        other => Problem { place: Place::Top("water"), message: other.to_string() },
    }
}

/// The water of `file`, checked as loading checks it (live tuning checks an edited water this
/// way before it reaches a running world).
pub fn water_spec(file: &SceneFile) -> Result<WaterSpec, Problem> {
    let Some(def) = &file.water else {
        return Err(Problem { place: Place::Top("water"), message: "the scene has no water".into() });
    };
    let spec = def.spec();
    let gravity = Vec3::new(file.gravity[0], file.gravity[1], file.gravity[2]);
    Water::new(spec, &gravity).map_err(|error| placed(SystemError::Water(error)))?;
    Ok(spec)
}

/// The coefficients of body `index` of `file` against its built body, checked as loading checks
/// them (live tuning).
pub fn hydro_spec(file: &SceneFile, index: usize, bodies: &Bodies) -> Result<HydroSpec, Problem> {
    let (Some(def), Some(body)) = (file.bodies.get(index), bodies.bodies().get(index)) else {
        return Err(Problem { place: Place::Top("bodies"), message: format!("the scene has no body {index}") });
    };
    let Some(hydro) = &def.hydro else {
        return Err(ItemAt::new(ItemKind::Body, &def.name, 0).at_name("declares no hydro".into()));
    };
    let spec = hydro.spec();
    let hull = Hull::of_body(body)
        .map_err(|e| placed(SystemError::Hydro { body: def.name.clone(), source: FloatingError::Hull(e) }))?;
    Hydro::new(spec, body, &hull)
        .map_err(|e| placed(SystemError::Hydro { body: def.name.clone(), source: FloatingError::Hydro(e) }))?;
    Ok(spec)
}
