//! `tether study`: the measuring library against known orders, and the command's outputs.

mod common;

use std::process::Command;
use tether_analysis::study::closed_form::Oscillator;
use tether_analysis::study::{self, Outcome, Plan, Reference, Setting, StudyError};
use tether_physics::integrator::Integrator;
use tether_scene::file::AdaptiveDef;

fn spring_mass() -> tether_scene::Scene {
    tether_scene::load(&common::repo("scenes/spring_mass.ron")).unwrap()
}

/// The spring-mass-damper (ω = 10 rad/s, ζ = 0.05) for 2 s against its closed form: the
/// leapfrog's error halves with dt (its damper is first order), RK4's drops 16× per halving,
/// dopri45's follows its tolerance; energy errors follow; step counts are exact; a time step
/// beyond the leapfrog's stable limit (0.2 s > 2(√(1+ζ²) − ζ)/ω = 0.190 s) is reported as
/// diverged, not a crash.
#[test]
fn study_measures_orders_costs_and_divergence() {
    let plan = Plan {
        integrators: vec![Integrator::Leapfrog, Integrator::Rk4, Integrator::Dopri45],
        dts: vec![0.2, 4e-3, 2e-3, 1e-3],
        tolerances: vec![1e-5, 1e-8],
        duration: 2.0,
        sample_interval: 0.2,
        reference: Reference::ClosedForm,
    };
    let mut lines = 0;
    let result = study::run(&spring_mass(), &plan, |_| lines += 1).unwrap();
    assert_eq!(lines, 1 + 4 + 4 + 2, "one progress line for the reference and for each run");
    assert_eq!(result.runs.len(), 10);
    assert!(result.translates);
    let measures = |integrator: Integrator, setting: Setting| match &result
        .runs
        .iter()
        .find(|r| r.integrator == integrator && r.setting == setting)
        .unwrap()
        .outcome
    {
        Outcome::Finished(m) => *m,
        Outcome::Failed { message, .. } => panic!("{message}"),
    };
    let failed = &result
        .runs
        .iter()
        .find(|r| r.integrator == Integrator::Leapfrog && r.setting == Setting::Step(0.2))
        .unwrap()
        .outcome;
    assert!(matches!(failed, Outcome::Failed { time, .. } if *time < 2.0), "{failed:?}");
    // RK4's limit there is 0.29 s: stable, but 45 % of the swing off.
    assert!(measures(Integrator::Rk4, Setting::Step(0.2)).position_error_max > 1e-3);
    let leapfrog = [4e-3, 2e-3, 1e-3].map(|dt| measures(Integrator::Leapfrog, Setting::Step(dt)));
    let rk4 = [4e-3, 2e-3, 1e-3].map(|dt| measures(Integrator::Rk4, Setting::Step(dt)));
    for pair in leapfrog.windows(2) {
        let order = (pair[0].position_error_max / pair[1].position_error_max).log2();
        assert!((order - 1.0).abs() < 0.2, "leapfrog order {order}");
        assert_eq!(pair[1].steps, 2 * pair[0].steps);
    }
    for pair in rk4.windows(2) {
        let order = (pair[0].position_error_max / pair[1].position_error_max).log2();
        assert!((order - 4.0).abs() < 0.3, "rk4 order {order}");
    }
    assert_eq!(leapfrog[2].steps, 2000);
    // 1e-3 s: leapfrog 1.9e-5 m, rk4 6e-12 m of a 0.01 m swing; energy errors 4.5e-4, 2e-10.
    assert!(leapfrog[2].position_error_max < 3e-5 && rk4[2].position_error_max < 1e-11);
    assert!(leapfrog[2].energy_error < 1e-3 && rk4[2].energy_error < 1e-9);
    assert!(leapfrog[2].orientation_error_max == 0.0, "the mass is held against rotation");
    let (loose, tight) = (
        measures(Integrator::Dopri45, Setting::Tolerance(1e-5)),
        measures(Integrator::Dopri45, Setting::Tolerance(1e-8)),
    );
    assert!(tight.position_error_max < loose.position_error_max / 100.0, "{loose:?} {tight:?}");
    assert!(tight.steps > loose.steps && loose.cpu_per_second > 0.0);

    let csv = study::report::csv(&result);
    assert_eq!(csv.lines().count(), 11);
    assert!(csv.lines().nth(1).unwrap().starts_with("leapfrog,2e-1,,,,,,,,,,\"diverged at t = "), "{csv}");
    let table = study::report::markdown(&result);
    assert!(
        table.contains("| leapfrog | dt 1.0e-3 s | ") && table.contains("| leapfrog | dt 2.0e-1 s | diverged at t = "),
        "{table}"
    );
    assert!(table.contains("| dopri45 | rtol 1e-8 | "), "{table}");

    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("chart.png");
    study::chart::write(&result, &png).unwrap();
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert!(bytes.len() > 20_000, "a chart with text and curves: {} bytes", bytes.len());
}

