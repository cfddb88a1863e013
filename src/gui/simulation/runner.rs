//! The simulation thread's loop. It works in ticks of [`TICK`] of wall time. Running, a tick
//! steps until simulated time reaches `t_anchor + speed × (wall − wall_anchor)` or the tick's
//! compute budget is spent (then the anchor moves: the simulation runs slower than asked, and
//! the status says how fast it really goes), and waits for commands for the rest of the tick.
//! Paused, it blocks on the channel: no core is spent. A command is taken at the latest one tick
//! after it was sent, before the next step.
//!
//! A step that fails (divergence, a coupling without forces) pauses the run with the error's
//! message, as `tether record` stops with it; the world must then be reset.

use super::Wake;
use super::protocol::{Command, Report, Run, Speed};
use super::recording::Recording;
use super::status::{self, RunState};
use crate::figures;
use crate::gui::stream::Sinks;
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender, TryRecvError};
use std::time::{Duration, Instant};
use tether_analysis::run_length;
use tether_physics::coupling::{Coupling, CouplingKind, LineModel};
use tether_physics::integrator::Timing;
use tether_physics::seabed::Seabed;
use tether_physics::statics::{Dof, Settings, equilibrium, offsets};
use tether_physics::world::World;

/// Wall time of one tick of the thread, about one display frame [s].
pub const TICK: Duration = Duration::from_millis(16);

/// Share of a tick the thread may spend stepping.
const BUDGET: Duration = Duration::from_millis(12);

/// Wall time over which the status's speed (×real time, steps/s) is measured: many ticks, so
/// that a step longer than a tick (RK4 at 50 ms: one step every third tick) reads as its
/// average, not as ×3 and ×0 in turn.
const PACE_WINDOW: Duration = Duration::from_millis(500);

/// Runs the thread until the GUI's handle drops: commands, steps, status.
pub(super) fn run(sinks: Sinks, reports: Sender<Report>, wake: Wake, inbox: &Receiver<Command>) {
    SimulationLoop::new(sinks, reports, wake).run(inbox);
}

/// Where simulated time should be: `sim + speed × (now − wall)`.
#[derive(Debug, Clone, Copy)]
struct Anchor {
    wall: Instant,
    sim: f64,
}

/// Simulated seconds, world steps and wall time, summed tick by tick over [`PACE_WINDOW`]; the
/// status shows the last full window (while the first fills, the sums so far: a shown wall time
/// under the window is the first one filling).
#[derive(Debug, Clone, Copy)]
struct Pace {
    sums: (f64, u64, Duration),
    shown: (f64, u64, Duration),
}

impl Pace {
    fn new() -> Self {
        Self { sums: (0.0, 0, Duration::ZERO), shown: (0.0, 0, TICK) }
    }

    /// Adds a tick that advanced `advanced` [s] in `steps` over `wall`.
    fn add(&mut self, advanced: f64, steps: u64, wall: Duration) {
        let (sum_advanced, sum_steps, sum_wall) = &mut self.sums;
        *sum_advanced += advanced;
        *sum_steps += steps;
        *sum_wall += wall;
        let full = *sum_wall >= PACE_WINDOW;
        let first_filling = self.shown.2 < PACE_WINDOW;
        if full || first_filling {
            self.shown = self.sums;
        }
        if full {
            self.sums = (0.0, 0, Duration::ZERO);
        }
    }
}

/// The thread's state.
struct SimulationLoop {
    reports: Sender<Report>,
    wake: Wake,
    run: Option<Run>,
    recording: Recording,
    running: bool,
    failure: Option<String>,
    speed: Speed,
    anchor: Anchor,
    initial_balance: f64,
    /// How fast the run went, over the last [`PACE_WINDOW`].
    pace: Pace,
    last_advance: Instant,
}

impl SimulationLoop {
    fn new(sinks: Sinks, reports: Sender<Report>, wake: Wake) -> Self {
        Self {
            reports,
            wake,
            run: None,
            recording: Recording::new(sinks),
            running: false,
            failure: None,
            speed: Speed::Factor(1.0),
            anchor: Anchor { wall: Instant::now(), sim: 0.0 },
            initial_balance: 0.0,
            pace: Pace::new(),
            last_advance: Instant::now(),
        }
    }

