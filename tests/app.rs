//! The whole app — control panel and embedded Rerun viewer — driven headlessly with egui_kittest
//! (wgpu on lavapipe): files dropped on the window as the windowing layer hands them over
//! (`RawInput::dropped_files`), and a body selected in the real viewer shown with its state in
//! the panel.

mod common;

use common::repo;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use rerun::external::re_viewer::external::re_viewer_context::Item;
use rerun::external::re_viewer::{self, SystemCommand, SystemCommandSender as _};
use rerun::external::{egui, tokio};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Arc, LazyLock};
use std::time::{Duration, Instant};
use tether::gui::GuiOptions;
use tether::gui::app::TetherApp;
use tether_physics::world::World;

/// Longest wait for the simulation thread or the viewer's loader.
const PATIENCE: Duration = Duration::from_secs(30);

/// The GUI tests' oscillator, body "bob".
static SPRING: LazyLock<String> = LazyLock::new(|| common::spring_scene_text("bob"));

/// A file as the windowing layer (egui-winit) hands a dropped file to egui: its path.
#[derive(Debug)]
struct DroppedPath(PathBuf);

impl egui::DroppedFile for DroppedPath {
    fn path(&self) -> &Path {
        &self.0
    }

    fn bytes(&self) -> Result<Vec<u8>, String> {
        std::fs::read(&self.0).map_err(|e| e.to_string())
    }
}

/// The app as `tether gui` builds it, with the embedded viewer, in a headless harness.
fn app(runtime: &tokio::runtime::Runtime, options: GuiOptions) -> Harness<'static, TetherApp> {
    let handle = runtime.handle().clone();
    Harness::builder().with_size([1400.0, 900.0]).wgpu().build_eframe(move |cc| {
        re_viewer::customize_eframe_and_setup_renderer(cc).expect("the viewer's renderer on wgpu");
        TetherApp::new(
            cc,
            re_viewer::MainThreadToken::i_promise_i_am_only_using_this_for_a_test(),
            handle,
            Vec::new(),
            options,
        )
        .expect("the app")
    })
}

fn runtime() -> tokio::runtime::Runtime {
    tokio::runtime::Builder::new_multi_thread().worker_threads(1).enable_all().build().unwrap()
}

/// Runs frames until `done` holds for the app, or fails after [`PATIENCE`].
fn until(harness: &mut Harness<'_, TetherApp>, what: &str, mut done: impl FnMut(&TetherApp) -> bool) {
    let start = Instant::now();
    loop {
        harness.step();
        if done(harness.state()) {
            return;
        }
        let log: Vec<_> = harness.state().panel().log().map(|l| l.text.clone()).collect();
        assert!(start.elapsed() < PATIENCE, "timed out waiting for {what}; log: {log:?}");
        std::thread::sleep(Duration::from_millis(10));
    }
}

fn drop_file(harness: &mut Harness<'_, TetherApp>, path: &Path) {
    harness.input_mut().dropped_files.push(Arc::new(DroppedPath(path.to_path_buf())));
    harness.step();
}

fn world(harness: &Harness<'_, TetherApp>) -> World {
    harness.state().panel().simulation().snapshot(PATIENCE).expect("a scene is running")
}

/// The `sim_time` range [ns] of a recording file, and its recording id.
fn recording_in_file(path: &Path) -> (String, i64) {
    let mut file = std::fs::File::open(path).unwrap();
    let stores = rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
    let (id, store) = stores.iter().find(|(id, _)| id.is_recording()).expect("a recording in the file");
    let last = store
        .iter_physical_chunks()
        .filter_map(|c| c.timelines().get(&"sim_time".into()).and_then(|t| t.times_raw().iter().copied().max()))
        .max()
        .unwrap();
    (id.recording_id().to_string(), last)
}

