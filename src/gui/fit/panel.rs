//! The Fit panel drawn (docs/window.md, "Fit"): the record, its columns' signals, the knobs and
//! their bounds, the Fit and Stop buttons, and the fit's session as it runs — its status, values,
//! intervals and cost per iteration; what the user asks for comes back as [`FitAction`]s.

use super::super::line_plot::{self, Framed};
use super::super::number_field::number_field;
use super::{
    Decision, FitAction, FitDraft, Session, amount, correlated_text, interval_text, number, signal_label, status,
};
use crate::figures;
use rerun::external::egui;
use tether_analysis::parameters::Parameter;
use tether_analysis::quantity::Quantity;

/// Draws the fit panel for a scene whose fittable values are `fittables` and whose signals are
/// `signals`; returns what it asks for.
pub fn ui(ui: &mut egui::Ui, draft: &mut FitDraft, fittables: &[Parameter], signals: &[Quantity]) -> Vec<FitAction> {
    let mut actions = Vec::new();
    egui::CollapsingHeader::new("Fit to a record").id_salt("fit").default_open(false).show(ui, |ui| {
        let running = draft.running();
        ui.add_enabled_ui(!running, |ui| choices_ui(ui, draft, fittables, signals, &mut actions));
        ui.horizontal_wrapped(|ui| {
            let why_not =
                if running { "a fit is running" } else { "open a record first: the fit compares the run with it" };
            if ui
                .add_enabled(!running && draft.record.is_some(), egui::Button::new("Fit"))
                .on_hover_text("Fit the ticked knobs to the record (tether fit), from their values now")
                .on_disabled_hover_text(why_not)
                .clicked()
            {
                actions.push(FitAction::Start);
            }
            if ui
                .add_enabled(running, egui::Button::new("Stop"))
                .on_hover_text("End the fit at the best values so far")
                .clicked()
            {
                actions.push(FitAction::Stop);
            }
            if draft.record.is_none() {
                ui.weak("open a record (above) to fit");
            }
        });
        if let Some(refusal) = &draft.refusal {
            let text = egui::RichText::new(refusal).color(ui.visuals().error_fg_color);
            let shown = ui.add(egui::Label::new(text).wrap());
            // Where the eye is: the Fit button may sit at the panel's bottom edge.
            if std::mem::take(&mut draft.reveal) {
                shown.scroll_to_me(None);
            }
        }
        if let Some(session) = &draft.session {
            session_ui(ui, session, &mut actions);
        }
    });
    actions
}

/// The record, its columns' signals, the knobs and their bounds, the window.
fn choices_ui(
    ui: &mut egui::Ui,
    draft: &mut FitDraft,
    fittables: &[Parameter],
    signals: &[Quantity],
    actions: &mut Vec<FitAction>,
) {
    ui.horizontal(|ui| {
        if ui.button("Open record…").on_hover_text("A measured record: CSV, Parquet or a Tether recording").clicked()
        {
            actions.push(FitAction::BrowseRecord);
        }
        match &draft.record {
            Some(record) => {
                let name = record.path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned());
                let summary = format!(
                    "{name}: {} column{}, {} to {}",
                    record.columns.len(),
                    if record.columns.len() == 1 { "" } else { "s" },
                    number(record.span.0),
                    figures::quantity(record.span.1, "s", 6)
                );
                // Wrapped: a long file name must not widen the panel and push the viewer.
                ui.add(egui::Label::new(summary).wrap()).on_hover_text(record.path.display().to_string());
            }
            None => {
                ui.weak("no record");
            }
        }
    });
    if let Some(record) = &draft.record {
        ui.label("Each column is the model signal:");
        for (index, (column, of)) in record.columns.iter().zip(&mut draft.mapping).enumerate() {
            let shown = of.as_ref().map_or_else(|| "not used".to_string(), signal_label);
            // Wrapped: a long column name breaks over lines, its choice goes to the next one.
            ui.horizontal_wrapped(|ui| {
                let name = ui.add(egui::Label::new(column).wrap());
                let choice =
                    egui::ComboBox::from_id_salt(("fit column", index)).selected_text(shown).show_ui(ui, |ui| {
                        ui.selectable_value(&mut *of, None, "not used");
                        for signal in signals {
                            ui.selectable_value(&mut *of, Some(signal.clone()), signal_label(signal));
                        }
                    });
                choice.response.labelled_by(name.id);
            });
        }
    }
    ui.label("Knobs to fit (bounds; the fit starts from the value now):");
    for fittable in fittables {
        let mut on = draft.ticked.contains_key(&fittable.path);
        ui.horizontal(|ui| {
            if ui.checkbox(&mut on, &fittable.label).changed() {
                draft.tick(fittable, on);
            }
            ui.weak(amount(fittable.value, fittable.unit));
        });
        if let Some(bounds) = draft.ticked.get_mut(&fittable.path) {
            ui.horizontal(|ui| {
                ui.add_space(24.0);
                bound(ui, &mut bounds.from, "from", &format!("{} from", fittable.label));
                bound(ui, &mut bounds.to, "to", &format!("{} to", fittable.label));
                ui.label(fittable.unit);
                ui.checkbox(&mut bounds.log, "log").on_hover_text("A log scale, for a value that spans decades");
            });
        }
    }
    ui.horizontal(|ui| {
        ui.label("window");
        bound(ui, &mut draft.window.0, "from", "window from");
        bound(ui, &mut draft.window.1, "to", "window to");
        ui.label("s");
    });
}

