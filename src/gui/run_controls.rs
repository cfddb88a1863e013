//! Run controls: play/pause (Space), one step (→), reset (Backspace), speed, and the time step
//! settings (integrator, dt, substeps) applied to the running simulation.

use super::number_field::number_field;
use super::simulation::{Speed, Status};
use crate::figures;
use rerun::external::egui;
use tether_physics::integrator::{Integrator, Substeps};
use tether_scene::SceneFile;

/// What the run controls ask for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RunAction {
    Play,
    Pause,
    Step,
    Reset,
    Speed(Speed),
    /// Draw the contacts' face forces as arrows in the viewer (or not).
    FaceArrows(bool),
    /// Apply the [`TimingDraft`].
    ApplyTiming,
}

/// The time step settings being edited, and why the last ones were refused.
#[derive(Debug, Clone, PartialEq)]
pub struct TimingDraft {
    /// World step [s].
    pub dt: f64,
    pub integrator: Integrator,
    /// `None`: `Auto`.
    pub substeps: Option<u32>,
    pub refusal: Option<String>,
}

impl Default for TimingDraft {
    fn default() -> Self {
        Self { dt: 1e-3, integrator: Integrator::default(), substeps: Some(1), refusal: None }
    }
}

impl TimingDraft {
    /// The settings a scene file gives.
    pub fn from_file(file: &SceneFile) -> Self {
        let substeps = match file.substeps {
            Substeps::Fixed(n) => Some(n),
            Substeps::Auto => None,
        };
        Self { dt: file.dt, integrator: file.integrator, substeps, refusal: None }
    }

    /// Writes the settings into a scene file.
    pub fn write_to(&self, file: &mut SceneFile) {
        file.dt = self.dt;
        file.integrator = self.integrator;
        file.substeps = self.substeps.map_or(Substeps::Auto, Substeps::Fixed);
    }
}

/// Speed factors offered (simulated seconds per wall second).
const FACTORS: [f64; 7] = [0.1, 0.25, 0.5, 1.0, 2.0, 5.0, 10.0];

/// Draws the controls; `status` is the simulation's latest.
pub fn ui(
    ui: &mut egui::Ui,
    status: Option<&Status>,
    timing: &mut TimingDraft,
    speed: &mut Speed,
    face_arrows: &mut bool,
) -> Vec<RunAction> {
    let mut actions = Vec::new();
    let running = status.is_some_and(|s| s.running);
    // Without a scene there is nothing to play, step or reset.
    ui.add_enabled_ui(status.is_some(), |ui| {
        ui.horizontal(|ui| {
            let (label, action) = if running { ("⏸ Pause", RunAction::Pause) } else { ("▶ Play", RunAction::Play) };
            if ui.button(label).on_hover_text("Space").clicked() {
                actions.push(action);
            }
            if ui.button("⏭ Step").on_hover_text("→: one world step").clicked() {
                actions.push(RunAction::Step);
            }
            if ui.button("⟲ Reset").on_hover_text("Backspace: back to t = 0, tuned values kept").clicked() {
                actions.push(RunAction::Reset);
            }
        });
    });
    if let Some(status) = status {
        ui.label(format!("t = {}   step {}", figures::quantity(status.time, "s", 5), figures::count(status.steps)));
        // The pace's row stays when paused, so nothing below moves on play and pause.
        ui.label(if status.running {
            let waiting = if status.waiting_for_viewer { ", waiting for the viewer" } else { "" };
            format!(
                "×{} real time, {} steps/s{waiting}",
                figures::number(status.rate, 2),
                figures::number(status.steps_per_second.round(), 3)
            )
        } else {
            "paused".to_string()
        });
        if let Some(failure) = &status.failure {
            ui.colored_label(ui.visuals().error_fg_color, format!("Paused: {failure}"));
        }
    }
    if let Some(new) = speed_ui(ui, *speed) {
        *speed = new;
        actions.push(RunAction::Speed(new));
    }
    if status.is_some_and(|s| !s.contacts.is_empty())
        && ui.checkbox(face_arrows, "Face forces as arrows").on_hover_text("Each contact's face forces drawn in the viewer, from now on (the contact force plots are always there)").changed()
    {
        actions.push(RunAction::FaceArrows(*face_arrows));
    }
    if timing_ui(ui, timing) {
        actions.push(RunAction::ApplyTiming);
    }
    actions
}

/// The speed selector; the new speed if it changed.
fn speed_ui(ui: &mut egui::Ui, speed: Speed) -> Option<Speed> {
    let label = |s: Speed| match s {
        Speed::Factor(f) => format!("×{f}"),
        Speed::Max => "as fast as possible".to_string(),
    };
    let mut chosen = speed;
    ui.horizontal(|ui| {
        ui.label("Speed");
        egui::ComboBox::from_id_salt("speed").selected_text(label(speed)).show_ui(ui, |ui| {
            for option in FACTORS.map(Speed::Factor).into_iter().chain([Speed::Max]) {
                ui.selectable_value(&mut chosen, option, label(option));
            }
        });
    });
    (chosen != speed).then_some(chosen)
}

/// Integrator, dt and substeps; true when the user asked to apply them.
fn timing_ui(ui: &mut egui::Ui, timing: &mut TimingDraft) -> bool {
    let mut apply = false;
    egui::Grid::new("timing").num_columns(3).show(ui, |ui| {
        ui.label("Integrator");
        egui::ComboBox::from_id_salt("integrator").selected_text(timing.integrator.name()).show_ui(ui, |ui| {
            for integrator in Integrator::ALL {
                apply |= ui.selectable_value(&mut timing.integrator, integrator, integrator.name()).clicked();
            }
        });
        ui.end_row();
        let label = ui.label("dt");
        let speed = timing.dt.abs().max(1e-6) * 0.01;
        let dt = number_field(ui, &mut timing.dt, speed).labelled_by(label.id);
        ui.label("s");
        apply |= dt.changed() && !dt.dragged() || dt.drag_stopped();
        ui.end_row();
        ui.label("Substeps");
        ui.horizontal(|ui| {
            let mut auto = timing.substeps.is_none();
            if ui
                .checkbox(&mut auto, "Auto")
                .on_hover_text("Enough to stay under 0.9 of the stable time step")
                .changed()
            {
                timing.substeps = if auto { None } else { Some(1) };
                apply = true;
            }
            if let Some(n) = &mut timing.substeps {
                apply |= number_field(ui, n, 0.1).changed();
            }
        });
        ui.label("per dt");
        ui.end_row();
    });
    if let Some(refusal) = &timing.refusal {
        ui.colored_label(ui.visuals().error_fg_color, refusal);
    }
    apply
}
