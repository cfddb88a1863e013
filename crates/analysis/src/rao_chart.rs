//! `tether rao --plot FILE`: a body's RAOs as a chart (PNG, 1600 × 1000; PHYSICS.md §9,
//! docs/potential-flow.md). Amplitude per metre of wave above (translations in m/m on the left,
//! rotations in deg/m on the right), phase \[deg] below, against the wave period \[s] on a
//! logarithmic axis; the frequency-domain solve as lines and, with `--time-domain`, the
//! regular-wave runs as circles of the same colour. A dof whose every amplitude is negligible
//! beside its kind's largest (sway, roll and yaw in head seas) is left out, and
//! [`Responses::omitted`] names it.

use crate::chart_style::{self, COLOURS, ChartError, padded, register_font_family, span};
use plotters::prelude::*;
use std::f64::consts::TAU;
use std::ops::Range;
use std::path::Path;
use tether_physics::potential::ComplexVector6;
use tether_physics::rao::RaoRow;

/// The six dofs, with the unit of their amplitude per metre of wave.
pub const DOFS: [(&str, &str); 6] =
    [("surge", "m/m"), ("sway", "m/m"), ("heave", "m/m"), ("roll", "deg/m"), ("pitch", "deg/m"), ("yaw", "deg/m")];

/// A dof whose largest amplitude is below this fraction of the largest of its kind (translations
/// or rotations) is not drawn: its phase is numerical noise.
pub const NEGLIGIBLE: f64 = 1e-3;

/// Amplitude and phase \[deg] per dof of `xi` (translations in m/m, rotations in deg/m).
pub fn polar(xi: &ComplexVector6) -> [(f64, f64); 6] {
    std::array::from_fn(|dof| {
        let scale = if dof < 3 { 1.0 } else { 1.0_f64.to_degrees() };
        (xi[dof].norm() * scale, xi[dof].arg().to_degrees())
    })
}

/// One dof's curves: (period \[s], amplitude, phase \[deg]) of the frequency-domain solve (a
/// singular period left out) and of the time-domain runs (empty without them).
#[derive(Debug, Clone, PartialEq)]
pub struct DofCurves {
    pub dof: usize,
    pub frequency_domain: Vec<(f64, f64, f64)>,
    pub time_domain: Vec<(f64, f64, f64)>,
}

/// The dofs the chart draws and those it leaves out.
#[derive(Debug, Clone, PartialEq)]
pub struct Responses {
    pub drawn: Vec<DofCurves>,
    pub omitted: Vec<usize>,
}

impl Responses {
    /// The curves of `rows` (and of `measured`, one per row, when given), sorted by period; the
    /// negligible dofs (below [`NEGLIGIBLE`] of their kind's largest, in either domain) left out.
    pub fn new(rows: &[RaoRow], measured: Option<&[ComplexVector6]>) -> Self {
        let mut curves: Vec<DofCurves> = (0..6)
            .map(|dof| {
                let mut frequency_domain: Vec<_> = rows
                    .iter()
                    .filter_map(|row| row.response.map(|xi| (TAU / row.omega, polar(&xi)[dof])))
                    .map(|(period, (amplitude, phase))| (period, amplitude, phase))
                    .collect();
                let mut time_domain: Vec<_> = measured
                    .unwrap_or_default()
                    .iter()
                    .zip(rows)
                    .map(|(xi, row)| {
                        let (amplitude, phase) = polar(xi)[dof];
                        (TAU / row.omega, amplitude, phase)
                    })
                    .collect();
                frequency_domain.sort_by(|a, b| a.0.total_cmp(&b.0));
                time_domain.sort_by(|a, b| a.0.total_cmp(&b.0));
                DofCurves { dof, frequency_domain, time_domain }
            })
            .collect();
        let largest = |curve: &DofCurves| {
            curve.frequency_domain.iter().chain(&curve.time_domain).map(|p| p.1).fold(0.0, f64::max)
        };
        let kind_largest =
            |rotation: bool| curves.iter().filter(|c| (c.dof >= 3) == rotation).map(largest).fold(0.0, f64::max);
        let thresholds = [kind_largest(false), kind_largest(true)].map(|l| NEGLIGIBLE * l);
        let omitted: Vec<usize> =
            curves.iter().filter(|c| largest(c) <= thresholds[usize::from(c.dof >= 3)]).map(|c| c.dof).collect();
        curves.retain(|c| !omitted.contains(&c.dof));
        Self { drawn: curves, omitted }
    }
}

