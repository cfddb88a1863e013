//! The water panel: the scene's waves, current and density, and each floating body's drag,
//! added-mass and linear damping coefficients, all live (PHYSICS.md §6). The knobs edit the open
//! scene's water and coefficient knobs' drafts (scene-file data, [`WaterDef`] and [`HydroDef`]);
//! the panel checks an edited draft with the scene builder (the same checks and messages as
//! loading) and sends the simulation what it accepts; a refused value stays in its knob with the
//! reason. A body with potential-flow data (PHYSICS.md §9) has a switch for it, which shows what
//! the simulation runs. Each knob's label and unit are the parameters catalogue's
//! (`tether_analysis::parameters::fields`).

use super::knobs::{Knob, Refused};
use super::tuning::{field_knob, knob};
use rerun::external::egui;
use std::fmt::Display;
use tether_analysis::parameters::fields;
use tether_physics::potential::{DriftModel, HydrostaticsModel};
use tether_scene::water::{CurrentDef, HydroDef, WaterDef, WavesDef};

/// What the water panel asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WaterAction {
    /// The water draft was edited.
    Water,
    /// Body `index`'s coefficients were edited.
    Hydro(usize),
    /// Body `body`'s potential flow switched on or off.
    PotentialFlow { body: usize, on: bool },
}

/// A floating body as the panel shows it.
pub struct FloatingKnobs<'a, R> {
    pub index: usize,
    pub name: &'a str,
    pub hydro: &'a mut HydroDef,
    /// Why its last edit was refused.
    pub refusals: &'a [Refused<R>],
    /// Whether its potential flow runs (`None`: it has no potential-flow data).
    pub potential_flow: Option<bool>,
    /// Whether its panel data hold mean drift coefficients (`.8`/`.9`): then its drift model is
    /// a knob.
    pub drift_data: bool,
}

/// The water's knobs, as the panel shows them; `R` is why a value was refused.
pub struct WaterKnobs<'a, R> {
    pub water: &'a mut Knob<WaterDef, R>,
    /// Each floating body.
    pub bodies: Vec<FloatingKnobs<'a, R>>,
}

/// Draws the water section; nothing for a scene without water.
pub fn ui<R: Display>(ui: &mut egui::Ui, knobs: Option<WaterKnobs<R>>) -> Vec<WaterAction> {
    let mut actions = Vec::new();
    let Some(WaterKnobs { water: Knob { draft: water, refusals: water_refusals }, bodies }) = knobs else {
        return actions;
    };
    egui::CollapsingHeader::new("Water").id_salt("water").default_open(true).show(ui, |ui| {
        let edited = egui::Grid::new("water knobs").num_columns(3).show(ui, |ui| water_knobs(ui, water)).inner;
        if edited {
            actions.push(WaterAction::Water);
        }
        for refused in water_refusals.iter() {
            ui.colored_label(ui.visuals().error_fg_color, format!("Refused: {refused}"));
        }
        for FloatingKnobs { index, name, hydro, refusals, potential_flow, drift_data } in bodies {
            ui.label(format!("body \"{name}\" in the water"));
            let linear = hydro.potential.as_ref().is_some_and(|p| p.hydrostatics == HydrostaticsModel::Linear);
            if let Some(running) = potential_flow
                && let Some(on) = potential_flow_switch(ui, running, linear)
            {
                actions.push(WaterAction::PotentialFlow { body: index, on });
            }
            let edited = egui::Grid::new(("hydro knobs", index))
                .num_columns(3)
                .show(ui, |ui| (drift_data && drift_choice(ui, index, hydro)) | hydro_knobs(ui, hydro))
                .inner;
            if edited {
                actions.push(WaterAction::Hydro(index));
            }
            for refused in refusals {
                ui.colored_label(ui.visuals().error_fg_color, format!("Refused: {refused}"));
            }
        }
    });
    actions
}

