//! How the viewer lays out a run: the 3D scene large on the left, the plots stacked on the
//! right (a fit's plots first, twice as tall as the others; the energy in two plots, stored and
//! moving; the couplings' tensions — a contact's normal force named as such; the catenaries' end tensions, their
//! grounded lengths on a seabed, and the contacts' forces when there are any; each floating
//! body's motion in the water, and a potential-flow body's radiation force and excitation); the
//! `sim_time` timeline; the viewer's own side panels folded, room being short beside the control
//! panel. The 3D view's eye frames what moves
//! ([`crate::framing`]), or follows a body the user chose.
//!
//! Rerun's Rust SDK 0.36 builds a 3D view without its eye (its Python SDK has `eye_controls`; the
//! Rust `Spatial3DView` keeps its properties private): the blueprint is built by the SDK as
//! usual, captured in memory, and sent with the eye's blueprint row added under the view's own
//! path (`view/<id>/EyeControls3D`, as the SDK writes a property), before the activation.

use crate::framing::Framing;
use crate::paths;
use crate::rerun;
use re_sdk_types::blueprint::archetypes::EyeControls3D;
use rerun::blueprint::components::{Eye3DKind, PanelState};
use rerun::blueprint::{
    Blueprint, BlueprintActivation, BlueprintPanel, ContainerLike, Horizontal, SelectionPanel, Spatial3DView,
    TimePanel, TimeSeriesView, Vertical,
};
use rerun::log::LogMsg;
use rerun::{EntityPath, RecordingStream, RecordingStreamBuilder, StoreKind};
use tether_physics::coupling::CouplingKind;
use tether_physics::world::World;

/// Where the 3D view's eye is: the run's framing, and the body it follows, if any.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    pub framing: Framing,
    /// The name of the body the eye follows (it keeps its distance and direction as the body
    /// moves), or `None`: it stays where the framing put it.
    pub follow: Option<String>,
}

impl Camera {
    /// The framing of `world`'s run ([`Framing::of`] runs a copy of it), following no body.
    pub fn framing(world: &World) -> Self {
        Self { framing: Framing::of(world), follow: None }
    }

    /// The eye's blueprint property.
    pub fn eye_controls(&self) -> EyeControls3D {
        let point = |p: &tether_physics::math::Vec3| [p.x as f32, p.y as f32, p.z as f32];
        let eye = EyeControls3D::new()
            .with_kind(Eye3DKind::Orbital)
            .with_position(point(&self.framing.eye))
            .with_look_target(point(&self.framing.target))
            .with_eye_up([0.0, 0.0, 1.0]);
        match &self.follow {
            // The shape is what has a bounding box for the viewer to centre (the body's own
            // entity holds only its pose).
            Some(body) => eye.with_tracking_entity(paths::body_shape(body)),
            None => eye,
        }
    }
}

/// The layout of a run of `world` with a fit's plot for each measured column of `columns`
/// (record and model, [`crate::comparison`]) at the top of the plots, and the blueprint path of
/// its 3D view (where its eye goes: [`send_layout_with_fits`]).
pub fn layout_with_fits(world: &World, columns: &[&str]) -> (Blueprint, EntityPath) {
    let couplings = world.couplings();
    let mut plots: Vec<ContainerLike> = columns
        .iter()
        .map(|column| TimeSeriesView::new(format!("fit: {column}")).with_origin(paths::fit_plot(column)).into())
        .collect();
    plots.extend(energy_views());
    let (mut pulls, mut lines, mut contacts) = (false, false, false);
    for coupling in couplings {
        match coupling.kind {
            // A spring's tension is in the tension plot.
            CouplingKind::SpringDamper(_) => pulls = true,
            CouplingKind::Catenary(_) => (pulls, lines) = (true, true),
            CouplingKind::Contact(_) => contacts = true,
        }
    }
    // The plot holds every coupling's scalar force: a contact's is its normal force, which is
    // not a tension.
    let forces = match (pulls, contacts) {
        (true, false) => Some("tension [N]"),
        (true, true) => Some("tension, contact normal force [N]"),
        (false, true) => Some("contact normal force [N]"),
        (false, false) => None,
    };
    if let Some(name) = forces {
        plots.push(TimeSeriesView::new(name).with_origin(paths::TENSION).into());
    }
    if lines {
        plots.push(TimeSeriesView::new("catenary end tensions [N]").with_origin(paths::CATENARY_PLOT).into());
    }
    if lines && world.system().seabed().is_some() {
        plots.push(TimeSeriesView::new("grounded length L_B [m]").with_origin(paths::SEABED_PLOT).into());
    }
    if contacts {
        plots.push(TimeSeriesView::new("contact forces [N]").with_origin(paths::CONTACT_PLOT).into());
    }
    if let Some(stage) = world.system().water() {
        for floating in &stage.floating {
            let name = &world.bodies()[floating.body].name;
            plots.push(
                TimeSeriesView::new(format!("{name}: elevation, heave [m]"))
                    .with_origin(paths::water_plot(name, "motion"))
                    .into(),
            );
            plots.push(
                TimeSeriesView::new(format!("{name}: roll, pitch [deg]"))
                    .with_origin(paths::water_plot(name, "angles"))
                    .into(),
            );
            if floating.has_potential_data() {
                for (plot, what) in
                    [(paths::RADIATION_PLOT, "radiation force"), (paths::EXCITATION_PLOT, "wave excitation")]
                {
                    plots.push(
                        TimeSeriesView::new(format!("{name}: {what} at G [N, N·m]"))
                            .with_origin(paths::water_plot(name, plot))
                            .into(),
                    );
                }
            }
        }
    }
    let scene: ContainerLike = Spatial3DView::new("scene").with_origin(paths::WORLD).into();
    let scene_path = match &scene {
        ContainerLike::View(view) => view.blueprint_path(),
        // A view converts to a view.
        ContainerLike::Horizontal(_) | ContainerLike::Vertical(_) | ContainerLike::Grid(_) | ContainerLike::Tabs(_) => {
            unreachable!("a Spatial3DView is a view")
        }
    };
    // A fit's plots are what a fit is watched by: twice the height of the others.
    let shares: Vec<f32> = (0..plots.len()).map(|i| if i < columns.len() { 2.0 } else { 1.0 }).collect();
    let plots = if columns.is_empty() { Vertical::new(plots) } else { Vertical::new(plots).with_row_shares(shares) };
    let blueprint = Blueprint::new(Horizontal::new([scene, plots.into()]).with_column_shares([3.0, 2.0]))
        .with_blueprint_panel(BlueprintPanel::from_state(PanelState::Collapsed))
        .with_selection_panel(SelectionPanel::from_state(PanelState::Collapsed))
        .with_time_panel(TimePanel::new().with_timeline("sim_time"));
    (blueprint, scene_path)
}

