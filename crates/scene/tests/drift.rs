//! Second-order wave drift (PHYSICS.md §10): the `.8`/`.9` reader on hand-made files (scaling,
//! headings, missing frequencies, which file is read, the refusals), the shipped Capytaine
//! cylinder's far-field drift against the short-wave limit, a moored body's mean offset in
//! regular waves against `a² D(ω)/k`, and a drift scene's refusals.

use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use tether_physics::potential::{Coefficients, DriftSource};
use tether_scene::wamit::{Scale, read};
use tether_test_support::repo;

const SCALE: Scale = Scale { density: 1000.0, gravity: 10.0, length: 2.0 };

/// ω = 1 and ω = 2 rad/s as WAMIT periods.
const PER_1: &str = "6.283185307179586";
const PER_2: &str = "3.141592653589793";

/// The smallest `.1` and `.3` that read: the radiation at two frequencies, one heading.
fn first_order() -> [(&'static str, String); 2] {
    let radiation =
        ["-1 1 1 3.0", " 0 1 1 2.0", &format!("{PER_2} 1 1 2.2 0.3"), &format!("{PER_1} 1 1 2.5 0.1")].join("\n");
    let excitation = [format!("{PER_1} 0.0 1 9 9 1.5 -0.5"), format!("{PER_2} 0.0 1 9 9 1.0 0.25")].join("\n");
    [("1", radiation), ("3", excitation)]
}

/// Writes the first-order files and each `(ext, text)` of `drift` as `body.EXT` into a fresh
/// directory; returns it and the stem.
fn files(drift: &[(&str, &str)]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let stem = dir.path().join("body");
    let first = first_order();
    let all = first.iter().map(|(e, t)| (*e, t.as_str())).chain(drift.iter().copied());
    for (extension, text) in all {
        std::fs::write(dir.path().join(format!("body.{extension}")), text).expect("written");
    }
    (dir, stem)
}

fn read_ok(stem: &Path) -> Coefficients {
    read(stem, SCALE).unwrap_or_else(|e| panic!("{e}"))
}

/// `.8` rows `PER β₁ β₂ I |F| phase Re Im`: `D = Re ρ g L` for a force, `Re ρ g L²` for a
/// moment; lowest frequency first; a heading pair β₁ ≠ β₂ (a spread sea's) not read; a
/// frequency a heading lacks is 0 there.
#[test]
fn the_momentum_file_is_scaled_per_dof_and_sorted_by_frequency() {
    let text = [
        format!("{PER_2} 0.0 0.0 1 0.8 180.0 -0.8 0.0"),
        format!("{PER_2} 0.0 0.0 6 0.1 0.0 0.1 0.0"),
        format!("{PER_1} 0.0 0.0 1 0.3 0.0 0.3 0.0"),
        format!("{PER_1} 0.0 45.0 1 9.0 0.0 9.0 0.0"),
        format!("{PER_1} 90.0 90.0 2 0.5 0.0 0.5 0.0"),
    ]
    .join("\n");
    let (_dir, stem) = files(&[("8", &text)]);
    let coefficients = read_ok(&stem);
    let drift = coefficients.mean_drift().expect("the .8 was read");
    assert_eq!(drift.source(), DriftSource::Momentum);
    assert_eq!(drift.frequencies(), &[1.0, 2.0]);
    assert_eq!(drift.headings(), &[0.0, PI / 2.0]);
    let rho_g_l = 1000.0 * 10.0 * 2.0;
    let at = |omega: f64, heading: f64| drift.coefficient(omega, heading).expect("inside");
    assert_eq!(at(1.0, 0.0)[0], 0.3 * rho_g_l, "surge at ω = 1, β = 0; the β₂ = 45° row not read");
    assert_eq!(at(2.0, 0.0)[0], -0.8 * rho_g_l);
    assert_eq!(at(2.0, 0.0)[5], 0.1 * rho_g_l * 2.0, "a moment takes L²");
    assert_eq!(at(1.0, PI / 2.0)[1], 0.5 * rho_g_l);
    assert_eq!(at(2.0, PI / 2.0)[1], 0.0, "ω = 2 is missing at 90°: zero");
    // Half way in ω and in β.
    let middle = at(1.5, PI / 4.0);
    assert!((middle[0] - 0.5 * (0.5 * (0.3 - 0.8) * rho_g_l)).abs() < 1e-9, "{middle}");
}

/// A `.9` is read when there is no `.8`, and said to be; with both the `.8` is; seven columns
/// (`PER β I …`, one heading per row) read as `β₁ = β₂`; without either, no drift.
#[test]
fn the_pressure_file_is_read_only_without_a_momentum_file() {
    let seven = format!("{PER_1} 0.0 1 0.4 0.0 0.4 0.0\n{PER_2} 0.0 1 0.6 0.0 0.6 0.0");
    let eight = format!("{PER_1} 0.0 0.0 1 0.3 0.0 0.3 0.0");
    let (_dir, stem) = files(&[("9", &seven)]);
    let pressure = read_ok(&stem);
    let drift = pressure.mean_drift().expect("the .9 was read");
    assert_eq!(drift.source(), DriftSource::Pressure);
    assert_eq!(drift.coefficient(2.0, 0.0).expect("inside")[0], 0.6 * 2.0e4);
    let (_dir, stem) = files(&[("9", &seven), ("8", &eight)]);
    assert_eq!(read_ok(&stem).mean_drift().expect("read").source(), DriftSource::Momentum);
    let (_dir, stem) = files(&[]);
    assert!(read_ok(&stem).mean_drift().is_none());
}

/// Every refusal is one line at the drift file's line and column.
#[test]
fn a_bad_drift_file_is_refused_at_its_line() {
    let cases = [
        (format!("{PER_1} 0.0 0.0 1 0.3 0.0 0.3 0.0 9"), "body.8:1: expected PER β₁ β₂ I |F| phase Re Im"),
        // Seven columns are `PER β I |F| phase Re Im`: an eight-column row cut short reads its
        // β₂ as the dof.
        (format!("{PER_1} 0.0 0.0 1 0.3 0.0 0.3"), "body.8:1:23: dof index must be an integer from 1 to 6"),
        (format!("{PER_1} 0.0 0.0 1 0.3 0.0 nan 0.0"), "body.8:1:"),
        ("0 0.0 0.0 1 0.3 0.0 0.3 0.0".to_string(), "body.8:1:1: the mean drift is defined at finite periods only"),
        (format!("{PER_1} 0.0 0.0 7 0.3 0.0 0.3 0.0"), "body.8:1:"),
        (format!("{PER_1} 0.0 45.0 1 0.3 0.0 0.3 0.0"), "no row with β₁ = β₂"),
        (String::new(), "body.8: the file is empty"),
    ];
    for (text, expected) in cases {
        let (_dir, stem) = files(&[("8", &text)]);
        let error = read(&stem, SCALE).expect_err(&text).to_string();
        assert!(error.contains(expected) && !error.contains('\n'), "{text:?}: {error}");
    }
}

/// The shipped cylinder's files' stem.
fn cylinder() -> PathBuf {
    repo("validation/potential-flow/cylinder/cylinder")
}

/// The project cylinder (R 3 m, draft 6 m; `validation/potential-flow/drift.py`, Capytaine
/// 3.0's far-field drift): its surge drift tends to the short-wave limit of a vertical
/// surface-piercing cylinder, `D₁ → (2/3) ρ g R` (Faltinsen, Sea Loads), within 5 % where
/// kR ≥ 3, and to 0 in long waves; an axisymmetric body has no yaw drift.
#[test]
fn the_cylinders_surge_drift_tends_to_the_short_wave_limit() {
    let stem = cylinder();
    let scale = Scale { density: 1025.0, gravity: 9.80665, length: 1.0 };
    let coefficients = read(&stem, scale).expect("the shipped cylinder");
    let drift = coefficients.mean_drift().expect("its .8");
    let (radius, rho_g) = (3.0, 1025.0 * 9.80665);
    let limit = 2.0 / 3.0 * rho_g * radius;
    let short: Vec<f64> = drift.frequencies().iter().copied().filter(|w| w * w / 9.80665 * radius >= 3.0).collect();
    assert!(!short.is_empty(), "the file reaches kR = 3: {:?}", drift.frequencies());
    for omega in short {
        let d = drift.coefficient(omega, 0.0).expect("heading 0");
        println!(
            "ω {omega:.3} rad/s, kR {:.2}: D₁/(ρgR) = {:.4}",
            omega * omega / 9.80665 * radius,
            d[0] / (rho_g * radius)
        );
        assert!((d[0] / limit - 1.0).abs() < 0.05, "ω {omega}: {} against {limit}", d[0]);
        assert!(d[5].abs() < 1e-3 * d[0] * radius, "yaw {}", d[5]);
    }
    let longest = drift.frequencies()[0];
    let d = drift.coefficient(longest, 0.0).expect("heading 0");
    assert!(d[0].abs() < 0.02 * limit, "at ω = {longest}: {} against the limit {limit}", d[0]);
}

/// The cylinder of `validation/potential-flow/cylinder.ron` held in surge by a horizontal
/// spring of `stiffness` [N/m] (1 km long, at G: heave Z tilts it and pulls G back by `Z²/(4L)`,
/// 1.8 cm at L = 100 m in the cylinder's heave resonance near 1.2 rad/s) with a damper
/// (a third of critical in surge: the slow surge settles in a few minutes; a damper to the
/// world, not Morison's linear damping, which acts on the velocity relative to the waves' and
/// so takes a Stokes drift of its own), with `potential`'s `Wamit` fields in the water of
/// `water`.
fn moored_cylinder(water: &str, potential: &str, stiffness: f64) -> String {
    format!(
        "Scene(dt: 0.02, integrator: rk4, water: {water}, bodies: [Body(name: \"cylinder\",
            master: Node(position: (0.0, 0.0, -4.0), mass: 172771.98917748,
                         inertia: Inertia(xx: 907052.94318179, yy: 907052.94318179, zz: 777473.95129867)),
            shape: Cylinder(radius: 3.0, length: 8.0, center: (0.0, 0.0, 2.0)),
            hydro: Hydro(potential: Wamit({potential})))],
         couplings: [SpringDamper(name: \"surge_spring\", end1: World((-1000.0, 0.0, -4.0)),
            end2: Body(body: \"cylinder\", point: (0.0, 0.0, 0.0)),
            law: Linear(stiffness: {stiffness}, rest_length: 1000.0), damping: 2.6e4)])"
    )
}

