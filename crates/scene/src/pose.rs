//! Bodies' poses written back into a scene file: the scene that starts where a static solve
//! left its bodies (`tether equilibrium --write`).
//!
//! A pose is written as the scene file says a body is placed: every node translated by the
//! same `Δ` and the body turned by `rotation` about its master node. With the centre of mass
//! `c` and master node `m` as declared, the principal axes `P` of the body as built, and the
//! state `(x_G, q)` to reach: `R = q P⁻¹`, `Δ = x_G − m − R (c − m)`. Coupling points, shapes and
//! inertias are given in the body's frame and do not change. The bodies start at rest.

use super::file::{SceneFile, Triple};
use tether_physics::body::{BodyState, RigidBody};
use tether_physics::math::Vec3;

/// `file` with each body that responds to forces placed at its state in `states` (velocities
/// zero); `bodies` are the file's bodies as built.
pub fn with_poses(file: &SceneFile, bodies: &[RigidBody], states: &[BodyState]) -> SceneFile {
    let mut placed = file.clone();
    for ((def, body), state) in placed.bodies.iter_mut().zip(bodies).zip(states) {
        if body.is_kinematic() {
            continue;
        }
        let properties = &body.mass_properties;
        let turn = state.orientation * properties.principal_axes.inverse();
        let master = triple(&def.master.position);
        let shift = state.position - master - turn * (properties.center_of_mass - master);
        for node in std::iter::once(&mut def.master).chain(def.slaves.iter_mut()) {
            node.position = untriple(&(triple(&node.position) + shift));
        }
        def.rotation = untriple(&turn.scaled_axis());
        def.velocity = [0.0; 3];
        def.angular_velocity = [0.0; 3];
    }
    placed
}

fn triple(t: &Triple) -> Vec3 {
    Vec3::new(t[0], t[1], t[2])
}

fn untriple(v: &Vec3) -> Triple {
    [v.x, v.y, v.z]
}
