//! The tangent stiffness of a system at an evaluation: `K = −∂(F, M)/∂(x, θ)` over the six
//! directions of every body ([`super::dofs`]), `6n × 6n`, in N/m, N/rad, N·m/m and N·m/rad.
//!
//! Every force source adds its own part, summed here (MuJoCo's per-source buffers, once more):
//! gravity acts at G with a constant force and adds none; a spring or a catenary adds its
//! ends' stiffness blocks `D_ij = ∂f_i/∂p_j` carried to the bodies through the lever arms
//! `a = x_end − x_G` (`δp = δx − [a]× δθ`, `δM = a × δf + (a fᵀ − (a·f) E) δθ`, the second
//! term because the arm turns with the body); a contact, whose force is a sum over faces, adds
//! central differences of its own loads as its bodies move; so does the water on each floating
//! body (pressure integrated over the hull cut at the waterline, the current's drag). A new
//! source joins by adding its part in [`tangent`]; the equilibrium solver only calls it.

use super::dofs::Direction;
use crate::body::{BodyFrame, Load};
use crate::coupling::ends::Attachment;
use crate::coupling::{Coupling, CouplingForces, CouplingKind};
use crate::evaluation::Evaluation;
use crate::math::{Mat3, Rotation, Vec3};
use crate::system::System;
use crate::water::WaterForces;
use crate::water_stage::{WaterScratch, WaterStageInputs};
use nalgebra::DMatrix;

/// The time \[s] of a static evaluation: nothing in the system at rest
/// ([`System::at_rest`]) depends on it.
pub const STATIC_TIME: f64 = 0.0;

/// Finite-difference steps: a translation [m] and a rotation [rad] small against any contact
/// range and large against round-off.
const TRANSLATION_STEP: f64 = 1e-7;
const ROTATION_STEP: f64 = 1e-7;

/// `K` \[SI] at the kinematics and coupling records of `evaluation` (its last evaluation, with
/// the bodies at rest, at [`STATIC_TIME`]).
pub fn tangent(system: &System, evaluation: &Evaluation) -> DMatrix<f64> {
    let n = system.bodies().len();
    let mut jacobian = DMatrix::zeros(6 * n, 6 * n);
    let frames = evaluation.frames();
    for (index, coupling) in system.couplings().iter().enumerate() {
        let record = &evaluation.forces()[index];
        match &coupling.kind {
            CouplingKind::SpringDamper(spring) => {
                add_ends(&mut jacobian, coupling, frames, record, &spring.end_stiffness(frames))
            }
            CouplingKind::Catenary(_) => {
                if let Some(state) = evaluation.line_state(index) {
                    add_ends(&mut jacobian, coupling, frames, record, &state.end_stiffness());
                }
            }
            CouplingKind::Contact(contact) => {
                let bodies: Vec<usize> = [Some(contact.body()), contact.other_body()].into_iter().flatten().collect();
                add_differences(&mut jacobian, system, frames, &bodies, |moved, loads| {
                    let mut cache = evaluation.caches()[index].clone();
                    let mut record = CouplingForces::default();
                    // Only non-finite kinematics make a coupling fail; a contact never does.
                    let _ = coupling.apply(&mut cache, moved, system.surroundings(), loads, &mut record);
                });
            }
        }
    }
    if let Some(stage) = system.water() {
        let bodies: Vec<usize> = stage.floating.iter().map(|f| f.body()).collect();
        let mut records = vec![WaterForces::default(); bodies.len()];
        let mut radiation = vec![crate::potential::RadiationRun::default(); bodies.len()];
        let mut scratch = WaterScratch::default();
        add_differences(&mut jacobian, system, frames, &bodies, |moved, loads| {
            let on = WaterStageInputs {
                bodies: system.bodies(),
                frames: moved,
                loads,
                records: &mut records,
                radiation: &mut radiation,
                scratch: &mut scratch,
            };
            stage.apply(system.supported_level(), on, STATIC_TIME);
        });
    }
    -jacobian
}

