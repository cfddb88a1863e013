//! How the viewer lays out a run: the 3D scene large on the left, the plots stacked on the
//! right (a fit's plots first, twice as tall as the others; the energy in two plots, stored and
//! moving; the couplings' tensions — a contact's normal force named as such; the catenaries' end tensions, their
//! grounded lengths on a seabed, and the contacts' forces when there are any; each floating
//! body's motion in the water); the `sim_time` timeline; the viewer's own side panels folded,
//! room being short beside the control panel.

use crate::paths;
use crate::rerun;
use rerun::RecordingStream;
use rerun::blueprint::components::PanelState;
use rerun::blueprint::{
    Blueprint, BlueprintActivation, BlueprintPanel, ContainerLike, Horizontal, SelectionPanel, Spatial3DView,
    TimePanel, TimeSeriesView, Vertical,
};
use tether_physics::coupling::CouplingKind;
use tether_physics::world::World;

/// The layout of a run of `world`.
pub fn layout(world: &World) -> Blueprint {
    layout_with_fits(world, &[])
}

/// The layout of a run of `world` with a fit's plot for each measured column of `columns`
/// (record and model, [`crate::comparison`]) at the top of the plots.
pub fn layout_with_fits(world: &World, columns: &[&str]) -> Blueprint {
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
        }
    }
    let scene: ContainerLike = Spatial3DView::new("scene").with_origin(paths::WORLD).into();
    // A fit's plots are what a fit is watched by: twice the height of the others.
    let shares: Vec<f32> = (0..plots.len()).map(|i| if i < columns.len() { 2.0 } else { 1.0 }).collect();
    let plots = if columns.is_empty() { Vertical::new(plots) } else { Vertical::new(plots).with_row_shares(shares) };
    Blueprint::new(Horizontal::new([scene, plots.into()]).with_column_shares([3.0, 2.0]))
        .with_blueprint_panel(BlueprintPanel::from_state(PanelState::Collapsed))
        .with_selection_panel(SelectionPanel::from_state(PanelState::Collapsed))
        .with_time_panel(TimePanel::new().with_timeline("sim_time"))
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

/// Sends `world`'s [`layout`] to the viewer behind `stream` (nothing for a disabled stream).
pub fn send_layout(stream: &RecordingStream, world: &World) -> rerun::RecordingStreamResult<()> {
    send_layout_with_fits(stream, world, &[])
}

/// Sends `world`'s [`layout_with_fits`] to the viewer behind `stream` (nothing for a disabled
/// stream).
pub fn send_layout_with_fits(
    stream: &RecordingStream,
    world: &World,
    columns: &[&str],
) -> rerun::RecordingStreamResult<()> {
    if !stream.is_enabled() {
        return Ok(());
    }
    layout_with_fits(world, columns).send(stream, BlueprintActivation { make_active: true, make_default: true })
}
