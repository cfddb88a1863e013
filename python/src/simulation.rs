//! `tether.Simulation`: a loaded scene and its world (MuJoCo's model and data in one object, as
//! MoorPy's `System`): load, parameters, step, run, statics, record.

use crate::advance::advance;
use crate::errors::{finite, guarded, runtime_error, value_error};
use crate::samples::Samples;
use crate::{parameters, record, statics};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::path::PathBuf;
use tether_record::FrameSchedule;
use tether_scene::Scene;

/// A run may take at most this many steps (10¹² steps of the cheapest scene are a day of CPU).
pub const MAX_STEPS: f64 = 1e12;

/// A run's samples may take at most this many bytes.
const MAX_SAMPLE_BYTES: f64 = 8.0 * 1024.0 * 1024.0 * 1024.0;

/// A scene and its world.
#[pyclass(module = "tether._tether")]
pub struct Simulation {
    pub(crate) scene: Scene,
}

impl Simulation {
    /// The number of world steps a run of `duration` seconds takes (as `tether record` counts
    /// them), checked.
    pub(crate) fn steps_for(&self, duration: f64) -> PyResult<u64> {
        let duration = finite("duration", duration)?;
        if duration <= 0.0 {
            return Err(value_error(format!("`duration` must be a positive number of seconds, got {duration}")));
        }
        let dt = self.scene.world.dt();
        let steps = (duration / dt).round().max(1.0);
        if steps > MAX_STEPS {
            return Err(value_error(format!(
                "`duration` {duration} s is {steps:.3e} steps of dt = {dt} s, more than the {MAX_STEPS:.0e} a run may take"
            )));
        }
        // Below 10¹² a float holds the count exactly.
        Ok(steps as u64)
    }

    /// A sample rate [1/s], checked against the step rate.
    pub(crate) fn rate(&self, name: &str, rate: f64) -> PyResult<f64> {
        let rate = finite(name, rate)?;
        let dt = self.scene.world.dt();
        if rate <= 0.0 {
            return Err(value_error(format!("`{name}` must be a positive number of samples per second, got {rate}")));
        }
        if rate * dt > 1.0 + 1e-9 {
            return Err(value_error(format!(
                "`{name}` {rate} per second is above the step rate {:.6} per second (dt = {dt} s): sample at most once a step",
                1.0 / dt
            )));
        }
        Ok(rate)
    }
}

#[pymethods]
impl Simulation {
    /// Loads the scene file at `path`.
    #[staticmethod]
    fn load(path: PathBuf) -> PyResult<Self> {
        guarded(|| tether_scene::load(&path).map(|scene| Self { scene }).map_err(value_error))
    }

    /// Loads a scene from RON `text`; `path` labels its errors and locates its mesh files.
    #[staticmethod]
    #[pyo3(signature = (text, path = PathBuf::from("<string>")))]
    fn from_ron(text: &str, path: PathBuf) -> PyResult<Self> {
        guarded(|| tether_scene::parse(text, &path).map(|scene| Self { scene }).map_err(value_error))
    }

