//! The control panel driven headlessly with egui_kittest, on the real simulation thread: load a
//! scene from the list, tune a stiffness and find it in the running world, refuse a bad value,
//! pause/step/reset by keyboard, keep running through a bad scene, pause on divergence, save the
//! tuned scene; and a render of the panel on the CPU (wgpu on lavapipe) checked against its
//! snapshot.

mod common;

use common::{here, repo};
use egui_kittest::kittest::{NodeT as _, Queryable as _};
use egui_kittest::{Harness, SnapshotOptions};
use rerun::external::egui::{self, accesskit};
use std::path::{Path, PathBuf};
use std::sync::{Arc, LazyLock};
use std::time::{Duration, Instant};
use tether::figures::quantity;
use tether::gui::panel::ControlPanel;
use tether::gui::stream::{Sinks, ViewerBacklog};
use tether_physics::coupling::{CouplingKind, ElasticLaw, LineModel};
use tether_physics::statics::{Settings, equilibrium};
use tether_physics::world::World;

/// Longest wait for the simulation thread.
const PATIENCE: Duration = Duration::from_secs(20);

/// The GUI tests' oscillator, body "m".
static SPRING: LazyLock<String> = LazyLock::new(|| common::spring_scene_text("m"));

/// The floating cylinder of `tests/fixtures/rao/cylinder.ron`, its potential-flow files named
/// by their path in the repository (the scene is written into a folder of its own).
fn cylinder_text() -> String {
    let file = repo("validation/potential-flow/cylinder/cylinder");
    let fixture = std::fs::read_to_string(repo("tests/fixtures/rao/cylinder.ron")).unwrap();
    let text = fixture.replace("\"../../../validation/potential-flow/cylinder/cylinder\"", &format!("{file:?}"));
    assert_ne!(text, fixture, "the fixture's file, found from the folder of scenes");
    text
}

/// The cylinder's `text` with `sections` (an `air: Air(…)`, and more) before its bodies and a
/// windage on the cylinder.
fn with_wind(text: &str, sections: &str) -> String {
    text.replace("bodies: [", &format!("{sections}\n    bodies: [")).replace(
        "center: (0.0, 0.0, 2.0)),",
        "center: (0.0, 0.0, 2.0)),\n windage: Windage(coefficients: (1.0, 1.0, 0.0)),",
    )
}

/// A folder of scenes for the panel's list.
fn scenes_folder(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    dir
}

fn panel(scenes: &Path) -> ControlPanel {
    ControlPanel::new(Sinks::none(), Arc::new(|| {}), scenes.to_path_buf()).unwrap()
}

fn harness(panel: ControlPanel) -> Harness<'static, ControlPanel> {
    Harness::builder()
        .with_size([440.0, 1100.0])
        .build_ui_state(|ui, panel: &mut ControlPanel| panel.ui(ui, None), panel)
}

/// A harness tall enough for every row of the shipped scenes' list above the panels below it
/// (a button scrolled out of view takes no click).
fn tall_harness(panel: ControlPanel) -> Harness<'static, ControlPanel> {
    Harness::builder()
        .with_size([440.0, 1600.0])
        .build_ui_state(|ui, panel: &mut ControlPanel| panel.ui(ui, None), panel)
}

/// A window 1200 points wide and `height` tall holding the panel as its side panel, the panel's
/// width kept for [`side_width`] each frame.
fn side_panel_harness(panel: ControlPanel, height: f32) -> Harness<'static, ControlPanel> {
    Harness::builder().with_size([1200.0, height]).build_ui_state(
        |ui, panel: &mut ControlPanel| {
            let width = panel.side_panel(ui, None);
            ui.data_mut(|d| d.insert_temp(egui::Id::new("side width"), width));
        },
        panel,
    )
}

/// The side panel's width at the last frame of a [`side_panel_harness`] [points].
fn side_width(harness: &Harness<'_, ControlPanel>) -> f32 {
    harness.ctx.data(|d| d.get_temp::<f32>(egui::Id::new("side width"))).expect("the panel's width")
}

/// Runs frames until `done` holds for the panel, or fails after [`PATIENCE`].
fn until(harness: &mut Harness<'_, ControlPanel>, what: &str, done: impl Fn(&ControlPanel) -> bool) {
    let start = Instant::now();
    loop {
        harness.step();
        if done(harness.state()) {
            return;
        }
        assert!(
            start.elapsed() < PATIENCE,
            "timed out waiting for {what}; log: {:?}",
            harness.state().log().collect::<Vec<_>>()
        );
        std::thread::yield_now();
    }
}

/// The running world, from the simulation thread.
fn world(harness: &Harness<'_, ControlPanel>) -> World {
    harness.state().simulation().snapshot(PATIENCE).expect("a scene is running")
}

fn spring_damping(world: &World) -> f64 {
    match &world.couplings()[0].kind {
        CouplingKind::SpringDamper(spring) => spring.damping(),
        kind => panic!("not a spring: {kind:?}"),
    }
}

fn spring_stiffness(world: &World) -> f64 {
    match &world.couplings()[0].kind {
        CouplingKind::SpringDamper(spring) => match spring.law() {
            ElasticLaw::Linear { stiffness, .. } => *stiffness,
            law => panic!("not linear: {law:?}"),
        },
        kind => panic!("not a spring: {kind:?}"),
    }
}

/// Types `value` into the knob labelled `label`, as a screen reader (AccessKit `SetValue`) would.
fn set_knob(harness: &mut Harness<'_, ControlPanel>, label: &str, value: f64) {
    let knob = harness.get_by_label(label).accesskit_node().locate();
    set_value(harness, knob, value);
}

/// Types `value` into the knob `knob` (its AccessKit node and tree).
fn set_value(
    harness: &mut Harness<'_, ControlPanel>,
    (target_node, target_tree): (accesskit::NodeId, accesskit::TreeId),
    value: f64,
) {
    let request = accesskit::ActionRequest {
        action: accesskit::Action::SetValue,
        target_tree,
        target_node,
        data: Some(accesskit::ActionData::NumericValue(value)),
    };
    harness.event(egui::Event::AccessKitActionRequest(request));
    // One frame takes the edit, the next shows what became of it.
    harness.run_steps(2);
}

/// Clicks the scene `name` in the list and waits for it to run.
fn open_from_list(harness: &mut Harness<'_, ControlPanel>, name: &str) {
    harness.get_by_label(name).click();
    until(harness, "the scene to load", |p| p.status().is_some_and(|s| s.label == name.trim_end_matches(".ron")));
}

#[test]
fn a_tuned_stiffness_reaches_the_running_simulation_and_a_bad_one_is_refused() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    assert_eq!(spring_stiffness(&world(&harness)), 100.0);

    set_knob(&mut harness, "stiffness k", 2500.0);
    until(&mut harness, "the applied message", |p| p.log().any(|l| l.text.starts_with("coupling \"spring\" applied")));
    assert_eq!(spring_stiffness(&world(&harness)), 2500.0, "the thread runs the tuned stiffness");
    for line in harness.state().log().filter(|l| l.text.contains("applied")) {
        println!("{}", line.text);
    }
    assert!(harness.query_by_label_contains("spring •").is_some(), "the coupling is marked as tuned");

    set_knob(&mut harness, "stiffness k", -5.0);
    harness.get_by_label(
        "Refused: law.stiffness = -5 not applied (the run keeps 2500): coupling \"spring\": stiffness must be ≥ 0 N/m, got -5",
    );
    assert_eq!(spring_stiffness(&world(&harness)), 2500.0, "a refused value leaves the simulation alone");

    // Another field of the same coupling, fixed, applies; the refused one keeps its message.
    set_knob(&mut harness, "damping k_d", 0.75);
    until(&mut harness, "the damping in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| spring_damping(&w) == 0.75)
    });
    assert_eq!(spring_stiffness(&world(&harness)), 2500.0);
    harness.get_by_label_contains("Refused: law.stiffness = -5 not applied (the run keeps 2500)");

    harness.get_by_label("Revert to file").click();
    until(&mut harness, "the revert", |p| p.scene().is_some_and(|s| s.tuned == s.file));
    harness.step();
    assert_eq!(spring_stiffness(&world(&harness)), 100.0);
    assert!(harness.query_by_label_contains("Refused").is_none());
}

