//! `tether export moordyn SCENE -o lines.dat`: a scene's lines, anchors, connection points and
//! the bodies they attach to as a MoorDyn v2 input file (`docs/moordyn-files.md`, "Export"), for
//! MoorDyn, OpenFAST's MoorDyn module or MoorPy.

use anyhow::Context as _;
use clap::{Args, ValueEnum};
use std::path::PathBuf;
use tether_scene::moordyn::export::{DEFAULT_SEGMENTS, export};

#[derive(Debug, Args)]
pub struct ExportArgs {
    /// The format to write.
    format: Format,
    /// Scene file (.ron, or a MoorDyn file).
    scene: PathBuf,
    /// The file to write.
    #[arg(short, long)]
    output: PathBuf,
    /// Segments of a quasi-static line (a dynamic one keeps its own).
    #[arg(long, default_value_t = DEFAULT_SEGMENTS)]
    segments: u32,
}

/// The formats `export` writes.
#[derive(Debug, Clone, Copy, ValueEnum)]
enum Format {
    /// A MoorDyn v2 input file.
    Moordyn,
}

pub fn run(args: &ExportArgs) -> anyhow::Result<()> {
    super::flags::at_least_one("--segments", args.segments)?;
    let scene = super::load(&args.scene)?;
    let text = match args.format {
        Format::Moordyn => export(&scene.file, scene.bodies.bodies(), &args.scene.display().to_string(), args.segments),
    };
    std::fs::write(&args.output, &text).with_context(|| format!("{}: cannot write", args.output.display()))?;
    super::print(&format!("wrote {} (MoorDyn v2)\n", args.output.display()))
}
