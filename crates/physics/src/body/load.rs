//! The load on a body: what its forces add up to (PHYSICS.md §1 \[11]–\[12]).

use crate::math::Vec3;

/// Sum of the forces \[N] and moments about G [N·m] on one body, world axes:
/// `F = Σ F_i`, `M = Σ M_i + Σ (x_i − x_G) × F_i`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Load {
    pub force: Vec3,
    pub moment: Vec3,
}