/// Check 1 of §10: the cylinder on a linear surge spring k in a regular wave of amplitude a
/// settles at the mean offset `a² D₁(ω)/k` within 1 %, at five frequencies, with the drift of
/// either model (in a regular wave both are the constant `a² D`); without drift, at none.
#[test]
fn a_moored_body_in_regular_waves_settles_at_the_mean_drift_over_its_stiffness() {
    let file = cylinder().display().to_string();
    let scale = Scale { density: 1025.0, gravity: 9.80665, length: 1.0 };
    let coefficients = read(&cylinder(), scale).expect("the shipped cylinder");
    let drift = coefficients.mean_drift().expect("its .8");
    let (amplitude, stiffness) = (0.3, 4.0e3);
    for (omega, model) in [(1.1, "Newman"), (1.5, "Mean"), (1.9, "Newman"), (2.5, "Mean"), (3.1, "Newman")] {
        let period = 2.0 * PI / omega;
        let water = format!("Water(waves: Regular(height: {}, period: {period}), ramp: 30.0)", 2.0 * amplitude);
        let mut scene =
            tether_test_support::scene(&moored_cylinder(&water, &format!("file: {file:?}, drift: {model}"), stiffness));
        let world = &mut scene.world;
        let settle = 20.0 * period.ceil().max(15.0);
        while world.time() < settle {
            world.step().expect("a stable cylinder");
        }
        // The mean over a whole number of wave periods.
        let window = period * (200.0 / period).ceil();
        let (mut sum, mut count) = (0.0, 0);
        let end = world.time() + window;
        while world.time() < end {
            world.step().expect("a stable cylinder");
            sum += world.state(0).position.x;
            count += 1;
        }
        let mean = sum / f64::from(count);
        let expected = amplitude * amplitude * drift.coefficient(omega, 0.0).expect("heading 0")[0] / stiffness;
        println!("ω {omega} rad/s ({model}): mean surge {mean:.5} m, a² D₁/k {expected:.5} m");
        assert!((mean / expected - 1.0).abs() < 0.01, "ω {omega}: {mean} against {expected}");
    }
}