/// Adds `∂(F, M)/∂(x, θ)` of a two-ended coupling with end forces `record.f1`, `record.f2` and
/// stiffness blocks `blocks[i][j] = ∂f_i/∂p_j`.
fn add_ends(
    jacobian: &mut DMatrix<f64>,
    coupling: &Coupling,
    frames: &[BodyFrame],
    record: &CouplingForces,
    blocks: &[[Mat3; 2]; 2],
) {
    let [end1, end2] = coupling.ends();
    let attachments = [end1.motion(frames).attachment, end2.motion(frames).attachment];
    let forces = [record.f1, record.f2];
    let on_body = |attachment: Attachment| match attachment {
        Attachment::World => None,
        Attachment::Center(body) => Some((body, Vec3::zeros())),
        Attachment::Arm(body, arm) => Some((body, arm)),
    };
    for i in 0..2 {
        let Some((body_i, arm_i)) = on_body(attachments[i]) else { continue };
        let (ti, ri) = (6 * body_i, 6 * body_i + 3);
        let cross_i = arm_i.cross_matrix();
        for j in 0..2 {
            let Some((body_j, arm_j)) = on_body(attachments[j]) else { continue };
            let (tj, rj) = (6 * body_j, 6 * body_j + 3);
            let d = &blocks[i][j];
            let cross_j = arm_j.cross_matrix();
            add_block(jacobian, ti, tj, d);
            add_block(jacobian, ti, rj, &(-d * cross_j));
            add_block(jacobian, ri, tj, &(cross_i * d));
            add_block(jacobian, ri, rj, &(-cross_i * d * cross_j));
        }
        let f = forces[i];
        add_block(jacobian, ri, ri, &(arm_i * f.transpose() - Mat3::identity() * arm_i.dot(&f)));
    }
}

fn add_block(jacobian: &mut DMatrix<f64>, row: usize, column: usize, block: &Mat3) {
    let mut view = jacobian.fixed_view_mut::<3, 3>(row, column);
    view += block;
}

/// Adds central differences of the loads that `loads_at` puts on the bodies as each direction
/// of each of `bodies` moves (kinematic bodies do not move).
pub fn add_differences(
    jacobian: &mut DMatrix<f64>,
    system: &System,
    frames: &[BodyFrame],
    bodies: &[usize],
    mut loads_at: impl FnMut(&[BodyFrame], &mut [Load]),
) {
    let n = frames.len();
    let mut moved = frames.to_vec();
    let (mut plus, mut minus) = (vec![Load::default(); n], vec![Load::default(); n]);
    for &body in bodies.iter().filter(|&&b| !system.bodies()[b].is_kinematic()) {
        for direction in Direction::ALL {
            let step = if direction.is_rotation() { ROTATION_STEP } else { TRANSLATION_STEP };
            for (sign, loads) in [(1.0, &mut plus), (-1.0, &mut minus)] {
                moved[body] = shifted(&frames[body], direction, sign * step);
                loads.fill(Load::default());
                loads_at(&moved, loads);
            }
            moved[body] = frames[body];
            let column = 6 * body + direction.index();
            for (row_body, (p, m)) in plus.iter().zip(&minus).enumerate() {
                let (df, dm) = ((p.force - m.force) / (2.0 * step), (p.moment - m.moment) / (2.0 * step));
                for axis in 0..3 {
                    jacobian[(6 * row_body + axis, column)] += df[axis];
                    jacobian[(6 * row_body + 3 + axis, column)] += dm[axis];
                }
            }
        }
    }
}

/// `frame` moved by `amount` [m or rad] in `direction` (a rotation about the world axis
/// through G), at rest.
fn shifted(frame: &BodyFrame, direction: Direction, amount: f64) -> BodyFrame {
    let mut moved = BodyFrame { velocity: Vec3::zeros(), angular_velocity: Vec3::zeros(), ..*frame };
    let index = direction.index();
    if direction.is_rotation() {
        moved.rotation =
            Rotation::from_scaled_axis(Vec3::ith(index - 3, amount)).to_rotation_matrix().into_inner() * frame.rotation;
    } else {
        moved.position[index] += amount;
    }
    moved
}
