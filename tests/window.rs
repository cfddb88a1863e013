//! The whole window as a user runs it, on a virtual X server (helpers in `common/x11.rs`); each
//! step waits for what it should lead to (a window, a recording growing), with a time limit:
//! - `tether gui SCENE --save OUT.rrd`: Space plays, Ctrl+Q quits; the recording holds the run
//!   and passes `rerun rrd verify` (the window shut the simulation down cleanly);
//! - `--connect URL`: the run streams to a real external receiver (`rerun --serve-grpc`, which
//!   saves what it receives);
//! - "Open scene…": the file dialog (rfd falls back to zenity without a desktop portal) opens in
//!   the scenes folder, a file name typed there is loaded.

mod common;

use common::x11::{self, Gui, Xvfb};
use std::os::unix::process::CommandExt as _;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// Longest wait for a played scene to reach 1 s of simulated time (about 1 s of wall-clock time
/// at real-time speed, on a machine busy rendering the viewer on its CPU).
const PLAYING: Duration = Duration::from_secs(60);

#[test]
fn the_window_plays_a_scene_records_it_and_quits_cleanly() {
    let x = Xvfb::start();
    let home = tempfile::tempdir().unwrap();
    let out = home.path().join("shown.rrd");
    let mut gui = Gui::start(
        &x,
        &common::repo("."),
        home.path(),
        &["gui", "scenes/spring_mass.ron", "--save", out.to_str().unwrap()],
    );
    gui.focus(&x, || x11::recorded(&out, "/world/bodies/mass"));
    x.xdotool(&["key", "space"]);
    x11::wait_for("Space to play 1 s of the scene into the recording", PLAYING, || x11::sim_time_so_far(&out) > 1.0);
    gui.quit(&x);
    x11::assert_verifies(&out);
    let simulated = x11::last_sim_time(&out);
    assert!(simulated > 1.0, "the finished recording holds the 1 s played; it ends at {simulated} s");
}

/// `rerun --serve-grpc --port PORT --save FILE` (the `rerun` CLI of the same version), in a
/// process group of its own so that the CLI's wrapper and the server stop together; killed when
/// dropped.
struct Receiver {
    process: Child,
    url: String,
}

impl Receiver {
    fn start(save: &Path) -> Self {
        let port = std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
        let mut command = Command::new("rerun");
        command.args(["--serve-grpc", "--port", &port.to_string(), "--save", save.to_str().unwrap()]).process_group(0);
        // Ctrl-C reaches it as in a terminal's foreground: a test run started in the background
        // (`cmd &`, nohup) passes SIGINT on ignored, and Python's wrapper then ignores it too.
        // SAFETY: signal(2) is async-signal-safe, as pre_exec requires; it touches no memory of
        // the parent.
        unsafe {
            command.pre_exec(|| {
                libc::signal(libc::SIGINT, libc::SIG_DFL);
                Ok(())
            });
        }
        let process = command
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("the `rerun` CLI (pip install rerun-sdk==0.36.3)");
        x11::wait_for("the receiver to listen", Duration::from_secs(30), || {
            std::net::TcpStream::connect(("127.0.0.1", port)).is_ok()
        });
        Self { process, url: format!("rerun+http://127.0.0.1:{port}/proxy") }
    }

    /// Ctrl-C to the receiver's group, as in a terminal; true if it exited within 30 s.
    fn interrupt(&mut self) -> bool {
        let group = i32::try_from(self.process.id()).unwrap();
        // SAFETY: kill(2) on the process group this test started.
        unsafe { libc::kill(-group, libc::SIGINT) };
        x11::wait_exit(&mut self.process, Duration::from_secs(30)).is_some()
    }
}

impl Drop for Receiver {
    fn drop(&mut self) {
        if self.process.try_wait().ok().flatten().is_none() {
            let group = i32::try_from(self.process.id()).unwrap();
            // SAFETY: as above.
            unsafe { libc::kill(-group, libc::SIGKILL) };
            self.process.wait().ok();
        }
    }
}

