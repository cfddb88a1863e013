//! The whole window as a user runs it: `tether gui SCENE --save OUT.rrd` on a virtual X server
//! (Xvfb; the viewer renders with Vulkan on lavapipe), Space pressed to play, Ctrl+Q to quit.
//! The recording then holds the run and passes `rerun rrd verify`: the window shut the
//! simulation down cleanly and the file got its footer.

mod common;

use std::io::{BufRead as _, BufReader};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A virtual X server, stopped when dropped.
struct Xvfb {
    process: Child,
    display: String,
}

impl Xvfb {
    /// Starts Xvfb on a free display it picks itself (`-displayfd`).
    fn start() -> Self {
        let mut process = Command::new("Xvfb")
            .args(["-displayfd", "1", "-screen", "0", "1600x1000x24", "-nolisten", "tcp"])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("Xvfb must be installed (apt-get install xvfb; .ci/run does it)");
        let mut line = String::new();
        BufReader::new(process.stdout.take().expect("piped")).read_line(&mut line).unwrap();
        Self { process, display: format!(":{}", line.trim()) }
    }

    /// `xdotool` on this display.
    fn xdotool(&self, args: &[&str]) -> std::process::Output {
        Command::new("xdotool").args(args).env("DISPLAY", &self.display).output().expect("xdotool must be installed (apt-get install xdotool)")
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        self.process.kill().ok();
        self.process.wait().ok();
    }
}

/// Waits for `done`, polling every 100 ms, at most `limit`.
fn wait_for(what: &str, limit: Duration, mut done: impl FnMut() -> bool) {
    let start = Instant::now();
    while !done() {
        assert!(start.elapsed() < limit, "timed out after {limit:?} waiting for {what}");
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Largest `sim_time` [s] of the energy plot in a recording.
fn last_sim_time(path: &Path) -> f64 {
    let mut file = std::fs::File::open(path).unwrap();
    let stores = rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
    let mut last = 0.0_f64;
    for store in stores.values() {
        for chunk in store.iter_physical_chunks().filter(|c| c.entity_path().to_string() == "/plots/energy") {
            if let Some(column) = chunk.timelines().get(&"sim_time".into()) {
                last = last.max(column.times_raw().iter().copied().max().unwrap_or(0) as f64 * 1e-9);
            }
        }
    }
    last
}

#[test]
fn the_window_plays_a_scene_records_it_and_quits_cleanly() {
    let x = Xvfb::start();
    let home = tempfile::tempdir().unwrap();
    let out = home.path().join("shown.rrd");
    let mut gui = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["gui", "scenes/spring_mass.ron", "--save", out.to_str().unwrap()])
        .current_dir(common::repo("."))
        .env("DISPLAY", &x.display)
        .env_remove("WAYLAND_DISPLAY")
        .env("HOME", home.path())
        .env("XDG_DATA_HOME", home.path())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let window = || x.xdotool(&["search", "--name", "^Tether$"]);
    wait_for("the window", Duration::from_secs(60), || window().status.success());
    let id = String::from_utf8_lossy(&window().stdout).lines().next().unwrap_or_default().to_string();
    // No window manager gives the window the keyboard: give it, let the first frames draw, play.
    std::thread::sleep(Duration::from_secs(2));
    x.xdotool(&["windowfocus", "--sync", &id]);
    std::thread::sleep(Duration::from_millis(500));
    x.xdotool(&["key", "space"]);
    std::thread::sleep(Duration::from_secs(3));
    x.xdotool(&["key", "ctrl+q"]);
    let start = Instant::now();
    let status = loop {
        if let Some(status) = gui.try_wait().unwrap() {
            break status;
        }
        if start.elapsed() > Duration::from_secs(30) {
            gui.kill().ok();
            panic!("the window did not close on Ctrl+Q");
        }
        std::thread::sleep(Duration::from_millis(100));
    };
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut gui.stderr.take().unwrap(), &mut stderr).unwrap();
    assert!(status.success(), "tether gui exited with {status}:\n{stderr}");
    let verify = Command::new("rerun").args(["rrd", "verify", out.to_str().unwrap()]).output().expect("the `rerun` CLI (pip install rerun-sdk==0.36.3)");
    assert!(verify.status.success(), "rerun rrd verify:\n{}", String::from_utf8_lossy(&verify.stderr));
    let simulated = last_sim_time(&out);
    assert!(simulated > 1.0, "Space should have played the scene for about 3 s; the recording ends at {simulated} s");
}
