//! The work-precision chart: error against cost on log-log axes, one curve per integrator
//! (font and colours: [`crate::chart_style`]).

use super::{Outcome, Study, StudyError};
use crate::chart_style::{self, COLOURS, register_font_family};
use plotters::prelude::*;
use std::path::Path;
use tether_physics::integrator::Integrator;

/// Errors below this are drawn at it (an exact result has no logarithm).
const FLOOR: f64 = 1e-16;

/// The error a run is charted by: the largest position error over time [m], or the largest
/// orientation error [rad] when nothing translates.
fn charted_error(study: &Study, m: &super::Measures) -> f64 {
    let error = if study.translates { m.position_error_max } else { m.orientation_error_max };
    error.max(FLOOR)
}

/// Writes the chart of `study` to `path` (PNG, 1200 × 800).
///
/// # Errors
/// [`StudyError::Output`] when the font cannot be loaded or the image cannot be written.
pub fn write(study: &Study, path: &Path) -> Result<(), StudyError> {
    let failed = |message: String| StudyError::Output { path: path.display().to_string(), message };
    register_font_family().map_err(failed)?;
    let curves: Vec<(Integrator, Vec<(f64, f64)>)> = Integrator::ALL
        .iter()
        .map(|&integrator| {
            let mut points: Vec<(f64, f64)> = study
                .runs
                .iter()
                .filter(|run| run.integrator == integrator)
                .filter_map(|run| match &run.outcome {
                    Outcome::Finished(m) => Some((m.cpu_per_second.max(1e-9), charted_error(study, m))),
                    Outcome::Failed { .. } => None,
                })
                .collect();
            points.sort_by(|a, b| a.0.total_cmp(&b.0));
            (integrator, points)
        })
        .filter(|(_, points)| !points.is_empty())
        .collect();
    let all = curves.iter().flat_map(|(_, p)| p.iter());
    let (x_min, x_max, y_min, y_max) = all
        .fold((f64::INFINITY, 0.0_f64, f64::INFINITY, 0.0_f64), |(a, b, c, d), &(x, y)| {
            (a.min(x), b.max(x), c.min(y), d.max(y))
        });
    if curves.is_empty() {
        return Err(failed("no run finished: nothing to chart".into()));
    }
    // A decade of margin split around the data, so no marker sits on a frame.
    let (x_range, y_range) = ((x_min / 2.0)..(x_max * 2.0), (y_min / 3.0)..(y_max * 3.0));
    let quantity = if study.translates {
        "largest position error over time [m]"
    } else {
        "largest orientation error over time [rad]"
    };

    let root = BitMapBackend::new(path, (1200, 800)).into_drawing_area();
    let draw = |e: &dyn std::fmt::Display| failed(e.to_string());
    root.fill(&WHITE).map_err(|e| draw(&e))?;
    let title = format!(
        "{}: error against cost, {} s simulated (reference {})",
        study.scene,
        study.duration,
        study.reference.describe()
    );
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 26))
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(100)
        .build_cartesian_2d(x_range.log_scale(), y_range.log_scale())
        .map_err(|e| draw(&e))?;
    chart_style::axes(&mut chart.configure_mesh())
        .x_desc("CPU seconds per simulated second")
        .y_desc(quantity)
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()
        .map_err(|e| draw(&e))?;
    for (integrator, points) in &curves {
        // One colour per integrator, in [`Integrator::ALL`] order.
        let colour = COLOURS[Integrator::ALL.iter().position(|i| i == integrator).unwrap_or(0)];
        let style = ShapeStyle::from(&colour).stroke_width(3);
        chart
            .draw_series(LineSeries::new(points.iter().copied(), style))
            .map_err(|e| draw(&e))?
            .label(integrator.name())
            .legend(move |(x, y)| PathElement::new(vec![(x - 5, y), (x + 18, y)], style));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 6, colour.filled()))).map_err(|e| draw(&e))?;
    }
    chart_style::legend(&mut chart.configure_series_labels(), 20)
        .position(SeriesLabelPosition::UpperRight)
        .margin(15)
        .draw()
        .map_err(|e| draw(&e))?;
    root.present().map_err(|e| draw(&e))?;
    Ok(())
}
