//! What one step of a scheme works on: the constant system, the bodies' states it advances and
//! the evaluation it leaves (the loads and each coupling's forces at the step's end), from a
//! time by a step — one value handed to every scheme's `step` ([`super::Scheme::step`]).

use crate::body::BodyState;
use crate::evaluation::Evaluation;
use crate::system::System;

/// One step's inputs: `system`, the `states` and `evaluation` it updates, from `time` \[s] by
/// `h` \[s] (for the adaptive `dopri45`, the span left to reach, which it may take in parts).
pub struct StepContext<'a> {
    pub system: &'a System,
    pub states: &'a mut [BodyState],
    pub evaluation: &'a mut Evaluation,
    pub time: f64,
    pub h: f64,
}