/// Steps that do not divide the sample interval cannot be compared at common times: refused.
#[test]
fn study_refuses_steps_that_miss_the_sample_times() {
    let plan = Plan {
        integrators: vec![Integrator::Leapfrog],
        dts: vec![3e-3],
        tolerances: vec![],
        duration: 1.0,
        sample_interval: 0.01,
        reference: Reference::Adaptive { rtol: 1e-12 },
    };
    let error = study::run(&spring_mass(), &plan, |_| {}).unwrap_err();
    assert!(
        matches!(error, StudyError::Plan(ref m) if m.contains("3e-3 s does not divide the sample interval 1e-2 s")),
        "{error}"
    );
}

/// The command prints the table and writes the CSV, the Markdown and the chart.
#[test]
fn study_command_writes_its_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args([
            "study",
            common::repo("scenes/spring_mass.ron").to_str().unwrap(),
            "--integrators",
            "splitting,rk4",
            "--dts",
            "2e-3,1e-3",
            "--duration",
            "1",
            "-o",
        ])
        .arg(dir.path())
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(
        stdout.contains("## Integrator study: spring_mass.ron (1 s simulated)")
            && stdout.contains("| rk4 | dt 1.0e-3 s | "),
        "{stdout}"
    );
    for name in ["study.csv", "study.md", "study.png"] {
        assert!(dir.path().join(name).metadata().unwrap().len() > 100, "{name}");
    }
    let exact = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args([
            "study",
            common::repo("scenes/spring_mass.ron").to_str().unwrap(),
            "--integrators",
            "rk4",
            "--dts",
            "1e-3",
            "--duration",
            "1",
            "--reference",
            "closed-form",
            "-o",
        ])
        .arg(dir.path().join("exact"))
        .output()
        .unwrap();
    assert!(exact.status.success(), "{}", String::from_utf8_lossy(&exact.stderr));
    assert!(String::from_utf8_lossy(&exact.stdout).contains("Errors against the closed form of the damped oscillator"));
    let none = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["study", common::repo("scenes/chain.ron").to_str().unwrap(), "--reference", "closed-form", "-o"])
        .arg(dir.path().join("none"))
        .output()
        .unwrap();
    assert_eq!(none.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&none.stderr).contains("the scene has no closed form: it has 10 bodies"),
        "{}",
        String::from_utf8_lossy(&none.stderr)
    );
    let bad = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["study", common::repo("scenes/spring_mass.ron").to_str().unwrap(), "--reference", "euler:1e-3"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("unknown integrator `euler`"));
}

/// The spring-mass scene with damping `damping` [N·s/m] (ζ = damping / 20) and the mass started
/// at `x` [m] with speed `v` [m/s] along x.
fn spring_mass_with(damping: f64, x: f64, v: f64) -> tether_scene::Scene {
    let text = std::fs::read_to_string(common::repo("scenes/spring_mass.ron")).unwrap();
    let text = text
        .replace("damping: 1.0", &format!("damping: {damping:e}"))
        .replace("position: (1.01, 0.0, 0.0)", &format!("position: ({x:e}, 0.0, 0.0)"))
        .replace("support: Fixed", &format!("velocity: ({v:e}, 0.0, 0.0), support: Fixed"));
    assert!(text.contains(&format!("damping: {damping:e}")) && text.contains("velocity: ("));
    tether_scene::parse(&text, &common::repo("scenes/spring_mass.ron")).unwrap()
}

/// The closed form is the exact solution: under-, critically and over-damped (ζ = 0.05, 1, 2.5),
/// started off equilibrium and moving, it agrees with dopri45 at rtol 1e-12 to 1e-12 m over 5 s
/// (measured 9e-15 m: the integrator's own error on positions near 1 m; a wrong branch or sign
/// would be off by millimetres), and with the
/// spring_mass scene's comment, `x(t) = e^(−ζω0 t) [x0 cos ωd t + (ζω0 x0/ωd) sin ωd t]`.
#[test]
fn the_closed_form_is_the_exact_motion() {
    for (damping, v) in [(1.0, 0.3), (20.0, -0.3), (50.0, 0.3)] {
        let scene = spring_mass_with(damping, 1.01, v);
        let oscillator = Oscillator::of_scene(&scene).unwrap();
        let mut file = scene.file.clone();
        file.integrator = Integrator::Dopri45;
        file.adaptive = Some(AdaptiveDef { rtol: 1e-12, atol: 1e-15, max_step: None });
        let mut world = tether_scene::world_with_timing(&scene, &file).unwrap();
        let mut largest: f64 = 0.0;
        while world.time() < 5.0 - 1e-9 {
            world.step().unwrap();
            let exact = oscillator.at(world.time());
            largest = largest.max((world.state(0).position - exact.position).norm());
            let energy = world.energy();
            approx::assert_relative_eq!(exact.kinetic + exact.elastic, energy.kinetic + energy.elastic, epsilon = 1e-9);
        }
        assert!(largest < 1e-12, "k_d = {damping}: off the integrator by {largest} m");
    }
    let oscillator = Oscillator::of_scene(&spring_mass()).unwrap();
    let (omega, zeta, x0) = (10.0_f64, 0.05_f64, 0.01);
    let omega_d = omega * (1.0 - zeta * zeta).sqrt();
    for t in [0.0, 0.37, 1.0, 4.2] {
        let x =
            (-zeta * omega * t).exp() * (x0 * (omega_d * t).cos() + zeta * omega * x0 / omega_d * (omega_d * t).sin());
        approx::assert_relative_eq!(oscillator.at(t).position.x, 1.0 + x, epsilon = 1e-15);
    }
}

