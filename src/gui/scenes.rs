//! The scene picker: the scene list, the file dialogs, and why the last scene would not load.

use rerun::external::egui;
use std::path::{Path, PathBuf};

/// What the picker asks for.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneAction {
    Open(PathBuf),
    /// The file dialog for a scene.
    Browse,
    /// The file dialog for a recording to play back.
    BrowseRecording,
    /// List the scenes folder again.
    Refresh,
}

/// Draws the picker: the open scene, the load error in red, the list and the dialogs.
pub fn ui(
    ui: &mut egui::Ui,
    current: Option<&Path>,
    scenes: &[PathBuf],
    load_error: Option<&str>,
) -> Option<SceneAction> {
    let mut action = None;
    match current {
        Some(path) => ui.label(format!("Scene: {}", file_name(path))).on_hover_text(path.display().to_string()),
        None => ui.label("No scene open: pick one below, open a file or drop a .ron on the window."),
    };
    if let Some(error) = load_error {
        ui.colored_label(ui.visuals().error_fg_color, error).on_hover_text("The previous scene keeps running.");
    }
    ui.horizontal(|ui| {
        if ui.button("Open scene…").clicked() {
            action = Some(SceneAction::Browse);
        }
        if ui.button("Open recording…").on_hover_text("Play back a .rrd (dropping one works too)").clicked() {
            action = Some(SceneAction::BrowseRecording);
        }
        if ui.button("⟳").on_hover_text("List the scenes folder again").clicked() {
            action = Some(SceneAction::Refresh);
        }
    });
    egui::CollapsingHeader::new(format!("Scenes ({})", scenes.len())).default_open(current.is_none()).show(ui, |ui| {
        for path in scenes {
            if ui
                .selectable_label(current == Some(path.as_path()), file_name(path))
                .on_hover_text(path.display().to_string())
                .clicked()
            {
                action = Some(SceneAction::Open(path.clone()));
            }
        }
    });
    action
}

fn file_name(path: &Path) -> String {
    path.file_name().map_or_else(|| path.display().to_string(), |n| n.to_string_lossy().into_owned())
}
