//! The simulation thread: it owns the running [`World`], steps it while simulated time lags the
//! wall clock × speed (MuJoCo simulate's physics loop), takes [`Command`]s over a channel,
//! streams frames through the [`Recorder`] and sends [`Report`]s back. The GUI never waits on it:
//! it sends commands and drains reports.
//!
//! Pacing: the thread works in ticks of [`TICK`] of wall time. Running, a tick steps until
//! simulated time reaches `t_anchor + speed × (wall − wall_anchor)` or the tick's compute budget
//! is spent (then the anchor moves: the simulation runs slower than asked, and the status says
//! how fast it really goes), and waits for commands for the rest of the tick. Paused, it blocks
//! on the channel: no core is spent. A command is taken at the latest one tick after it was
//! sent, before the next step.
//!
//! A step that fails (divergence, a coupling without forces) pauses the run with the error's
//! message, as `tether record` stops with it; the world must then be reset.

use crate::physics::body::BodyState;
use crate::physics::coupling::contact::Opposing;
use crate::physics::coupling::{Coupling, CouplingKind};
use crate::physics::energy::EnergyReport;
use crate::physics::integrator::Timing;
use crate::physics::stability::{self, Limiter};
use crate::physics::world::World;
use crate::physics::Vec3;
use crate::record::Recorder;
use super::stream::Sinks;
use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender, TryRecvError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Wall time of one tick of the thread, about one display frame [s].
pub const TICK: Duration = Duration::from_millis(16);

/// Share of a tick the thread may spend stepping.
const BUDGET: Duration = Duration::from_millis(12);

/// Frames logged per second of simulated time, as `tether record`'s default.
const LOG_HZ: f64 = 60.0;

/// At most this many frames per tick reach the viewer (faster runs log more sparsely).
const FRAMES_PER_TICK: f64 = 8.0;

/// How fast simulated time runs.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Speed {
    /// Simulated seconds per wall-clock second (1 = real time).
    Factor(f64),
    /// As fast as the machine steps.
    Max,
}

/// A scene ready to run: its world and a label for recordings and messages.
pub struct Run {
    pub label: String,
    pub world: World,
}

/// What the GUI asks of the simulation thread.
pub enum Command {
    Play,
    Pause,
    /// One world step (paused).
    Step,
    /// Back to t = 0 with the current parameters, as a new recording.
    Reset,
    SetSpeed(Speed),
    /// Time step, integrator and substeps, applied at the current time.
    SetTiming(Timing),
    /// Coupling `index` replaced by `coupling` (already checked by the scene builder) without a
    /// restart; `sent` dates the request, to measure how long it took to apply.
    SetCoupling { index: usize, coupling: Coupling, sent: Instant },
    /// A new scene, paused at t = 0.
    Load(Box<Run>),
    /// A copy of the running world, for inspection (tests, tools).
    Snapshot(Sender<Option<World>>),
}

/// What the simulation thread tells the GUI.
#[derive(Debug, Clone)]
pub enum Report {
    Status(Box<Status>),
    /// Something happened (a scene loaded, a value applied).
    Message(String),
    /// A command was refused, or a step failed (the run is paused).
    Error(String),
}

/// The running simulation at one instant.
#[derive(Debug, Clone, Default)]
pub struct Status {
    pub label: String,
    /// Simulated time [s] and world steps since t = 0.
    pub time: f64,
    pub steps: u64,
    pub running: bool,
    /// Why the run stopped, if a step failed.
    pub failure: Option<String>,
    pub energy: EnergyReport,
    /// `balance()` at t = 0 [J]: the drift is measured from it.
    pub initial_balance: f64,
    pub timing: Option<Timing>,
    /// Integrator step `dt / substeps` [s] and substeps per world step.
    pub step_size: f64,
    pub substeps: u32,
    /// Stable time step of every coupling [s] (`None`: nothing limits it), in scene order.
    pub coupling_limits: Vec<(String, Option<f64>)>,
    /// Stable time step set by the fastest spinning body, if any spins [s].
    pub rotation_limit: Option<(String, f64)>,
    /// Time step that resolves each contact's impact, `τ/10` [s] (not a stability limit).
    pub impact_limits: Vec<(String, f64)>,
    /// What the contact estimator needs of each contact.
    pub contacts: Vec<ContactStatus>,
    pub bodies: Vec<BodyStatus>,
    /// Simulated seconds per wall second, and world steps per wall second, over the last tick.
    pub rate: f64,
    pub steps_per_second: f64,
}

