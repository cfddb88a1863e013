//! What each case measures: the metrics the spec declares and a standard set, observed after
//! every world step (t = 0 included) and reduced as the run goes, so a case holds a few numbers
//! per metric whatever its length (the settle time keeps at most [`SETTLE_SAMPLES`] positions
//! per body).
//!
//! Standard metrics (units in the column names):
//! - `<coupling>.tension_max_N`, `<coupling>.tension_min_N`: the coupling's scalar force \[N]
//!   (a spring's `f_e + k_d ẋ`, a catenary's larger end tension, a contact's normal force);
//! - `<body>.excursion_max_m`: the largest `|x_G(t) − x_G(0)|` \[m]; `<body>.rotation_max_rad`:
//!   the largest angle of `q(0)⁻¹ q(t)` \[rad] (bodies that move: not kinematic, not held in
//!   every direction);
//! - `settle_time_s`: the time after which every moving body's G stays within a band of where
//!   it ends — `settle_band` (spec, default 2 %) of the largest distance any body's G is from its
//!   end position during the run; 0 when nothing moves, near the duration when the motion has
//!   not died out;
//! - `energy_error`: the largest energy-balance drift `|B(t) − B(0)|` (`B = total + dissipated −
//!   external work`, PHYSICS.md §5) over the largest kinetic + |elastic| energy of the run, as in
//!   `tether study`.
//!
//! A declared metric is a quantity reduced over the run (from its `after` time on):
//! `Metric(name: "heave", of: Position("buoy", Z), take: MaxAbs, after: 5.0)`.

use crate::quantity::{Probe, Quantity, Readings};
use serde::Deserialize;
use tether_physics::body::Support;
use tether_physics::math::Vec3;
use tether_physics::world::World;

/// At most this many positions per body are kept for the settle time (evenly spaced in steps).
pub const SETTLE_SAMPLES: u64 = 2048;

/// A metric as the spec declares it.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(rename = "Metric", deny_unknown_fields)]
pub struct MetricDef {
    /// Its column name.
    pub name: String,
    pub of: Quantity,
    pub take: Reduction,
    /// Start of the window it is taken over \[s] (default 0: the whole run).
    #[serde(default)]
    pub after: f64,
}

/// How a quantity's history becomes one number.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize)]
pub enum Reduction {
    Max,
    Min,
    /// The largest absolute value.
    MaxAbs,
    /// The mean over the world steps (equal in time).
    Mean,
    /// The root mean square over the world steps.
    Rms,
    /// The value at the end.
    Final,
    /// max − min.
    Range,
}

/// A declared metric the scene cannot measure: its name, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RefusedMetric {
    pub name: String,
    pub message: String,
}

/// A metric, its bodies and couplings found in the scene.
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    pub name: String,
    pub unit: &'static str,
    measure: Measure,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Measure {
    Reduced { probe: Probe, reduction: Reduction, after: f64 },
    SettleTime,
    EnergyError,
}

impl Metric {
    /// The metrics of a sweep of `world`'s scene: the standard set (if `standard`) and those
    /// the spec declares, their names checked against the scene.
    ///
    /// # Errors
    /// A declared metric naming a body or coupling the scene does not have, or an invalid
    /// window.
    pub fn all(world: &World, standard: bool, declared: &[MetricDef]) -> Result<Vec<Self>, RefusedMetric> {
        let mut metrics = Vec::new();
        if standard {
            for coupling in world.couplings() {
                let tension = Quantity::Tension(coupling.name.clone());
                metrics.push(standard_metric(world, &coupling.name, "tension_max", &tension, Reduction::Max)?);
                metrics.push(standard_metric(world, &coupling.name, "tension_min", &tension, Reduction::Min)?);
            }
            for body in world.bodies().iter().filter(|b| moves(&b.support)) {
                let (excursion, rotation) =
                    (Quantity::Excursion(body.name.clone()), Quantity::Rotation(body.name.clone()));
                metrics.push(standard_metric(world, &body.name, "excursion_max", &excursion, Reduction::Max)?);
                metrics.push(standard_metric(world, &body.name, "rotation_max", &rotation, Reduction::Max)?);
            }
        }
        metrics.push(Self { name: "settle_time_s".into(), unit: "s", measure: Measure::SettleTime });
        metrics.push(Self { name: "energy_error".into(), unit: "–", measure: Measure::EnergyError });
        for def in declared {
            let fail = |message: String| RefusedMetric { name: def.name.clone(), message };
            let probe = Probe::find(world, &def.of).map_err(fail)?;
            if !(def.after.is_finite() && def.after >= 0.0) {
                return Err(fail(format!("`after` must be a time ≥ 0 s, got {}", def.after)));
            }
            metrics.push(reduced(def.name.clone(), probe, def.of.unit(), def.take, def.after));
        }
        Ok(metrics)
    }

