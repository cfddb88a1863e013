//! Calibration (`tether fit`, docs/calibration.md): parameters recovered from records made by
//! Tether with seeded noise, by an ODE solved here, and by MoorDyn; honest intervals over many
//! noise draws; a combination the data cannot determine named; bad input refused in one line.

mod common;

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::fmt::Write as _;
use std::num::NonZeroUsize;
use std::path::{Path, PathBuf};
use std::process::Command;
use tether_analysis::fit::run::{self, Outcome};
use tether_analysis::fit::setup::Setup;
use tether_analysis::runner::Runner;

fn runner() -> Runner {
    Runner::new(NonZeroUsize::new(2).expect("2 > 0"))
}

/// A standard normal draw (Box–Muller).
fn normal(rng: &mut ChaCha8Rng) -> f64 {
    let u1: f64 = rng.random::<f64>().max(f64::MIN_POSITIVE);
    let u2: f64 = rng.random();
    (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
}

/// Writes `rows` (time, values…) as a CSV file with `header`.
fn write_csv(path: &Path, header: &str, rows: &[(f64, Vec<f64>)]) {
    let mut text = format!("{header}\n");
    for (t, values) in rows {
        let values: Vec<String> = values.iter().map(|v| format!("{v:.12e}")).collect();
        let _ = writeln!(text, "{t:.6},{}", values.join(","));
    }
    std::fs::write(path, text).unwrap();
}

/// Writes `samples` (t, x) as a CSV file `t,x` at `path`, each x with Gaussian noise of `sigma`
/// drawn from `seed` in sample order.
fn write_noisy_csv(path: &Path, samples: &[(f64, f64)], sigma: f64, seed: u64) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let rows: Vec<(f64, Vec<f64>)> = samples.iter().map(|(t, x)| (*t, vec![x + sigma * normal(&mut rng)])).collect();
    write_csv(path, "t,x", &rows);
}

/// Runs scene text `text` (labelled by `path`) and samples `probe(world)` every `every` steps.
fn simulate(
    text: &str,
    path: &Path,
    steps: usize,
    every: usize,
    probe: impl Fn(&tether_physics::world::World) -> f64,
) -> Vec<(f64, f64)> {
    let mut world = tether_scene::parse(text, path).unwrap_or_else(|e| panic!("{e}")).world;
    let mut samples = vec![(world.time(), probe(&world))];
    for step in 1..=steps {
        world.step().unwrap();
        if step % every == 0 {
            samples.push((world.time(), probe(&world)));
        }
    }
    samples
}

/// Writes a fit spec of `scene` and the spec's other fields `rest` to `spec`.
fn write_spec(spec: &Path, scene: &Path, rest: &str) {
    std::fs::write(spec, format!("Fit(\n    scene: \"{}\",\n{rest}\n)", scene.display())).unwrap();
}

fn fit(spec: &Path) -> Outcome {
    let setup = Setup::load(spec).unwrap_or_else(|e| panic!("{e}"));
    run::fit(&setup, &runner(), |_| {}).unwrap_or_else(|e| panic!("{e}"))
}

/// `spring_mass` with k = 120 N/m and c = 0.8 N·s/m (the scene has 100 and 1), its x sampled
/// at 100 Hz for 5 s, plus Gaussian noise of 1 % of the 0.01 m amplitude drawn from `seed`.
fn spring_record(dir: &Path, seed: u64) -> PathBuf {
    let scene = common::repo("scenes/spring_mass.ron");
    let text = std::fs::read_to_string(&scene)
        .unwrap()
        .replace("stiffness: 100.0", "stiffness: 120.0")
        .replace("damping: 1.0", "damping: 0.8");
    let samples = simulate(&text, &scene, 5000, 10, |w| w.state(0).position.x);
    let record = dir.join(format!("decay-{seed}.csv"));
    write_noisy_csv(&record, &samples, 1e-4, seed);
    let spec = dir.join(format!("fit-{seed}.ron"));
    write_spec(
        &spec,
        &scene,
        &format!(
            r#"    record: "{}",
    signals: [Signal(column: "x", of: Position("mass", X))],
    parameters: [
        Parameter(path: "couplings.spring.law.stiffness", from: 50.0, to: 200.0),
        Parameter(path: "couplings.spring.damping", from: 0.1, to: 10.0, scale: Log),
    ],"#,
            record.display()
        ),
    );
    spec
}

