//! The fit panel (docs/window.md, "Fit"; docs/calibration.md): a measured record opened, each of
//! its columns mapped to a model signal or left out, the knobs to fit ticked with their bounds
//! (prefilled around the value now), and `tether fit` run on the scene as the window holds it, on
//! a thread of its own. After every accepted iteration the fitted knobs move to the new values
//! in the running simulation and the model's curves are drawn again beside the record's in the
//! viewer; at the end each fitted knob shows its value and 95 % interval. "Apply" keeps the
//! values, "Revert" puts the file's back.
//!
//! Each scene opened in the window keeps its own fit state ([`SceneFits`]): a record mapped to
//! one scene's couplings never reaches another's.
//!
//! The state ([`FitDraft`]) and the signals a record's column can be ([`signals`]) have no egui in
//! them; [`ui`] draws them and returns [`FitAction`]s, which the panel carries out, and the panel
//! takes the fit's news as [`FitUpdate`]s ([`FitDraft::poll`]).
//!
//! The matches over the scene's coupling kinds, elastic laws, line models, waves and quantities
//! are exhaustive: a new kind does not compile until it says what can be fitted in it.

use super::line_plot::{self, Framed};
use super::number_field::number_field;
use super::open_scene::OpenScene;
use super::simulation::{Curve, Wake};
use crate::figures;
use crate::fit::measured::Record;
use crate::fit::run::{self, Fitted, Outcome, Progress};
use crate::fit::setup::{Setup, SetupError};
use crate::fit::solver::Ending;
use crate::fit::spec::{FitFile, ParameterDef, Scale, SignalDef, Window};
use crate::parameters::{KnobId, Parameter};
use crate::quantity::{Axis, End, EnergyPart, Quantity, Turn};
use crate::runner::{Runner, all_cores};
use crate::sweep::spec::PathsDef;
use rerun::external::egui;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, TryRecvError};
use tether_scene::SceneFile;
use tether_scene::file::CouplingDef;

/// Points of a model curve sent to the viewer at most (a run's every world step, thinned).
const CURVE_POINTS: usize = 4000;

/// The model signals a measured column can be: each body's position, velocity and roll, pitch,
/// yaw; each coupling's tension (a contact's normal force), a spring's or line's length, a line's
/// end tensions.
pub fn signals(file: &SceneFile) -> Vec<Quantity> {
    let mut signals = Vec::new();
    for body in &file.bodies {
        let name = || body.name.clone();
        signals.extend([Axis::X, Axis::Y, Axis::Z].map(|axis| Quantity::Position(name(), axis)));
        signals.extend([Axis::X, Axis::Y, Axis::Z].map(|axis| Quantity::Velocity(name(), axis)));
        signals.extend([Turn::Roll, Turn::Pitch, Turn::Yaw].map(|turn| Quantity::Angle(name(), turn)));
    }
    for def in &file.couplings {
        let name = || def.name().to_string();
        match def {
            CouplingDef::SpringDamper { .. } => signals.extend([Quantity::Tension(name()), Quantity::Length(name())]),
            CouplingDef::Catenary { .. } => signals.extend([
                Quantity::Tension(name()),
                Quantity::EndTension(name(), End::End1),
                Quantity::EndTension(name(), End::End2),
                Quantity::Length(name()),
            ]),
            CouplingDef::Contact { .. } => signals.push(Quantity::Tension(name())),
        }
    }
    signals
}

