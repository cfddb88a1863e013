//! Live indicators: the energy balance (PHYSICS.md §5) with a plot of its drift, the integrator
//! step against the stable time step of every coupling (green: under it, red: over it), and the
//! state of the body selected in the viewer.

use super::simulation::{BodyStatus, Status};
use crate::figures;
use rerun::external::egui;
use std::collections::VecDeque;
use tether_physics::energy::EnergyReport;

/// Points kept for the drift plot.
const HISTORY: usize = 600;

const GREEN: egui::Color32 = egui::Color32::from_rgb(60, 180, 75);
const RED: egui::Color32 = egui::Color32::from_rgb(230, 60, 50);

/// The balance drift `balance(t) − balance(0)` [J] against simulated time [s], and the energy
/// the run has exchanged, which the drift is read against.
#[derive(Debug, Clone, Default)]
pub struct EnergyHistory {
    points: VecDeque<(f64, f64)>,
    /// The energy account at the first point (t = 0 after a load or a reset).
    start: Option<EnergyReport>,
    /// The largest energy moved since the start \[J]: see [`exchanged`].
    exchanged: f64,
}

/// The energy a run has moved between its forms since `start` \[J]: half the sum of the changes
/// of kinetic, gravity and elastic energy and of what was dissipated and put in as external
/// work, each as a magnitude (every joule that moves leaves one form and enters another, so
/// each is counted twice in the sum). The spring-mass released 0.1 m out on k = 100 N/m has
/// moved 0.5 J at its centre. The balance drift is read against the largest of it so far, as
/// the integrator study reads its energy error against the energy its reference run holds —
/// never against a total, which can be zero.
pub fn exchanged(start: &EnergyReport, now: &EnergyReport) -> f64 {
    0.5 * ((now.kinetic - start.kinetic).abs()
        + (now.gravity - start.gravity).abs()
        + (now.elastic - start.elastic).abs()
        + (now.dissipated - start.dissipated).abs()
        + (now.external_work - start.external_work).abs())
}

impl EnergyHistory {
    /// Adds a status's point (a time that went back starts the plot again: a reset or a load).
    pub fn push(&mut self, status: &Status) {
        if self.points.back().is_some_and(|&(t, _)| status.time < t) {
            *self = Self::default();
        }
        if self.points.back().is_some_and(|&(t, _)| t == status.time) {
            return;
        }
        if self.points.len() == HISTORY {
            self.points.pop_front();
        }
        let start = self.start.get_or_insert(status.energy);
        self.exchanged = self.exchanged.max(exchanged(start, &status.energy));
        self.points.push_back((status.time, status.energy.balance() - status.initial_balance));
    }

    /// The largest energy exchanged so far \[J].
    pub fn largest_exchange(&self) -> f64 {
        self.exchanged
    }
}

/// The drift as the panel words it: `+1.2×10⁻⁹ J (3.1×10⁻¹⁰ of the 3.9 J exchanged)`, or
/// with nothing exchanged yet, the drift alone.
pub fn drift_text(drift: f64, exchanged: f64) -> String {
    let absolute = figures::change(drift, "J", 3);
    if exchanged > 0.0 {
        let relative = figures::signed(drift / exchanged, 3);
        format!("{absolute} ({relative} of the {} exchanged)", figures::quantity(exchanged, "J", 3))
    } else {
        format!("{absolute} (no energy exchanged yet)")
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

/// The ledger's resolution \[J] for the energies `e` after `exchanged` \[J] moved: 10⁻¹² of its
/// largest entry (each entry is a sum of terms that size, so it is known to about 10⁻¹⁵ of it;
/// a margin of a thousand for the sums of a long run).
fn resolution(e: &EnergyReport, exchanged: f64) -> f64 {
    let entries = [e.kinetic, e.gravity, e.elastic, e.dissipated, e.external_work, exchanged];
    1e-12 * entries.iter().fold(0.0_f64, |largest, x| largest.max(x.abs()))
}

/// `value` \[J] as the panel shows it: 0 below the ledger's `resolution` (an elastic energy of
/// 1.8×10⁻²⁸ J at rest beside 32 kJ of gravity is round-off, not a figure).
fn resolved(value: f64, resolution: f64) -> f64 {
    if value.abs() < resolution { 0.0 } else { value }
}

fn energy_ui(ui: &mut egui::Ui, status: &Status, history: &EnergyHistory) {
    let e = &status.energy;
    let resolution = resolution(e, history.largest_exchange());
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
            ui.label(figures::quantity(resolved(value, resolution), "J", 4));
            ui.end_row();
        }
    });
    // Its own line, which wraps: a grid's cell would widen the panel.
    let drift = e.balance() - status.initial_balance;
    ui.label(format!("balance drift {}", drift_text(drift, history.largest_exchange())));
    drift_plot(ui, history);
}

