//! A storm's statistics written out (docs/design-loads.md): `storm.md` (the table, with the
//! code's check), `storm.csv` and `storm.parquet` (a row per quantity: its fits, design numbers,
//! check and every seed's maximum), and `storm.png`, the seeds' maxima on Gumbel paper (the
//! reduced variate `−ln(−ln p)` of each maximum's plotting position `p = i/(n + 1)` against the
//! maximum, normalised by the quantity's MPM) with each maximum-likelihood fit's line.

use super::StormError;
use super::statistics::{Code, DesignCheck, Measured, QuantityStatistics};
use crate::chart_style::{self, COLOURS, register_font_family};
use arrow_array::builder::{Float64Builder, ListBuilder, StringBuilder};
use arrow_array::{ArrayRef, RecordBatch};
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The files written into `dir`, for `stats` of a storm of `hours` \[h] checked by `code`.
///
/// # Errors
/// A file that cannot be written.
pub fn write(dir: &Path, stats: &[QuantityStatistics], hours: f64, code: Code) -> Result<Vec<PathBuf>, StormError> {
    let markdown = dir.join("storm.md");
    let csv = dir.join("storm.csv");
    let parquet = dir.join("storm.parquet");
    let chart = dir.join("storm.png");
    write_text(&markdown, &table(stats, hours, code))?;
    write_text(&csv, &csv_text(stats))?;
    write_parquet(&parquet, stats)?;
    draw(&chart, stats, hours)?;
    Ok(vec![markdown, csv, parquet, chart])
}

fn write_text(path: &Path, text: &str) -> Result<(), StormError> {
    std::fs::write(path, text).map_err(|e| output(path, &e))
}

fn output(path: &Path, error: &dyn std::fmt::Display) -> StormError {
    StormError::Output { path: path.display().to_string(), message: error.to_string() }
}

/// A value in the quantity's unit for people: tensions in kN, offsets in m.
fn shown(measured: &Measured, value: f64) -> String {
    match measured {
        Measured::Tension { .. } => format!("{:.1}", value / 1e3),
        Measured::Offset { .. } => format!("{value:.3}"),
    }
}

/// The unit [`shown`] gives it in: kN for a tension, m for an offset.
fn shown_unit(measured: &Measured) -> &'static str {
    match measured {
        Measured::Tension { .. } => "kN",
        Measured::Offset { .. } => "m",
    }
}

/// `mooring1 tension [kN]`.
fn label(measured: &Measured) -> String {
    format!("{} {} [{}]", measured.subject(), measured.quantity(), shown_unit(measured))
}

/// The check's cell: `SF 2.41 ≥ 1.67 ✓`, `u 0.88 ≤ 1 ✓`, or why there is none.
fn check_cell(check: Option<&DesignCheck>, measured: &Measured) -> String {
    match (check, measured) {
        (Some(check), _) => {
            let mark = if check.passes { "passes" } else { "FAILS" };
            match check.code {
                Code::ApiRp2sk => format!("SF {:.2} (≥ 1.67): {mark}", check.figure),
                Code::DnvOsE301 { .. } => format!("utilisation {:.3} (≤ 1): {mark}", check.figure),
            }
        }
        (None, Measured::Tension { .. }) => "no breaking_load in the scene".into(),
        (None, Measured::Offset { .. }) => String::new(),
    }
}

/// The Markdown table.
pub fn table(stats: &[QuantityStatistics], hours: f64, code: Code) -> String {
    let seeds = stats.first().map_or(0, |s| s.maxima.len());
    let mut text = format!(
        "# Storm: {seeds} seeds of {hours} h\n\nPer quantity, the largest value of each seed fitted with a Gumbel distribution by moments (MoM) and maximum likelihood (ML): location μ and scale β; the design value is the ML fit's most probable maximum (MPM = μ), beside its 90 % quantile and the largest seed. Check: {}.\n\n\
         | quantity | seeds | mean | largest seed | MoM μ | MoM β | ML μ = MPM | ML β | 90 % | check |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
        code.describe()
    );
    for s in stats {
        let m = &s.measured;
        let largest = s.maxima.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        text += &format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            label(m),
            s.maxima.len(),
            s.mean.map_or_else(String::new, |v| shown(m, v)),
            shown(m, largest),
            shown(m, s.moments.location),
            shown(m, s.moments.scale),
            shown(m, s.most_probable_maximum),
            shown(m, s.likelihood.scale),
            shown(m, s.quantile_90),
            check_cell(s.check.as_ref(), m)
        );
    }
    text
}

/// `quantity,unit,…,maxima` with SI values, the maxima `;`-separated in seed order.
fn csv_text(stats: &[QuantityStatistics]) -> String {
    let mut text = "quantity,unit,seeds,mean,mom_location,mom_scale,ml_location,ml_scale,mpm,quantile_90,check_figure,check_passes,maxima\n".to_string();
    for s in stats {
        let (name, unit) = (s.measured.name(), s.measured.unit());
        let maxima: Vec<String> = s.maxima.iter().map(|v| format!("{v}")).collect();
        text += &format!(
            "{name},{unit},{},{},{},{},{},{},{},{},{},{},{}\n",
            s.maxima.len(),
            s.mean.map_or_else(String::new, |v| format!("{v}")),
            s.moments.location,
            s.moments.scale,
            s.likelihood.location,
            s.likelihood.scale,
            s.most_probable_maximum,
            s.quantile_90,
            s.check.map_or_else(String::new, |c| format!("{}", c.figure)),
            s.check.map_or_else(String::new, |c| format!("{}", c.passes)),
            maxima.join(";")
        );
    }
    text
}

