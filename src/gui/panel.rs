//! The control panel: the layout of the sub-panels, the simulation handle and the open scene
//! ([`OpenScene`]). The sub-panels draw and return what they want done; this module does it
//! (loads a scene, has a tuned value checked, sends the simulation a command).
//!
//! State is split the egui-demo way: [`Settings`] is plain data worth keeping between sessions;
//! the runtime handles (thread, watcher, dialogs) live beside it.

use super::air;
use super::contact_estimator::{self, ImpactDraft, UseEstimate};
use super::dialogs::{Dialogs, Purpose};
use super::fit::{self, Decision, FitAction, FitDraft, FitUpdate, SceneFits};
use super::follow;
use super::indicators::{self, EnergyHistory};
use super::knobs::Knob;
use super::open_scene::{KnobId, OnDisk, OpenScene};
use super::run_controls::{self, RunAction, TimingDraft};
use super::scenes::{self, Playback, SceneAction};
use super::simulation::{Command, Report, Simulation, Speed, Status, Wake};
use super::statics::{self, StaticsAction, StaticsDraft};
use super::stream::Sinks;
use super::sweep_table::{SweepAction, SweepTable};
use super::tuning::{self, TuningAction};
use super::water::{self, WaterAction};
use rerun::external::egui;
use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::time::Duration;
use tether_scene::file::CouplingDef;

/// Keys of the run shortcuts: play/pause, one step, reset.
const SHORTCUTS: [egui::Key; 3] = [egui::Key::Space, egui::Key::ArrowRight, egui::Key::Backspace];

/// Messages kept in the panel's log.
const LOG_LINES: usize = 6;

/// How long the open file must stay quiet after a change before it is reloaded (editors write
/// in several steps).
const SETTLE: Duration = Duration::from_millis(150);

/// What is worth keeping between sessions.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Settings {
    pub speed: Speed,
    /// Whether the contacts' face forces are drawn as arrows.
    #[serde(default)]
    pub face_arrows: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Self { speed: Speed::Factor(1.0), face_arrows: false }
    }
}

/// A line of the panel's log.
#[derive(Debug, Clone, PartialEq)]
pub struct LogLine {
    pub text: String,
    pub error: bool,
}

/// The control panel.
pub struct ControlPanel {
    pub settings: Settings,
    simulation: Simulation,
    wake: Wake,
    scene: Option<OpenScene>,
    /// The file the last scene came from that could not be opened, and why (the previous scene
    /// keeps running).
    load_error: Option<(PathBuf, String)>,
    status: Option<Status>,
    history: EnergyHistory,
    timing: TimingDraft,
    log: VecDeque<LogLine>,
    dialogs: Dialogs,
    scenes_dir: PathBuf,
    scene_list: Vec<PathBuf>,
    recordings_to_open: Vec<PathBuf>,
    impact: ImpactDraft,
    /// The sweep directory open beside the scene, if any.
    sweep: Option<SweepTable>,
    /// The statics panel's knobs and last offset curve.
    statics: StaticsDraft,
    /// The fit panel's record, choices and fit, of the open scene; the other scenes' in `fits`.
    fit: FitDraft,
    fits: SceneFits,
    /// The recording played back in the viewer since the scene was closed for it, and the scene
    /// that was closed (to go back to).
    playback: Option<Playback>,
    /// The body the viewer's eye follows, if any (none when a scene is loaded).
    follow: Option<String>,
}

impl ControlPanel {
    /// A panel with its simulation thread (no scene yet) writing to `sinks`; `wake` repaints.
    pub fn new(sinks: Sinks, wake: Wake, scenes_dir: PathBuf) -> std::io::Result<Self> {
        let simulation = Simulation::spawn(sinks, wake.clone())?;
        let scene_list = tether_scene::list(&scenes_dir);
        Ok(Self {
            settings: Settings::default(),
            simulation,
            wake,
            scene: None,
            load_error: None,
            status: None,
            history: EnergyHistory::default(),
            timing: TimingDraft::default(),
            log: VecDeque::new(),
            dialogs: Dialogs::default(),
            scenes_dir,
            scene_list,
            recordings_to_open: Vec::new(),
            impact: ImpactDraft::default(),
            sweep: None,
            statics: StaticsDraft::default(),
            fit: FitDraft::default(),
            fits: SceneFits::default(),
            playback: None,
            follow: None,
        })
    }

