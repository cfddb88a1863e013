//! `tether storm SCENE --hours H --seeds N -o DIR [--code api-rp-2sk | dnv-os-e301] [--jobs N]
//! [--shard I/N | auto] [--resume]` and `tether storm report DIR`: the scene's storm over seeds
//! as a sweep (a progress bar, every core, or a Slurm array's shards), then per line and per body
//! the seeds' maxima, their Gumbel fits, the MPM, the 90 % quantile and the code's check,
//! written as storm.md, storm.csv, storm.parquet and storm.png (docs/design-loads.md).

use super::flags::positive;
use anyhow::{Context as _, bail};
use clap::{Args, Subcommand, ValueEnum};
use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};
use std::time::Duration;
use tether_analysis::runner::Runner;
use tether_analysis::storm::statistics::{self, Code, Measured};
use tether_analysis::storm::{report, spec};
use tether_analysis::sweep::rows::Rows;
use tether_analysis::sweep::shard::{self, ShardArg};
use tether_analysis::sweep::store::Store;
use tether_analysis::sweep::{Options, SweepError};
use tether_physics::body::Support;
use tether_scene::file::{CouplingDef, SceneFile};

#[derive(Debug, Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct StormArgs {
    #[command(subcommand)]
    command: Option<StormCommand>,
    /// Scene file (.ron) with a random sea (JONSWAP) or gusts (NPD, Kaimal).
    #[arg(required = true)]
    scene: Option<PathBuf>,
    /// Output directory (new or empty, or this storm's with --resume).
    #[arg(short, long, required = true)]
    output: Option<PathBuf>,
    /// The storm's length after the warm-up [h].
    #[arg(long, default_value_t = 3.0)]
    hours: f64,
    /// Seeds (independent realisations of the sea and the gusts), at least 2.
    #[arg(long, default_value_t = 10)]
    seeds: u32,
    /// The first seed; the others follow it.
    #[arg(long, default_value_t = 1)]
    first_seed: u64,
    /// Simulated time before the maxima are taken [s]: the ramps and the slow drift's start.
    #[arg(long, default_value_t = 600.0)]
    warmup: f64,
    #[command(flatten)]
    check: CheckArgs,
    /// Seeds run at once (default: every core).
    #[arg(long)]
    jobs: Option<NonZeroUsize>,
    /// Run the I-th of N slices of the seeds (I from 0); `auto` takes it from a Slurm job array.
    /// Then `tether sweep merge DIR` and `tether storm report DIR` once every shard is done.
    #[arg(long, value_parser = shard::parse)]
    shard: Option<ShardArg>,
    /// Run only the seeds without a row in the output directory.
    #[arg(long)]
    resume: bool,
    /// Wall-time limit of one seed [s].
    #[arg(long, default_value_t = 86_400.0)]
    case_timeout: f64,
}

