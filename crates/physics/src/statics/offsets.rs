//! The offset curve (the mooring engineer's restoring-force curve): a body held at a ladder of
//! offsets from its static equilibrium along one direction, every other direction (its own and
//! the other bodies') settled again at each, and the load along the held direction recorded.

use super::dofs::{Dof, displace};
use super::equilibrium::{self, Equilibrium, EquilibriumError, Settings};
use crate::evaluation::Evaluation;
use crate::system::System;

/// One point of the curve.
#[derive(Debug, Clone)]
pub struct Offset {
    /// Displacement from equilibrium along the direction [m or rad].
    pub offset: f64,
    /// Net load on the body along the direction [N or N·m]: what the system pulls it back
    /// with is `−load`.
    pub load: f64,
    /// The evaluation there: every coupling's forces and solved lines.
    pub evaluation: Evaluation,
    /// Newton iterations of the settling solve.
    pub iterations: u32,
}

/// A body's offset curve.
#[derive(Debug, Clone)]
pub struct OffsetCurve {
    pub dof: Dof,
    pub points: Vec<Offset>,
}

/// Holds `dof` at `steps + 1` evenly spaced offsets from 0 to `to` [m or rad] from `equilibrium`
/// (of `system`), each settled from the last.
///
/// # Errors
/// An offset at which the other directions find no equilibrium.
pub fn curve(
    system: &System,
    equilibrium: &Equilibrium,
    dof: Dof,
    to: f64,
    steps: u32,
    settings: &Settings,
) -> Result<OffsetCurve, EquilibriumError> {
    let steps = steps.max(1);
    let mut states = equilibrium.states.clone();
    let mut points = Vec::with_capacity(steps as usize + 1);
    let mut previous = 0.0;
    for k in 0..=steps {
        let offset = to * f64::from(k) / f64::from(steps);
        displace(&mut states[dof.body], dof.direction, offset - previous);
        previous = offset;
        let settled = equilibrium::solve(system, &states, &[dof], settings)?;
        states.clone_from(&settled.states);
        points.push(Offset {
            offset,
            load: settled.load(dof),
            iterations: settled.iterations,
            evaluation: settled.evaluation,
        });
    }
    Ok(OffsetCurve { dof, points })
}