/// The energy account (PHYSICS.md §5) in two plots of `plots/energy`'s series: the stored
/// energies with their total and the balance, and what moves — kinetic, dissipated, external
/// work. Apart, the kinetic energy of a moored buoy (kJ) is not a flat line beside a mooring's
/// elastic energy (−6.9 MJ). Each plot hides the other's series (in the order the energy
/// track logs them).
fn energy_views() -> [ContainerLike; 2] {
    // kinetic, gravity, elastic, dissipated, external_work, total, balance
    let stored = [false, true, true, false, false, true, true];
    let moving = stored.map(|shown| !shown);
    let view = |name: &str, shown: [bool; 7]| -> ContainerLike {
        TimeSeriesView::new(name)
            .with_origin(paths::ENERGY)
            .with_override(paths::ENERGY, &rerun::SeriesLines::new().with_visible_series(shown))
            .into()
    };
    [
        view("energy: gravity, elastic, total, balance [J]", stored),
        view("energy: kinetic, dissipated, external work [J]", moving),
    ]
}

/// Sends `world`'s [`layout_with_fits`] with its eye at `camera` to the viewer behind `stream`
/// (nothing for a disabled stream).
pub fn send_layout_with_fits(
    stream: &RecordingStream,
    world: &World,
    columns: &[&str],
    camera: &Camera,
) -> rerun::RecordingStreamResult<()> {
    if !stream.is_enabled() {
        return Ok(());
    }
    send(stream, layout_with_fits(world, columns), camera)
}

/// Sends `blueprint` to `stream` with `camera`'s eye in its 3D view at `scene_path`, active and
/// the default: the SDK's own messages (captured from a memory stream of the same application),
/// the eye's row in the same blueprint store, then the activation (a memory sink's `take`
/// flushes its stream first).
fn send(
    stream: &RecordingStream,
    (blueprint, scene_path): (Blueprint, EntityPath),
    camera: &Camera,
) -> rerun::RecordingStreamResult<()> {
    let application =
        stream.store_info().map_or_else(|| crate::APPLICATION_ID.into(), |info| info.application_id().clone());
    let (capture, captured) = RecordingStreamBuilder::new(application.clone()).memory()?;
    blueprint.send(&capture, BlueprintActivation { make_active: true, make_default: true })?;
    let mut messages: Vec<LogMsg> =
        captured.take().into_iter().filter(|message| message.store_id().kind() == StoreKind::Blueprint).collect();
    let Some(store) = messages.first().map(|message| message.store_id().clone()) else { return Ok(()) };
    let (eye, eye_rows) =
        RecordingStreamBuilder::new(application).recording_id(store.recording_id().clone()).blueprint().memory()?;
    eye.set_time_sequence("blueprint", 0);
    eye.log(format!("{scene_path}/EyeControls3D"), &camera.eye_controls())?;
    let rows = eye_rows.take().into_iter().filter(|message| matches!(message, LogMsg::ArrowMsg(..)));
    let activation = messages.iter().position(|message| matches!(message, LogMsg::BlueprintActivationCommand(_)));
    let at = activation.unwrap_or(messages.len());
    messages.splice(at..at, rows);
    for message in messages {
        stream.record_msg(message);
    }
    Ok(())
}
