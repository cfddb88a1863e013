//! The whole window as a user runs it: a virtual X server (Xvfb; the viewer renders with Vulkan
//! on lavapipe), `tether gui` on it, keys and text typed with xdotool, and the recordings it
//! leaves read back.

use std::collections::BTreeMap;
use std::io::{BufRead as _, BufReader};
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Mutex, MutexGuard};
use std::time::{Duration, Instant};

/// Taken by each [`Xvfb`] while it lives: the window tests of one binary run one after another,
/// as three viewers rendering on the CPU at once starve a 2-core machine.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// A virtual X server, stopped when dropped.
pub struct Xvfb {
    process: Child,
    pub display: String,
    _turn: MutexGuard<'static, ()>,
}

impl Xvfb {
    /// Starts Xvfb on a free display it picks itself (`-displayfd`), once the window tests
    /// before it are done.
    pub fn start() -> Self {
        // A test that failed holding it poisoned it; the next one may still go.
        let turn = ONE_AT_A_TIME.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        let mut process = Command::new("Xvfb")
            // -noreset: without it the server resets each time its last client leaves (every
            // xdotool call), and a client connecting during a reset is refused.
            .args(["-displayfd", "1", "-screen", "0", "1600x1000x24", "-nolisten", "tcp", "-noreset"])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("Xvfb must be installed (apt-get install xvfb; .ci/run does it)");
        let mut line = String::new();
        BufReader::new(process.stdout.take().expect("piped")).read_line(&mut line).unwrap();
        let x = Self { process, display: format!(":{}", line.trim()), _turn: turn };
        // A client must be able to connect before the GUI is started on it (once in a full
        // suite run the GUI could not, right after the previous test's server was stopped).
        wait_for("the X server to take clients", Duration::from_secs(20), || {
            x.xdotool(&["getdisplaygeometry"]).status.success()
        });
        x
    }

    /// `xdotool` on this display.
    pub fn xdotool(&self, args: &[&str]) -> std::process::Output {
        Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &self.display)
            .output()
            .expect("xdotool must be installed (apt-get install xdotool)")
    }

    /// Waits (at most `limit`) for a visible window whose title matches the regex `name`, and
    /// gives it the keyboard (there is no window manager to do it).
    pub fn focus_window(&self, name: &str, limit: Duration) -> String {
        let search = || self.xdotool(&["search", "--onlyvisible", "--name", name]);
        wait_for(&format!("a window named {name:?}"), limit, || search().status.success());
        let id = String::from_utf8_lossy(&search().stdout).lines().next().unwrap_or_default().to_string();
        self.give_keyboard(&id);
        id
    }

    /// Gives window `id` the keyboard and waits (at most 10 s) until it has it.
    pub fn give_keyboard(&self, id: &str) {
        self.xdotool(&["windowfocus", "--sync", id]);
        wait_for(&format!("window {id} to have the keyboard"), Duration::from_secs(10), || {
            String::from_utf8_lossy(&self.xdotool(&["getwindowfocus"]).stdout).trim() == id
        });
    }
}

impl Drop for Xvfb {
    /// Stops the server with SIGTERM, so that it removes its lock file and socket before the next
    /// test's server looks for a free display; SIGKILL if that fails.
    fn drop(&mut self) {
        let terminated =
            Command::new("kill").args(["-TERM", &self.process.id().to_string()]).status().is_ok_and(|s| s.success());
        if !terminated {
            self.process.kill().ok();
        }
        self.process.wait().ok();
    }
}

/// `tether ARGS…` running on a virtual display; killed if still running when dropped (a failed
/// test).
pub struct Gui {
    process: Child,
}

impl Gui {
    /// `tether ARGS…` on `x`'s display, run from `folder`, with a fresh home (settings, GTK
    /// state) in `home`; its stderr kept for failure messages.
    pub fn start(x: &Xvfb, folder: &Path, home: &Path, args: &[&str]) -> Self {
        let process = Command::new(env!("CARGO_BIN_EXE_tether"))
            .args(args)
            .current_dir(folder)
            .env("DISPLAY", &x.display)
            .env_remove("WAYLAND_DISPLAY")
            .env_remove("DBUS_SESSION_BUS_ADDRESS")
            .env("HOME", home)
            .env("XDG_DATA_HOME", home)
            .env("XDG_CONFIG_HOME", home)
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        Self { process }
    }

    /// Waits (at most 120 s) for the Tether window to show and for `ready` (the program has
    /// started: its first scene is in the recording — keys sent before the window's event loop
    /// runs its app are dropped), then gives the window the keyboard and waits for it to have
    /// it; fails with the program's stderr if it exits first.
    pub fn focus(&mut self, x: &Xvfb, mut ready: impl FnMut() -> bool) -> String {
        let search = || x.xdotool(&["search", "--onlyvisible", "--name", "^Tether$"]);
        let start = Instant::now();
        while !(search().status.success() && ready()) {
            if let Some(status) = self.process.try_wait().unwrap() {
                panic!("tether exited with {status} before its window showed:\n{}", self.stderr());
            }
            assert!(start.elapsed() < Duration::from_secs(120), "no Tether window running its scene after 120 s");
            std::thread::sleep(Duration::from_millis(100));
        }
        let id = String::from_utf8_lossy(&search().stdout).lines().next().unwrap_or_default().to_string();
        x.give_keyboard(&id);
        id
    }

