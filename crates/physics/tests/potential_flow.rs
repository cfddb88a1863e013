//! Potential flow in the time domain (PHYSICS.md §9): Capytaine's floating cylinder
//! (`validation/potential-flow/cylinder.py`: R 3 m, draft 6 m, G 4 m below the still level, the
//! reference point) as a scene with `hydro: Hydro(potential: Wamit(...))`, its buoyancy from
//! Tether's 32-sided mesh. Checks: the settled response in regular waves against the
//! frequency-domain solve of the same files with the mesh's own linear stiffness and the
//! scene's mass; the state space against the convolution; the heave free decay against
//! `A(ω_n)`, `B(ω_n)`; the energy radiated in a free decay.

use tether_test_support as common;

use common::{repo, scene};
use std::f64::consts::PI;
use tether_physics::body::BodyState;
use tether_physics::potential::{Coefficients, ComplexVector6, Matrix6, Vector6};
use tether_physics::rao::LinearModel;
use tether_physics::rao_time_domain::RegularWaveRun;
use tether_physics::stability::Limiter;
use tether_physics::world::World;
use tether_scene::wamit::{Scale, read};

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;
const RADIUS: f64 = 3.0;
const DRAFT: f64 = 6.0;
const SIDES: f64 = 32.0;

/// The mesh's waterplane area \[m²]: the 32-gon inscribed in the circle.
fn waterplane() -> f64 {
    0.5 * SIDES * RADIUS * RADIUS * (2.0 * PI / SIDES).sin()
}

/// The mass that floats the mesh at its draft \[kg].
fn mass() -> f64 {
    RHO * waterplane() * DRAFT
}

/// Capytaine's cylinder as a scene, G `lift` \[m] above its equilibrium: `water` the water's
/// fields, `potential` the `Wamit`'s fields besides the file, integrator RK4 at `dt`.
fn cylinder(water: &str, lift: f64, potential: &str, dt: f64) -> World {
    cylinder_with("rk4", water, lift, potential, dt, "")
}

/// [`cylinder`] with the scene's `couplings` (text of the list's items).
fn moored_cylinder(water: &str, lift: f64, potential: &str, dt: f64, couplings: &str) -> World {
    cylinder_with("rk4", water, lift, potential, dt, couplings)
}

/// [`moored_cylinder`] integrated by `integrator`.
fn cylinder_with(integrator: &str, water: &str, lift: f64, potential: &str, dt: f64, couplings: &str) -> World {
    let file = repo("validation/potential-flow/cylinder/cylinder");
    let hydro = format!("Hydro(potential: Wamit(file: {file:?}, {potential}))");
    cylinder_scene(integrator, water, lift, &hydro, dt, couplings)
}

/// The cylinder with `hydro` as its body's `hydro` (the text of a `Hydro(...)`).
fn cylinder_scene(integrator: &str, water: &str, lift: f64, hydro: &str, dt: f64, couplings: &str) -> World {
    let z = -4.0 + lift;
    let m = mass();
    let (ixx, izz) = (m * (3.0 * RADIUS * RADIUS + DRAFT * DRAFT) / 12.0, m * RADIUS * RADIUS / 2.0);
    scene(&format!(
        "Scene(dt: {dt:e}, integrator: {integrator}, water: Water({water}), bodies: [Body(name: \"cylinder\",
            master: Node(position: (0.0, 0.0, {z:e}), mass: {m:e}, inertia: Inertia(xx: {ixx:e}, yy: {ixx:e}, zz: {izz:e})),
            shape: Cylinder(radius: {RADIUS:e}, length: 8.0, center: (0.0, 0.0, 2.0)),
            hydro: {hydro})], couplings: [{couplings}])"
    ))
    .world
}

fn coefficients() -> Coefficients {
    let stem = repo("validation/potential-flow/cylinder/cylinder");
    read(&stem, Scale { density: RHO, gravity: G, length: 1.0 }).expect("the shipped cylinder")
}

/// The linear model `tether rao` solves, about G (the cylinder's reference point): its mass is
/// the scene's, `diag(m, m, m, I_xx, I_xx, I_zz)`; its stiffness the wall-sided mesh's closed
/// form, `C33 = ρ g A_wp`, `C44 = C55 = ρ g (I_wp + V (z_B − z_G))`, `z_B − z_G = 1 m`
/// (`I_wp` the 32-gon's), nothing in surge, sway and yaw; to 1e-6.
#[test]
fn the_linear_model_is_the_scenes_mass_and_the_meshs_hydrostatic_stiffness() {
    let world = cylinder("", 0.0, "", 0.02);
    let model = LinearModel::new(world.system(), "cylinder").expect("a body with potential data");
    let m = mass();
    let ixx = m * (3.0 * RADIUS * RADIUS + DRAFT * DRAFT) / 12.0;
    let expected_mass = Matrix6::from_diagonal(&Vector6::new(m, m, m, ixx, ixx, m * RADIUS * RADIUS / 2.0));
    assert!((model.mass() - expected_mass).norm() < 1e-9 * expected_mass.norm(), "{}", model.mass());
    // The 32-gon's second moment about a diameter: n R⁴ (4 sin α + sin 2α)/48, α = 2π/n.
    let step = 2.0 * PI / SIDES;
    let second_moment = SIDES * RADIUS.powi(4) / 48.0 * (4.0 * step.sin() + (2.0 * step).sin());
    let volume = waterplane() * DRAFT;
    let pitch = RHO * G * (second_moment + volume * 1.0);
    let heave = RHO * G * waterplane();
    let mut expected = Matrix6::zeros();
    expected[(2, 2)] = heave;
    expected[(3, 3)] = pitch;
    expected[(4, 4)] = pitch;
    println!(
        "C33 {:.6e} (expected {heave:.6e}), C44 {:.6e}, C55 {:.6e} (expected {pitch:.6e})",
        model.stiffness()[(2, 2)],
        model.stiffness()[(3, 3)],
        model.stiffness()[(4, 4)]
    );
    assert!((model.stiffness() - expected).abs().max() < 1e-6 * pitch, "{}", model.stiffness());
}

