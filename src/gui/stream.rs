//! Where the live simulation's recordings go: the embedded viewer, an external viewer
//! (`--connect`) and an `.rrd` file (`--save`), all at once.
//!
//! Every run (a scene loaded, a reset) is a new Rerun recording, so the viewer shows it from its
//! start and keeps the earlier runs beside it. The sinks outlive the runs: each recording stream
//! gets a [`Forward`] sink onto the same shared ones, so one `.rrd` file holds every run of the
//! session and one connection serves them all. The file's footer is written when the last
//! [`Sinks`] handle is dropped, after the simulation thread has flushed and stopped.

use crate::physics::coupling::CouplingKind;
use crate::physics::world::World;
use crate::record::APPLICATION_ID;
use rerun::RecordingStream;
use rerun::blueprint::{Blueprint, BlueprintActivation, BlueprintPanel, ContainerLike, Horizontal, SelectionPanel, Spatial3DView, TimePanel, TimeSeriesView, Vertical};
use rerun::blueprint::components::PanelState;
use rerun::log::LogMsg;
use rerun::sink::{LogSink, MultiSink, SinkFlushError};
use std::sync::Arc;
use std::time::Duration;

/// The shared sinks of a session (none: recordings are not kept, as in tests).
#[derive(Clone)]
pub struct Sinks {
    shared: Option<Arc<MultiSink>>,
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
        Self { shared: None }
    }

    /// These sinks, shared by every run.
    pub fn new(sinks: Vec<Box<dyn LogSink>>) -> Self {
        Self { shared: (!sinks.is_empty()).then(|| Arc::new(MultiSink::new(sinks))) }
    }

    /// An `.rrd` file sink at `path` (created now, so a bad path fails before any run).
    pub fn file(path: &std::path::Path) -> Result<Box<dyn LogSink>, SinkError> {
        let sink = rerun::sink::FileSink::new(path).map_err(|source| SinkError::File { path: path.display().to_string(), source })?;
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

/// How the viewer lays out a run of `world`: the 3D scene large on the left, the energy and
/// tension plots stacked on the right (with the catenaries' end tensions when there are any);
/// the `sim_time` timeline; the viewer's own side panels folded, room being short beside the
/// control panel.
pub fn layout(world: &World) -> Blueprint {
    let mut plots: Vec<ContainerLike> = vec![TimeSeriesView::new("energy [J]").with_origin("plots/energy").into()];
    if !world.couplings.is_empty() {
        plots.push(TimeSeriesView::new("tension [N]").with_origin("plots/tension").into());
    }
    if world.couplings.iter().any(|c| matches!(c.kind, CouplingKind::Catenary(_))) {
        plots.push(TimeSeriesView::new("catenary end tensions [N]").with_origin("plots/catenary").into());
    }
    let scene: ContainerLike = Spatial3DView::new("scene").with_origin("world").into();
    Blueprint::new(Horizontal::new([scene, Vertical::new(plots).into()]).with_column_shares([3.0, 2.0]))
        .with_blueprint_panel(BlueprintPanel::from_state(PanelState::Collapsed))
        .with_selection_panel(SelectionPanel::from_state(PanelState::Collapsed))
        .with_time_panel(TimePanel::new().with_timeline("sim_time"))
}

/// Sends `world`'s [`layout`] to the viewer behind `stream` (nothing for a disabled stream).
pub fn send_layout(stream: &RecordingStream, world: &World) -> rerun::RecordingStreamResult<()> {
    if !stream.is_enabled() {
        return Ok(());
    }
    layout(world).send(stream, BlueprintActivation { make_active: true, make_default: true })
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