    /// The simulation thread's handle (tests query it).
    pub fn simulation(&self) -> &Simulation {
        &self.simulation
    }

    /// The latest status of the simulation.
    pub fn status(&self) -> Option<&Status> {
        self.status.as_ref()
    }

    /// The scene being run.
    pub fn scene(&self) -> Option<&OpenScene> {
        self.scene.as_ref()
    }

    /// Why the last scene could not be opened.
    pub fn load_error(&self) -> Option<&str> {
        self.load_error.as_ref().map(|(_, message)| message.as_str())
    }

    /// The panel's log, oldest first.
    pub fn log(&self) -> impl Iterator<Item = &LogLine> {
        self.log.iter()
    }

    /// The recording played back in the viewer, if one is.
    pub fn playback(&self) -> Option<&Playback> {
        self.playback.as_ref()
    }

    /// A recording is played back in the viewer: the live scene's run is stopped and closed
    /// (its controls go grey: the viewer no longer shows it, so nothing may run unseen), the
    /// panel says what plays and offers the closed scene back.
    pub fn play_back(&mut self, recording: &Path) {
        let closed = self.scene.take().map(|open| open.path);
        if let Some(path) = &closed {
            self.simulation.send(Command::Close);
            self.note(format!(
                "closed {} to play back a recording (tuned values not kept: \"Save as…\" keeps them)",
                path.display()
            ));
        }
        self.status = None;
        self.history = EnergyHistory::default();
        self.fit.scene_changed();
        self.note(format!("playing back {}", recording.display()));
        self.playback = Some(Playback { recording: recording.to_path_buf(), closed });
    }

    /// Recordings the user asked to play back (the app gives them to the viewer).
    pub fn take_recordings_to_open(&mut self) -> Vec<PathBuf> {
        std::mem::take(&mut self.recordings_to_open)
    }

    /// Adds a line to the log.
    pub fn note(&mut self, text: String) {
        self.push_log(LogLine { text, error: false });
    }

    /// Adds an error line to the log.
    pub fn note_error(&mut self, text: String) {
        self.push_log(LogLine { text, error: true });
    }

    fn push_log(&mut self, line: LogLine) {
        if self.log.len() == LOG_LINES {
            self.log.pop_front();
        }
        self.log.push_back(line);
    }

    /// Loads the scene at `path` and runs it paused at t = 0. A bad file keeps the previous
    /// scene running and shows its `path:line:col: message`.
    pub fn open_scene(&mut self, path: &Path) {
        match OpenScene::load(path, self.wake.clone()) {
            Ok(loaded) => self.start(loaded),
            Err(error) => self.load_error = Some((path.to_path_buf(), error.to_string())),
        }
    }

    /// Opens the sweep in directory `dir` in the sweep table (the scene running stays).
    pub fn open_sweep(&mut self, dir: &Path) {
        match SweepTable::open(dir) {
            Ok(table) => {
                self.note(format!("opened sweep {} ({})", table.name(), dir.display()));
                self.sweep = Some(table);
            }
            Err(error) => self.note_error(error),
        }
    }

    /// Opens the measured record at `path` in the fit panel (CSV, Parquet or a recording); a
    /// file that cannot be read is refused there with its file and line.
    pub fn open_record(&mut self, path: &Path) {
        match self.fit.open_record(path) {
            Ok(record) => {
                let text = format!("opened record {} ({} columns)", path.display(), record.columns.len());
                self.note(text);
            }
            Err(error) => self.fit.refuse(error),
        }
    }

    /// The fit panel's state (tests look into it).
    pub fn fit(&self) -> &FitDraft {
        &self.fit
    }

