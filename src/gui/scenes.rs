//! The scene picker: the scene list, the file dialogs, why the last scene would not load, and
//! the recording played back in place of a scene.

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

/// A recording played back in the viewer in place of the live run.
#[derive(Debug, Clone, PartialEq)]
pub struct Playback {
    pub recording: PathBuf,
    /// The scene whose run was closed for it.
    pub closed: Option<PathBuf>,
}

/// What the picker shows.
pub struct Picker<'a> {
    /// The open scene.
    pub current: Option<&'a Path>,
    /// The scenes folder's list.
    pub scenes: &'a [PathBuf],
    /// Why the last scene would not load.
    pub load_error: Option<&'a str>,
    /// The recording played back in place of a scene.
    pub playback: Option<&'a Playback>,
}

/// Draws the picker: the open scene (or the recording played back, with the scene closed for
/// it to go back to), the load error in red, the list and the dialogs.
pub fn ui(ui: &mut egui::Ui, picker: &Picker<'_>) -> Option<SceneAction> {
    let Picker { current, scenes, load_error, playback } = *picker;
    let mut action = None;
    match (current, playback) {
        (Some(path), _) => {
            ui.label(format!("Scene: {}", file_name(path))).on_hover_text(path.display().to_string());
        }
        (None, Some(Playback { recording, closed })) => {
            ui.strong(format!("Playing back {}", file_name(recording))).on_hover_text(recording.display().to_string());
            ui.label("The viewer shows this recording; no scene runs. Open a scene to run one.");
            if let Some(closed) = closed
                && ui
                    .button(format!("Back to {}", file_name(closed)))
                    .on_hover_text("Open the scene again, at t = 0")
                    .clicked()
            {
                action = Some(SceneAction::Open(closed.clone()));
            }
        }
        (None, None) => {
            ui.label("No scene open: pick one below, open a file or drop a .ron on the window.");
        }
    }
    if let Some(error) = load_error {
        ui.colored_label(ui.visuals().error_fg_color, error).on_hover_text("The previous scene keeps running.");
    }
    ui.horizontal(|ui| {
        if ui.button("Open scene…").clicked() {
            action = Some(SceneAction::Browse);
        }
        if ui
            .button("Open recording…")
            .on_hover_text("Play back a .rrd (dropping one works too); the scene running is closed")
            .clicked()
        {
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
