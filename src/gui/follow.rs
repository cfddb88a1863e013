//! The viewer's camera: the eye frames what moves in the run (`tether_record::framing`), or
//! follows a body the user picks, keeping its distance and direction as the body moves.

use super::simulation::Status;
use rerun::external::egui;

/// Shown for "no body followed".
const FRAMED: &str = "the whole run";

/// The "View" chooser: the run framed, or one of the bodies of `status` followed; the new choice
/// if the user changed it.
pub fn ui(ui: &mut egui::Ui, status: Option<&Status>, follow: &Option<String>) -> Option<Option<String>> {
    let bodies = status.map_or(&[][..], |s| s.bodies.as_slice());
    if bodies.is_empty() {
        return None;
    }
    let mut chosen = follow.clone();
    ui.horizontal(|ui| {
        ui.label("View");
        let shown = follow.as_ref().map_or(FRAMED.to_string(), |name| format!("follow {name}"));
        egui::ComboBox::from_id_salt("follow")
            .selected_text(shown)
            .show_ui(ui, |ui| {
                ui.selectable_value(&mut chosen, None, FRAMED);
                for body in bodies {
                    ui.selectable_value(&mut chosen, Some(body.name.clone()), format!("follow {}", body.name));
                }
            })
            .response
            .on_hover_text("The 3D view's eye: framing what moves in the first seconds, or following a body");
    });
    (chosen != *follow).then_some(chosen)
}