/// Check 1: k and c recovered within 0.5 % from a 1 %-noise record (seed 0); over 50 seeds the
/// fits are unbiased (their mean within 0.1 % of the truth) and the 95 % intervals contain the
/// truth in 90–99 % of the fits.
#[test]
fn spring_mass_recovered_with_honest_intervals() {
    let dir = tempfile::tempdir().unwrap();
    let truth = [120.0, 0.8];
    let mut covered = [0usize; 2];
    let mut covered_correlated = [0usize; 2];
    let mut sums = [0.0; 2];
    let seeds = 50;
    for seed in 0..seeds {
        let outcome = fit(&spring_record(dir.path(), seed));
        assert!(!outcome.partial(), "seed {seed}: {:?}", outcome.ending);
        for (j, p) in outcome.parameters.iter().enumerate() {
            let error = (p.value - truth[j]) / truth[j];
            if seed == 0 {
                assert!(error.abs() < 5e-3, "seed {seed}: {} = {} ({:+.3} %)", p.name, p.value, 100.0 * error);
            }
            sums[j] += p.value;
            let (lo, hi) = p.interval.unwrap_or_else(|| panic!("seed {seed}: {} undetermined", p.name));
            covered[j] += usize::from(lo <= truth[j] && truth[j] <= hi);
            let (lo, hi) = p.correlated_interval.unwrap_or_else(|| panic!("seed {seed}: {} undetermined", p.name));
            covered_correlated[j] += usize::from(lo <= truth[j] && truth[j] <= hi);
        }
        if seed == 0 {
            eprintln!(
                "seed 0: k = {} ± {:.3e}, c = {} ± {:.3e}, {} runs, {:.2} s",
                outcome.parameters[0].value,
                outcome.parameters[0].standard_error.unwrap_or(f64::NAN),
                outcome.parameters[1].value,
                outcome.parameters[1].standard_error.unwrap_or(f64::NAN),
                outcome.runs,
                outcome.wall_seconds
            );
        }
    }
    for j in 0..2 {
        let mean = sums[j] / seeds as f64;
        eprintln!("mean over {seeds} seeds: {mean} (truth {})", truth[j]);
        assert!(((mean - truth[j]) / truth[j]).abs() < 1e-3, "biased: mean {mean} against {}", truth[j]);
    }
    let total = covered[0] + covered[1];
    eprintln!(
        "95 % intervals containing the truth: k {}/{seeds}, c {}/{seeds}, together {total}/{}",
        covered[0],
        covered[1],
        2 * seeds
    );
    assert!((90..=99).contains(&total), "coverage {total} of {} intervals", 2 * seeds);
    // The intervals for a correlated residual are as honest on white noise (their lag window is
    // then 1–3 samples: the textbook covariance).
    let total = covered_correlated[0] + covered_correlated[1];
    eprintln!(
        "95 % intervals for a correlated residual containing the truth: k {}/{seeds}, c {}/{seeds}, together {total}/{}",
        covered_correlated[0],
        covered_correlated[1],
        2 * seeds
    );
    assert!((90..=99).contains(&total), "coverage {total} of {} correlated intervals", 2 * seeds);
}