/// `hydrostatics: Linear` (PHYSICS.md §9 "Linear hydrostatics"): the cylinder's restoring is
/// then the file's `.hst`, `Q₀ − C ξ` about its pose at t = 0, and nothing of the mesh's but its
/// still buoyancy there. The linear model `tether rao` solves has the file's stiffness to 1e-6
/// (finite differences of a linear load); at a pose 1 m lower and heeled 20° in pitch the
/// pressure on the body is the closed form `(ρ g V₀ + C33 · 1 m, C55 · 0.349 rad)` about G to 1e-9,
/// where the mesh's own, exact at that pose, differs by more than 1 % in pitch.
#[test]
fn linear_hydrostatics_are_the_files_stiffness_about_the_start_pose() {
    let world = cylinder("", 0.0, "hydrostatics: Linear", 0.02);
    let file = *coefficients().hydrostatic_stiffness().expect("the shipped cylinder has its .hst");
    let model = LinearModel::new(world.system(), "cylinder").expect("a body with potential data");
    println!(
        "C33 {:.6e} (file {:.6e}), C55 {:.6e} (file {:.6e})",
        model.stiffness()[(2, 2)],
        file[(2, 2)],
        model.stiffness()[(4, 4)],
        file[(4, 4)]
    );
    assert!((model.stiffness() - file).abs().max() < 1e-6 * file.abs().max(), "{}\n{}", model.stiffness(), file);

    let pressure_at = |world: &World, sink: f64, heel: f64| {
        let system = world.system();
        let mut states = system.initial_states().to_vec();
        let turn = tether_physics::math::Rotation::from_scaled_axis(tether_physics::math::Vec3::new(0.0, heel, 0.0));
        states[0].position.z -= sink;
        states[0].orientation = turn * states[0].orientation;
        let mut evaluation = tether_physics::evaluation::Evaluation::new(1, system.couplings());
        system.evaluate(&states, &mut evaluation, 0.0).expect("finite states");
        evaluation.water()[0].pressure
    };
    let (sink, heel) = (1.0, 20.0_f64.to_radians());
    let linear = pressure_at(&world, sink, heel);
    let buoyancy = RHO * G * waterplane() * DRAFT;
    let (heave, pitch) =
        (buoyancy + file[(2, 2)] * sink - file[(2, 4)] * heel, -file[(4, 4)] * heel + file[(4, 2)] * sink);
    println!(
        "linear: F_z {:.6e} N (closed form {heave:.6e}), M_y {:.6e} N·m (closed form {pitch:.6e})",
        linear.force.z, linear.moment.y
    );
    assert!((linear.force.z - heave).abs() < 1e-9 * heave, "{}", linear.force);
    assert!((linear.moment.y - pitch).abs() < 1e-9 * pitch.abs(), "{}", linear.moment);
    assert!(linear.force.x.abs() < 1e-9 * heave && linear.moment.x.abs() < 1e-9 * pitch.abs(), "{linear:?}");
    let mesh = pressure_at(&cylinder("", 0.0, "", 0.02), sink, heel);
    println!("mesh at the same pose: F_z {:.6e} N, M_y {:.6e} N·m", mesh.force.z, mesh.moment.y);
    assert!((mesh.moment.y / pitch - 1.0).abs() > 0.01, "the mesh is not linear at 20°: {} vs {pitch}", mesh.moment.y);
}

/// With linear hydrostatics the cylinder in regular waves settles to the frequency-domain solve
/// with the file's stiffness, as with the mesh's (check 2 of issue 33): surge, heave and pitch
/// at 6, 8 and 13 s within 2 % and 3°.
#[test]
fn linear_hydrostatics_settle_to_the_frequency_domain_solve() {
    let world = cylinder("", 0.0, "hydrostatics: Linear", 0.02);
    let model = LinearModel::new(world.system(), "cylinder").expect("a body with potential data");
    let run = RegularWaveRun::new(0.05, 60.0, Some(300.0)).expect("valid settings");
    for period in [6.0, 8.0, 13.0] {
        let solved = model.rao(&[2.0 * PI / period], 0)[0].response.expect("not singular");
        let measured = run.measure(world.clone(), &model, period, 0.0).expect("a stable cylinder");
        for (name, dof) in [("surge", 0), ("heave", 2), ("pitch", 4)] {
            let amplitude = measured[dof].norm() / solved[dof].norm() - 1.0;
            let phase = (measured[dof] / solved[dof]).arg().to_degrees();
            println!("T {period} s {name}: {:+.3} %, {phase:+.3}°", 100.0 * amplitude);
            assert!(amplitude.abs() < 0.02 && phase.abs() < 3.0, "T {period} {name}: {amplitude} {phase}°");
        }
    }
}

/// `hydrostatics: Linear` keeps the energy balance of check 4. The cylinder released 0.2 m high
/// in calm water is linearised about that pose: `Q₀ = ρ g A_mesh (T − 0.2 m)` and the file's
/// `C33`, so it heaves about `ξ_eq = (Q₀ − m g)/C33` below its start with the energy
/// `½ (m + A33∞) ż² + ½ C33 (ξ − ξ_eq)²` (`A∞` as the mass holds it). That energy falls by the
/// radiation's work to 1e-4 of its initial value over 60 s, and the world's own balance (the
/// linear restoring booked as the water's work) drifts by less than 1e-4 of it.
#[test]
fn linear_hydrostatics_keep_the_energy_balance() {
    let lift = 0.2;
    let stiffness = coefficients().hydrostatic_stiffness().expect(".hst")[(2, 2)];
    let preload = RHO * G * waterplane() * (DRAFT - lift);
    let equilibrium = (preload - mass() * G) / stiffness;
    let initial = 0.5 * stiffness * equilibrium * equilibrium;
    let infinite = held_infinite("hydrostatics: Linear")[(2, 2)];
    let (samples, radiated, drift) = heave_decay("hydrostatics: Linear", lift, 0.01, 60.0);
    let &(_, z, w) = samples.last().expect("samples");
    let xi = z - lift;
    println!("ξ_eq {equilibrium:.5} m");
    let energy = 0.5 * (mass() + infinite) * w * w + 0.5 * stiffness * (xi - equilibrium).powi(2);
    assert_energy_radiated(initial, energy, radiated, drift);
}