    /// The open sweep (tests look into it).
    pub fn sweep(&self) -> Option<&SweepTable> {
        self.sweep.as_ref()
    }

    /// Draws the sweep table, if a sweep is open, and loads the case it asks for.
    pub fn sweep_ui(&mut self, ui: &mut egui::Ui) {
        let Some(table) = &mut self.sweep else { return };
        if let Some(SweepAction::Load(case)) = table.ui(ui) {
            self.open_case(case);
        }
    }

    /// Loads case `case` of the open sweep: its base scene with the case's values, paused at
    /// t = 0, the values in the tuning panel.
    pub fn open_case(&mut self, case: usize) {
        let Some(table) = &self.sweep else { return };
        let label = format!("{} case {case}", table.name());
        let loaded = match table.case_scene(case) {
            Ok((path, file, changed)) => {
                if let Some(changed) = changed {
                    self.note_error(changed);
                }
                OpenScene::load_variant(&path, file, label, self.wake.clone()).map_err(|e| e.to_string())
            }
            Err(error) => Err(error),
        };
        match loaded {
            Ok(loaded) => {
                self.note(format!("case {case} loaded: press Space to run it"));
                self.start(loaded);
            }
            Err(error) => self.note_error(format!("case {case}: {error}")),
        }
    }

    /// Runs a loaded scene, paused at t = 0.
    fn start(&mut self, loaded: super::open_scene::Loaded) {
        for note in loaded.notes {
            self.note(note);
        }
        self.load_error = None;
        self.playback = None;
        // Per-scene state starts from the scene: nothing typed for the last one carries over.
        self.timing = TimingDraft::from_file(&loaded.scene.tuned);
        self.impact = ImpactDraft::default();
        self.history = EnergyHistory::default();
        self.statics = StaticsDraft::default();
        let (fittables, signals) =
            (tether_analysis::parameters::parameters(&loaded.scene.tuned), fit::signals(&loaded.scene.tuned));
        for dropped in self.fits.switch(&mut self.fit, &loaded.scene.path, &fittables, &signals) {
            self.note(dropped);
        }
        self.scene = Some(loaded.scene);
        self.follow = None;
        self.simulation.send(Command::Follow(None));
        self.simulation.send(Command::Load(Box::new(loaded.run)));
        self.simulation.send(Command::SetSpeed(self.settings.speed));
        self.simulation.send(Command::SetFaceArrows(self.settings.face_arrows));
    }

    /// Stops the simulation thread and flushes its recording.
    pub fn shutdown(&mut self) {
        self.simulation.stop();
    }

    /// Draws the panel as the window's left side panel, 380 points wide to start with and
    /// resizable by the user (long lines wrap in it instead of widening it); returns its width.
    pub fn side_panel(&mut self, ui: &mut egui::Ui, selected: Option<&str>) -> f32 {
        let shown = egui::Panel::left("tether_controls").resizable(true).default_size(380.0).show(ui, |ui| {
            self.ui(ui, selected);
        });
        shown.response.rect.width()
    }