/// Check 2 of §10 at the response: the cylinder on its surge spring (4 kN/m, half of critical
/// damping) in a JONSWAP sea of 200 components (Hs 2 m, Tp 4 s: its drift's band) under Newman's
/// drift, 10 seeds of two hours after a 10-minute warm-up. Its slow surge — the surge averaged
/// over 60 s, which keeps the minutes-long motion and removes the waves' (their periods under 7 s
/// pass at most 1/9 of their amplitude) — has the variance `Σ_{m<n} 2 w_m² w_n² |H(μ_mn)|²
/// G(μ_mn)²` of the sea's difference-frequency lines (`S_F`'s discrete form, `w = a √D`) through
/// `H(μ) = 1/(k − (m + A₁₁(0)) μ² + i c μ)` and the average's gain `G = sinc(30 μ)`, within 5 %;
/// its mean is `Σ a² D / k`, within 1 %.
#[test]
fn the_slow_surge_of_a_moored_body_in_an_irregular_sea_has_the_drifts_variance() {
    let file = cylinder().display().to_string();
    let scale = Scale { density: 1025.0, gravity: 9.80665, length: 1.0 };
    let coefficients = read(&cylinder(), scale).expect("the shipped cylinder");
    let drift = coefficients.mean_drift().expect("its .8");
    let (stiffness, damping, mass) = (4.0e3, 3.72e4, 172_771.989_177_48);
    let surge_mass = mass + coefficients.added_mass_zero()[(0, 0)];
    let (warmup, duration, average) = (600.0, 7200.0, 60.0);
    let (expected_variance, expected_mean, measured): (Vec<f64>, Vec<f64>, Vec<(f64, f64)>) = {
        let runs: Vec<_> = (1..=10u64)
            .map(|seed| {
                let water =
                    format!("Water(waves: Jonswap(hs: 2.0, tp: 4.0, components: 200, seed: {seed}), ramp: 60.0)");
                let text = moored_cylinder(&water, &format!("file: {file:?}, drift: Newman"), stiffness)
                    .replace("damping: 2.6e4", &format!("damping: {damping}"))
                    .replace("dt: 0.02", "dt: 0.05");
                std::thread::spawn(move || {
                    let mut scene = tether_test_support::scene(&text);
                    let world = &mut scene.world;
                    let components = world.system().water().expect("water").water.sea().components().to_vec();
                    while world.time() < warmup {
                        world.step().expect("a stable cylinder");
                    }
                    let mut surge = Vec::new();
                    while world.time() < warmup + duration {
                        world.step().expect("a stable cylinder");
                        surge.push(world.state(0).position.x);
                    }
                    (components, surge, world.dt())
                })
            })
            .collect();
        let mut variances = Vec::new();
        let mut means = Vec::new();
        let mut measured = Vec::new();
        for run in runs {
            let (components, surge, dt) = run.join().expect("a run");
            let weights: Vec<(f64, f64)> = components
                .iter()
                .map(|c| (c.frequency, c.amplitude * c.amplitude * drift.coefficient(c.frequency, 0.0).expect("in")[0]))
                .collect();
            let mut variance = 0.0;
            for (m, &(wm_frequency, wm)) in weights.iter().enumerate() {
                for &(wn_frequency, wn) in &weights[m + 1..] {
                    let mu = (wm_frequency - wn_frequency).abs();
                    let re = stiffness - surge_mass * mu * mu;
                    let response = 1.0 / (re * re + (damping * mu).powi(2));
                    let x = 0.5 * average * mu;
                    let gain = if x > 0.0 { (x.sin() / x).powi(2) } else { 1.0 };
                    variance += 2.0 * wm * wn * response * gain;
                }
            }
            variances.push(variance);
            means.push(weights.iter().map(|w| w.1).sum::<f64>() / stiffness);
            // The 60 s moving average of the surge, its mean and variance.
            let window = (average / dt).round() as usize;
            let mut sum: f64 = surge[..window].iter().sum();
            let mut averaged = vec![sum / window as f64];
            for i in window..surge.len() {
                sum += surge[i] - surge[i - window];
                averaged.push(sum / window as f64);
            }
            let mean = surge.iter().sum::<f64>() / surge.len() as f64;
            let slow = averaged.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / averaged.len() as f64;
            measured.push((mean, slow));
        }
        (variances, means, measured)
    };
    let seeds = measured.len() as f64;
    let mean = measured.iter().map(|m| m.0).sum::<f64>() / seeds;
    let variance = measured.iter().map(|m| m.1).sum::<f64>() / seeds;
    let expected_mean = expected_mean.iter().sum::<f64>() / seeds;
    let expected_variance = expected_variance.iter().sum::<f64>() / seeds;
    println!(
        "slow surge: mean {mean:.4} m (Σa²D/k {expected_mean:.4}), variance {variance:.5} m² (lines through H {expected_variance:.5})"
    );
    assert!((mean / expected_mean - 1.0).abs() < 0.01, "mean {mean} against {expected_mean}");
    assert!((variance / expected_variance - 1.0).abs() < 0.05, "variance {variance} against {expected_variance}");
}