/// The `A∞` the cylinder's time-domain mass holds with the `Wamit`'s fields `potential`:
/// `A∞_eff` (PHYSICS.md §9, "A∞ consistent with the band"), what its kinetic energy counts.
fn held_infinite(potential: &str) -> Matrix6 {
    let world = cylinder("", 0.0, potential, 0.01);
    let floating = &world.system().water().expect("water").floating[0];
    *floating.potential().as_ref().expect("potential flow").model().infinite_added_mass()
}

/// Surge \[m], heave \[m] and pitch \[rad] of the body from its start.
fn motion(world: &World, start: &BodyState) -> [f64; 3] {
    let state = world.state(0);
    let turn = (state.orientation * start.orientation.inverse()).scaled_axis();
    [state.position.x - start.position.x, state.position.z - start.position.z, turn.y]
}

/// The settled response per unit wave amplitude (`ξ`, WAMIT's convention) of the calm
/// cylinder in regular waves of period `period`, measured as `tether rao --time-domain` does it
/// (`tether_physics::rao_time_domain`): 0.05 m waves ramped over 60 s, fitted over the last
/// `max(3 T, 40 s)` of 300 s.
fn settled(period: f64) -> ComplexVector6 {
    let world = cylinder("", 0.0, "", 0.02);
    let model = LinearModel::new(world.system(), "cylinder").expect("a body with potential data");
    let run = RegularWaveRun::new(0.05, 60.0, Some(300.0)).expect("valid settings");
    run.measure(world, &model, period, 0.0).expect("a stable cylinder")
}

/// Check 2 of issue 33: at eight periods from 4 to 30 s, the settled surge, heave and pitch in
/// small regular waves are the frequency-domain solve's `ξ` (the same files, the mesh's linear
/// stiffness, the scene's mass) within 2 % in amplitude and 3° in phase (measured 0.73 % and
/// 0.09°, heave at 6 s, near its resonance; surge at 4 s 0.29 %, 1.5 % with the file's `A∞`).
#[test]
fn the_settled_response_in_regular_waves_is_the_frequency_domain_solve() {
    let world = cylinder("", 0.0, "radiation: Convolution", 0.02);
    let model = LinearModel::new(world.system(), "cylinder").expect("a body with potential data");
    for period in [4.0, 6.0, 8.0, 10.0, 13.0, 17.0, 22.0, 30.0] {
        let omega = 2.0 * PI / period;
        let xi = model.rao(&[omega], 0)[0].response.expect("damped");
        let measured = settled(period);
        for dof in [0, 2, 4] {
            let (expected, got) = (xi[dof], measured[dof]);
            let amplitude = (got.norm() - expected.norm()) / expected.norm();
            let phase = (got / expected).arg().to_degrees();
            println!(
                "T = {period:>4} s dof {}: time domain {:.5} ∠{:>7.2}°, frequency domain {:.5} ∠{:>7.2}°: {:+.2} %, {:+.2}°",
                dof + 1,
                got.norm(),
                got.arg().to_degrees(),
                expected.norm(),
                expected.arg().to_degrees(),
                100.0 * amplitude,
                phase
            );
            assert!(amplitude.abs() < 0.02, "T = {period} s dof {}: amplitude off by {amplitude:e}", dof + 1);
            assert!(phase.abs() < 3.0, "T = {period} s dof {}: phase off by {phase}°", dof + 1);
        }
    }
}

/// Check 1 of issue 33, its last part: the same scene in a JONSWAP sea (H_s 0.5 m, T_p 8 s),
/// moored in surge by a 100 m spring of 4 kN/m (a 60 s surge period: free, surge drifts with
/// the zero-frequency part of any kernel error), with the radiation force from the state space
/// (the kernel over its default 60 s, its spectrum fitted to 1e-3 per pair) and from the direct
/// convolution moves the same to 1e-3 of the largest motion, dof by dof, over 120 s (measured:
/// surge 3.1e-4, heave 5.8e-5, pitch 6.9e-4). The convolution is the reference only if 60 s of
/// kernel is enough: with 120 s (and that kernel's own `A∞_eff`) it moves the body the same to
/// 1e-3 too (measured 2.1e-4, 5.2e-5, 5.6e-4), while a kernel cut at 30 s, printed beside them,
/// moves it by more than the state space's difference (1.4e-3, 1.1e-4, 3.0e-3): the truncation's
/// own error.
#[test]
fn the_state_space_and_the_convolution_move_the_body_alike() {
    let water = "waves: Jonswap(hs: 0.5, tp: 8.0, heading_deg: 0.0, components: 30, seed: 7)";
    let spring = "SpringDamper(name: \"mooring\", end1: World((-100.0, 0.0, -4.0)), end2: Body(body: \"cylinder\"),
        law: Linear(stiffness: 4.0e3, rest_length: 100.0))";
    let run = |radiation: &str| moored_cylinder(water, 0.0, &format!("radiation: {radiation}"), 0.02, spring);
    let methods = [
        "Convolution",
        "StateSpace, fit_error: 1e-3, max_order: 40",
        "Convolution, kernel_duration: 120.0",
        "Convolution, kernel_duration: 30.0",
    ];
    let mut worlds: Vec<World> = methods.iter().map(|m| run(m)).collect();
    let start = worlds[0].state(0);
    let mut largest = [0.0_f64; 3];
    let mut worst = [[0.0_f64; 3]; 4];
    while worlds[0].time() < 120.0 - 0.01 {
        for world in &mut worlds {
            world.step().expect("a stable cylinder");
        }
        let reference = motion(&worlds[0], &start);
        for (world, worst) in worlds.iter().zip(&mut worst) {
            let moved = motion(world, &start);
            for dof in 0..3 {
                largest[dof] = largest[dof].max(reference[dof].abs());
                worst[dof] = worst[dof].max((moved[dof] - reference[dof]).abs());
            }
        }
    }
    let relative = |m: usize| -> [f64; 3] { std::array::from_fn(|dof| worst[m][dof] / largest[dof]) };
    for (m, method) in methods.iter().enumerate().skip(1) {
        let [surge, heave, pitch] = relative(m);
        println!(
            "{method}: surge {surge:.2e}, heave {heave:.2e}, pitch {pitch:.2e} of the largest motion off the reference"
        );
    }
    assert!(largest.iter().all(|&l| l > 0.01), "the body moves: {largest:?}");
    for m in [1, 2] {
        assert!(relative(m).iter().all(|&r| r < 1e-3), "{}: {:?}", methods[m], relative(m));
    }
}