/// A signal as the column choice shows it: `m: position x [m]`, `chain: end 2 tension [N]`.
pub fn signal_label(quantity: &Quantity) -> String {
    let axis = |axis: &Axis| match axis {
        Axis::X => "x",
        Axis::Y => "y",
        Axis::Z => "z",
    };
    let end = |end: &End| match end {
        End::End1 => "end 1",
        End::End2 => "end 2",
    };
    match quantity {
        Quantity::Tension(c) => format!("{c}: tension [N]"),
        Quantity::EndTension(c, e) => format!("{c}: {} tension [N]", end(e)),
        Quantity::EndForce(c, e, a) => format!("{c}: {} force {} [N]", end(e), axis(a)),
        Quantity::Length(c) => format!("{c}: length [m]"),
        Quantity::Position(b, a) => format!("{b}: position {} [m]", axis(a)),
        Quantity::Velocity(b, a) => format!("{b}: velocity {} [m/s]", axis(a)),
        Quantity::Angle(b, turn) => {
            let turn = match turn {
                Turn::Roll => "roll",
                Turn::Pitch => "pitch",
                Turn::Yaw => "yaw",
            };
            format!("{b}: {turn} [rad]")
        }
        Quantity::AngularVelocity(b, a) => format!("{b}: angular velocity {} [rad/s]", axis(a)),
        Quantity::Speed(b) => format!("{b}: speed [m/s]"),
        Quantity::AngularSpeed(b) => format!("{b}: angular speed [rad/s]"),
        Quantity::Excursion(b) => format!("{b}: excursion [m]"),
        Quantity::Rotation(b) => format!("{b}: rotation [rad]"),
        Quantity::Energy(part) => {
            let part = match part {
                EnergyPart::Kinetic => "kinetic",
                EnergyPart::Gravity => "gravity",
                EnergyPart::Elastic => "elastic",
                EnergyPart::Dissipated => "dissipated",
                EnergyPart::ExternalWork => "external work",
                EnergyPart::Total => "total",
                EnergyPart::Balance => "balance",
            };
            format!("energy: {part} [J]")
        }
    }
}

/// A ticked knob's bounds and scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    pub from: f64,
    pub to: f64,
    pub log: bool,
}

impl Bounds {
    /// Around `value`: a third of it to three times it (on a log scale when it is > 0); −1 to 1
    /// around 0.
    pub fn around(value: f64) -> Self {
        if value > 0.0 {
            Self { from: value / 3.0, to: value * 3.0, log: true }
        } else if value < 0.0 {
            Self { from: value * 3.0, to: value / 3.0, log: false }
        } else {
            Self { from: -1.0, to: 1.0, log: false }
        }
    }
}

/// The record opened: its path, its columns (not the time column) and the times it spans [s].
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    pub path: PathBuf,
    pub columns: Vec<String>,
    pub span: (f64, f64),
}

/// What the panel asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FitAction {
    /// A file dialog for the record.
    BrowseRecord,
    /// Fit with the choices made.
    Start,
    Stop,
    /// Keep the fitted values (they are running).
    Apply,
    /// The fitted knobs back to the file's values.
    Revert,
}

/// What a fit running asks the panel to do.
#[derive(Debug, Clone, PartialEq)]
pub enum FitUpdate {
    /// The fitted knobs to these values (`(knob, value path, value)`), as edits.
    Values(Vec<(KnobId, String, f64)>),
    /// The model's curves at them, in place of the last ones.
    Curves(Vec<Curve>),
    /// The fit ended: a line for the log (an error when it failed).
    Ended { text: String, error: bool },
}

/// The fit state of each scene opened in the window but the open one, by its file, and which
/// scene the panel's [`FitDraft`] belongs to: each scene's record, columns and ticks are its own.
#[derive(Default)]
pub struct SceneFits {
    owner: Option<PathBuf>,
    others: HashMap<PathBuf, FitDraft>,
}

impl SceneFits {
    /// The panel's `draft` becomes scene `to`'s (of `fittables` and `signals`): a fit running
    /// stops; the draft of the scene it belonged to is kept, and `to`'s own taken back (empty
    /// for a scene not opened before; the same draft for the same file, loaded again). Returns
    /// what of it the scene no longer takes ([`FitDraft::keep_to`]).
    pub fn switch(
        &mut self,
        draft: &mut FitDraft,
        to: &Path,
        fittables: &[Parameter],
        signals: &[Quantity],
    ) -> Vec<String> {
        draft.scene_changed();
        if self.owner.as_deref() != Some(to) {
            let own = self.others.remove(to).unwrap_or_default();
            let previous = std::mem::replace(draft, own);
            if let Some(owner) = self.owner.replace(to.to_path_buf()) {
                self.others.insert(owner, previous);
            }
        }
        draft.keep_to(fittables, signals)
    }
}

/// What became of a fit's values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Decision {
    Kept,
    Reverted,
}

