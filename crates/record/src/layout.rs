//! How the viewer lays out a run: the 3D scene large on the left; on the right the plots in
//! tabs of a few each, tall enough to read, the tab shown first being what the scene is about (a
//! fit's plots; a mooring's tensions and motions; a fender's contact forces: [`plot_tabs`]), the
//! rest a click away; the `sim_time` timeline folded to its controls and the viewer's own side
//! panels folded, room being short beside the control panel. The 3D view's eye frames what moves
//! ([`crate::framing`]), or follows a body the user chose.
//!
//! Rerun's Rust SDK 0.36 builds a 3D view without its eye (its Python SDK has `eye_controls`; the
//! Rust `Spatial3DView` keeps its properties private): the blueprint is built by the SDK as
//! usual, captured in memory, and sent with the eye's blueprint row added under the view's own
//! path (`view/<id>/EyeControls3D`, as the SDK writes a property), before the activation; the
//! line grid's row beside it (`view/<id>/LineGrid3D`: hidden in a scene with water or a seabed,
//! whose planes are the references), and for a scene at sea a sky (`view/<id>/Background`).

use crate::framing::Framing;
use crate::paths;
use crate::rerun;
use re_sdk_types::blueprint::archetypes::{Background, EyeControls3D, LineGrid3D};
use rerun::blueprint::components::{BackgroundKind, Eye3DKind, PanelState};
use rerun::blueprint::{
    Blueprint, BlueprintActivation, BlueprintPanel, ContainerLike, Horizontal, SelectionPanel, Spatial3DView, Tabs,
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

/// A plot of the layout: its title (what it shows, with its unit) and the entity whose series
/// it shows.
#[derive(Debug, Clone, PartialEq)]
pub struct Plot {
    pub title: String,
    pub origin: String,
}

impl Plot {
    fn new(title: impl Into<String>, origin: impl Into<String>) -> Self {
        Self { title: title.into(), origin: origin.into() }
    }
}

/// A tab of plots, named for what they are about.
#[derive(Debug, Clone, PartialEq)]
pub struct Tab {
    pub name: String,
    pub plots: Vec<Plot>,
}

impl Tab {
    fn new(name: impl Into<String>, plots: Vec<Plot>) -> Self {
        Self { name: name.into(), plots }
    }
}

/// The plots of a run of `world`, in tabs of at most four, the first being the one shown: what
/// the scene is about. In order, those a scene has: `fit` (a plot per measured column of
/// `columns`, record and model, [`crate::comparison`]); `mooring` for lines holding floating
/// bodies (the tensions and each body's heave, and its roll and pitch when it is the only one);
/// `contacts` (their forces, and the normal forces with any tensions); `lines` (the tensions,
/// the catenaries' end tensions and grounded lengths; `tensions` for springs alone); a tab per
/// floating body (elevation and heave, roll and pitch, a potential-flow body's radiation force
/// and excitation); the design loads (`drift`, `wind`: each body's wave drift and wind, PHYSICS.md
/// §10); `energy` (stored; moving). A plot may be in two tabs.
pub fn plot_tabs(world: &World, columns: &[&str]) -> Vec<Tab> {
    let (mut pulls, mut lines, mut contacts) = (false, false, false);
    for coupling in world.couplings() {
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
    }
    .map(|title| Plot::new(title, paths::TENSION));
    let floating = floating_bodies(world);
    let mut tabs = Vec::new();
    if !columns.is_empty() {
        let fits = columns.iter().map(|column| Plot::new(format!("fit: {column}"), paths::fit_plot(column))).collect();
        tabs.push(Tab::new("fit", fits));
    }
    if let (true, Some(tension)) = (lines && !floating.is_empty(), &forces) {
        let mut plots = vec![tension.clone()];
        plots.extend(floating.iter().map(|body| body.plots[0].clone()));
        if let [only] = floating.as_slice() {
            plots.push(only.plots[1].clone());
        }
        plots.truncate(4);
        tabs.push(Tab::new("mooring", plots));
    }
    if contacts {
        let mut plots = vec![Plot::new("contact forces [N]", paths::CONTACT_PLOT)];
        plots.extend(forces.clone());
        tabs.push(Tab::new("contacts", plots));
    }
    if pulls {
        let mut plots: Vec<Plot> = forces.into_iter().collect();
        if lines {
            plots.push(Plot::new("catenary end tensions [N]", paths::CATENARY_PLOT));
        }
        if lines && world.system().seabed().is_some() {
            plots.push(Plot::new("grounded length L_B [m]", paths::SEABED_PLOT));
        }
        tabs.push(Tab::new(if lines { "lines" } else { "tensions" }, plots));
    }
    tabs.extend(floating.into_iter().map(|body| Tab::new(body.name, body.plots)));
    if let Some((name, plots)) = design_load_plots(world) {
        tabs.push(Tab::new(name, plots));
    }
    tabs.push(Tab::new("energy", energy_plots()));
    tabs
}

/// A floating body's name and plots: elevation and heave, roll and pitch, and a potential-flow
/// body's radiation force and wave excitation (its drift is in the design loads' tab).
struct FloatingPlots {
    name: String,
    plots: Vec<Plot>,
}

fn floating_bodies(world: &World) -> Vec<FloatingPlots> {
    let Some(stage) = world.system().water() else { return Vec::new() };
    let plots = |floating: &tether_physics::water_stage::FloatingBody| {
        let name = world.bodies()[floating.body()].name.clone();
        let mut plots = vec![
            Plot::new(format!("{name}: elevation, heave [m]"), paths::water_plot(&name, "motion")),
            Plot::new(format!("{name}: roll, pitch [deg]"), paths::water_plot(&name, "angles")),
        ];
        if floating.has_potential_data() {
            for (plot, what) in
                [(paths::RADIATION_PLOT, "radiation force"), (paths::EXCITATION_PLOT, "wave excitation")]
            {
                plots.push(Plot::new(format!("{name}: {what} at G [N, N·m]"), paths::water_plot(&name, plot)));
            }
        }

        FloatingPlots { name, plots }
    };
    stage.floating.iter().map(plots).collect()
}

/// The design loads' tab (PHYSICS.md §10): each floating body's wave drift and each wind-loaded
/// body's wind, named for what it holds (`drift`, `wind`, `drift, wind`); `None` with neither.
fn design_load_plots(world: &World) -> Option<(&'static str, Vec<Plot>)> {
    let drift: Vec<Plot> = world.system().water().map_or_else(Vec::new, |stage| {
        stage
            .floating
            .iter()
            .filter(|f| has_drift(f))
            .map(|f| {
                let name = &world.bodies()[f.body()].name;
                Plot::new(format!("{name}: wave drift at G [N, N·m]"), paths::water_plot(name, paths::DRIFT_PLOT))
            })
            .collect()
    });
    let wind: Vec<Plot> = world.system().air().map_or_else(Vec::new, |stage| {
        stage
            .bodies()
            .iter()
            .map(|b| {
                let name = &world.bodies()[b.body()].name;
                Plot::new(format!("{name}: wind on windage and rotor [N, N·m]"), paths::air_plot(name))
            })
            .collect()
    });
    let name = match (drift.is_empty(), wind.is_empty()) {
        (true, true) => return None,
        (false, true) => "drift",
        (true, false) => "wind",
        (false, false) => "drift, wind",
    };
    Some((name, drift.into_iter().chain(wind).collect()))
}

/// Whether `floating` feels a wave drift (PHYSICS.md §10): potential flow on, a drift model.
pub(crate) fn has_drift(floating: &tether_physics::water_stage::FloatingBody) -> bool {
    floating.potential().is_some_and(|p| p.model().drift_model() != tether_physics::potential::DriftModel::Off)
}

/// The energy account (PHYSICS.md §5) in two plots: the stored energies with their total and
/// the balance, and what moves — kinetic, dissipated, external work. Apart, the kinetic energy
/// of a moored buoy (kJ) is not a flat line beside a mooring's elastic energy (−6.9 MJ).
fn energy_plots() -> Vec<Plot> {
    vec![
        Plot::new("energy: gravity, elastic, total, balance [J]", paths::ENERGY_STORED),
        Plot::new("energy: kinetic, dissipated, external work [J]", paths::ENERGY_MOVING),
    ]
}

/// The layout of a run of `world` with a fit's plot for each of `columns`: the 3D scene beside
/// [`plot_tabs`], and the blueprint path of its 3D view (where its eye goes:
/// [`send_layout_with_fits`]).
pub fn layout_with_fits(world: &World, columns: &[&str]) -> (Blueprint, EntityPath) {
    let tabs = plot_tabs(world, columns).into_iter().map(|tab| {
        let plots = tab.plots.into_iter().map(|plot| TimeSeriesView::new(plot.title).with_origin(plot.origin).into());
        ContainerLike::from(Vertical::new(plots).with_name(tab.name))
    });
    let scene: ContainerLike = Spatial3DView::new("scene").with_origin(paths::WORLD).into();
    let scene_path = match &scene {
        ContainerLike::View(view) => view.blueprint_path(),
        // A view converts to a view.
        ContainerLike::Horizontal(_) | ContainerLike::Vertical(_) | ContainerLike::Grid(_) | ContainerLike::Tabs(_) => {
            unreachable!("a Spatial3DView is a view")
        }
    };
    // The first tab is the one shown (egui_tiles opens a tab container on its first child).
    let blueprint = Blueprint::new(Horizontal::new([scene, Tabs::new(tabs).into()]).with_column_shares([3.0, 2.0]))
        .with_blueprint_panel(BlueprintPanel::from_state(PanelState::Collapsed))
        .with_selection_panel(SelectionPanel::from_state(PanelState::Collapsed))
        .with_time_panel(TimePanel::new().with_timeline("sim_time").with_state(PanelState::Collapsed));
    (blueprint, scene_path)
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
    // The sea surface and the seabed are the scene's own planes: the viewer's grid at z = 0
    // would cut through the water's surface (and hide in it) and float over the bottom.
    let grid = world.system().water().is_none() && world.system().seabed().is_none();
    send(stream, layout_with_fits(world, columns), camera, View { grid, sky: world.system().water().is_some() })
}

/// How the 3D view is drawn beside its eye.
#[derive(Debug, Clone, Copy)]
struct View {
    /// The viewer's line grid at z = 0 shown.
    grid: bool,
    /// A sky behind the scene ([`SKY_RGB`]; a scene at sea, whose horizon the sea reaches), or
    /// the viewer's dark gradient.
    sky: bool,
}

/// The sky's colour behind a scene at sea: red, green, blue.
const SKY_RGB: [u8; 3] = [96, 120, 150];

/// Sends `blueprint` to `stream` with `camera`'s eye in its 3D view at `scene_path`, its line
/// grid and background as `view` says, active and the default: the SDK's own messages (captured
/// from a memory stream of the same application), the view's property rows in the same
/// blueprint store, then the activation (a memory sink's `take` flushes its stream first).
fn send(
    stream: &RecordingStream,
    (blueprint, scene_path): (Blueprint, EntityPath),
    camera: &Camera,
    view: View,
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
    eye.log(format!("{scene_path}/LineGrid3D"), &LineGrid3D::new().with_visible(view.grid))?;
    if view.sky {
        let [r, g, b] = SKY_RGB;
        let sky = Background::new(BackgroundKind::SolidColor).with_color(rerun::Color::from_rgb(r, g, b));
        eye.log(format!("{scene_path}/Background"), &sky)?;
    }
    let rows = eye_rows.take().into_iter().filter(|message| matches!(message, LogMsg::ArrowMsg(..)));
    let activation = messages.iter().position(|message| matches!(message, LogMsg::BlueprintActivationCommand(_)));
    let at = activation.unwrap_or(messages.len());
    messages.splice(at..at, rows);
    for message in messages {
        stream.record_msg(message);
    }
    Ok(())
}
