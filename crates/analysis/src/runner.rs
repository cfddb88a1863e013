//! The engine of many cases: independent simulations on a pool of threads, each result handed
//! to the calling thread as it finishes. One runner serves `tether sweep` (which writes each
//! result to disk as it comes) and `tether study` (which keeps its runs in memory).
//!
//! Cases share nothing mutable: each builds its own world from the same read-only inputs, so a
//! case's numbers do not depend on the thread that ran it or on what ran beside it — a sweep run
//! on one thread and on all cores gives the same results bit for bit. Results come back in the
//! order the cases finish; callers that need the case order keep the case with its result.
//!
//! A case is [watched](Watch) between steps: it stops at its wall-time limit, and every case
//! stops when the run is cancelled (Ctrl-C) or the caller cannot take a result (a full disk).
//! The channel back to the caller holds at most one result per thread, so a slow caller holds
//! the workers back rather than letting results pile up in memory.

use std::num::NonZeroUsize;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError, mpsc};
use std::time::{Duration, Instant};

/// Why a case stopped before its end.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stop {
    /// It ran past its wall-time limit.
    TimedOut,
    /// The run was cancelled, or the caller stopped taking results.
    Cancelled,
}

/// What a running case checks between steps: its deadline and the run's stop flags.
pub struct Watch<'a> {
    deadline: Option<Instant>,
    flags: [&'a AtomicBool; 2],
}

impl Watch<'_> {
    /// A watch that never stops (a single run outside any runner).
    pub fn unlimited() -> Watch<'static> {
        static NEVER: AtomicBool = AtomicBool::new(false);
        Watch { deadline: None, flags: [&NEVER, &NEVER] }
    }

    /// Whether the case must stop now, and why.
    ///
    /// # Errors
    /// [`Stop::Cancelled`] once the run is cancelled; [`Stop::TimedOut`] past the deadline.
    pub fn check(&self) -> Result<(), Stop> {
        if self.flags.iter().any(|flag| flag.load(Ordering::Relaxed)) {
            return Err(Stop::Cancelled);
        }
        match self.deadline {
            Some(deadline) if Instant::now() >= deadline => Err(Stop::TimedOut),
            _ => Ok(()),
        }
    }
}

/// The threads and limits of a run of cases.
#[derive(Debug, Clone)]
pub struct Runner {
    jobs: NonZeroUsize,
    case_timeout: Option<Duration>,
    cancel: Arc<AtomicBool>,
}

impl Runner {
    /// A runner on `jobs` threads, no time limit, never cancelled.
    pub fn new(jobs: NonZeroUsize) -> Self {
        Self { jobs, case_timeout: None, cancel: Arc::new(AtomicBool::new(false)) }
    }

    /// A runner on every core of this machine.
    pub fn on_all_cores() -> Self {
        Self::new(all_cores())
    }

    /// Each case stops after `limit` of wall time.
    #[must_use]
    pub fn with_case_timeout(self, limit: Duration) -> Self {
        Self { case_timeout: Some(limit), ..self }
    }

    /// Every case stops once `flag` is set (by a Ctrl-C handler).
    #[must_use]
    pub fn with_cancel(self, flag: Arc<AtomicBool>) -> Self {
        Self { cancel: flag, ..self }
    }

    /// Threads the cases run on.
    pub fn jobs(&self) -> NonZeroUsize {
        self.jobs
    }

    /// Whether the run was cancelled.
    pub fn cancelled(&self) -> bool {
        self.cancel.load(Ordering::SeqCst)
    }