    /// The loop: commands, steps, status, until the GUI's handle drops.
    fn run(mut self, inbox: &Receiver<Command>) {
        // Ends: when the GUI's handle drops, the channel disconnects and `first` says so.
        loop {
            // Running: wait out the tick (not at all as fast as possible); paused: sleep until told.
            let first = match (self.running, self.speed) {
                (true, Speed::Max) => inbox.try_recv().map_err(|e| e == TryRecvError::Disconnected),
                (true, Speed::Factor(_)) => inbox
                    .recv_timeout(TICK.saturating_sub(self.last_advance.elapsed()))
                    .map_err(|e| e == RecvTimeoutError::Disconnected),
                (false, _) => inbox.recv().map_err(|_| true),
            };
            match first {
                Ok(command) => self.handle(command),
                Err(true) => break,
                Err(false) => {}
            }
            // Ends: the commands already queued (the GUI sends one per user action).
            while let Ok(command) = inbox.try_recv() {
                self.handle(command);
            }
            if self.running {
                self.advance();
            }
            // The frames of the last few ticks to the viewer, one chunk per entity.
            let flushed = self.recording.flush(self.running);
            self.report_failure(flushed);
            self.send_status();
        }
        self.finish_recording();
    }

    fn handle(&mut self, command: Command) {
        match command {
            Command::Play => self.play(),
            Command::Pause => self.running = false,
            Command::Step => {
                self.running = false;
                self.step_once();
            }
            Command::Reset => self.reset(),
            Command::SetSpeed(speed) => {
                self.speed = speed;
                self.restart_clock();
            }
            Command::SetTiming(timing) => self.set_timing(timing),
            Command::SetCoupling { index, coupling, sent } => self.set_coupling(index, coupling, sent),
            Command::SetFaceArrows(on) => self.set_face_arrows(on),
            Command::Follow(body) => {
                let set = self.recording.follow(body, self.run.as_ref().map(|run| &run.world));
                self.report_failure(set);
            }
            Command::SetWater(spec) => self.edit_water("the water", |world| world.replace_water(spec)),
            Command::SetHydro { body, spec, drift } => {
                self.edit_water("the body's coefficients in the water", |world| match drift {
                    Some(drift) => world.replace_hydro_and_drift(body, spec, drift),
                    None => world.replace_hydro(body, spec),
                })
            }
            Command::SetAir { spec, loads } => self.edit_water("the air", |world| world.replace_air(spec, loads)),
            Command::SetPotentialFlow { body, on } => self.set_potential_flow(body, on),
            Command::SetSeabed(seabed) => self.set_seabed(seabed),
            Command::Equilibrium => self.equilibrium(),
            Command::OffsetCurve { body, direction, to, steps } => {
                self.offset_curve(Dof { body, direction }, to, steps)
            }
            Command::ShowFit(measured) => {
                let Some(run) = &self.run else { return };
                let shown = self.recording.show_fit(&run.world, measured);
                self.report_failure(shown);
            }
            Command::FitModel(model) => {
                let drawn = self.recording.fit_model(model);
                self.report_failure(drawn);
            }
            Command::Load(run) => self.load(*run),
            Command::Close => self.close(),
            Command::Snapshot(reply) => {
                reply.send(self.run.as_ref().map(|run| run.world.clone())).ok();
            }
        }
    }

    fn report(&self, report: Report) {
        // The GUI dropped its receiver only when it is closing: nothing to tell then.
        self.reports.send(report).ok();
        (self.wake)();
    }

    fn play(&mut self) {
        let Some(run) = &self.run else {
            return self.report(Report::Error("no scene loaded".into()));
        };
        if let Err(long) = run_length::check(&run.world, run.duration, run_length::DEFAULT_MAX_STEPS) {
            return self
                .report(Report::Error(format!("not started: the scene's {} s at this timing: {long}", run.duration)));
        }
        if let Some(failure) = &self.failure {
            return self.report(Report::Error(format!("the run stopped ({failure}): reset it first")));
        }
        self.running = true;
        self.restart_clock();
    }

    fn restart_clock(&mut self) {
        self.anchor = Anchor { wall: Instant::now(), sim: self.world_time() };
        self.last_advance = Instant::now();
        self.pace = Pace::new();
    }