/// `points` (period, phase \[deg]) cut where the phase wraps — two neighbours more than 180°
/// apart — so that a line through each piece does not cross the chart.
pub fn unwrapped_pieces(points: &[(f64, f64)]) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    for &point in points {
        match pieces.last_mut() {
            Some(piece) if piece.last().is_some_and(|last| (point.1 - last.1).abs() <= 180.0) => piece.push(point),
            _ => pieces.push(vec![point]),
        }
    }
    pieces
}

/// Writes the chart of `responses` titled `title` to `path`.
///
/// # Errors
/// Nothing to draw (every dof negligible), the font cannot be loaded or the image cannot be
/// written.
pub fn write(responses: &Responses, title: &str, path: &Path) -> Result<(), ChartError> {
    let failed = |message: String| ChartError { path: path.display().to_string(), message };
    if responses.drawn.is_empty() {
        return Err(failed("no response to draw: every dof is negligible".to_string()));
    }
    register_font_family().map_err(failed)?;
    let draw = |e: &dyn std::fmt::Display| failed(e.to_string());
    let root = BitMapBackend::new(path, (1600, 1000)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw(&e))?;
    let root = root.titled(title, ("sans-serif", 24)).map_err(|e| draw(&e))?;
    let panels = root.split_evenly((2, 2));
    // A logarithmic period axis: a panel code's frequencies are usually evenly spaced in ω, which
    // a linear period axis would crowd against its left end.
    let (shortest, longest) =
        span(responses.drawn.iter().flat_map(|c| c.frequency_domain.iter().chain(&c.time_domain).map(|p| p.0)));
    let periods = shortest / 1.1..longest * 1.1;
    for (column, rotation) in [false, true].into_iter().enumerate() {
        let curves: Vec<&DofCurves> = responses.drawn.iter().filter(|c| (c.dof >= 3) == rotation).collect();
        if curves.is_empty() {
            continue;
        }
        let unit = if rotation { "deg/m" } else { "m/m" };
        let amplitudes = span(curves.iter().flat_map(|c| c.frequency_domain.iter().chain(&c.time_domain).map(|p| p.1)));
        draw_panel(
            &panels[column],
            &curves,
            periods.clone(),
            0.0..padded(amplitudes).end,
            &format!("amplitude [{unit}]"),
            |p| p.1,
        )
        .map_err(failed)?;
        draw_panel(&panels[2 + column], &curves, periods.clone(), -190.0..190.0, "phase [deg]", |p| p.2)
            .map_err(failed)?;
    }
    root.present().map_err(|e| draw(&e))?;
    Ok(())
}

/// One panel: `value` of each curve's points against the period, lines for the frequency domain
/// (cut where a phase wraps) and circles for the time domain, with a legend.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    curves: &[&DofCurves],
    periods: Range<f64>,
    values: Range<f64>,
    y_title: &str,
    value: fn(&(f64, f64, f64)) -> f64,
) -> Result<(), String> {
    let draw = |e: &dyn std::fmt::Display| e.to_string();
    let mut chart = ChartBuilder::on(area)
        .margin(16)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(periods.log_scale(), values)
        .map_err(|e| draw(&e))?;
    let short = |v: &f64| format!("{v:.3}").trim_end_matches('0').trim_end_matches('.').to_string();
    chart_style::axes(&mut chart.configure_mesh())
        .x_desc("wave period [s]")
        .y_desc(y_title)
        .x_label_formatter(&short)
        .y_label_formatter(&short)
        .draw()
        .map_err(|e| draw(&e))?;
    for curve in curves {
        let colour = COLOURS[curve.dof % COLOURS.len()];
        let (name, _) = DOFS[curve.dof];
        let line = ShapeStyle::from(&colour).stroke_width(3);
        let points: Vec<(f64, f64)> = curve.frequency_domain.iter().map(|p| (p.0, value(p))).collect();
        for (index, piece) in unwrapped_pieces(&points).into_iter().enumerate() {
            let series = chart.draw_series(LineSeries::new(piece, line)).map_err(|e| draw(&e))?;
            if index == 0 {
                series
                    .label(format!("{name}, frequency domain"))
                    .legend(move |(x, y)| PathElement::new(vec![(x - 5, y), (x + 18, y)], line));
            }
        }
        if !curve.time_domain.is_empty() {
            let marker = ShapeStyle::from(&colour).stroke_width(2);
            chart
                .draw_series(curve.time_domain.iter().map(|p| Circle::new((p.0, value(p)), 6, marker)))
                .map_err(|e| draw(&e))?
                .label(format!("{name}, time domain"))
                .legend(move |(x, y)| Circle::new((x + 6, y), 6, marker));
        }
    }
    chart_style::legend(&mut chart.configure_series_labels(), 16)
        .position(SeriesLabelPosition::UpperRight)
        .margin(10)
        .draw()
        .map_err(|e| draw(&e))
}