/// A small line plot of the drift, scaled to its range, its scale written above it (not over
/// the curve).
fn drift_plot(ui: &mut egui::Ui, history: &EnergyHistory) {
    let largest = history.points.iter().fold(0.0_f64, |m, &(_, d)| m.max(d.abs()));
    ui.label(
        egui::RichText::new(format!("drift, full scale ±{}", figures::quantity(largest, "J", 2)))
            .small()
            .color(ui.visuals().weak_text_color()),
    );
    let (rect, _) = ui.allocate_exact_size(egui::vec2(ui.available_width().min(360.0), 60.0), egui::Sense::hover());
    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 2.0, ui.visuals().extreme_bg_color);
    let points = &history.points;
    let (Some(first), Some(last)) = (points.front(), points.back()) else { return };
    let span = (last.0 - first.0).max(f64::MIN_POSITIVE);
    let extent = largest.max(f64::MIN_POSITIVE);
    let to_screen = |&(t, d): &(f64, f64)| {
        let x = rect.left() + rect.width() * ((t - first.0) / span) as f32;
        let y = rect.center().y - 0.45 * rect.height() * (d / extent) as f32;
        egui::pos2(x, y)
    };
    painter.hline(rect.x_range(), rect.center().y, egui::Stroke::new(1.0, ui.visuals().weak_text_color()));
    let line: Vec<egui::Pos2> = points.iter().map(to_screen).collect();
    painter.add(egui::Shape::line(line, egui::Stroke::new(1.5, ui.visuals().strong_text_color())));
}

/// The integrator step against each stable time step.
fn stability_ui(ui: &mut egui::Ui, status: &Status) {
    ui.strong("Stable time step");
    ui.label(format!(
        "integrator step {} ({} substep{} per dt)",
        figures::quantity(status.step_size, "s", 4),
        figures::count(status.substeps),
        if status.substeps == 1 { "" } else { "s" }
    ));
    egui::Grid::new("stability").num_columns(2).show(ui, |ui| {
        let substeps = status.line_substeps.iter().copied().chain(std::iter::repeat(None));
        let couplings = status.coupling_limits.iter().cloned().zip(substeps);
        let rotation =
            status.rotation_limit.iter().map(|(body, dt)| ((format!("rotation of {body}"), Some(*dt)), None));
        let water = status.water_limits.iter().map(|(body, dt)| ((format!("water on {body}"), Some(*dt)), None));
        let air = status.air_limits.iter().map(|(body, dt)| ((format!("air on {body}"), Some(*dt)), None));
        for ((name, limit), substeps) in couplings.chain(rotation).chain(water).chain(air) {
            ui.label(name);
            let (color, text) = match limit {
                Some(dt) => {
                    let (color, verdict) =
                        if status.step_size <= dt { (GREEN, "ok") } else { (RED, "too large: will diverge") };
                    (color, format!("{} {verdict}", figures::quantity(dt, "s", 4)))
                }
                None => (GREEN, "no limit".to_string()),
            };
            let text = match substeps {
                Some(substeps) => format!("{text}; {}", substeps_text(substeps)),
                None => text,
            };
            ui.add(egui::Label::new(egui::RichText::new(text).color(color)).wrap());
            ui.end_row();
        }
        for (name, dt) in &status.impact_limits {
            ui.label(name);
            let (color, verdict) =
                if status.step_size <= *dt { (GREEN, "resolved") } else { (RED, "too coarse: impacts not resolved") };
            ui.colored_label(color, format!("{} {verdict}", figures::quantity(*dt, "s", 4)));
            ui.end_row();
        }
    });
}