    fn world_time(&self) -> f64 {
        self.run.as_ref().map_or(0.0, |run| run.world.time())
    }

    fn world_steps(&self) -> u64 {
        self.run.as_ref().map_or(0, |run| run.world.steps())
    }

    /// Steps until simulated time catches up with the wall clock, or the budget is spent.
    fn advance(&mut self) {
        let start = Instant::now();
        let since_last = start.duration_since(self.last_advance);
        self.last_advance = start;
        let (t0, steps0) = (self.world_time(), self.world_steps());
        if self.recording.viewer_is_behind() {
            // The viewer is behind what it was sent (`stream::ViewerBacklog`): the run waits for
            // it, and goes on from here when it has caught up.
            self.anchor = Anchor { wall: start, sim: t0 };
            self.pace.add(0.0, 0, since_last);
            return;
        }
        let target = match self.speed {
            Speed::Factor(factor) => self.anchor.sim + factor * start.duration_since(self.anchor.wall).as_secs_f64(),
            Speed::Max => f64::INFINITY,
        };
        // Ends: within BUDGET of wall time.
        while self.running && self.world_time() < target && start.elapsed() < BUDGET {
            self.step_once();
        }
        if self.running && self.world_time() < target && matches!(self.speed, Speed::Factor(_)) {
            // Behind the wall clock: go on from here rather than run to catch up.
            self.anchor = Anchor { wall: Instant::now(), sim: self.world_time() };
        }
        let advanced = self.world_time() - t0;
        self.pace.add(advanced, self.world_steps() - steps0, since_last);
        self.recording.pace(advanced);
    }

    /// One world step; a failure pauses the run with its message. Frames are logged every
    /// frame period of simulated time, and after every single step.
    fn step_once(&mut self) {
        let Some(run) = &mut self.run else { return };
        if self.failure.is_some() {
            return;
        }
        if let Err(error) = run.world.step() {
            self.running = false;
            // The step that failed is shown where it can be (a first step that diverges would
            // otherwise leave the viewer at t = 0 with no sign of it); a state that is not
            // finite never reaches the recording.
            let shown = if status::finite(&run.world) {
                let time = run.world.time();
                let logged = self.recording.log(&run.world);
                self.report_failure(logged);
                format!("the viewer shows the state it reached at t = {}", figures::quantity(time, "s", 5))
            } else {
                "its state is not finite: the viewer shows the last step before".to_string()
            };
            let message = format!("{error} ({shown})");
            self.failure = Some(message.clone());
            return self.report(Report::Error(message));
        }
        let logged = if self.running { self.recording.log_if_due(&run.world) } else { self.recording.log(&run.world) };
        self.report_failure(logged);
    }

    /// Logs a frame of the current world now.
    fn log_frame(&mut self) {
        let Some(run) = &self.run else { return };
        let logged = self.recording.log(&run.world);
        self.report_failure(logged);
    }

    /// Reports what went wrong, if anything did.
    fn report_failure(&self, result: Result<(), String>) {
        if let Err(message) = result {
            self.report(Report::Error(message));
        }
    }

    fn reset(&mut self) {
        let Some(run) = &mut self.run else { return };
        match run.world.reset() {
            Ok(()) => {
                let label = run.label.clone();
                self.failure = None;
                self.start_recording();
                self.report(Report::Message(format!("{label}: reset to t = 0")));
            }
            Err(error) => self.report(Report::Error(format!("reset: {error}"))),
        }
    }

    fn load(&mut self, run: Run) {
        let label = run.label.clone();
        self.run = Some(run);
        self.recording.drop_fit();
        self.running = false;
        self.failure = None;
        self.start_recording();
        self.report(Report::Message(format!("loaded {label}")));
    }

    /// Stops the run and finishes its recording; nothing runs until the next load.
    fn close(&mut self) {
        let Some(run) = self.run.take() else { return };
        self.running = false;
        self.failure = None;
        self.recording.drop_fit();
        self.finish_recording();
        self.report(Report::Message(format!("{}: run stopped and closed", run.label)));
    }

