//! The charts: each metric (and the CPU time and steps of each case) against each factor, one
//! PNG each in `plots/`, drawn on the runner's threads.
//!
//! How the cases are drawn depends on the design: a grid draws one curve per combination of
//! the other factors' levels (when there are at most [`MAX_CURVES`], else every case as a
//! point); one at a time draws the factor's own cases through the base; a Latin hypercube
//! every case as a point. A case that did not run to its end has no value: it is drawn as a red
//! cross on the axis, at its factor's value. A factor spread in logarithm gets a log axis, and so
//! does a metric that spans three decades or more of positive values.
//!
//! Memory: the factors' values of every case, and the values of as many metrics at a time as
//! fit in `VALUES_PER_PASS` numbers (the rows are read again for each such pass).

use super::case::Status;
use super::error::{Stage, SweepError, unless_cancelled};
use super::factor::Values;
use super::plan::Plan;
use super::rows::Rows;
use super::spec::{Design, Level, LevelKind};
use super::table::{Columns, compact};
use crate::chart_style::{self, COLOURS, register_font_family};
use crate::runner::Runner;
use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// A grid's chart draws one curve per combination of the other factors' levels up to this many.
pub const MAX_CURVES: usize = 8;

/// Metric values held at once while charting.
const VALUES_PER_PASS: usize = 4_000_000;

/// Width and height of a chart [px].
const SIZE: (u32, u32) = (1200, 800);

/// What is charted against the factors.
#[derive(Debug, Clone)]
struct Series {
    name: String,
    unit: String,
    source: Source,
}

#[derive(Debug, Clone, Copy)]
enum Source {
    Metric(usize),
    Cpu,
    Steps,
}

/// Every case's place on each factor's axis, and whether it ran to its end.
struct Axes {
    /// Per factor, per case: the value, or the level's index for names and flags.
    positions: Vec<Vec<f64>>,
    /// Per factor: the names of its levels (names and flags), in the spec's order.
    categories: Vec<Vec<String>>,
    ok: Vec<bool>,
}

/// Draws every chart into `folder`; returns their file names, sorted.
///
/// # Errors
/// A chart that cannot be drawn or written; `runner` cancelled (checked at each row and chart).
pub fn draw(plan: &Plan, rows: &Rows, folder: &Path, runner: &Runner) -> Result<Vec<String>, SweepError> {
    let fail = |message: String| SweepError::Output { path: folder.display().to_string(), message };
    register_font_family().map_err(fail)?;
    std::fs::create_dir_all(folder).map_err(|e| super::store::io(folder, "cannot create", &e))?;
    let columns = plan.columns();
    let axes = axes(plan, rows, runner)?;
    let mut series: Vec<Series> = columns
        .metrics
        .iter()
        .enumerate()
        .map(|(k, m)| Series { name: m.name.clone(), unit: m.unit.clone(), source: Source::Metric(k) })
        .collect();
    series.push(Series { name: "cpu_s".into(), unit: "s".into(), source: Source::Cpu });
    series.push(Series { name: "steps".into(), unit: "–".into(), source: Source::Steps });
    let file_names = file_names(&series, &columns);
    let per_pass = (VALUES_PER_PASS / axes.ok.len().max(1)).max(1);
    let mut written = Vec::new();
    for chunk in series.chunks(per_pass) {
        let values = values(rows, chunk, runner)?;
        let charts: Vec<(usize, usize)> =
            (0..chunk.len()).flat_map(|s| (0..plan.factors.len()).map(move |f| (s, f))).collect();
        runner.run(
            charts.into_iter(),
            |&(s, f), _| {
                let file = &file_names[&(chunk[s].name.clone(), f)];
                let chart = Chart::new(plan, &axes, f, &chunk[s], &values[s]);
                chart
                    .render(&folder.join(file))
                    .map(|()| file.clone())
                    .map_err(|message| SweepError::Output { path: folder.join(file).display().to_string(), message })
            },
            |_, drawn| {
                written.push(drawn?);
                Ok::<(), SweepError>(())
            },
        )?;
        // A cancelled runner starts no further chart and returns.
        unless_cancelled(runner, Stage::Writing)?;
    }
    written.sort();
    Ok(written)
}

