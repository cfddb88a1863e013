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
//! Here, with no egui: the state ([`FitDraft`]) and the fit's worker thread, whose news the
//! panel takes as [`FitUpdate`]s ([`FitDraft::poll`]). In [`signals`], what a record's column
//! can be; in [`panel`], the egui drawing ([`ui`]), which returns [`FitAction`]s the control
//! panel carries out. What can be fitted is the scene's catalogue ([`tether_analysis::parameters`]).

mod panel;
mod signals;

pub use panel::ui;
pub use signals::{signal_label, signals};

use super::open_scene::OpenScene;
use super::simulation::{Curve, Wake};
use crate::figures;
use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, TryRecvError};
use tether_analysis::fit::measured::Record;
use tether_analysis::fit::run::{self, Fitted, Outcome, Progress};
use tether_analysis::fit::setup::{Setup, SetupError};
use tether_analysis::fit::solver::Ending;
use tether_analysis::fit::spec::{FitFile, ParameterDef, Scale, SignalDef, Window};
use tether_analysis::parameters::{KnobId, Parameter};
use tether_analysis::quantity::Quantity;
use tether_analysis::runner::{Runner, all_cores};
use tether_analysis::spec_text::PathsDef;

/// Points of a model curve sent to the viewer at most (a run's every world step, thinned).
const CURVE_POINTS: usize = 4000;

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_prefilled_around_the_value() {
        assert_eq!(Bounds::around(90.0), Bounds { from: 30.0, to: 270.0, log: true });
        assert_eq!(Bounds::around(-3.0), Bounds { from: -9.0, to: -1.0, log: false });
        assert_eq!(Bounds::around(0.0), Bounds { from: -1.0, to: 1.0, log: false });
    }
}