#[test]
fn space_arrow_and_backspace_play_step_and_reset() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");

    harness.key_press(egui::Key::ArrowRight);
    until(&mut harness, "one step", |p| p.status().is_some_and(|s| s.steps == 1));
    assert!((world(&harness).time() - 0.001).abs() < 1e-15);

    harness.key_press(egui::Key::Space);
    until(&mut harness, "0.05 s of simulated time", |p| p.status().is_some_and(|s| s.running && s.time > 0.05));
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the pause", |p| p.status().is_some_and(|s| !s.running));
    let paused = world(&harness).time();
    assert_eq!(world(&harness).time(), paused, "paused time must not advance");
    assert!(paused > 0.05);

    harness.key_press(egui::Key::Backspace);
    until(&mut harness, "the reset", |p| p.status().is_some_and(|s| s.steps == 0));
    let reset = world(&harness);
    assert_eq!((reset.time(), reset.state(0).position.x), (0.0, 1.1));
}

#[test]
fn a_bad_scene_shows_its_place_and_the_previous_one_keeps_running() {
    let bad = SPRING.replace("mass: 1.0,", "mass: -1.0,");
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str()), ("bad.ron", &bad)]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    harness.key_press(egui::Key::Space);

    harness.get_by_label("bad.ron").click();
    harness.run_steps(2);
    let error = harness.state().load_error().expect("the bad scene is refused").to_string();
    assert!(error.contains("bad.ron:4:"), "{error}");
    assert!(error.contains("body \"m\""), "{error}");
    harness.get_by_label(&error);

    let before = world(&harness).time();
    until(&mut harness, "the previous scene to go on", |p| {
        p.status().is_some_and(|s| s.label == "spring" && s.running && s.time > before + 0.02)
    });
}

#[test]
fn a_diverging_run_pauses_and_says_why() {
    let stiff = SPRING.replace("stiffness: 100.0", "stiffness: 1e7");
    let dir = scenes_folder(&[("stiff.ron", &stiff)]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "stiff.ron");
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the divergence", |p| p.status().is_some_and(|s| !s.running && s.failure.is_some()));
    let failure = harness.state().status().and_then(|s| s.failure.clone()).unwrap();
    assert!(failure.contains("the simulation diverged") && failure.contains("stable time step"), "{failure}");
    harness.get_by_label(&format!("Paused: {failure}"));
    // Play is refused until a reset.
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the refusal", |p| p.log().any(|l| l.error && l.text.contains("reset it first")));
}

#[test]
fn the_tuned_scene_is_saved_as_ron_that_loads_back() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    set_knob(&mut harness, "damping k_d", 0.75);
    let saved: PathBuf = dir.path().join("tuned.ron");
    harness.state_mut().save_as(&saved);
    let loaded = tether_scene::load(&saved).unwrap();
    assert_eq!(Some(&loaded.file), harness.state().scene().map(|s| &s.tuned));
    assert!(matches!(&loaded.world.couplings()[0].kind, CouplingKind::SpringDamper(s) if s.damping() == 0.75));
}

/// The open file is watched. An editor's save (a new file renamed over the old one) with another
/// stiffness reloads the scene into the running simulation; a broken save shows its
/// `path:line:col` and the running scene goes on; undoing that save clears the error without a
/// restart; a fixed save written in place reloads again.
#[test]
fn the_open_scene_reloads_when_its_file_changes_on_disk() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let path = dir.path().join("spring.ron");
    let save_by_rename = |text: &str| {
        let swap = dir.path().join(".spring.ron.new");
        std::fs::write(&swap, text).unwrap();
        std::fs::rename(&swap, &path).unwrap();
    };
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    assert_eq!(spring_stiffness(&world(&harness)), 100.0);

    let stiffer = SPRING.replace("stiffness: 100.0", "stiffness: 2500.0");
    save_by_rename(&stiffer);
    until(&mut harness, "the reload", |p| p.log().any(|l| l.text.ends_with("spring.ron changed on disk: reloading")));
    until(&mut harness, "k = 2500 N/m in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| spring_stiffness(&w) == 2500.0)
    });
    assert_eq!(
        harness.state().scene().map(|s| s.file.clone()),
        Some(tether_scene::parse(&stiffer, &path).unwrap().file)
    );

    harness.key_press(egui::Key::Space);
    until(&mut harness, "the run", |p| p.status().is_some_and(|s| s.running && s.time > 0.02));
    save_by_rename(&stiffer.replace("rest_length: 1.0)", "rest_length: 1.0"));
    until(&mut harness, "the load error", |p| p.load_error().is_some());
    let error = harness.state().load_error().unwrap().to_string();
    assert!(error.starts_with(&format!("{}:7:", path.display())), "{error}");
    harness.get_by_label(&error);
    let broken_at = world(&harness).time();
    until(&mut harness, "the previous scene to go on", |p| {
        p.status().is_some_and(|s| s.running && s.time > broken_at + 0.02)
    });
    assert_eq!(spring_stiffness(&world(&harness)), 2500.0, "the broken file left the simulation alone");

    // The broken save undone: the file is what runs again.
    save_by_rename(&stiffer);
    until(&mut harness, "the error to clear", |p| p.load_error().is_none());
    assert!(harness.state().log().any(|l| l.text.ends_with("spring.ron is back to the running scene")));
    assert!(harness.query_by_label(&error).is_none());
    assert!(world(&harness).time() > broken_at, "no restart: the file says what already runs");

    std::fs::write(&path, SPRING.replace("stiffness: 100.0", "stiffness: 400.0")).unwrap();
    until(&mut harness, "k = 400 N/m in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| spring_stiffness(&w) == 400.0)
    });
    assert_eq!(world(&harness).time(), 0.0, "a reloaded scene starts paused at t = 0");
    assert!(harness.state().load_error().is_none());
}

/// The panel with the moored buoy at t = 0, rendered by wgpu on the CPU (lavapipe in CI) and
/// compared with `tests/snapshots/control_panel.png` (`UPDATE_SNAPSHOTS=1` rewrites it).
#[test]
fn the_panel_renders_on_the_cpu_like_its_snapshot() {
    // A folder of its own: the scene list stays the same when scenes are added to the repository.
    let dir = scenes_folder(&[("moored_buoy.ron", &std::fs::read_to_string(repo("scenes/moored_buoy.ron")).unwrap())]);
    let panel = panel(dir.path());
    let mut harness = Harness::builder()
        .with_size([440.0, 1100.0])
        .with_options(SnapshotOptions::new().threshold(2.0).output_path(here!("snapshots")))
        .wgpu()
        .build_ui_state(|ui, panel: &mut ControlPanel| panel.ui(ui, None), panel);
    open_from_list(&mut harness, "moored_buoy.ron");
    harness.run_steps(4);
    let image = harness.render().expect("wgpu renders on this machine");
    let colors: std::collections::HashSet<_> = image.pixels().map(|p| p.0).collect();
    assert!(colors.len() > 20, "a blank render: {} colours", colors.len());
    harness.snapshot("control_panel");
}

/// Where there is contact: its knobs reach the running contact law, and the estimator's k1, k2
/// (from the default impact) go into them with one click.
#[test]
fn contact_knobs_and_the_estimator_tune_the_running_contact() {
    let mut harness = tall_harness(panel(&repo("scenes")));
    open_from_list(&mut harness, "box_drop.ron");
    set_knob(&mut harness, "stiffness k1", 2.5e8);
    until(&mut harness, "the applied message", |p| p.log().any(|l| l.text.contains("applied")));
    let contact_stiffness = |world: &World| match &world.couplings()[0].kind {
        CouplingKind::Contact(contact) => contact.law().stiffness(),
        kind => panic!("not a contact: {kind:?}"),
    };
    assert_eq!(contact_stiffness(&world(&harness)), 2.5e8);

    harness.get_by_label_contains("Use k1, k2 for").click();
    harness.run_steps(2);
    let estimated = harness.state().status().map(|s| s.contacts[0].clone()).unwrap();
    let impact = tether_physics::coupling::contact::estimator::Impact {
        mass: estimated.mass,
        other_mass: estimated.other_mass,
        area: estimated.area,
        speed: 1.0,
        range: estimated.range,
        min_distance: -0.005,
        damping_ratio: 0.1,
    };
    let expected = tether_physics::coupling::contact::estimator::estimate(&impact).unwrap().stiffness;
    until(&mut harness, "the estimate in the running contact", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| contact_stiffness(&w) == expected)
    });
}