/// What a fit gave: its parameters with their intervals, how it ended, what it cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub parameters: Vec<Fitted>,
    pub ending: Ending,
    pub iterations: u32,
    pub runs: usize,
    pub wall_seconds: f64,
}

/// A fit started from the panel: what it fits, where it is, how it ended.
pub struct Session {
    /// The knobs it fits, in the fit's parameter order (their values at the start).
    pub targets: Vec<Parameter>,
    worker: Option<Worker>,
    /// `(iteration, cost)` of the start and of every accepted iteration.
    pub costs: Vec<(u32, f64)>,
    /// The last iteration heard of.
    pub latest: Option<Progress>,
    /// The values last sent to the knobs.
    applied: Vec<f64>,
    /// How it ended, once it has.
    pub result: Option<Result<Summary, String>>,
    pub decision: Option<Decision>,
}

/// The fit's thread, as the panel holds it; dropping it cancels the fit.
struct Worker {
    cancel: Arc<AtomicBool>,
    events: Receiver<Event>,
}

impl Drop for Worker {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::SeqCst);
    }
}

/// What the fit's thread says.
enum Event {
    /// An iteration, and the model's curves at its values when it was accepted.
    Iteration(Progress, Option<Vec<Curve>>),
    Done(Result<Box<Outcome>, String>),
}

/// The fit panel's state: the record and the choices made, the fit running or done.
#[derive(Default)]
pub struct FitDraft {
    pub record: Option<Measured>,
    /// The model signal of each of the record's columns (`None`: not used).
    pub mapping: Vec<Option<Quantity>>,
    /// The ticked knobs' bounds, by value path.
    pub ticked: BTreeMap<String, Bounds>,
    /// The record's times compared [s].
    pub window: (f64, f64),
    /// Why the last choices could not be fitted, or the record read.
    pub refusal: Option<String>,
    /// A refusal not yet scrolled into view.
    reveal: bool,
    pub session: Option<Session>,
}

