//! A wind turbine's rotor as a quasi-steady thrust (PHYSICS.md §10): at its hub, a point of a
//! body, `F = ½ ρ_a A C_T(U_r) |U_r| U_r` along the rotor's axis `n` (world axes as the body
//! turns), with `U_r = (U(z) + r u(t)) e·n − v_hub·n` the relative wind along the axis at the hub
//! [m/s] and `C_T(U)` the thrust curve, linear between its points and held beyond them.
//!
//! The hub's own velocity enters `U_r`, so the rotor damps the body's surge and pitch: to first
//! order `dF/dv = −ρ_a A (C_T U + ½ U² dC_T/dU)`, the aerodynamic damping a floating turbine's
//! surge and pitch decays show. This is the model RAFT and MoorPy use for mean offsets and
//! aerodynamic damping, not an aeroelastic rotor: no blades, no control, no wake, no gyroscopic
//! moment (OpenFAST models those).

use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require};
use crate::table::{Extrapolation, Table};

/// What a scene says of a rotor, in its body's reference frame.
#[derive(Debug, Clone, PartialEq)]
pub struct RotorSpec {
    /// The hub \[m].
    pub point: Vec3,
    /// The axis the thrust acts along when the wind blows along it (downwind) [–]; normalised.
    pub axis: Vec3,
    /// The swept area A \[m²] > 0.
    pub area: f64,
    /// `(U [m/s], C_T [–])`: U strictly increasing from ≥ 0, C_T ≥ 0.
    pub thrust: Vec<(f64, f64)>,
}

/// A rotor, checked: its hub and axis in its body's principal frame, area and thrust curve.
#[derive(Debug, Clone, PartialEq)]
pub struct Rotor {
    hub: Vec3,
    axis: Vec3,
    area: f64,
    thrust: Table,
}

impl Rotor {
    /// `spec` on a body whose reference frame is `(axes, origin)` in its principal frame
    /// (columns; principal-frame point).
    ///
    /// # Errors
    /// An area that is not positive, an axis of zero length, a thrust table that is not one, a
    /// speed below 0 or a `C_T` below 0.
    pub fn new(spec: &RotorSpec, axes: &crate::math::Mat3, origin: &Vec3) -> Result<Self, ParameterError> {
        let area = require("area", spec.area, Bound::Positive, "m²")?;
        let length = require("axis", spec.axis.norm(), Bound::Positive, "")?;
        let thrust = Table::new(spec.thrust.clone(), Extrapolation::Constant)
            .map_err(|source| ParameterError::Table { field: "thrust", source })?;
        for &(speed, coefficient) in thrust.points() {
            require("thrust: U", speed, Bound::NonNegative, "m/s")?;
            require("thrust: C_T", coefficient, Bound::NonNegative, "")?;
        }
        Ok(Self { hub: origin + axes * spec.point, axis: axes * spec.axis / length, area, thrust })
    }

    /// The hub in the principal frame \[m].
    pub fn hub(&self) -> &Vec3 {
        &self.hub
    }

    /// The axis in the principal frame (unit).
    pub fn axis(&self) -> &Vec3 {
        &self.axis
    }

    /// The swept area A \[m²].
    pub fn area(&self) -> f64 {
        self.area
    }

    /// The largest `C_T` of the thrust curve [–].
    pub fn largest_thrust_coefficient(&self) -> f64 {
        self.thrust.points().iter().map(|p| p.1).fold(0.0, f64::max)
    }

    /// `C_T(U)` [–].
    pub fn thrust_coefficient(&self, speed: f64) -> f64 {
        self.thrust.value(speed.abs())
    }

    /// The thrust \[N] along the world axis `axis` for the relative air velocity `relative`
    /// [m/s] (world axes) at the hub, density `density`.
    pub fn force(&self, axis: &Vec3, relative: &Vec3, density: f64) -> Vec3 {
        let along = axis.dot(relative);
        axis * (0.5 * density * self.area * self.thrust_coefficient(along) * along.abs() * along)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Mat3;

    fn rotor(thrust: Vec<(f64, f64)>) -> Result<Rotor, ParameterError> {
        let spec =
            RotorSpec { point: Vec3::new(0.0, 0.0, 90.0), axis: Vec3::new(2.0, 0.0, 0.0), area: 12_469.0, thrust };
        Rotor::new(&spec, &Mat3::identity(), &Vec3::new(0.0, 0.0, 1.0))
    }

    #[test]
    fn the_thrust_is_half_rho_a_ct_u_squared_along_the_axis() {
        let rotor = rotor(vec![(3.0, 0.8), (11.4, 0.75), (25.0, 0.1)]).expect("valid");
        assert_eq!(rotor.hub(), &Vec3::new(0.0, 0.0, 91.0));
        let force = rotor.force(&Vec3::x(), &Vec3::new(11.4, 3.0, 0.0), 1.225);
        let expected = 0.5 * 1.225 * 12_469.0 * 0.75 * 11.4 * 11.4;
        assert!((force.x - expected).abs() < 1e-6 && force.y == 0.0, "{force}");
        assert!((rotor.thrust_coefficient(7.2) - (0.8 - 0.05 * 4.2 / 8.4)).abs() < 1e-12);
    }

    #[test]
    fn a_bad_thrust_curve_is_refused() {
        let error = rotor(vec![(3.0, 0.8), (2.0, 0.7)]).expect_err("decreasing U");
        assert_eq!(error.to_string(), "thrust: table point 1: x must increase strictly (3 then 2)");
        let error = rotor(vec![(3.0, 0.8), (5.0, -0.1)]).expect_err("negative C_T");
        assert_eq!(error.to_string(), "thrust: C_T must be ≥ 0, got -0.1");
    }
}