/// The water panel: wave height, current and a body's drag reach the running world; a density
/// of 0 and a negative drag are refused with the scene builder's reasons, the world untouched.
#[test]
fn water_knobs_tune_the_running_water_and_bad_values_are_refused() {
    let text = r#"Scene(dt: 0.01, water: Water(depth: 30.0, waves: Regular(height: 1.0, period: 6.0)), bodies: [
        Body(name: "float", master: Node(position: (0.0, 0.0, 0.0), mass: 1025.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
             shape: Box(size: (2.0, 2.0, 1.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0)))])"#;
    let dir = scenes_folder(&[("float.ron", text)]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "float.ron");
    let height = |world: &World| match world.system().water().expect("water").water.spec().waves {
        tether_physics::water::WaveSpec::Regular { height, .. } => height,
        other => panic!("{other:?}"),
    };
    let drag_z = |world: &World| world.system().water().expect("water").floating[0].hydro().spec().drag.z;

    set_knob(&mut harness, "wave height H", 1.5);
    until(&mut harness, "the water applied", |p| p.log().any(|l| l.text.starts_with("the water applied")));
    assert_eq!(height(&world(&harness)), 1.5);
    set_knob(&mut harness, "current speed", 0.4);
    until(&mut harness, "the current applied", |p| {
        p.log().filter(|l| l.text.starts_with("the water applied")).count() == 2
    });
    assert_eq!(world(&harness).system().water().expect("water").water.spec().current.speed, 0.4);

    set_knob(&mut harness, "density ρ", 0.0);
    harness.get_by_label_contains(
        "Refused: density = 0 not applied (the run keeps 1025): water: density must be > 0 kg/m³, got 0",
    );
    assert_eq!(world(&harness).system().water().expect("water").water.spec().density, 1025.0);

    set_knob(&mut harness, "drag C_d z", 0.7);
    until(&mut harness, "the coefficients applied", |p| {
        p.log().any(|l| l.text.starts_with("the body's coefficients in the water applied"))
    });
    assert_eq!(drag_z(&world(&harness)), 0.7);
    set_knob(&mut harness, "drag C_d z", -1.0);
    harness.get_by_label_contains(
        "Refused: drag[2] = -1 not applied (the run keeps 0.7): body \"float\": hydro: drag must be finite and ≥ 0",
    );
    assert_eq!(drag_z(&world(&harness)), 0.7);
}

/// Whether the checkbox labelled `label` is ticked, as a screen reader reads it.
fn ticked(harness: &Harness<'_, ControlPanel>, label: &str) -> bool {
    harness.get_by_label(label).accesskit_node().toggled() == Some(accesskit::Toggled::True)
}

/// The potential-flow switch (PHYSICS.md §9) on the cylinder of `tests/fixtures/rao/cylinder.ron`
/// in its regular sea: ticked for the cylinder, absent for the block beside it (no potential
/// data). Played for a while, paused and switched off, the running world is the world before it
/// switched off by the physics' own `set_potential_flow`, step for step (no radiation, no
/// excitation), and the box shows what runs; switched on again, potential flow runs with its
/// radiation memory started afresh (no radiation force yet, while the cylinder moves). The
/// recording has the cylinder's radiation and excitation plots.
#[test]
fn the_potential_flow_switch_reaches_the_running_world_and_shows_what_runs() {
    let text = cylinder_text();
    let dir = scenes_folder(&[("cylinder.ron", &text)]);
    let shown = dir.path().join("shown.rrd");
    let sinks = Sinks::new(vec![Sinks::file(&shown).unwrap()]);
    let mut harness = harness(ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap());
    open_from_list(&mut harness, "cylinder.ron");
    let running = |world: &World| world.system().water().expect("water").floating[0].potential().is_some();
    let shows = |on: bool| move |p: &ControlPanel| p.status().is_some_and(|s| s.potential_flow == [(0, on)]);
    until(&mut harness, "the status", shows(true));
    harness.run_steps(2);
    assert_eq!(harness.query_all_by_label("potential flow").count(), 1, "the cylinder's switch, not the block's");
    assert!(ticked(&harness, "potential flow") && running(&world(&harness)));

    harness.key_press(egui::Key::Space);
    until(&mut harness, "1 s of play", |p| p.status().is_some_and(|s| s.running && s.time > 1.0));
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the pause", |p| p.status().is_some_and(|s| !s.running));
    let before = world(&harness);
    harness.get_by_label("potential flow").click();
    until(&mut harness, "the switch off", |p| {
        p.log().any(|l| l.text.starts_with("potential flow off for body \"cylinder\" applied at t = "))
    });
    until(&mut harness, "the box unticked", shows(false));
    harness.run_steps(2);
    assert!(!ticked(&harness, "potential flow"));
    let mut expected = before.clone();
    expected.set_potential_flow(0, false).expect("a potential-flow body");
    let (mut kept, mut off) = (before, world(&harness));
    assert!(!running(&off));
    harness.key_press(egui::Key::ArrowRight);
    until(&mut harness, "one step", |p| p.status().is_some_and(|s| s.steps == off.steps() + 1));
    for world in [&mut expected, &mut kept, &mut off] {
        world.step().unwrap();
    }
    let stepped = world(&harness);
    assert_eq!(stepped.synchronized_states(), expected.synchronized_states(), "the physics' switch, step for step");
    assert_eq!(stepped.synchronized_states(), off.synchronized_states());
    assert_ne!(stepped.synchronized_states(), kept.synchronized_states(), "the switch changed the motion");
    let forces = stepped.water_forces()[0];
    assert_eq!((forces.radiation, forces.excitation), Default::default());

    harness.get_by_label("potential flow").click();
    until(&mut harness, "the switch on", |p| {
        p.log().any(|l| l.text.starts_with("potential flow on for body \"cylinder\" applied at t = "))
    });
    until(&mut harness, "the box ticked", shows(true));
    harness.run_steps(2);
    assert!(ticked(&harness, "potential flow"));
    let on = world(&harness);
    assert!(running(&on));
    let forces = on.water_forces()[0];
    assert!(on.state(0).velocity.norm() > 1e-3, "the cylinder moves: {:?}", on.state(0).velocity);
    assert_eq!(forces.radiation.force.norm(), 0.0, "a fresh radiation memory: the body at rest before");
    assert!(forces.excitation.force.norm() > 1.0, "{forces:?}");
    drop(harness);
    let names = |entity: &str| common::x11::series_names(&shown, entity);
    assert_eq!(
        names("/plots/water/cylinder/radiation"),
        ["Fx [N]", "Fy [N]", "Fz [N]", "Mx [N·m]", "My [N·m]", "Mz [N·m]"]
    );
    assert_eq!(names("/plots/water/cylinder/excitation").len(), 6);
    assert!(names("/plots/water/block/radiation").is_empty());
}