impl FitDraft {
    /// Reads the record at `path` (CSV, Parquet, or a Tether recording) in place of the one
    /// open; every column starts unused, the window spans the record.
    ///
    /// # Errors
    /// The file cannot be read, or a value in it is refused (its file and line).
    pub fn open_record(&mut self, path: &Path) -> Result<&Measured, String> {
        let record = Record::read(path, None)?;
        let span = record
            .series
            .iter()
            .filter_map(|s| Some((*s.times.first()?, *s.times.last()?)))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (first, last)| (a.min(first), b.max(last)));
        self.mapping = vec![None; record.series.len()];
        self.window = if span.0 <= span.1 { (span.0.max(0.0), span.1) } else { (0.0, 0.0) };
        self.refusal = None;
        let columns = record.series.into_iter().map(|s| s.name).collect();
        Ok(self.record.insert(Measured { path: path.to_path_buf(), columns, span }))
    }

    /// Ticks knob `fittable` with bounds around its value now, or unticks it.
    pub fn tick(&mut self, fittable: &Parameter, on: bool) {
        if on {
            self.ticked.insert(fittable.path.clone(), Bounds::around(fittable.value));
        } else {
            self.ticked.remove(&fittable.path);
        }
    }

    /// Says why the choices cannot be fitted (or the record read), in view at the next frame.
    pub fn refuse(&mut self, why: String) {
        self.refusal = Some(why);
        self.reveal = true;
    }

    /// Whether a fit is running.
    pub fn running(&self) -> bool {
        self.session.as_ref().is_some_and(|s| s.worker.is_some())
    }

    /// A new scene: a fit running stops; the record, the columns' signals and the ticks stay.
    pub fn scene_changed(&mut self) {
        self.session = None;
    }

    /// The choices the scene of `fittables` and `signals` cannot take dropped: a column mapped
    /// to a signal it lacks goes back to unused, a knob it lacks is unticked. Returns each, said
    /// as the log says it.
    pub fn keep_to(&mut self, fittables: &[Parameter], signals: &[Quantity]) -> Vec<String> {
        let mut dropped = Vec::new();
        let columns = self.record.as_ref().map_or(&[][..], |record| record.columns.as_slice());
        for (column, of) in columns.iter().zip(&mut self.mapping) {
            if let Some(signal) = of.take_if(|signal| !signals.contains(signal)) {
                dropped.push(format!(
                    "fit: column \"{column}\" unmapped ({} is not in this scene)",
                    signal_label(&signal)
                ));
            }
        }
        self.ticked.retain(|path, _| {
            let kept = fittables.iter().any(|f| &f.path == path);
            if !kept {
                dropped.push(format!("fit: {path} unticked (not in this scene)"));
            }
            kept
        });
        dropped
    }

    /// The fit of `open` (the scene as it runs) with the choices made, checked by the fit's
    /// setup, and the knobs it fits; `fittables` are the scene's. Why not, in one line.
    ///
    /// # Errors
    /// No record, no knob ticked, or what the setup refuses (no column mapped, bounds inverted or
    /// refused by the scene loader…).
    pub fn prepare(&self, open: &OpenScene, fittables: &[Parameter]) -> Result<(Setup, Vec<Parameter>), String> {
        let record = self.record.as_ref().ok_or("open a record first")?;
        let targets: Vec<Parameter> = fittables.iter().filter(|f| self.ticked.contains_key(&f.path)).cloned().collect();
        if targets.is_empty() {
            return Err("no knob ticked: tick at least one knob to fit".into());
        }
        let parameters = targets
            .iter()
            .map(|f| {
                let bounds = self.ticked[&f.path];
                ParameterDef {
                    name: Some(f.label.clone()),
                    path: PathsDef::One(f.path.clone()),
                    from: bounds.from,
                    to: bounds.to,
                    scale: if bounds.log { Scale::Log } else { Scale::Linear },
                    start: None,
                }
            })
            .collect();
        let signals: Vec<SignalDef> = record
            .columns
            .iter()
            .zip(&self.mapping)
            .filter_map(|(column, of)| Some(SignalDef { column: column.clone(), of: of.clone()?, weight: None }))
            .collect();
        if signals.is_empty() {
            return Err("no column mapped: choose the model signal of at least one column".into());
        }
        let (scene_path, scene_text) = open.as_run()?;
        let file = FitFile {
            scene: scene_path.display().to_string(),
            record: record.path.display().to_string(),
            time_column: None,
            window: Some(Window { from: self.window.0, to: self.window.1 }),
            signals,
            parameters,
            time_shift: None,
            max_iterations: 50,
        };
        // Made here, not read: a problem is its message alone (no place in a file to show).
        let label = scene_path.with_file_name("fit in the window");
        let setup = Setup::new(&file, &label, "", Some((scene_path, scene_text))).map_err(|e| match e {
            SetupError::Spec(error) => error.message,
            SetupError::File(message) => message,
        })?;
        Ok((setup, targets))
    }

    /// Starts fitting `setup` (of `targets`) on a thread of its own; `wake` repaints when it has
    /// news. Returns the record's series in the window, to draw once.
    ///
    /// # Errors
    /// The thread cannot be started.
    pub fn launch(&mut self, setup: Setup, targets: Vec<Parameter>, wake: Wake) -> Result<Vec<Curve>, String> {
        let measured = setup
            .model
            .signals
            .iter()
            .map(|s| Curve { column: s.column.clone(), times: s.times.clone(), values: s.measured.clone() })
            .collect();
        let cancel = Arc::new(AtomicBool::new(false));
        let (tell, events) = mpsc::channel();
        let flag = Arc::clone(&cancel);
        std::thread::Builder::new()
            .name("fit".into())
            .spawn(move || {
                let runner = Runner::new(all_cores()).with_cancel(flag);
                let send = |event: Event| {
                    // The panel dropped its end: the fit was let go, nobody to tell.
                    if tell.send(event).is_ok() {
                        wake();
                    }
                };
                let outcome = run::fit(&setup, &runner, |progress: &Progress| {
                    let curves = if progress.accepted { model_curves(&setup, &runner, &progress.values) } else { None };
                    send(Event::Iteration(progress.clone(), curves));
                });
                send(Event::Done(outcome.map(Box::new).map_err(|e| e.to_string())));
            })
            .map_err(|e| format!("cannot start the fit's thread: {e}"))?;
        let applied = targets.iter().map(|t| t.value).collect();
        self.session = Some(Session {
            targets,
            worker: Some(Worker { cancel, events }),
            costs: Vec::new(),
            latest: None,
            applied,
            result: None,
            decision: None,
        });
        self.refusal = None;
        Ok(measured)
    }

    /// Stops the fit running: it ends at the best point so far, said to be partial.
    pub fn stop(&self) {
        if let Some(worker) = self.session.as_ref().and_then(|s| s.worker.as_ref()) {
            worker.cancel.store(true, Ordering::SeqCst);
        }
    }

    /// The fit's news since the last call, as what the panel must do.
    pub fn poll(&mut self) -> Vec<FitUpdate> {
        let Some(session) = &mut self.session else { return Vec::new() };
        let mut events = Vec::new();
        if let Some(worker) = &session.worker {
            loop {
                match worker.events.try_recv() {
                    Ok(done @ Event::Done(_)) => {
                        events.push(done);
                        break;
                    }
                    Ok(event) => events.push(event),
                    Err(TryRecvError::Empty) => break,
                    Err(TryRecvError::Disconnected) => {
                        events.push(Event::Done(Err("the fit's thread stopped without a result".into())));
                        break;
                    }
                }
            }
        }
        let mut updates = Vec::new();
        for event in events {
            match event {
                Event::Iteration(progress, curves) => {
                    if progress.accepted {
                        session.costs.push((progress.iteration, progress.cost));
                        updates.extend(session.move_to(&progress.values));
                    }
                    updates.extend(curves.map(FitUpdate::Curves));
                    session.latest = Some(progress);
                }
                Event::Done(result) => {
                    session.worker = None;
                    let (summary, line) = match result {
                        Ok(outcome) => {
                            updates.extend(session.move_to(&outcome.values));
                            let summary = Summary {
                                parameters: outcome.parameters.clone(),
                                ending: outcome.ending,
                                iterations: outcome.iterations.last().map_or(0, |p| p.iteration),
                                runs: outcome.runs,
                                wall_seconds: outcome.wall_seconds,
                            };
                            let line = format!("fit {}: {}", status(&summary), values_line(&summary));
                            (Ok(summary), FitUpdate::Ended { text: line, error: false })
                        }
                        Err(message) => {
                            let line = FitUpdate::Ended { text: format!("the fit failed: {message}"), error: true };
                            (Err(message), line)
                        }
                    };
                    session.result = Some(summary);
                    updates.push(line);
                }
            }
        }
        updates
    }
}