    /// Runs `work` on every case of `cases`, on [`Runner::jobs`] threads; `done(case, result)`
    /// is called on this thread as each case finishes. Cases are taken in the iterator's order.
    ///
    /// # Errors
    /// The first error `done` returns: the cases in flight are then stopped (their watch says
    /// [`Stop::Cancelled`]) and their results dropped, and no further case starts.
    pub fn run<C, R, E>(
        &self,
        cases: impl Iterator<Item = C> + Send,
        work: impl Fn(&C, &Watch<'_>) -> R + Sync,
        mut done: impl FnMut(C, R) -> Result<(), E>,
    ) -> Result<(), E>
    where
        C: Send,
        R: Send,
    {
        let cases = Mutex::new(cases);
        let failed = AtomicBool::new(false);
        let (sender, results) = mpsc::sync_channel::<(C, R)>(self.jobs.get());
        std::thread::scope(|scope| {
            for _ in 0..self.jobs.get() {
                let sender = sender.clone();
                let (cases, failed, work) = (&cases, &failed, &work);
                scope.spawn(move || {
                    let flags = [self.cancel.as_ref(), failed];
                    // Ends: when the cases run out, a flag is set, or the results' receiver is gone.
                    loop {
                        if flags.iter().any(|flag| flag.load(Ordering::Relaxed)) {
                            return;
                        }
                        // A panic elsewhere cannot leave the iterator half-advanced: `next` is
                        // the only thing done under the lock.
                        let Some(case) = cases.lock().unwrap_or_else(PoisonError::into_inner).next() else { return };
                        let watch = Watch { deadline: self.case_timeout.map(|limit| Instant::now() + limit), flags };
                        let result = work(&case, &watch);
                        if sender.send((case, result)).is_err() {
                            return;
                        }
                    }
                });
            }
            drop(sender);
            let mut outcome = Ok(());
            // Ends when every worker has returned and dropped its sender.
            for (case, result) in results {
                if outcome.is_ok()
                    && let Err(error) = done(case, result)
                {
                    failed.store(true, Ordering::SeqCst);
                    outcome = Err(error);
                }
            }
            outcome
        })
    }
}

/// The cores this process may run on (1 if the system cannot tell).
pub fn all_cores() -> NonZeroUsize {
    std::thread::available_parallelism().unwrap_or(NonZeroUsize::MIN)
}

/// CPU time of the calling thread \[s] (`CLOCK_THREAD_CPUTIME_ID`): unlike wall-clock time it
/// does not count the time other processes take the core.
pub fn thread_cpu_seconds() -> f64 {
    let mut time = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `time` is a valid, writable timespec for the call's duration.
    if unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut time) } == 0 {
        time.tv_sec as f64 + time.tv_nsec as f64 * 1e-9
    } else {
        // The clock exists on every Linux; elsewhere, fall back to the process's wall clock.
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0.0, |d| d.as_secs_f64())
    }
}

/// CPU time of the whole process so far, user and system, every thread \[s] (`getrusage`).
pub fn process_cpu_seconds() -> f64 {
    // SAFETY: an all-zero rusage is a valid value of the plain C struct, which the call fills.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: `usage` is a valid, writable rusage for the call's duration.
    if unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut usage) } != 0 {
        return 0.0;
    }
    let seconds = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    seconds(usage.ru_utime) + seconds(usage.ru_stime)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every case runs exactly once whatever the threads, and a failing caller stops the run.
    #[test]
    fn runs_each_case_once_and_stops_on_the_first_error() {
        for jobs in [1, 2, 5] {
            let runner = Runner::new(NonZeroUsize::new(jobs).unwrap());
            let mut seen = vec![0; 100];
            runner
                .run(
                    0..100usize,
                    |&case, _| case * case,
                    |case, square| {
                        assert_eq!(square, case * case);
                        seen[case] += 1;
                        Ok::<(), ()>(())
                    },
                )
                .unwrap();
            assert!(seen.iter().all(|&n| n == 1), "{jobs} jobs: {seen:?}");
            let mut taken = 0;
            let error = runner.run(
                0..100usize,
                |&case, _| case,
                |_, _| {
                    taken += 1;
                    if taken == 3 { Err("disk full") } else { Ok(()) }
                },
            );
            assert_eq!(error, Err("disk full"));
            // At most the cases already in flight or queued finish after the failure.
            assert!(taken <= 3 + 2 * jobs, "{taken} results taken with {jobs} jobs");
        }
    }

    /// A case past its limit is told so; a cancelled run tells every case.
    #[test]
    fn watch_reports_timeouts_and_cancellation() {
        let runner = Runner::new(NonZeroUsize::MIN).with_case_timeout(Duration::from_millis(20));
        runner
            .run(
                0..1,
                |_, watch| {
                    assert_eq!(watch.check(), Ok(()));
                    std::thread::sleep(Duration::from_millis(30));
                    assert_eq!(watch.check(), Err(Stop::TimedOut));
                },
                |_, ()| Ok::<(), ()>(()),
            )
            .unwrap();
        let cancel = Arc::new(AtomicBool::new(true));
        let runner = Runner::new(NonZeroUsize::MIN).with_cancel(cancel);
        let mut ran = 0;
        runner
            .run(
                0..10,
                |_, _| (),
                |_, ()| {
                    ran += 1;
                    Ok::<(), ()>(())
                },
            )
            .unwrap();
        assert_eq!(ran, 0, "a cancelled run starts no case");
        assert_eq!(Watch::unlimited().check(), Ok(()));
    }
}