/// The drift and air knobs (PHYSICS.md §10) on the cylinder of `tests/fixtures/rao/cylinder.ron`
/// in a 15 m/s wind: the drift model is a choice for the cylinder (its files have a `.8`), not
/// for the block; Newman chosen, the running world's cylinder runs Newman's drift and the tuned
/// scene says so. The wind speed, the gusts (steady to NPD) and their seed reach the running
/// air; a negative speed is refused with the loader's reason, the run keeping its wind; Revert
/// puts the file's air and drift back in the running world.
#[test]
fn drift_and_air_knobs_tune_the_running_world_and_bad_values_are_refused() {
    use tether_physics::air::GustSpec;
    use tether_physics::potential::DriftModel;
    let text = with_wind(&cylinder_text(), "air: Air(wind: Wind(speed: 15.0)),");
    assert_eq!(text.matches("windage").count() + text.matches("air: Air").count(), 2, "{text}");
    let dir = scenes_folder(&[("cylinder.ron", &text)]);
    let mut harness = tall_harness(panel(dir.path()));
    open_from_list(&mut harness, "cylinder.ron");
    until(&mut harness, "the status", |p| p.status().is_some_and(|s| s.drift == [(0, DriftModel::Off)]));
    harness.run_steps(2);
    assert_eq!(harness.query_all_by_label("wave drift").count(), 1, "the cylinder's choice, not the block's");
    let drift = |world: &World| {
        let floating = world.system().water().expect("water").floating_body(0).expect("the cylinder floats");
        floating.potential_model().expect("potential flow").drift_model()
    };
    let air = |world: &World| *world.system().air().expect("air").air().spec();

    choose_view(&mut harness, "Off", "Newman");
    until(&mut harness, "the drift applied", |p| p.status().is_some_and(|s| s.drift == [(0, DriftModel::Newman)]));
    assert_eq!(drift(&world(&harness)), DriftModel::Newman);
    let tuned = |harness: &Harness<'_, ControlPanel>| harness.state().scene().expect("a scene").tuned.clone();
    let potential = |file: &tether_scene::SceneFile| file.bodies[0].hydro.as_ref().and_then(|h| h.potential.clone());
    assert_eq!(potential(&tuned(&harness)).expect("the cylinder's").drift, DriftModel::Newman);

    set_knob(&mut harness, "wind speed U_r (at z_r)", 22.0);
    until(&mut harness, "the air applied", |p| p.log().any(|l| l.text.starts_with("the air applied at t = ")));
    assert_eq!(air(&world(&harness)).wind.speed, 22.0);
    choose_view(&mut harness, "steady", "NPD (API, ISO 19901-1)");
    until(&mut harness, "the gusts applied", |p| {
        p.log().filter(|l| l.text.starts_with("the air applied")).count() == 2
    });
    assert_eq!(air(&world(&harness)).wind.gusts, GustSpec::Npd { seed: 1, components: 200 });
    set_knob(&mut harness, "gust seed", 9.0);
    until(&mut harness, "the seed applied", |p| p.log().filter(|l| l.text.starts_with("the air applied")).count() == 3);
    assert_eq!(air(&world(&harness)).wind.gusts, GustSpec::Npd { seed: 9, components: 200 });

    set_knob(&mut harness, "wind speed U_r (at z_r)", -1.0);
    harness.get_by_label_contains("Refused: wind.speed = -1 not applied (the run keeps 22): air: ");
    harness.get_by_label_contains("speed must be ≥ 0 m/s, got -1");
    assert_eq!(air(&world(&harness)).wind.speed, 22.0);

    harness.get_by_label("Revert to file").click();
    until(&mut harness, "the revert", |p| p.scene().is_some_and(|s| s.tuned == s.file));
    until(&mut harness, "the file's drift", |p| p.status().is_some_and(|s| s.drift == [(0, DriftModel::Off)]));
    until(&mut harness, "the file's wind", |p| p.log().filter(|l| l.text.starts_with("the air applied")).count() == 4);
    let reverted = world(&harness);
    assert_eq!((air(&reverted).wind.speed, air(&reverted).wind.gusts), (15.0, GustSpec::Steady));
    assert_eq!(drift(&reverted), DriftModel::Off);
}

/// A body whose scene asks for linear hydrostatics (`hydrostatics: Linear`, PHYSICS.md §9) says
/// so on its switch, which the plain label does not match, while the running world has them;
/// switched off, the running world has no potential flow, so its hydrostatics are the mesh's.
/// The window's knobs are drawn from the parameters catalogue: every number it lists for a scene
/// with a spring, water, a floating body's coefficients, wind and a seabed has a knob labelled as
/// the catalogue labels it (less the `name: ` the catalogue puts before it).
#[test]
fn every_catalogued_parameter_has_a_knob_with_its_label() {
    let air = "air: Air(wind: Wind(speed: 15.0, gusts: Kaimal(intensity: 0.1, seed: 3))),\n    seabed: Seabed(line_friction: 0.8),";
    // A seabed lies at the water's depth.
    let text = with_wind(&cylinder_text(), air).replace("water: Water(waves:", "water: Water(depth: 60.0, waves:");
    assert_eq!(
        text.matches("windage").count() + text.matches("seabed: Seabed").count() + text.matches("depth: 60").count(),
        3,
        "{text}"
    );
    let dir = scenes_folder(&[("cylinder.ron", &text), ("spring.ron", &SPRING)]);
    for scene in ["cylinder.ron", "spring.ron"] {
        let mut harness = tall_harness(panel(dir.path()));
        open_from_list(&mut harness, scene);
        harness.run_steps(2);
        let tuned = harness.state().scene().expect("a scene").tuned.clone();
        let catalogue = tether_analysis::parameters::parameters(&tuned);
        assert!(catalogue.len() >= 3, "{scene}: {catalogue:?}");
        for parameter in &catalogue {
            let (_, label) = parameter.label.split_once(": ").expect("the catalogue's `name: label`");
            assert!(
                harness.query_all_by_label(label).count() >= 1,
                "{scene}: no knob labelled {label:?} ({})",
                parameter.path
            );
        }
    }
}

#[test]
fn the_potential_flow_switch_says_when_it_brings_linear_hydrostatics() {
    let file = repo("validation/potential-flow/cylinder/cylinder");
    let fixture = std::fs::read_to_string(repo("tests/fixtures/rao/cylinder.ron")).unwrap();
    let text = fixture.replace(
        "\"../../../validation/potential-flow/cylinder/cylinder\")",
        &format!("{file:?}, hydrostatics: Linear)"),
    );
    assert_ne!(text, fixture);
    let dir = scenes_folder(&[("cylinder.ron", &text)]);
    let sinks = Sinks::new(vec![Sinks::file(&dir.path().join("shown.rrd")).unwrap()]);
    let mut harness = harness(ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap());
    open_from_list(&mut harness, "cylinder.ron");
    let shows = |on: bool| move |p: &ControlPanel| p.status().is_some_and(|s| s.potential_flow == [(0, on)]);
    until(&mut harness, "the status", shows(true));
    harness.run_steps(2);
    let label = "potential flow, linear hydrostatics (.hst)";
    assert_eq!(harness.query_all_by_label("potential flow").count(), 0, "not the plain switch");
    assert!(ticked(&harness, label));
    let linear = |world: &World| {
        world.system().water().expect("water").floating[0]
            .potential()
            .as_ref()
            .is_some_and(|p| p.linear_hydrostatics().is_some())
    };
    assert!(linear(&world(&harness)));
    harness.get_by_label(label).click();
    until(&mut harness, "the switch off", shows(false));
    harness.run_steps(2);
    assert!(!ticked(&harness, label));
    let off = world(&harness);
    assert!(off.system().water().expect("water").floating[0].potential().is_none());
}

/// The statics panel on a buoy moored by three lines lying on a seabed: the seabed's C_B and a
/// line's A_d reach the running world (a negative C_B is refused, the world untouched); the
/// equilibrium button puts the buoy where `tether equilibrium` finds it, at rest; the offset
/// curve is computed and drawn.
#[test]
fn statics_panel_tunes_the_seabed_jumps_to_equilibrium_and_draws_the_offset_curve() {
    let dir = scenes_folder(&[("moored.ron", common::MOORED_ON_SEABED)]);
    // Tall enough for the statics panel below four couplings' knobs.
    let mut harness = Harness::builder()
        .with_size([440.0, 2600.0])
        .build_ui_state(|ui, panel: &mut ControlPanel| panel.ui(ui, None), panel(dir.path()));
    open_from_list(&mut harness, "moored.ron");
    let friction = |world: &World| world.system().seabed().expect("a seabed").line_friction();

    set_knob(&mut harness, "line friction C_B", 0.9);
    until(&mut harness, "C_B applied", |p| {
        p.log().any(|l| l.text.starts_with("seabed line friction C_B = 0.9 applied"))
    });
    assert_eq!(friction(&world(&harness)), 0.9);
    let tuned = |harness: &Harness<'_, ControlPanel>| harness.state().scene().expect("a scene").tuned.clone();
    assert_eq!(tuned(&harness).seabed.expect("a seabed").line_friction, 0.9, "what runs, for Save as");
    set_knob(&mut harness, "line friction C_B", -0.1);
    harness.get_by_label_contains(
        "Refused: line_friction = -0.1 not applied (the run keeps 0.9): seabed: line_friction must be ≥ 0, got -0.1",
    );
    assert_eq!(friction(&world(&harness)), 0.9);
    // A fit can move it as it moves the other knobs.
    let fittable = tether_analysis::parameters::parameters(&tuned(&harness));
    assert!(fittable.iter().any(|f| f.path == "seabed.line_friction" && f.value == 0.9), "{fittable:?}");

    // The first line's A_d (three lines show the knob).
    let knob = harness.get_all_by_label("displaced area A_d").next().expect("an A_d knob").accesskit_node().locate();
    set_value(&mut harness, knob, 0.004);
    until(&mut harness, "A_d applied", |p| p.log().any(|l| l.text.starts_with("coupling \"m1\" applied")));
    match &world(&harness).couplings()[0].kind {
        CouplingKind::Catenary(line) => assert_eq!(line.displaced_area(), 0.004),
        kind => panic!("not a catenary: {kind:?}"),
    }

    harness.get_by_label("Equilibrium").click();
    until(&mut harness, "the equilibrium", |p| p.log().any(|l| l.text.starts_with("static equilibrium in")));
    let placed = world(&harness);
    let solved = equilibrium::solve(placed.system(), &placed.synchronized_states(), &[], &Settings::default()).unwrap();
    assert_eq!(solved.iterations, 0, "the world is at its static equilibrium");
    assert_eq!(placed.state(0).velocity.norm(), 0.0, "at rest");

    harness.get_by_label("Offset curve").click();
    until(&mut harness, "the offset curve", |p| {
        p.log().any(|l| l.text.starts_with("offset curve of body \"buoy\" in x: 21 offsets"))
    });
    harness.run_steps(2);
    harness.get_by_label("body \"buoy\": restoring force against offset in x");

    // Revert puts the file's C_B back in the running world.
    harness.get_by_label("Revert to file").click();
    until(&mut harness, "the file's C_B", |p| {
        p.log().any(|l| l.text.starts_with("seabed line friction C_B = 0.5 applied"))
    });
    assert_eq!(friction(&world(&harness)), 0.5);
}