/// `A33(ω_n)`, `B33(ω_n)` at the heave natural frequency `ω_n = √(C33/(m + A33(ω_n)))`
/// (fixed-point iteration), `C33 = ρ g A_wp` of the mesh.
fn heave_resonance() -> (f64, f64, f64) {
    let coefficients = coefficients();
    let (m, c) = (mass(), RHO * G * waterplane());
    let mut omega = (c / m).sqrt();
    for _ in 0..50 {
        omega = (c / (m + coefficients.radiation_at(omega).0[(2, 2)])).sqrt();
    }
    let (a, b) = coefficients.radiation_at(omega);
    (omega, a[(2, 2)], b[(2, 2)])
}

/// Heave of the cylinder released `lift` [m] above its equilibrium in calm water (the `Wamit`'s
/// fields `potential` besides the file), sampled each step `dt` over `duration` \[s], with the
/// radiation work `∫ F_r·v dt` (trapezoid over the steps) and the energy balance's drift.
fn heave_decay(potential: &str, lift: f64, dt: f64, duration: f64) -> (Vec<(f64, f64, f64)>, f64, f64) {
    let mut world = cylinder("", lift, potential, dt);
    let start = world.energy().balance();
    let radiation_power = |world: &World| {
        let record = &world.evaluation().water()[0];
        record.radiation.force.dot(&world.state(0).velocity)
    };
    let mut samples = vec![(0.0, lift, 0.0)];
    let (mut work, mut power) = (0.0, radiation_power(&world));
    while world.time() < duration - 0.5 * dt {
        world.step().expect("a stable cylinder");
        let now = radiation_power(&world);
        work += 0.5 * dt * (power + now);
        power = now;
        let state = world.state(0);
        samples.push((world.time(), state.position.z + 4.0, state.velocity.z));
    }
    (samples, work, world.energy().balance() - start)
}

/// Check 3 of issue 33: released 0.2 m high in calm water, the cylinder heaves at the damped
/// period `2π/(ω_n √(1 − ζ²))` and decays by the log decrement `2πζ/√(1 − ζ²)`,
/// `ζ = B33(ω_n)/(2 (m + A33(ω_n)) ω_n)`, within 3 % (measured over its cycles 2 to 5: the first
/// carries the start of the radiation memory).
#[test]
fn the_heave_free_decay_has_the_period_and_decrement_of_a_and_b_at_resonance() {
    let (omega, a, b) = heave_resonance();
    let zeta = b / (2.0 * (mass() + a) * omega);
    let expected_period = 2.0 * PI / (omega * (1.0 - zeta * zeta).sqrt());
    let expected_decrement = 2.0 * PI * zeta / (1.0 - zeta * zeta).sqrt();
    let (samples, _, _) = heave_decay("", 0.2, 0.01, 40.0);
    // Peaks (local maxima of the heave) by the parabola through three samples.
    let peaks: Vec<(f64, f64)> = samples
        .windows(3)
        .filter(|w| w[1].1 > w[0].1 && w[1].1 >= w[2].1)
        .map(|w| {
            let (y0, y1, y2) = (w[0].1, w[1].1, w[2].1);
            let shift = 0.5 * (y0 - y2) / (y0 - 2.0 * y1 + y2);
            (w[1].0 + shift * 0.01, y1 - 0.25 * (y0 - y2) * shift)
        })
        .collect();
    assert!(peaks.len() >= 6, "{peaks:?}");
    let cycles = &peaks[1..6];
    let period = (cycles[4].0 - cycles[0].0) / 4.0;
    let decrement = (cycles[0].1 / cycles[4].1).ln() / 4.0;
    println!(
        "ω_n {omega:.4} rad/s, A33 {a:.4e} kg, B33 {b:.4e} kg/s, ζ {zeta:.4}: period {period:.4} s \
         (expected {expected_period:.4}), log decrement {decrement:.4} (expected {expected_decrement:.4})"
    );
    assert!((period / expected_period - 1.0).abs() < 0.03, "period {period} vs {expected_period}");
    assert!((decrement / expected_decrement - 1.0).abs() < 0.03, "decrement {decrement} vs {expected_decrement}");
}

/// Check 4 of issue 33: in calm water, radiation the only loss, the cylinder's energy
/// `½ (m + A33∞) ż² + ½ ρ g A_wp z²` (`A∞` as the mass holds it; exact for the wall-sided mesh
/// in pure heave) falls by the work of the radiation force, to 1e-4 of the initial energy over
/// 60 s (measured 3e-8); the world's own energy balance (the water's work booked, `A∞`'s
/// reaction among it) holds to 1e-4 as well.
#[test]
fn in_calm_water_the_energy_lost_is_the_energy_radiated() {
    let lift = 0.2;
    let stiffness = RHO * G * waterplane();
    let initial = 0.5 * stiffness * lift * lift;
    let infinite = held_infinite("")[(2, 2)];
    let (samples, radiated, drift) = heave_decay("", lift, 0.01, 60.0);
    let &(_, z, w) = samples.last().expect("samples");
    let energy = 0.5 * (mass() + infinite) * w * w + 0.5 * stiffness * z * z;
    assert_energy_radiated(initial, energy, radiated, drift);
}

