//! The recording's entity paths, in one table: the recorder writes them, the viewer layout and
//! the GUI's selection read them.
//!
//! | path | what |
//! |---|---|
//! | `world` | view coordinates (right-handed, z up) |
//! | `world/bodies/<name>` | a body's pose: G and its principal axes |
//! | `world/bodies/<name>/shape`, `…/nodes` | its static shape and slave nodes |
//! | `world/springs` | every spring-damper's line, one strip each |
//! | `world/couplings/<name>` | a catenary's shape |
//! | `world/contacts/<name>` | a contact's face forces |
//! | `world/boundaries/<name>` | a contact's planes (a ground, a quay wall), each under the first contact against it |
//! | `world/anchors` | every coupling end fixed in the world |
//! | `plots/energy/stored`, `…/moving` | the energy balance: what is stored (gravity, elastic, their total, the balance), what moves (kinetic, dissipated, external work) |
//! | `plots/tension` | every coupling's tension |
//! | `plots/catenary` | every catenary's end tensions |
//! | `plots/catenary/quasi-static/<line>` | a dynamic line's quasi-static end tensions |
//! | `plots/contact` | every contact's normal force and friction |
//! | `world/water/surface`, `world/water/seabed` | the sea surface, the seabed plane |
//! | `world/water/forces/<body>` | the water's force on a floating body |
//! | `plots/water/<body>/motion`, `…/angles` | wave elevation and heave; roll and pitch |
//! | `plots/water/<body>/radiation`, `…/excitation` | a potential-flow body's radiation force and wave excitation |
//! | `world/seabed/plane` | the seabed of a scene without water |
//! | `world/seabed/grounded/<line>`, `world/seabed/touchdowns/<line>` | a line's part on the bottom, its touchdowns |
//! | `plots/seabed` | every line's grounded length, a series named after it |
//! | `plots/fit/<column>/record`, `…/model` | a measured signal and the model's beside it (a fit) |

use tether_physics::coupling::{Coupling, CouplingKind};

/// The 3D scene.
pub const WORLD: &str = "world";
/// Where the bodies are.
pub const BODIES: &str = "world/bodies";
/// Every spring-damper's line, one strip each in scene order.
pub const SPRINGS: &str = "world/springs";
/// Every coupling end fixed in the world, as points.
pub const ANCHORS: &str = "world/anchors";
/// The energy balance's stored energies: gravity, elastic, their total with the kinetic, and the
/// balance.
pub const ENERGY_STORED: &str = "plots/energy/stored";
/// The energy balance's moving terms: kinetic, dissipated, external work.
pub const ENERGY_MOVING: &str = "plots/energy/moving";
/// Every coupling's tension, one series each.
pub const TENSION: &str = "plots/tension";
/// Every catenary's end tensions, two series each.
pub const CATENARY_PLOT: &str = "plots/catenary";
/// Every contact's normal force and friction, two series each.
pub const CONTACT_PLOT: &str = "plots/contact";

/// The sea surface.
pub const WATER_SURFACE: &str = "world/water/surface";
/// The seabed plane.
pub const SEABED: &str = "world/water/seabed";
/// The floating bodies' plots.
pub const WATER_PLOTS: &str = "plots/water";
/// A potential-flow body's plot of its radiation force ([`water_plot`]).
pub const RADIATION_PLOT: &str = "radiation";
/// A potential-flow body's plot of its wave excitation ([`water_plot`]).
pub const EXCITATION_PLOT: &str = "excitation";
/// A potential-flow body's plot of its second-order wave drift (PHYSICS.md §10, [`water_plot`]).
pub const DRIFT_PLOT: &str = "drift";

/// The wind-loaded bodies' plots (PHYSICS.md §10).
pub const AIR_PLOTS: &str = "plots/air";

/// `plots/air/<body>`: the wind's force on body `body`.
pub fn air_plot(body: &str) -> String {
    format!("{AIR_PLOTS}/{body}")
}

/// The seabed plane of a scene without water.
pub const SEABED_PLANE: &str = "world/seabed/plane";
/// Every line's grounded length, a series each.
pub const SEABED_PLOT: &str = "plots/seabed";

/// The fit's plots, one per measured signal.
pub const FIT_PLOTS: &str = "plots/fit";
/// A fit plot's measured series.
pub const FIT_RECORD: &str = "record";
/// A fit plot's model series.
pub const FIT_MODEL: &str = "model";

/// `plots/fit/<column>`: a measured signal's plot (a `/` in the column's name becomes `_`, so
/// that the column stays one entity).
pub fn fit_plot(column: &str) -> String {
    format!("{FIT_PLOTS}/{}", column.replace('/', "_"))
}

/// `plots/fit/<column>/<series>`.
pub fn fit_series(column: &str, series: &str) -> String {
    format!("{}/{series}", fit_plot(column))
}

/// `world/seabed/grounded/<line>`: the part of a line on the bottom.
pub fn grounded_line(line: &str) -> String {
    format!("world/seabed/grounded/{line}")
}

/// `world/seabed/touchdowns/<line>`.
pub fn touchdowns(line: &str) -> String {
    format!("world/seabed/touchdowns/{line}")
}

/// `world/boundaries/<contact>`: the planes a contact pushes its body away from (those no earlier
/// contact is against).
pub fn boundary(contact: &str) -> String {
    format!("world/boundaries/{contact}")
}

/// `world/water/forces/<body>`.
pub fn water_force(body: &str) -> String {
    format!("world/water/forces/{body}")
}

/// `plots/water/<body>/<plot>`.
pub fn water_plot(body: &str, plot: &str) -> String {
    format!("{WATER_PLOTS}/{body}/{plot}")
}

/// `plots/catenary/quasi-static/<line>`: the quasi-static end tensions of dynamic line `line`,
/// in the catenary plot.
pub fn quasi_static_plot(line: &str) -> String {
    format!("{CATENARY_PLOT}/quasi-static/{line}")
}

/// `world/bodies/<name>`: the body's pose.
pub fn body(name: &str) -> String {
    format!("{BODIES}/{name}")
}

/// `world/bodies/<name>/shape`.
pub fn body_shape(name: &str) -> String {
    format!("{BODIES}/{name}/shape")
}

/// `world/bodies/<name>/nodes`.
pub fn body_nodes(name: &str) -> String {
    format!("{BODIES}/{name}/nodes")
}

/// Where a coupling is drawn: [`SPRINGS`] for a spring-damper (one strip among all of
/// them), `world/couplings/<name>` for a catenary (its shape), `world/contacts/<name>` for a
/// contact (its face forces).
pub fn coupling(coupling: &Coupling) -> String {
    match coupling.kind {
        CouplingKind::SpringDamper(_) => SPRINGS.to_string(),
        CouplingKind::Catenary(_) => format!("world/couplings/{}", coupling.name),
        CouplingKind::Contact(_) => format!("world/contacts/{}", coupling.name),
    }
}

/// The body an entity path (`world/bodies/<name>` or below, with or without a leading `/`)
/// belongs to.
pub fn body_of(path: &str) -> Option<&str> {
    path.trim_start_matches('/')
        .strip_prefix(BODIES)?
        .strip_prefix('/')?
        .split('/')
        .next()
        .filter(|name| !name.is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_selected_entity_names_its_body() {
        assert_eq!(body_of("/world/bodies/buoy/shape"), Some("buoy"));
        assert_eq!(body_of(&body("hull")), Some("hull"));
        assert_eq!(body_of("world/couplings/rope"), None);
        assert_eq!(body_of("world/bodies/"), None);
    }
}