    /// Draws the panel and does what it asks; `selected` is the entity selected in the viewer.
    pub fn ui(&mut self, ui: &mut egui::Ui, selected: Option<&str>) {
        self.receive();
        self.reload_if_changed(ui.ctx());
        self.poll_dialogs();
        self.shortcuts(ui.ctx());
        // The log at the bottom of the panel, always in sight, newest first.
        // Not resizable: a resize handle would take the keyboard focus before "Open scene…" (Tab).
        egui::Panel::bottom("tether_log").resizable(false).exact_size(120.0).show(ui, |ui| self.log_ui(ui));
        egui::ScrollArea::vertical().auto_shrink([false, false]).show(ui, |ui| {
            ui.heading("Tether");
            let scene_path = self.scene.as_ref().map(|s| s.path.as_path());
            let picker = scenes::Picker {
                current: scene_path,
                scenes: &self.scene_list,
                load_error: self.load_error(),
                playback: self.playback.as_ref(),
            };
            if let Some(action) = scenes::ui(ui, &picker) {
                self.scene_action(action);
            }
            ui.separator();
            let actions = run_controls::ui(
                ui,
                self.status.as_ref(),
                &mut self.timing,
                &mut self.settings.speed,
                &mut self.settings.face_arrows,
            );
            for action in actions {
                self.run_action(action);
            }
            if let Some(follow) = follow::ui(ui, self.status.as_ref(), &self.follow) {
                self.follow = follow.clone();
                self.simulation.send(Command::Follow(follow));
            }
            ui.separator();
            indicators::ui(ui, self.status.as_ref(), &self.history, selected);
            ui.separator();
            let contacts = self.status.as_ref().map_or(&[][..], |s| s.contacts.as_slice());
            if let Some(estimate) = contact_estimator::ui(ui, contacts, &mut self.impact) {
                self.use_estimate(estimate);
            }
            self.tuning_ui(ui);
            self.water_ui(ui);
            self.air_ui(ui);
            self.statics_ui(ui, selected);
            self.fit_ui(ui);
        });
        if self.status.as_ref().is_some_and(|s| s.running) {
            ui.ctx().request_repaint_after(super::simulation::TICK);
        }
    }

    /// Takes the simulation's reports and the fit's news.
    fn receive(&mut self) {
        self.receive_fit();
        for report in self.simulation.drain() {
            match report {
                // A status sent before the scene was closed is no run's any more.
                Report::Status(_) if self.scene.is_none() => {}
                Report::Status(status) => {
                    self.history.push(&status);
                    self.status = Some(*status);
                }
                Report::Message(text) => self.note(text),
                Report::Error(text) => self.note_error(text),
                Report::OffsetCurve(curve) => {
                    self.note(format!(
                        "offset curve of body \"{}\" in {}: {} offsets",
                        curve.body,
                        curve.direction,
                        curve.points.len()
                    ));
                    self.statics.curve = Some(curve);
                }
            }
        }
    }

    /// Reloads the open scene when its file changed on disk and has settled.
    fn reload_if_changed(&mut self, ctx: &egui::Context) {
        let Some(open) = &self.scene else { return };
        let path = open.path.clone();
        match open.on_disk(SETTLE) {
            OnDisk::Changed => {
                self.note(format!("{} changed on disk: reloading", path.display()));
                self.open_scene(&path);
            }
            OnDisk::Restored if self.load_error.as_ref().is_some_and(|(failed, _)| *failed == path) => {
                // A broken save undone: the file says again what runs, so its error goes.
                self.load_error = None;
                self.note(format!("{} is back to the running scene", path.display()));
            }
            OnDisk::Settling => ctx.request_repaint_after(SETTLE),
            OnDisk::Restored | OnDisk::Quiet => {}
        }
    }

    fn poll_dialogs(&mut self) {
        let Some((purpose, path)) = self.dialogs.poll() else { return };
        match purpose {
            Purpose::OpenScene => self.open_scene(&path),
            Purpose::OpenRecording => self.recordings_to_open.push(path),
            Purpose::SaveScene => self.save_as(&path),
            Purpose::OpenRecord => self.open_record(&path),
        }
    }

    /// Takes the run shortcuts (Space: play/pause; →: one step, repeating while held;
    /// Backspace: reset) out of the window's raw input before anything else sees them — the
    /// embedded viewer takes the same keys for its timeline at the start of each frame — and
    /// acts on them. Nothing is taken while a text field (a knob being typed into) has the
    /// keyboard.
    pub fn take_shortcuts(&mut self, ctx: &egui::Context, events: &mut Vec<egui::Event>) {
        if ctx.text_edit_focused() {
            return;
        }
        let mut pressed = Vec::new();
        events.retain(|event| match event {
            egui::Event::Key { key, pressed: down, repeat, modifiers, .. }
                if modifiers.is_none() && SHORTCUTS.contains(key) =>
            {
                if *down && (!*repeat || *key == egui::Key::ArrowRight) {
                    pressed.push(*key);
                }
                false
            }
            _ => true,
        });
        for key in pressed {
            self.shortcut(key);
        }
    }