/// The heave decay's energy `energy` \[J] is its `initial` less the radiation's work `radiated`,
/// most of it radiated away, to 1e-4 of the initial; the world's ledger drifted by `drift`, under
/// 1e-4 of it too.
fn assert_energy_radiated(initial: f64, energy: f64, radiated: f64, drift: f64) {
    let imbalance = energy - initial - radiated;
    println!(
        "initial {initial:.3} J, final {energy:.3} J, radiation work {radiated:.3} J: imbalance {:.2e}, ledger drift {:.2e} of the initial energy",
        imbalance / initial,
        drift / initial
    );
    assert!(radiated < -0.8 * initial, "most of the energy is radiated away in 60 s: {radiated}");
    assert!(imbalance.abs() < 1e-4 * initial, "{imbalance}");
    assert!(drift.abs() < 1e-4 * initial, "{drift}");
}

/// Every integrator carries the radiation memory (committed at accepted steps, RK stages and
/// rejected adaptive attempts leaving nothing): the cylinder released 0.2 m high in a regular
/// sea (0.1 m, 7 s) heaves as RK4 at a quarter of the step has it, over 40 s at dt = 20 ms,
/// within 1e-4 of the lift for RK4 and Dopri45 (measured 1.1e-5, 9e-6) and 1e-2 for the second-order
/// schemes (3.3e-3).
#[test]
fn every_integrator_carries_the_radiation_memory() {
    let water = "waves: Regular(height: 0.2, period: 7.0), ramp: 7.0";
    let heave = |integrator: &str, dt: f64| {
        let mut world = cylinder_with(integrator, water, 0.2, "", dt, "");
        let mut samples = Vec::new();
        while world.time() < 40.0 - 0.5 * dt {
            world.step().expect("a stable cylinder");
            samples.push((world.time(), world.state(0).position.z + 4.0));
        }
        samples
    };
    let reference = heave("rk4", 0.005);
    for (integrator, tolerance) in
        [("rk4", 1e-4), ("dopri45", 1e-4), ("leapfrog", 1e-2), ("leapfrog2", 1e-2), ("splitting", 1e-2)]
    {
        let samples = heave(integrator, 0.02);
        let worst = samples
            .iter()
            .map(|(t, z)| {
                let index = ((t / 0.005).round() as usize).saturating_sub(1);
                (z - reference[index].1).abs()
            })
            .fold(0.0, f64::max);
        println!("{integrator}: worst heave difference {:.2e} of the lift", worst / 0.2);
        assert!(worst < tolerance * 0.2, "{integrator}: {worst}");
    }
}

/// The largest difference between the synchronised states of `a` and `b`: positions \[m],
/// velocities \[m/s], angular velocities \[rad/s] and orientations (the quaternions' components).
fn state_difference(a: &World, b: &World) -> f64 {
    a.synchronized_states()
        .iter()
        .zip(&b.synchronized_states())
        .map(|(x, y)| {
            let quaternion = (x.orientation.coords - y.orientation.coords).amax();
            let moving =
                [(x.position - y.position), (x.velocity - y.velocity), (x.angular_velocity - y.angular_velocity)];
            moving.iter().map(|d| d.amax()).fold(quaternion, f64::max)
        })
        .fold(0.0, f64::max)
}

/// The window's switch (PHYSICS.md §9): the cylinder, released 0.2 m high in a regular sea
/// (0.4 m, 6 s, ramped over two periods), under potential flow for two periods, then switched
/// off: it goes on as a world built without `potential` (`hydro: Hydro(added_mass: (0.5, 0.5,
/// 0.3))`: the incident wave's pressure and this added mass, which potential flow leaves
/// unapplied) started from that state, to 1e-12 over 2 s, with that world's stable time step.
/// Switched on again two periods later, it goes on as a fresh potential-flow world started from
/// that state (its radiation memory empty, the excitation about the mean position of t = 0), to
/// 1e-12 as well, with its stable time step. The sea at time `t` of the switched world is the
/// fresh worlds' at `t − 2n T` (they start at t = 0, unramped, at a whole number of periods),
/// which only round-off tells apart (measured 3.7e-14 and 1.1e-13); the worlds that did not
/// switch differ by 5e-2 and 0.1 (m, m/s), and without the memory started afresh the switched
/// world is 1.9e-2 away, so the comparisons can fail. A body without potential data refuses
/// the switch in one line.
#[test]
fn potential_flow_switches_off_and_on_as_worlds_built_with_and_without_it() {
    let period = 6.0;
    let file = repo("validation/potential-flow/cylinder/cylinder");
    let morison = "Hydro(added_mass: (0.5, 0.5, 0.3))";
    let potential = format!("Hydro(added_mass: (0.5, 0.5, 0.3), potential: Wamit(file: {file:?}))");
    let sea = |ramp: f64| format!("waves: Regular(height: 0.4, period: {period:e}), ramp: {ramp:e}");
    let dt = 0.02;
    let mut switched = cylinder_scene("rk4", &sea(2.0 * period), 0.2, &potential, dt, "");
    let mut kept = switched.clone();
    let run = |world: &mut World, until: f64| {
        while world.time() < until - 0.5 * dt {
            world.step().expect("a stable cylinder");
        }
    };
    // A fresh world of `hydro` from the switched world's state, at the same phase of the sea.
    let fresh = |hydro: &str, from: &World| {
        let mut world = cylinder_scene("rk4", &sea(0.0), 0.2, hydro, dt, "");
        world.place(&from.synchronized_states()).expect("the switched world's state");
        world
    };
    let compare = |switched: &mut World, fresh: &mut World, kept: &mut World, what: &str| {
        let (start, mut worst) = (switched.time(), 0.0_f64);
        while switched.time() < start + 2.0 - 0.5 * dt {
            for world in [&mut *switched, &mut *fresh, &mut *kept] {
                world.step().expect("a stable cylinder");
            }
            worst = worst.max(state_difference(switched, fresh));
        }
        let apart = state_difference(switched, kept);
        println!("switched {what}: {worst:.2e} from the fresh world over 2 s, {apart:.2e} from the unswitched one");
        assert!(worst < 1e-12, "{what}: {worst}");
        assert!(apart > 1e-4, "{what}: the switch changed the motion ({apart})");
    };

    run(&mut switched, 2.0 * period);
    run(&mut kept, 2.0 * period);
    switched.set_potential_flow(0, false).expect("a potential-flow body");
    let floating = &switched.system().water().expect("water").floating[0];
    assert!(floating.potential().is_none() && floating.has_potential_data());
    let mut without = fresh(morison, &switched);
    let limit = |world: &World| {
        let water = world.limits().into_iter().find(|l| l.limiter == Limiter::Water(0));
        water.expect("the water's stable time step").dt
    };
    assert_eq!(limit(&switched), limit(&without), "A∞ is out of the stable time step");
    let refused = without.clone().set_potential_flow(0, true).expect_err("no potential data to switch on");
    assert_eq!(
        refused.to_string(),
        "body \"cylinder\": potential flow cannot be switched: it has no potential-flow data (hydro: Hydro(potential: Wamit(...)))"
    );
    compare(&mut switched, &mut without, &mut kept, "off");
    let forces = switched.water_forces()[0];
    assert_eq!((forces.radiation, forces.excitation), Default::default(), "no potential-flow force while off");

    run(&mut switched, 4.0 * period);
    run(&mut kept, 4.0 * period);
    let mut kept = without;
    run(&mut kept, 2.0 * period);
    switched.set_potential_flow(0, true).expect("a potential-flow body");
    let mut with = fresh(&potential, &switched);
    assert_eq!(limit(&switched), limit(&with), "A∞ back in the stable time step");
    compare(&mut switched, &mut with, &mut kept, "on");
    let forces = switched.water_forces()[0];
    assert!(forces.radiation.force.norm() > 0.0 && forces.excitation.force.norm() > 0.0, "{forces:?}");
}