/// The code of practice the lines are checked by.
#[derive(Debug, Args)]
struct CheckArgs {
    /// API RP 2SK (MBL / T_MPM ≥ 1.67) or DNV-OS-E301 (ULS partial safety factors).
    #[arg(long, value_enum, default_value_t = CodeArg::ApiRp2sk)]
    code: CodeArg,
    /// DNV-OS-E301's consequence class (1 or 2).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u8).range(1..=2))]
    class: u8,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum CodeArg {
    ApiRp2sk,
    DnvOsE301,
}

impl CheckArgs {
    fn code(&self) -> Code {
        match self.code {
            CodeArg::ApiRp2sk => Code::ApiRp2sk,
            CodeArg::DnvOsE301 => Code::DnvOsE301 { class: self.class },
        }
    }
}

#[derive(Debug, Subcommand)]
enum StormCommand {
    /// The statistics of a storm whose shards are merged (`tether sweep merge DIR` first).
    Report {
        /// The storm's output directory.
        dir: PathBuf,
        #[command(flatten)]
        check: CheckArgs,
    },
}

/// How a storm command ended.
pub enum Outcome {
    Finished,
    Interrupted,
}

pub fn run(args: &StormArgs) -> anyhow::Result<Outcome> {
    let cancel = super::cancel_on_ctrl_c()?;
    if let Some(StormCommand::Report { dir, check }) = &args.command {
        return write_report(dir, check.code()).map(|()| Outcome::Finished);
    }
    let (Some(scene_path), Some(output)) = (&args.scene, &args.output) else { bail!("give a scene and -o DIR") };
    positive("--case-timeout", args.case_timeout, "s")?;
    let scene = super::load(scene_path)?;
    let request =
        spec::StormRequest { hours: args.hours, warmup: args.warmup, seeds: args.seeds, first_seed: args.first_seed };
    let plan = spec::plan(scene_path, &scene.file, &moving_bodies(&scene), &request)?;
    let shard = shard::resolve(args.shard, &|name| std::env::var(name).ok()).map_err(anyhow::Error::msg)?;
    let runner = Runner::new(args.jobs.unwrap_or_else(tether_analysis::runner::all_cores))
        .with_case_timeout(Duration::from_secs_f64(args.case_timeout))
        .with_cancel(cancel);
    let jobs = runner.jobs();
    let options = Options { runner, shard: shard.as_ref().map(|(s, _)| *s), resume: args.resume, record: None };
    eprintln!(
        "storm: {} seeds of {} h after {} s of warm-up, on {jobs} threads",
        plan.cases.len(),
        args.hours,
        args.warmup
    );
    let report = super::sweep::run_with_progress(&plan, output, &options, "seeds");
    let report = match report {
        Err(SweepError::Interrupted(stage)) => {
            eprintln!("interrupted while {stage}");
            return Ok(Outcome::Interrupted);
        }
        other => other?,
    };
    if report.interrupted {
        eprintln!("interrupted: the finished seeds are kept; run again with --resume");
        return Ok(Outcome::Interrupted);
    }
    eprintln!(
        "ran {} seeds in {:.1} s ({:.1} s of CPU in the simulations)",
        report.ran,
        report.running.as_secs_f64(),
        report.case_cpu_seconds
    );
    if report.written.is_none() {
        super::print(&format!(
            "rows in {}/runs/; when every shard is done: tether sweep merge {0} && tether storm report {0}\n",
            output.display()
        ))?;
        return Ok(Outcome::Finished);
    }
    write_report(output, args.check.code())?;
    Ok(Outcome::Finished)
}

/// The names of the bodies whose G can move (their offset is measured).
fn moving_bodies(scene: &tether_scene::Scene) -> Vec<String> {
    scene
        .world
        .bodies()
        .iter()
        .filter(|b| match &b.support {
            Support::Free => true,
            Support::Fixed { translation, .. } => !translation.iter().all(|&held| held),
            Support::Kinematic(_) => false,
        })
        .map(|b| b.name.clone())
        .collect()
}

/// What a storm measures: each catenary's tension (with its breaking load), each moving body's
/// offset.
fn measured(file: &SceneFile, moving: &[String]) -> Vec<Measured> {
    let lines = file.couplings.iter().filter_map(|c| match c {
        CouplingDef::Catenary { name, breaking_load, .. } => {
            Some(Measured::Tension { line: name.clone(), breaking_load: *breaking_load })
        }
        CouplingDef::SpringDamper { .. } | CouplingDef::Contact { .. } => None,
    });
    lines.chain(moving.iter().map(|body| Measured::Offset { body: body.clone() })).collect()
}

/// The statistics of the storm in `dir`, written beside its rows and printed.
fn write_report(dir: &Path, code: Code) -> anyhow::Result<()> {
    let store = Store::new(dir);
    let manifest = store.manifest()?.with_context(|| format!("{} holds no storm (no manifest)", dir.display()))?;
    let scene = tether_scene::parse(&manifest.scene_text, &manifest.scene_path)?;
    let rows = Rows::gather(&store, &manifest.columns)?;
    let mut all = Vec::new();
    rows.for_each(|row| {
        all.push(row);
        Ok(())
    })?;
    let hours = storm_hours(&manifest.spec_text)?;
    let measured = measured(&scene.file, &moving_bodies(&scene));
    let stats = statistics::compute(&measured, &manifest.columns, &all, code)?;
    let files = report::write(dir, &stats, hours, code)?;
    let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
    super::print(&format!("{}written: {}\n", report::summary(&stats), names.join(", ")))
}

/// The storm's hours: its spec's duration less the warm-up its metrics start after (the spec
/// [`spec::spec_text`] wrote).
fn storm_hours(spec_text: &str) -> anyhow::Result<f64> {
    let text = tether_analysis::spec_text::SpecText { path: Path::new("storm.ron"), text: spec_text };
    let spec: tether_analysis::sweep::spec::SpecFile = text.parse().context("the storm's spec in its manifest")?;
    let warmup = spec.metrics.first().map_or(0.0, |m| m.after);
    Ok((spec.duration.unwrap_or(0.0) - warmup) / 3600.0)
}
