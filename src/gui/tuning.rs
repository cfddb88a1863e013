//! Live tuning: every parameter of every coupling, with its unit, edited in place (spring law
//! coefficients and tables, rest length, damping; catenary λ0, L_eq, D; contact k1, k2, d0, μ,
//! k_t and the expected area when the scene sets it). The knobs
//! edit the open scene's coupling knobs' drafts (scene-file data, [`CouplingDef`]); the panel
//! checks an edited draft with the scene builder and sends the simulation the coupling it
//! builds. "Revert to file" and "save as" act on the whole scene.
//!
//! The matches on [`CouplingDef`] and [`LawDef`] are exhaustive: a new coupling kind or elastic
//! law does not compile until it has its knobs here.

use super::knobs::Knob;
use super::number_field::number_field;
use crate::line_hint::Measures;
use rerun::external::egui;
use rerun::external::egui::emath::Numeric;
use std::fmt::Display;
use tether_analysis::parameters::fields::{self, Field};
use tether_physics::coupling::{InternalDamping, LumpedMassSpec};
use tether_scene::SceneFile;
use tether_scene::file::{CouplingDef, LawDef};
use tether_scene::line_model::LineModelDef;

/// What the tuning panel asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TuningAction {
    /// Draft `index` was edited: check it and apply it.
    Edited(usize),
    Revert,
    SaveAs,
}

/// Draws a section per coupling with its knobs and why a value was refused; `file` is what the
/// scene file says (edited couplings are marked); `hints`, by coupling, what the running world
/// says of each driven quasi-static line (`crate::line_hint`), shown under its model switch.
pub fn ui(
    ui: &mut egui::Ui,
    knobs: &mut [Knob<CouplingDef, impl Display>],
    file: &SceneFile,
    hints: &[Option<Measures>],
) -> Vec<TuningAction> {
    let mut actions = Vec::new();
    ui.horizontal(|ui| {
        ui.strong("Couplings");
        if ui
            .button("Revert to file")
            .on_hover_text("Every coupling and the water back to what the scene file says")
            .clicked()
        {
            actions.push(TuningAction::Revert);
        }
        if ui.button("Save as…").on_hover_text("Write the scene with the tuned values (RON)").clicked() {
            actions.push(TuningAction::SaveAs);
        }
    });
    if knobs.is_empty() {
        ui.label("This scene has no couplings.");
    }
    for (index, Knob { draft, refusals }) in knobs.iter_mut().enumerate() {
        let edited = file.couplings.get(index) != Some(&*draft);
        let title = format!("{}{} ({})", draft.name(), if edited { " •" } else { "" }, kind_name(draft));
        egui::CollapsingHeader::new(title).id_salt(("coupling", index)).default_open(index < 4).show(ui, |ui| {
            if coupling_knobs(ui, index, draft) {
                actions.push(TuningAction::Edited(index));
            }
            if let Some(Some(measures)) = hints.get(index) {
                line_hint(ui, measures);
            }
            for refused in refusals.iter() {
                ui.colored_label(ui.visuals().error_fg_color, format!("Refused: {refused}"));
            }
        });
    }
    actions
}

fn kind_name(def: &CouplingDef) -> &'static str {
    match def {
        CouplingDef::SpringDamper { .. } => "spring-damper",
        CouplingDef::Catenary { .. } => "catenary",
        CouplingDef::Contact { .. } => "contact",
    }
}

/// A quasi-static line's measures against its fairlead, in the warning colour when they
/// suggest `Dynamic`.
fn line_hint(ui: &mut egui::Ui, measures: &Measures) {
    let text = egui::RichText::new(measures.to_string()).small();
    if measures.suggests_dynamic() {
        ui.add(egui::Label::new(text.color(ui.visuals().warn_fg_color)).wrap());
    } else {
        ui.add(egui::Label::new(text.weak()).wrap());
    }
}

/// The knobs of one coupling; true when one was edited.
fn coupling_knobs(ui: &mut egui::Ui, index: usize, def: &mut CouplingDef) -> bool {
    egui::Grid::new(("knobs", index))
        .num_columns(3)
        .show(ui, |ui| match def {
            CouplingDef::SpringDamper { law, damping, .. } => {
                law_knobs(ui, law) | field_knob(ui, &fields::SPRING_DAMPING, damping)
            }
            CouplingDef::Catenary { mass_per_length, length, stiffness, displaced_area, model, .. } => {
                field_knob(ui, &fields::MASS_PER_LENGTH, mass_per_length)
                    | field_knob(ui, &fields::LENGTH, length)
                    | field_knob(ui, &fields::LINE_STIFFNESS, stiffness)
                    | field_knob(ui, &fields::DISPLACED_AREA, displaced_area)
                    | line_model_knobs(ui, model)
            }
            CouplingDef::Contact { stiffness, damping, range, friction, friction_sharpness, expected_area, .. } => {
                let law = field_knob(ui, &fields::CONTACT_STIFFNESS, stiffness)
                    | field_knob(ui, &fields::CONTACT_DAMPING, damping)
                    | field_knob(ui, &fields::RANGE, range)
                    | field_knob(ui, &fields::FRICTION, friction)
                    | field_knob(ui, &fields::FRICTION_SHARPNESS, friction_sharpness);
                law | expected_area.as_mut().is_some_and(|area| field_knob(ui, &fields::EXPECTED_AREA, area))
            }
        })
        .inner
}

