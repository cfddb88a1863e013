//! The degrees of freedom a static solve moves: for each body that responds to forces, the
//! translation of G along the world axes and a small rotation about the world axes through G
//! (`R ← exp([δθ]×) R`), less what its support holds; kinematic bodies stay where they are.
//! The loads conjugate to them are the force on the body and its moment about G, world axes.

use crate::body::{BodyState, Support};
use crate::math::{Rotation, Vec3};
use crate::system::System;

/// A direction a body moves in: along or about a world axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Direction {
    X,
    Y,
    Z,
    /// About x.
    Roll,
    /// About y.
    Pitch,
    /// About z.
    Yaw,
}

impl Direction {
    pub const ALL: [Self; 6] = [Self::X, Self::Y, Self::Z, Self::Roll, Self::Pitch, Self::Yaw];

    /// 0–2 for the translations, 3–5 for the rotations: the index into a body's six loads.
    pub fn index(self) -> usize {
        self as usize
    }

    /// `x`, `y`, `z`, `roll`, `pitch`, `yaw`.
    pub fn name(self) -> &'static str {
        match self {
            Self::X => "x",
            Self::Y => "y",
            Self::Z => "z",
            Self::Roll => "roll",
            Self::Pitch => "pitch",
            Self::Yaw => "yaw",
        }
    }

    /// Whether it turns the body.
    pub fn is_rotation(self) -> bool {
        self.index() >= 3
    }

    /// Unit of a displacement along it: `m` or `rad`.
    pub fn unit(self) -> &'static str {
        if self.is_rotation() { "rad" } else { "m" }
    }

    /// Unit of the load along it: `N` or `N·m`.
    pub fn load_unit(self) -> &'static str {
        if self.is_rotation() { "N·m" } else { "N" }
    }
}

impl std::fmt::Display for Direction {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Direction {
    type Err = String;

    fn from_str(text: &str) -> Result<Self, Self::Err> {
        Self::ALL
            .into_iter()
            .find(|d| d.name() == text)
            .ok_or_else(|| format!("unknown direction {text:?} (x, y, z, roll, pitch, yaw)"))
    }
}

/// One degree of freedom: a body and a direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Dof {
    pub body: usize,
    pub direction: Direction,
}

impl Dof {
    /// Its row in a vector of six loads per body.
    pub fn row(self) -> usize {
        6 * self.body + self.direction.index()
    }
}

/// The degrees of freedom of a system that a static solve moves.
#[derive(Debug, Clone, PartialEq)]
pub struct Dofs {
    free: Vec<Dof>,
}

impl Dofs {
    /// Every direction of every body that responds to forces, less what its support holds and
    /// what `held` lists.
    pub fn of(system: &System, held: &[Dof]) -> Self {
        let mut free = Vec::new();
        for (body, rigid) in system.bodies().iter().enumerate() {
            let holds = |direction: Direction| match &rigid.support {
                Support::Free => false,
                Support::Kinematic(_) => true,
                Support::Fixed { translation, rotation } => {
                    if direction.is_rotation() {
                        *rotation
                    } else {
                        translation[direction.index()]
                    }
                }
            };
            for direction in Direction::ALL {
                let dof = Dof { body, direction };
                if !holds(direction) && !held.contains(&dof) {
                    free.push(dof);
                }
            }
        }
        Self { free }
    }

    /// The degrees of freedom, in order.
    pub fn free(&self) -> &[Dof] {
        &self.free
    }

    pub fn len(&self) -> usize {
        self.free.len()
    }

    pub fn is_empty(&self) -> bool {
        self.free.is_empty()
    }
}

/// Moves `state` by `amount` [m or rad] in `direction`: a translation of G, or a rotation about
/// the world axis through G.
pub fn displace(state: &mut BodyState, direction: Direction, amount: f64) {
    let index = direction.index();
    if direction.is_rotation() {
        let axis = Vec3::ith(index - 3, amount);
        state.orientation = Rotation::from_scaled_axis(axis) * state.orientation;
    } else {
        state.position[index] += amount;
    }
}

/// A body's displacement `(δx, δθ)` [m, rad] applied at once: G moved by `δx`, the body turned
/// by the rotation vector `δθ` (world axes) about G.
pub fn displace_by(state: &mut BodyState, translation: &Vec3, rotation: &Vec3) {
    state.position += translation;
    state.orientation = Rotation::from_scaled_axis(*rotation) * state.orientation;
}
