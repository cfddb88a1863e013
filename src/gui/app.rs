//! The eframe application: the control panel on the left, the embedded Rerun viewer in the rest
//! of the window (or a note when streaming to an external viewer), dropped files.

use super::panel::{ControlPanel, Settings};
use super::stream::{Sinks, ViewerBacklog};
use super::{GuiError, GuiOptions, waker};
use rerun::external::{eframe, egui, re_log_channel, re_viewer};
use rerun::sink::{CallbackSink, LogSink};
use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::rc::Rc;

/// Key of the panel's [`Settings`] in eframe's storage.
const SETTINGS_KEY: &str = "tether_settings";

/// The window.
pub struct TetherApp {
    panel: ControlPanel,
    /// The embedded viewer (`None` with `--connect`).
    viewer: Option<re_viewer::App>,
    /// The entity selected in the viewer, from its selection events.
    selection: Rc<RefCell<Option<String>>>,
    connect: Option<String>,
    /// The frame rate's cap (on a software rasterizer, or as `--max-fps` asks).
    frame_cap: Option<super::renderer::FrameCap>,
    /// What the embedded viewer left in its channel after the last frame.
    backlog: ViewerBacklog,
    /// Shown above the viewer: the renderer's driver leaks while it plays, and its fix.
    driver_banner: Option<String>,
}

impl TetherApp {
    /// The window's state: the simulation thread writing to `sinks` (and to the embedded viewer,
    /// unless `options` connect to an external one), and what `options` open.
    pub fn new(
        cc: &eframe::CreationContext<'_>,
        main_thread: re_viewer::MainThreadToken,
        runtime: rerun::external::tokio::runtime::Handle,
        mut sinks: Vec<Box<dyn LogSink>>,
        options: GuiOptions,
    ) -> Result<Self, GuiError> {
        let selection = Rc::new(RefCell::new(None));
        let backlog = ViewerBacklog::default();
        let viewer = options.connect.is_none().then(|| {
            let (viewer, sink) = embedded_viewer(cc, main_thread, runtime, Rc::clone(&selection));
            sinks.push(sink);
            viewer
        });
        let sinks = Sinks::with_viewer(sinks, backlog.clone());
        let mut panel =
            ControlPanel::new(sinks, waker(&cc.egui_ctx), options.scenes_dir.clone()).map_err(GuiError::Thread)?;
        if let Some(settings) = cc.storage.and_then(|storage| eframe::get_value::<Settings>(storage, SETTINGS_KEY)) {
            panel.settings = settings;
        }
        if let Some(scene) = &options.scene {
            panel.open_scene(scene);
        }
        if let Some(sweep) = &options.sweep {
            panel.open_sweep(sweep);
        }
        let ctx = cc.egui_ctx.clone();
        // Ctrl-C and SIGTERM close the window as its close button does: the recordings are
        // flushed and the `.rrd` footer written.
        let closing = ctrlc::set_handler(move || {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
            ctx.request_repaint();
        });
        if let Err(error) = closing {
            panel.note_error(format!("Ctrl-C will not close the window cleanly: {error}"));
        }
        let adapter = cc.wgpu_render_state.as_ref().map(|state| state.adapter.get_info());
        let driver_banner = adapter.as_ref().and_then(super::renderer::leak_banner);
        // Rendering on the CPU is said; in red only with a driver that leaks (its banner too).
        match (adapter.as_ref().and_then(super::renderer::software_note), &driver_banner) {
            (Some(note), Some(_)) => panel.note_error(note),
            (Some(note), None) => panel.note(note),
            (None, _) => {}
        }
        let frame_cap = super::renderer::FrameCap::for_adapter(options.max_fps, adapter.as_ref());
        let mut app = Self { panel, viewer, selection, connect: options.connect, frame_cap, backlog, driver_banner };
        if let Some(recording) = &options.recording {
            app.open_recording(recording);
        }
        Ok(app)
    }

