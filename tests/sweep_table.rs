//! The sweep table driven headlessly with egui_kittest, on the real simulation thread: a sweep
//! with failed cases opened, sorted by a metric both ways, failures put first, and a failed
//! case loaded into the tuning panel with its values — running in the simulation thread; a case
//! that varies the waves shows its wave height in the water panel and keeps it through an edit
//! of another water value.

mod common;

use egui_kittest::Harness;
use egui_kittest::kittest::NodeT as _;
use egui_kittest::kittest::Queryable as _;
use rerun::external::egui::{self, accesskit};
use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, Instant};
use tether::gui::panel::ControlPanel;
use tether::gui::stream::Sinks;
use tether_analysis::runner::Runner;
use tether_analysis::sweep::{self, Options, Plan};
use tether_physics::coupling::{CouplingKind, ElasticLaw};
use tether_physics::water::WaveSpec;
use tether_physics::world::World;

/// Longest wait for the simulation thread.
const PATIENCE: Duration = Duration::from_secs(20);

/// Four cases of the GUI tests' oscillator (k = 100 N/m, 1 kg, released 0.1 m out): k ∈ {100,
/// 400} × dt ∈ {1 ms, 0.5 s}. At 0.5 s the leapfrog (limit 2/ω: 0.2 s, 0.1 s) diverges: cases
/// 1 and 3 fail, 0 and 2 pull 10 N and 40 N at most.
fn sweep_with_failures() -> tempfile::TempDir {
    let spec = r#"Sweep(scene: "spring.ron", duration: 2.0, design: Grid, factors: [
        Factor(path: "couplings.spring.law.stiffness", values: List([100.0, 400.0])),
        Factor(path: "dt", values: List([1e-3, 0.5])),
    ])"#;
    run_sweep("spring.ron", &common::spring_scene_text("m"), spec)
}

/// Runs `plan_text` (a sweep of `scene`, saved as `name`) into `DIR/out`.
fn run_sweep(name: &str, scene: &str, plan_text: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join(name), scene).unwrap();
    std::fs::write(dir.path().join("sweep.ron"), plan_text).unwrap();
    let plan = Plan::load(&dir.path().join("sweep.ron"), tether_analysis::sweep::design::DEFAULT_MAX_CASES).unwrap();
    let options = Options {
        runner: Runner::new(std::num::NonZeroUsize::new(2).unwrap()),
        shard: None,
        resume: false,
        record: None,
    };
    sweep::run(&plan, &dir.path().join("out"), &options, |_| {}).unwrap();
    dir
}

fn harness(sweep: &Path) -> Harness<'static, ControlPanel> {
    let mut panel = ControlPanel::new(Sinks::none(), Arc::new(|| {}), sweep.to_path_buf()).unwrap();
    panel.open_sweep(sweep);
    Harness::builder()
        .with_size([1400.0, 400.0])
        .build_ui_state(|ui, panel: &mut ControlPanel| panel.sweep_ui(ui), panel)
}

fn order(harness: &Harness<'_, ControlPanel>) -> Vec<usize> {
    harness.state().sweep().expect("a sweep is open").order()
}

#[test]
fn the_table_sorts_puts_failures_first_and_loads_a_case() {
    let dir = sweep_with_failures();
    let mut harness = harness(&dir.path().join("out"));
    harness.run_steps(2);
    assert_eq!(order(&harness), [0, 1, 2, 3], "case order at first");
    harness.get_by_label_contains("4 of 4 cases have a row, 2 failed");

    harness.get_by_label("spring.tension_max_N").click();
    harness.run_steps(2);
    assert_eq!(order(&harness), [0, 2, 1, 3], "10 N, 40 N, then the cases without a value");
    harness.get_by_label("spring.tension_max_N ▲").click();
    harness.run_steps(2);
    assert_eq!(order(&harness), [2, 0, 1, 3], "40 N, 10 N: still the cases without a value last");

    harness.get_by_label("failures first").click();
    harness.run_steps(2);
    assert_eq!(order(&harness), [1, 3, 2, 0], "failures first, the rest as sorted");

    harness.get_by_label("#3").click();
    harness.run_steps(2);
    let panel = harness.state();
    let scene = panel.scene().expect("case 3 loaded");
    assert_eq!((scene.tuned.dt, scene.file.dt), (0.5, 0.001), "the case's dt runs; the file's is kept to revert to");
    let world = panel.simulation().snapshot(Duration::from_secs(20)).expect("the case runs");
    assert_eq!(world.dt(), 0.5);
    match &world.couplings()[0].kind {
        CouplingKind::SpringDamper(spring) => assert!(
            matches!(spring.law(), ElasticLaw::Linear { stiffness, .. } if *stiffness == 400.0),
            "{:?}",
            spring.law()
        ),
        kind => panic!("{kind:?}"),
    }
    assert!(
        panel.log().any(|l| l.text == "case 3 loaded: press Space to run it"),
        "{:?}",
        panel.log().collect::<Vec<_>>()
    );
}