/// The switch of a body's potential flow, showing `running` (what the simulation runs) and,
/// when its scene asks for them (`linear`), that it brings the `.hst`'s linear hydrostatics; the
/// state asked for when clicked.
fn potential_flow_switch(ui: &mut egui::Ui, running: bool, linear: bool) -> Option<bool> {
    let mut on = running;
    let tip = "On: radiation and wave excitation from the panel code's files, A∞ in the body's mass. \
               Off: the body as without them (the incident wave's pressure on the hull, Morison's \
               added mass). Switched on again, the radiation memory restarts: the body as if at \
               rest before.";
    let (label, tip) = if linear {
        let more = " With it on, the buoyancy is linear, from the .hst file, about the pose at t = 0 \
                    (hydrostatics: Linear); off, the mesh's.";
        ("potential flow, linear hydrostatics (.hst)", format!("{tip}{more}"))
    } else {
        ("potential flow", tip.to_string())
    };
    ui.checkbox(&mut on, label).on_hover_text(tip).changed().then_some(on)
}

/// Waves (height, period, heading), current (speed, heading) and density; true when one was
/// edited. A current is added when its speed is first set.
fn water_knobs(ui: &mut egui::Ui, water: &mut WaterDef) -> bool {
    let mut edited = match &mut water.waves {
        WavesDef::Calm => {
            ui.label("waves");
            ui.label("calm");
            ui.end_row();
            false
        }
        WavesDef::Regular { height, period, heading_deg, .. } => {
            field_knob(ui, &fields::WAVE_HEIGHT, height)
                | field_knob(ui, &fields::WAVE_PERIOD, period)
                | field_knob(ui, &fields::WAVE_HEADING, heading_deg)
        }
        WavesDef::Jonswap { hs, tp, heading_deg, .. } => {
            field_knob(ui, &fields::SIGNIFICANT_HEIGHT, hs)
                | field_knob(ui, &fields::PEAK_PERIOD, tp)
                | field_knob(ui, &fields::WAVE_HEADING, heading_deg)
        }
    };
    let mut current =
        water.current.clone().unwrap_or(CurrentDef { speed: 0.0, heading_deg: 0.0, profile: Default::default() });
    if field_knob(ui, &fields::CURRENT_SPEED, &mut current.speed)
        | field_knob(ui, &fields::CURRENT_HEADING, &mut current.heading_deg)
    {
        water.current = Some(current);
        edited = true;
    }
    edited | field_knob(ui, &fields::WATER_DENSITY, &mut water.density)
}

/// The drift model of body `index`'s potential flow (PHYSICS.md §10), a grid row; true when
/// another was chosen.
fn drift_choice(ui: &mut egui::Ui, index: usize, hydro: &mut HydroDef) -> bool {
    let Some(potential) = &mut hydro.potential else { return false };
    let tip = "The second-order wave drift from the panel code's mean drift coefficients (.8/.9): \
               Off; Mean, the constant Σ a² D(ω); Newman, the mean and its slow variation at the \
               sea's difference frequencies (what excites a moored body's surge resonance).";
    let mut chosen = false;
    ui.label("wave drift").on_hover_text(tip);
    egui::ComboBox::from_id_salt(("drift model", index)).selected_text(potential.drift.name()).show_ui(ui, |ui| {
        for model in DriftModel::ALL {
            chosen |= ui.selectable_value(&mut potential.drift, model, model.name()).clicked();
        }
    });
    ui.label("");
    ui.end_row();
    chosen
}

/// Drag, added-mass and linear damping coefficients per body axis; true when one was edited.
fn hydro_knobs(ui: &mut egui::Ui, hydro: &mut HydroDef) -> bool {
    let mut edited = false;
    for (field, values) in [
        (&fields::HYDRO_DRAG, &mut hydro.drag),
        (&fields::HYDRO_ADDED_MASS, &mut hydro.added_mass),
        (&fields::HYDRO_LINEAR_DAMPING, &mut hydro.linear_damping),
    ] {
        for (axis, value) in values.iter_mut().enumerate() {
            let (_, label) = field.axis(axis);
            edited |= knob(ui, &label, value, field.unit);
        }
    }
    edited
}