    /// The run shortcuts, when the panel runs on its own (no window to hook into).
    fn shortcuts(&mut self, ctx: &egui::Context) {
        if ctx.text_edit_focused() {
            return;
        }
        for key in SHORTCUTS {
            if ctx.input_mut(|i| i.consume_key(egui::Modifiers::NONE, key)) {
                self.shortcut(key);
            }
        }
    }

    fn shortcut(&mut self, key: egui::Key) {
        let running = self.status.as_ref().is_some_and(|s| s.running);
        let action = match key {
            egui::Key::Space if running => RunAction::Pause,
            egui::Key::Space => RunAction::Play,
            egui::Key::ArrowRight => RunAction::Step,
            _ => RunAction::Reset,
        };
        self.run_action(action);
    }

    fn scene_action(&mut self, action: SceneAction) {
        match action {
            SceneAction::Open(path) => self.open_scene(&path),
            SceneAction::Browse => self.dialogs.open(Purpose::OpenScene, &self.scenes_dir, self.wake.clone()),
            SceneAction::BrowseRecording => {
                self.dialogs.open(Purpose::OpenRecording, Path::new("."), self.wake.clone())
            }
            SceneAction::Refresh => self.scene_list = tether_scene::list(&self.scenes_dir),
        }
    }

    fn run_action(&mut self, action: RunAction) {
        let command = match action {
            RunAction::Play => Command::Play,
            RunAction::Pause => Command::Pause,
            RunAction::Step => Command::Step,
            RunAction::Reset => {
                self.history = EnergyHistory::default();
                Command::Reset
            }
            RunAction::Speed(speed) => Command::SetSpeed(speed),
            RunAction::FaceArrows(on) => Command::SetFaceArrows(on),
            RunAction::ApplyTiming => match self.checked_timing() {
                Ok(timing) => Command::SetTiming(timing),
                Err(message) => return self.timing.refusal = Some(message),
            },
        };
        self.simulation.send(command);
    }

    /// The timing draft, checked by the scene builder; accepted into the tuned scene.
    fn checked_timing(&mut self) -> Result<tether_physics::integrator::Timing, String> {
        let Some(open) = &mut self.scene else { return Err("no scene loaded".into()) };
        let mut candidate = open.tuned.clone();
        self.timing.write_to(&mut candidate);
        let timing = open.retime(candidate)?;
        self.timing.refusal = None;
        Ok(timing)
    }

    fn tuning_ui(&mut self, ui: &mut egui::Ui) {
        let Some(open) = &mut self.scene else {
            ui.label("Open a scene to tune its couplings.");
            return;
        };
        let hints = self.status.as_ref().map_or(&[][..], |s| s.line_hints.as_slice());
        let actions = tuning::ui(ui, open.knobs.couplings.knobs_mut(), &open.file, hints);
        for action in actions {
            match action {
                TuningAction::Edited(index) => self.tune(KnobId::Coupling(index)),
                TuningAction::Revert => self.revert_to_file(),
                TuningAction::SaveAs => {
                    let folder =
                        self.scene.as_ref().and_then(|s| s.path.parent().map(Path::to_path_buf)).unwrap_or_default();
                    self.dialogs.open(Purpose::SaveScene, &folder, self.wake.clone());
                }
            }
        }
    }