/// A contact coupling as the estimator sees it (PHYSICS.md §4).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactStatus {
    /// Coupling index in the scene, and name.
    pub index: usize,
    pub name: String,
    /// Mass of the body [kg], and of the opposing body (`None` against the environment).
    pub mass: f64,
    pub other_mass: Option<f64>,
    /// Expected contact area `A` [m²] and range `d0` [m].
    pub area: f64,
    pub range: f64,
}

/// A body's state, synchronised at the current time.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyStatus {
    pub name: String,
    /// Position of G [m], velocity of G [m/s], angular velocity [rad/s], world axes.
    pub position: Vec3,
    pub velocity: Vec3,
    pub angular_velocity: Vec3,
}

/// The GUI's side of the thread: send commands, drain reports; dropping it stops and joins the
/// thread (which flushes its recording).
pub struct Simulation {
    commands: Option<Sender<Command>>,
    reports: Receiver<Report>,
    thread: Option<JoinHandle<()>>,
}

/// Called by the thread after each report, so a sleeping GUI repaints.
pub type Wake = Arc<dyn Fn() + Send + Sync>;

impl Simulation {
    /// Starts the thread with no scene, paused at real-time speed.
    pub fn spawn(sinks: Sinks, wake: Wake) -> std::io::Result<Self> {
        let (commands, inbox) = mpsc::channel();
        let (outbox, reports) = mpsc::channel();
        let thread = std::thread::Builder::new().name("simulation".into()).spawn(move || Runner::new(sinks, outbox, wake).run(&inbox))?;
        Ok(Self { commands: Some(commands), reports, thread: Some(thread) })
    }

    /// Sends a command; never blocks. After [`Simulation::stop`] it is lost.
    pub fn send(&self, command: Command) {
        if let Some(commands) = &self.commands {
            commands.send(command).ok();
        }
    }

    /// The reports sent since the last call, oldest first; never blocks.
    pub fn drain(&self) -> Vec<Report> {
        self.reports.try_iter().collect()
    }

    /// A copy of the running world, waiting at most `timeout` for the thread (tests, tools).
    pub fn snapshot(&self, timeout: Duration) -> Option<World> {
        let (reply, answer) = mpsc::channel();
        self.send(Command::Snapshot(reply));
        answer.recv_timeout(timeout).ok().flatten()
    }
}

impl Simulation {
    /// Stops the thread and waits for it; it flushes its recording first. Later commands are
    /// lost.
    pub fn stop(&mut self) {
        // Closing the channel ends the thread's loop.
        self.commands.take();
        if let Some(thread) = self.thread.take() {
            thread.join().ok();
        }
    }
}

impl Drop for Simulation {
    fn drop(&mut self) {
        self.stop();
    }
}

/// Where simulated time should be: `sim + speed × (now − wall)`.
#[derive(Debug, Clone, Copy)]
struct Anchor {
    wall: Instant,
    sim: f64,
}

/// The thread's state.
struct Runner {
    sinks: Sinks,
    reports: Sender<Report>,
    wake: Wake,
    run: Option<Run>,
    /// The current run's recording (`None` only if it could not be opened).
    recorder: Option<Recorder>,
    running: bool,
    failure: Option<String>,
    speed: Speed,
    anchor: Anchor,
    initial_balance: f64,
    last_logged: f64,
    log_period: f64,
    /// Simulated seconds and steps of the last tick, and the wall time since the tick before.
    last_tick: (f64, u64, Duration),
    last_advance: Instant,
}

