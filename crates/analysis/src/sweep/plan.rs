//! A sweep's plan: the spec read, the base scene loaded, each factor's paths found in the
//! scene's data, the design's cases and the metrics — everything checked before any case runs.
//!
//! A case's scene is the base scene's data with the case's values written at the factors'
//! paths, read back into a [`SceneFile`] and built by the scene loader, with the loader's checks
//! and messages (placed in the base scene's text). [`Plan::check_factors`] builds the base with
//! each factor's values one at a time, so that a value the loader refuses is named with its
//! factor; [`Plan::check_cases`] builds every case to run, so that a combination it refuses is
//! named with its case — both before anything runs, each stopping at a Ctrl-C or SIGTERM.

use super::design::Cases;
use super::error::{Stage, SweepError, unless_cancelled};
use super::factor::{Factor, Values};
use super::metrics::{Metric, MetricDef, RefusedMetric};
use super::spec::{Design, Level, SpecFile};
use super::table::{CASE_COLUMN, Columns, FactorColumn, MetricColumn, OUTCOME_COLUMNS};
use crate::runner::Runner;
use crate::spec_text::SpecText;
use serde_json::Value;
use std::path::{Path, PathBuf};
use tether_physics::parameter::{Bound, require};
use tether_scene::{Scene, SceneError, SceneFile};

/// A sweep, ready to run.
pub struct Plan {
    /// The sweep's name (recordings' application id).
    pub name: String,
    pub spec_path: PathBuf,
    pub spec_text: String,
    pub scene_path: PathBuf,
    pub scene_text: String,
    /// The base scene's data, the spec's duration written in.
    base: Value,
    pub factors: Vec<Factor>,
    pub design: Design,
    pub cases: Cases,
    pub metrics: Vec<Metric>,
    /// Fraction of the largest distance from the end position that counts as settled.
    pub settle_band: f64,
    /// The base scene's body and coupling names, which a case must keep (metrics use them).
    names: Vec<String>,
}

impl Plan {
    /// Reads the spec at `spec_path` and its base scene; the sweep may have at most
    /// `max_cases` cases ([`super::design::DEFAULT_MAX_CASES`] unless the user says otherwise),
    /// counted before any is made.
    ///
    /// # Errors
    /// A spec or scene that cannot be read or is wrong, or a sweep of more cases than
    /// `max_cases` (with its size), placed `path:line:col`.
    pub fn load(spec_path: &Path, max_cases: usize) -> Result<Self, SweepError> {
        let spec_text = std::fs::read_to_string(spec_path).map_err(|e| SweepError::Io {
            path: spec_path.display().to_string(),
            message: format!("cannot read the sweep spec: {e}"),
        })?;
        Self::read(spec_path, spec_text, None, max_cases)
    }

    /// The plan of a sweep directory's copy of its spec `spec_text` (read from `spec_path`) and
    /// of its base scene `scene` (path and text), or of the scene the spec names: no limit on
    /// its size, which was accepted when it ran.
    ///
    /// # Errors
    /// As [`Plan::load`].
    pub fn from_text(
        spec_path: &Path,
        spec_text: String,
        scene: Option<(PathBuf, String)>,
    ) -> Result<Self, SweepError> {
        Self::read(spec_path, spec_text, scene, usize::MAX)
    }

