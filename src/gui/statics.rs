//! The statics panel (PHYSICS.md §7): the seabed's line friction `C_B`, live (the open scene's
//! seabed knob, checked by the scene builder as the other knobs are); an
//! "equilibrium" button that puts the scene at its static pose; the offset curve of a body (the
//! one selected in the viewer, or chosen here) drawn as the restoring force against the offset.
//! A line's displaced area `A_d` is tuned with its other knobs ([`super::tuning`]).

use super::knobs::Knob;
use super::line_plot::{self, Framed};
use super::number_field::number_field;
use super::simulation::OffsetCurve;
use super::tuning::{field_knob, knob};
use crate::figures;
use rerun::external::egui;
use std::fmt::Display;
use tether_analysis::parameters::fields;
use tether_physics::statics::Direction;
use tether_scene::file::SeabedDef;

/// What the panel asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum StaticsAction {
    /// The seabed knob's draft was edited.
    Seabed,
    Equilibrium,
    OffsetCurve {
        body: usize,
        direction: Direction,
        to: f64,
        steps: u32,
    },
}

/// What the panel's knobs show.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticsDraft {
    /// The body chosen for the offset curve (index), when none is selected in the viewer.
    pub body: usize,
    pub direction: Direction,
    /// The largest offset [m or rad] and the number of offsets.
    pub to: f64,
    pub steps: u32,
    /// The last curve computed.
    pub curve: Option<OffsetCurve>,
}

impl Default for StaticsDraft {
    /// A newly opened scene's: the first body's offset curve in x, to 10 m in 20 offsets.
    fn default() -> Self {
        Self { body: 0, direction: Direction::X, to: 10.0, steps: 20, curve: None }
    }
}

/// Draws the panel for a scene with `bodies` (names) and its seabed knob (`None`: no seabed);
/// `selected` is the body selected in the viewer, if any.
pub fn ui<R: Display>(
    ui: &mut egui::Ui,
    draft: &mut StaticsDraft,
    seabed: Option<&mut Knob<SeabedDef, R>>,
    bodies: &[String],
    selected: Option<&str>,
) -> Vec<StaticsAction> {
    let mut actions = Vec::new();
    egui::CollapsingHeader::new("Statics and seabed").id_salt("statics").default_open(true).show(ui, |ui| {
        if let Some(Knob { draft: seabed, refusals }) = seabed {
            let edited = egui::Grid::new("seabed knobs")
                .num_columns(3)
                .show(ui, |ui| field_knob(ui, &fields::LINE_FRICTION, &mut seabed.line_friction))
                .inner;
            if edited {
                actions.push(StaticsAction::Seabed);
            }
            for refused in refusals.iter() {
                ui.colored_label(ui.visuals().error_fg_color, format!("Refused: {refused}"));
            }
        }
        if ui
            .button("Equilibrium")
            .on_hover_text("Put every free body at its static pose, at rest (tether equilibrium)")
            .clicked()
        {
            actions.push(StaticsAction::Equilibrium);
        }
        if bodies.is_empty() {
            return;
        }
        if let Some(index) = selected.and_then(|name| bodies.iter().position(|b| b == name)) {
            draft.body = index;
        }
        draft.body = draft.body.min(bodies.len() - 1);
        ui.horizontal(|ui| {
            egui::ComboBox::from_id_salt("offset body").selected_text(&bodies[draft.body]).show_ui(ui, |ui| {
                for (index, name) in bodies.iter().enumerate() {
                    ui.selectable_value(&mut draft.body, index, name);
                }
            });
            egui::ComboBox::from_id_salt("offset direction").selected_text(draft.direction.name()).show_ui(ui, |ui| {
                for direction in Direction::ALL {
                    ui.selectable_value(&mut draft.direction, direction, direction.name());
                }
            });
        });
        egui::Grid::new("offset knobs").num_columns(3).show(ui, |ui| {
            knob(ui, "to", &mut draft.to, draft.direction.unit());
            ui.label("offsets");
            number_field(ui, &mut draft.steps, 0.1);
            draft.steps = draft.steps.clamp(1, 200);
            ui.end_row();
        });
        let valid = draft.to.is_finite() && draft.to != 0.0;
        if ui
            .add_enabled(valid, egui::Button::new("Offset curve"))
            .on_hover_text("The restoring force held at offsets from equilibrium (tether offsets)")
            .clicked()
        {
            actions.push(StaticsAction::OffsetCurve {
                body: draft.body,
                direction: draft.direction,
                to: draft.to,
                steps: draft.steps,
            });
        }
        if let Some(curve) = &draft.curve {
            plot(ui, curve);
        }
    });
    actions
}

/// The curve as a line in a framed box, with its ranges written at the axes.
fn plot(ui: &mut egui::Ui, curve: &OffsetCurve) {
    ui.label(format!("body \"{}\": restoring force against offset in {}", curve.body, curve.direction));
    let Some(Framed { painter, rect, x: (x0, x1), y: (y0, y1), line }) = line_plot::frame(ui, &curve.points, 160.0)
    else {
        return;
    };
    painter.add(egui::Shape::line(line, egui::Stroke::new(2.0, ui.visuals().hyperlink_color)));
    let text = ui.visuals().text_color();
    let font = egui::FontId::proportional(11.0);
    let (unit, load) = (curve.direction.unit(), curve.direction.load_unit());
    painter.text(
        rect.left_top() + egui::vec2(4.0, 2.0),
        egui::Align2::LEFT_TOP,
        figures::quantity(y1, load, 4),
        font.clone(),
        text,
    );
    painter.text(
        rect.left_bottom() + egui::vec2(4.0, -2.0),
        egui::Align2::LEFT_BOTTOM,
        figures::quantity(y0, load, 4),
        font.clone(),
        text,
    );
    painter.text(
        rect.right_bottom() + egui::vec2(-4.0, -2.0),
        egui::Align2::RIGHT_BOTTOM,
        format!("offset {} … {}", figures::quantity(x0, unit, 3), figures::quantity(x1, unit, 3)),
        font,
        text,
    );
}