/// What a dynamic line's own nodes step by within each integrator step (PHYSICS.md §8): its
/// count of sub-steps and their length, `its nodes: 26 sub-steps of 1.923 ms`. The limit beside
/// it is the bodies' step's (the line's first segments on its end bodies): a line between two
/// ends that forces do not move sets none, and its nodes still step at their own.
fn substeps_text((count, length): (u32, f64)) -> String {
    format!(
        "its nodes: {} sub-step{} of {}",
        figures::count(count),
        if count == 1 { "" } else { "s" },
        figures::quantity(length, "s", 4)
    )
}

/// The body a selected entity path (`world/bodies/<name>` or below) belongs to.
fn selected_body<'a>(path: &str, bodies: &'a [BodyStatus]) -> Option<&'a BodyStatus> {
    let name = tether_record::paths::body_of(path)?;
    bodies.iter().find(|b| b.name == name)
}

fn body_ui(ui: &mut egui::Ui, body: &BodyStatus) {
    ui.strong(format!("Selected body: {}", body.name));
    let v = |v: &tether_physics::math::Vec3| {
        format!("({}, {}, {})", figures::number(v.x, 4), figures::number(v.y, 4), figures::number(v.z, 4))
    };
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

#[cfg(test)]
mod tests {
    use super::*;

    fn energy(kinetic: f64, elastic: f64, dissipated: f64) -> EnergyReport {
        EnergyReport { kinetic, gravity: 0.0, elastic, dissipated, external_work: 0.0 }
    }

    /// The spring-mass (k = 100 N/m, released 0.1 m out: ½ k x² = 0.5 J): at its centre all of
    /// it is kinetic, 0.5 J moved; damped to rest, 0.5 J moved into the damper. The issue's
    /// drift of 1.678×10⁻¹⁵ J reads against that, not against a total near zero.
    #[test]
    fn the_drift_reads_against_the_energy_the_run_moved() {
        let start = energy(0.0, 0.5, 0.0);
        assert_eq!(exchanged(&start, &start), 0.0);
        assert_eq!(exchanged(&start, &energy(0.5, 0.0, 0.0)), 0.5);
        assert_eq!(exchanged(&start, &energy(0.0, 0.0, 0.5)), 0.5);
        assert_eq!(exchanged(&start, &energy(0.125, 0.125, 0.25)), 0.375);
        assert_eq!(drift_text(1.678e-15, 0.5), "+1.68×10⁻¹⁵ J (+3.36×10⁻¹⁵ of the 500 mJ exchanged)");
        assert_eq!(drift_text(0.0, 0.0), "0 J (no energy exchanged yet)");
        assert_eq!(drift_text(-2.0e-3, 6.9e6), "-2 mJ (-2.9×10⁻¹⁰ of the 6.9 MJ exchanged)");
    }

    /// Issue 47: `chain_forced_surge`'s dynamic chain read "no limit" (its ends do not respond to
    /// forces) while its nodes step at their own step: the row says both.
    #[test]
    fn a_dynamic_line_says_what_its_nodes_step_by() {
        assert_eq!(substeps_text((26, 1.923e-3)), "its nodes: 26 sub-steps of 1.923 ms");
        assert_eq!(substeps_text((1, 0.05)), "its nodes: 1 sub-step of 50 ms");
    }

    /// Issue 47: moored_buoy at rest showed `elastic 1.756×10⁻²⁸ J` beside 32 kJ of gravity;
    /// below 10⁻¹² of the ledger's largest entry a figure is round-off and reads 0, above it the
    /// figure stands (a spring-mass's 0.5 J, a lone 1.8×10⁻²⁸ J with nothing larger beside it).
    #[test]
    fn round_off_reads_zero() {
        let at_rest = EnergyReport { gravity: -3.2e4, elastic: 1.756e-28, ..EnergyReport::default() };
        let fine = resolution(&at_rest, 0.0);
        assert!((fine - 3.2e-8).abs() < 1e-22, "{fine}");
        assert_eq!(resolved(at_rest.elastic, fine), 0.0);
        assert_eq!(resolved(at_rest.gravity, fine), -3.2e4);
        assert_eq!(resolved(0.5, resolution(&energy(0.0, 0.5, 0.0), 0.5)), 0.5);
        let alone = energy(0.0, 1.756e-28, 0.0);
        assert_eq!(resolved(alone.elastic, resolution(&alone, 0.0)), 1.756e-28);
    }
}
