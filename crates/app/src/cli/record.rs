//! `tether record SCENE -o OUT.rrd`: a headless run written to a Rerun recording.
//!
//! The run stops cleanly — the recording complete up to there, footer written — when it ends,
//! when the simulation diverges (exit 1, with the body, the time and the stable time step), and
//! on Ctrl-C or SIGTERM (exit 130).

use anyhow::{Context as _, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use tether_physics::integrator::Integrator;
use tether_physics::world::StepError;
use tether_record::Recorder;

#[derive(Debug, Args)]
pub struct RecordArgs {
    /// Scene file (.ron).
    scene: PathBuf,
    /// Output recording (.rrd).
    #[arg(short, long)]
    output: PathBuf,
    /// Simulated duration [s] (default: the scene's).
    #[arg(long)]
    duration: Option<f64>,
    /// Frames logged per simulated second.
    #[arg(long, default_value_t = 60.0)]
    log_hz: f64,
    /// Time step [s] (default: the scene's).
    #[arg(long)]
    dt: Option<f64>,
    /// Integrator, as named in scene files (default: the scene's).
    #[arg(long, value_parser = parse_integrator)]
    integrator: Option<Integrator>,
}

/// How a recording run ended.
pub enum Outcome {
    Finished,
    Interrupted,
}

/// An integrator by its scene-file name (`leapfrog`, …).
pub(super) fn parse_integrator(name: &str) -> Result<Integrator, String> {
    Integrator::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Integrator::ALL.iter().map(|i| i.name()).collect();
        format!("unknown integrator `{name}`, expected one of {}", names.join(", "))
    })
}

fn positive(name: &str, value: f64, unit: &str) -> anyhow::Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        bail!("{name} must be a positive number of {unit}, got {value}")
    }
}

pub fn run(args: &RecordArgs) -> anyhow::Result<Outcome> {
    let log_hz = positive("--log-hz", args.log_hz, "frames per second")?;
    if let Some(dt) = args.dt {
        positive("--dt", dt, "seconds")?;
    }
    if let Some(duration) = args.duration {
        positive("--duration", duration, "seconds")?;
    }
    let mut scene = super::load(&args.scene)?;
    if args.dt.is_some() || args.integrator.is_some() {
        scene.file.dt = args.dt.unwrap_or(scene.file.dt);
        scene.file.integrator = args.integrator.unwrap_or(scene.file.integrator);
        scene = tether_scene::retime(scene)?;
    }
    let duration = args.duration.unwrap_or(scene.file.duration);
    super::warn_if_unstable(&scene.world);
    let world = &mut scene.world;
    let dt = world.dt();
    let total_steps = (duration / dt).round().max(1.0) as u64;
    let steps_per_frame = ((1.0 / (log_hz * dt)).round() as u64).max(1);
    let recorder = Recorder::to_file(&args.output, world).with_context(|| format!("cannot write {}", args.output.display()))?;
    let interrupted = Arc::new(AtomicBool::new(false));
    let flag = Arc::clone(&interrupted);
    ctrlc::set_handler(move || flag.store(true, Ordering::SeqCst)).context("installing the Ctrl-C / SIGTERM handler")?;

    recorder.log_frame(world)?;
    let progress = ProgressBar::new(total_steps).with_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} steps  {msg}").expect("the template is a valid literal"),
    );
    let mut failure: Option<StepError> = None;
    for step in 1..=total_steps {
        if interrupted.load(Ordering::SeqCst) {
            break;
        }
        if let Err(error) = world.step() {
            failure = Some(error);
            break;
        }
        if step % steps_per_frame == 0 || step == total_steps {
            recorder.log_frame(world)?;
            progress.set_position(step);
            progress.set_message(format!("t = {:.3} s", world.time()));
        }
    }
    progress.finish_and_clear();
    recorder.finish()?;
    let output = args.output.display();
    if let Some(error) = failure {
        bail!("{error}\nthe recording {output} holds everything up to the last healthy frame");
    }
    if interrupted.load(Ordering::SeqCst) {
        eprintln!("interrupted at t = {:.6} s; {output} is complete up to there", world.time());
        return Ok(Outcome::Interrupted);
    }
    eprintln!("recorded {total_steps} steps ({duration} s simulated) to {output}");
    Ok(Outcome::Finished)
}