/// `<metric>--<factor>.png` per chart, made safe as file names and unique.
fn file_names(series: &[Series], columns: &Columns) -> BTreeMap<(String, usize), String> {
    let safe = |text: &str| {
        text.chars().map(|c| if c.is_alphanumeric() || "-_.".contains(c) { c } else { '_' }).collect::<String>()
    };
    let mut names = BTreeMap::new();
    let mut taken = std::collections::BTreeSet::new();
    for s in series {
        for (f, factor) in columns.factors.iter().enumerate() {
            let stem = format!("{}--{}", safe(&s.name), safe(&factor.name));
            let mut name = format!("{stem}.png");
            let mut k = 2;
            while !taken.insert(name.clone()) {
                name = format!("{stem}-{k}.png");
                k += 1;
            }
            names.insert((s.name.clone(), f), name);
        }
    }
    names
}

/// Every case's place on each factor's axis.
fn axes(plan: &Plan, rows: &Rows, runner: &Runner) -> Result<Axes, SweepError> {
    let categories: Vec<Vec<String>> = plan
        .factors
        .iter()
        .map(|f| match (&f.values, f.kind()) {
            (Values::Levels(levels), LevelKind::Text | LevelKind::Flag) => {
                levels.iter().map(ToString::to_string).collect()
            }
            _ => Vec::new(),
        })
        .collect();
    let mut positions = vec![Vec::with_capacity(rows.len()); plan.factors.len()];
    let mut ok = Vec::with_capacity(rows.len());
    rows.for_each(|row| {
        unless_cancelled(runner, Stage::Writing)?;
        for ((slot, value), names) in positions.iter_mut().zip(&row.values).zip(&categories) {
            slot.push(match value {
                Level::Number(x) => *x,
                other => names.iter().position(|n| *n == other.to_string()).unwrap_or(0) as f64,
            });
        }
        ok.push(row.ending.status == Status::Ok);
        Ok(())
    })?;
    Ok(Axes { positions, categories, ok })
}

/// The values of `series` for every case (`None`: the case has none).
fn values(rows: &Rows, series: &[Series], runner: &Runner) -> Result<Vec<Vec<Option<f64>>>, SweepError> {
    let mut values = vec![Vec::with_capacity(rows.len()); series.len()];
    rows.for_each(|row| {
        unless_cancelled(runner, Stage::Writing)?;
        let ok = row.ending.status == Status::Ok;
        for (slot, s) in values.iter_mut().zip(series) {
            slot.push(match s.source {
                Source::Metric(k) => row.metrics[k],
                Source::Cpu => ok.then_some(row.ending.cpu_seconds),
                Source::Steps => ok.then_some((row.ending.steps + row.ending.rejected_steps) as f64),
            });
        }
        Ok(())
    })?;
    Ok(values)
}

/// A curve: its legend, if it has one, and its points.
type Curve = (Option<String>, Vec<(f64, f64)>);

/// The cases of a curve, with its legend.
type Group = (Option<String>, Vec<usize>);

/// One chart's data.
struct Chart<'a> {
    title: String,
    x_label: String,
    y_label: String,
    x_log: bool,
    y_log: bool,
    /// Level names along a factor of names or flags (drawn at 0, 1, 2…).
    categories: &'a [String],
    curves: Vec<Curve>,
    /// Whether the curves are drawn as lines (else as points).
    lines: bool,
    /// The factor's values of the cases without a value.
    failed: Vec<f64>,
}

