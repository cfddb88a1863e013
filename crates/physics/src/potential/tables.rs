//! The rules a panel code's tables obey and how a sea's heading is found in them (PHYSICS.md §9,
//! §10): frequencies strictly increasing and positive, headings strictly increasing, one value
//! per frequency and heading, every number finite — what [`super::Coefficients::new`] and
//! [`super::MeanDrift::new`] check, with the error that names the table.

use std::f64::consts::TAU;

/// Why a body's frequency-domain data were refused: each names the quantity as PHYSICS.md §9 does.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CoefficientsError {
    #[error("{what}: no finite frequency given")]
    NoFrequencies { what: &'static str },
    #[error("{what}: frequencies must increase strictly and be > 0 rad/s ({previous} then {value} at index {index})")]
    FrequencyOrder { what: &'static str, index: usize, previous: f64, value: f64 },
    #[error("{what} headings must increase strictly ({previous} then {value} rad at index {index})")]
    HeadingOrder { what: &'static str, index: usize, previous: f64, value: f64 },
    #[error("{what}: {count} values given for {expected} (one per frequency{per_heading})")]
    Count { what: &'static str, count: usize, expected: usize, per_heading: &'static str },
    #[error("{what} at index {index} is not finite")]
    NotFinite { what: &'static str, index: usize },
    #[error(
        "the ω = ∞ added mass is not the limit of the finite-ω added mass (A{dof}{dof}: {at_infinity:.6e} at \
         ω = ∞, {at_zero:.6e} at ω = 0, {highest:.6e} at the highest ω, {omega} rad/s): the ω = 0 and ω = ∞ \
         blocks look swapped, as Capytaine's WAMIT export before version 3.0 wrote them (Capytaine PR #855); \
         export again with Capytaine 3.0 or later"
    )]
    SwappedLimits { dof: usize, at_infinity: f64, at_zero: f64, highest: f64, omega: f64 },
}

/// Headings this close \[rad] to a file's heading are taken as it.
const SAME_HEADING: f64 = 1e-6;

/// A sea heading the body's file does not cover.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "the waves travel toward {heading:.3}° but the potential-flow file's {table} covers headings \
     {first:.3}° to {last:.3}° only: run the panel code for this heading"
)]
pub struct HeadingMissing {
    /// The file's table that lacks it (`excitation`, `mean drift`).
    pub table: &'static str,
    /// The sea's heading \[deg].
    pub heading: f64,
    /// The file's first and last headings \[deg].
    pub first: f64,
    pub last: f64,
}

/// Where a heading falls among a file's headings: the indices either side and the fraction of
/// the way from the lower to the upper (the same index twice on a file's heading).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HeadingBracket {
    pub lower: usize,
    pub upper: usize,
    pub fraction: f64,
}

/// The bracket of `heading` \[rad] (or of it a turn either way) among `headings` (strictly
/// increasing, not empty: [`super::Coefficients::new`] checks) of the file's `table`.
///
/// # Errors
/// A heading outside the file's, named with the table.
pub(crate) fn bracket_heading(
    headings: &[f64],
    heading: f64,
    table: &'static str,
) -> Result<HeadingBracket, HeadingMissing> {
    let (first, last) = (headings[0], headings[headings.len() - 1]);
    let inside = [heading, heading - TAU, heading + TAU]
        .into_iter()
        .find(|&b| b >= first - SAME_HEADING && b <= last + SAME_HEADING)
        .ok_or(HeadingMissing {
            table,
            heading: heading.to_degrees(),
            first: first.to_degrees(),
            last: last.to_degrees(),
        })?;
    let upper = headings.partition_point(|&b| b < inside).min(headings.len() - 1);
    if upper == 0 || (headings[upper] - inside).abs() <= SAME_HEADING {
        return Ok(HeadingBracket { lower: upper, upper, fraction: 0.0 });
    }
    let (b0, b1) = (headings[upper - 1], headings[upper]);
    Ok(HeadingBracket { lower: upper - 1, upper, fraction: ((inside - b0) / (b1 - b0)).clamp(0.0, 1.0) })
}

pub(crate) fn check_frequencies(what: &'static str, frequencies: &[f64]) -> Result<(), CoefficientsError> {
    if frequencies.is_empty() {
        return Err(CoefficientsError::NoFrequencies { what });
    }
    let mut previous = 0.0;
    for (index, &value) in frequencies.iter().enumerate() {
        if !(value.is_finite() && value > previous) {
            return Err(CoefficientsError::FrequencyOrder { what, index, previous, value });
        }
        previous = value;
    }
    Ok(())
}

pub(crate) fn check_count(
    what: &'static str,
    count: usize,
    expected: usize,
    per_heading: &'static str,
) -> Result<(), CoefficientsError> {
    if count == expected { Ok(()) } else { Err(CoefficientsError::Count { what, count, expected, per_heading }) }
}

pub(crate) fn check_finite(what: &'static str, finite: impl Iterator<Item = bool>) -> Result<(), CoefficientsError> {
    match finite.enumerate().find(|(_, ok)| !ok) {
        Some((index, _)) => Err(CoefficientsError::NotFinite { what, index }),
        None => Ok(()),
    }
}

/// At least one heading, every one finite, strictly increasing.
pub(crate) fn check_headings(what: &'static str, headings: &[f64]) -> Result<(), CoefficientsError> {
    if headings.is_empty() {
        return Err(CoefficientsError::Count { what, count: 0, expected: 1, per_heading: " heading" });
    }
    check_finite(what, headings.iter().map(|h| h.is_finite()))?;
    for (index, pair) in headings.windows(2).enumerate() {
        if !(pair[1] > pair[0]) {
            return Err(CoefficientsError::HeadingOrder { what, index: index + 1, previous: pair[0], value: pair[1] });
        }
    }
    Ok(())
}

/// Where a frequency falls among a table's: the points either side and the fraction of the way
/// from the lower to the upper; outside the table, its end point twice (the end value held).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct FrequencyBracket {
    pub lower: usize,
    pub upper: usize,
    pub fraction: f64,
}

/// The bracket of `omega` [rad/s] among `frequencies` (strictly increasing, not empty:
/// [`check_frequencies`]).
pub(crate) fn bracket_frequency(frequencies: &[f64], omega: f64) -> FrequencyBracket {
    let n = frequencies.len();
    let upper = frequencies.partition_point(|&w| w < omega);
    if upper == 0 || upper == n {
        let end = upper.min(n - 1);
        return FrequencyBracket { lower: end, upper: end, fraction: 0.0 };
    }
    let (w0, w1) = (frequencies[upper - 1], frequencies[upper]);
    FrequencyBracket { lower: upper - 1, upper, fraction: (omega - w0) / (w1 - w0) }
}
