//! `tether forces SCENE --json`: the forces of the initial state.

use serde::Serialize;
use tether_physics::math::Vec3;
use tether_physics::world::World;
use tether_scene::Scene;

#[derive(Serialize)]
struct Report<'a> {
    couplings: Vec<CouplingReport<'a>>,
    bodies: Vec<BodyReport<'a>>,
}

/// Forces exerted by the coupling on end 1 and end 2 [N], world frame; for a catenary also
/// the horizontal tension [N] and the parameters `u1`, `u2` (PHYSICS.md §3; null when the line
/// is vertical and they are infinite).
#[derive(Serialize)]
struct CouplingReport<'a> {
    name: &'a str,
    kind: &'a str,
    f1: [f64; 3],
    f2: [f64; 3],
    #[serde(flatten, skip_serializing_if = "Option::is_none")]
    catenary: Option<CatenaryReport>,
    /// A dynamic line's nodes, none for other couplings.
    #[serde(skip_serializing_if = "Option::is_none")]
    nodes: Option<Vec<[f64; 3]>>,
}

#[derive(Serialize)]
struct CatenaryReport {
    horizontal_tension: f64,
    u1: f64,
    u2: f64,
}

fn catenary_report(world: &World, index: usize) -> Option<CatenaryReport> {
    let state = world.line_state(index)?;
    let (u1, u2) = state.parameters();
    Some(CatenaryReport { horizontal_tension: state.horizontal_tension, u1, u2 })
}

/// A dynamic line's node positions `r_0 … r_N` \[m] (PHYSICS.md §8).
fn line_nodes(world: &World, index: usize) -> Option<Vec<[f64; 3]>> {
    let nodes = world.evaluation().line_run(index)?.nodes()?;
    Some(nodes.positions.iter().map(a).collect())
}

/// Total force [N] and moment about G [N·m] on a body, world frame; for a floating body also
/// what the water does (PHYSICS.md §6).
#[derive(Serialize)]
struct BodyReport<'a> {
    name: &'a str,
    force: [f64; 3],
    moment: [f64; 3],
    #[serde(skip_serializing_if = "Option::is_none")]
    water: Option<WaterReport>,
}

/// The water's force [N] and moment about G [N·m] on a body (pressure, drag and added mass
/// together, and the pressure alone), world frame; its submerged volume [m³] and wetted
/// fraction.
#[derive(Serialize)]
struct WaterReport {
    force: [f64; 3],
    moment: [f64; 3],
    pressure_force: [f64; 3],
    pressure_moment: [f64; 3],
    submerged_volume: f64,
    wetted_fraction: f64,
}

fn water_report(world: &World, body: usize) -> Option<WaterReport> {
    let record = world.water_forces().iter().find(|r| r.body == body)?;
    let total = record.total();
    Some(WaterReport {
        force: a(&total.force),
        moment: a(&total.moment),
        pressure_force: a(&record.pressure.force),
        pressure_moment: a(&record.pressure.moment),
        submerged_volume: record.submerged_volume,
        wetted_fraction: record.wetted_fraction,
    })
}

fn a(v: &Vec3) -> [f64; 3] {
    [v.x, v.y, v.z]
}

fn report(world: &World) -> Report<'_> {
    Report {
        couplings: world
            .couplings()
            .iter()
            .zip(world.coupling_forces())
            .enumerate()
            .map(|(i, (c, f))| CouplingReport {
                name: &c.name,
                kind: c.kind_name(),
                f1: a(&f.f1),
                f2: a(&f.f2),
                catenary: catenary_report(world, i),
                nodes: line_nodes(world, i),
            })
            .collect(),
        bodies: world
            .bodies()
            .iter()
            .enumerate()
            .map(|(i, b)| BodyReport {
                name: &b.name,
                force: a(&world.load(i).force),
                moment: a(&world.load(i).moment),
                water: water_report(world, i),
            })
            .collect(),
    }
}

pub fn run(scene: &Scene, json: bool) -> anyhow::Result<()> {
    let report = report(&scene.world);
    let text = if json {
        serde_json::to_string_pretty(&report)? + "\n"
    } else {
        let mut out = String::new();
        for c in &report.couplings {
            out += &format!("coupling {:<20} f1 {:?} N  f2 {:?} N\n", c.name, c.f1, c.f2);
        }
        for b in &report.bodies {
            out += &format!("body     {:<20} force {:?} N  moment {:?} N·m\n", b.name, b.force, b.moment);
            if let Some(w) = &b.water {
                out += &format!(
                    "  water  {:<20} force {:?} N  moment {:?} N·m  submerged {} m³\n",
                    "", w.force, w.moment, w.submerged_volume
                );
            }
        }
        out
    };
    super::print(&text)
}
