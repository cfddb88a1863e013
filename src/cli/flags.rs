//! A command-line number checked by the rule the physics checks a scene's values by
//! ([`tether_physics::parameter`]), so that a refused flag reads as a refused scene field does:
//! `--duration must be > 0 s, got -1`, `--segments must be at least 1, got 0`. Each command checks
//! its flags here, after clap has parsed them, before any work.

use tether_physics::parameter::{Bound, ParameterError, require};

/// `value` of flag `flag` if it is finite and > 0 (in `unit`).
///
/// # Errors
/// Otherwise, naming the flag, the rule, the unit and the value.
pub fn positive(flag: &'static str, value: f64, unit: &'static str) -> anyhow::Result<f64> {
    Ok(require(flag, value, Bound::Positive, unit)?)
}

/// `value` of flag `flag` if it is at least 1.
///
/// # Errors
/// Otherwise, naming the flag and the value.
pub fn at_least_one(flag: &'static str, value: u32) -> anyhow::Result<u32> {
    if value >= 1 { Ok(value) } else { Err(ParameterError::TooFew { field: flag, value, least: 1 }.into()) }
}
