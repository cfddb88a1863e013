//! `tether storm`: the design answer of a moored system (PHYSICS.md §10, docs/design-loads.md) —
//! how hard each line pulls and how far each body goes in a storm, as codes of practice
//! (API RP 2SK, DNV-OS-E301) ask for it: the storm run for several seeds (independent
//! realisations of its random sea and gusts), the largest value of each seed fitted with a
//! Gumbel distribution, its most probable maximum (MPM) and 90 % quantile, and each line's
//! safety against its minimum breaking load.
//!
//! The way through:
//! - [`spec`]: the storm as a sweep over seeds (every seed path the scene has, the same seed in
//!   each), measured after a warm-up, run by the sweep's engine on every core or as the shards
//!   of a cluster's job array;
//! - [`extremes`]: the Gumbel fits (moments, maximum likelihood) and the Gaussian check;
//! - [`statistics`]: per line and per body, the seeds' maxima, both fits, the design numbers
//!   and the code's check;
//! - [`report`]: them as a Markdown table, CSV, Parquet and a chart.

pub mod extremes;
pub mod report;
pub mod spec;
pub mod statistics;

/// Why a storm cannot be run or reported.
#[derive(Debug, thiserror::Error)]
pub enum StormError {
    #[error("{0}")]
    Scene(String),
    #[error(transparent)]
    Sweep(#[from] crate::sweep::SweepError),
    #[error("{quantity}: {source}")]
    Fit { quantity: String, source: extremes::ExtremesError },
    #[error("{path}: {message}")]
    Output { path: String, message: String },
}