impl Session {
    /// The knobs to `values`, unless they are there already.
    fn move_to(&mut self, values: &[f64]) -> Option<FitUpdate> {
        if values == self.applied.as_slice() {
            return None;
        }
        self.applied = values.to_vec();
        Some(FitUpdate::Values(self.targets.iter().zip(values).map(|(t, v)| (t.knob, t.path.clone(), *v)).collect()))
    }
}

/// The model's curve of each signal at `values`, run on `runner` (a stopped fit stops it), its
/// times moved back by the time shift so that it lies over the record; `None` if the run fails.
fn model_curves(setup: &Setup, runner: &Runner, values: &[f64]) -> Option<Vec<Curve>> {
    let model = &setup.model;
    let trajectory = model.runs(&[values], runner).pop()?.ok()?;
    let shift = model.shift(values);
    let every = trajectory.times.len().div_ceil(CURVE_POINTS).max(1);
    let times: Vec<f64> = trajectory.times.iter().step_by(every).map(|t| t - shift).collect();
    let curves = model
        .signals
        .iter()
        .enumerate()
        .map(|(s, signal)| Curve {
            column: signal.column.clone(),
            times: times.clone(),
            values: trajectory.series(s).into_iter().step_by(every).collect(),
        })
        .collect();
    Some(curves)
}

/// `converged: the cost stopped falling after 6 iterations, 14 runs, 0.8 s`, or `partial: …`.
fn status(summary: &Summary) -> String {
    let why = match summary.ending {
        Ending::CostConverged => "the cost stopped falling",
        Ending::StepConverged => "no step lowers the cost",
        Ending::WithinNoise => "the next step is under a tenth of a standard error",
        Ending::GradientConverged => "the gradient vanished",
        Ending::IterationLimit => "out of iterations",
        Ending::Cancelled => "stopped",
    };
    format!(
        "{}: {why} after {} iterations, {} runs, {:.1} s",
        if summary.ending.converged() { "converged" } else { "partial" },
        summary.iterations,
        summary.runs,
        summary.wall_seconds
    )
}

