//! The sweep table driven headlessly with egui_kittest, on the real simulation thread: a sweep
//! with failed cases opened, sorted by a metric both ways, failures put first, and a failed
//! case loaded into the tuning panel with its values — running in the simulation thread.

mod common;

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable as _;
use std::path::Path;
use std::sync::Arc;
use std::time::Duration;
use tether::gui::panel::ControlPanel;
use tether::gui::stream::Sinks;
use tether::runner::Runner;
use tether::sweep::{self, Options, Plan};
use tether_physics::coupling::{CouplingKind, ElasticLaw};

/// Four cases of the GUI tests' oscillator (k = 100 N/m, 1 kg, released 0.1 m out): k ∈ {100,
/// 400} × dt ∈ {1 ms, 0.5 s}. At 0.5 s the leapfrog (limit 2/ω: 0.2 s, 0.1 s) diverges: cases
/// 1 and 3 fail, 0 and 2 pull 10 N and 40 N at most.
fn sweep_with_failures() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("spring.ron"), common::spring_scene_text("m")).unwrap();
    let spec = r#"Sweep(scene: "spring.ron", duration: 2.0, design: Grid, factors: [
        Factor(path: "couplings.spring.law.stiffness", values: List([100.0, 400.0])),
        Factor(path: "dt", values: List([1e-3, 0.5])),
    ])"#;
    std::fs::write(dir.path().join("sweep.ron"), spec).unwrap();
    let plan = Plan::load(&dir.path().join("sweep.ron"), tether::sweep::design::DEFAULT_MAX_CASES).unwrap();
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
            matches!(spring.law, ElasticLaw::Linear { stiffness, .. } if stiffness == 400.0),
            "{:?}",
            spring.law
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