/// Issue 48 (PHYSICS.md §9, "A∞ consistent with the band"): the shipped cylinder's kernel (the
/// defaults, 60 s every 0.05 s) has no damping beyond the file's 5 rad/s, so with the file's
/// `A∞` the time domain's added mass `A_K(ω)` falls short of the file's `A(ω)` over the whole
/// band (pitch by 2.8 % of `max|A − A∞|`); `A∞_eff` shifts `A55` by +7.485e3 kg·m² (+3.3 %),
/// `A11` by +503 kg and `A15` by +1.956e3 kg·m (each within 1 % of a numpy computation of the
/// same formula on the same file), heave by noise (−1.4 kg), and leaves `A_K` within 1 % of
/// `max|A − A∞|` below 0.8 ω_max in surge, pitch and their coupling (measured 0.27 %, 0.86 %,
/// 0.51 %, from 0.86 %, 2.76 %, 1.60 %). The scene's body holds it.
/// The same file cut at 3 rad/s (a coarser panel run): pitch's misfit falls from 18.5 % to
/// 5.9 %, and the kernel's pitch natural frequency (surge and pitch, free, `A_K(ω_n)`) from
/// 1.3338 rad/s to 1.3190, the file's own being 1.3196.
#[test]
fn the_cylinders_infinite_added_mass_is_made_consistent_with_its_band() {
    use tether_physics::potential::kernel::{SampledKernel, added_mass_from_kernel, consistent_with_band};
    let c = coefficients();
    let kernel = SampledKernel::from_damping(&c, 0.05, 60.0);
    let consistency = consistent_with_band(&c, &kernel);
    let file = c.added_mass_infinite();
    let shift = consistency.infinite - file;
    for (name, (i, j), expected) in [("A11", (0, 0), 503.2), ("A55", (4, 4), 7.485e3), ("A15", (0, 4), 1.956e3)] {
        let (before, after) = (consistency.misfit_file[(i, j)], consistency.misfit_consistent[(i, j)]);
        println!(
            "{name}: A∞ {:.5e} → A∞_eff {:.5e} ({:+.4e}, {:+.2} %); max|A_K − A|/max|A − A∞| below 0.8 ω_max {:.2} % → {:.2} %",
            file[(i, j)],
            consistency.infinite[(i, j)],
            shift[(i, j)],
            100.0 * shift[(i, j)] / file[(i, j)],
            100.0 * before,
            100.0 * after
        );
        assert!((shift[(i, j)] / expected - 1.0).abs() < 0.01, "{name}: {} against {expected}", shift[(i, j)]);
        assert!(after < 0.01 && after < before, "{name}: {after} (before {before})");
    }
    assert!(consistency.misfit_file[(4, 4)] > 0.025, "pitch's misfit before: {}", consistency.misfit_file[(4, 4)]);
    assert!(shift[(2, 2)].abs() < 1e-4 * file[(2, 2)], "heave's shift is noise: {}", shift[(2, 2)]);
    assert!((shift - shift.transpose()).abs().max() < 1e-9 * shift.abs().max(), "the shift is symmetric: {shift}");
    println!("relative shift per dof: {:?}", consistency.relative_shift(file));

    let world = cylinder("", 0.0, "", 0.02);
    let model = &world.system().water().expect("water").floating[0].potential().as_ref().expect("potential").model();
    assert_eq!(model.infinite_added_mass(), &consistency.infinite, "the scene's body holds A∞_eff");
    assert!(!model.infinite_is_the_files());

    // The file cut at 3 rad/s.
    let keep = c.frequencies().iter().filter(|&&w| w <= 3.0 + 1e-9).count();
    let cut = Coefficients::new(tether_physics::potential::CoefficientsData {
        frequencies: c.frequencies()[..keep].to_vec(),
        added_mass: c.added_mass()[..keep].to_vec(),
        damping: c.damping()[..keep].to_vec(),
        added_mass_infinite: *file,
        added_mass_zero: *c.added_mass_zero(),
        excitation: c.excitation().clone(),
        hydrostatic_stiffness: None,
        mean_drift: None,
    })
    .expect("the cut file");
    let cut_kernel = SampledKernel::from_damping(&cut, 0.05, 60.0);
    let cut_consistency = consistent_with_band(&cut, &cut_kernel);
    let linear = LinearModel::new(world.system(), "cylinder").expect("a body with potential data");
    // Surge and pitch, free: `ω² = λ` of `(M + A(ω))⁻¹ C` restricted to them, iterated at ω.
    let pitch_frequency = |added: &dyn Fn(f64) -> Matrix6| {
        let mut omega = 1.3;
        for _ in 0..100 {
            let inertia = linear.mass() + added(omega);
            let pick = |m: &Matrix6| nalgebra::Matrix2::new(m[(0, 0)], m[(0, 4)], m[(4, 0)], m[(4, 4)]);
            let lambda = (pick(&inertia).try_inverse().expect("positive") * pick(linear.stiffness())).eigenvalues();
            omega = lambda.expect("real").max().sqrt();
        }
        omega
    };
    let of_file = pitch_frequency(&|w| c.radiation_at(w).0);
    let kernel_with = |infinite: Matrix6| {
        let kernel = &cut_kernel;
        move |w: f64| added_mass_from_kernel(kernel, &infinite, w)
    };
    let (before, after) =
        (pitch_frequency(&kernel_with(*file)), pitch_frequency(&kernel_with(cut_consistency.infinite)));
    println!(
        "cut at 3 rad/s: pitch misfit {:.2} % → {:.2} %; pitch ω_n {before:.4} → {after:.4} rad/s (the file's {of_file:.4})",
        100.0 * cut_consistency.misfit_file[(4, 4)],
        100.0 * cut_consistency.misfit_consistent[(4, 4)]
    );
    assert!(cut_consistency.misfit_file[(4, 4)] > 0.15 && cut_consistency.misfit_consistent[(4, 4)] < 0.065);
    assert!((before / of_file - 1.0) > 0.008 && (after / of_file - 1.0).abs() < 0.001, "{before} {after} {of_file}");
}