/// A scene that is no damped linear oscillator has no closed form: the study says why.
#[test]
fn a_scene_without_a_closed_form_is_refused() {
    let chain = tether_scene::load(&common::repo("scenes/chain.ron")).unwrap();
    let plan = Plan {
        integrators: vec![Integrator::Leapfrog],
        dts: vec![1e-3],
        tolerances: vec![],
        duration: 1.0,
        sample_interval: 0.1,
        reference: Reference::ClosedForm,
    };
    let error = study::run(&chain, &plan, |_| {}).unwrap_err().to_string();
    assert_eq!(error, "the scene has no closed form: it has 10 bodies, the closed form one");
    // The spring with a polynomial law, and a body free in two axes.
    let polynomial = spring_mass_with(1.0, 1.01, 0.0);
    let text = polynomial
        .text
        .replace("Linear(stiffness: 100.0, rest_length: 1.0)", "Polynomial(a: 100.0, c: 10.0, rest_length: 1.0)");
    let why = Oscillator::of_scene(&tether_scene::parse(&text, &polynomial.path).unwrap()).unwrap_err();
    assert_eq!(why, "coupling \"spring\" has no linear law");
    let text = polynomial.text.replace("translation: (false, true, true)", "translation: (false, false, true)");
    let why = Oscillator::of_scene(&tether_scene::parse(&text, &polynomial.path).unwrap()).unwrap_err();
    assert_eq!(why, "body \"mass\" must be free along exactly one axis, it is along 2");
}

/// The line-model study on the driven chain over 5 s (statistics over 2.5–5 s, where the
/// fairlead reaches 2 m away at t = 2.5 s): the quasi-static peak is the catenary's at
/// x = +2 m (54.15 kN, validation/moordyn's closed form), the dynamic lines' peaks approach
/// the reference's with every doubling of N, each run costs its CPU, and a scene without lines is refused.
#[test]
fn the_line_model_study_measures_peaks_against_the_finest_line() {
    let scene = tether_scene::load(&common::repo("scenes/chain_forced_surge.ron")).unwrap();
    let runner = tether_analysis::runner::Runner::new(std::num::NonZeroUsize::new(2).unwrap());
    let result = study::lines::run(&runner, &scene, 5.0, |_| {}).unwrap();
    let peak = |setting: study::lines::LineSetting| {
        result.runs.iter().find(|run| run.setting == setting).map(|run| run.lines[0].peak).unwrap()
    };
    let quasi_static = peak(study::lines::LineSetting::QuasiStatic);
    assert!((quasi_static / 54_150.0 - 1.0).abs() < 2e-3, "quasi-static peak {quasi_static} N");
    let reference = result.reference.lines[0].peak;
    let errors: Vec<f64> = study::lines::SEGMENTS
        .iter()
        .map(|&n| (peak(study::lines::LineSetting::Dynamic(n)) / reference - 1.0).abs())
        .collect();
    // Over these first seconds the start-up still rings (up to about 125 kN): the errors, 8.2,
    // 5.6, 3.8 and 2.1 % at N = 10 … 80, fall with every doubling.
    assert!(
        errors.windows(2).all(|pair| pair[1] < pair[0]) && errors[3] < 0.03,
        "peak errors at N = 10 … 80: {errors:?}"
    );
    assert!(result.runs.iter().all(|run| run.cpu_per_second > 0.0));
    let table = study::lines::markdown(&result);
    assert!(table.contains("| quasi-static | chain |") && table.contains("| dynamic N = 160 | chain |"), "{table}");
    let spring = spring_mass();
    assert!(matches!(study::lines::run(&runner, &spring, 1.0, |_| {}), Err(study::lines::LineStudyError::NoLines)));
}