#[test]
fn a_folder_that_is_not_a_sweep_is_refused_in_the_log() {
    let dir = tempfile::tempdir().unwrap();
    let mut panel = ControlPanel::new(Sinks::none(), Arc::new(|| {}), dir.path().to_path_buf()).unwrap();
    panel.open_sweep(dir.path());
    assert!(panel.sweep().is_none());
    let line = panel.log().last().expect("a line in the log");
    assert!(
        line.error && line.text == format!("{}: not a sweep directory (no sweep.json)", dir.path().display()),
        "{line:?}"
    );
}

/// A floating box in regular waves 1 m high (the file's height).
const FLOAT: &str = r#"Scene(dt: 0.01, water: Water(depth: 30.0, waves: Regular(height: 1.0, period: 6.0)), bodies: [
    Body(name: "float", master: Node(position: (0.0, 0.0, 0.0), mass: 1025.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
         shape: Box(size: (2.0, 2.0, 1.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0)))])"#;

/// The wave height [m] the running world's water has.
fn wave_height(world: &World) -> f64 {
    match world.system().water().expect("water").water.spec().waves {
        WaveSpec::Regular { height, .. } => height,
        other => panic!("{other:?}"),
    }
}

/// Runs frames until `done` holds for the panel, or fails after [`PATIENCE`].
fn until(harness: &mut Harness<'_, ControlPanel>, what: &str, done: impl Fn(&ControlPanel) -> bool) {
    let start = Instant::now();
    while !done(harness.state()) {
        assert!(
            start.elapsed() < PATIENCE,
            "timed out waiting for {what}; log: {:?}",
            harness.state().log().collect::<Vec<_>>()
        );
        harness.step();
    }
}

/// The value the knob labelled `label` shows.
fn knob_value(harness: &Harness<'_, ControlPanel>, label: &str) -> f64 {
    harness.get_by_label(label).accesskit_node().numeric_value().expect("a knob shows a number")
}

/// Types `value` into the knob labelled `label`, as a screen reader (AccessKit `SetValue`) would.
fn set_knob(harness: &mut Harness<'_, ControlPanel>, label: &str, value: f64) {
    let (target_node, target_tree) = harness.get_by_label(label).accesskit_node().locate();
    let request = accesskit::ActionRequest {
        action: accesskit::Action::SetValue,
        target_tree,
        target_node,
        data: Some(accesskit::ActionData::NumericValue(value)),
    };
    harness.event(egui::Event::AccessKitActionRequest(request));
    harness.run_steps(2);
}

/// A case of a sweep over the wave height opens with the case's height in the water knob (the
/// file's 1 m kept to revert to); an edit of the wave period keeps the case's 2.5 m in the
/// running water, and "Revert to file" brings back 1 m and the file's 6 s period.
#[test]
fn a_case_that_varies_the_wave_height_shows_it_and_keeps_it_through_another_water_edit() {
    let spec = r#"Sweep(scene: "float.ron", duration: 0.05, design: Grid, factors: [
        Factor(path: "water.waves.height", values: List([1.0, 2.5])),
    ])"#;
    let dir = run_sweep("float.ron", FLOAT, spec);
    let mut panel = ControlPanel::new(Sinks::none(), Arc::new(|| {}), dir.path().to_path_buf()).unwrap();
    panel.open_sweep(&dir.path().join("out"));
    let mut harness = Harness::builder()
        .with_size([440.0, 1100.0])
        .build_ui_state(|ui, panel: &mut ControlPanel| panel.ui(ui, None), panel);
    harness.state_mut().open_case(1);
    until(&mut harness, "case 1 to run", |p| p.status().is_some_and(|s| s.label.ends_with("case 1")));
    let world = |harness: &Harness<'_, ControlPanel>| harness.state().simulation().snapshot(PATIENCE).expect("a run");
    assert_eq!(wave_height(&world(&harness)), 2.5, "the case's height runs");
    assert_eq!(knob_value(&harness, "wave height H"), 2.5, "the water knob shows the case's height");

    set_knob(&mut harness, "wave period T", 7.0);
    until(&mut harness, "the water applied", |p| p.log().any(|l| l.text.starts_with("the water applied")));
    let running = world(&harness);
    let Some(WaveSpec::Regular { height, period, .. }) = running.system().water().map(|w| w.water.spec().waves) else {
        panic!("regular waves run")
    };
    assert_eq!((height, period), (2.5, 7.0), "the new period, the case's height");
    assert_eq!(knob_value(&harness, "wave height H"), 2.5);

    // The case's duration is the sweep's, not a knob: only the water goes back to the file.
    harness.get_by_label("Revert to file").click();
    until(&mut harness, "the revert", |p| p.scene().is_some_and(|s| s.tuned.water == s.file.water));
    until(&mut harness, "the file's waves in the running world", |p| {
        p.simulation().snapshot(PATIENCE).is_some_and(|w| wave_height(&w) == 1.0)
    });
    assert_eq!((knob_value(&harness, "wave height H"), knob_value(&harness, "wave period T")), (1.0, 6.0));
}
