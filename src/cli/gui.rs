//! `tether gui [SCENE] [--connect URL] [--save OUT.rrd] [--sweep DIR]` and `tether view
//! FILE.rrd`: the window.

use anyhow::{Context as _, bail};
use clap::Args;
use std::path::{Path, PathBuf};
use tether::gui::GuiOptions;

/// Opened when `tether` runs with no scene, if it exists (relative to the working folder).
const DEFAULT_SCENE: &str = "scenes/moored_buoy.ron";

/// Listed in the window's scene list.
const SCENES_DIR: &str = "scenes";

#[derive(Debug, Default, Args)]
pub struct GuiArgs {
    /// Scene file (.ron) to open (default: scenes/moored_buoy.ron when there is one).
    scene: Option<PathBuf>,
    /// Stream to the external Rerun viewer at this URL instead of the embedded one
    /// (e.g. rerun+http://127.0.0.1:9876/proxy).
    #[arg(long)]
    connect: Option<String>,
    /// Also write everything shown to this recording (.rrd).
    #[arg(long)]
    save: Option<PathBuf>,
    /// Open a sweep's output directory in the sweep table (a case loads in one click).
    #[arg(long)]
    sweep: Option<PathBuf>,
}

pub fn run(args: GuiArgs) -> anyhow::Result<()> {
    let scene = args.scene.or_else(|| Some(PathBuf::from(DEFAULT_SCENE)).filter(|p| p.is_file()));
    if let Some(dir) = &args.sweep
        && !dir.join(tether::sweep::store::MANIFEST).is_file()
    {
        bail!("{} is not a sweep directory (no {})", dir.display(), tether::sweep::store::MANIFEST);
    }
    let options = GuiOptions {
        scene,
        recording: None,
        connect: args.connect,
        save: args.save,
        scenes_dir: PathBuf::from(SCENES_DIR),
        sweep: args.sweep,
    };
    tether::gui::run(options).context("the window")
}

pub fn view(recording: PathBuf) -> anyhow::Result<()> {
    if !Path::new(&recording).is_file() {
        bail!("no recording at {}", recording.display());
    }
    let options =
        GuiOptions { recording: Some(recording), scenes_dir: PathBuf::from(SCENES_DIR), ..Default::default() };
    tether::gui::run(options).context("the window")
}
