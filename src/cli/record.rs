//! `tether record SCENE -o OUT.rrd`: a headless run written to a Rerun recording.
//!
//! The run stops cleanly — the recording complete up to there, footer written — when it ends,
//! when the simulation diverges (exit 1, with the body, the time and the stable time step), and
//! on Ctrl-C or SIGTERM (exit 130).
//!
//! The file holds the window's layout (a blueprint), its 3D view's eye framing what moves
//! (`tether_record::framing`), so that it opens in Rerun's viewer as in the window.
//!
//! `--face-arrows` draws contacts' face forces (none by default: they are the costliest kind of
//! entity, and the contact force plots are always there); `--timing` reports where the time
//! went and what each kind of entity costs per frame.

use super::flags::positive;
use anyhow::{Context as _, bail};
use clap::Args;
use indicatif::{ProgressBar, ProgressState, ProgressStyle};
use std::path::PathBuf;
use std::sync::atomic::Ordering;
use tether_physics::integrator::Integrator;
use tether_physics::world::{StepError, World};
use tether_record::framing::{Framing, MotionSweep, view_direction};
use tether_record::layout::{self, Camera};
use tether_record::{ArrowedContacts, FaceArrows, FrameSchedule, Recorder};

#[derive(Debug, Args)]
pub struct RecordArgs {
    /// Scene file (.ron), or a MoorDyn input file.
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
    /// Draw the face forces of these contacts as arrows: `all`, or names separated by commas
    /// (default: none; the contact force plots are always recorded).
    #[arg(long, value_name = "all|NAME,...", value_parser = parse_contacts)]
    face_arrows: Option<ArrowedContacts>,
    /// Draw the face arrows from this simulated time on [s].
    #[arg(long, value_name = "S", requires = "face_arrows")]
    face_arrows_from: Option<f64>,
    /// Draw the face arrows up to this simulated time [s].
    #[arg(long, value_name = "S", requires = "face_arrows")]
    face_arrows_until: Option<f64>,
    /// Report the time spent in the physics and in the recording, and the bytes per frame of
    /// each kind of entity.
    #[arg(long)]
    timing: bool,
    /// Refuse a run of more integrator steps than this (duration ÷ dt × sub-steps).
    #[arg(long, value_name = "N", default_value_t = tether_analysis::run_length::DEFAULT_MAX_STEPS)]
    max_steps: u64,
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

/// `all`, or contact names separated by commas.
fn parse_contacts(text: &str) -> Result<ArrowedContacts, String> {
    if text == "all" {
        return Ok(ArrowedContacts::All);
    }
    let names: Vec<String> = text.split(',').map(|name| name.trim().to_string()).collect();
    if names.iter().any(String::is_empty) {
        return Err(format!("expected `all` or contact names separated by commas, got `{text}`"));
    }
    Ok(ArrowedContacts::Named(names))
}

/// The face arrows the flags ask for.
fn face_arrows(args: &RecordArgs) -> anyhow::Result<FaceArrows> {
    for (name, time) in [("--face-arrows-from", args.face_arrows_from), ("--face-arrows-until", args.face_arrows_until)]
    {
        if let Some(time) = time.filter(|t| !t.is_finite()) {
            bail!("{name} must be a time in seconds, got {time}");
        }
    }
    if let (Some(from), Some(until)) = (args.face_arrows_from, args.face_arrows_until)
        && until < from
    {
        bail!("--face-arrows-until ({until} s) is before --face-arrows-from ({from} s)");
    }
    Ok(FaceArrows {
        contacts: args.face_arrows.clone().unwrap_or_default(),
        from: args.face_arrows_from,
        until: args.face_arrows_until,
    })
}

/// Draws the contacts' planes and sends the window's layout, its eye framing the run (the file
/// opens in any viewer as in the window), from `sweep` of the run's first seconds (finished on a
/// copy of `world` when the run was shorter).
fn frame(recorder: &Recorder, world: &World, sweep: MotionSweep) -> anyhow::Result<()> {
    let swept = sweep.finish(world);
    recorder.log_planes(world, &swept)?;
    let camera = Camera { framing: Framing::around(&swept, &view_direction(world)), follow: None };
    layout::send_layout_with_fits(recorder.stream(), world, &[], &camera)?;
    Ok(())
}

pub fn run(args: &RecordArgs) -> anyhow::Result<Outcome> {
    let log_hz = positive("--log-hz", args.log_hz, "Hz")?;
    if let Some(duration) = args.duration {
        positive("--duration", duration, "s")?;
    }
    let mut scene = super::load(&args.scene)?;
    if args.dt.is_some() || args.integrator.is_some() {
        scene.file.dt = args.dt.unwrap_or(scene.file.dt);
        scene.file.integrator = args.integrator.unwrap_or(scene.file.integrator);
        // The time step is checked where the physics builds it (`Timing::new`): the flag reads
        // the message a scene file's `dt` would.
        scene = tether_scene::retime(scene).map_err(|error| anyhow::anyhow!("--dt: {}", error.message))?;
    }
    let duration = args.duration.unwrap_or(scene.file.duration);
    super::warn_if_unstable(&scene.world);
    tether_analysis::run_length::check(&scene.world, duration, args.max_steps)
        .map_err(|long| anyhow::anyhow!("{long} (or --max-steps N)"))?;
    let world = &mut scene.world;
    let dt = world.dt();
    let total_steps = (duration / dt).round().max(1.0) as u64;
    let frames = FrameSchedule::new(log_hz, dt, total_steps);
    let face_arrows = face_arrows(args)?;
    face_arrows.check(world)?;
    // The framing (the eye, the contacts' planes) sweeps what moves over the run's first seconds:
    // this run's own steps, rather than a copy's.
    let mut sweep = MotionSweep::start(world);
    let mut recorder = Recorder::to_file_unframed(&args.output, world, &face_arrows)
        .with_context(|| format!("cannot write {}", args.output.display()))?;
    let interrupted = super::cancel_on_ctrl_c()?;

    let mut stopwatch = super::timing::Stopwatch::start();
    stopwatch.recorder(|| recorder.log_frame(world))?;
    let progress = ProgressBar::new(total_steps).with_style(
        ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} steps  t = {sim_time} s")
            .expect("the template is a valid literal")
            // Formatted when the bar is drawn (a few times a second), not at every frame.
            .with_key("sim_time", move |state: &ProgressState, text: &mut dyn std::fmt::Write| {
                let _ = write!(text, "{:.3}", state.pos() as f64 * dt);
            }),
    );
    let mut failure: Option<StepError> = None;
    for step in 1..=total_steps {
        if interrupted.load(Ordering::SeqCst) {
            // The frames so far and the file's footer are written below: not cut by the watchdog.
            tether_analysis::interrupt::finishing();
            break;
        }
        if let Err(error) = world.step() {
            sweep.halt();
            failure = Some(error);
            break;
        }
        sweep.after_step(world);
        if frames.is_due(step) {
            stopwatch.recorder(|| recorder.log_frame(world))?;
            progress.set_position(step);
        }
    }
    progress.finish_and_clear();
    // The framing is the recorder's work (and a short run's copy stepped to finish the sweep);
    // the layout's memory streams wait for their threads.
    stopwatch
        .recorder_waiting(|| frame(&recorder, world, sweep))
        .with_context(|| format!("cannot write {}", args.output.display()))?;
    let stats = stopwatch.recorder_waiting(|| recorder.finish())?;
    if args.timing {
        let file_bytes = std::fs::metadata(&args.output).map_or(0, |m| m.len());
        let measured =
            super::timing::Measured { stats: &stats, simulated: world.time(), steps: world.steps(), file_bytes };
        eprint!("{}", stopwatch.report(&measured));
    }
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
