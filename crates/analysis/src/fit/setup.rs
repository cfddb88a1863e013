//! A fit made ready: the spec read, its scene and record loaded, every name, path, bound and
//! weight checked against them before any run (docs/calibration.md, "The spec"). Each problem is
//! one line placed in the spec (`fit.ron:line:col: …`), or naming the record's file and line.

use super::measured::Record;
use super::model::{Model, Signal};
use super::parameter::{Parameter, Target};
use super::series::Series;
use super::spec::{FitFile, Window};
use crate::quantity::Probe;
use crate::spec_text::{SpecError, SpecText};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Why a fit cannot run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SetupError {
    /// A problem placed in the spec file.
    #[error(transparent)]
    Spec(#[from] SpecError),
    /// The scene, or the record, cannot be read (the message names the file and line).
    #[error("{0}")]
    File(String),
}

/// Everything a fit needs, checked.
#[derive(Debug, Clone)]
pub struct Setup {
    pub spec_path: PathBuf,
    pub spec_text: String,
    pub record_path: PathBuf,
    pub model: Model,
    pub max_iterations: u32,
}

impl Setup {
    /// Reads the spec at `spec_path`, its scene and its record.
    ///
    /// # Errors
    /// See [`SetupError`].
    pub fn load(spec_path: &Path) -> Result<Self, SetupError> {
        let spec_text = std::fs::read_to_string(spec_path)
            .map_err(|e| SetupError::File(format!("{}: cannot read the fit spec: {e}", spec_path.display())))?;
        Self::from_text(spec_path, &spec_text)
    }

    /// The fit spec `spec_text`, labelled `spec_path` in messages; the paths in it are relative
    /// to `spec_path`'s folder (a spec made in Python or the window, not read from a file).
    ///
    /// # Errors
    /// See [`SetupError`].
    pub fn from_text(spec_path: &Path, spec_text: &str) -> Result<Self, SetupError> {
        let spec = SpecText { path: spec_path, text: spec_text };
        let file: FitFile = spec.parse()?;
        Self::new(&file, spec_path, spec_text, None)
    }

    /// The fit `file` (whose text, for placing problems, is `spec_text` at `spec_path`; paths in
    /// it are relative to `spec_path`'s folder). `scene` gives the scene's path and text when
    /// the caller holds them (the window's scene), else the file's scene is read.
    ///
    /// # Errors
    /// See [`SetupError`].
    pub fn new(
        file: &FitFile,
        spec_path: &Path,
        spec_text: &str,
        scene: Option<(PathBuf, String)>,
    ) -> Result<Self, SetupError> {
        let spec = SpecText { path: spec_path, text: spec_text };
        let directory = spec_path.parent().unwrap_or(Path::new("."));
        let (scene_path, scene_text) = match scene {
            Some(given) => given,
            None => {
                let path = directory.join(&file.scene);
                let text = std::fs::read_to_string(&path).map_err(|e| {
                    spec.error_at(&file.scene, "scene", format!("cannot read the scene {}: {e}", path.display()))
                })?;
                (path, text)
            }
        };
        let scene = tether_scene::parse(&scene_text, &scene_path).map_err(|e| SetupError::File(e.to_string()))?;
        let mut base = serde_json::to_value(&scene.file)
            .map_err(|e| spec.error_at(&file.scene, "scene", format!("the scene's data cannot be addressed: {e}")))?;
        let record_path = directory.join(&file.record);
        if !record_path.is_file() {
            return Err(spec
                .error_at(&file.record, "record", format!("no record file {}", record_path.display()))
                .into());
        }
        let record = Record::read(&record_path, file.time_column.as_deref()).map_err(SetupError::File)?;
        let mut parameters = Vec::new();
        for def in &file.parameters {
            let first = def.path.paths().first().map_or("", String::as_str);
            let parameter = Parameter::new(def, &base).map_err(|m| spec.error_at(first, "parameters", m))?;
            check_values(&parameter, &base, &scene_text, &scene_path)
                .map_err(|m| spec.error_after(first, "from", m))?;
            parameters.push(parameter);
        }
        if let Some(shift) = &file.time_shift {
            parameters.push(Parameter::time_shift(shift).map_err(|m| spec.error_at("", "time_shift", m))?);
        }
        if parameters.is_empty() {
            return Err(spec.error_at("", "parameters", "no parameter to fit: name at least one").into());
        }
        let names: Vec<&str> = parameters.iter().map(|p| p.name.as_str()).collect();
        if let Some(twice) = names.iter().enumerate().find(|(i, n)| names[..*i].contains(n)).map(|(_, n)| *n) {
            return Err(spec.error_at(twice, "parameters", format!("parameter `{twice}` is fitted twice")).into());
        }
        let (shift_from, shift_to) =
            parameters.iter().find(|p| p.target == Target::TimeShift).map_or((0.0, 0.0), |p| (p.from, p.to));
        let columns = file
            .signals
            .iter()
            .map(|def| record.series(&def.column).map_err(|m| spec.error_at(&def.column, "signals", m)))
            .collect::<Result<Vec<_>, _>>()?;
        let window = window(file.window, &columns, scene.file.duration, shift_from)
            .map_err(|m| spec.error_at("", if file.window.is_some() { "window" } else { "record" }, m))?;
        let mut signals = Vec::new();
        for (def, series) in file.signals.iter().zip(&columns) {
            // The signal names what the scene has (the model's run finds it again).
            Probe::find(&scene.world, &def.of)
                .map_err(|m| spec.error_after(&def.column, "of", format!("signal \"{}\": {m}", def.column)))?;
            let (times, measured): (Vec<f64>, Vec<f64>) = series
                .times
                .iter()
                .zip(&series.values)
                .filter(|(t, _)| **t >= window.from && **t <= window.to)
                .map(|(t, v)| (*t, *v))
                .unzip();
            if times.len() < 2 {
                let message = format!(
                    "signal \"{}\" has {} sample(s) in the window {} to {} s: nothing to fit to",
                    def.column,
                    times.len(),
                    window.from,
                    window.to
                );
                return Err(spec.error_at(&def.column, "signals", message).into());
            }
            let spread = spread(&def.column, &times, &measured)
                .map_err(|m| SetupError::File(format!("{}: {m}", record_path.display())))?;
            let weight = weight(def.weight, spread)
                .map_err(|m| spec.error_after(&def.column, "weight", format!("signal \"{}\": {m}", def.column)))?;
            signals.push(Signal {
                column: def.column.clone(),
                quantity: def.of.clone(),
                unit: def.of.unit(),
                weight,
                times,
                measured,
            });
        }
        if signals.is_empty() {
            return Err(spec.error_at("", "signals", "no signal to fit to: map at least one column").into());
        }
        let samples: usize = signals.iter().map(|s| s.times.len()).sum();
        if samples <= parameters.len() {
            let message = format!("{samples} samples cannot fit {} parameters", parameters.len());
            return Err(spec.error_at("", "signals", message).into());
        }
        let end_time = window.to + shift_to.max(0.0);
        base["duration"] = Value::from(end_time.max(scene.file.dt));
        let model = Model { scene_path, scene_text, base, parameters, signals, end_time };
        Ok(Self {
            spec_path: spec_path.to_path_buf(),
            spec_text: spec_text.to_string(),
            record_path,
            model,
            max_iterations: file.max_iterations,
        })
    }

    /// The start values of the parameters.
    pub fn start(&self) -> Vec<f64> {
        self.model.parameters.iter().map(|p| p.start).collect()
    }
}

/// The scene loader's word on each parameter's bounds and start (its validation owns the
/// knob's valid range).
fn check_values(parameter: &Parameter, base: &Value, scene_text: &str, scene_path: &Path) -> Result<(), String> {
    for (label, value) in [("from", parameter.from), ("to", parameter.to), ("start", parameter.start)] {
        let mut tree = base.clone();
        parameter.set(&mut tree, value);
        let built =
            serde_json::from_value::<tether_scene::SceneFile>(tree).map_err(|e| e.to_string()).and_then(|file| {
                tether_scene::build_variant(scene_text, scene_path, file).map(drop).map_err(|e| e.to_string())
            });
        if let Err(message) = built {
            return Err(format!("parameter `{}` {label} = {value}: {message}", parameter.name));
        }
    }
    Ok(())
}

/// The record's times compared: `given`, or every time of the signals' `columns` the scene's run
/// (0 to `duration`) covers; `shift_from` (≤ 0 moves the model earlier) must not reach before
/// t = 0.
fn window(given: Option<Window>, columns: &[&Series], duration: f64, shift_from: f64) -> Result<Window, String> {
    let (first, last) = columns
        .iter()
        .filter_map(|s| Some((*s.times.first()?, *s.times.last()?)))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (f, l)| (a.min(f), b.max(l)));
    let window = match given {
        Some(w) => {
            if !(w.from.is_finite() && w.to.is_finite() && w.from < w.to && w.from >= 0.0) {
                return Err(format!("the window must run forwards from t ≥ 0 s, got {} to {} s", w.from, w.to));
            }
            w
        }
        None => Window { from: first.max(-shift_from.min(0.0)).max(0.0), to: last.min(duration) },
    };
    if !(window.from < window.to) || window.to < first || window.from > last {
        return Err(format!(
            "no time overlap: the record spans {first} to {last} s, the model runs 0 to {} s{}",
            if given.is_some() { window.to } else { duration },
            if given.is_some() { format!(", the window is {} to {} s", window.from, window.to) } else { String::new() }
        ));
    }
    if window.from + shift_from < 0.0 {
        return Err(format!(
            "the time shift may reach {shift_from} s, before the model's t = 0 at the window's start {} s: start the window at {} s or later",
            window.from, -shift_from
        ));
    }
    Ok(window)
}

