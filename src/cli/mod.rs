//! Subcommands of `tether`, one module each.

mod check;
mod equilibrium;
mod estimate_contact;
mod export;
mod fit;
mod flags;
mod forces;
mod gui;
mod import;
mod offsets;
mod rao;
mod record;
mod storm;
mod study;
mod sweep;
mod timing;

use anyhow::Context as _;
use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use tether_scene::{self as scene, Scene};

/// Coupled rigid bodies — springs, catenaries, contact — simulated, tuned live and recorded for
/// Rerun. With no command: the window, with the default scene.
#[derive(Debug, Parser)]
#[command(name = "tether", version, about)]
pub struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Validate a scene; print each body's mass properties, the couplings and the initial energy.
    Check {
        /// Scene file (.ron), or a MoorDyn input file.
        scene: PathBuf,
    },
    /// Run a scene headless and write a Rerun recording (.rrd).
    Record(record::RecordArgs),
    /// Open the window: control panel and Rerun viewer, a scene running live (the default).
    Gui(gui::GuiArgs),
    /// Play a recording (.rrd) back in the window's viewer.
    View {
        /// Recording file (.rrd).
        recording: PathBuf,
    },
    /// Run the scene with each integrator at a ladder of time steps against a reference run;
    /// print the accuracy-versus-cost table and write it as CSV, Markdown and a PNG chart.
    Study(study::StudyArgs),
    /// Run the scene over a design of factor values (grid, one at a time, Latin hypercube) on
    /// every core or as a shard of a cluster's job array; write each case's metrics and status
    /// to results.csv, results.parquet, summary.md and charts. `tether sweep merge DIR` joins
    /// the shards' rows.
    Sweep(sweep::SweepArgs),
    /// The scene's storm over seeds (its JONSWAP sea's and gusts'): per line and per body the
    /// seeds' maxima, their Gumbel fits, the most probable maximum, the 90 % quantile and the
    /// code of practice's check (API RP 2SK, DNV-OS-E301), written as storm.md, storm.csv,
    /// storm.parquet and storm.png; on every core or as a Slurm array's shards.
    Storm(storm::StormArgs),
    /// Fit the scene's parameters (by the sweep's value paths) to a measured record — CSV,
    /// Parquet or a recording — by bounded least squares; print the fitted values with their 95 %
    /// intervals and what the data cannot determine; write the report, a chart per signal, the
    /// fitted run's recording and the fitted scene.
    Fit(fit::FitArgs),
    /// Print the forces of the initial state.
    Forces {
        /// Scene file (.ron), or a MoorDyn input file.
        scene: PathBuf,
        /// Print JSON (world frame, N and N·m; f1/f2 are exerted by the coupling on end 1 / end 2).
        #[arg(long)]
        json: bool,
    },
    /// Contact parameters k1, k2, the stopping time τ and a time step from an expected impact.
    EstimateContact(estimate_contact::EstimateArgs),
    /// The static equilibrium of every free body: poses, line tensions, grounded lengths and
    /// touchdowns, each body's 6 × 6 stiffness; --write saves the scene starting there.
    Equilibrium(equilibrium::EquilibriumArgs),
    /// A body's restoring force held at offsets from equilibrium (the offset curve): a table, a
    /// CSV file and a PNG chart.
    Offsets(offsets::OffsetsArgs),
    /// A floating body's linear RAOs from its potential-flow data (the frequency-domain solve):
    /// amplitude per metre of wave and phase per dof at the file's periods or those given.
    Rao(rao::RaoArgs),
    /// Convert a MoorDyn input file (v2, or v1 as OpenFAST writes it) into a commented RON scene;
    /// print the time the import and the build took.
    Import(import::ImportArgs),
    /// Write a scene's lines, anchors, points and the bodies they attach to as a MoorDyn v2 input
    /// file.
    Export(export::ExportArgs),
}

/// Exit code of a run stopped by Ctrl-C or SIGTERM.
pub const INTERRUPTED: u8 = tether_analysis::interrupt::EXIT_CODE;