/// A fitted or fitting value as the panel writes numbers: six significant digits
/// ([`figures::number`]).
fn number(x: f64) -> String {
    figures::number(x, 6)
}

/// `x` in `unit` as the panel writes quantities (`130.002 N/m`, `66.2 kN`), and a pure number
/// bare (`1.60604`, not `1.60604 –`).
fn amount(x: f64, unit: &str) -> String {
    if unit == "–" || unit.is_empty() { number(x) } else { figures::quantity(x, unit, 6) }
}

/// `spring: stiffness k = 130.002 (95 % 129.9 … 130.1)` for each parameter.
fn values_line(summary: &Summary) -> String {
    let each: Vec<String> =
        summary.parameters.iter().map(|p| format!("{} = {}", p.name, interval_text(p, ""))).collect();
    each.join(", ")
}

/// `130.002 (95 % 129.9 … 130.1)`, or `… (not determined by the data)`; with `unit` after the
/// value and each end of the interval when it is given (`130.002 N/m (95 % 129.9 N/m … 130.1
/// N/m)`).
fn interval_text(fitted: &Fitted, unit: &str) -> String {
    let interval = match fitted.interval {
        Some((lo, hi)) => format!("95 % {} … {}", amount(lo, unit), amount(hi, unit)),
        None => "not determined by the data".into(),
    };
    let bound = if fitted.at_bound { ", at a bound" } else { "" };
    format!("{} ({interval}{bound})", amount(fitted.value, unit))
}

/// The knob's other interval, for a residual that is correlated model error (another code's
/// run, a real test; docs/calibration.md, "What the intervals mean"), as the knob's tooltip.
fn correlated_text(fitted: &Fitted, unit: &str) -> String {
    match fitted.correlated_interval {
        Some((lo, hi)) => format!(
            "95 % {} … {} if the residual is correlated model error rather than white noise",
            amount(lo, unit),
            amount(hi, unit)
        ),
        None => "not determined by the data".into(),
    }
}

/// Draws the fit panel for a scene whose fittable values are `fittables` and whose signals are
/// `signals`; returns what it asks for.
pub fn ui(ui: &mut egui::Ui, draft: &mut FitDraft, fittables: &[Parameter], signals: &[Quantity]) -> Vec<FitAction> {
    let mut actions = Vec::new();
    egui::CollapsingHeader::new("Fit to a record").id_salt("fit").default_open(false).show(ui, |ui| {
        let running = draft.running();
        ui.add_enabled_ui(!running, |ui| choices_ui(ui, draft, fittables, signals, &mut actions));
        ui.horizontal_wrapped(|ui| {
            let why_not =
                if running { "a fit is running" } else { "open a record first: the fit compares the run with it" };
            if ui
                .add_enabled(!running && draft.record.is_some(), egui::Button::new("Fit"))
                .on_hover_text("Fit the ticked knobs to the record (tether fit), from their values now")
                .on_disabled_hover_text(why_not)
                .clicked()
            {
                actions.push(FitAction::Start);
            }
            if ui
                .add_enabled(running, egui::Button::new("Stop"))
                .on_hover_text("End the fit at the best values so far")
                .clicked()
            {
                actions.push(FitAction::Stop);
            }
            if draft.record.is_none() {
                ui.weak("open a record (above) to fit");
            }
        });
        if let Some(refusal) = &draft.refusal {
            let text = egui::RichText::new(refusal).color(ui.visuals().error_fg_color);
            let shown = ui.add(egui::Label::new(text).wrap());
            // Where the eye is: the Fit button may sit at the panel's bottom edge.
            if std::mem::take(&mut draft.reveal) {
                shown.scroll_to_me(None);
            }
        }
        if let Some(session) = &draft.session {
            session_ui(ui, session, &mut actions);
        }
    });
    actions
}