/// A line's model (PHYSICS.md §3 quasi-static, §8 dynamic): the switch, and a dynamic line's
/// segments, internal damping, drag and added mass. Switched to dynamic, a line takes 20
/// segments, ζ = 0.8 and a wire's coefficients (C_dn 1.2, C_dt 0.008, C_an 1, C_at 0), and
/// starts from its quasi-static shape where it is.
fn line_model_knobs(ui: &mut egui::Ui, model: &mut LineModelDef) -> bool {
    let name = ui.label("line model");
    let mut dynamic = !model.is_quasi_static();
    let switched = ui.checkbox(&mut dynamic, "dynamic (lumped mass)").labelled_by(name.id).changed();
    ui.label("");
    ui.end_row();
    if switched {
        *model = if dynamic { LineModelDef::Dynamic(LumpedMassSpec::wire(20)) } else { LineModelDef::QuasiStatic };
    }
    let edited = match model {
        LineModelDef::QuasiStatic => false,
        LineModelDef::Dynamic(line) => {
            let damping = match &mut line.damping {
                InternalDamping::Ratio(zeta) => field_knob(ui, &fields::DAMPING_RATIO, zeta),
                InternalDamping::Coefficient(ba) => field_knob(ui, &fields::DAMPING_BA, ba),
            };
            field_knob(ui, &fields::SEGMENTS, &mut line.segments)
                | damping
                | field_knob(ui, &fields::DRAG_NORMAL, &mut line.drag_normal)
                | field_knob(ui, &fields::DRAG_TANGENTIAL, &mut line.drag_tangential)
                | field_knob(ui, &fields::ADDED_MASS_NORMAL, &mut line.added_mass_normal)
                | field_knob(ui, &fields::ADDED_MASS_TANGENTIAL, &mut line.added_mass_tangential)
        }
    };
    switched | edited
}

/// The knobs of an elastic law (PHYSICS.md §2).
fn law_knobs(ui: &mut egui::Ui, law: &mut LawDef) -> bool {
    match law {
        LawDef::Linear { stiffness, rest_length } => {
            field_knob(ui, &fields::LAW_STIFFNESS, stiffness) | field_knob(ui, &fields::LAW_REST_LENGTH, rest_length)
        }
        LawDef::Polynomial { a, b, c, rest_length } => {
            field_knob(ui, &fields::LAW_A, a)
                | field_knob(ui, &fields::LAW_B, b)
                | field_knob(ui, &fields::LAW_C, c)
                | field_knob(ui, &fields::LAW_REST_LENGTH, rest_length)
        }
        LawDef::ForceCurve { points } => table_knobs(ui, points, &fields::FORCE_CURVE_X, &fields::FORCE_CURVE_F),
        LawDef::StiffnessCurve { points, rest_length } => {
            table_knobs(ui, points, &fields::STIFFNESS_CURVE_XI, &fields::STIFFNESS_CURVE_K)
                | field_knob(ui, &fields::LAW_REST_LENGTH, rest_length)
        }
        LawDef::ReferenceForce { points, reference_length, reference_force, rest_length } => {
            table_knobs(ui, points, &fields::STIFFNESS_CURVE_XI, &fields::STIFFNESS_CURVE_K)
                | field_knob(ui, &fields::LAW_REFERENCE_LENGTH, reference_length)
                | field_knob(ui, &fields::LAW_REFERENCE_FORCE, reference_force)
                | field_knob(ui, &fields::LAW_REST_LENGTH, rest_length)
        }
    }
}

/// One number (a real, or a count) with its label and unit, in a grid row; true when it was
/// edited. The drag speed is 1 % of the value, so a knob tunes coarse and fine values alike;
/// typing any number works, and the scene builder refuses the bad ones.
pub(super) fn knob(ui: &mut egui::Ui, label: &str, value: &mut impl Numeric, unit: &str) -> bool {
    let name = ui.label(label);
    let speed = value.to_f64().abs().max(1e-3) * 0.01;
    let response = number_field(ui, value, speed).labelled_by(name.id);
    ui.label(unit);
    ui.end_row();
    response.changed()
}

/// A knob over a catalogued field ([`fields`]): its label and unit as the catalogue lists them.
pub(super) fn field_knob(ui: &mut egui::Ui, field: &Field, value: &mut impl Numeric) -> bool {
    knob(ui, field.label, value, field.unit)
}

/// The points of a table, one grid row each: `x [m] … f [N] …`.
fn table_knobs(ui: &mut egui::Ui, points: &mut [(f64, f64)], x: &Field, y: &Field) -> bool {
    let mut edited = false;
    for (row, (px, py)) in points.iter_mut().enumerate() {
        let name = ui.label(format!("point {}", row + 1));
        ui.horizontal(|ui| {
            for (value, field) in [(px, x), (py, y)] {
                ui.label(field.label);
                let speed = value.abs().max(1e-3) * 0.01;
                edited |= number_field(ui, value, speed).labelled_by(name.id).changed();
                ui.label(field.unit);
            }
        });
        ui.end_row();
    }
    edited
}