    /// The window's start \[s] (0 for the whole run).
    pub fn after(&self) -> f64 {
        match self.measure {
            Measure::Reduced { after, .. } => after,
            Measure::SettleTime | Measure::EnergyError => 0.0,
        }
    }
}

fn reduced(name: String, probe: Probe, unit: &'static str, reduction: Reduction, after: f64) -> Metric {
    Metric { name, unit, measure: Measure::Reduced { probe, reduction, after } }
}

/// A standard metric of the world's own body or coupling `subject`, over the whole run, named
/// with its unit: `mooring1.tension_max_N`. (Its probe is found by the name the world gave it.)
fn standard_metric(
    world: &World,
    subject: &str,
    what: &str,
    quantity: &Quantity,
    reduction: Reduction,
) -> Result<Metric, RefusedMetric> {
    let name = format!("{subject}.{what}_{}", quantity.unit());
    let probe = Probe::find(world, quantity).map_err(|message| RefusedMetric { name: name.clone(), message })?;
    Ok(reduced(name, probe, quantity.unit(), reduction, 0.0))
}

/// Whether a body with this support can move under forces.
fn moves(support: &Support) -> bool {
    !matches!(support, Support::Kinematic(_) | Support::Fixed { translation: [true, true, true], rotation: true })
}

/// Running statistics of one quantity.
#[derive(Debug, Clone, Copy)]
struct Tally {
    max: f64,
    min: f64,
    max_abs: f64,
    sum: f64,
    sum_of_squares: f64,
    count: u64,
    last: f64,
}

impl Default for Tally {
    fn default() -> Self {
        Self {
            max: f64::NEG_INFINITY,
            min: f64::INFINITY,
            max_abs: 0.0,
            sum: 0.0,
            sum_of_squares: 0.0,
            count: 0,
            last: 0.0,
        }
    }
}

impl Tally {
    fn add(&mut self, x: f64) {
        self.max = self.max.max(x);
        self.min = self.min.min(x);
        self.max_abs = self.max_abs.max(x.abs());
        self.sum += x;
        self.sum_of_squares += x * x;
        self.count += 1;
        self.last = x;
    }

    fn reduce(&self, reduction: Reduction) -> f64 {
        let n = self.count.max(1) as f64;
        match reduction {
            Reduction::Max => self.max,
            Reduction::Min => self.min,
            Reduction::MaxAbs => self.max_abs,
            Reduction::Mean => self.sum / n,
            Reduction::Rms => (self.sum_of_squares / n).sqrt(),
            Reduction::Final => self.last,
            Reduction::Range => self.max - self.min,
        }
    }
}

/// One case's metrics as its run goes.
pub struct Observer<'m> {
    metrics: &'m [Metric],
    tallies: Vec<Tally>,
    /// Half a world step [s]: a sample at `after − half_step` is in the window.
    half_step: f64,
    /// The bodies' states the probes read, and their poses at t = 0.
    readings: Readings,
    /// Energy balance at t = 0, its largest drift, and the largest kinetic + |elastic| [J].
    balance0: f64,
    drift: f64,
    peak_energy: f64,
    settle: SettleTrack,
}

/// Positions of the moving bodies every `stride` world steps.
struct SettleTrack {
    bodies: Vec<usize>,
    stride: u64,
    times: Vec<f64>,
    /// `bodies.len()` positions per sample.
    positions: Vec<Vec3>,
}

