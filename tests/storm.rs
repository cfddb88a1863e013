//! `tether storm` (PHYSICS.md §10, docs/design-loads.md, check 5): the MPM of a Gaussian process
//! against `σ √(2 ln N)`, the command end to end (its table, CSV, Parquet and chart agreeing with
//! the sweep rows it fitted) and its refusals.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use tether_analysis::storm::extremes::{Gumbel, gaussian_most_probable_maximum};
use tether_physics::water::spectrum::Jonswap;

fn tether(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tether")).args(args).output().expect("the tether binary runs")
}

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// A linear spring-mass (natural period 1 s, above the sea's band, 5 % of critical damping: it follows the waves'
/// force) in a narrow-band JONSWAP sea (Hs 2 m, Tp 8 s, γ = 7, 200 components): its response
/// `x(t) = Σ a_n |H_n| cos(ω_n t + φ_n + arg H_n)`, `H = 1/(ω_n² − ω² + 2iζω_nω)` per unit force
/// per unit mass, is the exact linear response, Gaussian (many components of comparable size).
/// The largest x of each of 40 seeds of 3 hours (sampled 32 times a zero-crossing period),
/// fitted by maximum likelihood: its MPM against `σ √(2 ln N)` (N the zero up-crossings,
/// `3 h / T_z`, `T_z = 2π √(m₀/m₂)` of the response spectrum: Rice's rate of high
/// up-crossings) within 3 %: it is 2.7 % below (sampling 64 times a period moves it by 0.06 %;
/// the rest is the fit of 40 maxima and the synthesis: a sum of harmonics of fixed amplitudes
/// has a lighter tail than a Gaussian's). (The response is computed in closed form, not integrated: this
/// checks the storm statistics, as the wave tests check the sea.)
#[test]
fn the_mpm_of_a_gaussian_response_is_sigma_root_two_log_n() {
    let (omega_n, zeta, duration) = (2.0 * PI, 0.05, 10_800.0);
    let sea = Jonswap { significant_height: 2.0, peak_period: 8.0, gamma: 7.0 };
    let response = |omega: f64| {
        let (re, im) = (omega_n * omega_n - omega * omega, 2.0 * zeta * omega_n * omega);
        (1.0 / (re * re + im * im).sqrt(), -im.atan2(re))
    };
    let (mut m0, mut m2) = (0.0, 0.0);
    let mut maxima = Vec::new();
    let mut step = 0.0;
    for seed in 0..40 {
        let components = sea.components(200, 0.0, seed, None, 9.80665);
        let lines: Vec<(f64, f64, f64)> = components
            .iter()
            .map(|c| {
                let (gain, phase) = response(c.frequency);
                (c.amplitude * gain, c.frequency, c.phase + phase)
            })
            .collect();
        if seed == 0 {
            m0 = lines.iter().map(|(a, _, _)| 0.5 * a * a).sum();
            m2 = lines.iter().map(|(a, w, _)| 0.5 * a * a * w * w).sum();
            step = 2.0 * PI * (m0 / m2).sqrt() / 32.0;
        }
        let samples = (duration / step) as usize;
        let largest = (0..samples)
            .map(|i| {
                let t = i as f64 * step;
                lines.iter().map(|(a, w, phi)| a * (w * t + phi).cos()).sum::<f64>()
            })
            .fold(0.0, f64::max);
        maxima.push(largest);
    }
    let sigma = m0.sqrt();
    let crossings = duration / (2.0 * PI * (m0 / m2).sqrt());
    let expected = gaussian_most_probable_maximum(sigma, crossings);
    let fit = Gumbel::by_maximum_likelihood(&maxima).expect("40 maxima");
    let mpm = fit.most_probable_maximum();
    println!("MPM {mpm} against σ√(2 ln N) = {expected}");
    assert!(
        (mpm / expected - 1.0).abs() < 0.03,
        "MPM {mpm} against σ√(2 ln N) = {expected} (σ {sigma}, N {crossings})"
    );
}

/// A short storm of the storm example: the statistics are those of the rows the sweep wrote (the
/// same maxima), the design check is API's figure, and the four files are there.
#[test]
fn a_storm_writes_its_statistics_from_its_seeds_rows() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let out = dir.path().join("storm");
    let scene = repo("scenes/buoy_in_a_storm.ron");
    let run = tether(&[
        "storm",
        scene.to_str().expect("UTF-8"),
        "--hours",
        "0.01",
        "--seeds",
        "3",
        "--warmup",
        "20",
        "--jobs",
        "2",
        "-o",
        out.to_str().expect("UTF-8"),
    ]);
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "{}\n{stdout}", String::from_utf8_lossy(&run.stderr));
    for file in ["storm.md", "storm.csv", "storm.parquet", "storm.png", "results.csv"] {
        assert!(out.join(file).exists(), "{file} written");
    }
    // The seeds' maxima in the sweep's rows against the storm's CSV.
    let results = std::fs::read_to_string(out.join("results.csv")).expect("results.csv");
    let header: Vec<&str> = results.lines().next().expect("a header").split(',').collect();
    let column = header.iter().position(|h| *h == "mooring2.storm_tension_max_N").expect("the column");
    let mut from_rows: Vec<f64> =
        results.lines().skip(1).map(|l| l.split(',').nth(column).expect("a cell").parse().expect("a number")).collect();
    let storm = std::fs::read_to_string(out.join("storm.csv")).expect("storm.csv");
    let line = storm.lines().find(|l| l.starts_with("mooring2.tension,")).expect("mooring2's row");
    let cells: Vec<&str> = line.split(',').collect();
    let mut maxima: Vec<f64> = cells[12].split(';').map(|v| v.parse().expect("a number")).collect();
    from_rows.sort_by(f64::total_cmp);
    maxima.sort_by(f64::total_cmp);
    assert_eq!(maxima, from_rows);
    let fit = Gumbel::by_maximum_likelihood(&maxima).expect("three maxima");
    let mpm: f64 = cells[8].parse().expect("the MPM");
    assert_eq!(mpm, fit.most_probable_maximum());
    let safety: f64 = cells[10].parse().expect("the check's figure");
    assert!((safety - 1_188_000.0 / mpm).abs() < 1e-9 * safety, "SF {safety}");
    assert!(stdout.contains("mooring2 tension [kN]: MPM"), "{stdout}");
}

/// Bad requests: one line each, nothing run.
#[test]
fn a_bad_storm_is_refused_in_one_line() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let out = dir.path().join("storm");
    let out = out.to_str().expect("UTF-8");
    let storm = repo("scenes/buoy_in_a_storm.ron");
    let calm = repo("scenes/moored_buoy.ron");
    let cases: [(Vec<&str>, &str); 3] = [
        (vec![storm.to_str().expect("UTF-8"), "--seeds", "1"], "--seeds must be at least 2"),
        (vec![storm.to_str().expect("UTF-8"), "--hours=-1"], "--hours must be > 0 h, got -1"),
        (vec![calm.to_str().expect("UTF-8")], "nothing in the scene is random"),
    ];
    for (args, expected) in cases {
        let mut all = vec!["storm"];
        all.extend(args);
        all.extend(["-o", out]);
        let run = tether(&all);
        let stderr = String::from_utf8_lossy(&run.stderr);
        let error: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error")).collect();
        assert!(!run.status.success() && error.len() == 1 && error[0].contains(expected), "{expected}: {stderr}");
        assert!(!Path::new(out).exists(), "nothing written");
    }
}
