//! A small line plot in the panel: a curve scaled into a framed box (the statics panel's offset
//! curve, the Fit panel's cost per iteration). The caller draws the line and its labels on what
//! [`frame`] returns. Considered: `egui_plot`, a dependency (and a second plot style beside the
//! viewer's) for two sparklines.

use rerun::external::egui;

/// A framed box with a curve scaled into it.
pub struct Framed {
    pub painter: egui::Painter,
    /// The box, inside its frame.
    pub rect: egui::Rect,
    /// The points' ranges, `(lowest, highest)` in x and in y.
    pub x: (f64, f64),
    pub y: (f64, f64),
    /// The points on screen, in order.
    pub line: Vec<egui::Pos2>,
}

/// Allocates a box `height` points tall across the panel, frames it and scales `points` into it
/// (a range of one value sits in the middle); `None` when there is no finite point to draw.
pub fn frame(ui: &mut egui::Ui, points: &[(f64, f64)], height: f32) -> Option<Framed> {
    let (response, painter) =
        ui.allocate_painter(egui::vec2(ui.available_width().max(200.0), height), egui::Sense::hover());
    let rect = response.rect.shrink(4.0);
    painter.rect_stroke(rect, 2.0, ui.visuals().widgets.noninteractive.bg_stroke, egui::StrokeKind::Inside);
    let span = |values: &mut dyn Iterator<Item = f64>| {
        values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)))
    };
    let x = span(&mut points.iter().map(|p| p.0));
    let y = span(&mut points.iter().map(|p| p.1));
    if !(x.0.is_finite() && y.0.is_finite()) {
        return None;
    }
    let fraction = |v: f64, (lo, hi): (f64, f64)| if hi > lo { (v - lo) / (hi - lo) } else { 0.5 };
    let line = points
        .iter()
        .map(|&(px, py)| {
            egui::pos2(
                rect.left() + rect.width() * fraction(px, x) as f32,
                rect.bottom() - rect.height() * fraction(py, y) as f32,
            )
        })
        .collect();
    Some(Framed { painter, rect, x, y, line })
}
