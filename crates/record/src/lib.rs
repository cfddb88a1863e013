//! Tether's Rerun adapter: reads a [`World`] and logs it. Nothing in the physics crate knows
//! about it. The entity paths are in [`paths`]; the viewer's layout of a run in [`layout`]; each
//! kind of entity in its own module of `tracks`.
//!
//! Recording layout (timelines `sim_time` \[s] and `step`; view coordinates z-up):
//! - `world/bodies/<name>`: temporal `Transform3D` (G and the principal axes);
//!   `…/shape`: static display shape, with a static transform from the principal frame to the
//!   shape; `…/nodes`: static slave nodes (principal frame);
//! - `world/couplings/<name>`: `LineStrips3D` between the ends, each frame; a catenary is drawn
//!   along its solved shape in 32 segments, 8 bands coloured by tension (blue: the lowest
//!   tension along the line, red: the highest);
//! - `world/boundaries/<contact>`: static, a contact's planes as patches; `world/anchors`:
//!   static, every coupling end fixed in the world, as points;
//! - `plots/energy/stored`: series gravity, elastic, total and balance \[J];
//!   `plots/energy/moving`: kinetic, dissipated and external_work \[J];
//! - `plots/tension`: one series per coupling, named after it \[N], in one plot (a catenary's
//!   series is its larger end tension, a contact's its normal force);
//! - `plots/catenary`: every catenary's end tensions, series `<name> end1` and `<name> end2` \[N];
//!   a dynamic line's quasi-static ones in `plots/catenary/quasi-static/<name>`;
//! - `plots/contact`: every contact's total normal force `Σ|f_n|` and friction `|Σ f_t|`, series
//!   `<name> normal` and `<name> friction` \[N];
//! - `world/contacts/<name>`: a contact's face forces as arrows from the face centroids, for the
//!   contacts and times asked for ([`FaceArrows`]; none by default);
//! - the water, when the scene has some: `world/water/…` and `plots/water/<body>/…` (the
//!   `tracks::water` module);
//! - the seabed, when the scene has one: `world/seabed/…` (each line's grounded part and
//!   touchdowns) and `plots/seabed` (every line's grounded length) (the `tracks::seabed` module).
//!
//! How it keeps up with the physics: a [`Recorder`] buffers each frame's values in plain
//! vectors and sends them as Arrow columns built straight from those vectors, one chunk per
//! entity for many frames, instead of one `log` call per entity per frame; time series share one
//! entity per plot; what does not change (shapes, series names, colours, widths) is logged once,
//! statically, a body's shape and placement in one chunk; the contact forces are those the step
//! summed. A file recorder sends every [`FRAMES_PER_CHUNK`] frames (or [`BYTES_PER_CHUNK`]
//! bytes), a live one whenever its caller flushes (the GUI: every 100 ms).
//!
//! What Rerun's file writer costs (callgrind, `tether record`): about 2 ms of CPU to open and
//! close a recording (its footer, the manifest of every chunk, is half of it), about 0.8 M
//! instructions a chunk whatever its size, and about 30 a byte of Arrow data (LZ4 compression 27
//! of them). Hence few chunks, few bytes; see the README's "Recording speed".

pub mod comparison;
pub mod framing;
pub mod layout;
pub mod paths;

mod columns;
mod frames;
mod rerun;
mod stats;
mod tracks;

pub use frames::{FrameSchedule, SIM_TIME, STEP};
pub use stats::{KindStats, ROW_INDEX_BYTES, RecordStats};
pub use tracks::face_arrows::{ArrowedContacts, FaceArrows};

use frames::Frames;
use rerun::RecordingStream;
use std::path::Path;
use tether_physics::math::Vec3;
use tether_physics::world::World;
use tracks::{Settings, Track};

/// The Rerun application id of Tether recordings.
pub const APPLICATION_ID: &str = "tether";