    /// The control panel (tests look into it).
    pub fn panel(&self) -> &ControlPanel {
        &self.panel
    }

    /// The embedded viewer (`None` with `--connect`; tests look into it and select in it).
    pub fn viewer(&self) -> Option<&re_viewer::App> {
        self.viewer.as_ref()
    }

    fn open_recording(&mut self, path: &Path) {
        match &self.viewer {
            Some(viewer) => {
                self.panel.play_back(path);
                viewer.open_url_or_file(&path.display().to_string());
            }
            None => self.panel.note_error(format!(
                "{}: recordings play back in the embedded viewer, not with --connect",
                path.display()
            )),
        }
    }

    /// Scenes dropped on the window are opened by the panel, recordings by the viewer, sweep
    /// directories (or their `sweep.json`) by the sweep table; any other file is refused with a
    /// line in the log.
    fn take_dropped_files(&mut self, ctx: &egui::Context) {
        let dropped: Vec<PathBuf> = ctx
            .input_mut(|i| std::mem::take(&mut i.raw.dropped_files))
            .into_iter()
            .map(|f| f.path().to_path_buf())
            .filter(|p| !p.as_os_str().is_empty())
            .collect();
        for path in dropped {
            match Dropped::of(&path) {
                Dropped::Scene => self.panel.open_scene(&path),
                Dropped::Recording => self.open_recording(&path),
                Dropped::Sweep(dir) => self.panel.open_sweep(&dir),
                Dropped::Other => self.panel.note_error(format!(
                    "{}: not a scene (.ron), a recording (.rrd) or a sweep directory; nothing opened",
                    path.display()
                )),
            }
        }
    }
}

/// What a dropped file is taken for: by its extension, or a sweep's directory.
#[derive(Debug, PartialEq)]
enum Dropped {
    Scene,
    Recording,
    /// A sweep's output directory (dropped itself, or its manifest).
    Sweep(PathBuf),
    Other,
}

impl Dropped {
    fn of(path: &Path) -> Self {
        let manifest = tether_analysis::sweep::store::MANIFEST;
        if path.is_dir() && path.join(manifest).is_file() {
            return Self::Sweep(path.to_path_buf());
        }
        if path.file_name().is_some_and(|n| n == manifest) {
            return Self::Sweep(path.parent().unwrap_or(Path::new(".")).to_path_buf());
        }
        let extension = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase());
        match extension.as_deref() {
            Some("ron") => Self::Scene,
            Some("rrd") => Self::Recording,
            _ => Self::Other,
        }
    }
}

/// The viewer, fed through an in-process channel, and the sink that feeds it.
fn embedded_viewer(
    cc: &eframe::CreationContext<'_>,
    main_thread: re_viewer::MainThreadToken,
    runtime: rerun::external::tokio::runtime::Handle,
    selection: Rc<RefCell<Option<String>>>,
) -> (re_viewer::App, Box<dyn LogSink>) {
    let (tx, rx) = re_log_channel::log_channel(re_log_channel::LogSource::Sdk);
    let on_event = move |event: re_viewer::ViewerEvent| {
        if let re_viewer::ViewerEventKind::SelectionChange { items } = event.kind {
            *selection.borrow_mut() = items.into_iter().find_map(|item| match item {
                re_viewer::SelectionChangeItem::Entity { entity_path, .. } => Some(entity_path.to_string()),
                _ => None,
            });
        }
    };
    let mut startup = re_viewer::StartupOptions {
        persist_state: false,
        hide_welcome_screen: true,
        expect_data_soon: Some(true),
        on_event: Some(Rc::new(on_event)),
        ..Default::default()
    };
    // Room for the views beside the control panel: the viewer's own side panels start folded.
    let collapsed = Some(re_viewer::external::re_sdk_types::blueprint::components::PanelState::Collapsed);
    startup.panel_state_overrides.blueprint = collapsed;
    startup.panel_state_overrides.selection = collapsed;
    let mut viewer = re_viewer::App::new(
        main_thread,
        re_viewer::build_info(),
        re_viewer::AppEnvironment::Custom("tether".into()),
        startup,
        cc,
        None,
        re_viewer::AsyncRuntimeHandle::new_native(runtime),
    );
    viewer.app_options_mut().custom_window_decorations = false;
    viewer.app_options_mut().memory_limit = super::renderer::memory_limit();
    viewer.add_log_receiver(rx);
    let sink = CallbackSink::new(move |messages| {
        for message in messages {
            // The viewer closed its end only when the window is closing.
            tx.send(re_log_channel::DataSourceMessage::LogMsg(message.clone())).ok();
        }
    });
    (viewer, Box::new(sink))
}

