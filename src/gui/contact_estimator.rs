//! The contact estimator (PHYSICS.md §4): from the impact a contact must stop — normal speed
//! `v`, the distance `d_min` where it must be stopped, a damping ratio `ζ` — the stiffness
//! `k1`, damping `k2`, stopping time `τ` and the time step that resolves it, for each contact of
//! the running scene (its masses, expected area `A` and range `d0`). "Use k1, k2" puts them in
//! the contact's knobs, which tune the running simulation as any edit does.

use super::number_field::number_field;
use super::simulation::ContactStatus;
use crate::figures;
use rerun::external::egui;
use tether_physics::coupling::contact::estimator::{self, Impact};

/// The impact being estimated for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactDraft {
    /// `v` [m/s] > 0.
    pub speed: f64,
    /// `d_min` [m] < d0.
    pub min_distance: f64,
    /// `ζ` [–] ≥ 0.
    pub damping_ratio: f64,
}

impl Default for ImpactDraft {
    fn default() -> Self {
        Self { speed: 1.0, min_distance: -0.005, damping_ratio: 0.1 }
    }
}

/// What the estimator asks for: contact `index`'s knobs set to these k1 [N/m³] and k2 [N·s/m³].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UseEstimate {
    pub index: usize,
    pub stiffness: f64,
    pub damping: f64,
}

/// Draws the estimator for every contact (nothing without one).
pub fn ui(ui: &mut egui::Ui, contacts: &[ContactStatus], impact: &mut ImpactDraft) -> Option<UseEstimate> {
    if contacts.is_empty() {
        return None;
    }
    ui.strong("Contact estimator");
    egui::Grid::new("impact").num_columns(3).show(ui, |ui| {
        for (label, value, unit) in [
            ("impact speed v", &mut impact.speed, "m/s"),
            ("stopped at d_min", &mut impact.min_distance, "m"),
            ("damping ratio ζ", &mut impact.damping_ratio, "–"),
        ] {
            let name = ui.label(label);
            let speed = 0.001_f64.max(value.abs() * 0.01);
            number_field(ui, value, speed).labelled_by(name.id);
            ui.label(unit);
            ui.end_row();
        }
    });
    let mut chosen = None;
    for contact in contacts {
        let estimate = estimator::estimate(&Impact {
            mass: contact.mass,
            other_mass: contact.other_mass,
            area: contact.area,
            speed: impact.speed,
            range: contact.range,
            min_distance: impact.min_distance,
            damping_ratio: impact.damping_ratio,
        });
        ui.label(format!(
            "{} (m_e from {} kg, A = {} m², d0 = {})",
            contact.name,
            figures::number(contact.mass, 4),
            figures::number(contact.area, 4),
            figures::quantity(contact.range, "m", 4)
        ));
        match estimate {
            Ok(e) => {
                ui.label(format!(
                    "k1 = {}   k2 = {}",
                    figures::quantity(e.stiffness, "N/m³", 4),
                    figures::quantity(e.damping, "N·s/m³", 4)
                ));
                ui.label(format!(
                    "τ = {}   recommended dt ≤ {}",
                    figures::quantity(e.stopping_time, "s", 4),
                    figures::quantity(e.recommended_dt, "s", 4)
                ));
                if ui.button(format!("Use k1, k2 for {}", contact.name)).clicked() {
                    chosen = Some(UseEstimate { index: contact.index, stiffness: e.stiffness, damping: e.damping });
                }
            }
            Err(error) => {
                ui.colored_label(ui.visuals().error_fg_color, error.to_string());
            }
        }
    }
    chosen
}