/// Bad drift input in a scene (check 6): a drift model on a body whose files have no `.8` or
/// `.9`, and a sea heading the `.8` lacks while the `.3` has it — each one line at the body's
/// `potential`, no panic.
#[test]
fn a_drift_the_files_cannot_give_is_refused_at_the_bodys_potential() {
    let directory = tempfile::tempdir().expect("a temporary directory");
    let copy = |extension: &str| {
        std::fs::copy(cylinder().with_extension(extension), directory.path().join(format!("body.{extension}")))
            .expect("the shipped cylinder's files");
    };
    copy("1");
    copy("3");
    let stem = directory.path().join("body").display().to_string();
    let regular = |heading: f64| format!("Water(waves: Regular(height: 0.5, period: 6.0, heading_deg: {heading}))");
    let error =
        tether_test_support::error_of(&moored_cylinder(&regular(0.0), &format!("file: {stem:?}, drift: Mean"), 4.0e3));
    assert!(
        error.contains("drift: Mean needs the panel code's mean drift coefficients, and no .8 or .9 file was read")
            && !error.contains('\n'),
        "{error}"
    );
    // The excitation at 0° and 90° (the 0° rows again: a refusal needs only the headings), the
    // drift at 0° alone.
    let excitation = std::fs::read_to_string(cylinder().with_extension("3")).expect("the .3");
    let turned: String = excitation
        .lines()
        .filter_map(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            (fields.len() == 7).then(|| format!("{} 90.0 {}\n", fields[0], fields[2..].join(" ")))
        })
        .collect();
    std::fs::write(directory.path().join("body.3"), format!("{excitation}\n{turned}")).expect("written");
    copy("8");
    let error = tether_test_support::error_of(&moored_cylinder(
        &regular(90.0),
        &format!("file: {stem:?}, drift: Newman"),
        4.0e3,
    ));
    assert!(
        error.contains("the waves travel toward 90.000° but the potential-flow file's mean drift covers headings 0.000° to 0.000° only")
            && !error.contains('\n'),
        "{error}"
    );
}