/// The box's heave `z(t)` solved here, apart from Tether: wall-sided, so the buoyancy is
/// `ρ g A (d₀ − z)` exactly; the damper `c ż` in full; the drag `½ ρ C_d A |ż| ż` scaled by the
/// wetted fraction `(d₀ − z)/H` (PHYSICS.md §6); RK4 at 1e-4 s.
fn heave_ode(c: f64, cd: f64, until: f64, every: f64) -> Vec<(f64, f64)> {
    let (rho, g, area, height, draft, mass) = (1025.0, 9.80665, 200.0, 4.0, 2.0, 410_000.0);
    let acceleration = |z: f64, v: f64| {
        let wetted = ((draft - z) / height).clamp(0.0, 1.0);
        (rho * g * area * (draft - z) - mass * g - c * v - wetted * 0.5 * rho * cd * area * v.abs() * v) / mass
    };
    let h = 1e-4;
    let (mut z, mut v, mut t) = (0.5, 0.0, 0.0);
    let per_sample = (every / h).round() as usize;
    let mut samples = vec![(0.0, z)];
    let steps = (until / h).round() as usize;
    for step in 1..=steps {
        let (k1z, k1v) = (v, acceleration(z, v));
        let (k2z, k2v) = (v + 0.5 * h * k1v, acceleration(z + 0.5 * h * k1z, v + 0.5 * h * k1v));
        let (k3z, k3v) = (v + 0.5 * h * k2v, acceleration(z + 0.5 * h * k2z, v + 0.5 * h * k2v));
        let (k4z, k4v) = (v + h * k3v, acceleration(z + h * k3z, v + h * k3v));
        z += h / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        t += h;
        if step % per_sample == 0 {
            samples.push((t, z));
        }
    }
    samples
}

/// Check 2: a floating box's heave decay solved outside Tether with c = 6e4 N·s/m and C_d = 2.5:
/// both recovered within 2 % from the scene's 9.1e4 and 1.
#[test]
fn heave_decay_damping_recovered_from_an_independent_solution() {
    let dir = tempfile::tempdir().unwrap();
    let (c, cd) = (6.0e4, 2.5);
    let rows: Vec<(f64, Vec<f64>)> = heave_ode(c, cd, 30.0, 0.05).into_iter().map(|(t, z)| (t, vec![z])).collect();
    let record = dir.path().join("heave.csv");
    write_csv(&record, "time,heave", &rows);
    let spec = dir.path().join("heave.ron");
    write_spec(
        &spec,
        &common::repo("examples/calibration/heave_box.ron"),
        r#"    record: "heave.csv",
    signals: [Signal(column: "heave", of: Position("box", Z))],
    parameters: [
        Parameter(path: "bodies.box.hydro.linear_damping.2", from: 1e4, to: 1e6, scale: Log),
        Parameter(path: "bodies.box.hydro.drag.2", from: 0.1, to: 10.0, scale: Log),
    ],"#,
    );
    let outcome = fit(&spec);
    let (fitted_c, fitted_cd) = (outcome.parameters[0].value, outcome.parameters[1].value);
    eprintln!("heave decay: c = {fitted_c:.1} (truth {c}), C_d = {fitted_cd:.4} (truth {cd}), {} runs", outcome.runs);
    assert!(((fitted_c - c) / c).abs() < 0.02, "c = {fitted_c}");
    assert!(((fitted_cd - cd) / cd).abs() < 0.02, "C_d = {fitted_cd}");
}

