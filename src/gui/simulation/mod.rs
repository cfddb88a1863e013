//! The simulation thread: it owns the running world, steps it while simulated time lags the wall
//! clock × speed (MuJoCo simulate's physics loop), takes commands over a channel, streams frames
//! to the recording and sends reports back. The GUI never waits on it: it sends commands and
//! drains reports.
//!
//! - [`protocol`]: the commands and reports;
//! - [`runner`]: the thread's loop, pacing and command handling;
//! - [`recording`]: the recording of each run, opened, fed and finished;
//! - [`status`]: the run at one instant, as the panel shows it.

pub mod protocol;
mod recording;
mod runner;
pub mod status;

use super::stream::Sinks;
pub use protocol::{Command, Curve, OffsetCurve, Report, Run, Speed};
pub use runner::TICK;
pub use status::{BodyStatus, ContactStatus, Status};
use std::sync::Arc;
use std::sync::mpsc::{self, Receiver, Sender};
use std::thread::JoinHandle;
use std::time::Duration;
use tether_physics::world::World;

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
        let thread = std::thread::Builder::new()
            .name("simulation".into())
            .spawn(move || runner::run(sinks, outbox, wake, &inbox))?;
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
