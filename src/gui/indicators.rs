//! Live indicators: the energy balance (PHYSICS.md §5) with a plot of its drift, the integrator
//! step against the stable time step of every coupling (green: under it, red: over it), and the
//! state of the body selected in the viewer.

use super::simulation::{BodyStatus, Status};
use rerun::external::egui;
use std::collections::VecDeque;

/// Points kept for the drift plot.
const HISTORY: usize = 600;

const GREEN: egui::Color32 = egui::Color32::from_rgb(60, 180, 75);
const RED: egui::Color32 = egui::Color32::from_rgb(230, 60, 50);

/// The balance drift `balance(t) − balance(0)` [J] against simulated time [s].
#[derive(Debug, Clone, Default)]
pub struct EnergyHistory {
    points: VecDeque<(f64, f64)>,
}

impl EnergyHistory {
    /// Adds a status's point (a time that went back starts the plot again: a reset or a load).
    pub fn push(&mut self, status: &Status) {
        if self.points.back().is_some_and(|&(t, _)| status.time < t) {
            self.points.clear();
        }
        if self.points.back().is_some_and(|&(t, _)| t == status.time) {
            return;
        }
        if self.points.len() == HISTORY {
            self.points.pop_front();
        }
        self.points.push_back((status.time, status.energy.balance() - status.initial_balance));
    }
}

/// Draws the indicators for the latest `status`; `selected` is the viewer's selected entity.
pub fn ui(ui: &mut egui::Ui, status: Option<&Status>, history: &EnergyHistory, selected: Option<&str>) {
    let Some(status) = status else {
        ui.label("No simulation running.");
        return;
    };
    energy_ui(ui, status, history);
    stability_ui(ui, status);
    if let Some(body) = selected.and_then(|path| selected_body(path, &status.bodies)) {
        body_ui(ui, body);
    }
}

fn energy_ui(ui: &mut egui::Ui, status: &Status, history: &EnergyHistory) {
    let e = &status.energy;
    ui.strong("Energy balance");
    egui::Grid::new("energy").num_columns(2).show(ui, |ui| {
        for (name, value) in [
            ("kinetic", e.kinetic),
            ("gravity", e.gravity),
            ("elastic", e.elastic),
            ("dissipated", e.dissipated),
            ("external work", e.external_work),
        ] {
            ui.label(name);
            ui.label(format!("{value:+.6e} J"));
            ui.end_row();
        }
        let drift = e.balance() - status.initial_balance;
        ui.label("balance drift");
        ui.label(format!("{drift:+.3e} J ({:+.2e} of the total)", drift / e.total().abs().max(f64::MIN_POSITIVE)));
        ui.end_row();
    });
    drift_plot(ui, history);
}

/// A small line plot of the drift, scaled to its range.
fn drift_plot(ui: &mut egui::Ui, history: &EnergyHistory) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(ui.available_width().min(360.0), 60.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 2.0, ui.visuals().extreme_bg_color);
    let points = &history.points;
    let (Some(first), Some(last)) = (points.front(), points.back()) else { return };
    let span = (last.0 - first.0).max(f64::MIN_POSITIVE);
    let largest = points.iter().fold(0.0_f64, |m, &(_, d)| m.max(d.abs()));
    let extent = largest.max(f64::MIN_POSITIVE);
    let to_screen = |&(t, d): &(f64, f64)| {
        let x = rect.left() + rect.width() * ((t - first.0) / span) as f32;
        let y = rect.center().y - 0.45 * rect.height() * (d / extent) as f32;
        egui::pos2(x, y)
    };
    painter.hline(rect.x_range(), rect.center().y, egui::Stroke::new(1.0, ui.visuals().weak_text_color()));
    let line: Vec<egui::Pos2> = points.iter().map(to_screen).collect();
    painter.add(egui::Shape::line(line, egui::Stroke::new(1.5, ui.visuals().strong_text_color())));
    painter.text(
        rect.left_top(),
        egui::Align2::LEFT_TOP,
        format!("drift ±{largest:.1e} J"),
        egui::FontId::monospace(10.0),
        ui.visuals().weak_text_color(),
    );
}

/// The integrator step against each stable time step.
fn stability_ui(ui: &mut egui::Ui, status: &Status) {
    ui.strong("Stable time step");
    ui.label(format!("integrator step {:.3e} s ({} substep(s) per dt)", status.step_size, status.substeps));
    egui::Grid::new("stability").num_columns(2).show(ui, |ui| {
        let rotation = status.rotation_limit.iter().map(|(body, dt)| (format!("rotation of {body}"), Some(*dt)));
        let water = status.water_limits.iter().map(|(body, dt)| (format!("water on {body}"), Some(*dt)));
        for (name, limit) in status.coupling_limits.iter().cloned().chain(rotation).chain(water) {
            ui.label(name);
            match limit {
                Some(dt) => {
                    let (color, verdict) =
                        if status.step_size <= dt { (GREEN, "ok") } else { (RED, "too large: will diverge") };
                    ui.colored_label(color, format!("{dt:.3e} s {verdict}"));
                }
                None => {
                    ui.colored_label(GREEN, "no limit");
                }
            }
            ui.end_row();
        }
        for (name, dt) in &status.impact_limits {
            ui.label(name);
            let (color, verdict) =
                if status.step_size <= *dt { (GREEN, "resolved") } else { (RED, "too coarse: impacts not resolved") };
            ui.colored_label(color, format!("{dt:.3e} s {verdict}"));
            ui.end_row();
        }
    });
}

/// The body a selected entity path (`world/bodies/<name>` or below) belongs to.
fn selected_body<'a>(path: &str, bodies: &'a [BodyStatus]) -> Option<&'a BodyStatus> {
    let name = tether_record::paths::body_of(path)?;
    bodies.iter().find(|b| b.name == name)
}

fn body_ui(ui: &mut egui::Ui, body: &BodyStatus) {
    ui.strong(format!("Selected body: {}", body.name));
    let v = |v: &tether_physics::math::Vec3| format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z);
    egui::Grid::new("selected body").num_columns(2).show(ui, |ui| {
        for (name, value, unit) in [
            ("position of G", &body.position, "m"),
            ("velocity of G", &body.velocity, "m/s"),
            ("angular velocity", &body.angular_velocity, "rad/s"),
        ] {
            ui.label(name);
            ui.label(format!("{} {unit}", v(value)));
            ui.end_row();
        }
    });
}