/// The 95 % half-widths of a one-parameter fit, as `(white noise, AR(1)-widened, correlated)`:
/// the textbook one (the AR(1)-widened one over its widening), the reported one, and the one for
/// a correlated residual; each printed with its interval.
fn half_widths(outcome: &Outcome, label: &str) -> (f64, f64, f64) {
    let p = &outcome.parameters[0];
    let (lo, hi) = p.interval.unwrap_or_else(|| panic!("{label}: undetermined"));
    let (clo, chi) = p.correlated_interval.unwrap_or_else(|| panic!("{label}: undetermined"));
    let widened = 0.5 * (hi - lo);
    let white = widened / outcome.uncertainty.inflation;
    let correlated = 0.5 * (chi - clo);
    let c = &outcome.uncertainty.correlated;
    eprintln!(
        "{label}: fitted {:.5}; white noise ±{white:.5} ({:.5} … {:.5}); AR(1)-widened ×{:.2} (ρ₁ {:.3}) ±{widened:.5} ({lo:.5} … {hi:.5}); correlated ±{correlated:.5} ({clo:.5} … {chi:.5}; window {:.0} samples, ν {:.0}, t {:.3})",
        p.value,
        p.value - white,
        p.value + white,
        outcome.uncertainty.inflation,
        outcome.uncertainty.autocorrelation,
        c.bandwidths[0],
        c.degrees_of_freedom[0],
        c.t_quantiles[0],
    );
    (white, widened, correlated)
}

/// Check 3: MoorDyn v2's fairlead tension of the driven chain with C_dn = 1.6
/// (validation/calibration/): the fit recovers C_dn within 5 % from the tension alone, starting
/// from the scene's 2.4. The residual is the two codes' difference, periodic: the interval for a
/// correlated residual spans half the record's lags and is wider than the AR(1)-widened one, and
/// that wider than the white-noise one. (It still does not reach 1.6: the part of the codes'
/// difference that looks like a change of C_dn is taken up by the fit and leaves no trace in the
/// residual; docs/calibration.md.)
#[test]
fn moordyn_drag_coefficient_recovered_from_its_tension_record() {
    let outcome = fit(&common::repo("validation/calibration/chain_cdn.ron"));
    let cdn = outcome.parameters[0].value;
    eprintln!(
        "MoorDyn's C_dn 1.6: fitted {cdn:.4}, RMS {:.0} → {:.0} N, {} runs, {:.2} s",
        outcome.signals[0].rms_start, outcome.signals[0].rms_fitted, outcome.runs, outcome.wall_seconds
    );
    assert!(((cdn - 1.6) / 1.6).abs() < 0.05, "C_dn = {cdn}");
    assert!(outcome.signals[0].rms_fitted < 0.5 * outcome.signals[0].rms_start);
    let (white, widened, correlated) = half_widths(&outcome, "C_dn 1.6");
    assert!(white < widened && 2.0 * widened < correlated, "{white} {widened} {correlated}");
    let samples = outcome.signals[0].samples as f64;
    assert!(outcome.uncertainty.correlated.bandwidths[0] >= 0.45 * samples, "{:?}", outcome.uncertainty.correlated);
}

/// Check 3b, issue 48's case: the same fit to MoorDyn's record made with C_dn = 1.7
/// (validation/calibration/chain_cdn1.7.ron): 1.7 lies inside the interval for a correlated
/// residual, which is wider than the white-noise one.
#[test]
fn the_correlated_interval_holds_moordyns_drag_coefficient() {
    let outcome = fit(&common::repo("validation/calibration/chain_cdn1.7.ron"));
    let (white, _, correlated) = half_widths(&outcome, "C_dn 1.7");
    let cdn = outcome.parameters[0].value;
    assert!(((cdn - 1.7) / 1.7).abs() < 0.05, "C_dn = {cdn}");
    let (lo, hi) = outcome.parameters[0].correlated_interval.expect("determined (half_widths checked)");
    assert!(lo <= 1.7 && 1.7 <= hi, "C_dn 1.7 outside {lo} … {hi}");
    assert!(white < correlated, "{white} {correlated}");
}

