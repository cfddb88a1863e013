//! The recording of each run: opened when a run starts (a scene loaded, a reset) with the
//! viewer's layout, fed a frame every so often of simulated time, sent to the viewer every
//! [`FLUSH_EVERY`] while it runs ([`Recording::flush`]: the frames since the last send go as one
//! chunk per entity; paused, at once), finished when the run ends. The sinks outlive the runs
//! ([`Sinks`]).
//!
//! While a fit is shown ([`Recording::show_fit`]), each recording of the scene lays out a plot
//! per measured column beside the others, with the record's samples and the model's latest
//! curve in it ([`tether_record::comparison`]).
//!
//! The 3D view's eye frames each run ([`tether_record::framing`]) or follows the body chosen
//! ([`Recording::follow`]), in this run and the next ones while the body is in the scene.

use super::protocol::Curve;
use crate::gui::stream::Sinks;
use rerun::RecordingStream;
use std::time::{Duration, Instant};
use tether_physics::world::World;
use tether_record::layout::Camera;
use tether_record::{FaceArrows, Recorder, comparison, layout, paths};

/// Frames logged per second of simulated time, as `tether record`'s default.
const LOG_HZ: f64 = 60.0;

/// At most this many frames per tick reach the viewer (faster runs log more sparsely).
const FRAMES_PER_TICK: f64 = 8.0;

/// Wall time between two sends to the viewer while the run goes: the viewer's data moves on ten
/// times a second (the SDK's own batcher sent every 200 ms). Every chunk the viewer ingests
/// invalidates its caches of that entity, so the number of chunks, not their size, is what it
/// pays for: a chunk per entity every 16 ms tick left the viewer falling behind the moored buoy
/// under the CPU renderer (its latency growing past 20 s), every 50 ms still by 6 s after 50 s;
/// every 100 ms it keeps in step, at ×1 as at full speed, and the simulation thread sends a sixth
/// as often.
const FLUSH_EVERY: Duration = Duration::from_millis(100);

/// The current run's recording.
pub(super) struct Recording {
    sinks: Sinks,
    /// `None` when no run is recorded (none yet, or it could not be opened).
    recorder: Option<Recorder>,
    /// Simulated time of the last frame [s].
    last_logged: f64,
    /// Simulated time between frames [s].
    period: f64,
    /// Whether the contacts' face forces are drawn (every contact, from now on).
    face_arrows: bool,
    /// When the buffered frames were last sent.
    last_flush: Instant,
    /// The fit shown, if any.
    fit: Option<FitPlots>,
    /// The current run's camera (`None` before the first run).
    camera: Option<Camera>,
    /// The body the eye follows, by name, if the user chose one.
    follow: Option<String>,
}

/// A fit's plots: the record of each measured column, the model's latest curve of each.
struct FitPlots {
    measured: Vec<Curve>,
    model: Vec<Curve>,
    /// Model curves drawn in the current recording (the next one's number).
    drawn: u32,
}

impl Recording {
    pub(super) fn new(sinks: Sinks) -> Self {
        Self {
            sinks,
            recorder: None,
            last_logged: f64::NEG_INFINITY,
            period: 1.0 / LOG_HZ,
            face_arrows: false,
            last_flush: Instant::now(),
            fit: None,
            camera: None,
            follow: None,
        }
    }

    /// Ends the current recording and starts one for the run `label` of `world`, with the
    /// viewer's layout and the first frame.
    pub(super) fn start(&mut self, label: &str, world: &World) -> Result<(), String> {
        self.finish()?;
        let stream = self.sinks.stream(label).map_err(|e| format!("recording: {e}"))?;
        let follow = self.follow.clone().filter(|name| world.bodies().iter().any(|body| &body.name == name));
        let camera = self.camera.insert(Camera { follow, ..Camera::framing(world) });
        match &mut self.fit {
            None => {
                layout::send_layout_with_fits(&stream, world, &[], camera).map_err(|e| format!("recording: {e}"))?
            }
            Some(fit) => {
                fit.drawn = 0;
                fit.draw(&stream, world, camera)?;
            }
        }
        self.recorder = Some(Recorder::new(stream, world, &self.arrows()).map_err(|e| format!("recording: {e}"))?);
        self.log(world)
    }

    /// Shows a fit from now on: a plot per measured column of `measured` with its samples, in
    /// this recording of `world` and the next ones, until [`Recording::drop_fit`].
    pub(super) fn show_fit(&mut self, world: &World, measured: Vec<Curve>) -> Result<(), String> {
        let fit = self.fit.insert(FitPlots { measured, model: Vec::new(), drawn: 0 });
        match (&self.recorder, &self.camera) {
            (Some(recorder), Some(camera)) => fit.draw(recorder.stream(), world, camera),
            _ => Ok(()),
        }
    }

    /// The eye follows body `body` (by name) from now on, or, with `None`, goes back to the
    /// run's framing: the layout of `world`'s run is sent again with it.
    pub(super) fn follow(&mut self, body: Option<String>, world: Option<&World>) -> Result<(), String> {
        self.follow = body;
        let (Some(recorder), Some(camera), Some(world)) = (&self.recorder, &mut self.camera, world) else {
            return Ok(());
        };
        camera.follow = self.follow.clone().filter(|name| world.bodies().iter().any(|b| &b.name == name));
        match &mut self.fit {
            None => layout::send_layout_with_fits(recorder.stream(), world, &[], camera)
                .map_err(|e| format!("recording: {e}")),
            Some(fit) => {
                let columns: Vec<&str> = fit.measured.iter().map(|c| c.column.as_str()).collect();
                layout::send_layout_with_fits(recorder.stream(), world, &columns, camera)
                    .map_err(|e| format!("recording the fit: {e}"))
            }
        }
    }