#[test]
fn dropped_scenes_open_dropped_recordings_play_back_and_other_files_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("dropped.ron");
    std::fs::write(&scene, SPRING.as_str()).unwrap();
    let recording = dir.path().join("spring_mass.rrd");
    let record = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args([
            "record",
            repo("scenes/spring_mass.ron").to_str().unwrap(),
            "-o",
            recording.to_str().unwrap(),
            "--duration",
            "0.5",
        ])
        .output()
        .unwrap();
    assert!(record.status.success(), "{}", String::from_utf8_lossy(&record.stderr));
    let (file_recording, file_last) = recording_in_file(&recording);
    assert!(
        (450_000_000..=500_000_000).contains(&file_last),
        "tether record ran 0.5 s, its last frame at {file_last} ns"
    );

    let runtime = runtime();
    let mut harness = app(&runtime, GuiOptions { scenes_dir: dir.path().to_path_buf(), ..Default::default() });
    harness.run_steps(3);
    assert!(harness.state().panel().scene().is_none());

    drop_file(&mut harness, &scene);
    until(&mut harness, "the dropped scene to run", |app| app.panel().status().is_some_and(|s| s.label == "dropped"));
    assert_eq!(harness.state().panel().scene().map(|s| s.path.clone()), Some(scene.clone()));
    let running = world(&harness);
    assert_eq!((running.bodies()[0].name.as_str(), running.state(0).position.x), ("bob", 1.1));

    drop_file(&mut harness, &recording);
    let viewer_has_it = |app: &TetherApp| {
        let Some(db) = app.viewer().and_then(|v| v.recording_db()) else { return false };
        db.recording_id().to_string() == file_recording
            && db.time_range_for(&"sim_time".into()).is_some_and(|r| r.max().as_i64() == file_last)
    };
    until(&mut harness, "the viewer to show the dropped recording to its last frame (0.5 s)", viewer_has_it);
    assert!(harness.state().panel().log().any(|l| l.text == format!("playing back {}", recording.display())));
    let db = harness.state().viewer().and_then(|v| v.recording_db()).unwrap();
    assert!(db.is_logged_entity(&"world/bodies/mass".into()), "the recording's body is in the viewer");
    // The live run is closed, not left running unseen behind the recording: no scene, no
    // status, Play greyed, the panel saying what plays and offering the scene back.
    let panel = harness.state().panel();
    assert!(panel.scene().is_none() && panel.status().is_none(), "the scene is closed for the playback");
    assert_eq!(
        panel.playback().map(|p| (p.recording.clone(), p.closed.clone())),
        Some((recording.clone(), Some(scene.clone())))
    );
    harness.run_steps(2);
    assert!(harness.get_by_label("▶ Play").accesskit_node().is_disabled(), "nothing to play");
    harness.get_by_label("Playing back spring_mass.rrd");
    let closed = harness.state().panel().simulation().snapshot(PATIENCE);
    assert!(closed.is_none(), "the simulation thread has no run");

    harness.get_by_label("Back to dropped.ron").click();
    until(&mut harness, "the scene again", |app| app.panel().status().is_some_and(|s| s.label == "dropped"));
    let live_in_viewer = |app: &TetherApp| {
        app.viewer().and_then(|v| v.recording_db()).is_some_and(|db| {
            db.recording_id().to_string() != file_recording && db.is_logged_entity(&"world/bodies/bob".into())
        })
    };
    until(&mut harness, "the viewer to show the live run again", live_in_viewer);
    assert!(harness.state().panel().playback().is_none());
    drop_file(&mut harness, &recording);
    until(&mut harness, "the recording again", viewer_has_it);

    let notes = dir.path().join("notes.txt");
    std::fs::write(&notes, "Scene(").unwrap();
    drop_file(&mut harness, &notes);
    harness.run_steps(2);
    let refusal =
        format!("{}: not a scene (.ron), a recording (.rrd) or a sweep directory; nothing opened", notes.display());
    assert!(
        harness.state().panel().log().any(|l| l.error && l.text == refusal),
        "log: {:?}",
        harness.state().panel().log().collect::<Vec<_>>()
    );
    harness.get_by_label(&refusal);
    assert_eq!(harness.state().panel().load_error(), None, "not read as a scene");
    let db = harness.state().viewer().and_then(|v| v.recording_db()).unwrap();
    assert_eq!(db.recording_id().to_string(), file_recording, "the viewer still shows the recording");
}

/// Selecting an entity in the real viewer (its selection command, as a click sends) reaches the
/// panel through the viewer's selection event: a body's own entity or any entity below it shows
/// that body's state, synchronised with the running world; another entity shows none.
#[test]
fn the_body_selected_in_the_viewer_is_shown_with_its_state() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("spring.ron");
    std::fs::write(&scene, SPRING.as_str()).unwrap();
    let runtime = runtime();
    let mut harness =
        app(&runtime, GuiOptions { scene: Some(scene), scenes_dir: dir.path().to_path_buf(), ..Default::default() });
    until(&mut harness, "the scene", |app| app.panel().status().is_some_and(|s| s.label == "spring"));
    // Ten steps, paused: the body has moved and stays put. (The keyboard shortcuts are taken
    // in the window's raw-input hook, which the harness does not call: the button then.)
    for _ in 0..10 {
        harness.get_by_label("⏭ Step").click();
        harness.step();
    }
    until(&mut harness, "ten steps", |app| app.panel().status().is_some_and(|s| s.steps == 10));
    let now = world(&harness);
    let state = now.state(0);
    assert!(state.position.x < 1.1 && state.velocity.x < 0.0, "the spring pulls the body in: {state:?}");
    let number = |x: f64| tether::figures::number(x, 4);
    let shown = |v: &tether_physics::math::Vec3| format!("({}, {}, {})", number(v.x), number(v.y), number(v.z));
    let position = format!("{} m", shown(&state.position));
    let velocity = format!("{} m/s", shown(&state.velocity));
    until(&mut harness, "the viewer to hold the body's entity", |app| {
        app.viewer().and_then(|v| v.recording_db()).is_some_and(|db| db.is_logged_entity(&"world/bodies/bob".into()))
    });

    let select = |harness: &mut Harness<'_, TetherApp>, path: &str| {
        let viewer = harness.state().viewer().expect("the embedded viewer");
        viewer.command_sender.send_system(SystemCommand::set_selection(Item::from(rerun::EntityPath::from(path))));
    };
    select(&mut harness, "world/bodies/bob/shape");
    let start = Instant::now();
    while harness.query_by_label("Selected body: bob").is_none() {
        assert!(start.elapsed() < PATIENCE, "the panel never showed the selected body");
        harness.step();
    }
    harness.get_by_label(&position);
    harness.get_by_label(&velocity);
    harness.get_by_label("(0, 0, 0) rad/s");

    select(&mut harness, "world/springs");
    let start = Instant::now();
    while harness.query_by_label("Selected body: bob").is_some() {
        assert!(start.elapsed() < PATIENCE, "a coupling selected still shows the body");
        harness.step();
    }
    assert!(harness.query_by_label(&position).is_none());
}