/// Runs one subcommand; returns the process exit code.
pub fn run(cli: Cli) -> anyhow::Result<u8> {
    let command = cli.command.unwrap_or(Command::Gui(gui::GuiArgs::default()));
    if !matches!(command, Command::Gui(_) | Command::View { .. }) {
        // Every headless stage stops within a second of Ctrl-C or SIGTERM (the window closes
        // by its own handler).
        tether_analysis::interrupt::install().context("installing the Ctrl-C / SIGTERM handler")?;
    }
    match command {
        Command::Gui(args) => gui::run(args).map(|()| 0),
        Command::View { recording } => gui::view(recording).map(|()| 0),
        Command::Check { scene } => check::run(&load(&scene)?).map(|()| 0),
        Command::Record(args) => record::run(&args).map(|outcome| match outcome {
            record::Outcome::Finished => 0,
            record::Outcome::Interrupted => INTERRUPTED,
        }),
        Command::Forces { scene, json } => forces::run(&load(&scene)?, json).map(|()| 0),
        Command::EstimateContact(args) => estimate_contact::run(&args).map(|()| 0),
        Command::Study(args) => study::run(&args).map(|()| 0),
        Command::Equilibrium(args) => equilibrium::run(&args).map(|()| 0),
        Command::Offsets(args) => offsets::run(&args).map(|()| 0),
        Command::Rao(args) => rao::run(&args).map(|()| 0),
        Command::Import(args) => import::run(&args).map(|()| 0),
        Command::Export(args) => export::run(&args).map(|()| 0),
        Command::Fit(args) => fit::run(&args).map(|outcome| match outcome {
            fit::Outcome::Finished => 0,
            fit::Outcome::Interrupted => INTERRUPTED,
        }),
        Command::Sweep(args) => sweep::run(&args).map(|outcome| match outcome {
            sweep::Outcome::Finished => 0,
            sweep::Outcome::Interrupted => INTERRUPTED,
        }),
        Command::Storm(args) => storm::run(&args).map(|outcome| match outcome {
            storm::Outcome::Finished => 0,
            storm::Outcome::Interrupted => INTERRUPTED,
        }),
    }
}

/// The flag Ctrl-C or SIGTERM sets ([`tether_analysis::interrupt`]): the long commands (record, sweep,
/// fit) stop at it and keep what they finished.
fn cancel_on_ctrl_c() -> anyhow::Result<Arc<AtomicBool>> {
    tether_analysis::interrupt::install().context("installing the Ctrl-C / SIGTERM handler")
}

/// Loads a scene and prints its warnings to stderr.
fn load(path: &Path) -> anyhow::Result<Scene> {
    let scene = scene::load(path)?;
    for warning in &scene.warnings {
        eprintln!("warning: {}: {warning}", path.display());
    }
    Ok(scene)
}

/// Warns once when the integrator step exceeds the binding stable time step of the world's
/// integrator; for the adaptive one, notes that a stiff coupling will hold its steps.
fn warn_if_unstable(world: &tether_physics::world::World) {
    let limits = world.limits();
    let Some(binding) = tether_physics::stability::binding(&limits).filter(|b| world.step_size() > b.dt) else {
        return;
    };
    let name = world.integrator().name();
    if world.integrator().is_adaptive() {
        eprintln!(
            "note: {} holds {name}'s steps near {:.3e} s (stiff for an explicit scheme): expect about {:.0} steps per integrator step of {:.3e} s",
            binding.describe(world.system()),
            binding.dt,
            (world.step_size() / binding.dt).ceil(),
            world.step_size()
        );
    } else {
        eprintln!(
            "warning: the integrator step {:.3e} s exceeds the stable time step {:.3e} s of {name}, set by {}: the run will likely diverge (lower dt or set substeps: Auto)",
            world.step_size(),
            binding.dt,
            binding.describe(world.system())
        );
    }
}

/// Writes `text` to stdout; a closed pipe is not an error worth a panic.
fn print(text: &str) -> anyhow::Result<()> {
    use std::io::Write as _;
    std::io::stdout().lock().write_all(text.as_bytes()).context("writing to stdout")
}
