//! One PNG per measured signal (1200 × 700): the record as dots, the model at the start and at
//! the optimum as lines, over the window.

use super::model::Signal;
use super::run::SignalFit;
use crate::chart_style::{self, COLOURS, register_font_family};
use plotters::prelude::*;
use std::path::Path;

/// Draws `signal` with its fit `fit` to `path`; `scene` names the chart.
///
/// # Errors
/// The font cannot be loaded or the image cannot be written, with the path.
pub fn write(signal: &Signal, fit: &SignalFit, scene: &str, path: &Path) -> Result<(), String> {
    let failed = |message: String| format!("{}: {message}", path.display());
    register_font_family().map_err(failed)?;
    let draw = |e: &dyn std::fmt::Display| failed(e.to_string());
    let all = signal.measured.iter().chain(&fit.start).chain(&fit.fitted);
    let (low, high) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| (a.min(y), b.max(y)));
    let pad = 0.05 * (high - low).max(1e-12 * high.abs().max(1.0));
    let (t0, t1) = (signal.times[0], signal.times[signal.times.len() - 1]);
    let root = BitMapBackend::new(path, (1200, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(format!("{scene}: {} — record, start and fitted model", signal.column), ("sans-serif", 24))
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(110)
        .build_cartesian_2d(t0..t1, (low - pad)..(high + pad))
        .map_err(|e| draw(&e))?;
    chart_style::axes(&mut chart.configure_mesh())
        .x_desc("time [s]")
        .y_desc(format!("{} [{}]", signal.column, signal.unit))
        .draw()
        .map_err(|e| draw(&e))?;
    let points = |values: &[f64]| signal.times.iter().copied().zip(values.iter().copied()).collect::<Vec<_>>();
    let measured = COLOURS[7];
    chart
        .draw_series(points(&signal.measured).into_iter().map(|p| Circle::new(p, 2, measured.filled())))
        .map_err(|e| draw(&e))?
        .label("record")
        .legend(move |(x, y)| Circle::new((x + 6, y), 4, measured.filled()));
    for (values, label, colour) in
        [(&fit.start, "model at the start", COLOURS[1]), (&fit.fitted, "model fitted", COLOURS[0])]
    {
        let style = ShapeStyle::from(&colour).stroke_width(2);
        chart
            .draw_series(LineSeries::new(points(values), style))
            .map_err(|e| draw(&e))?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x - 5, y), (x + 18, y)], style));
    }
    chart_style::legend(&mut chart.configure_series_labels(), 18)
        .position(SeriesLabelPosition::UpperRight)
        .margin(12)
        .draw()
        .map_err(|e| draw(&e))?;
    root.present().map_err(|e| draw(&e))?;
    Ok(())
}
