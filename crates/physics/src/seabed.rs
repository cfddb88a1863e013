//! The seabed (PHYSICS.md §7): a flat, level bottom at elevation `z_b` \[m], measured along the
//! upward vertical `−ĝ` (with the default gravity, the plane `z = z_b`).
//!
//! It does two things, both through couplings: a catenary whose end lies on it lays its
//! grounded length there, held by the line friction coefficient `C_B` [–]
//! ([`crate::coupling::catenary`]); and bodies touch it through contact couplings against its
//! plane (PHYSICS.md §4), which the scene declares.

use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require};

/// A flat seabed, built by [`Seabed::new`], which checks its values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seabed {
    elevation: f64,
    line_friction: f64,
}

/// A seabed that cannot be: the parameter at fault.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("seabed: {0}")]
pub struct SeabedError(pub ParameterError);

impl Seabed {
    /// A seabed at `elevation` z_b \[m] (finite) with line friction `line_friction` C_B [–] ≥ 0.
    ///
    /// # Errors
    /// A non-finite elevation, or a negative or non-finite friction coefficient.
    pub fn new(elevation: f64, line_friction: f64) -> Result<Self, SeabedError> {
        Ok(Self {
            elevation: require("elevation", elevation, Bound::Finite, "m").map_err(SeabedError)?,
            line_friction: require("line_friction", line_friction, Bound::NonNegative, "").map_err(SeabedError)?,
        })
    }

    /// `z_b` \[m]: the height of the bottom along the upward vertical.
    pub fn elevation(&self) -> f64 {
        self.elevation
    }

    /// `C_B` [–] ≥ 0: friction of a line lying on the bottom, as a fraction of its submerged
    /// weight per length (the anchor tension is `H_A = max(H − C_B W L_B, 0)`).
    pub fn line_friction(&self) -> f64 {
        self.line_friction
    }

    /// The same seabed at `elevation` z_b \[m]: the bottom of a water whose depth its own
    /// constructor checked finite (PHYSICS.md §7: the seabed stays at the water's depth).
    pub(crate) fn at_water_bottom(self, elevation: f64) -> Self {
        Self { elevation, ..self }
    }

    /// The same seabed without line friction (`C_B = 0`).
    pub(crate) fn frictionless(self) -> Self {
        Self { line_friction: 0.0, ..self }
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