    /// The model's curves at the fit's latest values, in place of the last ones.
    pub(super) fn fit_model(&mut self, model: Vec<Curve>) -> Result<(), String> {
        let Some(fit) = &mut self.fit else { return Ok(()) };
        fit.model = model;
        match &self.recorder {
            Some(recorder) => fit.draw_model(recorder.stream()),
            None => Ok(()),
        }
    }

    /// No fit shown from the next recording on (a new scene).
    pub(super) fn drop_fit(&mut self) {
        self.fit = None;
    }

    /// Draws the contacts' face forces (`on`) or not, from the next frame on, in the run of
    /// `world` and the next ones.
    pub(super) fn set_face_arrows(&mut self, on: bool, world: Option<&World>) -> Result<(), String> {
        self.face_arrows = on;
        let arrows = self.arrows();
        match (&mut self.recorder, world) {
            (Some(recorder), Some(world)) => {
                recorder.set_face_arrows(world, &arrows).map_err(|e| format!("recording: {e}"))
            }
            _ => Ok(()),
        }
    }

    fn arrows(&self) -> FaceArrows {
        if self.face_arrows { FaceArrows::all() } else { FaceArrows::default() }
    }

    /// Follows an edit that changed what `world` records (a line's model switched): the
    /// recorder's tracks start again from it (a dynamic line's quasi-static series appear).
    pub(super) fn restart_tracks(&mut self, world: &World) -> Result<(), String> {
        match &mut self.recorder {
            Some(recorder) => recorder.restart_tracks(world).map_err(|e| format!("recording: {e}")),
            None => Ok(()),
        }
    }

    /// Buffers a frame of `world` now (sent at the next [`Recording::flush`]).
    pub(super) fn log(&mut self, world: &World) -> Result<(), String> {
        let Some(recorder) = &mut self.recorder else { return Ok(()) };
        self.last_logged = world.time();
        recorder.log_frame(world).map_err(|e| format!("recording: {e}"))
    }

    /// Buffers a frame of `world` if a frame period has passed since the last.
    pub(super) fn log_if_due(&mut self, world: &World) -> Result<(), String> {
        if world.time() - self.last_logged >= self.period { self.log(world) } else { Ok(()) }
    }

    /// Sends the buffered frames to the sinks (the viewer shows them): at once when the run is
    /// not `running` (a step, a pause), else once [`FLUSH_EVERY`] has passed since the last send.
    pub(super) fn flush(&mut self, running: bool) -> Result<(), String> {
        let every = if running { FLUSH_EVERY } else { Duration::ZERO };
        if self.last_flush.elapsed() < every {
            return Ok(());
        }
        self.last_flush = Instant::now();
        match &mut self.recorder {
            Some(recorder) => recorder.flush().map_err(|e| format!("recording: {e}")),
            None => Ok(()),
        }
    }

    /// Whether the embedded viewer is behind what it was sent (the run waits for it).
    pub(super) fn viewer_is_behind(&self) -> bool {
        self.sinks.viewer_is_behind()
    }

    /// Spreads the frames of a tick that advanced `advanced` [s] of simulated time: at most
    /// [`FRAMES_PER_TICK`], at most [`LOG_HZ`] per simulated second.
    pub(super) fn pace(&mut self, advanced: f64) {
        self.period = (advanced / FRAMES_PER_TICK).max(1.0 / LOG_HZ);
    }

    /// Flushes the current recording (the sinks stay open for the next run).
    pub(super) fn finish(&mut self) -> Result<(), String> {
        match self.recorder.take() {
            Some(recorder) => recorder.finish().map(|_| ()).map_err(|e| format!("recording: {e}")),
            None => Ok(()),
        }
    }
}

impl FitPlots {
    /// The layout with the fit's plots (the eye at `camera`), the record's samples and the
    /// model's latest curves, into `stream` (a recording of `world`).
    fn draw(&mut self, stream: &RecordingStream, world: &World, camera: &Camera) -> Result<(), String> {
        let fail = |e: &dyn std::fmt::Display| format!("recording the fit: {e}");
        let columns: Vec<&str> = self.measured.iter().map(|c| c.column.as_str()).collect();
        layout::send_layout_with_fits(stream, world, &columns, camera).map_err(|e| fail(&e))?;
        for curve in &self.measured {
            comparison::log_styles(stream, &curve.column).map_err(|e| fail(&e))?;
            comparison::send_series(stream, &curve.column, paths::FIT_RECORD, &curve.times, &curve.values)
                .map_err(|e| fail(&e))?;
        }
        self.draw_model(stream)
    }

    /// The model's latest curves into `stream`, hiding the ones drawn before.
    fn draw_model(&mut self, stream: &RecordingStream) -> Result<(), String> {
        if self.model.is_empty() {
            return Ok(());
        }
        for curve in &self.model {
            comparison::send_model_draft(stream, &curve.column, self.drawn, &curve.times, &curve.values)
                .map_err(|e| format!("recording the fit: {e}"))?;
        }
        self.drawn += 1;
        Ok(())
    }
}
