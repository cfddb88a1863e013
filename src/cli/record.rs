//! `tether record SCENE -o OUT.rrd`: a headless run written to a Rerun recording.

use anyhow::{Context as _, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use std::path::PathBuf;
use tether::record::Recorder;

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
}

pub fn run(args: &RecordArgs) -> anyhow::Result<()> {
    if !(args.log_hz.is_finite() && args.log_hz > 0.0) {
        bail!("--log-hz must be a positive number of frames per second, got {}", args.log_hz);
    }
    let mut scene = super::load(&args.scene)?;
    let duration = args.duration.unwrap_or(scene.file.duration);
    if !(duration.is_finite() && duration > 0.0) {
        bail!("--duration must be a positive number of seconds, got {duration}");
    }
    let world = &mut scene.world;
    let dt = world.dt();
    let total_steps = (duration / dt).round().max(1.0) as u64;
    let steps_per_frame = ((1.0 / (args.log_hz * dt)).round() as u64).max(1);
    let recorder = Recorder::to_file(&args.output, world).with_context(|| format!("cannot write {}", args.output.display()))?;
    recorder.log_frame(world)?;
    let progress = ProgressBar::new(total_steps).with_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} steps  {msg}").expect("the template is a valid literal"),
    );
    for step in 1..=total_steps {
        world.step()?;
        if step % steps_per_frame == 0 || step == total_steps {
            recorder.log_frame(world)?;
            progress.set_position(step);
            progress.set_message(format!("t = {:.3} s", world.time()));
        }
    }
    progress.finish_and_clear();
    recorder.finish()?;
    eprintln!("recorded {total_steps} steps ({duration} s simulated) to {}", args.output.display());
    Ok(())
}
