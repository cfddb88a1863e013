//! The WAMIT reader (PHYSICS.md §9, "WAMIT files"): hand-made files for the scaling, the
//! periods −1 and 0, missing pairs, headings and every refusal; the shipped Capytaine cylinder
//! (`validation/potential-flow/cylinder.py`) read and solved in the frequency domain against
//! Capytaine's own RAO.

use nalgebra::Complex;
use std::f64::consts::PI;
use std::path::PathBuf;
use tether_physics::potential::kernel::added_mass_from_kernel;
use tether_physics::potential::response::response;
use tether_physics::potential::{
    Coefficients, CoefficientsData, FitSettings, Matrix6, RadiationStateSpace, SampledKernel,
};
use tether_scene::wamit::{Scale, read};
use tether_test_support::repo;

const SCALE: Scale = Scale { density: 1000.0, gravity: 10.0, length: 2.0 };

/// ω = 1 and ω = 2 rad/s as WAMIT periods.
const PER_1: &str = "6.283185307179586";
const PER_2: &str = "3.141592653589793";

fn radiation_text() -> String {
    [
        "-1 1 1 3.0",
        "-1 3 3 5.0",
        " 0 1 1 2.0",
        " 0 3 3 4.0",
        " 0 1 5 0.5",
        " 0 5 5 7.0",
        &format!("{PER_2} 1 1 2.2 0.3"),
        &format!("{PER_2} 3 3 4.1 0.4"),
        &format!("{PER_2} 5 5 7.2 0.01"),
        "",
        &format!("{PER_1} 1 1 2.5 0.1"),
        &format!("{PER_1} 3 3 4.5 0.2"),
        &format!("{PER_1} 5 1 0.3 0.05"),
        &format!("{PER_1} 5 5 7.2 0.01"),
    ]
    .join("\n")
}

fn excitation_text() -> String {
    [
        format!("{PER_1} 0.0 1 9 9 1.5 -0.5"),
        format!("{PER_1} 0.0 5 9 9 0.2 0.3"),
        format!("{PER_1} 90.0 2 9 9 1.0 2.0"),
        format!("{PER_2} 0.0 3 9 9 -1.0 0.25"),
    ]
    .join("\n")
}

/// Writes `STEM.EXT` for each `(ext, text)` into a fresh directory; returns it and the stem.
fn files(parts: &[(&str, &str)]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let stem = dir.path().join("body");
    for (extension, text) in parts {
        std::fs::write(dir.path().join(format!("body.{extension}")), text).expect("written");
    }
    (dir, stem)
}

