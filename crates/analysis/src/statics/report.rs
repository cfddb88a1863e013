//! The static equilibrium in numbers: how it was solved, where each body rests and how stiffly,
//! what each coupling carries there.

use std::fmt::Write as _;
use std::time::Duration;
use tether_physics::body::BodyState;
use tether_physics::coupling::CouplingKind;
use tether_physics::math::Vec3;
use tether_physics::statics::{Direction, Equilibrium};
use tether_physics::system::System;

/// The report of `equilibrium` of `system`, reached from `start` in `elapsed`.
pub fn equilibrium(system: &System, equilibrium: &Equilibrium, start: &[BodyState], elapsed: Duration) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "static equilibrium in {} Newton iterations ({} force evaluations, {:.3} ms); largest load left {:.3e} N, {:.3e} N·m",
        equilibrium.iterations,
        equilibrium.evaluations,
        elapsed.as_secs_f64() * 1e3,
        equilibrium.residual_force,
        equilibrium.residual_moment
    );
    if let Some(dof) = equilibrium.unstable {
        let _ = writeln!(
            out,
            "warning: the equilibrium is unstable: body \"{}\" has a negative stiffness in {}",
            system.bodies()[dof.body].name,
            dof.direction
        );
    }
    for (index, body) in system.bodies().iter().enumerate() {
        if body.is_kinematic() {
            continue;
        }
        let state = &equilibrium.states[index];
        let turn = state.orientation * body.mass_properties.principal_axes.inverse();
        let (roll, pitch, yaw) = turn.euler_angles();
        let _ = writeln!(out, "\nbody \"{}\"", body.name);
        let _ = writeln!(
            out,
            "  centre of mass  {} m (moved {} m)",
            v(&state.position),
            v(&(state.position - start[index].position))
        );
        let _ = writeln!(
            out,
            "  attitude        roll {:.4}°, pitch {:.4}°, yaw {:.4}° (rotation vector {} rad)",
            roll.to_degrees(),
            pitch.to_degrees(),
            yaw.to_degrees(),
            v(&turn.scaled_axis())
        );
        let _ = writeln!(
            out,
            "  stiffness at equilibrium, the other bodies held (rows: force x, y, z [N], moment roll, pitch, yaw [N·m]; columns: move x, y, z [m], turn roll, pitch, yaw [rad]):"
        );
        let k = equilibrium.body_stiffness(index);
        let header: String = Direction::ALL.iter().map(|d| format!("{:>14}", d.name())).collect();
        let _ = writeln!(out, "  {:>6}{header}", "");
        for (row, direction) in Direction::ALL.iter().enumerate() {
            let cells: String = (0..6).map(|column| format!("{:>14.6e}", k[(row, column)] + 0.0)).collect();
            let _ = writeln!(out, "  {:>6}{cells}", direction.name());
        }
    }
    for (index, (coupling, forces)) in system.couplings().iter().zip(equilibrium.evaluation.forces()).enumerate() {
        let _ = write!(out, "\ncoupling \"{}\" ({}): ", coupling.name, coupling.kind_name());
        match &coupling.kind {
            CouplingKind::Catenary(_) => match equilibrium.evaluation.line_state(index) {
                Some(line) => {
                    let (t1, t2) = line.end_tensions();
                    let _ = writeln!(
                        out,
                        "tension {t1:.6e} N at end 1, {t2:.6e} N at end 2; horizontal tension {:.6e} N",
                        line.horizontal_tension
                    );
                    if line.ground.is_some() {
                        let touchdowns: Vec<String> = line.touchdowns().iter().map(v).collect();
                        let touchdowns = if touchdowns.is_empty() {
                            "none (the line lies on the seabed from both ends)".to_string()
                        } else {
                            format!("{} m", touchdowns.join(", "))
                        };
                        let _ = writeln!(
                            out,
                            "  on the seabed: grounded length L_B {:.6} m, touchdown {touchdowns}",
                            line.grounded_length()
                        );
                    } else {
                        let _ = writeln!(out, "  clear of the seabed");
                    }
                }
                None => {
                    let _ = writeln!(out, "not solved");
                }
            },
            CouplingKind::SpringDamper(_) => {
                let _ = writeln!(
                    out,
                    "tension {:.6e} N at length {:.6} m",
                    forces.tension,
                    (forces.point2 - forces.point1).norm()
                );
            }
            CouplingKind::Contact(_) => {
                let _ = writeln!(
                    out,
                    "normal force {:.6e} N",
                    equilibrium.evaluation.contact_forces(index).map_or(f64::NAN, |f| f.normal)
                );
            }
        }
    }
    out
}

/// `(x, y, z)` with 6 decimals; `+ 0.0` prints −0 as 0.
pub(crate) fn v(x: &Vec3) -> String {
    format!("({:.6}, {:.6}, {:.6})", x.x + 0.0, x.y + 0.0, x.z + 0.0)
}