/// The mean and the standard deviation `σ = √(Σ (y − ȳ)²/n)` of the samples `measured` of
/// column `column` (at `times` \[s]), the weight's scale (docs/calibration.md, "The spec"), with
/// σ finite: a sample far enough from the others (10³⁰⁸ among tensions of 10⁵ N) overflows σ² and
/// would weigh the column by 0 and make its residuals infinite.
///
/// # Errors
/// A σ that is not finite, naming the column and the row (its time) of the sample farthest from
/// the mean (from 0 when the mean overflows too).
fn spread(column: &str, times: &[f64], measured: &[f64]) -> Result<(f64, f64), String> {
    let n = measured.len() as f64;
    let mean = measured.iter().sum::<f64>() / n;
    let deviation = (measured.iter().map(|y| (y - mean).powi(2)).sum::<f64>() / n).sqrt();
    if deviation.is_finite() {
        return Ok((mean, deviation));
    }
    let centre = if mean.is_finite() { mean } else { 0.0 };
    let distance = |y: f64| (y - centre).abs();
    let farthest = times.iter().zip(measured).max_by(|a, b| distance(*a.1).total_cmp(&distance(*b.1)));
    let (time, value) = farthest.map_or((f64::NAN, f64::NAN), |(t, y)| (*t, *y));
    Err(format!(
        "column \"{column}\", row at t = {time} s: the value {value:e} makes the column's standard deviation {deviation} (a weight of 1/σ = 0 and residuals that overflow): is its exponent mistyped?"
    ))
}

