//! The Rerun SDK under the `rerun` crate's own paths (`rerun::RecordingStream`,
//! `rerun::LineStrips3D`, `rerun::blueprint::…`), so that this crate reads as Rerun's
//! documentation does, built from the SDK's two crates alone: `re_sdk` (the recording stream,
//! its sinks, blueprints, chunks) and `re_sdk_types` (archetypes, components, datatypes).
//!
//! Why not the `rerun` crate itself: besides the SDK it always builds the chunk store, the
//! entity database, the query cache and the Rerun Cloud client (OpenTelemetry, OAuth, TLS with
//! `ring`), none of which writing a recording uses. Without them the headless build
//! (`--no-default-features`) compiles 47 crates fewer (docs/commands.md gives the cold-build
//! figures). The window, which embeds the viewer, depends on `rerun`; its types are these same
//! ones, re-exported.

pub use re_sdk::*;
pub use re_sdk_types::archetypes::*;
pub use re_sdk_types::components::{Color, Radius};
pub use re_sdk_types::datatypes::Quaternion;
pub use re_sdk_types::{components, datatypes};