/// A dry rope between a world point and a ball, quasi-static as written.
const ROPE: &str = r#"Scene(dt: 1e-3, bodies: [Body(name: "ball",
    master: Node(position: (6.0, 0.0, 2.0), mass: 100.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
    shape: Sphere(radius: 0.2))],
  couplings: [Catenary(name: "rope", end1: World((0.0, 0.0, 10.0)), end2: Body(body: "ball"),
    mass_per_length: 2.0, length: 10.0, stiffness: 2.0e5)])"#;

fn line_model(world: &World) -> LineModel {
    match &world.couplings()[0].kind {
        CouplingKind::Catenary(line) => line.model(),
        kind => panic!("not a line: {kind:?}"),
    }
}

/// A line switched to dynamic while it runs: its model reaches the world, its plot gains the
/// quasi-static series docs/dynamic-lines.md promises (issue 35: they were missing after a live
/// switch), a bad segment count is refused.
#[test]
fn a_line_switches_to_dynamic_live_and_a_bad_segment_count_is_refused() {
    let dir = scenes_folder(&[("rope.ron", ROPE)]);
    let shown = dir.path().join("shown.rrd");
    let sinks = Sinks::new(vec![Sinks::file(&shown).unwrap()]);
    let mut harness = harness(ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap());
    open_from_list(&mut harness, "rope.ron");
    assert_eq!(line_model(&world(&harness)), LineModel::QuasiStatic);

    harness.get_by_label("dynamic (lumped mass)").click();
    until(&mut harness, "the switch", |p| p.log().any(|l| l.text.starts_with("coupling \"rope\" applied")));
    let LineModel::Dynamic(model) = line_model(&world(&harness)) else { panic!("still quasi-static") };
    assert_eq!(model.segments(), 20, "a switched line takes 20 segments");

    set_knob(&mut harness, "segments N", 0.0);
    harness.get_by_label_contains("Refused: model.segments = 0 not applied (the run keeps 20): coupling \"rope\": segments must be at least 1, got 0");
    set_knob(&mut harness, "segments N", 8.0);
    until(&mut harness, "8 segments", |p| {
        p.simulation()
            .snapshot(PATIENCE)
            .is_some_and(|w| matches!(line_model(&w), LineModel::Dynamic(m) if m.segments() == 8))
    });
    let world = world(&harness);
    let nodes = world.evaluation().line_run(0).and_then(|run| run.nodes()).expect("the line has nodes");
    assert_eq!(nodes.positions.len(), 9, "8 segments, 9 nodes");
    drop(harness);
    assert_eq!(common::x11::series_names(&shown, "/plots/catenary"), ["rope end1", "rope end2"]);
    assert_eq!(
        common::x11::series_names(&shown, "/plots/catenary/quasi-static/rope"),
        ["rope end1 quasi-static", "rope end2 quasi-static"]
    );
}

/// The spring of [`SPRING`] with stiffness `k` N/m, its x sampled every 10 ms for 2 s with
/// uniform noise of ±0.2 mm (0.2 % of the 0.1 m amplitude, seeded), as a CSV file
/// `spring_k.csv` (columns `t`, `x_measured`) in `dir`.
fn spring_record(dir: &Path, k: f64) -> PathBuf {
    use rand::{Rng as _, SeedableRng as _};
    let mut noise = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let path = dir.join("spring_k.csv");
    let text = SPRING.replace("stiffness: 100.0", &format!("stiffness: {k:?}"));
    let mut world = tether_scene::parse(&text, &path).unwrap().world;
    let mut csv = String::from("t,x_measured\n");
    for step in 0..=2000 {
        if step > 0 {
            world.step().unwrap();
        }
        if step % 10 == 0 {
            let x = world.state(0).position.x + 2e-4 * (2.0 * noise.random::<f64>() - 1.0);
            csv += &format!("{:.6},{x:.12e}\n", world.time());
        }
    }
    std::fs::write(&path, csv).unwrap();
    path
}

/// The fit panel opened, `record` read into it and its column mapped to the body's x.
fn fit_panel_with_record(harness: &mut Harness<'_, ControlPanel>, record: &Path) {
    harness.state_mut().open_record(record);
    harness.get_by_label("Fit to a record").click();
    harness.run_steps(2);
    harness.get_by_label("x_measured").click();
    harness.run_steps(2);
    harness.get_by_label("m: position x [m]").click();
    harness.run_steps(2);
}