    /// Ends the current recording and starts a new one for the current world, its first frame
    /// logged.
    fn start_recording(&mut self) {
        let Some(run) = &self.run else { return };
        self.initial_balance = run.world.energy().balance();
        let started = self.recording.start(&run.label, &run.world);
        self.report_failure(started);
        self.restart_clock();
    }

    /// Flushes the current recording (the sinks stay open for the next run).
    fn finish_recording(&mut self) {
        let finished = self.recording.finish();
        self.report_failure(finished);
    }

    /// The new time step, sub-steps and integrator; a running scene that the new timing makes
    /// too long to end (`tether_analysis::run_length`) is paused, with Play's message.
    fn set_timing(&mut self, timing: Timing) {
        let Some(run) = &mut self.run else { return };
        let report = match run.world.set_timing(timing) {
            Ok(()) => match run_length::check(&run.world, run.duration, run_length::DEFAULT_MAX_STEPS) {
                Err(long) if self.running => {
                    self.running = false;
                    Report::Error(format!(
                        "paused: the scene's {} at this timing: {long}",
                        figures::quantity(run.duration, "s", 6)
                    ))
                }
                _ => Report::Message(format!(
                    "dt = {}, {} substep(s), {:?} from t = {}",
                    figures::quantity(timing.dt(), "s", 6),
                    run.world.substeps(),
                    timing.integrator().name(),
                    figures::quantity(run.world.time(), "s", 5)
                )),
            },
            Err(error) => Report::Error(error.to_string()),
        };
        self.report(report);
    }

    fn set_coupling(&mut self, index: usize, coupling: Coupling, sent: Instant) {
        let Some(run) = &mut self.run else { return };
        let name = coupling.name.clone();
        let model_before = line_model(&run.world, index);
        match run.world.replace_coupling(index, coupling) {
            Ok(()) => {
                let (time, latency) = (run.world.time(), sent.elapsed().as_secs_f64() * 1e3);
                let short = status::short_line(&run.world, index);
                if line_model(&run.world, index) != model_before {
                    // A line switched to dynamic or back: its plot's series change.
                    let restarted = self.recording.restart_tracks(&run.world);
                    self.report_failure(restarted);
                }
                self.log_frame();
                self.report(Report::Message(format!(
                    "coupling \"{name}\" applied at t = {}, {} after the edit",
                    figures::quantity(time, "s", 5),
                    figures::quantity(latency * 1e-3, "s", 3)
                )));
                if let Some(warning) = short {
                    self.report(Report::Error(warning));
                }
            }
            Err(error) => self.report(Report::Error(error.to_string())),
        }
    }

    /// Draws every contact's face forces in the recording (or not) from the next frame on.
    fn set_face_arrows(&mut self, on: bool) {
        let set = self.recording.set_face_arrows(on, self.run.as_ref().map(|run| &run.world));
        self.report_failure(set);
    }

    /// Body `body`'s potential flow on or off, as a live edit of the water.
    fn set_potential_flow(&mut self, body: usize, on: bool) {
        let Some(run) = &self.run else { return };
        let name = run.world.bodies().get(body).map_or_else(|| format!("{body}"), |b| format!("\"{}\"", b.name));
        let what = format!("potential flow {} for body {name}", if on { "on" } else { "off" });
        self.edit_water(&what, |world| world.set_potential_flow(body, on));
    }

    /// A live edit of the water (`what` names it in the report).
    fn edit_water(
        &mut self,
        what: &str,
        edit: impl FnOnce(&mut World) -> Result<(), tether_physics::world::EditError>,
    ) {
        let Some(run) = &mut self.run else { return };
        match edit(&mut run.world) {
            Ok(()) => {
                let time = run.world.time();
                self.log_frame();
                self.report(Report::Message(format!("{what} applied at t = {}", figures::quantity(time, "s", 5))));
            }
            Err(error) => self.report(Report::Error(error.to_string())),
        }
    }

    /// The seabed replaced (its line friction `C_B` tuned); the lines' energy jump booked.
    fn set_seabed(&mut self, seabed: Seabed) {
        let Some(run) = &mut self.run else { return };
        let friction = seabed.line_friction();
        match run.world.set_seabed(seabed) {
            Ok(()) => {
                let time = run.world.time();
                self.log_frame();
                self.report(Report::Message(format!(
                    "seabed line friction C_B = {} applied at t = {}",
                    figures::number(friction, 6),
                    figures::quantity(time, "s", 5)
                )));
            }
            Err(error) => self.report(Report::Error(error.to_string())),
        }
    }

