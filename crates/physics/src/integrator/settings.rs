//! The time step settings a scene declares: which integrator, the world step, its substeps and
//! the adaptive scheme's tolerances, each checked by its constructor ([`Timing::new`],
//! [`Tolerances::new`]).

use crate::parameter::{Bound, ParameterError, require};

/// The scheme that advances a world by one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Integrator {
    /// The central-difference scheme of PHYSICS.md §1 "Time integration" ([`super::leapfrog`]).
    #[default]
    Leapfrog,
    /// The leapfrog with the gyroscopic term at a predicted ω(t) ([`super::leapfrog2`]).
    Leapfrog2,
    /// Kick–drift–kick with the free rigid body split into exact rotations about the principal
    /// axes ([`super::splitting`]).
    Splitting,
    /// Classical fourth-order Runge–Kutta ([`super::rk4`]).
    Rk4,
    /// Adaptive Dormand–Prince 5(4) ([`super::dopri45`]), settings in [`Tolerances`].
    Dopri45,
}

impl Integrator {
    /// Every scheme, in the order of the table above.
    pub const ALL: [Self; 5] = [Self::Leapfrog, Self::Leapfrog2, Self::Splitting, Self::Rk4, Self::Dopri45];

    /// The name scene files and the command line use.
    pub fn name(self) -> &'static str {
        match self {
            Self::Leapfrog => "leapfrog",
            Self::Leapfrog2 => "leapfrog2",
            Self::Splitting => "splitting",
            Self::Rk4 => "rk4",
            Self::Dopri45 => "dopri45",
        }
    }

    /// The scheme called `name` (as in scene files), if there is one.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|i| i.name() == name)
    }

    /// Whether the scheme chooses its own steps (and so has no stability limit to respect).
    pub fn is_adaptive(self) -> bool {
        match self {
            Self::Dopri45 => true,
            Self::Leapfrog | Self::Leapfrog2 | Self::Splitting | Self::Rk4 => false,
        }
    }
}

/// How many integrator steps one world step takes: the world advances by `dt`, its integrator
/// by `dt / n` (recordings log world steps).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Substeps {
    /// `n ≥ 1` integrator steps per world step.
    Fixed(u32),
    /// Enough integrator steps to keep each under 0.9 of the binding stable time step of the
    /// scene's integrator at t = 0 and of every contact's impact resolution τ/10 (one for the
    /// adaptive `dopri45`, whose steps adapt), up to [`MAX_AUTO_SUBSTEPS`].
    Auto,
}

/// `Substeps::Auto` takes at most this many integrator steps per world step: a scene that needs
/// more (a stiffness typed a million times too high) runs unstable and the health check stops
/// it with the stable time step in the message, rather than seeming to hang.
pub const MAX_AUTO_SUBSTEPS: u32 = 10_000;

impl Default for Substeps {
    fn default() -> Self {
        Self::Fixed(1)
    }
}

/// Settings of the adaptive [`Integrator::Dopri45`]: a step is accepted when its estimated
/// error is below `atol + rtol·|y|` for every component (position \[m], velocity [m/s],
/// orientation quaternion [–], angular velocity [rad/s]), in the root-mean-square sense.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerances {
    rtol: f64,
    atol: f64,
    max_step: Option<f64>,
}

impl Tolerances {
    /// Relative tolerance `rtol` [–] in (0, 1), absolute tolerance `atol` > 0, largest step
    /// `max_step` \[s] > 0 if any.
    ///
    /// # Errors
    /// A value out of its range, named by its field.
    pub fn new(rtol: f64, atol: f64, max_step: Option<f64>) -> Result<Self, ParameterError> {
        Ok(Self {
            rtol: require("rtol", rtol, Bound::OpenUnit, "")?,
            atol: require("atol", atol, Bound::Positive, "")?,
            max_step: max_step.map(|step| require("max_step", step, Bound::Positive, "s")).transpose()?,
        })
    }

    /// Relative tolerance [–] in (0, 1).
    pub fn rtol(&self) -> f64 {
        self.rtol
    }

    /// Absolute tolerance [SI unit of each component] > 0.
    pub fn atol(&self) -> f64 {
        self.atol
    }

    /// Largest step \[s] > 0, if any; the integrator step `dt / substeps` bounds it anyway, as
    /// every world step ends exactly on its boundary.
    pub fn max_step(&self) -> Option<f64> {
        self.max_step
    }
}

impl Default for Tolerances {
    fn default() -> Self {
        Self { rtol: 1e-6, atol: 1e-9, max_step: None }
    }
}

/// The time step settings of a world, built by [`Timing::new`], which checks them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Timing {
    dt: f64,
    integrator: Integrator,
    substeps: Substeps,
    tolerances: Tolerances,
}

impl Timing {
    /// World step `dt` \[s] > 0 taken by `integrator` in `substeps` (at least 1 when fixed), with
    /// `tolerances` for the adaptive scheme.
    ///
    /// # Errors
    /// A time step out of its range, or no substeps.
    pub fn new(
        dt: f64,
        integrator: Integrator,
        substeps: Substeps,
        tolerances: Tolerances,
    ) -> Result<Self, ParameterError> {
        let dt = require("dt", dt, Bound::Positive, "s")?;
        if let Substeps::Fixed(n @ 0) = substeps {
            return Err(ParameterError::TooFew { field: "substeps", value: n, least: 1 });
        }
        Ok(Self { dt, integrator, substeps, tolerances })
    }

    /// World step \[s] > 0.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    pub fn integrator(&self) -> Integrator {
        self.integrator
    }

    /// Integrator steps per world step as declared (`Fixed(n)` with `n ≥ 1`, or `Auto`).
    pub fn substeps(&self) -> Substeps {
        self.substeps
    }

    /// Integrator steps per world step before `Auto` is planned: `n` of `Fixed(n)`, else one
    /// (the world then plans `Auto` from the stable time steps at its current state).
    pub(crate) fn first_substeps(&self) -> u32 {
        match self.substeps {
            Substeps::Fixed(n) => n,
            Substeps::Auto => 1,
        }
    }

    /// Used by [`Integrator::Dopri45`] only.
    pub fn tolerances(&self) -> Tolerances {
        self.tolerances
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_constructors_refuse_each_bad_value_by_its_field() {
        let tolerances = Tolerances::default();
        let refused = |result: Result<Timing, ParameterError>| result.unwrap_err().to_string();
        assert_eq!(refused(Timing::new(0.0, Integrator::Rk4, Substeps::Auto, tolerances)), "dt must be > 0 s, got 0");
        assert_eq!(
            refused(Timing::new(1e-3, Integrator::Rk4, Substeps::Fixed(0), tolerances)),
            "substeps must be at least 1, got 0"
        );
        assert_eq!(Timing::new(1e-3, Integrator::Rk4, Substeps::Fixed(2), tolerances).unwrap().dt(), 1e-3);
        assert_eq!(Tolerances::new(0.0, 1e-9, None).unwrap_err().to_string(), "rtol must be > 0 and < 1, got 0");
        assert_eq!(Tolerances::new(1e-6, -1e-9, None).unwrap_err().field(), "atol");
        assert_eq!(Tolerances::new(1e-6, 1e-9, Some(0.0)).unwrap_err().to_string(), "max_step must be > 0 s, got 0");
    }
}