/// The record, its columns' signals, the knobs and their bounds, the window.
fn choices_ui(
    ui: &mut egui::Ui,
    draft: &mut FitDraft,
    fittables: &[Parameter],
    signals: &[Quantity],
    actions: &mut Vec<FitAction>,
) {
    ui.horizontal(|ui| {
        if ui.button("Open record…").on_hover_text("A measured record: CSV, Parquet or a Tether recording").clicked()
        {
            actions.push(FitAction::BrowseRecord);
        }
        match &draft.record {
            Some(record) => {
                let name = record.path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
                let summary = format!(
                    "{name}: {} column{}, {} to {}",
                    record.columns.len(),
                    if record.columns.len() == 1 { "" } else { "s" },
                    number(record.span.0),
                    figures::quantity(record.span.1, "s", 6)
                );
                // Wrapped: a long file name must not widen the panel and push the viewer.
                ui.add(egui::Label::new(summary).wrap()).on_hover_text(record.path.display().to_string());
            }
            None => {
                ui.weak("no record");
            }
        }
    });
    if let Some(record) = &draft.record {
        ui.label("Each column is the model signal:");
        for (index, (column, of)) in record.columns.iter().zip(&mut draft.mapping).enumerate() {
            let shown = of.as_ref().map_or_else(|| "not used".to_string(), signal_label);
            // Wrapped: a long column name breaks over lines, its choice goes to the next one.
            ui.horizontal_wrapped(|ui| {
                let name = ui.add(egui::Label::new(column).wrap());
                let choice =
                    egui::ComboBox::from_id_salt(("fit column", index)).selected_text(shown).show_ui(ui, |ui| {
                        ui.selectable_value(&mut *of, None, "not used");
                        for signal in signals {
                            ui.selectable_value(&mut *of, Some(signal.clone()), signal_label(signal));
                        }
                    });
                choice.response.labelled_by(name.id);
            });
        }
    }
    ui.label("Knobs to fit (bounds; the fit starts from the value now):");
    for fittable in fittables {
        let mut on = draft.ticked.contains_key(&fittable.path);
        ui.horizontal(|ui| {
            if ui.checkbox(&mut on, &fittable.label).changed() {
                draft.tick(fittable, on);
            }
            ui.weak(amount(fittable.value, fittable.unit));
        });
        if let Some(bounds) = draft.ticked.get_mut(&fittable.path) {
            ui.horizontal(|ui| {
                ui.add_space(24.0);
                bound(ui, &mut bounds.from, "from", &format!("{} from", fittable.label));
                bound(ui, &mut bounds.to, "to", &format!("{} to", fittable.label));
                ui.label(fittable.unit);
                ui.checkbox(&mut bounds.log, "log").on_hover_text("A log scale, for a value that spans decades");
            });
        }
    }
    ui.horizontal(|ui| {
        ui.label("window");
        bound(ui, &mut draft.window.0, "from", "window from");
        bound(ui, &mut draft.window.1, "to", "window to");
        ui.label("s");
    });
}

/// A bound: a number after `prefix`, named `name` for screen readers (and tests).
fn bound(ui: &mut egui::Ui, value: &mut f64, prefix: &str, name: &str) {
    let speed = value.abs().max(1e-3) * 0.01;
    ui.label(prefix);
    let response = number_field(ui, value, speed);
    ui.ctx().accesskit_node_builder(response.id, |node| node.set_label(name));
}

