//! `tether gui [SCENE] [--connect URL] [--save OUT.rrd] [--sweep DIR] [--max-fps N]` and `tether view
//! FILE.rrd`: the window. A build without the `gui` feature (the headless build) keeps the
//! subcommands and says, when one is run, that it has no window and how to get one.

use anyhow::bail;
use clap::Args;
use std::path::PathBuf;
#[cfg(feature = "gui")]
use {anyhow::Context as _, tether::gui::GuiOptions};

/// Opened when `tether` runs with no scene, if it exists (relative to the working folder).
const DEFAULT_SCENE: &str = "scenes/buoy_on_dynamic_chains.ron";

/// Listed in the window's scene list.
#[cfg(feature = "gui")]
const SCENES_DIR: &str = "scenes";

#[derive(Debug, Default, Args)]
pub struct GuiArgs {
    /// Scene file (.ron) or MoorDyn input file to open (default: scenes/buoy_on_dynamic_chains.ron when there is one).
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
    /// Frames drawn per second at most (default: 30 when the viewer renders on the CPU, as on a
    /// machine without a GPU; no cap on a GPU).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    max_fps: Option<u32>,
}

#[cfg(feature = "gui")]
pub fn run(args: GuiArgs) -> anyhow::Result<()> {
    let scene = args.scene.or_else(|| Some(PathBuf::from(DEFAULT_SCENE)).filter(|p| p.is_file()));
    if let Some(dir) = &args.sweep
        && !dir.join(tether_analysis::sweep::store::MANIFEST).is_file()
    {
        bail!("{} is not a sweep directory (no {})", dir.display(), tether_analysis::sweep::store::MANIFEST);
    }
    let options = GuiOptions {
        scene,
        recording: None,
        connect: args.connect,
        save: args.save,
        scenes_dir: PathBuf::from(SCENES_DIR),
        sweep: args.sweep,
        max_fps: args.max_fps,
    };
    tether::gui::run(options).context("the window")
}

#[cfg(feature = "gui")]
pub fn view(recording: PathBuf) -> anyhow::Result<()> {
    if !recording.is_file() {
        bail!("no recording at {}", recording.display());
    }
    let options =
        GuiOptions { recording: Some(recording), scenes_dir: PathBuf::from(SCENES_DIR), ..Default::default() };
    tether::gui::run(options).context("the window")
}

/// What the headless build says for `tether`, `tether gui` and `tether view`, before what it
/// can do instead.
#[cfg(not(feature = "gui"))]
const NO_WINDOW: &str = "this tether is the headless build (without the `gui` feature), which has no window \
    (the full one: `cargo install --path .`, or `scripts/run`)";

/// The headless build: no window; says how to record the scene instead, for which viewer.
#[cfg(not(feature = "gui"))]
pub fn run(args: GuiArgs) -> anyhow::Result<()> {
    let scene = args.scene.unwrap_or_else(|| PathBuf::from(DEFAULT_SCENE));
    let recording = args.save.unwrap_or_else(|| scene.with_extension("rrd"));
    let viewer = args.connect.map_or("any Rerun viewer".to_string(), |url| format!("the viewer at {url}"));
    let sweep = args.sweep.map(|dir| format!("; the sweep's table is {}", dir.join("summary.md").display()));
    bail!(
        "{NO_WINDOW}; `tether record {} -o {}` records the scene for {viewer}{}",
        scene.display(),
        recording.display(),
        sweep.unwrap_or_default()
    )
}

/// The headless build: no window; the Rerun viewer plays the recording.
#[cfg(not(feature = "gui"))]
pub fn view(recording: PathBuf) -> anyhow::Result<()> {
    bail!("{NO_WINDOW}; `rerun {}` plays the recording", recording.display())
}
