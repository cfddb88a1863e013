//! The panel's number field: egui's `DragValue` (drag it, or click and type) showing the value
//! as a person reads it ([`figures::editable`]: `20`, `200000`, `2.5e10`, never `20.0` nor
//! `0.00000`) and reading what is typed as a person writes it ([`figures::parse`]). Typed text
//! is taken on Enter or when the field is left; text that is not a number is said so beside the
//! field ("“abc” is not a number: nothing applied") until the field next changes.

use crate::figures;
use rerun::external::egui;
use rerun::external::egui::emath::Numeric;
use std::cell::RefCell;

/// Significant digits a field shows.
const DIGITS: usize = 6;

/// A number field over `value`, dragged at `speed` per point; its response (`changed()` when a
/// drag or a typed number changed the value).
pub fn number_field<N: Numeric>(ui: &mut egui::Ui, value: &mut N, speed: f64) -> egui::Response {
    let not_a_number = RefCell::new(None::<String>);
    ui.horizontal(|ui| {
        // The drag value's own id (it takes the next one), the same whether it is being typed
        // into or not (its response's id is not).
        let id = ui.next_auto_id().with("not a number");
        let field = egui::DragValue::new(value)
            .speed(speed)
            .update_while_editing(false)
            .custom_formatter(|x, _| figures::editable(x, DIGITS))
            .custom_parser(|text| {
                let parsed = figures::parse(text);
                if parsed.is_none() {
                    *not_a_number.borrow_mut() = Some(text.trim().to_string());
                }
                parsed
            });
        let response = ui.add(field);
        if let Some(text) = not_a_number.take() {
            ui.data_mut(|data| data.insert_temp(id, text));
        }
        if response.changed() || response.gained_focus() {
            ui.data_mut(|data| data.remove::<String>(id));
        }
        if let Some(text) = ui.data(|data| data.get_temp::<String>(id)) {
            ui.colored_label(ui.visuals().error_fg_color, format!("“{text}” is not a number: nothing applied"));
        }
        response
    })
    .inner
}
