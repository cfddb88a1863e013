//! What the two kick–drift–kick schemes ([`super::leapfrog`], [`super::splitting`]) share: the
//! pass that moves the bodies to the step's end, and the forces there with the work they do over
//! the step (PHYSICS.md §5). Each scheme says only how a free body is kicked, drifted and turned,
//! and how its closing kick is taken.

use crate::body::{Acceleration, BodyFrame, BodyState, RigidBody, Support};
use crate::energy::{BodyEnergy, CouplingPower, Powers, Work};
use crate::evaluation::Evaluation;
use crate::integrator::report::StepReport;
use crate::system::{EvaluationError, System};

/// Stages *prescribe*, *advance* and *gravity* at the step's end `time` \[s]: a kinematic body
/// placed on its prescribed motion (and its frame with it), every other moved by `advance`
/// (its state, the acceleration held from the last step, its frame), and each body's load
/// cleared to its weight.
#[inline(always)]
pub fn advance_bodies(
    system: &System,
    states: &mut [BodyState],
    accelerations: &[Acceleration],
    evaluation: &mut Evaluation,
    time: f64,
    mut advance: impl FnMut(&RigidBody, &mut BodyState, &Acceleration, &mut BodyFrame),
) {
    let per_body = system
        .bodies()
        .iter()
        .zip(states.iter_mut())
        .zip(accelerations)
        .zip(evaluation.frames.iter_mut())
        .zip(evaluation.loads.iter_mut())
        .zip(system.initial_states());
    for (((((body, state), acceleration), frame), load), initial) in per_body {
        if let Support::Kinematic(motion) = &body.support {
            *state = motion.state_at(initial, time);
            *frame = state.frame();
        } else {
            advance(body, state, acceleration, frame);
        }
        *load = system.gravity_load(body);
    }
}

/// The forces at the step's end, and the powers they need for the step's work.
pub struct EndForces {
    couplings: CouplingPower,
    /// The water's and the air's power at the moved bodies' lagged velocities, before and
    /// after their forces are evaluated again \[W].
    environment_before: f64,
    environment: f64,
}

/// Stages *lines*, *couplings* and *water and air*: the forces at the moved bodies at `time`
/// \[s].
///
/// # Errors
/// A coupling that cannot give its forces.
#[inline(always)]
pub fn end_forces(system: &System, evaluation: &mut Evaluation, time: f64) -> Result<EndForces, EvaluationError> {
    system.apply_lines(evaluation, time)?;
    let couplings = system.apply_couplings(evaluation)?;
    let environment_before = system.environment_power(evaluation);
    let environment = system.apply_environment(evaluation, time);
    Ok(EndForces { couplings, environment_before, environment })
}

impl EndForces {
    /// Stage *powers*, after the scheme's closing kick (which gave `energy`, the bodies' at
    /// synchronised velocities): the work over the step of `h` \[s] by the trapezoid of the
    /// powers at both ends (`previous`, replaced by the end's). The water's and the air's work
    /// takes their forces at both ends against the half-step velocities they straddle (second
    /// order; against each end's own lagged velocity it would drift at first order, ½h ∫ F·a dt).
    #[inline(always)]
    pub fn report(
        self,
        system: &System,
        evaluation: &Evaluation,
        h: f64,
        previous: &mut Powers,
        energy: BodyEnergy,
    ) -> StepReport {
        let powers = Powers {
            couplings: self.couplings,
            external: system.external_power(evaluation),
            environment: self.environment,
        };
        let mut work = Work::trapezoid(h, previous, &powers);
        work.external += 0.5 * h * (self.environment_before + self.environment);
        *previous = powers;
        StepReport::accepted(h, work, energy)
    }
}