/// The fit panel on the spring against a record made with k = 130 N/m (the file says 100): the
/// column mapped, the stiffness ticked (bounds prefilled around 100), Fit pressed. The fit ends
/// with k within 0.5 % of 130, the running world's spring has the fitted value, its 95 %
/// interval is shown beside the knob; Revert puts the file's 100 N/m back in the running world.
#[test]
fn a_fit_moves_the_running_stiffness_to_the_record_and_revert_puts_the_file_back() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let truth = 130.0;
    let record = spring_record(dir.path(), truth);
    let shown = dir.path().join("shown.rrd");
    let sinks = Sinks::new(vec![Sinks::file(&shown).unwrap()]);
    let panel = ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap();
    let mut harness = tall_harness(panel);
    open_from_list(&mut harness, "spring.ron");
    fit_panel_with_record(&mut harness, &record);
    harness.get_by_label("spring: stiffness k").click();
    harness.run_steps(2);
    harness.get_by_label("Fit").click();
    until(&mut harness, "the fit to end", |p| p.fit().session.as_ref().is_some_and(|s| s.result.is_some()));
    let session = harness.state().fit().session.as_ref().unwrap();
    let summary = session.result.clone().unwrap().unwrap_or_else(|e| panic!("the fit failed: {e}"));
    let fitted = &summary.parameters[0];
    println!(
        "fitted k = {} N/m, interval {:?}, {} iterations, {} runs",
        fitted.value, fitted.interval, summary.iterations, summary.runs
    );
    assert!(summary.ending.converged(), "{:?}", summary.ending);
    assert!((fitted.value - truth).abs() < 5e-3 * truth, "k = {}", fitted.value);
    assert!(session.costs.len() >= 2, "the cost of the start and of each accepted iteration: {:?}", session.costs);
    until(&mut harness, "the fitted k in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| spring_stiffness(&w) == fitted.value)
    });
    harness.run_steps(2);
    let (lo, hi) = fitted.interval.expect("the data determine k");
    assert!(lo < fitted.value && fitted.value < hi);
    let interval = format!("(95 % {} … {})", quantity(lo, "N/m", 6), quantity(hi, "N/m", 6));
    assert!(harness.query_all_by_label_contains(&interval).count() == 1, "the interval beside the knob: {interval}");
    assert!(harness.query_by_label_contains("spring •").is_some(), "the fitted coupling is marked as tuned");

    harness.get_by_label("Revert").click();
    until(&mut harness, "the file's k in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| spring_stiffness(&w) == 100.0)
    });
    assert!(harness.state().scene().is_some_and(|s| s.tuned == s.file));
    let first = harness.state().fit().session.as_ref().map_or(0, |s| s.costs.len());

    // A second fit in the same window draws its curves where the first one's were, visible.
    harness.get_by_label("Fit").click();
    harness.run_steps(2);
    until(&mut harness, "the second fit to end", |p| p.fit().session.as_ref().is_some_and(|s| s.result.is_some()));
    let second = harness.state().fit().session.as_ref().map_or(0, |s| s.costs.len());

    // What the viewer was sent: the record's samples once per fit, a model curve per accepted
    // iteration, each but the last hidden by its style logged again (the viewer draws the
    // latest alone).
    drop(harness);
    let stores = common::x11::stores(&shown);
    let chunks: Vec<_> = stores.values().flat_map(|store| store.iter_physical_chunks().cloned()).collect();
    let rows = |entity: &str, fixed: bool| -> usize {
        let of = chunks.iter().filter(|c| c.entity_path().to_string() == entity && c.is_static() == fixed);
        of.map(|c| c.num_rows()).sum()
    };
    // The latest static `visible_series` of an entity (static data: the last write wins).
    let visible = |entity: &str| -> Option<bool> {
        let component = rerun::SeriesLines::descriptor_visible_series().component;
        let of = chunks.iter().filter(|c| c.entity_path().to_string() == entity && c.is_static());
        of.flat_map(|c| c.row_ids().zip(c.iter_slices::<bool>(component)).map(|(id, v)| (id, v.iter().next())))
            .filter_map(|(id, v)| Some((id, v?)))
            .max_by_key(|(id, _)| *id)
            .map(|(_, v)| v)
    };
    assert_eq!(rows("/plots/fit/x_measured/record", false), 2 * 201, "the record's samples, once per fit");
    for curve in 0..first.max(second) {
        let entity = format!("/plots/fit/x_measured/model/{curve}");
        assert!(rows(&entity, false) > 1000, "{entity}: the model's curve at every world step");
        assert_eq!(visible(&entity), Some(curve + 1 == second), "{entity}: only the second fit's last curve shows");
    }
    assert_eq!(
        rows(&format!("/plots/fit/x_measured/model/{}", first.max(second)), false),
        0,
        "one curve per accepted iteration"
    );
}

/// Bad choices are refused in one line and nothing runs: no column mapped; a negative bound on a
/// log scale; the same bound on a linear scale, which the scene loader refuses with its message.
#[test]
fn a_fit_with_bad_choices_is_refused_with_one_line() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let record = spring_record(dir.path(), 130.0);
    let mut harness = tall_harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    harness.state_mut().open_record(&record);
    harness.get_by_label("Fit to a record").click();
    harness.run_steps(2);
    harness.get_by_label("spring: stiffness k").click();
    harness.run_steps(2);
    harness.get_by_label("Fit").click();
    harness.run_steps(2);
    harness.get_by_label("no column mapped: choose the model signal of at least one column");

    harness.get_by_label("x_measured").click();
    harness.run_steps(2);
    harness.get_by_label("m: position x [m]").click();
    harness.run_steps(2);
    set_knob(&mut harness, "spring: stiffness k from", -50.0);
    harness.get_by_label("Fit").click();
    harness.run_steps(2);
    harness.get_by_label_contains("a Log scale needs bounds > 0, got from -50");
    harness.get_by_label("log").click();
    harness.run_steps(2);
    harness.get_by_label("Fit").click();
    harness.run_steps(2);
    let refusal = harness.state().fit().refusal.clone().unwrap_or_default();
    assert!(refusal.contains("from = -50") && refusal.contains("stiffness must be ≥ 0 N/m, got -50"), "{refusal}");
    harness.get_by_label(&refusal);
    assert!(harness.state().fit().session.is_none(), "nothing ran");
    assert_eq!(spring_stiffness(&world(&harness)), 100.0);
}

/// Issue 47: each scene keeps its own fit state. The spring's record mapped to body "m" and its
/// stiffness ticked; another scene (body "n", its spring named "other") opens with an empty fit
/// panel, not the spring's mapping to a body it lacks; back on the spring, its record, column
/// and tick are there again. A scene reloaded without the body a column was mapped to says it
/// unmapped the column.
#[test]
fn each_scene_keeps_its_own_fit_and_a_missing_signal_is_unmapped_and_said() {
    let other = common::spring_scene_text("n").replace("name: \"spring\"", "name: \"other\"");
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str()), ("other.ron", &other)]);
    let record = spring_record(dir.path(), 130.0);
    let mut harness = tall_harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    fit_panel_with_record(&mut harness, &record);
    harness.get_by_label("spring: stiffness k").click();
    harness.run_steps(2);
    let mapped = |harness: &Harness<'_, ControlPanel>| -> Vec<String> {
        harness.state().fit().mapping.iter().flatten().map(tether::gui::fit::signal_label).collect()
    };
    assert_eq!(mapped(&harness), ["m: position x [m]"]);

    open_from_list(&mut harness, "other.ron");
    harness.run_steps(2);
    assert!(harness.state().fit().record.is_none(), "the other scene's fit starts empty");
    assert!(harness.state().fit().ticked.is_empty());
    assert!(harness.query_by_label("x_measured").is_none(), "no column of the spring's record shows");

    open_from_list(&mut harness, "spring.ron");
    harness.run_steps(2);
    assert_eq!(mapped(&harness), ["m: position x [m]"], "the spring's mapping is back");
    assert_eq!(harness.state().fit().ticked.keys().collect::<Vec<_>>(), ["couplings.spring.law.stiffness"]);

    // The spring's file now names its body "n": the column's signal is gone, and said.
    std::fs::write(dir.path().join("spring.ron"), &other).unwrap();
    until(&mut harness, "the reload", |p| p.scene().is_some_and(|s| s.tuned.bodies[0].name == "n"));
    assert!(mapped(&harness).is_empty(), "unmapped: {:?}", mapped(&harness));
    assert!(harness.state().fit().ticked.is_empty(), "the spring's coupling is gone: unticked");
    let said = |text: &str| harness.state().log().any(|l| l.text.contains(text));
    assert!(said("fit: column \"x_measured\" unmapped (m: position x [m] is not in this scene)"));
    assert!(said("fit: couplings.spring.law.stiffness unticked (not in this scene)"));
}

/// The unstretched length of catenary coupling `index` in `world` [m].
fn line_length(world: &World, index: usize) -> f64 {
    match &world.couplings()[index].kind {
        CouplingKind::Catenary(line) => line.length(),
        kind => panic!("not a line: {kind:?}"),
    }
}

/// Issue 47: a value being typed into a knob of the shipped moored buoy while it runs applies
/// nothing, and logs nothing, until Enter: two seconds of the run with "260" typed into the
/// second chain's length leave the log without an "applied" line and the chain at its 250 m;
/// Enter applies 260 m and says so once.
#[test]
fn a_value_being_typed_applies_nothing_until_enter() {
    let text = std::fs::read_to_string(repo("scenes/moored_buoy.ron")).unwrap();
    let dir = scenes_folder(&[("moored_buoy.ron", &text)]);
    let mut harness = tall_harness(panel(dir.path()));
    open_from_list(&mut harness, "moored_buoy.ron");
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the run", |p| p.status().is_some_and(|s| s.running && s.time > 0.5));
    let applied =
        |harness: &Harness<'_, ControlPanel>| harness.state().log().filter(|l| l.text.contains("applied")).count();
    let before = applied(&harness);
    let length = line_length(&world(&harness), 1);
    harness.get_all_by_label("length L_eq").nth(1).expect("a second chain").click();
    harness.run_steps(2);
    harness.get_all_by_label("length L_eq").nth(1).expect("a second chain").type_text("260");
    let typing = Instant::now();
    while typing.elapsed() < Duration::from_secs(2) {
        harness.step();
        std::thread::sleep(Duration::from_millis(20));
    }
    let log: Vec<String> = harness.state().log().map(|l| l.text.clone()).collect();
    assert_eq!(applied(&harness), before, "nothing applied while typing: {log:?}");
    assert!(harness.state().status().is_some_and(|s| s.time > 1.0), "the run went on");
    assert_eq!(line_length(&world(&harness), 1), length, "the run keeps its length while it is typed");
    harness.key_press(egui::Key::Enter);
    until(&mut harness, "the applied edit", |p| p.log().filter(|l| l.text.contains("applied")).count() > before);
    assert_eq!(applied(&harness), before + 1, "applied once");
    assert_eq!(line_length(&world(&harness), 1), 260.0);
}