impl Runner {
    fn new(sinks: Sinks, reports: Sender<Report>, wake: Wake) -> Self {
        Self {
            sinks,
            reports,
            wake,
            run: None,
            recorder: None,
            running: false,
            failure: None,
            speed: Speed::Factor(1.0),
            anchor: Anchor { wall: Instant::now(), sim: 0.0 },
            initial_balance: 0.0,
            last_logged: f64::NEG_INFINITY,
            log_period: 1.0 / LOG_HZ,
            last_tick: (0.0, 0, TICK),
            last_advance: Instant::now(),
        }
    }

    /// The loop: commands, steps, status, until the GUI's handle drops.
    fn run(mut self, inbox: &Receiver<Command>) {
        loop {
            // Running: wait out the tick (not at all as fast as possible); paused: sleep until told.
            let first = match (self.running, self.speed) {
                (true, Speed::Max) => inbox.try_recv().map_err(|e| e == TryRecvError::Disconnected),
                (true, Speed::Factor(_)) => inbox.recv_timeout(TICK.saturating_sub(self.last_advance.elapsed())).map_err(|e| e == RecvTimeoutError::Disconnected),
                (false, _) => inbox.recv().map_err(|_| true),
            };
            match first {
                Ok(command) => self.handle(command),
                Err(true) => break,
                Err(false) => {}
            }
            while let Ok(command) = inbox.try_recv() {
                self.handle(command);
            }
            if self.running {
                self.advance();
            }
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
            Command::Load(run) => self.load(*run),
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
        if self.run.is_none() {
            return self.report(Report::Error("no scene loaded".into()));
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
        let target = match self.speed {
            Speed::Factor(factor) => self.anchor.sim + factor * start.duration_since(self.anchor.wall).as_secs_f64(),
            Speed::Max => f64::INFINITY,
        };
        while self.running && self.world_time() < target && start.elapsed() < BUDGET {
            self.step_once();
        }
        if self.running && self.world_time() < target && matches!(self.speed, Speed::Factor(_)) {
            // Behind the wall clock: go on from here rather than run to catch up.
            self.anchor = Anchor { wall: Instant::now(), sim: self.world_time() };
        }
        let advanced = self.world_time() - t0;
        self.last_tick = (advanced, self.world_steps() - steps0, since_last);
        self.log_period = (advanced / FRAMES_PER_TICK).max(1.0 / LOG_HZ);
    }

    /// One world step; a failure pauses the run with its message. Frames are logged every
    /// `log_period` of simulated time, and after every single step.
    fn step_once(&mut self) {
        let Some(run) = &mut self.run else { return };
        if self.failure.is_some() {
            return;
        }
        if let Err(error) = run.world.step() {
            self.running = false;
            let message = error.to_string();
            self.failure = Some(message.clone());
            return self.report(Report::Error(message));
        }
        if !self.running || run.world.time() - self.last_logged >= self.log_period {
            self.log_frame();
        }
    }

    fn log_frame(&mut self) {
        let (Some(run), Some(recorder)) = (&self.run, &self.recorder) else { return };
        self.last_logged = run.world.time();
        if let Err(error) = recorder.log_frame(&run.world) {
            self.report(Report::Error(format!("recording: {error}")));
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
        self.running = false;
        self.failure = None;
        self.start_recording();
        self.report(Report::Message(format!("loaded {label}")));
    }

    /// Ends the current recording and starts a new one for the current world, its first frame
    /// logged.
    fn start_recording(&mut self) {
        self.finish_recording();
        let Some(run) = &self.run else { return };
        self.initial_balance = run.world.energy().balance();
        let recording = self.sinks.stream(&run.label).and_then(|stream| {
            super::stream::send_layout(&stream, &run.world)?;
            Recorder::new(stream, &run.world)
        });
        match recording {
            Ok(recorder) => {
                self.recorder = Some(recorder);
                self.log_frame();
            }
            Err(error) => self.report(Report::Error(format!("recording: {error}"))),
        }
        self.restart_clock();
    }

    /// Flushes the current recording (the sinks stay open for the next run).
    fn finish_recording(&mut self) {
        if let Some(recorder) = self.recorder.take()
            && let Err(error) = recorder.finish()
        {
            self.report(Report::Error(format!("recording: {error}")));
        }
    }

    fn set_timing(&mut self, timing: Timing) {
        let Some(run) = &mut self.run else { return };
        let report = match run.world.set_timing(timing) {
            Ok(()) => Report::Message(format!(
                "dt = {:e} s, {} substep(s), {:?} from t = {:.4} s",
                timing.dt,
                run.world.substeps(),
                timing.integrator.name(),
                run.world.time()
            )),
            Err(error) => Report::Error(error.to_string()),
        };
        self.report(report);
    }

    fn set_coupling(&mut self, index: usize, coupling: Coupling, sent: Instant) {
        let Some(run) = &mut self.run else { return };
        let name = coupling.name.clone();
        match run.world.replace_coupling(index, coupling) {
            Ok(()) => {
                let (time, latency) = (run.world.time(), sent.elapsed().as_secs_f64() * 1e3);
                self.log_frame();
                self.report(Report::Message(format!("coupling \"{name}\" applied at t = {time:.4} s, {latency:.2} ms after the edit")));
            }
            Err(error) => self.report(Report::Error(error.to_string())),
        }
    }

    fn send_status(&self) {
        let Some(run) = &self.run else { return };
        let world = &run.world;
        let (advanced, steps, wall) = self.last_tick;
        let wall = wall.as_secs_f64().max(1e-6);
        let limits = stability::limits(world);
        let coupling_limit = |i: usize| limits.iter().find(|l| l.limiter == Limiter::Coupling(i)).map(|l| l.dt);
        let rotation_limit = limits
            .iter()
            .filter_map(|l| match l.limiter {
                Limiter::Rotation(body) => Some((world.bodies[body].name.clone(), l.dt)),
                Limiter::Coupling(_) | Limiter::Impact(_) => None,
            })
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let status = Status {
            label: run.label.clone(),
            time: world.time(),
            steps: world.steps(),
            running: self.running,
            failure: self.failure.clone(),
            energy: world.energy(),
            initial_balance: self.initial_balance,
            timing: Some(world.timing()),
            step_size: world.step_size(),
            substeps: world.substeps(),
            coupling_limits: world.couplings.iter().enumerate().map(|(i, c)| (c.name.clone(), coupling_limit(i))).collect(),
            rotation_limit,
            impact_limits: stability::impact_limits(world).iter().map(|l| (l.describe(world), l.dt)).collect(),
            contacts: contacts(world),
            bodies: (0..world.bodies.len()).map(|i| body_status(world, i)).collect(),
            rate: if self.running { advanced / wall } else { 0.0 },
            steps_per_second: if self.running { steps as f64 / wall } else { 0.0 },
        };
        self.report(Report::Status(Box::new(status)));
    }
}

fn contacts(world: &World) -> Vec<ContactStatus> {
    let contact = |(index, coupling): (usize, &Coupling)| match &coupling.kind {
        CouplingKind::Contact(contact) => Some(ContactStatus {
            index,
            name: coupling.name.clone(),
            mass: world.bodies[contact.body].mass(),
            other_mass: match &contact.against {
                Opposing::Body { body, .. } => Some(world.bodies[*body].mass()),
                Opposing::Planes(_) => None,
            },
            area: contact.expected_area,
            range: contact.law.range,
        }),
        CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => None,
    };
    world.couplings.iter().enumerate().filter_map(contact).collect()
}

fn body_status(world: &World, index: usize) -> BodyStatus {
    let BodyState { position, orientation, velocity, angular_velocity } = world.state(index);
    BodyStatus { name: world.bodies[index].name.clone(), position, velocity, angular_velocity: orientation * angular_velocity }
}
