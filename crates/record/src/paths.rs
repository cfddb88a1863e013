//! The recording's entity paths, in one table: the recorder writes them, the viewer layout and
//! the GUI's selection read them.
//!
//! | path | what |
//! |---|---|
//! | `world` | view coordinates (right-handed, z up) |
//! | `world/bodies/<name>` | a body's pose: G and its principal axes |
//! | `world/bodies/<name>/shape`, `…/nodes` | its static shape and slave nodes |
//! | `world/couplings/<name>` | a spring's or a line's drawing |
//! | `world/contacts/<name>` | a contact's face forces |
//! | `plots/energy` | the energy balance |
//! | `plots/tension` | every coupling's tension |
//! | `plots/catenary/<name>` | a catenary's end tensions |
//! | `plots/contact/<name>` | a contact's normal force and friction |
//! | `world/water/surface`, `world/water/seabed` | the sea surface, the seabed plane |
//! | `world/water/forces/<body>` | the water's force on a floating body |
//! | `plots/water/<body>/motion`, `…/angles` | wave elevation and heave; roll and pitch |
//! | `world/seabed/plane` | the seabed of a scene without water |
//! | `world/seabed/grounded/<line>`, `world/seabed/touchdowns/<line>` | a line's part on the bottom, its touchdowns |
//! | `plots/seabed/<line>` | a line's grounded length |

use tether_physics::coupling::{Coupling, CouplingKind};

/// The 3D scene.
pub const WORLD: &str = "world";
/// Where the bodies are.
pub const BODIES: &str = "world/bodies";
/// The energy plot.
pub const ENERGY: &str = "plots/energy";
/// Every coupling's tension, one series each.
pub const TENSION: &str = "plots/tension";
/// The catenaries' end tension plots.
pub const CATENARY_PLOTS: &str = "plots/catenary";
/// The contacts' force plots.
pub const CONTACT_PLOTS: &str = "plots/contact";

/// The sea surface.
pub const WATER_SURFACE: &str = "world/water/surface";
/// The seabed plane.
pub const SEABED: &str = "world/water/seabed";
/// The floating bodies' plots.
pub const WATER_PLOTS: &str = "plots/water";

/// The seabed plane of a scene without water.
pub const SEABED_PLANE: &str = "world/seabed/plane";
/// The lines' grounded length plots.
pub const SEABED_PLOTS: &str = "plots/seabed";

/// `world/seabed/grounded/<line>`: the part of a line on the bottom.
pub fn grounded_line(line: &str) -> String {
    format!("world/seabed/grounded/{line}")
}

/// `world/seabed/touchdowns/<line>`.
pub fn touchdowns(line: &str) -> String {
    format!("world/seabed/touchdowns/{line}")
}

/// `plots/seabed/<line>`.
pub fn seabed_plot(line: &str) -> String {
    format!("{SEABED_PLOTS}/{line}")
}

/// `world/water/forces/<body>`.
pub fn water_force(body: &str) -> String {
    format!("world/water/forces/{body}")
}

/// `plots/water/<body>/<plot>`.
pub fn water_plot(body: &str, plot: &str) -> String {
    format!("{WATER_PLOTS}/{body}/{plot}")
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

/// Where a coupling is drawn: `world/contacts/<name>` for a contact (its face forces),
/// `world/couplings/<name>` for the others (a line).
pub fn coupling(coupling: &Coupling) -> String {
    match coupling.kind {
        CouplingKind::Contact(_) => format!("world/contacts/{}", coupling.name),
        CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => format!("world/couplings/{}", coupling.name),
    }
}

/// `plots/catenary/<name>`.
pub fn catenary_plot(name: &str) -> String {
    format!("{CATENARY_PLOTS}/{name}")
}

/// `plots/contact/<name>`.
pub fn contact_plot(name: &str) -> String {
    format!("{CONTACT_PLOTS}/{name}")
}

/// The body an entity path (`world/bodies/<name>` or below, with or without a leading `/`)
/// belongs to.
pub fn body_of(path: &str) -> Option<&str> {
    path.trim_start_matches('/').strip_prefix(BODIES)?.strip_prefix('/')?.split('/').next().filter(|name| !name.is_empty())
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
