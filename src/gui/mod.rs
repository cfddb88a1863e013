//! The GUI: one eframe window with the control panel on the left and the Rerun viewer embedded
//! beside it, fed in-process by the simulation thread. An adapter, like the recorder crate: it
//! sends the simulation commands and reads its reports; physics and scene know nothing of it.
//!
//! - [`app`]: the eframe application (window, embedded viewer, dropped files);
//! - [`panel`]: the control panel, which the tests drive headlessly: it lays out the sub-panels,
//!   holds the simulation handle and the [`open_scene`] (the scene being tuned, no egui in it;
//!   its [`knobs`]: each tunable group's drafts and refusals, checked by the scene builder), and
//!   applies what its sub-panels ask for:
//!   - [`scenes`]: scene list, file dialogs, load errors;
//!   - [`run_controls`]: play/pause/step/reset, speed, integrator, dt, substeps;
//!   - [`follow`]: the viewer's eye framing the run or following a body;
//!   - [`tuning`]: every parameter of every coupling, with units, each in a [`number_field`];
//!     revert, save as;
//!   - [`indicators`]: energy balance, stable time steps, the selected body;
//!   - [`contact_estimator`]: k1, k2, τ from an impact, where the scene has contact;
//!   - [`water`]: waves, current, density, each floating body's coefficients, live;
//!   - [`statics`]: the seabed's line friction, live; the equilibrium button; a body's offset
//!     curve;
//!   - [`fit`]: a measured record's columns mapped to model signals, knobs ticked with their
//!     bounds, `tether fit` run in the background, the knobs and the viewer's curves following
//!     each iteration, the intervals at the end;
//!   - [`sweep_table`]: a sweep directory's cases, sortable, a case loaded in one click (drawn
//!     below the viewer when a sweep is open);
//! - [`simulation`]: the thread that owns the world;
//! - [`stream`]: where recordings go (embedded viewer, `--connect`, `--save`);
//! - [`renderer`]: a software rasterizer noted once and its frame rate capped, the viewer's
//!   memory limit;
//! - [`watch`], [`dialogs`]: the open file watched on disk, file dialogs off the GUI thread.

pub mod air;
pub mod app;
pub mod contact_estimator;
pub mod dialogs;
pub mod fit;
pub mod follow;
pub mod indicators;
pub mod knobs;
pub mod line_plot;
pub mod number_field;
pub mod open_scene;
pub mod panel;
pub mod renderer;
pub mod run_controls;
pub mod scenes;
pub mod simulation;
pub mod statics;
pub mod stream;
pub mod sweep_table;
pub mod tuning;
pub mod watch;
pub mod water;

use rerun::external::{eframe, egui, re_viewer};
use std::path::PathBuf;

/// What `tether gui` / `tether view` open.
#[derive(Debug, Clone, Default)]
pub struct GuiOptions {
    /// Scene to open at start.
    pub scene: Option<PathBuf>,
    /// Recording (`.rrd`) to play back at start.
    pub recording: Option<PathBuf>,
    /// Stream to the external viewer at this URL instead of the embedded one.
    pub connect: Option<String>,
    /// Also write everything shown to this `.rrd` file.
    pub save: Option<PathBuf>,
    /// Folder listed as the scene list (default `scenes`).
    pub scenes_dir: PathBuf,
    /// A sweep's output directory to open in the sweep table.
    pub sweep: Option<PathBuf>,
    /// Frames drawn per second at most; `None`: [`renderer::FrameCap::for_adapter`]'s default.
    pub max_fps: Option<u32>,
}

/// Why the window could not run.
#[derive(Debug, thiserror::Error)]
pub enum GuiError {
    #[error(transparent)]
    Sink(#[from] stream::SinkError),
    #[error("cannot start the async runtime of the viewer: {0}")]
    Runtime(std::io::Error),
    #[error("cannot start the simulation thread: {0}")]
    Thread(std::io::Error),
    #[error("the window failed: {0}")]
    Window(String),
}

/// Opens the window and runs until it is closed; the simulation thread is stopped and its
/// recordings flushed before this returns. A bad `--save` path or `--connect` URL fails before
/// the window opens.
pub fn run(options: GuiOptions) -> Result<(), GuiError> {
    // The viewer's own warnings and notes (a memory limit reached, data dropped, a renderer
    // problem) reach stderr, as in Rerun's viewer (`RUST_LOG` chooses what).
    rerun::external::re_log::setup_logging();
    let mut sinks = Vec::new();
    if let Some(url) = &options.connect {
        sinks.push(stream::Sinks::connect(url)?);
    }
    if let Some(path) = &options.save {
        sinks.push(stream::Sinks::file(path)?);
    }
    // `run_native` must be called on the main thread, which is where `tether` calls this.
    let main_thread = re_viewer::MainThreadToken::i_promise_i_am_on_the_main_thread();
    let runtime = rerun::external::tokio::runtime::Builder::new_multi_thread()
        .worker_threads(1)
        .enable_all()
        .build()
        .map_err(GuiError::Runtime)?;
    let mut native = re_viewer::native::eframe_options(None);
    // A plain, opaque, decorated window: transparent ones come out black under X without a
    // compositor (Xvfb screenshots).
    native.viewport = native
        .viewport
        .with_title("Tether")
        .with_app_id("tether")
        .with_decorations(true)
        .with_transparent(false)
        .with_inner_size([1600.0, 1000.0]);
    let mut failure: Option<GuiError> = None;
    let result = eframe::run_native(
        "Tether",
        native,
        Box::new(|cc| {
            re_viewer::customize_eframe_and_setup_renderer(cc)?;
            match app::TetherApp::new(cc, main_thread, runtime.handle().clone(), sinks, options) {
                Ok(app) => Ok(Box::new(app) as Box<dyn eframe::App>),
                Err(error) => {
                    let message = error.to_string();
                    failure = Some(error);
                    Err(message.into())
                }
            }
        }),
    );
    match (failure, result) {
        (Some(error), _) => Err(error),
        (None, Ok(())) => Ok(()),
        (None, Err(error)) => Err(GuiError::Window(error.to_string())),
    }
}

/// Repaints the window from another thread (the simulation, the file watcher, dialogs).
fn waker(ctx: &egui::Context) -> simulation::Wake {
    let ctx = ctx.clone();
    std::sync::Arc::new(move || ctx.request_repaint())
}
