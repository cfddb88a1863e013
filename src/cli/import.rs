//! `tether import FILE -o SCENE.ron`: a MoorDyn input file (v2, or v1 as OpenFAST writes it)
//! as a commented RON scene (`docs/moordyn-files.md`), checked by building it; prints how long
//! the import and the build (the lines' static Newton solve included) took.

use anyhow::Context as _;
use clap::Args;
use std::path::PathBuf;
use std::time::Instant;
use tether_scene::moordyn;

#[derive(Debug, Args)]
pub struct ImportArgs {
    /// MoorDyn input file (.dat, .txt, …).
    file: PathBuf,
    /// The scene to write (.ron).
    #[arg(short, long, value_name = "SCENE.ron")]
    output: PathBuf,
}

pub fn run(args: &ImportArgs) -> anyhow::Result<()> {
    let text = std::fs::read_to_string(&args.file).with_context(|| format!("{}: cannot read", args.file.display()))?;
    let clock = Instant::now();
    let imported = moordyn::import(&text, &args.file)?;
    let read = clock.elapsed();
    // The scene is built (and so checked) before anything is written.
    let scene = moordyn::load(&text, &args.file)?;
    let total = clock.elapsed();
    for warning in &scene.warnings {
        eprintln!("warning: {}: {warning}", args.file.display());
    }
    std::fs::write(&args.output, &imported.written.text)
        .with_context(|| format!("{}: cannot write", args.output.display()))?;
    let world = &scene.world;
    super::print(&format!(
        "{}: {} bodies, {} lines → wrote {}\nimport {:.2} ms; import and build (the lines' static solve included) {:.2} ms\n",
        args.file.display(),
        world.bodies().len(),
        world.couplings().len(),
        args.output.display(),
        read.as_secs_f64() * 1e3,
        total.as_secs_f64() * 1e3,
    ))
}
