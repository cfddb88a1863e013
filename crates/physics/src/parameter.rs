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
    /// A value derived from checked ones outside its range, with the input that made it
    /// ([`require_derived`]): "EA = stiffness × length must be finite, got inf (from stiffness =
    /// 1e306)", "a node's mass λ0 L/N must be > 0 kg, got 0 (from mass_per_length = 0)".
    #[error("{quantity} must be {}, got {} (from {field} = {})", range(*bound, unit), number(*value), number(*input))]
    Derived { quantity: &'static str, value: f64, bound: Bound, unit: &'static str, field: &'static str, input: f64 },
}

impl ParameterError {
    /// The field at fault, as scene files spell it.
    pub fn field(&self) -> &'static str {
        match self {
            Self::OutOfRange { field, .. }
            | Self::TooFew { field, .. }
            | Self::TooMany { field, .. }
            | Self::Table { field, .. }
            | Self::Derived { field, .. } => field,
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

/// `value`, derived from `inputs` (each a field as scene files spell it, and its checked value),
/// if it lies within `bound`; else the error naming `quantity`, the rule it breaks (`finite` for an
/// overflow, else `bound`), its `unit` and the input that made it: the one farthest from 1 in
/// orders of magnitude, `|log₁₀ |x||`, which is the one a mistyped exponent makes (`1e308` for
/// `1e3`). A zero input is the farthest when the value is zero too, and the nearest when it
/// overflows (a product does not overflow by a factor 0).
///
/// # Errors
/// [`ParameterError::Derived`].
pub fn require_derived(
    quantity: &'static str,
    value: f64,
    bound: Bound,
    unit: &'static str,
    inputs: &[(&'static str, f64)],
) -> Result<f64, ParameterError> {
    if bound.holds(value) {
        return Ok(value);
    }
    let zero = if value.is_finite() { f64::INFINITY } else { f64::NEG_INFINITY };
    let orders = |x: f64| if x == 0.0 { zero } else { x.abs().log10().abs() };
    let (field, input) =
        inputs.iter().copied().max_by(|a, b| orders(a.1).total_cmp(&orders(b.1))).unwrap_or((quantity, value));
    let bound = if value.is_finite() { bound } else { Bound::Finite };
    Err(ParameterError::Derived { quantity, value, bound, unit, field, input })
}

/// `x` as a message writes it: as Rust prints it between 10⁻⁴ and 10¹⁶ in magnitude (and 0),
/// else in exponent form (`1e308`, not its 309 digits).
fn number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e16).contains(&x.abs()) { x.to_string() } else { format!("{x:e}") }
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

    #[test]
    fn a_derived_value_names_the_input_farthest_from_one() {
        let inputs = [("stiffness", 1e306), ("length", 1000.0)];
        assert_eq!(require_derived("EA = stiffness × length", 1e308, Bound::Positive, "N", &inputs), Ok(1e308));
        let refused = require_derived("EA = stiffness × length", f64::INFINITY, Bound::Positive, "N", &inputs);
        let refused = refused.unwrap_err();
        assert_eq!(refused.to_string(), "EA = stiffness × length must be finite, got inf (from stiffness = 1e306)");
        assert_eq!(refused.field(), "stiffness");
        let tiny = [("mass_per_length", 1e-308), ("stiffness", 4e8), ("length", 900.0)];
        let refused = require_derived("the axial stable step", 0.0, Bound::Positive, "s", &tiny).unwrap_err();
        assert_eq!(refused.to_string(), "the axial stable step must be > 0 s, got 0 (from mass_per_length = 1e-308)");
        let zero = [("mass_per_length", 0.0), ("length", 1e-300)];
        assert_eq!(
            require_derived("a node's mass", 0.0, Bound::Positive, "kg", &zero).unwrap_err().field(),
            "mass_per_length"
        );
        let heavy = [("mass_per_length", 1e308), ("displaced_area", 0.0), ("gravity", 9.81)];
        let refused = require_derived("w", f64::INFINITY, Bound::Finite, "N/m", &heavy).unwrap_err();
        assert_eq!(refused.field(), "mass_per_length");
    }
}