    #[getter]
    fn path(&self) -> PathBuf {
        self.scene.path.clone()
    }

    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.scene.warnings.clone()
    }

    #[getter]
    fn bodies(&self) -> Vec<String> {
        self.scene.world.bodies().iter().map(|b| b.name.clone()).collect()
    }

    #[getter]
    fn couplings(&self) -> Vec<String> {
        self.scene.world.couplings().iter().map(|c| c.name.clone()).collect()
    }

    #[getter]
    fn coupling_kinds(&self) -> Vec<String> {
        self.scene.world.couplings().iter().map(|c| c.kind_name().to_string()).collect()
    }

    #[getter]
    fn time(&self) -> f64 {
        self.scene.world.time()
    }

    #[getter]
    fn dt(&self) -> f64 {
        self.scene.world.dt()
    }

    #[getter]
    fn duration(&self) -> f64 {
        self.scene.file.duration
    }

    #[getter]
    fn step_count(&self) -> u64 {
        self.scene.world.steps()
    }

    /// The value at a sweep parameter path (`None`: left to the loader's default).
    fn get<'py>(&self, py: Python<'py>, path: &str) -> PyResult<Bound<'py, PyAny>> {
        guarded(|| parameters::get(py, &self.scene, path))
    }

    /// Every tunable number of the scene (`tether_analysis::parameters`, the window's catalogue): its
    /// path, label, unit and value, one dict each.
    fn parameters<'py>(&self, py: Python<'py>) -> PyResult<Vec<Bound<'py, PyDict>>> {
        tether_analysis::parameters::parameters(&self.scene.file)
            .into_iter()
            .map(|parameter| {
                let entry = PyDict::new(py);
                entry.set_item("path", parameter.path)?;
                entry.set_item("label", parameter.label)?;
                entry.set_item("unit", parameter.unit)?;
                entry.set_item("value", parameter.value)?;
                Ok(entry)
            })
            .collect()
    }

    /// Sets the value at a sweep parameter path; the scene is built again (t = 0).
    fn set(&mut self, path: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        guarded(|| {
            let value = parameters::data(path, value)?;
            self.scene = parameters::set(&self.scene, path, value)?;
            Ok(())
        })
    }

    /// The scene as RON text (the loader reads it back to the same scene).
    fn to_ron(&self) -> PyResult<String> {
        tether_scene::to_ron(&self.scene.file).map_err(value_error)
    }

    /// Back to t = 0 with the scene's initial state.
    fn reset(&mut self) -> PyResult<()> {
        guarded(|| self.scene.world.reset().map_err(runtime_error))
    }

    /// Advances `n` world steps.
    #[pyo3(signature = (n = 1))]
    fn step(&mut self, py: Python<'_>, n: u64) -> PyResult<()> {
        if n == 1 {
            // The one-step call's fixed cost is the figure to keep small: no slicing.
            return guarded(|| self.scene.world.step().map_err(runtime_error));
        }
        guarded(|| advance(py, &mut self.scene.world, n, |_, _| {}))
    }

    /// Runs `duration` seconds, sampling `rate` times per simulated second (None: every step);
    /// `{name: (bytes, shape)}` of float64 columns, the first sample the state at the start.
    #[pyo3(signature = (duration, rate = None))]
    fn _run<'py>(&mut self, py: Python<'py>, duration: f64, rate: Option<f64>) -> PyResult<Bound<'py, PyDict>> {
        guarded(|| {
            let steps = self.steps_for(duration)?;
            let dt = self.scene.world.dt();
            let rate = match rate {
                Some(rate) => self.rate("rate", rate)?,
                None => 1.0 / dt,
            };
            let world = &self.scene.world;
            let expected = (steps as f64 * (rate * dt).min(1.0)).ceil() + 2.0;
            let per_sample = Samples::bytes_per_sample(world.bodies().len(), world.couplings().len());
            if expected * per_sample as f64 > MAX_SAMPLE_BYTES {
                return Err(value_error(format!(
                    "{expected:.3e} samples of {per_sample} bytes would take more than {:.0} GiB: lower `rate` or `duration`",
                    MAX_SAMPLE_BYTES / 1024f64.powi(3)
                )));
            }
            let mut samples = Samples::new(world, expected as usize);
            samples.push(world);
            let schedule = FrameSchedule::new(rate, dt, steps);
            advance(py, &mut self.scene.world, steps, |step, world| {
                if schedule.is_due(step) {
                    samples.push(world);
                }
            })?;
            samples.into_dict(py)
        })
    }

    /// The static equilibrium from the scene's initial poses, as `tether equilibrium --json`.
    fn _equilibrium_json(&self, py: Python<'_>) -> PyResult<String> {
        guarded(|| statics::equilibrium_json(py, &self.scene))
    }

    /// The offset curve of `body` along `direction` to `to`, as `tether offsets` tabulates it.
    fn _offsets(&self, py: Python<'_>, body: &str, direction: &str, to: f64, steps: u32) -> PyResult<statics::Columns> {
        guarded(|| statics::offsets(py, &self.scene, body, direction, to, steps))
    }

    /// Runs `duration` seconds (None: the scene's) and records them to the `.rrd` file `path`
    /// at `log_hz` frames per simulated second.
    #[pyo3(signature = (path, duration = None, log_hz = 60.0))]
    fn record(&mut self, py: Python<'_>, path: PathBuf, duration: Option<f64>, log_hz: f64) -> PyResult<()> {
        guarded(|| {
            let steps = self.steps_for(duration.unwrap_or(self.scene.file.duration))?;
            let log_hz = self.rate("log_hz", log_hz)?;
            record::record(py, &mut self.scene.world, &path, steps, log_hz)
        })
    }

    fn __repr__(&self) -> String {
        format!(
            "Simulation({:?}: {} bodies, {} couplings, t = {} s)",
            self.scene.path.display().to_string(),
            self.scene.world.bodies().len(),
            self.scene.world.couplings().len(),
            self.scene.world.time()
        )
    }
}