/// The time domain against the frequency domain for one body at a list of periods: `ξ` of
/// [`RegularWaveRun::measure`] against [`LinearModel::rao`], dof by dof, a dof left out where its
/// frequency-domain response is below `tether rao`'s 1e-3 of the larger of its period's largest
/// response and its own largest over the periods (`src/cli/rao.rs`). Prints every line; returns
/// the largest amplitude \[relative] and phase \[°] differences, and where.
fn time_against_frequency(
    label: &str,
    world: &World,
    body: &str,
    run: &RegularWaveRun,
    periods: &[f64],
) -> ((f64, String), (f64, String)) {
    let model = LinearModel::new(world.system(), body).expect("a body with potential data");
    let omegas: Vec<f64> = periods.iter().map(|t| 2.0 * PI / t).collect();
    let solved: Vec<ComplexVector6> =
        model.rao(&omegas, 0).into_iter().map(|row| row.response.expect("damped or off resonance")).collect();
    let dof_largest: [f64; 6] = std::array::from_fn(|dof| solved.iter().map(|xi| xi[dof].norm()).fold(0.0, f64::max));
    let mut worst = ((0.0_f64, String::new()), (0.0_f64, String::new()));
    for (&period, expected) in periods.iter().zip(&solved) {
        let measured = run.measure(world.clone(), &model, period, 0.0).expect("a stable run");
        let largest = expected.iter().map(|x| x.norm()).fold(0.0, f64::max);
        for dof in 0..6 {
            if expected[dof].norm() < 1e-3 * largest.max(dof_largest[dof]) {
                continue;
            }
            let amplitude = measured[dof].norm() / expected[dof].norm() - 1.0;
            let phase = (measured[dof] / expected[dof]).arg().to_degrees();
            let at = format!("{label} T = {period:.3} s dof {}", dof + 1);
            println!(
                "{at}: time domain {:.5e} ∠{:>7.2}°, frequency domain {:.5e} ∠{:>7.2}°: {:+.3} %, {:+.3}°",
                measured[dof].norm(),
                measured[dof].arg().to_degrees(),
                expected[dof].norm(),
                expected[dof].arg().to_degrees(),
                100.0 * amplitude,
                phase
            );
            if amplitude.abs() > worst.0.0.abs() {
                worst.0 = (amplitude, at.clone());
            }
            if phase.abs() > worst.1.0.abs() {
                worst.1 = (phase, at);
            }
        }
    }
    worst
}

/// The periods of `body`'s undamped modes at its static equilibrium with `A(ω_n)`
/// (`natural_periods`) that waves along x excite (dominated by surge, heave or pitch), each
/// once, longest first.
fn excited_natural_periods(world: &World, body: &str) -> Vec<f64> {
    use tether_physics::natural_periods::{AddedMassAt, at_equilibrium};
    use tether_physics::statics::{Settings, equilibrium};
    let system = world.system();
    let index = system.bodies().iter().position(|b| b.name == body).expect("the body");
    let solved = equilibrium::solve(system, system.initial_states(), &[], &Settings::default()).expect("at rest");
    let modes = at_equilibrium(system, &solved, index, AddedMassAt::Resonance).expect("potential flow");
    let mut periods: Vec<f64> = Vec::new();
    for mode in modes.iter().filter(|m| [0, 2, 4].contains(&m.dominant)) {
        println!(
            "{body}: natural period {:.4} s, dominant dof {}, shape {:?}",
            mode.period,
            mode.dominant + 1,
            mode.shape
        );
        if periods.iter().all(|p| (p - mode.period).abs() > 1e-6 * p) {
            periods.push(mode.period);
        }
    }
    periods
}