    fn read(
        spec_path: &Path,
        spec_text: String,
        scene: Option<(PathBuf, String)>,
        max_cases: usize,
    ) -> Result<Self, SweepError> {
        let spec = SpecText { path: spec_path, text: &spec_text };
        let file: SpecFile = spec.parse()?;
        let (scene_path, scene_text) = match scene {
            Some(given) => given,
            None => {
                let path = spec_path.parent().unwrap_or(Path::new(".")).join(&file.scene);
                let text = std::fs::read_to_string(&path).map_err(|e| {
                    spec.error_at(&file.scene, "scene", format!("cannot read the scene {}: {e}", path.display()))
                })?;
                (path, text)
            }
        };
        let scene = tether_scene::parse(&scene_text, &scene_path)?;
        let mut base = serde_json::to_value(&scene.file)
            .map_err(|e| spec.error_at(&file.scene, "scene", format!("the scene's data cannot be addressed: {e}")))?;
        if let Some(duration) = file.duration {
            // The rule and message of the scene file's own duration (its one owner).
            let duration = require("duration", duration, Bound::Positive, "s")
                .map_err(|refused| spec.error_at("", "duration", refused.to_string()))?;
            base["duration"] = Value::from(duration);
        }
        let name = file.name.clone().unwrap_or_else(|| {
            spec_path.file_stem().map_or_else(|| "sweep".into(), |s| s.to_string_lossy().into_owned())
        });
        if name.is_empty() || !name.chars().all(|c| c.is_alphanumeric() || "-_".contains(c)) {
            return Err(spec.error_at(&name, "name", format!("the sweep's name \"{name}\" must be letters, digits, - and _ (it names the recordings' application)")).into());
        }
        let factors =
            file.factors.iter().map(|def| Factor::new(def, &base, &spec, max_cases)).collect::<Result<Vec<_>, _>>()?;
        let cases =
            Cases::new(&file.design, &factors, max_cases).map_err(|message| spec.error_at("", "design", message))?;
        require("settle_band", file.settle_band, Bound::OpenUnit, "")
            .map_err(|refused| spec.error_at("", "settle_band", refused.to_string()))?;
        let metrics = Metric::all(&scene.world, file.standard_metrics, &file.metrics).map_err(
            |RefusedMetric { name, message }| spec.error_at(&name, "metrics", format!("metric \"{name}\": {message}")),
        )?;
        check_names(&factors, &metrics, &file.metrics, &spec)?;
        let names = names(&scene);
        Ok(Self {
            name,
            spec_path: spec_path.to_path_buf(),
            spec_text,
            scene_path,
            scene_text,
            base,
            factors,
            design: file.design,
            cases,
            metrics,
            settle_band: file.settle_band,
            names,
        })
    }

    /// The factors' values in case `case`.
    pub fn values(&self, case: usize) -> Vec<Level> {
        self.cases.values(case, &self.factors)
    }

    /// The scene file of the base with `values` written at the factors' paths.
    ///
    /// # Errors
    /// The loader's reading of the data: a value of the wrong type, an unknown field.
    pub fn scene_file(&self, values: &[Level]) -> Result<SceneFile, String> {
        let mut tree = self.base.clone();
        for (factor, level) in self.factors.iter().zip(values) {
            factor.set(&mut tree, level);
        }
        serde_json::from_value(tree).map_err(|e| e.to_string())
    }

    /// The scene of the base with `values`, built by the scene loader.
    ///
    /// # Errors
    /// What the loader refuses (`scene.ron:line:col: message`, placed in the base scene), or
    /// values that rename a body or coupling.
    pub fn scene(&self, values: &[Level]) -> Result<Scene, String> {
        let file = self.scene_file(values)?;
        let scene = tether_scene::build_variant(&self.scene_text, &self.scene_path, file)
            .map_err(|e: SceneError| e.to_string())?;
        if names(&scene) != self.names {
            return Err("the values rename a body or a coupling: a sweep changes values, not names".into());
        }
        Ok(scene)
    }

