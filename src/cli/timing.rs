//! `tether record --timing`: where a recording run's CPU time went — the physics, the recorder
//! on the simulation thread, Rerun's encoding and writing threads — and what each kind of
//! entity costs per frame.
//!
//! CPU time, not wall time: the machine may be shared, and Rerun's threads work beside the
//! simulation. The recorder's frame calls on the simulation thread are timed one by one by the
//! monotonic clock (20 ns a reading, against a system call of about 0.5 µs for the thread's CPU
//! clock, which at 60 frames per second cost a small scene's run as much as its recorder): the
//! thread computes throughout such a call. Its last call, which waits for Rerun's threads to
//! write everything, is timed by the thread's CPU clock (the wait is their time, counted once).
//! The physics is the rest of the simulation thread's CPU time; the recording is the rest of
//! the process's.

use std::fmt::Write as _;
use std::time::{Duration, Instant};
use tether_analysis::runner::{process_cpu_seconds, thread_cpu_seconds};
use tether_record::RecordStats;

/// The clocks of a run, started with it.
pub(super) struct Stopwatch {
    started: Instant,
    process_cpu: f64,
    thread_cpu: f64,
    /// Time of the simulation thread inside the recorder's calls.
    recorder: Duration,
}

/// What the run did, as measured at its end.
pub(super) struct Measured<'a> {
    pub stats: &'a RecordStats,
    /// Simulated time covered [s].
    pub simulated: f64,
    /// World steps taken.
    pub steps: u64,
    /// Size of the finished `.rrd` file [bytes].
    pub file_bytes: u64,
}

impl Stopwatch {
    pub(super) fn start() -> Self {
        Self {
            started: Instant::now(),
            process_cpu: process_cpu_seconds(),
            thread_cpu: thread_cpu_seconds(),
            recorder: Duration::ZERO,
        }
    }

    /// Runs `call` (a call of the recorder that computes, never waits) and adds its time to the
    /// recorder's.
    pub(super) fn recorder<T>(&mut self, call: impl FnOnce() -> T) -> T {
        let start = Instant::now();
        let result = call();
        self.recorder += start.elapsed();
        result
    }

    /// Runs `call` (a call of the recorder that waits for Rerun's threads) and adds the CPU time
    /// it took on this thread to the recorder's.
    pub(super) fn recorder_waiting<T>(&mut self, call: impl FnOnce() -> T) -> T {
        let start = thread_cpu_seconds();
        let result = call();
        self.recorder += Duration::from_secs_f64((thread_cpu_seconds() - start).max(0.0));
        result
    }

    /// The report, a few lines for stderr.
    pub(super) fn report(&self, run: &Measured) -> String {
        let wall = self.started.elapsed().as_secs_f64();
        let process = process_cpu_seconds() - self.process_cpu;
        let recorder = self.recorder.as_secs_f64();
        let physics = (thread_cpu_seconds() - self.thread_cpu - recorder).max(0.0);
        let recording = (process - physics).max(0.0);
        let rerun_threads = (recording - recorder).max(0.0);
        let share = |part: f64| 100.0 * part / process.max(f64::MIN_POSITIVE);
        let stats = run.stats;
        let frames = stats.frames.max(1) as f64;
        let mut text = String::new();
        // Writing to a String cannot fail.
        let _ = writeln!(
            text,
            "timing: {:.3} s simulated in {wall:.3} s wall ({:.1}× real time), {} steps, {} frames",
            run.simulated,
            run.simulated / wall.max(f64::MIN_POSITIVE),
            run.steps,
            stats.frames
        );
        let _ = writeln!(
            text,
            "  CPU {process:.3} s: physics {physics:.3} s ({:.0}%, {:.2} µs per step), recording {recording:.3} s ({:.0}%, {:.1} µs per frame: {:.3} s on the simulation thread, {rerun_threads:.3} s in Rerun's threads)",
            share(physics),
            1e6 * physics / run.steps.max(1) as f64,
            share(recording),
            1e6 * recording / frames,
            recorder,
        );
        let _ = writeln!(
            text,
            "file: {:.2} MB, {:.0} bytes per frame on disk ({:.0} bytes of Arrow data before compression)",
            run.file_bytes as f64 / 1e6,
            run.file_bytes as f64 / frames,
            stats.bytes_per_frame()
        );
        for kind in &stats.kinds {
            let _ = writeln!(
                text,
                "  {:<13} {:>5} entities {:>9} rows {:>8.0} bytes per frame",
                kind.kind,
                kind.entities,
                kind.rows,
                kind.bytes_per_frame(stats.frames)
            );
        }
        text
    }
}