/// Where the fit is or how it ended; each fitted knob's value and interval; Apply, Revert.
fn session_ui(ui: &mut egui::Ui, session: &Session, actions: &mut Vec<FitAction>) {
    ui.separator();
    match (&session.result, &session.latest) {
        (None, None) => {
            ui.label("fitting: the first runs…");
        }
        (None, Some(latest)) => {
            ui.label(format!(
                "fitting: iteration {}, cost {}, {} runs",
                latest.iteration,
                figures::number(latest.cost, 4),
                latest.runs
            ));
        }
        (Some(Ok(summary)), _) => {
            ui.label(status(summary));
        }
        (Some(Err(message)), _) => {
            ui.colored_label(ui.visuals().error_fg_color, format!("the fit failed: {message}"));
        }
    }
    let fitted = match &session.result {
        Some(Ok(summary)) => Some(&summary.parameters),
        Some(Err(_)) | None => None,
    };
    egui::Grid::new("fit results").num_columns(2).show(ui, |ui| {
        for (index, target) in session.targets.iter().enumerate() {
            ui.label(&target.label);
            match fitted.and_then(|parameters| parameters.get(index)) {
                Some(parameter) => ui
                    .label(interval_text(parameter, target.unit))
                    .on_hover_text(correlated_text(parameter, target.unit)),
                None => {
                    let now = session.applied.get(index).copied().unwrap_or(target.value);
                    ui.label(format!("{} (from {})", amount(now, target.unit), amount(target.value, target.unit)))
                }
            };
            ui.end_row();
        }
    });
    if session.costs.len() > 1 {
        cost_plot(ui, &session.costs);
    }
    if session.result.is_some() {
        match session.decision {
            None => {
                ui.horizontal(|ui| {
                    if ui.button("Apply").on_hover_text("Keep the fitted values (they are running)").clicked() {
                        actions.push(FitAction::Apply);
                    }
                    if ui.button("Revert").on_hover_text("The fitted knobs back to the scene file's values").clicked() {
                        actions.push(FitAction::Revert);
                    }
                });
            }
            Some(Decision::Kept) => {
                ui.weak("kept: the fitted values are the tuned ones (\"Save as…\" writes them)");
            }
            Some(Decision::Reverted) => {
                ui.weak("reverted to the file's values");
            }
        }
    }
}

/// The cost of each accepted iteration, on a log scale, in a framed box.
fn cost_plot(ui: &mut egui::Ui, costs: &[(u32, f64)]) {
    let first = costs.first().map_or(0.0, |c| c.1);
    let last = costs.last().map_or(0.0, |c| c.1);
    ui.label(format!("cost per iteration: {} → {} (log scale)", figures::number(first, 4), figures::number(last, 4)));
    let points: Vec<(f64, f64)> =
        costs.iter().filter(|c| c.1 > 0.0).map(|&(i, cost)| (f64::from(i), cost.log10())).collect();
    let Some(Framed { painter, line, .. }) = line_plot::frame(ui, &points, 80.0) else {
        return;
    };
    let stroke = egui::Stroke::new(2.0, ui.visuals().hyperlink_color);
    for point in &line {
        painter.circle_filled(*point, 2.5, stroke.color);
    }
    painter.add(egui::Shape::line(line, stroke));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A float in waves on a spring, and a dynamic line, with every kind of value fittable.
    const SCENE: &str = r#"Scene(dt: 0.01, water: Water(depth: 30.0, waves: Regular(height: 1.0, period: 6.0), current: Current(speed: 0.5)),
        bodies: [Body(name: "float", master: Node(position: (0.0, 0.0, 0.0), mass: 1025.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
             shape: Box(size: (2.0, 2.0, 1.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0), linear_damping: (0.0, 0.0, 50.0)))],
        couplings: [
            SpringDamper(name: "spring", end1: World((0.0, 0.0, -5.0)), end2: Body(body: "float"),
                law: ForceCurve(points: [(0.0, 0.0), (1.0, 100.0)]), damping: 2.0),
            Catenary(name: "line", end1: World((20.0, 0.0, -30.0)), end2: Body(body: "float"),
                mass_per_length: 50.0, length: 40.0, stiffness: 1e8,
                model: Dynamic(segments: 10, damping: Ratio(0.8), drag_normal: 1.2)),
        ])"#;

    #[test]
    fn bounds_are_prefilled_around_the_value() {
        assert_eq!(Bounds::around(90.0), Bounds { from: 30.0, to: 270.0, log: true });
        assert_eq!(Bounds::around(-3.0), Bounds { from: -9.0, to: -1.0, log: false });
        assert_eq!(Bounds::around(0.0), Bounds { from: -1.0, to: 1.0, log: false });
    }

    #[test]
    fn each_body_and_coupling_offers_its_signals() {
        let file = tether_scene::parse(SCENE, Path::new("float.ron")).unwrap().file;
        let labels: Vec<String> = signals(&file).iter().map(signal_label).collect();
        assert_eq!(labels.len(), 9 + 2 + 4);
        assert_eq!(labels[2], "float: position z [m]");
        assert!(labels.contains(&"line: end 2 tension [N]".to_string()), "{labels:?}");
    }
}