impl<'a> Chart<'a> {
    fn new(plan: &Plan, axes: &'a Axes, factor: usize, series: &Series, values: &[Option<f64>]) -> Self {
        let column = &plan.columns().factors[factor];
        let x_log = column.log && column.kind == LevelKind::Number && axes.positions[factor].iter().all(|&x| x > 0.0);
        let (low, high) =
            values.iter().flatten().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &y| (l.min(y), h.max(y)));
        let y_log = low > 0.0 && high / low >= 1e3;
        let (groups, lines) = groups(plan, axes, factor);
        let mut failed = Vec::new();
        let curves = groups
            .into_iter()
            .map(|(label, cases)| {
                let mut points: Vec<(f64, f64)> = Vec::with_capacity(cases.len());
                for case in cases {
                    let x = axes.positions[factor][case];
                    match values[case] {
                        Some(y) => points.push((x, y)),
                        None => failed.push(x),
                    }
                }
                points.sort_by(|a, b| a.0.total_cmp(&b.0));
                (label, points)
            })
            .collect();
        let unit = if series.unit == "–" { String::new() } else { format!(" [{}]", series.unit) };
        Self {
            title: format!("{}: {} against {}", plan.name, series.name, column.name),
            x_label: format!("{}{}", column.name, if x_log { " (log scale)" } else { "" }),
            y_label: format!("{}{unit}{}", series.name, if y_log { " (log scale)" } else { "" }),
            x_log,
            y_log,
            categories: &axes.categories[factor],
            curves,
            lines,
            failed,
        }
    }

    /// Draws the chart to the PNG `path`.
    fn render(&self, path: &Path) -> Result<(), String> {
        let points = || self.curves.iter().flat_map(|(_, p)| p.iter());
        let (x_low, x_high) = points()
            .map(|p| p.0)
            .chain(self.failed.iter().copied())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
        let (y_low, y_high) =
            points().map(|p| p.1).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
        let x_range = if self.categories.is_empty() {
            padded(x_low, x_high, self.x_log)
        } else {
            (x_low.min(0.0) - 0.5)..(x_high.max(self.categories.len() as f64 - 1.0) + 0.5)
        };
        let y_range = padded(y_low, y_high, self.y_log);
        match (self.x_log, self.y_log) {
            (false, false) => self.render_on(path, x_range.clone(), y_range.clone(), &x_range, &y_range),
            (true, false) => self.render_on(path, x_range.clone().log_scale(), y_range.clone(), &x_range, &y_range),
            (false, true) => self.render_on(path, x_range.clone(), y_range.clone().log_scale(), &x_range, &y_range),
            (true, true) => {
                self.render_on(path, x_range.clone().log_scale(), y_range.clone().log_scale(), &x_range, &y_range)
            }
        }
    }

    /// Draws the chart on axes `x` and `y` (linear or logarithmic) spanning `x_range`, `y_range`.
    fn render_on<X, Y>(
        &self,
        path: &Path,
        x: X,
        y: Y,
        x_range: &std::ops::Range<f64>,
        y_range: &std::ops::Range<f64>,
    ) -> Result<(), String>
    where
        X: AsRangedCoord<Value = f64>,
        Y: AsRangedCoord<Value = f64>,
        X::CoordDescType: ValueFormatter<f64>,
        Y::CoordDescType: ValueFormatter<f64>,
    {
        let error = |e: &dyn std::fmt::Display| e.to_string();
        let root = BitMapBackend::new(path, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| error(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&self.title, ("sans-serif", 26))
            .margin(20)
            .x_label_area_size(60)
            .y_label_area_size(110)
            .build_cartesian_2d(x, y)
            .map_err(|e| error(&e))?;
        let categories = self.categories;
        let x_format = move |x: &f64| if categories.is_empty() { compact(*x) } else { category(*x, categories) };
        let y_format = |y: &f64| compact(*y);
        chart_style::axes(&mut chart.configure_mesh())
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .x_labels(if categories.is_empty() { 10 } else { categories.len() * 2 + 1 })
            .x_label_formatter(&x_format)
            .y_label_formatter(&y_format)
            .draw()
            .map_err(|e| error(&e))?;
        let mut labelled = false;
        for (k, (label, points)) in self.curves.iter().enumerate() {
            let colour = COLOURS[k % COLOURS.len()];
            let radius = if self.lines { 5 } else { 4 };
            let as_line = self.lines && points.len() > 1;
            if as_line {
                let style = ShapeStyle::from(&colour).stroke_width(3);
                let drawn = chart.draw_series(LineSeries::new(points.iter().copied(), style)).map_err(|e| error(&e))?;
                if let Some(label) = label {
                    drawn.label(label).legend(move |(x, y)| PathElement::new(vec![(x - 5, y), (x + 18, y)], style));
                    labelled = true;
                }
            }
            let dots = chart
                .draw_series(points.iter().map(|&p| Circle::new(p, radius, colour.filled())))
                .map_err(|e| error(&e))?;
            if let (Some(label), false) = (label, as_line) {
                dots.label(label).legend(move |(x, y)| Circle::new((x + 6, y), radius, colour.filled()));
                labelled = true;
            }
        }
        if !self.failed.is_empty() {
            // On the x axis, just above the frame's bottom.
            let bottom = if self.y_log {
                y_range.start * (y_range.end / y_range.start).powf(0.03)
            } else {
                y_range.start + 0.03 * (y_range.end - y_range.start)
            };
            let red = RGBColor(214, 39, 40);
            let crosses = chart
                .draw_series(self.failed.iter().map(|&x| Cross::new((x, bottom), 7, red.stroke_width(3))))
                .map_err(|e| error(&e))?;
            crosses
                .label(format!("{} failed (no value)", self.failed.len()))
                .legend(move |(x, y)| Cross::new((x + 6, y), 6, red.stroke_width(3)));
            labelled = true;
        }
        if labelled {
            chart_style::legend(&mut chart.configure_series_labels(), 18)
                .position(self.emptiest_corner(x_range, y_range))
                .margin(15)
                .draw()
                .map_err(|e| error(&e))?;
        }
        root.present().map_err(|e| error(&e))
    }

    /// The corner of the frame with the fewest points, for the legend.
    fn emptiest_corner(&self, x_range: &std::ops::Range<f64>, y_range: &std::ops::Range<f64>) -> SeriesLabelPosition {
        let place = |value: f64, range: &std::ops::Range<f64>, log: bool| {
            if log {
                (value / range.start).ln() / (range.end / range.start).ln()
            } else {
                (value - range.start) / (range.end - range.start)
            }
        };
        let mut counts = [0_usize; 4];
        for &(x, y) in self.curves.iter().flat_map(|(_, p)| p.iter()) {
            let (u, v) = (place(x, x_range, self.x_log), place(y, y_range, self.y_log));
            let corner = usize::from(u < 0.5) + 2 * usize::from(v < 0.5);
            counts[corner] += 1;
        }
        let corners = [
            SeriesLabelPosition::UpperRight,
            SeriesLabelPosition::UpperLeft,
            SeriesLabelPosition::LowerRight,
            SeriesLabelPosition::LowerLeft,
        ];
        let emptiest = (0..4).min_by_key(|&k| counts[k]).unwrap_or(0);
        corners[emptiest].clone()
    }
}

