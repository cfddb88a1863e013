//! The statics panel (PHYSICS.md §7): the seabed's line friction `C_B`, live; an
//! "equilibrium" button that puts the scene at its static pose; the offset curve of a body (the
//! one selected in the viewer, or chosen here) drawn as the restoring force against the offset.
//! A line's displaced area `A_d` is tuned with its other knobs ([`super::tuning`]).

use super::line_plot::{self, Framed};
use super::number_field::number_field;
use super::simulation::OffsetCurve;
use super::tuning::knob;
use crate::figures;
use rerun::external::egui;
use tether_physics::seabed::Seabed;
use tether_physics::statics::Direction;

/// What the panel asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum StaticsAction {
    /// The seabed's `C_B`, checked.
    SeabedFriction(f64),
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
    /// `C_B` as the knob shows it, if the scene has a seabed, and why it was refused.
    pub friction: Option<f64>,
    pub friction_refusal: Option<String>,
    /// The body chosen for the offset curve (index), when none is selected in the viewer.
    pub body: usize,
    pub direction: Direction,
    /// The largest offset [m or rad] and the number of offsets.
    pub to: f64,
    pub steps: u32,
    /// The last curve computed.
    pub curve: Option<OffsetCurve>,
}

impl StaticsDraft {
    /// The draft of a newly opened scene, `friction` its seabed's `C_B` if it has one.
    pub fn new(friction: Option<f64>) -> Self {
        Self { friction, friction_refusal: None, body: 0, direction: Direction::X, to: 10.0, steps: 20, curve: None }
    }
}

/// Draws the panel for a scene with `bodies` (names); `selected` is the body selected in the
/// viewer, if any.
pub fn ui(
    ui: &mut egui::Ui,
    draft: &mut StaticsDraft,
    bodies: &[String],
    selected: Option<&str>,
) -> Vec<StaticsAction> {
    let mut actions = Vec::new();
    egui::CollapsingHeader::new("Statics and seabed").id_salt("statics").default_open(true).show(ui, |ui| {
        if let Some(friction) = &mut draft.friction {
            let edited = egui::Grid::new("seabed knobs")
                .num_columns(3)
                .show(ui, |ui| knob(ui, "seabed line friction C_B", friction, "–"))
                .inner;
            if edited {
                // The elevation is the running seabed's; only C_B is checked here.
                match Seabed::new(0.0, *friction) {
                    Ok(_) => {
                        draft.friction_refusal = None;
                        actions.push(StaticsAction::SeabedFriction(*friction));
                    }
                    Err(error) => draft.friction_refusal = Some(error.to_string()),
                }
            }
            if let Some(refusal) = &draft.friction_refusal {
                ui.colored_label(ui.visuals().error_fg_color, format!("Refused: {refusal}"));
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