/// A file recorder sends its buffered frames when it holds this many: chunks of up to 4096 rows
/// per entity, the most Rerun's store compacts into one, 68 s of simulation at 60 frames per
/// second. Each chunk costs the file writer an Arrow schema and a footer entry whatever its
/// size (about 0.8 M instructions), so fewer, fuller chunks are cheaper.
pub const FRAMES_PER_CHUNK: usize = 4096;

/// …or when its frames hold this many bytes, which bounds its memory for large scenes (chain100
/// buffers 13 kB a frame, the moored buoy 6 kB: both send 4096 frames at a time).
pub const BYTES_PER_CHUNK: usize = 64 << 20;

/// Why a recording could not be written.
#[derive(Debug, thiserror::Error)]
pub enum RecordError {
    #[error(transparent)]
    Stream(#[from] rerun::RecordingStreamError),
    #[error("cannot build a chunk of frames: {0}")]
    Chunk(#[from] rerun::log::ChunkError),
    #[error("cannot finish the recording: {0}")]
    Flush(#[from] rerun::sink::SinkFlushError),
    #[error("no contact named \"{name}\" to draw face arrows for (contacts: {known})")]
    UnknownContact { name: String, known: String },
}

/// Logs a world, frame after frame, to a recording stream.
pub struct Recorder {
    stream: RecordingStream,
    frames: Frames,
    tracks: Vec<(Box<dyn Track>, KindStats)>,
    settings: Settings,
    /// Bytes of the buffered frames.
    buffered: usize,
    stats: RecordStats,
}

impl Recorder {
    /// A recorder writing to the `.rrd` file `path`; the file is created now, so an unwritable
    /// path fails before any simulation (and face arrows asked for an unknown contact before
    /// the file is created).
    pub fn to_file(path: &Path, world: &World, face_arrows: &FaceArrows) -> Result<Self, RecordError> {
        let recorder = Self::to_file_unframed(path, world, face_arrows)?;
        recorder.frame_planes(world)?;
        Ok(recorder)
    }

    /// As [`Self::to_file`], but the contacts' planes, whose patches cover what moves over the
    /// run's first seconds, are left for [`Self::log_planes`] to draw once the caller's own run
    /// has swept that ([`framing::MotionSweep`]), rather than drawn now from a copy's run.
    pub fn to_file_unframed(path: &Path, world: &World, face_arrows: &FaceArrows) -> Result<Self, RecordError> {
        face_arrows.check(world)?;
        let stream = rerun::RecordingStreamBuilder::new(APPLICATION_ID).save(path)?;
        Self::unframed(stream, world, face_arrows)
    }

    /// A recorder writing to the `.rrd` file `path` under application id `application` and
    /// recording id `recording` (a sweep's: one application, one recording per case, so that
    /// several cases open side by side in the viewer), without face arrows; the file is created
    /// now.
    pub fn to_file_as(path: &Path, world: &World, application: &str, recording: &str) -> Result<Self, RecordError> {
        let application = rerun::ApplicationId::new_or_unknown(application);
        let stream = rerun::RecordingStreamBuilder::new(application).recording_id(recording).save(path)?;
        Self::new(stream, world, &FaceArrows::default())
    }

    /// A recorder on an existing stream, drawing the face arrows `face_arrows`; logs the static
    /// scene (view coordinates, shapes, nodes, series names) and sends it now.
    ///
    /// # Errors
    /// A stream that fails, or face arrows asked for a contact the world does not have.
    pub fn new(stream: RecordingStream, world: &World, face_arrows: &FaceArrows) -> Result<Self, RecordError> {
        let recorder = Self::unframed(stream, world, face_arrows)?;
        recorder.frame_planes(world)?;
        Ok(recorder)
    }

    /// A recorder on `stream` that has logged the static scene but the contacts' planes.
    fn unframed(stream: RecordingStream, world: &World, face_arrows: &FaceArrows) -> Result<Self, RecordError> {
        let settings = Settings { face_arrows: face_arrows.resolve(world)? };
        stream.log_static(paths::WORLD, &rerun::ViewCoordinates::RIGHT_HAND_Z_UP())?;
        let tracks = tracks::for_world(world);
        for (track, _) in &tracks {
            track.log_static(&stream, world)?;
        }
        // The static rows are all the batcher ever holds (frames go as columns): out they go.
        stream.flush_async()?;
        Ok(Self { stream, frames: Frames::default(), tracks, settings, buffered: 0, stats: RecordStats::default() })
    }

    /// Draws the contacts' planes around what a copy of `world` sweeps (no run when it has none).
    fn frame_planes(&self, world: &World) -> Result<(), RecordError> {
        if tracks::boundaries::has_planes(world) {
            self.log_planes(world, &framing::swept_box(world))?;
        }
        Ok(())
    }

    /// Logs, statically, the contacts' planes of `world` as patches covering `swept`, the box of
    /// what moves over the run's first seconds ([`framing::MotionSweep`]), and sends them now.
    ///
    /// # Errors
    /// A stream that fails.
    pub fn log_planes(&self, world: &World, swept: &(Vec3, Vec3)) -> Result<(), RecordError> {
        tracks::boundaries::log_planes(&self.stream, world, swept)?;
        self.stream.flush_async()?;
        Ok(())
    }

    /// The stream it logs to (to log beside the frames: a fit's measured series).
    pub fn stream(&self) -> &RecordingStream {
        &self.stream
    }

    /// Changes which face arrows are drawn from the next frame on.
    ///
    /// # Errors
    /// A contact the world does not have (the arrows drawn are then left as they were).
    pub fn set_face_arrows(&mut self, world: &World, face_arrows: &FaceArrows) -> Result<(), RecordError> {
        self.settings.face_arrows = face_arrows.resolve(world)?;
        Ok(())
    }

    /// Follows a live edit that changed what `world` records (a line switched to dynamic or
    /// back: its plot gains or loses its quasi-static series): the buffered frames go out as
    /// they were, then every track starts again from `world` and logs its static part anew
    /// (what was sent so far is still counted).
    ///
    /// # Errors
    /// A stream that fails.
    pub fn restart_tracks(&mut self, world: &World) -> Result<(), RecordError> {
        self.flush()?;
        let mut tracks = tracks::for_world(world);
        for (track, stats) in &mut tracks {
            if let Some((_, sent)) = self.tracks.iter().find(|(_, sent)| sent.kind == stats.kind) {
                *stats = KindStats { entities: stats.entities, ..sent.clone() };
            }
            track.log_static(&self.stream, world)?;
        }
        self.tracks = tracks;
        self.stream.flush_async()?;
        self.frame_planes(world)
    }

    /// Buffers the world's current state as a frame at its `sim_time` and `step`; sends the
    /// buffered frames when there are [`FRAMES_PER_CHUNK`] of them or [`BYTES_PER_CHUNK`].
    pub fn log_frame(&mut self, world: &World) -> Result<(), RecordError> {
        let frame = self.frames.push(world);
        for (track, _) in &mut self.tracks {
            self.buffered += track.capture(world, frame, &self.settings);
        }
        self.stats.frames += 1;
        if self.frames.len() >= FRAMES_PER_CHUNK || self.buffered >= BYTES_PER_CHUNK {
            self.flush()?;
        }
        Ok(())
    }

    /// Sends the buffered frames now, one chunk per entity (a live viewer gets them at once).
    pub fn flush(&mut self) -> Result<(), RecordError> {
        if self.frames.is_empty() {
            return Ok(());
        }
        for (track, sent) in &mut self.tracks {
            track.send(&self.stream, &self.frames, sent)?;
        }
        self.frames.clear();
        self.buffered = 0;
        Ok(())
    }

    /// What has been sent so far.
    pub fn stats(&self) -> RecordStats {
        RecordStats { kinds: self.tracks.iter().map(|(_, sent)| sent.clone()).collect(), ..self.stats.clone() }
    }

    /// Sends the buffered frames, flushes everything to the sink and closes the stream (writes
    /// the `.rrd` footer); returns what was sent.
    pub fn finish(mut self) -> Result<RecordStats, RecordError> {
        self.flush()?;
        self.stream.flush_blocking()?;
        Ok(self.stats())
    }
}