fn read_ok(parts: &[(&str, &str)]) -> Coefficients {
    let (_dir, stem) = files(parts);
    read(&stem, SCALE).unwrap_or_else(|e| panic!("{e}"))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

#[test]
fn added_mass_and_damping_are_scaled_by_rho_omega_and_l_to_the_pair_power() {
    let c = read_ok(&[("1", &radiation_text()), ("3", &excitation_text())]);
    assert_eq!(c.frequencies().len(), 2);
    assert!(close(c.frequencies()[0], 1.0) && close(c.frequencies()[1], 2.0), "{:?}", c.frequencies());
    // PER = 0 is ω = ∞, PER = −1 is ω = 0; A = Ā ρ L^k, k = 3, 4, 5.
    let (inf, zero) = (c.added_mass_infinite(), c.added_mass_zero());
    assert!(close(inf[(0, 0)], 2.0 * 1000.0 * 8.0) && close(inf[(0, 4)], 0.5 * 1000.0 * 16.0));
    assert!(close(inf[(4, 4)], 7.0 * 1000.0 * 32.0) && close(zero[(2, 2)], 5.0 * 1000.0 * 8.0));
    // B = B̄ ρ ω L^k.
    let (a1, b1, b2) = (c.added_mass()[0], c.damping()[0], c.damping()[1]);
    assert!(close(a1[(0, 0)], 2.5 * 8000.0) && close(b1[(0, 0)], 0.1 * 1000.0 * 1.0 * 8.0));
    assert!(close(b1[(4, 0)], 0.05 * 1000.0 * 1.0 * 16.0) && close(b2[(2, 2)], 0.4 * 1000.0 * 2.0 * 8.0));
    // Pairs the file leaves out are 0.
    assert_eq!((inf[(4, 0)], zero[(4, 4)], b1[(0, 4)], b2[(4, 0)], a1[(1, 1)]), (0.0, 0.0, 0.0, 0.0, 0.0));
    assert!(c.hydrostatic_stiffness().is_none(), "no .hst, no stiffness");
}

#[test]
fn excitation_is_scaled_by_rho_g_l_squared_or_cubed_per_heading_and_frequency() {
    let c = read_ok(&[("1", &radiation_text()), ("3", &excitation_text())]);
    let x = c.excitation();
    assert_eq!(x.headings.len(), 2);
    assert!(close(x.headings[0], 0.0) && close(x.headings[1], PI / 2.0), "{:?}", x.headings);
    assert!(close(x.frequencies[0], 1.0) && close(x.frequencies[1], 2.0));
    let force = 1000.0 * 10.0 * 4.0; // ρ g L²
    let moment = 1000.0 * 10.0 * 8.0; // ρ g L³
    assert_eq!(x.at(0, 0)[0], Complex::new(1.5, -0.5) * force);
    assert_eq!(x.at(0, 0)[4], Complex::new(0.2, 0.3) * moment);
    assert_eq!(x.at(1, 0)[1], Complex::new(1.0, 2.0) * force);
    assert_eq!(x.at(0, 1)[2], Complex::new(-1.0, 0.25) * force);
    assert_eq!(x.at(1, 1), nalgebra::Vector6::zeros(), "a heading and period the file leaves out is 0");
    assert_eq!(x.at(0, 0)[2], Complex::ZERO);
}

#[test]
fn hydrostatic_stiffness_is_scaled_by_rho_g_l_to_the_pair_power() {
    let hst = "3 3 28.0\n4 4 230.0\n3 5 1.5\n";
    let c = read_ok(&[("1", &radiation_text()), ("3", &excitation_text()), ("hst", hst)]);
    let k = c.hydrostatic_stiffness().expect("a .hst was read");
    assert!(
        close(k[(2, 2)], 28.0 * 1e4 * 4.0) && close(k[(3, 3)], 230.0 * 1e4 * 16.0) && close(k[(2, 4)], 1.5 * 1e4 * 8.0)
    );
    assert_eq!(k[(4, 2)], 0.0);
}

/// The error reading `parts`, with the temporary directory's path replaced by `DIR`.
fn error(parts: &[(&str, &str)]) -> String {
    let (dir, stem) = files(parts);
    let message = read(&stem, SCALE).map(|_| ()).expect_err("refused").to_string();
    assert!(!message.contains('\n'), "one line: {message}");
    message.replace(&dir.path().display().to_string(), "DIR")
}

#[test]
fn bad_files_are_refused_with_one_line_naming_the_file_and_line() {
    let (one, three) = (radiation_text(), excitation_text());
    let with_one = |text: &str| error(&[("1", text), ("3", &three)]);
    assert!(error(&[("3", &three)]).starts_with("DIR/body.1: cannot read WAMIT file:"));
    assert!(error(&[("1", &one)]).starts_with("DIR/body.3: cannot read WAMIT file:"));
    // A truncated last row.
    let truncated = format!("{one}\n{PER_1} 3");
    assert!(with_one(&truncated).starts_with("DIR/body.1:15: expected PER I J A [B]"), "{}", with_one(&truncated));
    // A finite period without its damping; a limit with one.
    let short = one.replace(&format!("{PER_1} 3 3 4.5 0.2"), &format!("{PER_1} 3 3 4.5"));
    assert_eq!(with_one(&short), format!("DIR/body.1:12: expected 5 columns at PER = {PER_1} (PER I J A B), found 4"));
    let long = one.replace(" 0 3 3 4.0", " 0 3 3 4.0 1.0");
    assert_eq!(with_one(&long), "DIR/body.1:4: expected 4 columns at PER = 0 (PER I J A), found 5");
    // A period out of range, a dof index out of range, a coupled multi-body file, a bad number.
    assert_eq!(
        with_one(&one.replace("-1 3 3 5.0", "-2 3 3 5.0")),
        "DIR/body.1:2:1: the period PER must be > 0 s, −1 (ω = 0) or 0 (ω = ∞), got -2"
    );
    assert_eq!(
        with_one(&one.replace(" 0 5 5 7.0", " 0 0 5 7.0")),
        "DIR/body.1:6:4: dof index must be an integer from 1 to 6, got \"0\""
    );
    assert!(
        with_one(&one.replace(" 0 5 5 7.0", " 0 5 11 7.0"))
            .starts_with("DIR/body.1:6:6: dof index 11 > 6: a coupled multi-body file"),
        "{}",
        with_one(&one.replace(" 0 5 5 7.0", " 0 5 11 7.0"))
    );
    assert_eq!(
        with_one(&one.replace("-1 1 1 3.0", "-1 1 1 3.0x")),
        "DIR/body.1:1:8: the added mass must be a finite number, got \"3.0x\""
    );
    assert_eq!(
        with_one(&one.replace("-1 1 1 3.0", "-1 1 1 nan")),
        "DIR/body.1:1:8: the added mass must be a finite number, got \"nan\""
    );
    // No ω = ∞ block; no ω = 0 block.
    let no_infinity: String = one.lines().filter(|l| !l.starts_with(" 0 ")).collect::<Vec<_>>().join("\n");
    assert_eq!(
        with_one(&no_infinity),
        "DIR/body.1: no ω = ∞ (PER = 0) block: Tether needs both limits of the added mass (PHYSICS.md §9)"
    );
    let no_zero: String = one.lines().filter(|l| !l.starts_with("-1 ")).collect::<Vec<_>>().join("\n");
    assert!(with_one(&no_zero).starts_with("DIR/body.1: no ω = 0 (PER = −1) block"));
    // A pair twice; an empty file.
    assert_eq!(
        with_one(&format!("{one}\n{PER_1} 1 1 2.5 0.1")),
        format!("DIR/body.1:15: pair (1, 1) given twice at PER = {PER_1}")
    );
    assert_eq!(with_one("\n\n"), "DIR/body.1: the file is empty");
    // The excitation: a wrong column count, a limit period, a dof index out of range.
    let with_three = |text: &str| error(&[("1", &one), ("3", text)]);
    assert!(
        with_three(&format!("{three}\n{PER_1} 0.0 1 9 9 1.5"))
            .starts_with("DIR/body.3:5: expected PER β I |X| phase Re Im (7 columns), found 6")
    );
    assert_eq!(
        with_three(&format!("{three}\n0 0.0 1 9 9 1.5 0")),
        "DIR/body.3:5:1: the excitation is defined at finite periods only (PER > 0)"
    );
    assert!(
        with_three(&format!("{three}\n{PER_1} 0.0 8 9 9 1.5 0")).contains("dof index 8 > 6: a coupled multi-body file")
    );
    // The hydrostatics: a wrong column count.
    assert_eq!(
        error(&[("1", &one), ("3", &three), ("hst", "3 3\n")]),
        "DIR/body.hst:1: expected I J C (3 columns), found 2 column(s) (a truncated or foreign file?)"
    );
}

fn cylinder() -> PathBuf {
    repo("validation/potential-flow/cylinder/cylinder")
}

/// Water of `validation/potential-flow/cylinder.py`.
const CYLINDER_WATER: Scale = Scale { density: 1025.0, gravity: 9.80665, length: 1.0 };

#[test]
fn a_capytaine_file_from_before_3_0_with_swapped_limits_is_refused_and_says_why() {
    let text = std::fs::read_to_string(cylinder().with_extension("1")).expect("the shipped cylinder.1");
    // Capytaine < 3.0 wrote the ω = 0 block under PER = 0 and the ω = ∞ block under PER = −1.
    let swapped: String = text
        .lines()
        .map(|l| {
            if let Some(rest) = l.strip_prefix("-1.000000e+00") {
                format!("0.000000e+00{rest}")
            } else if let Some(rest) = l.strip_prefix("0.000000e+00") {
                format!("-1.000000e+00{rest}")
            } else {
                l.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let three = std::fs::read_to_string(cylinder().with_extension("3")).expect("the shipped cylinder.3");
    let (dir, stem) = files(&[("1", &swapped), ("3", &three)]);
    let message = read(&stem, CYLINDER_WATER).map(|_| ()).expect_err("refused").to_string();
    let message = message.replace(&dir.path().display().to_string(), "DIR");
    assert!(
        message.starts_with("DIR/body.1:1: the ω = ∞ added mass is not the limit of the finite-ω added mass (A11"),
        "{message}"
    );
    assert!(message.contains("Capytaine PR #855") && message.contains("Capytaine 3.0 or later"), "{message}");
    // The file as shipped is read.
    assert!(read(&cylinder(), CYLINDER_WATER).is_ok());
}

/// `M` or `C` from `cylinder_body.csv` (rows `matrix,row,col,value`).
fn body_matrix(name: &str) -> Matrix6 {
    let text = std::fs::read_to_string(repo("validation/potential-flow/cylinder/cylinder_body.csv")).expect("body csv");
    let mut m = Matrix6::zeros();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let f: Vec<&str> = line.split(',').collect();
        if f[0] == name {
            let (i, j): (usize, usize) = (f[1].parse().expect("row"), f[2].parse().expect("col"));
            m[(i - 1, j - 1)] = f[3].parse().expect("value");
        }
    }
    m
}

#[test]
fn the_cylinders_hydrostatics_file_is_capytaines_stiffness() {
    let c = read(&cylinder(), CYLINDER_WATER).expect("the shipped cylinder");
    let (read_k, expected) = (c.hydrostatic_stiffness().expect("cylinder.hst"), body_matrix("C"));
    for (i, j) in [(2, 2), (3, 3), (4, 4)] {
        assert!(
            (read_k[(i, j)] / expected[(i, j)] - 1.0).abs() < 1e-6,
            "C{i}{j}: {} against {}",
            read_k[(i, j)],
            expected[(i, j)]
        );
    }
}

/// `A` and `B` transposed: Capytaine 3.0.0's export writes `I` the radiating and `J` the
/// influenced dof (`capytaine/io/wamit.py`, `export_wamit_1`), the transpose of WAMIT's `A_ij`
/// (force in mode i from motion in mode j). A panel code's matrices are symmetric but for its
/// numerical error (the cylinder's `A15` and `A51` differ by 0.5 %), so the reader keeps WAMIT's
/// reading and this test transposes, to repeat Capytaine's own solve to its digits.
fn transposed(c: &Coefficients) -> Coefficients {
    Coefficients::new(CoefficientsData {
        frequencies: c.frequencies().to_vec(),
        added_mass: c.added_mass().iter().map(Matrix6::transpose).collect(),
        damping: c.damping().iter().map(Matrix6::transpose).collect(),
        added_mass_infinite: c.added_mass_infinite().transpose(),
        added_mass_zero: c.added_mass_zero().transpose(),
        excitation: c.excitation().clone(),
        hydrostatic_stiffness: c.hydrostatic_stiffness().copied(),
        mean_drift: c.mean_drift().cloned(),
    })
    .expect("the shipped cylinder transposed")
}

/// The frequency-domain solve of §9 from the shipped files against `capytaine.post_pro.rao`
/// (solved by Capytaine from its unrounded coefficients; the WAMIT files carry 7 digits).
#[test]
fn the_frequency_domain_response_from_the_files_is_capytaines_rao() {
    let c = transposed(&read(&cylinder(), CYLINDER_WATER).expect("the shipped cylinder"));
    let (mass, stiffness) = (body_matrix("M"), body_matrix("C"));
    let table = std::fs::read_to_string(repo("validation/potential-flow/cylinder/cylinder_rao.csv")).expect("rao csv");
    let (mut worst_amplitude, mut worst_phase, mut rows) = (0.0_f64, 0.0_f64, 0);
    for line in table.lines().filter(|l| !l.starts_with('#') && !l.starts_with("omega")) {
        let f: Vec<f64> = line.split(',').map(|v| v.parse().expect("a number")).collect();
        let xi = response(&c, &mass, &stiffness, f[0], 0).expect("not singular");
        for (k, dof) in [(1, 0), (3, 2), (5, 4)] {
            let (amplitude, phase) = (f[k], f[k + 1]);
            let ours = (xi[dof].norm(), xi[dof].arg().to_degrees());
            worst_amplitude = worst_amplitude.max((ours.0 / amplitude - 1.0).abs());
            let difference = (ours.1 - phase + 540.0).rem_euclid(360.0) - 180.0;
            worst_phase = worst_phase.max(difference.abs());
            if (ours.0 / amplitude - 1.0).abs() > 1e-3 || difference.abs() > 0.1 {
                println!("ω {} dof {dof}: {:?} against ({amplitude}, {phase})", f[0], ours);
            }
        }
        rows += 1;
    }
    println!("{rows} frequencies: amplitude within {worst_amplitude:.2e} relative, phase within {worst_phase:.2e}°");
    assert_eq!(rows, 100);
    assert!(worst_amplitude < 1e-3 && worst_phase < 0.1, "{worst_amplitude:e}, {worst_phase}°");
}

/// The file's checks (PHYSICS.md §9): the added mass that the kernel of the damping implies
/// (Ogilvie's relation) is the file's, as a panel code's consistent data must give; the kernel
/// from `A(ω) − A∞` is the kernel from `B` up to the tails the files cut off at 5 rad/s (the
/// damping's tail makes the last fifth of the frequencies' added mass differ; the added mass's
/// tail, the kernel's first seconds).
/// `max |A_K(ω) − A(ω)| / max |A(ω) − A∞|` over 0.2–4 rad/s for dof `i`, `A_K` Ogilvie's from the
/// kernel of the damping.
fn added_mass_misfit(c: &Coefficients, kernel: &SampledKernel, i: usize) -> f64 {
    let infinite = c.added_mass_infinite()[(i, i)];
    let span = c.added_mass().iter().map(|a| (a[(i, i)] - infinite).abs()).fold(0.0, f64::max);
    let worst = c
        .frequencies()
        .iter()
        .zip(c.added_mass())
        .filter(|(w, _)| (0.2..=4.0).contains(*w))
        .map(|(w, a)| (added_mass_from_kernel(kernel, c.added_mass_infinite(), *w)[(i, i)] - a[(i, i)]).abs())
        .fold(0.0, f64::max);
    worst / span
}

#[test]
fn the_cylinders_added_mass_and_damping_are_consistent() {
    let c = read(&cylinder(), CYLINDER_WATER).expect("the shipped cylinder");
    let kernel = SampledKernel::from_damping(&c, 0.05, 60.0);
    let from_a = SampledKernel::from_added_mass(&c, 0.05, 60.0);
    // The same file with its damping doubled: what a wrong scaling of B would read.
    let doubled = Coefficients::new(CoefficientsData {
        frequencies: c.frequencies().to_vec(),
        added_mass: c.added_mass().to_vec(),
        damping: c.damping().iter().map(|b| b * 2.0).collect(),
        added_mass_infinite: *c.added_mass_infinite(),
        added_mass_zero: *c.added_mass_zero(),
        excitation: c.excitation().clone(),
        hydrostatic_stiffness: None,
        mean_drift: None,
    })
    .expect("valid");
    let doubled_kernel = SampledKernel::from_damping(&doubled, 0.05, 60.0);
    for (i, name) in [(0, "surge"), (2, "heave"), (4, "pitch")] {
        let misfit = added_mass_misfit(&c, &kernel, i);
        let (truncation, disagreement) = (kernel.truncation()[i], kernel.disagreement(&from_a, 2.0)[i]);
        let (wrong_misfit, wrong_disagreement) =
            (added_mass_misfit(&doubled, &doubled_kernel, i), doubled_kernel.disagreement(&from_a, 2.0)[i]);
        println!(
            "{name}: A from K within {misfit:.2e} of max|A − A∞| (0.2 to 4 rad/s); |K(60 s)|/K_peak {truncation:.1e}; \
             K from A within {disagreement:.2e} K_peak of K from B after 2 s; B doubled: {wrong_misfit:.2}, {wrong_disagreement:.2}"
        );
        assert!(misfit < 0.03 && truncation < 2e-3 && disagreement < 0.1, "{name}");
        assert!(wrong_misfit > 0.3, "{name}: the check sees a wrong damping");
    }
}

/// The state-space fit of a real body's kernel (PHYSICS.md §9): every nonzero pair within the
/// stated error at a small order, the fitted spectrum checked between the frequencies it was
/// fitted at (a grid 4 × finer, weighted as the fit is: a narrow spurious resonance would show
/// there), and `K̂(0)` (the damping at ω → 0, which a body has not) within 1e-4 of the peak.
#[test]
fn the_cylinders_kernel_is_fitted_by_a_few_states_per_pair() {
    let c = read(&cylinder(), CYLINDER_WATER).expect("the shipped cylinder");
    let kernel = SampledKernel::from_damping(&c, 0.05, 60.0);
    let band = c.highest_frequency();
    let fit = RadiationStateSpace::fit(&kernel, band, FitSettings::new(1e-3, 40).expect("valid"))
        .unwrap_or_else(|e| panic!("{e}"));
    // The fit's grid is `π/(2 t_K)` apart; this one 4 × finer.
    let count = (4.0 * band * 2.0 * 60.0 / std::f64::consts::PI).ceil() as usize;
    let omegas: Vec<f64> = (0..=count).map(|k| band * k as f64 / count as f64).collect();
    for pair in fit.pairs() {
        let exact = kernel.spectrum(pair.i, pair.j, &omegas);
        let peak = exact.iter().map(|k| k.norm()).fold(0.0, f64::max);
        let (mut diff, mut norm) = (0.0, 0.0);
        for (&w, k) in omegas.iter().zip(&exact) {
            let weight = 1.0 / k.norm().max(1e-2 * peak);
            diff += (weight * (pair.spectrum(w) - k)).norm_sqr();
            norm += (weight * k).norm_sqr();
        }
        let between = (diff / norm).sqrt();
        let at_zero = (pair.spectrum(0.0) - exact[0]).norm() / peak;
        println!(
            "K{}{}: {} states, error {:.2e} at the fitted frequencies, {between:.2e} on a 4 × finer grid, K̂(0) − K(0) {at_zero:.1e} of the peak",
            pair.i + 1,
            pair.j + 1,
            pair.states(),
            pair.error
        );
        assert!(pair.error <= 1e-3 && between <= 2e-3 && at_zero < 1e-4, "K{}{}", pair.i + 1, pair.j + 1);
    }
    println!("{} pairs, {} states at 1e-3", fit.pairs().len(), fit.state_count());
    let coarse = RadiationStateSpace::fit(&kernel, band, FitSettings::new(1e-2, 40).expect("valid"))
        .unwrap_or_else(|e| panic!("{e}"));
    println!("{} states at 1e-2", coarse.state_count());
    assert!(coarse.state_count() < fit.state_count() && coarse.pairs().iter().all(|p| p.error <= 1e-2));
    let pairs: Vec<(usize, usize)> = fit.pairs().iter().map(|p| (p.i, p.j)).collect();
    assert_eq!(
        pairs,
        [(0, 0), (0, 4), (1, 1), (1, 3), (2, 2), (3, 1), (3, 3), (4, 0), (4, 4)],
        "the cylinder's coupled pairs"
    );
}

/// The cylinder as a scene with `water` (a `water: …,` entry or nothing) and the `Wamit`'s
/// fields `potential`.
fn cylinder_scene(water: &str, potential: &str) -> String {
    format!(
        "Scene(dt: 0.02, {water} bodies: [Body(name: \"cylinder\",
            master: Node(position: (0.0, 0.0, -4.0), mass: 1.7e5, inertia: Inertia(xx: 9e5, yy: 9e5, zz: 7.8e5)),
            shape: Cylinder(radius: 3.0, length: 8.0, center: (0.0, 0.0, 2.0)),
            hydro: Hydro(potential: Wamit({potential})))])"
    )
}

