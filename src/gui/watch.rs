//! Watches the open scene file, so an edit saved in another program reloads it.
//!
//! The folder is watched rather than the file: editors often save by writing a new file and
//! renaming it over the old one, which a watch on the old file would miss.

use super::simulation::Wake;
use notify::Watcher as _;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// A watch on one file.
pub struct FileWatch {
    _watcher: notify::RecommendedWatcher,
    /// When the file last changed, until the change is taken.
    changed: Arc<Mutex<Option<Instant>>>,
}

impl FileWatch {
    /// Watches `path`; `wake` repaints on a change.
    pub fn new(path: &Path, wake: Wake) -> notify::Result<Self> {
        let name = path.file_name().map(ToOwned::to_owned);
        let folder =
            path.parent().filter(|p| !p.as_os_str().is_empty()).map_or_else(|| PathBuf::from("."), Path::to_path_buf);
        let changed = Arc::new(Mutex::new(None));
        let flag = Arc::clone(&changed);
        let mut watcher = notify::recommended_watcher(move |event: notify::Result<notify::Event>| {
            let Ok(event) = event else { return };
            let ours = event.paths.iter().any(|p| p.file_name() == name.as_deref());
            if ours && (event.kind.is_modify() || event.kind.is_create()) {
                // A poisoned lock means a panic elsewhere; the watch then just stops reporting.
                if let Ok(mut changed) = flag.lock() {
                    *changed = Some(Instant::now());
                }
                wake();
            }
        })?;
        watcher.watch(&folder, notify::RecursiveMode::NonRecursive)?;
        Ok(Self { _watcher: watcher, changed })
    }

    /// `Some(true)` once, when the file changed and has been quiet for `quiet` since;
    /// `Some(false)` while it is still settling; `None` when nothing changed.
    pub fn settled(&self, quiet: Duration) -> Option<bool> {
        let mut changed = self.changed.lock().ok()?;
        let at = (*changed)?;
        if at.elapsed() < quiet {
            return Some(false);
        }
        *changed = None;
        Some(true)
    }
}
