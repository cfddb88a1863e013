//! One validation path, end to end: the same bad value set from the scene file (`tether check`),
//! a knob in the window (the open scene's tune, no window needed), a sweep case (`tether sweep`)
//! and a command-line flag (`tether record --dt`) is refused with the same message, naming the
//! coupling and the field; only where it is placed differs.

mod common;

use std::path::Path;
use std::process::{Command, Output};
use std::sync::Arc;
use tether::gui::open_scene::{KnobId, OpenScene};
use tether_scene::file::{CouplingDef, LawDef};

/// What each path must say of the spring's stiffness set to −5 N/m.
const STIFFNESS: &str = "coupling \"spring\": stiffness must be ≥ 0 N/m, got -5";
/// What each path must say of the time step set to −1 ms.
const TIME_STEP: &str = "dt must be > 0 s, got -0.001";

fn tether(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tether")).args(args).current_dir(dir).output().unwrap()
}

/// The one `error: ` line of `args` run in `dir`, which must fail with exit code 1.
fn error_line(args: &[&str], dir: &Path) -> String {
    let out = tether(args, dir);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(1), "tether {args:?} should fail: {stderr}");
    let lines: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error: ")).collect();
    assert_eq!(lines.len(), 1, "one error line: {stderr}");
    lines[0].trim_start_matches("error: ").to_string()
}

/// A folder with the GUI tests' spring scene as `spring.ron`, and a copy with `edit` applied as
/// `bad.ron`.
fn folder(edit: (&str, &str)) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let text = common::spring_scene_text("m");
    assert!(text.contains(edit.0), "{edit:?}");
    std::fs::write(dir.path().join("spring.ron"), &text).unwrap();
    std::fs::write(dir.path().join("bad.ron"), text.replacen(edit.0, edit.1, 1)).unwrap();
    dir
}

/// A grid sweep of `spring.ron` over one factor at `path` with the one value `value`.
fn sweep_of(dir: &Path, path: &str, value: &str) {
    let spec = format!(
        "Sweep(\n  scene: \"spring.ron\",\n  design: Grid,\n  factors: [Factor(path: \"{path}\", values: List([{value}]))],\n)"
    );
    std::fs::write(dir.join("sweep.ron"), spec).unwrap();
}

#[test]
fn a_negative_stiffness_reads_the_same_from_the_file_a_knob_and_a_sweep_case() {
    let dir = folder(("stiffness: 100.0", "stiffness: -5.0"));
    let from_file = error_line(&["check", "bad.ron"], dir.path());
    assert_eq!(from_file, format!("bad.ron:7:21: {STIFFNESS}"));
    // The knob: the open scene checks the edited draft as loading does, and keeps the reason.
    let loaded = OpenScene::load(&dir.path().join("spring.ron"), Arc::new(|| {})).unwrap();
    let mut open = loaded.scene;
    let CouplingDef::SpringDamper { law: LawDef::Linear { stiffness, .. }, .. } =
        &mut open.knobs.couplings.knobs_mut()[0].draft
    else {
        panic!("the spring scene's coupling is a linear spring")
    };
    *stiffness = -5.0;
    assert!(open.tune(KnobId::Coupling(0)).is_none(), "a negative stiffness must be refused");
    let reasons: Vec<&str> = open.knobs.couplings.knobs()[0].refusals.iter().map(|r| r.reason.as_str()).collect();
    assert_eq!(reasons, [STIFFNESS]);
    // The sweep case: the factor's value, placed in the base scene.
    sweep_of(dir.path(), "couplings.spring.law.stiffness", "-5.0");
    let from_case = error_line(&["sweep", "sweep.ron", "-o", "out"], dir.path());
    assert!(from_case.ends_with(&format!("spring.ron:7:21: {STIFFNESS}")), "{from_case}");
}

#[test]
fn a_negative_time_step_reads_the_same_from_the_file_a_sweep_case_and_the_flag() {
    let dir = folder(("dt: 0.001", "dt: -0.001"));
    assert_eq!(error_line(&["check", "bad.ron"], dir.path()), format!("bad.ron:3:5: {TIME_STEP}"));
    sweep_of(dir.path(), "dt", "-0.001");
    let from_case = error_line(&["sweep", "sweep.ron", "-o", "out"], dir.path());
    assert!(from_case.ends_with(&format!("spring.ron:3:5: {TIME_STEP}")), "{from_case}");
    let from_flag = error_line(&["record", "spring.ron", "-o", "never.rrd", "--dt=-0.001"], dir.path());
    assert_eq!(from_flag, format!("--dt: {TIME_STEP}"));
    assert!(!dir.path().join("never.rrd").exists());
}
