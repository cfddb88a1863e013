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
use tether_physics::potential::{FitSettings, HydrostaticsModel, PotentialSpec};
use tether_physics::system::{System, SystemError};
use tether_physics::water::morison::HydroSpec;
use tether_physics::water::{Hull, Hydro, Water, WaterSpec};
use tether_physics::water_stage::FloatingError;

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
            hydrostatics: wamit.hydrostatics,
            drift: wamit.drift,
        };
        let with_mesh = (wamit.hydrostatics == HydrostaticsModel::Linear).then(|| system.clone());
        system = system.with_potential_flow(index, spec).map_err(placed)?;
        if let Some(with_mesh) = with_mesh {
            warnings.extend(linear_hydrostatics_warnings(&with_mesh, &system, index, &body_def.name));
        }
    }
    Ok(system)
}

/// A `.hst` more than this fraction from the mesh's stiffness in heave, roll or pitch is warned
/// of: Capytaine's finer mesh and Tether's differ by 0.4 % on the shipped cylinder, a weight term
/// counted twice by 100 % and more.
const HYDROSTATICS_MISMATCH: f64 = 0.05;

/// The warnings for body `index`, whose potential flow in `linear` has linear hydrostatics, when
/// their stiffness about its reference point differs from the mesh's in `with_mesh` (the same
/// system without its potential flow) by more than [`HYDROSTATICS_MISMATCH`] in heave, roll or
/// pitch (`tether_physics::rao::stiffness_about`: the weight's terms the same on both sides).
fn linear_hydrostatics_warnings(with_mesh: &System, linear: &System, index: usize, name: &str) -> Vec<String> {
    let floating = linear.water().and_then(|stage| stage.floating.iter().find(|f| f.body() == index));
    let Some(potential) = floating.and_then(|f| f.potential()) else { return Vec::new() };
    let arm = potential.model().arm(&linear.initial_states()[index].frame());
    let stiffness = |system: &System| tether_physics::rao::stiffness_about(system, index, &arm);
    // Both evaluate the start pose, which the rest of loading evaluates too: a failure there
    // is reported where it happens, not as a warning here.
    let (Ok(mesh), Ok(file)) = (stiffness(with_mesh), stiffness(linear)) else { return Vec::new() };
    [(2, "heave", "N/m"), (3, "roll", "N·m/rad"), (4, "pitch", "N·m/rad")]
        .into_iter()
        .filter(|&(dof, _, _)| (file[(dof, dof)] - mesh[(dof, dof)]).abs() > HYDROSTATICS_MISMATCH * mesh[(dof, dof)].abs())
        .map(|(dof, what, unit)| {
            format!(
                "body \"{name}\": its .hst's {what} stiffness with the weight is {:.4e} {unit}, the mesh's {:.4e} ({:+.1} %): linear hydrostatics need a buoyancy-only file (a weight term in it is counted twice: Tether applies the weight at G) computed at the scene's draft",
                file[(dof, dof)],
                mesh[(dof, dof)],
                100.0 * (file[(dof, dof)] / mesh[(dof, dof)] - 1.0)
            )
        })
        .collect()
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
        SystemError::Line { coupling, source } => super::line_problem(&coupling, &source),
        other => Problem { place: Place::Top("water"), message: other.to_string() },
    }
}

/// The water of `file`, checked as loading checks it (live tuning checks an edited water this
/// way before it reaches a running world).
pub fn water_spec(file: &SceneFile) -> Result<WaterSpec, Problem> {
    water(file).map(|water| *water.spec())
}

/// The water of `file`, built as loading builds it, with the same messages.
pub(super) fn water(file: &SceneFile) -> Result<Water, Problem> {
    let Some(def) = &file.water else {
        return Err(Problem { place: Place::Top("water"), message: "the scene has no water".into() });
    };
    let gravity = Vec3::new(file.gravity[0], file.gravity[1], file.gravity[2]);
    Water::new(def.spec(), &gravity).map_err(|error| placed(SystemError::Water(error)))
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