/// Issue 48's hold ("the RAO check runs periods within ±20 % of every natural period of the
/// shipped potential-flow bodies, time domain against frequency domain within 2 % and 3°"), for
/// Capytaine's cylinder as `tether rao --time-domain` runs it (the scene's defaults: the state
/// space fitted to 1e-2, waves ramped over 60 s) but 600 s long (heave at its resonance, 2 %
/// of critical damping, settles in 65 s per e-fold): at 0.8, 1 and 1.2 of its heave and pitch
/// natural periods (5.58 and 4.76 s; surge free, no period), every dof the waves move.
/// - On the mesh's hydrostatics, in waves of 5 mm: within 0.3 % and 0.4° (measured 0.30 %,
///   heave at 5.71 s; 0.38°, surge at the pitch resonance). With the file's `A∞` in the mass
///   (issue 48) surge was 7.1 % off at 4.47 s, pitch 2.8 %, and both 5.5° at the pitch resonance.
/// - On the `.hst`'s linear hydrostatics, in the default 5 cm waves: the same (measured 0.30 %,
///   0.25°). On the mesh, 5 cm is not small at the resonances: the cylinder pitches 10° at
///   4.76 s and heaves 0.6 m at 5.58 s, and the mesh's exact restoring moves pitch's phase there
///   by 13° (2.3° in 2 cm waves, 0.7° in 1 cm: as the amplitude squared), which is the
///   linearisation's error, not the time domain's.
#[test]
fn the_cylinder_settles_to_the_frequency_domain_solve_near_its_natural_periods() {
    for (hydrostatics, amplitude) in [("", 0.005), ("hydrostatics: Linear", 0.05)] {
        let world = cylinder("", 0.0, hydrostatics, 0.02);
        let natural = excited_natural_periods(&world, "cylinder");
        assert_eq!(natural.len(), 2, "heave and pitch: {natural:?}");
        let periods: Vec<f64> = natural.iter().flat_map(|t| [0.8 * t, *t, 1.2 * t]).collect();
        let run = RegularWaveRun::new(amplitude, 60.0, Some(600.0)).expect("valid settings");
        let label =
            format!("cylinder ({}, a = {amplitude} m)", if hydrostatics.is_empty() { "mesh" } else { "linear" });
        let ((amplitude, amplitude_at), (phase, phase_at)) =
            time_against_frequency(&label, &world, "cylinder", &run, &periods);
        println!("largest: {:+.3} % ({amplitude_at}), {phase:+.3}° ({phase_at})", 100.0 * amplitude);
        assert!(amplitude.abs() < 0.02, "{amplitude_at}: {amplitude}");
        assert!(phase.abs() < 3.0, "{phase_at}: {phase}°");
    }
}

/// The OC3-Hywind spar's coefficients (`scenes/meshes/oc3_spar.1`, `.3`, the shipped
/// `oc3_hywind`'s potential flow) on its hull, floating free: the scene's turbine with its
/// nacelle and rotor moved onto the axis and, in place of the lines' 1,607 kN pull, ballast at
/// the fairleads' depth (the mass that floats the mesh at its draft, found from the model's
/// unbalanced load), no drag or added damping: the frequency-domain solve's model (couplings
/// and viscous loads are not in it).
fn free_spar() -> World {
    let spar = |ballast: f64| {
        let (mesh, file) = (repo("scenes/meshes/oc3_spar.obj"), repo("scenes/meshes/oc3_spar"));
        scene(&format!(
            "Scene(dt: 0.05, integrator: rk4, water: Water(depth: 320.0), bodies: [Body(name: \"spar\",
                master: Node(position: (0.0, 0.0, -89.9155), mass: 7466330.0, inertia: Inertia(xx: 4229230000.0, yy: 4229230000.0, zz: 164230000.0)),
                slaves: [
                    Node(position: (0.0, 0.0, 43.4), mass: 249718.0, inertia: Inertia(xx: 119349100.0, yy: 119349100.0, zz: 0.0)),
                    Node(position: (0.0, 0.0, 89.35), mass: 240000.0, inertia: Inertia(xx: 0.0, yy: 0.0, zz: 1741490.0)),
                    Node(position: (0.0, 0.0, 90.0), mass: 110000.0, inertia: Inertia(xx: 38759236.0, yy: 19379618.0, zz: 19379618.0)),
                    Node(position: (0.0, 0.0, -70.0), mass: {ballast:e}, inertia: Inertia(xx: 0.0, yy: 0.0, zz: 0.0)),
                ],
                shape: Mesh(file: {mesh:?}, center: (0.0, 0.0, 89.9155)),
                hydro: Hydro(potential: Wamit(file: {file:?})))], couplings: [])"
        ))
        .world
    };
    let guess = 1.6072e6 / G;
    let first = spar(guess);
    let unbalanced = LinearModel::new(first.system(), "spar").expect("potential flow").unbalanced();
    let world = spar(guess + unbalanced.force.z / G);
    let left = LinearModel::new(world.system(), "spar").expect("potential flow").unbalanced();
    println!(
        "ballast {:.1} kg; left unbalanced {:.3e} N, {:.3e} N·m",
        guess + unbalanced.force.z / G,
        left.force.norm(),
        left.moment.norm()
    );
    world
}

/// The hold for the OC3-Hywind spar's coefficients ([`free_spar`]): at 0.8 and 1.2 of its heave
/// and pitch natural periods (31.7 and 29.9 s free), surge, heave and pitch within 2 % and 3° of
/// the frequency-domain solve (measured 0.17 % and 0.36°; 0.19 % and 0.36° with the file's `A∞`,
/// which differs from `A∞_eff` by 0.1 % or less here). Not at the natural periods themselves:
/// the spar's radiation damping there is next to nothing (`B33` 35 kg/s, `B55` 8.7e5 N·m·s:
/// decay times of 10⁵ and 10⁴ s), so the response is not finite in practice and no run settles.
/// The modes' own oscillation, which the ramp starts, is as little damped, so the ramp lasts
/// 1200 s (600 s leaves 1.6 % and 1.9° of it in heave at 1.2 × the pitch period, 60 s tens of
/// per cent).
#[test]
fn the_oc3_spar_settles_to_the_frequency_domain_solve_near_its_natural_periods() {
    let world = free_spar();
    let natural = excited_natural_periods(&world, "spar");
    assert_eq!(natural.len(), 2, "heave and pitch: {natural:?}");
    let periods: Vec<f64> = natural.iter().flat_map(|t| [0.8 * t, 1.2 * t]).collect();
    let run = RegularWaveRun::new(0.05, 1200.0, None).expect("valid settings");
    let ((amplitude, amplitude_at), (phase, phase_at)) = time_against_frequency("spar", &world, "spar", &run, &periods);
    println!("largest: {:+.3} % ({amplitude_at}), {phase:+.3}° ({phase_at})", 100.0 * amplitude);
    assert!(amplitude.abs() < 0.02, "{amplitude_at}: {amplitude}");
    assert!(phase.abs() < 3.0, "{phase_at}: {phase}°");
}