    fn water_ui(&mut self, ui: &mut egui::Ui) {
        let Some(open) = &mut self.scene else { return };
        let running = self.status.as_ref().map_or(&[][..], |s| s.potential_flow.as_slice());
        let drift = self.status.as_ref().map_or(&[][..], |s| s.drift.as_slice());
        let knobs = &mut open.knobs;
        let drafts = knobs.water.knobs_mut().first_mut().map(|water| water::WaterKnobs {
            water,
            bodies: knobs
                .hydro
                .knobs_mut()
                .iter_mut()
                .zip(&open.file.bodies)
                .enumerate()
                .filter_map(|(index, (Knob { draft, refusals }, body))| {
                    draft.as_mut().map(|hydro| water::FloatingKnobs {
                        index,
                        name: body.name.as_str(),
                        hydro,
                        refusals: refusals.as_slice(),
                        potential_flow: running.iter().find(|(b, _)| *b == index).map(|(_, on)| *on),
                        drift_data: drift.iter().any(|(b, _)| *b == index),
                    })
                })
                .collect(),
        });
        for action in water::ui(ui, drafts) {
            match action {
                WaterAction::Water => self.tune(KnobId::Water),
                WaterAction::Hydro(index) => self.tune(KnobId::Hydro(index)),
                WaterAction::PotentialFlow { body, on } => self.simulation.send(Command::SetPotentialFlow { body, on }),
            }
        }
    }

    /// The air panel: the wind, its gusts, the air's density (none without air).
    fn air_ui(&mut self, ui: &mut egui::Ui) {
        let Some(open) = &mut self.scene else { return };
        if air::ui(ui, open.knobs.air.knobs_mut().first_mut()) {
            self.tune(KnobId::Air);
        }
    }

    /// The statics panel: the seabed's C_B, the equilibrium button, the offset curve of the body
    /// selected in the viewer (or chosen in the panel).
    fn statics_ui(&mut self, ui: &mut egui::Ui, selected: Option<&str>) {
        let Some(open) = &mut self.scene else { return };
        let bodies: Vec<String> = open.tuned.bodies.iter().map(|b| b.name.clone()).collect();
        let selected = selected.and_then(tether_record::paths::body_of);
        let seabed = open.knobs.seabed.knobs_mut().first_mut();
        for action in statics::ui(ui, &mut self.statics, seabed, &bodies, selected) {
            match action {
                StaticsAction::Seabed => self.tune(KnobId::Seabed),
                StaticsAction::Equilibrium => self.simulation.send(Command::Equilibrium),
                StaticsAction::OffsetCurve { body, direction, to, steps } => {
                    self.simulation.send(Command::OffsetCurve { body, direction, to, steps })
                }
            }
        }
    }

    /// The fit panel: the record, its columns' signals, the knobs to fit, the fit running or
    /// done.
    fn fit_ui(&mut self, ui: &mut egui::Ui) {
        let Some(open) = &self.scene else { return };
        let fittables = tether_analysis::parameters::parameters(&open.tuned);
        let signals = fit::signals(&open.tuned);
        let folder = open.path.parent().map(Path::to_path_buf).unwrap_or_default();
        for action in fit::ui(ui, &mut self.fit, &fittables, &signals) {
            match action {
                FitAction::BrowseRecord => self.dialogs.open(Purpose::OpenRecord, &folder, self.wake.clone()),
                FitAction::Start => self.start_fit(&fittables),
                FitAction::Stop => self.fit.stop(),
                FitAction::Apply => self.end_fit(Decision::Kept),
                FitAction::Revert => self.end_fit(Decision::Reverted),
            }
        }
    }

    /// Starts the fit chosen in the fit panel on the scene as it runs, its record drawn in the
    /// viewer; a bad choice is refused there in one line and nothing runs.
    fn start_fit(&mut self, fittables: &[tether_analysis::parameters::Parameter]) {
        let Some(open) = &self.scene else { return };
        let launched = self
            .fit
            .prepare(open, fittables)
            .and_then(|(setup, targets)| self.fit.launch(setup, targets, self.wake.clone()));
        match launched {
            Ok(measured) => self.simulation.send(Command::ShowFit(measured)),
            Err(refusal) => self.fit.refuse(refusal),
        }
    }

    /// Takes the fit's news: the fitted knobs moved (as edits: the running simulation follows),
    /// the model's curves redrawn, a line in the log at the end.
    fn receive_fit(&mut self) {
        for update in self.fit.poll() {
            match update {
                FitUpdate::Values(values) => self.set_values(&values),
                FitUpdate::Curves(curves) => self.simulation.send(Command::FitModel(curves)),
                FitUpdate::Ended { text, error: false } => self.note(text),
                FitUpdate::Ended { text, error: true } => self.note_error(text),
            }
        }
    }