/// Check 4: two springs in series seen only through the end mass: one direction undetermined
/// (k1 against k2, along (k1, −k2) in relative changes), neither with an interval, and the series
/// stiffness k1 k2 / (k1 + k2) they determine found.
#[test]
fn springs_in_series_are_reported_not_identifiable() {
    let dir = tempfile::tempdir().unwrap();
    let scene = common::here!("fixtures/fit/springs_in_series.ron");
    let text = std::fs::read_to_string(&scene).unwrap();
    let samples = simulate(&text, &scene, 6000, 20, |w| w.state(1).position.x);
    write_noisy_csv(&dir.path().join("end.csv"), &samples, 1e-3, 7);
    let spec = dir.path().join("series.ron");
    write_spec(
        &spec,
        &scene,
        r#"    record: "end.csv",
    signals: [Signal(column: "x", of: Position("mass", X))],
    parameters: [
        Parameter(path: "couplings.k1.law.stiffness", from: 100.0, to: 3000.0, scale: Log, start: 350.0),
        Parameter(path: "couplings.k2.law.stiffness", from: 100.0, to: 3000.0, scale: Log, start: 550.0),
    ],"#,
    );
    let outcome = fit(&spec);
    let (k1, k2) = (outcome.parameters[0].value, outcome.parameters[1].value);
    let series = k1 * k2 / (k1 + k2);
    eprintln!(
        "springs in series: k1 = {k1:.1}, k2 = {k2:.1}, series {series:.3}; undetermined {:?}",
        outcome.uncertainty.undetermined
    );
    assert!((series - 200.0).abs() < 2.0, "k1 k2/(k1 + k2) = {series}");
    assert_eq!(outcome.uncertainty.undetermined.len(), 1, "{:?}", outcome.uncertainty);
    assert_eq!(outcome.uncertainty.box_half_widths.len(), 1, "one determined combination");
    let direction = &outcome.uncertainty.undetermined[0];
    let norm = k1.hypot(k2);
    // Along ±(k1, −k2)/‖·‖: changing k1 by δ and k2 by −δ k2/k1 relative keeps k1 k2/(k1 + k2).
    let along = direction[0] * k1 / norm - direction[1] * k2 / norm;
    assert!(along.abs() > 0.999, "{direction:?} against ±({}, {})", k1 / norm, -k2 / norm);
    assert!(outcome.parameters.iter().all(|p| p.interval.is_none() && p.standard_error.is_none()));
}

/// A spec and record in a fresh folder for the bad-input checks: `spring_mass`, a CSV of x.
fn bad_input_folder() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("x.csv"), "t,x\n0.0,0.01\n0.5,0.0\n1.0,-0.005\n1.5,0.003\n").unwrap();
    dir
}

fn spec_text(record: &str, column: &str, of: &str, parameter: &str, extra: &str) -> String {
    format!(
        r#"Fit(
    scene: "{}",
    record: "{record}",
    signals: [Signal(column: "{column}", of: {of})],
    parameters: [{parameter}],{extra}
)"#,
        common::repo("scenes/spring_mass.ron").display()
    )
}

const K: &str = r#"Parameter(path: "couplings.spring.law.stiffness", from: 50.0, to: 200.0)"#;