impl<'m> Observer<'m> {
    /// An observer of `world` (at t = 0, about to run `steps` world steps) for `metrics`; takes
    /// the t = 0 sample.
    pub fn new(metrics: &'m [Metric], world: &World, steps: u64) -> Self {
        let bodies = world.bodies().len();
        let probes: Vec<Probe> = metrics
            .iter()
            .filter_map(|m| match m.measure {
                Measure::Reduced { probe, .. } => Some(probe),
                Measure::SettleTime | Measure::EnergyError => None,
            })
            .collect();
        let readings = Readings::new(world, &probes);
        let moving: Vec<usize> = (0..bodies).filter(|&i| moves(&world.bodies()[i].support)).collect();
        let stride = steps.div_ceil(SETTLE_SAMPLES).max(1);
        let capacity = (steps / stride + 2) as usize;
        let settle = SettleTrack {
            stride,
            times: Vec::with_capacity(capacity),
            positions: Vec::with_capacity(capacity * moving.len()),
            bodies: moving,
        };
        let energy = world.energy();
        let mut observer = Self {
            metrics,
            tallies: vec![Tally::default(); metrics.len()],
            half_step: 0.5 * world.dt(),
            readings,
            balance0: energy.balance(),
            drift: 0.0,
            peak_energy: 0.0,
            settle,
        };
        observer.observe(world);
        observer
    }

    /// Takes the sample of `world` after a world step.
    pub fn observe(&mut self, world: &World) {
        self.readings.update(world);
        let time = world.time();
        for (metric, tally) in self.metrics.iter().zip(&mut self.tallies) {
            if let Measure::Reduced { probe, after, .. } = metric.measure
                && time + self.half_step >= after
            {
                tally.add(self.readings.value(probe, world));
            }
        }
        let energy = world.energy();
        self.drift = self.drift.max((energy.balance() - self.balance0).abs());
        self.peak_energy = self.peak_energy.max(energy.kinetic + energy.elastic.abs());
        if world.steps().is_multiple_of(self.settle.stride) {
            self.settle.take(world);
        }
    }

    /// The metrics' values at the end of the run, in the order of the metrics.
    ///
    /// # Errors
    /// The name of a metric whose value is not finite (a run the health check let through
    /// with an infinite force, say): such a value never reaches the results.
    pub fn finish(mut self, world: &World, settle_band: f64) -> Result<Vec<f64>, String> {
        if !world.steps().is_multiple_of(self.settle.stride) {
            self.settle.take(world);
        }
        let budget = if self.peak_energy > 0.0 { self.peak_energy } else { 1.0 };
        let settle_time = self.settle.time(settle_band);
        let values: Vec<f64> = self
            .metrics
            .iter()
            .zip(&self.tallies)
            .map(|(metric, tally)| match metric.measure {
                Measure::Reduced { reduction, .. } => tally.reduce(reduction),
                Measure::SettleTime => settle_time,
                Measure::EnergyError => self.drift / budget,
            })
            .collect();
        match self.metrics.iter().zip(&values).find(|(_, v)| !v.is_finite()) {
            Some((metric, v)) => Err(format!("metric {} came out {v}", metric.name)),
            None => Ok(values),
        }
    }
}

impl SettleTrack {
    fn take(&mut self, world: &World) {
        self.times.push(world.time());
        self.positions.extend(self.bodies.iter().map(|&i| world.state(i).position));
    }

    /// The first sample time after which every body stays within `band` × the largest
    /// distance from its end position.
    fn time(&self, band: f64) -> f64 {
        let n = self.bodies.len();
        let Some(end) = self.positions.len().checked_sub(n).map(|start| &self.positions[start..]) else { return 0.0 };
        if n == 0 {
            return 0.0;
        }
        let distance = |k: usize| (0..n).map(|b| (self.positions[k * n + b] - end[b]).norm()).fold(0.0, f64::max);
        let largest = (0..self.times.len()).map(distance).fold(0.0, f64::max);
        let limit = band * largest;
        match (0..self.times.len()).rev().find(|&k| distance(k) > limit) {
            Some(last_outside) => self.times.get(last_outside + 1).copied().unwrap_or(self.times[last_outside]),
            None => 0.0,
        }
    }
}
