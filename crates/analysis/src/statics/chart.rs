//! The offset curve as a chart (PNG, 1200 × 900): the restoring force against the offset above,
//! each line's tension at its ends below, one colour per line.

use super::offsets::Table;
use crate::chart_style::{self, COLOURS, ChartError, padded, register_font_family, span};
use plotters::prelude::*;
use std::path::Path;

/// Writes the chart of `table` (from [`super::offsets::table`]) titled `title` to `path`.
///
/// # Errors
/// The font cannot be loaded or the image cannot be written.
pub fn write(table: &Table, title: &str, path: &Path) -> Result<(), ChartError> {
    let failed = |message: String| ChartError { path: path.display().to_string(), message };
    let draw = |e: &dyn std::fmt::Display| failed(e.to_string());
    register_font_family().map_err(failed)?;
    let column = |index: usize| table.rows.iter().map(move |row| row[index]);
    let offsets: Vec<f64> = column(0).collect();
    let restoring: Vec<(f64, f64)> = offsets.iter().copied().zip(column(2)).collect();
    // Every line's end tensions: the columns named "… T1 [N]" and "… T2 [N]".
    let tensions: Vec<(String, Vec<(f64, f64)>)> = table
        .columns
        .iter()
        .enumerate()
        .filter(|(_, name)| name.ends_with(" T1 [N]") || name.ends_with(" T2 [N]"))
        .map(|(index, name)| {
            (
                name.trim_end_matches(" [N]").to_string(),
                offsets.iter().copied().zip(column(index)).filter(|(_, t)| t.is_finite()).collect(),
            )
        })
        .collect();
    let x_range = padded(span(offsets.iter().copied()));

    let root = BitMapBackend::new(path, (1200, 900)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| draw(&e))?;
    let root = root.titled(title, ("sans-serif", 26)).map_err(|e| draw(&e))?;
    let (upper, lower) = root.split_vertically(430);
    let mut chart = ChartBuilder::on(&upper)
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(110)
        .build_cartesian_2d(x_range.clone(), padded(span(restoring.iter().map(|p| p.1))))
        .map_err(|e| draw(&e))?;
    chart_style::axes(&mut chart.configure_mesh())
        .x_desc(table.columns[0].as_str())
        .y_desc(table.columns[2].as_str())
        .y_label_formatter(&|y| format!("{y:.3e}"))
        .draw()
        .map_err(|e| draw(&e))?;
    let style = ShapeStyle::from(&BLACK).stroke_width(3);
    chart.draw_series(LineSeries::new(restoring.iter().copied(), style)).map_err(|e| draw(&e))?;
    chart.draw_series(restoring.iter().map(|&p| Circle::new(p, 5, BLACK.filled()))).map_err(|e| draw(&e))?;
    if tensions.is_empty() {
        root.present().map_err(|e| draw(&e))?;
        return Ok(());
    }
    let mut chart = ChartBuilder::on(&lower)
        .margin(20)
        .x_label_area_size(50)
        .y_label_area_size(110)
        .build_cartesian_2d(x_range, padded(span(tensions.iter().flat_map(|(_, p)| p.iter().map(|q| q.1)))))
        .map_err(|e| draw(&e))?;
    chart_style::axes(&mut chart.configure_mesh())
        .x_desc(table.columns[0].as_str())
        .y_desc("line tension [N]")
        .y_label_formatter(&|y| format!("{y:.3e}"))
        .draw()
        .map_err(|e| draw(&e))?;
    for (index, (name, points)) in tensions.iter().enumerate() {
        let colour = COLOURS[(index / 2) % COLOURS.len()];
        // End 2 (the fairlead of a mooring) solid, end 1 (its anchor) thin.
        let style = if name.ends_with("T2") {
            ShapeStyle::from(&colour).stroke_width(3)
        } else {
            ShapeStyle::from(&colour.mix(0.6)).stroke_width(1)
        };
        chart
            .draw_series(LineSeries::new(points.iter().copied(), style))
            .map_err(|e| draw(&e))?
            .label(name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x - 5, y), (x + 18, y)], style));
    }
    chart_style::legend(&mut chart.configure_series_labels(), 18)
        .position(SeriesLabelPosition::UpperLeft)
        .margin(12)
        .draw()
        .map_err(|e| draw(&e))?;
    root.present().map_err(|e| draw(&e))?;
    Ok(())
}