/// A signal's weight: `given` (finite, > 0), or 1 / the standard deviation of its samples, whose
/// `(mean, σ)` is `spread` ([`spread`]).
fn weight(given: Option<f64>, spread: (f64, f64)) -> Result<f64, String> {
    let (mean, deviation) = spread;
    match given {
        Some(w) if w.is_finite() && w > 0.0 => Ok(w),
        Some(w) => Err(format!("weight must be a finite number > 0, got {w}")),
        None if deviation > 0.0 => Ok(1.0 / deviation),
        None => Err(format!("the column is constant ({mean}) in the window: give it a `weight`")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 48: a record with one sample of 10³⁰⁸ was fitted with weight 0 and an RMS of inf; it
    /// is refused, naming the column and the row; the same column without it keeps its σ.
    #[test]
    fn a_sample_that_overflows_the_standard_deviation_is_refused_by_column_and_row() {
        let times = [0.0, 0.05, 0.1, 0.15];
        let (mean, deviation) = spread("F", &times, &[41166.0, 95606.0, 91057.0, 80384.0]).unwrap();
        assert!((mean - 77053.25).abs() < 1e-9 && (deviation / 21443.52 - 1.0).abs() < 1e-6, "{mean} {deviation}");
        assert_eq!(weight(None, (mean, deviation)), Ok(1.0 / deviation));
        let refused = spread("fairlead_tension_N", &times, &[41166.0, 1e308, 91057.0, 80384.0]).unwrap_err();
        assert_eq!(
            refused,
            "column \"fairlead_tension_N\", row at t = 0.05 s: the value 1e308 makes the column's standard deviation inf (a weight of 1/σ = 0 and residuals that overflow): is its exponent mistyped?"
        );
        // Two such samples overflow the mean as well: the largest is named.
        let refused = spread("F", &times, &[1e308, 1.7e308, 91057.0, 80384.0]).unwrap_err();
        assert!(refused.contains("row at t = 0.05 s: the value 1.7e308"), "{refused}");
        assert!(weight(None, (5.0, 0.0)).unwrap_err().contains("constant (5)"));
    }

    /// The same through the fit's setup: one line, the record's path, the column and the row.
    #[test]
    fn a_record_with_a_sample_of_1e308_is_refused_in_one_line() {
        let dir = tempfile::tempdir().unwrap();
        let record = dir.path().join("x.csv");
        std::fs::write(&record, "t,x\n0.0,0.01\n0.5,1e308\n1.0,-0.005\n1.5,0.003\n").unwrap();
        let scene = tether_test_support::repo("scenes/spring_mass.ron");
        let spec = format!(
            r#"Fit(scene: "{}", record: "x.csv", signals: [Signal(column: "x", of: Position("mass", X))],
                parameters: [Parameter(path: "couplings.spring.law.stiffness", from: 50.0, to: 200.0)])"#,
            scene.display()
        );
        let error = Setup::from_text(&dir.path().join("fit.ron"), &spec).map(drop).unwrap_err().to_string();
        assert_eq!(
            error,
            format!(
                "{}: column \"x\", row at t = 0.5 s: the value 1e308 makes the column's standard deviation inf (a weight of 1/σ = 0 and residuals that overflow): is its exponent mistyped?",
                record.display()
            )
        );
    }
}
