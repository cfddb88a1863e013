//! A parameter's range: the rule a number a physics type is built from must obey, checked once,
//! in that type's constructor ([`crate::coupling::Catenary::new`], [`crate::seabed::Seabed::new`],
//! [`crate::integrator::Timing::new`], …), and the typed error that names the field (as scene
//! files spell it), the rule, the unit and the value refused. Every path that sets a value (a
//! scene file, a knob in the window, a sweep case, a command-line flag) goes through the
//! constructor and so reads the same message.

use crate::table::TableError;

/// The range a number must lie in. No range holds NaN or an infinity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// `> 0`.
    Positive,
    /// `≥ 0`.
    NonNegative,
    /// `> 0 and < 1`.
    OpenUnit,
    /// `≥ 0 and ≤ 1`.
    UnitInterval,
    /// Any finite number.
    Finite,
}

impl Bound {
    /// Whether `value` lies in the range.
    pub fn holds(self, value: f64) -> bool {
        value.is_finite()
            && match self {
                Self::Positive => value > 0.0,
                Self::NonNegative => value >= 0.0,
                Self::OpenUnit => value > 0.0 && value < 1.0,
                Self::UnitInterval => (0.0..=1.0).contains(&value),
                Self::Finite => true,
            }
    }

    /// The rule as a message writes it.
    fn rule(self) -> &'static str {
        match self {
            Self::Positive => "> 0",
            Self::NonNegative => "≥ 0",
            Self::OpenUnit => "> 0 and < 1",
            Self::UnitInterval => "≥ 0 and ≤ 1",
            Self::Finite => "finite",
        }
    }
}

impl std::fmt::Display for Bound {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.rule())
    }
}

/// A parameter refused by the constructor of the type it belongs to.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ParameterError {
    /// A number outside its range: "stiffness must be > 0 N/m, got -1", "level must be finite,
    /// got NaN".
    #[error("{field} must be {}, got {value}", range(*bound, unit))]
    OutOfRange { field: &'static str, value: f64, bound: Bound, unit: &'static str },
    /// A count below its least value.
    #[error("{field} must be at least {least}, got {value}")]
    TooFew { field: &'static str, value: u32, least: u32 },
    /// A count above its greatest value.
    #[error("{field} must be at most {most}, got {value}")]
    TooMany { field: &'static str, value: u32, most: u32 },
    /// A list of points that is not a table.
    #[error("{field}: {source}")]
    Table { field: &'static str, source: TableError },
}

impl ParameterError {
    /// The field at fault, as scene files spell it.
    pub fn field(&self) -> &'static str {
        match self {
            Self::OutOfRange { field, .. }
            | Self::TooFew { field, .. }
            | Self::TooMany { field, .. }
            | Self::Table { field, .. } => field,
        }
    }
}

/// `value` if it lies within `bound`; else the error naming `field` and its `unit` (empty for a
/// number without one).
///
/// # Errors
/// [`ParameterError::OutOfRange`].
pub fn require(field: &'static str, value: f64, bound: Bound, unit: &'static str) -> Result<f64, ParameterError> {
    if bound.holds(value) { Ok(value) } else { Err(ParameterError::OutOfRange { field, value, bound, unit }) }
}

/// The range as a message writes it: `> 0 N/m`, `≥ 0` for a number without a unit, `finite`.
fn range(bound: Bound, unit: &str) -> String {
    if unit.is_empty() || bound == Bound::Finite { bound.to_string() } else { format!("{bound} {unit}") }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_bound_refuses_what_it_says_and_nan() {
        assert_eq!(require("length", 2.5, Bound::Positive, "m"), Ok(2.5));
        assert_eq!(require("damping", 0.0, Bound::NonNegative, "N·s/m"), Ok(0.0));
        let refused = require("stiffness", -1.0, Bound::Positive, "N/m").unwrap_err();
        assert_eq!(refused.to_string(), "stiffness must be > 0 N/m, got -1");
        assert_eq!(refused.field(), "stiffness");
        assert_eq!(
            require("friction", -0.5, Bound::NonNegative, "").unwrap_err().to_string(),
            "friction must be ≥ 0, got -0.5"
        );
        assert_eq!(
            require("rtol", 1.0, Bound::OpenUnit, "").unwrap_err().to_string(),
            "rtol must be > 0 and < 1, got 1"
        );
        let not_finite = require("level", f64::NAN, Bound::Finite, "m").unwrap_err();
        assert_eq!(not_finite.to_string(), "level must be finite, got NaN");
        for bound in [Bound::Positive, Bound::NonNegative, Bound::OpenUnit, Bound::UnitInterval, Bound::Finite] {
            assert!(!bound.holds(f64::NAN) && !bound.holds(f64::INFINITY), "{bound}");
        }
        assert!(Bound::Finite.holds(-3.0) && !Bound::Positive.holds(0.0) && Bound::NonNegative.holds(0.0));
    }
}