/// A bound: a number after `prefix`, named `name` for screen readers (and tests).
fn bound(ui: &mut egui::Ui, value: &mut f64, prefix: &str, name: &str) {
    let speed = value.abs().max(1e-3) * 0.01;
    ui.label(prefix);
    let response = number_field(ui, value, speed);
    ui.ctx().accesskit_node_builder(response.id, |node| node.set_label(name));
}

/// Where the fit is or how it ended; each fitted knob's value and interval; Apply, Revert.
fn session_ui(ui: &mut egui::Ui, session: &Session, actions: &mut Vec<FitAction>) {
    ui.separator();
    match (&session.result, &session.latest) {
        (None, None) => {
            ui.label("fitting: the first runs…");
        }
        (None, Some(latest)) => {
            ui.label(format!(
                "fitting: iteration {}, cost {}, {} runs",
                latest.iteration,
                figures::number(latest.cost, 4),
                latest.runs
            ));
        }
        (Some(Ok(summary)), _) => {
            ui.label(status(summary));
        }
        (Some(Err(message)), _) => {
            ui.colored_label(ui.visuals().error_fg_color, format!("the fit failed: {message}"));
        }
    }
    let fitted = match &session.result {
        Some(Ok(summary)) => Some(&summary.parameters),
        Some(Err(_)) | None => None,
    };
    egui::Grid::new("fit results").num_columns(2).show(ui, |ui| {
        for (index, target) in session.targets.iter().enumerate() {
            ui.label(&target.label);
            match fitted.and_then(|parameters| parameters.get(index)) {
                Some(parameter) => ui
                    .label(interval_text(parameter, target.unit))
                    .on_hover_text(correlated_text(parameter, target.unit)),
                None => {
                    let now = session.applied.get(index).copied().unwrap_or(target.value);
                    ui.label(format!("{} (from {})", amount(now, target.unit), amount(target.value, target.unit)))
                }
            };
            ui.end_row();
        }
    });
    if session.costs.len() > 1 {
        cost_plot(ui, &session.costs);
    }
    if session.result.is_some() {
        match session.decision {
            None => {
                ui.horizontal(|ui| {
                    if ui.button("Apply").on_hover_text("Keep the fitted values (they are running)").clicked() {
                        actions.push(FitAction::Apply);
                    }
                    if ui.button("Revert").on_hover_text("The fitted knobs back to the scene file's values").clicked() {
                        actions.push(FitAction::Revert);
                    }
                });
            }
            Some(Decision::Kept) => {
                ui.weak("kept: the fitted values are the tuned ones (\"Save as…\" writes them)");
            }
            Some(Decision::Reverted) => {
                ui.weak("reverted to the file's values");
            }
        }
    }
}

/// The cost of each accepted iteration, on a log scale, in a framed box.
fn cost_plot(ui: &mut egui::Ui, costs: &[(u32, f64)]) {
    let first = costs.first().map_or(0.0, |c| c.1);
    let last = costs.last().map_or(0.0, |c| c.1);
    ui.label(format!("cost per iteration: {} → {} (log scale)", figures::number(first, 4), figures::number(last, 4)));
    let points: Vec<(f64, f64)> =
        costs.iter().filter(|c| c.1 > 0.0).map(|&(i, cost)| (f64::from(i), cost.log10())).collect();
    let Some(Framed { painter, line, .. }) = line_plot::frame(ui, &points, 80.0) else {
        return;
    };
    let stroke = egui::Stroke::new(2.0, ui.visuals().hyperlink_color);
    for point in &line {
        painter.circle_filled(*point, 2.5, stroke.color);
    }
    painter.add(egui::Shape::line(line, stroke));
}