/// The drift model set live (the window's choice, PHYSICS.md §10): the cylinder in a JONSWAP
/// sea built without drift and set to Newman at t = 0 runs as the cylinder built with Newman,
/// bit for bit over 40 s; set from Newman to Mean, as one built with Mean, and to what it runs,
/// unchanged. The three models move it differently (so the comparisons can fail). On files
/// without a `.8` the edit is refused in one line, the world unchanged.
#[test]
fn a_drift_model_set_live_runs_as_one_built_with_it() {
    use tether_physics::potential::DriftModel;
    use tether_physics::world::World;
    let file = cylinder().display().to_string();
    let water = "Water(waves: Jonswap(hs: 2.0, tp: 4.0, components: 50, seed: 3), ramp: 10.0)";
    let built = |model: &str| {
        tether_test_support::scene(&moored_cylinder(water, &format!("file: {file:?}, drift: {model}"), 4.0e3)).world
    };
    let run = |mut world: World| {
        while world.time() < 40.0 {
            world.step().expect("a stable cylinder");
        }
        world.synchronized_states()
    };
    let mut newman = built("Off");
    newman.set_drift_model(0, DriftModel::Newman).expect("the cylinder has a .8");
    let mut mean = built("Newman");
    mean.set_drift_model(0, DriftModel::Mean).expect("the cylinder has a .8");
    let unchanged = mean.clone();
    mean.set_drift_model(0, DriftModel::Mean).expect("what it runs");
    assert_eq!(mean.synchronized_states(), unchanged.synchronized_states());
    let (newman, mean, off) = (run(newman), run(mean), run(built("Off")));
    assert_eq!(newman, run(built("Newman")), "set live as built with Newman");
    assert_eq!(mean, run(built("Mean")), "set live as built with Mean");
    let surge = |states: &[tether_physics::body::BodyState]| states[0].position.x;
    println!("surge at 40 s: off {:.6} m, mean {:.6} m, Newman {:.6} m", surge(&off), surge(&mean), surge(&newman));
    assert!((surge(&newman) - surge(&off)).abs() > 1e-4 && (surge(&newman) - surge(&mean)).abs() > 1e-5);

    let directory = tempfile::tempdir().expect("a temporary directory");
    for extension in ["1", "3"] {
        std::fs::copy(cylinder().with_extension(extension), directory.path().join(format!("body.{extension}")))
            .expect("the shipped cylinder's files");
    }
    let stem = directory.path().join("body").display().to_string();
    let mut world = tether_test_support::scene(&moored_cylinder(water, &format!("file: {stem:?}"), 4.0e3)).world;
    let before = world.clone();
    let error = world.set_drift_model(0, DriftModel::Newman).expect_err("no .8 beside the .1 and .3").to_string();
    assert!(
        error.contains("body \"cylinder\": its drift model cannot be changed: hydro: potential: drift: Newman needs the panel code's mean drift coefficients")
            && !error.contains('\n'),
        "{error}"
    );
    assert_eq!(world.synchronized_states(), before.synchronized_states());
    assert_eq!(world.time(), before.time());
}