fn write_parquet(path: &Path, stats: &[QuantityStatistics]) -> Result<(), StormError> {
    let numbers = |f: &dyn Fn(&QuantityStatistics) -> Option<f64>| -> ArrayRef {
        let mut builder = Float64Builder::new();
        for s in stats {
            builder.append_option(f(s));
        }
        Arc::new(builder.finish())
    };
    let mut names = StringBuilder::new();
    let mut units = StringBuilder::new();
    let mut maxima = ListBuilder::new(Float64Builder::new());
    for s in stats {
        let (name, unit) = (s.measured.name(), s.measured.unit());
        names.append_value(name);
        units.append_value(unit);
        for &m in &s.maxima {
            maxima.values().append_value(m);
        }
        maxima.append(true);
    }
    let columns: Vec<(&str, ArrayRef)> = vec![
        ("quantity", Arc::new(names.finish())),
        ("unit", Arc::new(units.finish())),
        ("mean", numbers(&|s| s.mean)),
        ("mom_location", numbers(&|s| Some(s.moments.location))),
        ("mom_scale", numbers(&|s| Some(s.moments.scale))),
        ("ml_location", numbers(&|s| Some(s.likelihood.location))),
        ("ml_scale", numbers(&|s| Some(s.likelihood.scale))),
        ("mpm", numbers(&|s| Some(s.most_probable_maximum))),
        ("quantile_90", numbers(&|s| Some(s.quantile_90))),
        ("check_figure", numbers(&|s| s.check.map(|c| c.figure))),
        ("maxima", Arc::new(maxima.finish())),
    ];
    let batch = RecordBatch::try_from_iter(columns).map_err(|e| output(path, &e))?;
    let file = std::fs::File::create(path).map_err(|e| output(path, &e))?;
    let mut writer = parquet::arrow::ArrowWriter::try_new(file, batch.schema(), None).map_err(|e| output(path, &e))?;
    writer.write(&batch).map_err(|e| output(path, &e))?;
    writer.close().map_err(|e| output(path, &e))?;
    Ok(())
}

/// The Gumbel paper chart (module docs), 1200 × 800.
fn draw(path: &Path, stats: &[QuantityStatistics], hours: f64) -> Result<(), StormError> {
    register_font_family().map_err(|e| output(path, &e))?;
    let fail = |e: &dyn std::fmt::Display| output(path, e);
    let reduced = |i: usize, n: usize| -(-((i + 1) as f64 / (n + 1) as f64).ln()).ln();
    let points: Vec<Vec<(f64, f64)>> = stats
        .iter()
        .map(|s| {
            let mut sorted = s.maxima.clone();
            sorted.sort_by(f64::total_cmp);
            let n = sorted.len();
            sorted.iter().enumerate().map(|(i, &m)| (reduced(i, n), m / s.most_probable_maximum)).collect()
        })
        .collect();
    let (y_low, y_high) = chart_style::span(points.iter().flatten().map(|p| p.1));
    let (x_low, x_high) = chart_style::span(points.iter().flatten().map(|p| p.0));
    let root = BitMapBackend::new(path, (1200, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| fail(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("Storm maxima on Gumbel paper: {} seeds of {hours} h", stats.first().map_or(0, |s| s.maxima.len())),
            ("sans-serif", 26),
        )
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(90)
        .build_cartesian_2d(
            chart_style::padded((x_low, x_high)),
            chart_style::padded((y_low.min(0.9), y_high.max(1.1))),
        )
        .map_err(|e| fail(&e))?;
    chart_style::axes(&mut chart.configure_mesh())
        .x_desc("reduced variate −ln(−ln p), p = i/(n + 1)")
        .y_desc("seed's maximum / MPM")
        .draw()
        .map_err(|e| fail(&e))?;
    for (index, (s, points)) in stats.iter().zip(&points).enumerate() {
        let colour = COLOURS[index % COLOURS.len()];
        let fit = &s.likelihood;
        let line = [x_low, x_high].map(|x| (x, (fit.location + fit.scale * x) / s.most_probable_maximum));
        let style = ShapeStyle::from(&colour).stroke_width(2);
        chart
            .draw_series(LineSeries::new(line, style))
            .map_err(|e| fail(&e))?
            .label(format!("{}: MPM {}", label(&s.measured), shown(&s.measured, s.most_probable_maximum)))
            .legend(move |(x, y)| PathElement::new(vec![(x - 5, y), (x + 18, y)], style));
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 6, colour.filled()))).map_err(|e| fail(&e))?;
    }
    chart_style::legend(&mut chart.configure_series_labels(), 18)
        .position(SeriesLabelPosition::UpperLeft)
        .margin(15)
        .draw()
        .map_err(|e| fail(&e))?;
    root.present().map_err(|e| fail(&e))?;
    Ok(())
}

/// `12.3 kN` or `0.456 m`, for the command's summary.
pub fn summary(stats: &[QuantityStatistics]) -> String {
    stats
        .iter()
        .map(|s| {
            format!(
                "{}: MPM {}, 90 % {}{}",
                label(&s.measured),
                shown(&s.measured, s.most_probable_maximum),
                shown(&s.measured, s.quantile_90),
                s.check.map_or_else(String::new, |c| format!(", {}", check_cell(Some(&c), &s.measured)))
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}