/// Check 5: each bad input is one line naming the file and line, or the path; the CLI writes
/// nothing.
#[test]
fn bad_input_is_one_line_and_writes_nothing() {
    let dir = bad_input_folder();
    let x = r#"Position("mass", X)"#;
    let cases: Vec<(String, &str)> = vec![
        (spec_text("missing.csv", "x", x, K, ""), "no record file"),
        (spec_text("x.csv", "heave", x, K, ""), "has no column \"heave\""),
        (spec_text("x.csv", "x", r#"Position("buoy", X)"#, K, ""), "the scene has no body \"buoy\""),
        (spec_text("x.csv", "x", r#"Tension("rope")"#, K, ""), "the scene has no coupling \"rope\""),
        (spec_text("x.csv", "x", x, K, "\n    window: Window(from: 10.0, to: 20.0),"), "no time overlap"),
        (
            spec_text(
                "x.csv",
                "x",
                x,
                r#"Parameter(path: "couplings.spring.law.stiffness", from: 200.0, to: 50.0)"#,
                "",
            ),
            "must be below",
        ),
        (
            spec_text(
                "x.csv",
                "x",
                x,
                r#"Parameter(path: "couplings.spring.law.stiffness", from: -50.0, to: 200.0)"#,
                "",
            ),
            "stiffness",
        ),
        (
            spec_text("x.csv", "x", x, r#"Parameter(path: "couplings.spring.law.stifness", from: 1.0, to: 2.0)"#, ""),
            "stifness",
        ),
        (
            spec_text("x.csv", "x", x, r#"Parameter(path: "couplings.rope.damping", from: 1.0, to: 2.0)"#, ""),
            "no item named \"rope\"",
        ),
    ];
    for (text, expected) in &cases {
        let spec = dir.path().join("bad.ron");
        std::fs::write(&spec, text).unwrap();
        let error = Setup::load(&spec).map(drop).unwrap_err().to_string();
        assert!(error.contains(expected), "expected {expected:?} in: {error}");
        assert_eq!(error.lines().count(), 1, "{error}");
        assert!(error.contains("bad.ron:") || error.contains(".csv"), "placed: {error}");
    }
    // NaN and time going backwards in the record: the record's file and line.
    for (record, expected) in
        [("t,x\n0.0,0.01\n0.5,nan\n", "x.csv:3:"), ("t,x\n0.0,0.01\n0.5,0.0\n0.4,0.0\n", "x.csv:4:")]
    {
        std::fs::write(dir.path().join("x.csv"), record).unwrap();
        let spec = dir.path().join("bad.ron");
        std::fs::write(&spec, spec_text("x.csv", "x", x, K, "")).unwrap();
        let error = Setup::load(&spec).map(drop).unwrap_err().to_string();
        assert!(error.contains(expected), "expected {expected:?} in: {error}");
    }
    // The command line: exit 1, one line on stderr, no output folder, no fitted scene.
    let out = dir.path().join("out");
    let run = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["fit", dir.path().join("bad.ron").to_str().unwrap(), "-o", out.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(stderr.trim().lines().count(), 1, "{stderr}");
    assert!(!out.exists());
    assert!(!common::repo("scenes/spring_mass.fitted.ron").exists());
}

/// The command line end to end on a noisy spring record: the report, a chart, the recording, the
/// JSON, and the fitted scene, which loads and holds the fitted values with the scene's comments.
#[test]
fn the_command_writes_the_report_and_the_fitted_scene() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spring_record(dir.path(), 3);
    let out = dir.path().join("out");
    let scene_out = dir.path().join("spring_mass.fitted.ron");
    let run = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args([
            "fit",
            spec.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--json",
            "--scene-out",
            scene_out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let report: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();
    assert_eq!(report["status"], "converged");
    let k = report["parameters"][0]["value"].as_f64().unwrap();
    assert!((k - 120.0).abs() < 0.6, "{k}");
    let interval = report["parameters"][0]["interval_95"].as_array().unwrap();
    assert!(interval[0].as_f64().unwrap() < k && k < interval[1].as_f64().unwrap());
    assert!(report["iterations"].as_array().unwrap().len() >= 2);
    for file in ["report.md", "report.json", "fitted.rrd", "plots/x.png"] {
        let path = out.join(file);
        assert!(path.metadata().map(|m| m.len() > 100).unwrap_or(false), "{}", path.display());
    }
    // The recording of the fitted run holds the record beside the model, in a plot of their own.
    let recording = tether_analysis::fit::measured::Record::read(&out.join("fitted.rrd"), None).unwrap();
    let record = recording.series("plots/fit/x/record/record").unwrap();
    assert_eq!(record.times.len(), 501);
    let model = recording.series("plots/fit/x/model/model").unwrap();
    assert_eq!(model.times.len(), 5001, "every world step of the fitted run");
    assert!(recording.series("world/bodies/mass/x").is_ok());
    let fitted = std::fs::read_to_string(&scene_out).unwrap();
    assert!(fitted.starts_with("// Fitted by `tether fit`"), "{fitted}");
    assert!(fitted.contains("// Spring-mass-damper: m = 1 kg"), "the scene's own comments are kept");
    tether_scene::parse(&fitted, &scene_out).unwrap_or_else(|e| panic!("{e}"));
    let stiffness =
        fitted.split("stiffness: ").nth(1).and_then(|s| s.split(',').next()).and_then(|s| s.trim().parse::<f64>().ok());
    assert!(stiffness.is_some_and(|s| (s - k).abs() < 1e-4 * k), "{stiffness:?} against {k}");
}

/// A fit to another recording: `spring_mass` with k = 120 N/m recorded by `tether record`, the
/// scene (k = 100) fitted to its `world/bodies/mass/x` (stored as f32, so 1e-7 relative).
#[test]
fn a_recording_is_a_record() {
    let dir = tempfile::tempdir().unwrap();
    let scene = common::repo("scenes/spring_mass.ron");
    let stiff = dir.path().join("stiff.ron");
    std::fs::write(&stiff, std::fs::read_to_string(&scene).unwrap().replace("stiffness: 100.0", "stiffness: 120.0"))
        .unwrap();
    let recording = dir.path().join("stiff.rrd");
    let run = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["record", stiff.to_str().unwrap(), "-o", recording.to_str().unwrap(), "--log-hz", "100"])
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let spec = dir.path().join("fit.ron");
    write_spec(
        &spec,
        &scene,
        r#"    record: "stiff.rrd",
    signals: [Signal(column: "world/bodies/mass/x", of: Position("mass", X))],
    parameters: [Parameter(path: "couplings.spring.law.stiffness", from: 50.0, to: 200.0)],"#,
    );
    let outcome = fit(&spec);
    let k = outcome.parameters[0].value;
    eprintln!("fitted to a recording: k = {k} (truth 120), {} samples", outcome.signals[0].samples);
    assert!((k - 120.0).abs() < 1e-3 * 120.0, "k = {k}");
    assert_eq!(outcome.signals[0].samples, 501);
}

/// A trial the model cannot run (a spring so stiff that the step diverges) is an error with the
/// health check's message, which the solver takes as a rejected step (`solver` tests), never a
/// panic or a NaN residual.
#[test]
fn a_diverging_trial_is_refused_with_its_message() {
    let dir = bad_input_folder();
    let spec = dir.path().join("fit.ron");
    std::fs::write(
        &spec,
        spec_text(
            "x.csv",
            "x",
            r#"Position("mass", X)"#,
            r#"Parameter(path: "couplings.spring.law.stiffness", from: 50.0, to: 1e9, scale: Log)"#,
            "",
        ),
    )
    .unwrap();
    let setup = Setup::load(&spec).unwrap_or_else(|e| panic!("{e}"));
    let (results, runs) = setup.model.evaluate(&[vec![100.0], vec![1e9]], &runner());
    assert_eq!(runs, 2);
    assert!(results[0].as_ref().is_ok_and(|r| r.iter().all(|x| x.is_finite())));
    let refused = results[1].as_ref().unwrap_err();
    assert!(refused.contains("diverged") || refused.contains("stable"), "{refused}");
}

/// Ctrl-C (SIGINT) during a fit: the best point so far is written as the result, said to be
/// partial, with exit code 130.
#[test]
fn ctrl_c_keeps_the_best_point_as_a_partial_result() {
    use std::io::{BufRead, BufReader};
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let scene_out = dir.path().join("chain.fitted.ron");
    let mut child = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args([
            "fit",
            common::repo("validation/calibration/chain_cdn.ron").to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--scene-out",
            scene_out.to_str().unwrap(),
            "--jobs",
            "1",
        ])
        .stderr(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let stderr = BufReader::new(child.stderr.take().unwrap());
    let mut seen = Vec::new();
    for line in stderr.lines() {
        let line = line.unwrap();
        let first_iteration = line.starts_with("iteration 1:");
        seen.push(line);
        if first_iteration {
            // SAFETY: kill with a valid pid and signal has no memory effects.
            unsafe { libc::kill(child.id() as i32, libc::SIGINT) };
            break;
        }
    }
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(130), "{seen:?}");
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    assert_eq!(report["status"], "partial");
    assert_eq!(report["ending"], "cancelled");
    let fitted = std::fs::read_to_string(&scene_out).unwrap();
    assert!(fitted.lines().next().is_some_and(|l| l.contains("PARTIAL")), "{fitted}");
}

/// A fit is deterministic: the same spec and record give the same values, bit for bit, on one
/// thread and on two.
#[test]
fn the_same_fit_on_one_and_two_threads_is_the_same() {
    let dir = tempfile::tempdir().unwrap();
    let spec = spring_record(dir.path(), 11);
    let setup = Setup::load(&spec).unwrap_or_else(|e| panic!("{e}"));
    let one = run::fit(&setup, &Runner::new(NonZeroUsize::MIN), |_| {}).unwrap();
    let two = run::fit(&setup, &runner(), |_| {}).unwrap();
    assert_eq!(one.values, two.values);
    assert_eq!(one.runs, two.runs);
    let bits = |o: &Outcome| o.parameters.iter().map(|p| p.standard_error.map(f64::to_bits)).collect::<Vec<_>>();
    assert_eq!(bits(&one), bits(&two));
}

/// An initial condition and a time shift fitted with the knobs: `spring_mass` let go from
/// 1.012 m (the scene: 1.01) recorded on a clock 0.05 s behind the model's (the record at t shows
/// the model at t + 0.05), with 1e-5 m of noise: both found within 4 standard errors (one draw:
/// the 95 % coverage is the 50-seed test's), and to 1e-4 m and 0.25 ms.
#[test]
fn an_initial_offset_and_a_time_shift_are_parameters_too() {
    let dir = tempfile::tempdir().unwrap();
    let scene = common::repo("scenes/spring_mass.ron");
    let text =
        std::fs::read_to_string(&scene).unwrap().replace("position: (1.01, 0.0, 0.0)", "position: (1.012, 0.0, 0.0)");
    let samples = simulate(&text, &scene, 5000, 10, |w| w.state(0).position.x);
    // The record's clock: sample k of the model (t_k) is the record's t_k − 0.05.
    let late: Vec<(f64, f64)> =
        samples.iter().filter(|(t, _)| *t >= 0.05 - 1e-9).map(|(t, x)| (t - 0.05, *x)).collect();
    write_noisy_csv(&dir.path().join("late.csv"), &late, 1e-5, 5);
    let spec = dir.path().join("late.ron");
    write_spec(
        &spec,
        &scene,
        r#"    record: "late.csv",
    signals: [Signal(column: "x", of: Position("mass", X))],
    parameters: [Parameter(path: "bodies.mass.master.position.0", from: 1.005, to: 1.02)],
    time_shift: Shift(from: 0.0, to: 0.1, start: 0.02),"#,
    );
    let outcome = fit(&spec);
    let (x0, shift) = (outcome.parameters[0].value, outcome.parameters[1].value);
    eprintln!("initial position {x0} (truth 1.012), time shift {shift} s (truth 0.05)");
    assert!((x0 - 1.012).abs() < 1e-4, "x0 = {x0}");
    assert!((shift - 0.05).abs() < 2.5e-4, "shift = {shift}");
    for (p, truth) in outcome.parameters.iter().zip([1.012, 0.05]) {
        let error = p.standard_error.unwrap_or_else(|| panic!("{} undetermined", p.name));
        assert!((p.value - truth).abs() < 4.0 * error, "{}: {} ± {error} against {truth}", p.name, p.value);
    }
}
