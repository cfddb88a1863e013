//! Sweeps: one scene run thousands of times over a design of factor values, on every core or
//! as shards of a cluster's job array, each case measured and its row written to disk as it
//! finishes.
//!
//! The way through:
//! - [`spec`]: the spec file (RON): the base scene, the factors, the design, the metrics, read
//!   and placed by [`crate::spec_text`]; each factor's path to a value of the scene file is a
//!   [`crate::value_path::ValuePath`], read against the scene's serde data, so any section of a
//!   scene can be swept;
//! - [`factor`], [`design`]: the values each factor takes and the cases they make (full grid,
//!   one at a time, seeded Latin hypercube);
//! - [`plan`]: all of it checked against the base scene, every case's scene built by the scene
//!   loader before anything runs;
//! - [`metrics`], [`case`]: what each case measures and how one case runs;
//! - [`execute`]: a run into the output directory ([`store`]: manifest, run files, resume),
//!   on the engine of many cases shared with `tether study` ([`crate::runner`]), in
//!   [`shard`]s on a cluster, and the merge of the shards;
//! - [`rows`]: the rows gathered from the run files in case order; [`results`]: them written as
//!   [`table`] (CSV), [`parquet`], [`summary`] (Markdown) and [`plots`] (PNG);
//! - [`error`]: why a sweep cannot run or its results cannot be written.
//!
//! Re-running a spec gives the same rows bit for bit, serial or parallel, sharded or not: a
//! case's numbers depend on its values alone (the one exception is `cpu_s`, a measurement). On
//! a cluster of mixed processors, the physics' vector code is chosen per machine (AVX-512,
//! AVX2 or SSE2, with the same IEEE operations in each), so the rows agree there too.

pub mod case;
pub mod design;
pub mod error;
pub mod execute;
pub mod factor;
pub mod metrics;
pub mod parquet;
pub mod plan;
pub mod plots;
pub mod results;
pub mod rows;
pub mod shard;
pub mod spec;
pub mod store;
pub mod summary;
pub mod table;

pub use error::{Stage, SweepError};
pub use execute::{Options, Progress, Report, merge, run};
pub use plan::Plan;
