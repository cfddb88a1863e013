//! Ctrl-C and SIGTERM for the headless commands: a stop requested is a stop within a second.
//!
//! One handler per process ([`install`], idempotent): the first signal sets the flag the long
//! commands watch (`record` between steps, the runner's cases between steps, a sweep's planning
//! and writing between cases and files, a fit between runs); they stop there and write what they
//! finished. A stage that cannot see the flag in time — a single step, an equilibrium's Newton
//! iterations, a frequency-domain solve — is not made to: [`GRACE`] after the signal, unless the
//! command said it is [`finishing`] (closing the file it was writing, which must not be cut), the
//! process exits with [`EXIT_CODE`], keeping every file it had closed. A second signal exits at
//! once. The window installs its own handler (it closes the window as its close button does).
//!
//! (`signal-hook` was considered; `ctrlc` with its `termination` feature, already the window's,
//! covers SIGINT and SIGTERM on one thread of its own, all a watchdog needs.)

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock};
use std::time::Duration;

/// Exit code of a run stopped by Ctrl-C or SIGTERM (128 + SIGINT, the shell's convention).
pub const EXIT_CODE: u8 = 130;

/// How long after the signal a command that is not [`finishing`] has to stop by itself before
/// the process exits: half of the second a stop may take, the rest for the exit.
pub const GRACE: Duration = Duration::from_millis(500);

struct State {
    requested: Arc<AtomicBool>,
    finishing: AtomicBool,
}

static STATE: OnceLock<State> = OnceLock::new();

/// Installs the process's Ctrl-C / SIGTERM handler (once: later calls give the same flag) and
/// returns the flag it sets, for the commands' loops and [`crate::runner::Runner::with_cancel`].
///
/// # Errors
/// The handler could not be installed (another one was, by other code).
pub fn install() -> Result<Arc<AtomicBool>, ctrlc::Error> {
    if let Some(state) = STATE.get() {
        return Ok(Arc::clone(&state.requested));
    }
    let state =
        STATE.get_or_init(|| State { requested: Arc::new(AtomicBool::new(false)), finishing: AtomicBool::new(false) });
    ctrlc::set_handler(on_signal)?;
    Ok(Arc::clone(&state.requested))
}

/// Whether a stop was requested.
pub fn requested() -> bool {
    STATE.get().is_some_and(|state| state.requested.load(Ordering::SeqCst))
}

/// The command has seen the stop and is closing what it wrote (a recording's last frames and
/// footer): the watchdog lets it end by itself.
pub fn finishing() {
    if let Some(state) = STATE.get() {
        state.finishing.store(true, Ordering::SeqCst);
    }
}

/// The handler (on `ctrlc`'s own thread): the first signal requests the stop and starts the
/// watchdog; a second one exits at once.
fn on_signal() {
    let Some(state) = STATE.get() else { return };
    if state.requested.swap(true, Ordering::SeqCst) {
        exit("a second signal");
    }
    std::thread::spawn(|| {
        std::thread::sleep(GRACE);
        if STATE.get().is_some_and(|state| !state.finishing.load(Ordering::SeqCst)) {
            exit(&format!("the running stage did not reach a stopping point within {} s", GRACE.as_secs_f64()));
        }
    });
}

fn exit(why: &str) -> ! {
    eprintln!("interrupted ({why}): stopped; the files already written are kept");
    std::process::exit(i32::from(EXIT_CODE))
}