/// Play refuses a scene whose duration at its time step is past the run limit (the run-length
/// check of `tether record`, `tether_analysis::run_length`): the spring at dt = 1e-12 s for its 10 s
/// needs 10¹³ steps; the panel says so, names dt, and the run stays at t = 0.
#[test]
fn play_refuses_a_run_that_cannot_end() {
    let endless = SPRING.replace("dt: 0.001,", "dt: 1e-12,\n    duration: 10.0,");
    let dir = scenes_folder(&[("endless.ron", &endless)]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "endless.ron");
    harness.key_press(egui::Key::Space);
    until(&mut harness, "Play's refusal", |p| p.log().any(|line| line.error && line.text.contains("not started")));
    let refusal = harness.state().log().find(|line| line.text.contains("not started")).unwrap().text.clone();
    assert!(refusal.contains("the run needs 1.00e13 integrator steps, past the limit of 1e8"), "{refusal}");
    assert!(refusal.contains("the time step dt = 1.000e-12 s is"), "{refusal}");
    let status = harness.state().status().expect("the scene is loaded");
    assert!(!status.running, "the run did not start");
    assert_eq!(world(&harness).steps(), 0);
}

/// The quasi-static line hint of `tether check` beside the model switch: `chain_forced_surge`'s
/// chain as a catenary, surged at 10 s against its first transverse period of 7.2 s, says
/// "likely wrong quasi-static: try Dynamic" with the numbers under its switch; switched to
/// dynamic, the hint goes.
#[test]
fn the_window_says_when_a_quasi_static_line_is_likely_wrong() {
    let text = std::fs::read_to_string(repo("scenes/chain_forced_surge.ron")).unwrap();
    let start = text.find("model: Dynamic(").unwrap();
    let end = start + text[start..].find("),\n        ),").unwrap() + 1;
    let quasi_static = format!("{}model: QuasiStatic{}", &text[..start], &text[end..]);
    let dir = scenes_folder(&[("chain_qs.ron", &quasi_static)]);
    let mut harness = tall_harness(panel(dir.path()));
    open_from_list(&mut harness, "chain_qs.ron");
    until(&mut harness, "the line's hint", |p| {
        p.status().is_some_and(|s| s.line_hints.first().is_some_and(Option::is_some))
    });
    harness.run_steps(2);
    let measures = harness.state().status().unwrap().line_hints[0].unwrap();
    assert!(measures.suggests_dynamic());
    let shown = measures.to_string();
    assert!(shown.starts_with("likely wrong quasi-static: try Dynamic: first transverse period T₁ = 7."), "{shown}");
    harness.get_by_label(&shown);

    harness.get_by_label("dynamic (lumped mass)").click();
    until(&mut harness, "the switch", |p| p.log().any(|l| l.text.starts_with("coupling \"chain\" applied")));
    until(&mut harness, "the hint to go", |p| p.status().is_some_and(|s| s.line_hints[0].is_none()));
    harness.run_steps(2);
    assert!(harness.query_by_label_contains("likely wrong quasi-static").is_none());
}

/// Issue 35: text typed into a number field is said not to be a number (it was dropped
/// silently), the value and the run untouched; a number typed then applies and the note goes.
#[test]
fn text_typed_into_a_number_field_says_it_is_not_a_number() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "spring.ron");
    let type_into = |harness: &mut Harness<'_, ControlPanel>, text: &str| {
        harness.get_by_label("damping k_d").click();
        harness.run_steps(2);
        harness.get_by_label("damping k_d").type_text(text);
        harness.run_steps(1);
        harness.key_press(egui::Key::Enter);
        harness.run_steps(2);
    };
    type_into(&mut harness, "abc");
    harness.get_by_label("“abc” is not a number: nothing applied");
    assert_eq!(spring_damping(&world(&harness)), 0.0);

    type_into(&mut harness, "0.5");
    until(&mut harness, "the damping in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| spring_damping(&w) == 0.5)
    });
    harness.run_steps(2);
    assert!(harness.query_by_label_contains("is not a number").is_none());
}

/// Issue 35: with no scene (`tether view`), Play, Step and Reset are greyed.
#[test]
fn without_a_scene_play_step_and_reset_are_greyed() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let mut harness = harness(panel(dir.path()));
    harness.run_steps(2);
    for button in ["▶ Play", "⏭ Step", "⟲ Reset"] {
        assert!(harness.get_by_label(button).accesskit_node().is_disabled(), "{button} is greyed with no scene");
    }
    open_from_list(&mut harness, "spring.ron");
    harness.run_steps(2);
    for button in ["▶ Play", "⏭ Step", "⟲ Reset"] {
        assert!(!harness.get_by_label(button).accesskit_node().is_disabled(), "{button} works on a scene");
    }
}

/// Issue 35: the contact estimator's impact typed on one scene does not carry over to the next:
/// each scene's estimator starts from the default impact (1 m/s).
#[test]
fn the_contact_estimator_starts_from_each_scene() {
    let mut harness = tall_harness(panel(&repo("scenes")));
    open_from_list(&mut harness, "fender.ron");
    harness.run_steps(2);
    set_knob(&mut harness, "impact speed v", 7.0);
    let speed = |harness: &Harness<'_, ControlPanel>| {
        harness.get_by_label("impact speed v").accesskit_node().numeric_value().expect("a number field")
    };
    assert_eq!(speed(&harness), 7.0);
    open_from_list(&mut harness, "box_drop.ron");
    harness.run_steps(2);
    assert_eq!(speed(&harness), 1.0, "the next scene's estimator starts from the default impact");
}

/// Issue 35: a run that diverges in its very first step (k = 10⁹ N/m at dt = 1 ms, 30 times its
/// stable step) shows that step in the viewer — the recording's last frame is at t = 1 ms, not
/// 0 — and says so; the panel's step count stays 0.
#[test]
fn a_first_step_that_diverges_is_shown_in_the_viewer_and_said() {
    let stiff = SPRING.replace("stiffness: 100.0", "stiffness: 1e9");
    let dir = scenes_folder(&[("stiff.ron", &stiff)]);
    let shown = dir.path().join("shown.rrd");
    let sinks = Sinks::new(vec![Sinks::file(&shown).unwrap()]);
    let mut harness = harness(ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap());
    open_from_list(&mut harness, "stiff.ron");
    harness.key_press(egui::Key::ArrowRight);
    until(&mut harness, "the divergence", |p| p.status().is_some_and(|s| s.failure.is_some()));
    let status = harness.state().status().cloned().unwrap();
    let failure = status.failure.unwrap();
    assert_eq!(status.steps, 0, "{failure}");
    assert!(failure.contains("the simulation diverged at t = 0.001 s"), "{failure}");
    assert!(failure.ends_with("(the viewer shows the state it reached at t = 1 ms)"), "{failure}");
    drop(harness);
    let stores = common::x11::stores(&shown);
    let last = stores
        .values()
        .flat_map(|store| store.iter_physical_chunks())
        .filter_map(|c| c.timelines().get(&"sim_time".into()).and_then(|t| t.times_raw().iter().copied().max()))
        .max();
    assert_eq!(last, Some(1_000_000), "the diverged step's frame, at 1 ms");
}

