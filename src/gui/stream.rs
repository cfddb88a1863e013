//! Where the live simulation's recordings go: the embedded viewer, an external viewer
//! (`--connect`) and an `.rrd` file (`--save`), all at once.
//!
//! Every run (a scene loaded, a reset) is a new Rerun recording, so the viewer shows it from its
//! start and keeps the earlier runs beside it. The sinks outlive the runs: each recording stream
//! gets a [`Forward`] sink onto the same shared ones, so one `.rrd` file holds every run of the
//! session and one connection serves them all. The file's footer is written when the last
//! [`Sinks`] handle is dropped, after the simulation thread has flushed and stopped.
//!
//! The embedded viewer takes in what it is sent for at most 10 ms of each frame it draws; on a
//! slow frame rate (the viewer rendering on a busy CPU) what a run sends piles up in the channel
//! to it (up to 128 MB) and what the viewer shows falls behind what runs. The window counts what
//! is left in the channel after each frame ([`ViewerBacklog`]); the simulation holds its steps
//! while that is more than [`ViewerBacklog::LIMIT`] messages, so the run goes as fast as the
//! viewer can show it and the memory stays bounded (docs/window.md, "Memory").

use rerun::RecordingStream;
use rerun::log::LogMsg;
use rerun::sink::{LogSink, MultiSink, SinkFlushError};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;
use tether_record::APPLICATION_ID;

/// The shared sinks of a session (none: recordings are not kept, as in tests).
#[derive(Clone)]
pub struct Sinks {
    shared: Option<Arc<MultiSink>>,
    /// What the embedded viewer has not taken in yet, when there is one.
    backlog: ViewerBacklog,
}

/// The messages waiting in the channel to the embedded viewer after its last frame: set by the
/// window each frame, read by the simulation before each step (none counted without an
/// embedded viewer).
#[derive(Clone, Default)]
pub struct ViewerBacklog(Arc<AtomicUsize>);

impl ViewerBacklog {
    /// Messages left over after a frame past which the viewer is behind. A run sends one
    /// message per entity ten times a second: this is a few seconds of a scene with tens of
    /// entities, so a viewer that keeps up never reaches it.
    pub const LIMIT: usize = 256;

    /// The viewer left `messages` in its channel after this frame.
    pub fn set(&self, messages: usize) {
        self.0.store(messages, Ordering::Relaxed);
    }

    /// Whether the viewer is behind what was sent to it.
    pub fn is_behind(&self) -> bool {
        self.0.load(Ordering::Relaxed) > Self::LIMIT
    }
}

/// A sink that could not be opened.
#[derive(Debug, thiserror::Error)]
pub enum SinkError {
    #[error("cannot write the recording {path}: {source}")]
    File { path: String, source: rerun::sink::FileSinkError },
    #[error("not a Rerun viewer address {url:?} (e.g. rerun+http://127.0.0.1:9876/proxy): {source}")]
    Url { url: String, source: rerun::external::re_uri::Error },
}

impl Sinks {
    /// No sinks: recordings go nowhere.
    pub fn none() -> Self {
        Self { shared: None, backlog: ViewerBacklog::default() }
    }

    /// These sinks, shared by every run.
    pub fn new(sinks: Vec<Box<dyn LogSink>>) -> Self {
        Self::with_viewer(sinks, ViewerBacklog::default())
    }

    /// These sinks, one of them an embedded viewer whose channel's `backlog` the window counts.
    pub fn with_viewer(sinks: Vec<Box<dyn LogSink>>, backlog: ViewerBacklog) -> Self {
        Self { shared: (!sinks.is_empty()).then(|| Arc::new(MultiSink::new(sinks))), backlog }
    }

    /// Whether the embedded viewer is behind what was sent to it ([`ViewerBacklog`]).
    pub fn viewer_is_behind(&self) -> bool {
        self.backlog.is_behind()
    }

    /// An `.rrd` file sink at `path` (created now, so a bad path fails before any run).
    pub fn file(path: &std::path::Path) -> Result<Box<dyn LogSink>, SinkError> {
        let sink = rerun::sink::FileSink::new(path)
            .map_err(|source| SinkError::File { path: path.display().to_string(), source })?;
        Ok(Box::new(sink))
    }

    /// A sink streaming to the external viewer at `url` (`rerun+http://host:port/proxy`).
    pub fn connect(url: &str) -> Result<Box<dyn LogSink>, SinkError> {
        let uri = url.parse().map_err(|source| SinkError::Url { url: url.to_string(), source })?;
        Ok(Box::new(rerun::sink::GrpcSink::new(uri)))
    }

    /// A new recording stream for one run, writing to the shared sinks (a disabled stream,
    /// which costs nothing, when there are none).
    pub fn stream(&self, run_name: &str) -> rerun::RecordingStreamResult<RecordingStream> {
        match &self.shared {
            None => Ok(RecordingStream::disabled()),
            Some(shared) => {
                let forward: Box<dyn LogSink> = Box::new(Forward(Arc::clone(shared)));
                rerun::RecordingStreamBuilder::new(APPLICATION_ID).recording_name(run_name).set_sinks(vec![forward])
            }
        }
    }
}

/// Forwards one recording stream's messages to the shared sinks; dropping it (the stream ended)
/// leaves them open for the next run.
struct Forward(Arc<MultiSink>);

impl LogSink for Forward {
    fn send(&self, msg: LogMsg) {
        self.0.send(msg);
    }

    fn send_all(&self, messages: Vec<LogMsg>) {
        self.0.send_all(messages);
    }

    fn flush_blocking(&self, timeout: Duration) -> Result<(), SinkFlushError> {
        self.0.flush_blocking(timeout)
    }
}