impl eframe::App for TetherApp {
    fn logic(&mut self, ctx: &egui::Context, frame: &mut eframe::Frame) {
        if let Some(cap) = &mut self.frame_cap {
            cap.wait();
        }
        self.take_dropped_files(ctx);
        // The embedded viewer quits on Ctrl+Q; without it, so does the window.
        if self.viewer.is_none() && ctx.input_mut(|i| i.consume_key(egui::Modifiers::COMMAND, egui::Key::Q)) {
            ctx.send_viewport_cmd(egui::ViewportCommand::Close);
        }
        for recording in self.panel.take_recordings_to_open() {
            self.open_recording(&recording);
        }
        if let Some(viewer) = &mut self.viewer {
            viewer.logic(ctx, frame);
            self.backlog.set(viewer.msg_receive_set().queue_len());
        }
    }

    fn ui(&mut self, ui: &mut egui::Ui, frame: &mut eframe::Frame) {
        let selected = self.selection.borrow().clone();
        self.panel.side_panel(ui, selected.as_deref());
        if self.panel.sweep().is_some() {
            egui::Panel::bottom("tether_sweep").resizable(true).default_size(300.0).show(ui, |ui| {
                self.panel.sweep_ui(ui);
            });
        }
        if let Some(banner) = &self.driver_banner {
            egui::Panel::top("tether_driver_banner").show(ui, |ui| {
                let text = egui::RichText::new(banner).color(ui.visuals().warn_fg_color).strong();
                ui.add(egui::Label::new(text).wrap().selectable(true));
            });
        }
        match (&mut self.viewer, &self.connect) {
            (Some(viewer), _) => viewer.ui(ui, frame),
            (None, url) => {
                egui::CentralPanel::default().show(ui, |ui| {
                    ui.label(format!("Streaming to the viewer at {}", url.as_deref().unwrap_or("?")));
                });
            }
        }
    }

    fn raw_input_hook(&mut self, ctx: &egui::Context, raw_input: &mut egui::RawInput) {
        self.panel.take_shortcuts(ctx, &mut raw_input.events);
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, SETTINGS_KEY, &self.panel.settings);
    }

    fn on_exit(&mut self) {
        self.panel.shutdown();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sweep directory is known by its manifest, whether the folder or the manifest is dropped.
    #[test]
    fn dropped_sweep_directories_are_told_from_scenes_and_recordings() {
        let dir = tempfile::tempdir().unwrap();
        assert_eq!(Dropped::of(dir.path()), Dropped::Other, "a folder with no sweep in it");
        let manifest = dir.path().join(tether_analysis::sweep::store::MANIFEST);
        std::fs::write(&manifest, "{}").unwrap();
        assert_eq!(Dropped::of(dir.path()), Dropped::Sweep(dir.path().to_path_buf()));
        assert_eq!(Dropped::of(&manifest), Dropped::Sweep(dir.path().to_path_buf()));
        assert_eq!(Dropped::of(Path::new("scenes/chain.ron")), Dropped::Scene);
        assert_eq!(Dropped::of(Path::new("out.RRD")), Dropped::Recording);
        assert_eq!(Dropped::of(Path::new("notes.txt")), Dropped::Other);
    }
}