/// Issue 35: a line edited shorter than the distance between its ends is applied with a
/// warning (it is stretched by EA at once), and `substeps: Auto` plans again for it: the rope
/// (D = 2×10⁵ N/m, λ0 = 2 kg/m) slack at 10 m over 8.485 m holds the 100 kg ball at one
/// sub-step of 50 ms; pulled taut at 8 m (EA/L = 2.5×10⁵ N/m, stable step 2/ω = 40 ms) it
/// needs ⌈0.05/(0.9·0.04)⌉ = 2.
#[test]
fn a_line_edited_shorter_than_its_ends_warns_and_auto_substeps_follow() {
    let rope = ROPE.replace("dt: 1e-3,", "dt: 0.05, substeps: Auto,").replace("(6.0, 0.0, 2.0)", "(6.0, 0.0, 4.0)");
    let dir = scenes_folder(&[("rope.ron", &rope)]);
    let mut harness = harness(panel(dir.path()));
    open_from_list(&mut harness, "rope.ron");
    assert_eq!(harness.state().status().map(|s| s.substeps), Some(1));
    set_knob(&mut harness, "length L_eq", 8.0);
    let warning = "warning: line \"rope\" is 8 m long, shorter than the 8.485 m between its ends: it is stretched by EA = 1.6 MN at once";
    until(&mut harness, "the warning", |p| p.log().any(|l| l.error && l.text == warning));
    until(&mut harness, "two sub-steps", |p| p.status().is_some_and(|s| s.substeps == 2));
    assert_eq!(world(&harness).substeps(), 2);
    harness.run_steps(2);
    harness.get_by_label("integrator step 25 ms (2 substeps per dt)");
}

/// Issue 35: a long line in the log (or a refusal, a load error) wraps in the side panel
/// instead of widening it; the newest log line is on top; the pace's row is there paused and
/// playing, so the rows below it do not move.
#[test]
fn long_lines_wrap_the_log_is_newest_first_and_rows_stay_put() {
    let long_name = "a_body_named_at_such_length_that_its_name_cannot_fit_in_any_panel_".repeat(3);
    let bad = common::spring_scene_text(&long_name).replace("mass: 1.0,", "mass: -1.0,");
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str()), ("bad.ron", &bad)]);
    let mut harness = side_panel_harness(panel(dir.path()), 1100.0);
    open_from_list(&mut harness, "spring.ron");
    harness.run_steps(2);
    let before = side_width(&harness);
    let long = format!("{} end", "a_very_long_path_segment/".repeat(20));
    harness.state_mut().note_error(long.clone());
    harness.state_mut().note("the newest line".into());
    harness.get_by_label("bad.ron").click();
    harness.run_steps(3);
    let error = harness.state().load_error().expect("the bad scene is refused").to_string();
    assert!(error.contains(&long_name), "{error}");
    harness.get_by_label(&error);
    assert_eq!(side_width(&harness), before, "the panel keeps its width ({before})");
    let top = |harness: &Harness<'_, ControlPanel>, label: &str| {
        harness.get_by_label_contains(label).accesskit_node().bounding_box().expect("laid out").y0
    };
    assert!(top(&harness, "the newest line") < top(&harness, "a_very_long_path_segment"), "newest first");

    let speed_row = |harness: &Harness<'_, ControlPanel>| top(harness, "Speed");
    let paused = speed_row(&harness);
    harness.get_by_label("paused");
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the run", |p| p.status().is_some_and(|s| s.running && s.time > 0.01));
    harness.run_steps(1);
    assert_eq!(speed_row(&harness), paused, "the rows below the pace stay where they were");
}

/// Issue 47: a record with a long file name and a long column name opened in the fit panel
/// wraps its summary and its mapping row inside the side panel instead of widening it (it
/// widened by about 20 points and pushed the viewer).
#[test]
fn a_long_record_name_and_column_wrap_in_the_fit_panel() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let column = "x_measured_by_the_laser_displacement_sensor_mounted_on_the_carriage_in_metres";
    let csv = std::fs::read_to_string(spring_record(dir.path(), 130.0)).unwrap().replacen("x_measured", column, 1);
    let record = dir.path().join(format!("{}.csv", "tank_test_2026_decay_run_with_a_long_name_".repeat(3)));
    std::fs::write(&record, csv).unwrap();
    let mut harness = side_panel_harness(panel(dir.path()), 1400.0);
    open_from_list(&mut harness, "spring.ron");
    harness.get_by_label("Fit to a record").click();
    harness.run_steps(2);
    let before = side_width(&harness);
    harness.state_mut().open_record(&record);
    harness.run_steps(3);
    harness.get_by_label_contains("_long_name_.csv: 1 column");
    harness.get_by_label(column);
    assert_eq!(side_width(&harness), before, "the panel keeps its width ({before})");
}

/// The tracking entity of the 3D view's eye in each blueprint of the recording `path` (`None`
/// for an eye that frames the run).
fn eye_tracking_in(path: &Path) -> Vec<Option<String>> {
    use rerun::external::re_sdk_types::blueprint::archetypes::EyeControls3D;
    let position = EyeControls3D::descriptor_position().component;
    let tracking = EyeControls3D::descriptor_tracking_entity().component;
    let stores = common::x11::stores(path);
    let eyes = stores.values().filter(|store| !store.id().is_recording()).flat_map(|store| {
        store.iter_physical_chunks().filter(|c| c.entity_path().to_string().ends_with("/EyeControls3D"))
    });
    eyes.filter(|chunk| chunk.iter_slices::<[f32; 3]>(position).next().is_some())
        .map(|chunk| chunk.iter_slices::<String>(tracking).next().map(|row| row[0].trim_start_matches('/').to_string()))
        .collect()
}

/// Opens the "View" chooser, which shows `shown`, and picks `choice` in it.
fn choose_view(harness: &mut Harness<'_, ControlPanel>, shown: &str, choice: &str) {
    let chooser = harness
        .get_all_by_role(accesskit::Role::ComboBox)
        .find(|node| node.accesskit_node().value().as_deref() == Some(shown))
        .unwrap_or_else(|| panic!("no chooser showing {shown:?}"));
    chooser.click();
    harness.run_steps(2);
    harness.get_by_label(choice).click();
    harness.run_steps(2);
}

/// Issue 35: "View ▸ follow m" sends the viewer a layout whose eye tracks the body's shape;
/// "the whole run" sends one that frames the run again (no tracking). The three layouts of
/// the run (loaded, followed, framed again) are in what the viewer was sent.
#[test]
fn the_view_follows_the_chosen_body_and_frames_the_run_again() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let shown = dir.path().join("shown.rrd");
    let sinks = Sinks::new(vec![Sinks::file(&shown).unwrap()]);
    let mut harness = harness(ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap());
    open_from_list(&mut harness, "spring.ron");
    harness.run_steps(2);
    choose_view(&mut harness, "the whole run", "follow m");
    choose_view(&mut harness, "follow m", "the whole run");
    harness.run_steps(4);
    drop(harness);
    let mut eyes = eye_tracking_in(&shown);
    eyes.sort();
    assert_eq!(eyes, [None, None, Some(tether_record::paths::body_shape("m"))], "the eyes sent: {eyes:?}");
}

/// Issue 35: while the embedded viewer is behind what it was sent (more than
/// `ViewerBacklog::LIMIT` messages left in its channel after a frame), the run waits for it and
/// says so; when the viewer has caught up the run goes on.
#[test]
fn the_run_waits_for_a_viewer_that_is_behind() {
    let dir = scenes_folder(&[("spring.ron", SPRING.as_str())]);
    let backlog = ViewerBacklog::default();
    let sinks = Sinks::with_viewer(Vec::new(), backlog.clone());
    let mut harness = harness(ControlPanel::new(sinks, Arc::new(|| {}), dir.path().to_path_buf()).unwrap());
    open_from_list(&mut harness, "spring.ron");
    backlog.set(ViewerBacklog::LIMIT + 1);
    harness.key_press(egui::Key::Space);
    until(&mut harness, "the run to say it waits", |p| p.status().is_some_and(|s| s.waiting_for_viewer));
    let waiting_at = harness.state().status().unwrap().time;
    std::thread::sleep(Duration::from_millis(300));
    until(&mut harness, "a status after the wait", |p| p.status().is_some_and(|s| s.waiting_for_viewer));
    assert_eq!(harness.state().status().unwrap().time, waiting_at, "no step while the viewer is behind");
    harness.get_by_label_contains("waiting for the viewer");

    backlog.set(ViewerBacklog::LIMIT);
    until(&mut harness, "the run to go on", |p| p.status().is_some_and(|s| !s.waiting_for_viewer && s.time > 0.1));
}