    /// Builds the base scene with each value of each factor alone (a range: its two ends),
    /// until `runner` is cancelled.
    ///
    /// # Errors
    /// The first value the loader refuses, placed at its factor in the spec; the run cancelled
    /// (checked before each value).
    pub fn check_factors(&self, runner: &Runner) -> Result<(), SweepError> {
        let spec = SpecText { path: &self.spec_path, text: &self.spec_text };
        for factor in &self.factors {
            let levels = match &factor.values {
                Values::Levels(levels) => levels.clone(),
                Values::Range { from, to, .. } => vec![Level::Number(*from), Level::Number(*to)],
            };
            for level in levels {
                unless_cancelled(runner, Stage::Checking)?;
                // The other factors as the base scene has them.
                let mut tree = self.base.clone();
                factor.set(&mut tree, &level);
                let checked = serde_json::from_value::<SceneFile>(tree).map_err(|e| e.to_string()).and_then(|file| {
                    tether_scene::build_variant(&self.scene_text, &self.scene_path, file)
                        .map(drop)
                        .map_err(|e| e.to_string())
                });
                if let Err(message) = checked {
                    let first = factor.paths.first().map_or("", |p| p.text.as_str());
                    return Err(spec
                        .error_after(first, "values", format!("factor `{}` = {level}: {message}", factor.name))
                        .into());
                }
            }
        }
        Ok(())
    }

    /// Builds the scene of every case in `cases` on `runner`'s threads.
    ///
    /// # Errors
    /// A case the loader refuses, with its values ([`SweepError::Case`]); the run cancelled.
    pub fn check_cases(&self, runner: &Runner, cases: impl Iterator<Item = usize> + Send) -> Result<(), SweepError> {
        runner.run(
            cases,
            |&case, _| self.scene(&self.values(case)).err(),
            |case, refused| match refused {
                None => Ok(()),
                Some(message) => Err(SweepError::Case { case, values: self.describe(case), message }),
            },
        )?;
        unless_cancelled(runner, Stage::Checking)
    }

    /// `couplings.mooring1.stiffness = 5000000, integrator = rk4`.
    pub fn describe(&self, case: usize) -> String {
        let values = self.values(case);
        let pairs: Vec<String> = self.factors.iter().zip(&values).map(|(f, v)| format!("{} = {v}", f.name)).collect();
        pairs.join(", ")
    }

    /// The results' columns.
    pub fn columns(&self) -> Columns {
        Columns {
            factors: self
                .factors
                .iter()
                .map(|f| FactorColumn { name: f.name.clone(), kind: f.kind(), log: f.logarithmic() })
                .collect(),
            metrics: self
                .metrics
                .iter()
                .map(|m| MetricColumn { name: m.name.clone(), unit: m.unit.to_string() })
                .collect(),
        }
    }
}

/// Body and coupling names of a scene, in order.
fn names(scene: &Scene) -> Vec<String> {
    scene
        .world
        .bodies()
        .iter()
        .map(|b| b.name.clone())
        .chain(scene.world.couplings().iter().map(|c| c.name.clone()))
        .collect()
}

/// Every column name once: factors, the outcome's columns, metrics.
fn check_names(
    factors: &[Factor],
    metrics: &[Metric],
    declared: &[MetricDef],
    spec: &SpecText<'_>,
) -> Result<(), SweepError> {
    let mut seen: Vec<&str> = vec![CASE_COLUMN];
    seen.extend(OUTCOME_COLUMNS);
    for factor in factors {
        if seen.contains(&factor.name.as_str()) {
            let first = factor.paths.first().map_or(factor.name.as_str(), |p| p.text.as_str());
            return Err(spec
                .error_at(
                    first,
                    "factors",
                    format!("factor `{}`: the results already have a column of that name", factor.name),
                )
                .into());
        }
        seen.push(&factor.name);
    }
    for metric in metrics {
        let is_declared = declared.iter().any(|d| d.name == metric.name);
        if metric.name.is_empty() || seen.contains(&metric.name.as_str()) {
            let message = if is_declared {
                format!("metric \"{}\": the results already have a column of that name", metric.name)
            } else {
                format!("the standard metric {} has the name of another column", metric.name)
            };
            return Err(spec.error_at(&metric.name, "metrics", message).into());
        }
        seen.push(&metric.name);
    }
    Ok(())
}