/// `low..high` with a margin: 8 % of the span (of its logarithm on a log axis); a single value
/// gets ±10 % of itself (±1 at zero).
fn padded(low: f64, high: f64, log: bool) -> std::ops::Range<f64> {
    if !(low.is_finite() && high.is_finite()) {
        return if log { 0.1..10.0 } else { 0.0..1.0 };
    }
    if log {
        let ratio = (high / low).max(1.0 + 1e-9).powf(0.08).max(1.5_f64.sqrt());
        return (low / ratio)..(high * ratio);
    }
    let span = high - low;
    if span <= 1e-12 * high.abs().max(low.abs()) {
        let half = if low == 0.0 { 1.0 } else { 0.1 * low.abs() };
        return (low - half)..(high + half);
    }
    (low - 0.08 * span)..(high + 0.08 * span)
}

/// The name of the level at tick `x` of a named axis (ticks between levels have none).
fn category(x: f64, categories: &[String]) -> String {
    let nearest = x.round();
    if (x - nearest).abs() < 1e-6 && nearest >= 0.0 {
        categories.get(nearest as usize).cloned().unwrap_or_default()
    } else {
        String::new()
    }
}

/// The cases of each curve of a chart against factor `factor`, and whether they are lines.
fn groups(plan: &Plan, axes: &Axes, factor: usize) -> (Vec<Group>, bool) {
    let cases = axes.ok.len();
    let others: Vec<usize> = (0..plan.factors.len()).filter(|&f| f != factor).collect();
    match plan.design {
        Design::Grid => {
            let mut curves: BTreeMap<Vec<u64>, Vec<usize>> = BTreeMap::new();
            for case in 0..cases {
                curves
                    .entry(others.iter().map(|&f| axes.positions[f][case].to_bits()).collect())
                    .or_default()
                    .push(case);
            }
            if others.is_empty() {
                (vec![(None, (0..cases).collect())], true)
            } else if curves.len() <= MAX_CURVES {
                // Grid cases come in order, so each curve's first case labels it.
                let mut labelled: Vec<Group> =
                    curves.into_values().map(|cases| (Some(label(plan, axes, &others, cases[0])), cases)).collect();
                labelled.sort_by_key(|(_, cases)| cases[0]);
                (labelled, true)
            } else {
                (vec![(None, (0..cases).collect())], false)
            }
        }
        // Case 0 is the base: the factor's own cases have every other factor where it has it.
        Design::OneAtATime => {
            let at_base = (0..cases)
                .filter(|&case| {
                    others.iter().all(|&f| axes.positions[f][case].to_bits() == axes.positions[f][0].to_bits())
                })
                .collect();
            (vec![(None, at_base)], true)
        }
        Design::LatinHypercube { .. } => (vec![(None, (0..cases).collect())], false),
    }
}

/// `mass = 3000, integrator = rk4`: the other factors' values of a curve.
fn label(plan: &Plan, axes: &Axes, others: &[usize], case: usize) -> String {
    let parts: Vec<String> = others
        .iter()
        .map(|&f| {
            let x = axes.positions[f][case];
            let value = axes.categories[f]
                .get(x as usize)
                .filter(|_| !axes.categories[f].is_empty())
                .cloned()
                .unwrap_or_else(|| compact(x));
            format!("{} = {value}", plan.factors[f].name)
        })
        .collect();
    parts.join(", ")
}

/// Where the charts of a sweep directory go.
pub fn folder(dir: &Path) -> PathBuf {
    dir.join("plots")
}
