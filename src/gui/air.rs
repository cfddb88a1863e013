//! The air panel: the scene's wind (speed at its reference height, heading), its gusts
//! (steady, NPD or Kaimal, and their seed) and the air's density, all live (PHYSICS.md §10).
//! The knobs edit the open scene's air knob's draft (scene-file data, [`AirDef`]); the panel
//! checks an edited draft with the scene builder (the same checks and messages as loading) and
//! sends the simulation what it accepts; a refused value stays in its knob with the reason.

use super::knobs::Knob;
use super::tuning::field_knob;
use rerun::external::egui;
use std::fmt::Display;
use tether_analysis::parameters::fields;
use tether_scene::air::{AirDef, GustKind, GustsDef};

/// Draws the air section; true when its draft was edited. Nothing for a scene without air.
pub fn ui<R: Display>(ui: &mut egui::Ui, knob: Option<&mut Knob<AirDef, R>>) -> bool {
    let Some(Knob { draft: air, refusals }) = knob else { return false };
    egui::CollapsingHeader::new("Air")
        .id_salt("air")
        .default_open(true)
        .show(ui, |ui| {
            let edited = egui::Grid::new("air knobs").num_columns(3).show(ui, |ui| air_knobs(ui, air)).inner;
            for refused in refusals.iter() {
                ui.colored_label(ui.visuals().error_fg_color, format!("Refused: {refused}"));
            }
            edited
        })
        .body_returned
        .unwrap_or(false)
}

/// Wind speed, its height and heading, the gusts and the density; true when one was edited.
fn air_knobs(ui: &mut egui::Ui, air: &mut AirDef) -> bool {
    let wind = &mut air.wind;
    field_knob(ui, &fields::WIND_SPEED, &mut wind.speed)
        | field_knob(ui, &fields::WIND_HEIGHT, &mut wind.height)
        | field_knob(ui, &fields::WIND_HEADING, &mut wind.heading_deg)
        | gusts_knobs(ui, &mut wind.gusts)
        | field_knob(ui, &fields::AIR_DENSITY, &mut air.density)
}

/// The gusts' spectrum, and its seed (and a Kaimal wind's intensity); true when one was edited.
fn gusts_knobs(ui: &mut egui::Ui, gusts: &mut GustsDef) -> bool {
    let tip = "Steady: the mean wind alone. NPD: the offshore gust spectrum of API RP 2A and ISO \
               19901-1, its intensity from the mean speed. Kaimal: IEC 61400-1's, at the given \
               turbulence intensity. The same seed gives the same wind, bit for bit.";
    ui.label("gusts").on_hover_text(tip);
    let mut chosen = gusts.kind();
    egui::ComboBox::from_id_salt("gusts").selected_text(chosen.name()).show_ui(ui, |ui| {
        for kind in GustKind::ALL {
            ui.selectable_value(&mut chosen, kind, kind.name());
        }
    });
    ui.label("");
    ui.end_row();
    let mut edited = chosen != gusts.kind();
    if edited {
        *gusts = gusts.of_kind(chosen);
    }
    match gusts {
        GustsDef::Steady => {}
        GustsDef::Npd { seed, .. } => edited |= field_knob(ui, &fields::GUST_SEED, seed),
        GustsDef::Kaimal { intensity, seed, .. } => {
            edited |=
                field_knob(ui, &fields::TURBULENCE_INTENSITY, intensity) | field_knob(ui, &fields::GUST_SEED, seed);
        }
    }
    edited
}