    /// Presses Ctrl+Q and waits (at most 30 s) for the window to close; fails with its stderr
    /// unless it exited cleanly.
    pub fn quit(mut self, x: &Xvfb) {
        x.xdotool(&["key", "ctrl+q"]);
        let status = wait_exit(&mut self.process, Duration::from_secs(30))
            .unwrap_or_else(|| panic!("the window did not close on Ctrl+Q"));
        assert!(status.success(), "tether gui exited with {status}:\n{}", self.stderr());
    }

    /// What the program wrote to stderr (once it has exited).
    fn stderr(&mut self) -> String {
        let mut stderr = String::new();
        if let Some(mut pipe) = self.process.stderr.take() {
            std::io::Read::read_to_string(&mut pipe, &mut stderr).ok();
        }
        stderr
    }
}

impl Drop for Gui {
    fn drop(&mut self) {
        if self.process.try_wait().ok().flatten().is_none() {
            self.process.kill().ok();
            self.process.wait().ok();
        }
    }
}

/// The child's exit status, waiting at most `limit`.
pub fn wait_exit(child: &mut Child, limit: Duration) -> Option<ExitStatus> {
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return Some(status);
        }
        if start.elapsed() > limit {
            return None;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Waits for `done`, polling every 100 ms, at most `limit`.
pub fn wait_for(what: &str, limit: Duration, mut done: impl FnMut() -> bool) {
    let start = Instant::now();
    while !done() {
        assert!(start.elapsed() < limit, "timed out after {limit:?} waiting for {what}");
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Every store (recording or blueprint) in an `.rrd` file.
pub fn stores(path: &Path) -> BTreeMap<rerun::StoreId, rerun::ChunkStore> {
    try_stores(path).unwrap_or_else(|e| panic!("{}: {e:#}", path.display()))
}

/// The series names the recording `path` gives entity `entity` (its static `SeriesLines`).
pub fn series_names(path: &Path, entity: &str) -> Vec<String> {
    let component = rerun::SeriesLines::descriptor_names().component;
    let mut names = Vec::new();
    for store in stores(path).values() {
        for chunk in store.iter_physical_chunks().filter(|c| c.is_static() && c.entity_path().to_string() == entity) {
            for row in chunk.iter_slices::<String>(component) {
                names = row.into_iter().map(|name| name.to_string()).collect();
            }
        }
    }
    names
}

/// Every store in an `.rrd` file, or why it cannot be read (yet: it may still be written).
fn try_stores(path: &Path) -> anyhow::Result<BTreeMap<rerun::StoreId, rerun::ChunkStore>> {
    let mut file = std::fs::File::open(path)?;
    rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file)
}

/// Largest `sim_time` [s] of the energy plot in a recording file.
pub fn last_sim_time(path: &Path) -> f64 {
    sim_time_in(&stores(path))
}

/// Largest `sim_time` [s] of the energy plot in these stores.
pub fn sim_time_in(stores: &BTreeMap<rerun::StoreId, rerun::ChunkStore>) -> f64 {
    let mut last = 0.0_f64;
    for store in stores.values() {
        for chunk in store.iter_physical_chunks().filter(|c| c.entity_path().to_string() == "/plots/energy/stored") {
            if let Some(column) = chunk.timelines().get(&"sim_time".into()) {
                last = last.max(column.times_raw().iter().copied().max().unwrap_or(0) as f64 * 1e-9);
            }
        }
    }
    last
}

/// Whether a recording in the file logged the entity `path` (e.g. `/world/bodies/mass`).
pub fn has_entity(path: &Path, entity: &str) -> bool {
    logs_entity(&stores(path), entity)
}

/// Whether a recording in these stores logged the entity `entity`.
fn logs_entity(stores: &BTreeMap<rerun::StoreId, rerun::ChunkStore>, entity: &str) -> bool {
    stores.values().any(|store| store.iter_physical_chunks().any(|c| c.entity_path().to_string() == entity))
}

/// Whether the recording at `path`, which may still be being written, has logged `entity` yet.
pub fn recorded(path: &Path, entity: &str) -> bool {
    try_stores(path).is_ok_and(|stores| logs_entity(&stores, entity))
}

/// Largest `sim_time` [s] of the energy plot in the recording at `path` so far (it may still be
/// being written; 0 while it cannot be read).
pub fn sim_time_so_far(path: &Path) -> f64 {
    try_stores(path).map_or(0.0, |stores| sim_time_in(&stores))
}

/// `rerun rrd verify` passes on the file (it is complete, footer included).
pub fn assert_verifies(path: &Path) {
    let verify = Command::new("rerun")
        .args(["rrd", "verify", path.to_str().unwrap()])
        .output()
        .expect("the `rerun` CLI (pip install rerun-sdk==0.36.3)");
    assert!(
        verify.status.success(),
        "rerun rrd verify {}:\n{}",
        path.display(),
        String::from_utf8_lossy(&verify.stderr)
    );
}
