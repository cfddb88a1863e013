//! Subcommands of `tether`, one module each.

mod check;
mod forces;
mod record;

use anyhow::Context as _;
use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use tether::scene::{self, Scene};

/// Coupled rigid bodies — springs, catenaries, contact — simulated and recorded for Rerun.
#[derive(Debug, Parser)]
#[command(name = "tether", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Validate a scene; print each body's mass properties, the couplings and the initial energy.
    Check {
        /// Scene file (.ron).
        scene: PathBuf,
    },
    /// Run a scene headless and write a Rerun recording (.rrd).
    Record(record::RecordArgs),
    /// Print the forces of the initial state.
    Forces {
        /// Scene file (.ron).
        scene: PathBuf,
        /// Print JSON (world frame, N and N·m; f1/f2 are exerted by the coupling on end 1 / end 2).
        #[arg(long)]
        json: bool,
    },
}

/// Runs one subcommand.
pub fn run(cli: Cli) -> anyhow::Result<()> {
    match cli.command {
        Command::Check { scene } => check::run(&load(&scene)?),
        Command::Record(args) => record::run(&args),
        Command::Forces { scene, json } => forces::run(&load(&scene)?, json),
    }
}

/// Loads a scene and prints its warnings to stderr.
fn load(path: &Path) -> anyhow::Result<Scene> {
    let scene = scene::load(path)?;
    for warning in &scene.warnings {
        eprintln!("warning: {}: {warning}", path.display());
    }
    Ok(scene)
}

/// Writes `text` to stdout; a closed pipe is not an error worth a panic.
fn print(text: &str) -> anyhow::Result<()> {
    use std::io::Write as _;
    std::io::stdout().lock().write_all(text.as_bytes()).context("writing to stdout")
}