#[test]
fn with_connect_the_window_streams_its_runs_to_an_external_viewer() {
    let home = tempfile::tempdir().unwrap();
    let received = home.path().join("received.rrd");
    let x = Xvfb::start();
    let mut receiver = Receiver::start(&received);
    let mut gui =
        Gui::start(&x, &common::repo("."), home.path(), &["gui", "scenes/spring_mass.ron", "--connect", &receiver.url]);
    // The receiver writes what it got as it comes.
    gui.focus(&x, || x11::recorded(&received, "/world/bodies/mass"));
    x.xdotool(&["key", "space"]);
    x11::wait_for("Space to play 1 s of the scene to the receiver", PLAYING, || x11::sim_time_so_far(&received) > 1.0);
    gui.quit(&x);
    assert!(receiver.interrupt(), "the receiver did not stop on Ctrl-C");
    let stores = x11::stores(&received);
    let recordings: Vec<_> = stores.keys().filter(|id| id.is_recording()).collect();
    assert!(
        !recordings.is_empty() && recordings.iter().all(|id| id.application_id().to_string() == "tether"),
        "{recordings:?}"
    );
    assert!(x11::has_entity(&received, "/world/bodies/mass"), "the body's poses reached the receiver");
    assert!(x11::has_entity(&received, "/world/springs"), "the spring's line reached the receiver");
    let simulated = x11::sim_time_in(&stores);
    assert!(simulated > 1.0, "the receiver's file holds the 1 s played; it ends at {simulated} s");
}

#[test]
fn open_scene_shows_a_file_dialog_in_the_scenes_folder_and_loads_the_file_picked() {
    let x = Xvfb::start();
    let zenity = Command::new("zenity").arg("--version").env("DISPLAY", &x.display).output();
    assert!(
        zenity.is_ok_and(|o| o.status.success()),
        "zenity must be installed (apt-get install zenity; .ci/run does it): without a desktop portal, rfd's file dialogs are zenity's"
    );
    let home = tempfile::tempdir().unwrap();
    let folder = tempfile::tempdir().unwrap();
    std::fs::create_dir(folder.path().join("scenes")).unwrap();
    std::fs::write(folder.path().join("scenes/start.ron"), common::spring_scene_text("start_body")).unwrap();
    std::fs::write(folder.path().join("scenes/picked.ron"), common::spring_scene_text("picked_body")).unwrap();
    let out = folder.path().join("shown.rrd");
    // Run from the folder above `scenes/`: a dialog opened in the working folder would not find
    // `picked.ron` by its bare name.
    let mut gui =
        Gui::start(&x, folder.path(), home.path(), &["gui", "scenes/start.ron", "--save", out.to_str().unwrap()]);
    let window = gui.focus(&x, || x11::recorded(&out, "/world/bodies/start_body"));
    // Tab gives the keyboard focus to the panel's first button, "Open scene…"; Enter presses it.
    x.xdotool(&["key", "Tab"]);
    x.xdotool(&["key", "Return"]);
    x.focus_window("^zenity$", Duration::from_secs(30));
    // Ctrl+L opens GTK's location field, where a bare name is looked up in the dialog's folder.
    x.xdotool(&["key", "ctrl+l"]);
    x.xdotool(&["type", "--delay", "20", "picked.ron"]);
    x.xdotool(&["key", "Return"]);
    let dialog_open = || x.xdotool(&["search", "--onlyvisible", "--name", "^zenity$"]).status.success();
    x11::wait_for("the dialog to close on picked.ron (was it opened in scenes/?)", Duration::from_secs(30), || {
        !dialog_open()
    });
    x.give_keyboard(&window);
    x11::wait_for("the scene picked to be loaded and recorded", Duration::from_secs(30), || {
        x11::recorded(&out, "/world/bodies/picked_body")
    });
    gui.quit(&x);
    x11::assert_verifies(&out);
    assert!(x11::has_entity(&out, "/world/bodies/start_body"), "the scene the window started on was recorded");
    assert!(
        x11::has_entity(&out, "/world/bodies/picked_body"),
        "the scene picked in the dialog was loaded and recorded"
    );
}
