//! The seabed (PHYSICS.md §7): a flat, level bottom at elevation `z_b` \[m], measured along the
//! upward vertical `−ĝ` (with the default gravity, the plane `z = z_b`).
//!
//! It does two things, both through couplings: a catenary whose end lies on it lays its
//! grounded length there, held by the line friction coefficient `C_B` [–]
//! ([`crate::coupling::catenary`]); and bodies touch it through contact couplings against its
//! plane (PHYSICS.md §4), which the scene declares.

use crate::math::Vec3;

/// A flat seabed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seabed {
    /// `z_b` \[m]: the height of the bottom along the upward vertical.
    pub elevation: f64,
    /// `C_B` [–] ≥ 0: friction of a line lying on the bottom, as a fraction of its submerged
    /// weight per length (the anchor tension is `H_A = max(H − C_B W L_B, 0)`).
    pub line_friction: f64,
}

/// A seabed that cannot be.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum SeabedError {
    #[error("seabed elevation must be finite, got {0} m")]
    Elevation(f64),
    #[error("seabed line friction C_B must be ≥ 0, got {0}")]
    LineFriction(f64),
}

impl Seabed {
    /// A seabed at `elevation` \[m] with line friction `line_friction` [–].
    ///
    /// # Errors
    /// A non-finite elevation, or a negative or non-finite friction coefficient.
    pub fn new(elevation: f64, line_friction: f64) -> Result<Self, SeabedError> {
        if !elevation.is_finite() {
            return Err(SeabedError::Elevation(elevation));
        }
        if !(line_friction >= 0.0 && line_friction.is_finite()) {
            return Err(SeabedError::LineFriction(line_friction));
        }
        Ok(Self { elevation, line_friction })
    }

    /// Height \[m] of `point` above the bottom, along the unit upward vertical `up`.
    #[inline]
    pub fn height(&self, point: &Vec3, up: &Vec3) -> f64 {
        point.dot(up) - self.elevation
    }

    /// The point of the bottom below `point` \[m].
    pub fn below(&self, point: &Vec3, up: &Vec3) -> Vec3 {
        point - up * self.height(point, up)
    }
}