    /// The bodies jump to the static equilibrium found from where they are, at rest (paused).
    fn equilibrium(&mut self) {
        let Some(run) = &mut self.run else { return };
        let clock = Instant::now();
        let solved =
            equilibrium::solve(run.world.system(), &run.world.synchronized_states(), &[], &Settings::default());
        let placed = solved
            .map_err(|e| e.to_string())
            .and_then(|eq| run.world.place(&eq.states).map(|()| eq.iterations).map_err(|e| e.to_string()));
        match placed {
            Ok(iterations) => {
                self.running = false;
                let elapsed = clock.elapsed().as_secs_f64() * 1e3;
                self.log_frame();
                self.report(Report::Message(format!(
                    "static equilibrium in {iterations} Newton iterations ({}): the bodies placed there at rest",
                    figures::quantity(elapsed * 1e-3, "s", 3)
                )));
            }
            Err(error) => self.report(Report::Error(error)),
        }
    }

    /// The offset curve of `dof` from the static equilibrium found from where the bodies are.
    fn offset_curve(&mut self, dof: Dof, to: f64, steps: u32) {
        let Some(run) = &self.run else { return };
        let system = run.world.system();
        let settings = Settings::default();
        let curve = equilibrium::solve(system, &run.world.synchronized_states(), &[], &settings)
            .and_then(|eq| offsets::curve(system, &eq, dof, to, steps, &settings));
        let name = system.bodies().get(dof.body).map_or_else(String::new, |b| b.name.clone());
        match curve {
            Ok(curve) => {
                let points = curve.points.iter().map(|p| (p.offset, -p.load)).collect();
                self.report(Report::OffsetCurve(super::protocol::OffsetCurve {
                    body: name,
                    direction: dof.direction,
                    points,
                }));
            }
            Err(error) => {
                self.report(Report::Error(format!("offset curve of body \"{name}\" in {}: {error}", dof.direction)))
            }
        }
    }

    fn send_status(&self) {
        let Some(run) = &self.run else { return };
        let (advanced, steps, wall) = self.pace.shown;
        let state = RunState {
            label: run.label.clone(),
            running: self.running,
            failure: self.failure.clone(),
            initial_balance: self.initial_balance,
            advanced,
            steps,
            wall: wall.as_secs_f64(),
            waiting_for_viewer: self.recording.viewer_is_behind(),
        };
        self.report(Report::Status(Box::new(status::status(&run.world, &state))));
    }
}

/// Whether coupling `index` of `world` is a line, and a dynamic one (`None`: not a line).
fn line_model(world: &World, index: usize) -> Option<bool> {
    match &world.couplings().get(index)?.kind {
        CouplingKind::Catenary(line) => Some(line.model() != LineModel::QuasiStatic),
        CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::{PACE_WINDOW, Pace, TICK};

    /// RK4 at 50 ms at ×1: one step every third 16 ms tick. Each tick alone reads ×3.1 or ×0;
    /// the window reads the average: 11 steps of 50 ms in 32 ticks of 16 ms, ×1.07.
    #[test]
    fn a_step_longer_than_a_tick_reads_as_its_average() {
        let mut pace = Pace::new();
        pace.add(0.05, 1, TICK);
        assert_eq!(pace.shown, (0.05, 1, TICK), "while the first window fills: the sums so far");
        for tick in 1..33 {
            let steps = u64::from(tick % 3 == 0);
            pace.add(0.05 * steps as f64, steps, TICK);
        }
        let (advanced, steps, wall) = pace.shown;
        assert_eq!(wall, TICK * 32, "the window closes at its first tick past {PACE_WINDOW:?}");
        assert_eq!(steps, 11);
        assert!((advanced / wall.as_secs_f64() - 0.55 / 0.512).abs() < 1e-12, "×{}", advanced / wall.as_secs_f64());
        // The next window's ticks are summed apart; the full window stays shown until they fill.
        pace.add(0.05, 1, TICK);
        assert_eq!(pace.shown.1, 11);
        assert_eq!(pace.sums, (0.05, 1, TICK * 2));
    }
}