/// `scene` with its body turned by the rotation vector `rotation` at t = 0.
fn turned(scene: &str, rotation: &str) -> String {
    scene.replacen("shape: Cylinder", &format!("rotation: {rotation}, shape: Cylinder"), 1)
}

/// Potential flow's scene key: the shipped cylinder accepted; bad input refused with one line
/// placed at the body's `potential` (the reader's own file:line:col inside it).
#[test]
fn potential_flow_in_a_scene_is_refused_with_one_line_where_it_cannot_be() {
    let file = format!("file: {:?}", cylinder().display().to_string());
    let calm = "water: Water(),";
    for accepted in [file.clone(), format!("{file}, hydrostatics: Linear"), format!("{file}, hydrostatics: Mesh")] {
        let good = tether_scene::parse(&cylinder_scene(calm, &accepted), std::path::Path::new("test.ron"));
        assert!(good.is_ok(), "{accepted}: {:?}", good.err().map(|e| e.to_string()));
    }
    // The cylinder's .1 and .3 without its .hst.
    let directory = tempfile::tempdir().expect("a temporary directory");
    for extension in ["1", "3"] {
        std::fs::copy(cylinder().with_extension(extension), directory.path().join(format!("body.{extension}")))
            .expect("the shipped cylinder's files");
    }
    let without_hst = directory.path().join("body").display().to_string();
    // A decay test's initial heel (3°) is a small rotation, which the linear theory is about.
    let heeled = tether_scene::parse(
        &turned(&cylinder_scene(calm, &file), "(0.0, 0.0524, 0.0)"),
        std::path::Path::new("test.ron"),
    );
    assert!(heeled.is_ok(), "{:?}", heeled.err().map(|e| e.to_string()));
    let cases = [
        (cylinder_scene("", &file), "potential flow needs water: the scene has none"),
        (cylinder_scene(calm, "file: \"no/such/stem\""), "no/such/stem.1"),
        (
            cylinder_scene("water: Water(waves: Regular(height: 0.1, period: 8.0, heading_deg: 90.0)),", &file),
            "the waves travel toward 90.000° but the potential-flow file's excitation covers headings 0.000° to 0.000° only",
        ),
        (cylinder_scene(calm, &format!("{file}, fit_error: 2.0")), "fit_error"),
        (cylinder_scene(calm, &format!("{file}, kernel_step: 0.0")), "kernel_step"),
        (cylinder_scene(calm, &format!("{file}, kernel_step: 2.0, kernel_duration: 1.0")), "below its duration"),
        (
            turned(&cylinder_scene(calm, &file), "(0.0, 0.0, 1.5707963)"),
            "the body starts turned 90.0° from the panel code's axes",
        ),
        (
            cylinder_scene(calm, &format!("file: {without_hst:?}, hydrostatics: Linear")),
            "hydrostatics: Linear needs the panel code's hydrostatic stiffness, and no .hst file was read",
        ),
        (cylinder_scene(calm, &format!("{file}, hydrostatics: Linaer")), "Linaer"),
    ];
    for (text, expected) in cases {
        let error = tether_test_support::error_of(&text);
        println!("{error}");
        assert!(error.contains(expected) && !error.contains('\n'), "{error}");
        assert!(error.contains("body \"cylinder\""), "{error}");
    }
}

