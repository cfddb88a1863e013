//! CPU time of the calling thread and of the whole process [s]: unlike wall-clock time it does
//! not count the time other processes take the cores, and the process's counts every thread
//! (Rerun's batcher and file writer among them).

/// CPU time of the calling thread [s] (`CLOCK_THREAD_CPUTIME_ID`).
pub fn thread_seconds() -> f64 {
    clock_seconds(libc::CLOCK_THREAD_CPUTIME_ID)
}

/// CPU time of every thread of the process [s] (`CLOCK_PROCESS_CPUTIME_ID`).
pub fn process_seconds() -> f64 {
    clock_seconds(libc::CLOCK_PROCESS_CPUTIME_ID)
}

fn clock_seconds(clock: libc::clockid_t) -> f64 {
    let mut time = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    // SAFETY: `time` is a valid, writable timespec for the call's duration.
    if unsafe { libc::clock_gettime(clock, &mut time) } == 0 {
        time.tv_sec as f64 + time.tv_nsec as f64 * 1e-9
    } else {
        // The clocks exist on every Linux; elsewhere, fall back to the wall clock.
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0.0, |d| d.as_secs_f64())
    }
}