    /// Values at value paths into their knobs, checked and applied as edits.
    fn set_values(&mut self, values: &[(KnobId, String, f64)]) {
        let Some(open) = &mut self.scene else { return };
        let values: Vec<(KnobId, &str, f64)> = values.iter().map(|(k, p, v)| (*k, p.as_str(), *v)).collect();
        match open.set_values(&values) {
            Ok(commands) => commands.into_iter().for_each(|command| self.simulation.send(command)),
            Err(error) => self.note_error(format!("the fitted values cannot be set: {error}")),
        }
    }

    /// The fit's values kept (they are running, tuned), or its knobs back to the file's values.
    fn end_fit(&mut self, decision: Decision) {
        let (Some(open), Some(session)) = (&mut self.scene, &mut self.fit.session) else { return };
        session.decision = Some(decision);
        let labels: Vec<&str> = session.targets.iter().map(|t| t.label.as_str()).collect();
        let line = match decision {
            Decision::Kept => format!("kept the fitted {}", labels.join(", ")),
            Decision::Reverted => {
                let paths: Vec<(KnobId, &str)> = session.targets.iter().map(|t| (t.knob, t.path.as_str())).collect();
                for command in open.revert_values(&paths) {
                    self.simulation.send(command);
                }
                format!("{} back to the file's values", labels.join(", "))
            }
        };
        self.note(line);
    }

    /// Has what knob `knob` shows checked by the scene builder (same checks and messages as
    /// loading): an accepted value goes to the simulation, a refused one stays in its knob with
    /// the reason and the simulation is untouched.
    pub fn tune(&mut self, knob: KnobId) {
        let Some(open) = &mut self.scene else { return };
        if let Some(command) = open.tune(knob) {
            self.simulation.send(command);
        }
    }

    /// The estimator's k1 and k2 into a contact's knobs, applied as an edit.
    fn use_estimate(&mut self, estimate: UseEstimate) {
        let Some(open) = &mut self.scene else { return };
        let knob = open.knobs.couplings.knobs_mut().get_mut(estimate.index);
        if let Some(Knob { draft: CouplingDef::Contact { stiffness, damping, .. }, .. }) = knob {
            (*stiffness, *damping) = (estimate.stiffness, estimate.damping);
            self.tune(KnobId::Coupling(estimate.index));
        }
    }

    /// Every coupling and the water back to what the file says, in the running simulation too
    /// (a body's potential flow switched off, on again).
    pub fn revert_to_file(&mut self) {
        let Some(open) = &mut self.scene else { return };
        for knob in open.revert_to_file() {
            self.tune(knob);
        }
        let off = self.status.as_ref().map_or(&[][..], |s| s.potential_flow.as_slice()).iter().filter(|(_, on)| !on);
        for &(body, _) in off {
            self.simulation.send(Command::SetPotentialFlow { body, on: true });
        }
    }

    /// Writes the tuned scene to `path` as RON that loads back to the same scene (mesh files
    /// found from the new folder too).
    pub fn save_as(&mut self, path: &Path) {
        let Some(open) = &self.scene else { return };
        match open.save_as(path) {
            Ok(()) => self.note(format!("saved the tuned scene to {}", path.display())),
            Err(error) => self.note_error(format!("cannot save {}: {error}", path.display())),
        }
    }

    /// The log, newest line first, each wrapped in the panel's width.
    fn log_ui(&self, ui: &mut egui::Ui) {
        ui.style_mut().wrap_mode = Some(egui::TextWrapMode::Wrap);
        ui.weak("Log, newest first");
        egui::ScrollArea::vertical().auto_shrink([false, false]).show(ui, |ui| {
            for line in self.log.iter().rev() {
                if line.error {
                    ui.colored_label(ui.visuals().error_fg_color, &line.text);
                } else {
                    ui.label(&line.text);
                }
            }
        });
    }
}
