//! File dialogs on their own thread, so the window keeps drawing while one is open (rfd's
//! xdg-portal backend, falling back to zenity; neither needs a -dev package to build).

use super::simulation::Wake;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{self, Receiver};

/// What a dialog's file is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Purpose {
    OpenScene,
    OpenRecording,
    SaveScene,
    /// A measured record for the fit panel.
    OpenRecord,
}

/// At most one dialog at a time.
#[derive(Default)]
pub struct Dialogs {
    pending: Option<(Purpose, Receiver<Option<PathBuf>>)>,
}

impl Dialogs {
    /// Opens a dialog in `folder` unless one is already open; `wake` repaints when it closes.
    pub fn open(&mut self, purpose: Purpose, folder: &Path, wake: Wake) {
        if self.pending.is_some() {
            return;
        }
        let (reply, answer) = mpsc::channel();
        let folder = std::path::absolute(folder).unwrap_or_else(|_| folder.to_path_buf());
        let mut dialog = rfd::FileDialog::new().set_directory(&folder);
        if purpose != Purpose::SaveScene {
            // rfd's zenity fallback does not pass the folder on, only a file name: zenity starts
            // in a folder given as `folder/` (the portal takes the folder above and no file name
            // when opening).
            dialog = dialog.set_file_name(format!("{}/", folder.display()));
        }
        let spawned = std::thread::Builder::new().name("file dialog".into()).spawn(move || {
            let path = match purpose {
                Purpose::OpenScene => dialog.add_filter("Tether scene", &["ron"]).pick_file(),
                Purpose::OpenRecording => dialog.add_filter("Rerun recording", &["rrd"]).pick_file(),
                Purpose::OpenRecord => dialog
                    .add_filter("Measured record", &["csv", "parquet", "rrd"])
                    .add_filter("Any file", &["*"])
                    .pick_file(),
                Purpose::SaveScene => {
                    dialog.add_filter("Tether scene", &["ron"]).set_file_name("tuned.ron").save_file()
                }
            };
            reply.send(path).ok();
            wake();
        });
        if spawned.is_ok() {
            self.pending = Some((purpose, answer));
        }
    }

    /// The file picked in a dialog that has closed since the last call.
    pub fn poll(&mut self) -> Option<(Purpose, PathBuf)> {
        let (purpose, answer) = self.pending.as_ref()?;
        let purpose = *purpose;
        match answer.try_recv() {
            Ok(path) => {
                self.pending = None;
                path.map(|p| (purpose, p))
            }
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => {
                self.pending = None;
                None
            }
        }
    }
}