/// `hydrostatics: Linear` with the shipped cylinder's `.hst` (Capytaine's finer mesh: 0.4 % from
/// Tether's 32-sided one) loads without a warning; the same file with its pitch stiffness doubled
/// (as a weight term counted twice would) is warned of in one line naming pitch and both
/// figures, and heave and roll, unchanged, are not.
#[test]
fn a_linear_hydrostatics_file_far_from_the_mesh_is_warned_of() {
    let calm = "water: Water(),";
    let load = |stem: &str| {
        let text = cylinder_scene(calm, &format!("file: {stem:?}, hydrostatics: Linear"));
        tether_scene::parse(&text, std::path::Path::new("test.ron")).expect("accepted").warnings
    };
    let shipped = load(&cylinder().display().to_string());
    assert!(shipped.is_empty(), "{shipped:?}");

    let directory = tempfile::tempdir().expect("a temporary directory");
    for extension in ["1", "3"] {
        std::fs::copy(cylinder().with_extension(extension), directory.path().join(format!("body.{extension}")))
            .expect("the shipped cylinder's files");
    }
    let hst = std::fs::read_to_string(cylinder().with_extension("hst")).expect("the shipped .hst");
    let doubled: String = hst
        .lines()
        .map(|line| {
            let fields: Vec<&str> = line.split_whitespace().collect();
            match fields[..] {
                ["5", "5", value] => format!("5 5 {:e}\n", 2.0 * value.parse::<f64>().expect("a number")),
                _ => format!("{line}\n"),
            }
        })
        .collect();
    std::fs::write(directory.path().join("body.hst"), doubled).expect("a temporary file");
    let warnings = load(&directory.path().join("body").display().to_string());
    println!("{warnings:?}");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    let warning = &warnings[0];
    assert!(warning.starts_with("body \"cylinder\": its .hst's pitch stiffness with the weight is"), "{warning}");
    // The file's C55 is 232.4698 ρg about G, doubled; the mesh's 232.0 ρg less the 32-gon's
    // smaller waterplane: about +100 %.
    let rho_g = 1025.0 * 9.80665;
    assert!(warning.contains(&format!("{:.4e}", 2.0 * 232.4698 * rho_g)), "{warning}");
    assert!(warning.contains("(+10"), "{warning}");
    assert!(!warning.contains('\n'));
}
