//! The static equilibrium as data (PHYSICS.md §7): what [`super::report`] prints, in numbers a
//! program reads — `tether equilibrium --json` and the Python module's `equilibrium()` both
//! serialise this one struct, so the two agree by construction.
//!
//! Units: positions \[m]; orientations as unit quaternions `[w, x, y, z]` of the body's frame
//! (the scene file's axes) in the world; stiffness rows force x, y, z \[N], moment roll, pitch,
//! yaw \[N·m], columns move x, y, z \[m], turn roll, pitch, yaw \[rad]; forces \[N].

use serde::Serialize;
use tether_physics::body::{BodyState, RigidBody};
use tether_physics::coupling::CouplingKind;
use tether_physics::math::Rotation;
use tether_physics::statics::Equilibrium;
use tether_physics::system::System;

/// A static equilibrium: how it was solved, each free body's rest pose and stiffness, what each
/// coupling carries there.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EquilibriumData {
    /// Newton iterations and force evaluations taken.
    pub iterations: u32,
    pub evaluations: u32,
    /// The largest load left along a free direction \[N] and about one \[N·m].
    pub residual_force: f64,
    pub residual_moment: f64,
    /// `body direction` of a negative stiffness (an unstable equilibrium), if any.
    pub unstable: Option<String>,
    /// The bodies that respond to forces (kinematic ones are where their motion puts them).
    pub bodies: Vec<BodyRest>,
    pub couplings: Vec<CouplingLoad>,
}

/// A free body at equilibrium.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyRest {
    pub name: String,
    /// Centre of mass, world \[m].
    pub position: [f64; 3],
    /// Its move from the scene's start \[m].
    pub moved: [f64; 3],
    /// Orientation of the body's frame, `[w, x, y, z]`.
    pub quaternion: [f64; 4],
    /// 6 × 6 stiffness there, the other bodies held (units in the module's doc).
    pub stiffness: [[f64; 6]; 6],
}

/// What a coupling carries at equilibrium; the fields its kind has, the others `None`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CouplingLoad {
    pub name: String,
    /// `spring_damper`, `catenary` or `contact`.
    pub kind: String,
    /// Tension at end 1 and end 2 \[N] (a spring: its tension at both).
    pub tension1: Option<f64>,
    pub tension2: Option<f64>,
    /// A catenary's horizontal tension \[N] and length lying on the seabed \[m].
    pub horizontal_tension: Option<f64>,
    pub grounded_length: Option<f64>,
    /// A spring's length \[m].
    pub length: Option<f64>,
    /// A contact's normal force \[N].
    pub normal: Option<f64>,
}

/// The orientation of `body`'s frame (the scene file's axes) for its principal-axes state
/// `state`, `[w, x, y, z]`.
pub fn body_quaternion(body: &RigidBody, state: &BodyState) -> [f64; 4] {
    let turn: Rotation = state.orientation * body.mass_properties.principal_axes.inverse();
    [turn.w, turn.i, turn.j, turn.k]
}

/// The data of `equilibrium` of `system`, reached from `start`.
pub fn equilibrium(system: &System, equilibrium: &Equilibrium, start: &[BodyState]) -> EquilibriumData {
    let bodies = system
        .bodies()
        .iter()
        .enumerate()
        .filter(|(_, body)| !body.is_kinematic())
        .map(|(index, body)| {
            let state = &equilibrium.states[index];
            let k = equilibrium.body_stiffness(index);
            let moved = state.position - start[index].position;
            BodyRest {
                name: body.name.clone(),
                position: state.position.into(),
                moved: moved.into(),
                quaternion: body_quaternion(body, state),
                stiffness: std::array::from_fn(|row| std::array::from_fn(|column| k[(row, column)] + 0.0)),
            }
        })
        .collect();
    let couplings = system
        .couplings()
        .iter()
        .zip(equilibrium.evaluation.forces())
        .enumerate()
        .map(|(index, (coupling, forces))| {
            let mut load = CouplingLoad {
                name: coupling.name.clone(),
                kind: coupling.kind_name().to_string(),
                tension1: None,
                tension2: None,
                horizontal_tension: None,
                grounded_length: None,
                length: None,
                normal: None,
            };
            match &coupling.kind {
                CouplingKind::Catenary(_) => {
                    if let Some(line) = equilibrium.evaluation.line_state(index) {
                        let (t1, t2) = line.end_tensions();
                        load.tension1 = Some(t1);
                        load.tension2 = Some(t2);
                        load.horizontal_tension = Some(line.horizontal_tension);
                        load.grounded_length = Some(line.grounded_length());
                    }
                }
                CouplingKind::SpringDamper(_) => {
                    load.tension1 = Some(forces.tension);
                    load.tension2 = Some(forces.tension);
                    load.length = Some((forces.point2 - forces.point1).norm());
                }
                CouplingKind::Contact(_) => {
                    load.normal = equilibrium.evaluation.contact_forces(index).map(|f| f.normal);
                }
            }
            load
        })
        .collect();
    EquilibriumData {
        iterations: equilibrium.iterations,
        evaluations: equilibrium.evaluations,
        residual_force: equilibrium.residual_force,
        residual_moment: equilibrium.residual_moment,
        unstable: equilibrium.unstable.map(|dof| format!("{} {}", system.bodies()[dof.body].name, dof.direction)),
        bodies,
        couplings,
    }
}
