//! Wind (PHYSICS.md §10, check 4): the steady force and the aerodynamic damping of a decay
//! against their closed forms, the realised gusts' variance and spectrum against NPD's formula
//! over many seeds, a rotor's mean offset against the static solve's `F/K`, the air's work in
//! the energy balance, and the scene's refusals.

use std::f64::consts::PI;
use tether_physics::air::{GustSpec, GustSpectrum, Gusts};
use tether_physics::statics::equilibrium::{self, Settings};
use tether_physics::statics::{Direction, Dof};

/// A 1000 kg point body without gravity held along x by a spring of `stiffness` [N/m] (100 m
/// long, so that a sideways gust barely turns it), in the air `air`, with `loads` (its
/// `windage`/`rotor` fields).
fn sprung_body(air: &str, loads: &str, stiffness: f64, velocity: f64) -> String {
    format!(
        "Scene(dt: 0.01, integrator: rk4, gravity: (0.0, 0.0, 0.0), {air}
            bodies: [Body(name: \"box\", master: Node(position: (0.0, 0.0, 10.0), mass: 1000.0,
                inertia: Inertia(xx: 100.0, yy: 100.0, zz: 100.0)),
                velocity: ({velocity}, 0.0, 0.0),
                shape: Box(size: (1.0, 1.0, 1.0)), {loads})],
            couplings: [SpringDamper(name: \"spring\", end1: World((-100.0, 0.0, 10.0)),
                end2: Body(body: \"box\", point: (0.0, 0.0, 0.0)),
                law: Linear(stiffness: {stiffness}, rest_length: 100.0))])"
    )
}

const STEADY: &str = "air: Air(wind: Wind(speed: 20.0, height: 10.0), ramp: 0.0),";
const WINDAGE: &str = "windage: Windage(coefficients: (1.2, 1.2, 0.0), areas: (4.0, 4.0, 1.0))";

/// The steady force `½ ρ_a C A U²` at the equilibrium, `F/k` its offset (the static solve).
#[test]
fn the_steady_wind_pushes_a_sprung_body_by_its_drag_over_the_stiffness() {
    let scene = tether_test_support::scene(&sprung_body(STEADY, WINDAGE, 500.0, 0.0));
    let system = scene.world.system();
    let solved = equilibrium::solve(system, system.initial_states(), &[], &Settings::default()).expect("a solve");
    let force = 0.5 * 1.225 * 1.2 * 4.0 * 20.0 * 20.0;
    let offset = solved.states[0].position.x;
    assert!((offset / (force / 500.0) - 1.0).abs() < 1e-6, "{offset} against {}", force / 500.0);
}

/// Released from its equilibrium at 0.05 m/s, the body decays at the damping ratio
/// `ζ = ρ_a C A U / (2 √(k m))` of the linearised drag (the quadratic's `v²` term is 0.1 % of it
/// at this speed), to 1 %.
#[test]
fn a_decay_in_steady_wind_has_the_aerodynamic_damping_ratio() {
    let (stiffness, mass, speed) = (500.0, 1000.0, 20.0);
    let mut scene = tether_test_support::scene(&sprung_body(STEADY, WINDAGE, stiffness, 0.0));
    let system = scene.world.system();
    let solved = equilibrium::solve(system, system.initial_states(), &[], &Settings::default()).expect("a solve");
    let mut start = solved.states.clone();
    start[0].velocity.x = 0.05;
    let world = &mut scene.world;
    world.place(&start).expect("forces at the start");
    let rest = solved.states[0].position.x;
    let mut peaks = Vec::new();
    let (mut before, mut now) = (0.0, world.state(0).position.x - rest);
    while world.time() < 120.0 {
        world.step().expect("a stable body");
        let next = world.state(0).position.x - rest;
        if now > before && now > next && now > 0.0 {
            peaks.push(now);
        }
        (before, now) = (now, next);
    }
    let decrement = (peaks[0] / peaks[4]).ln() / 4.0;
    let zeta = decrement / (4.0 * PI * PI + decrement * decrement).sqrt();
    let expected = 1.225 * 1.2 * 4.0 * speed / (2.0 * (stiffness * mass).sqrt());
    assert!((zeta / expected - 1.0).abs() < 0.01, "ζ = {zeta} against {expected} ({} peaks)", peaks.len());
}

/// NPD gusts at 10 m in a 20 m/s wind, 20 seeds of six hours sampled every second: the mean of
/// their variances is the formula's over the realised band within 2 % (measured −0.14 %), and
/// their averaged periodogram holds the formula's `∫ S df` within 2 % in each of three bands a
/// factor of 4 wide from 1/600 to 0.1 Hz, about 30 of the 200 log-spaced components in each
/// (measured −0.8 %, +0.8 %, +1.1 %).
#[test]
fn the_realised_gusts_follow_the_npd_spectrum() {
    let (duration, step, seeds) = (21_600.0, 1.0, 20);
    let samples = (duration / step) as usize;
    let band_variance =
        Gusts::new(&GustSpec::Npd { seed: 1, components: 200 }).expect("npd").at(10.0, 20.0, 20.0).variance();
    let mut variance = 0.0;
    let bands: Vec<(f64, f64)> = (0..3).map(|i| (1.0 / 600.0 * 4f64.powi(i), 1.0 / 600.0 * 4f64.powi(i + 1))).collect();
    let mut band_power = vec![0.0; bands.len()];
    for seed in 0..seeds {
        let gusts = Gusts::new(&GustSpec::Npd { seed, components: 200 }).expect("npd");
        let point = gusts.at(10.0, 20.0, 20.0);
        let series: Vec<f64> = (0..samples).map(|i| gusts.speed(&point, i as f64 * step)).collect();
        let mean = series.iter().sum::<f64>() / samples as f64;
        variance += series.iter().map(|u| (u - mean).powi(2)).sum::<f64>() / samples as f64 / f64::from(seeds as u32);
        // The periodogram's power in each band, at the record's Fourier frequencies n/T.
        for (power, &(low, high)) in band_power.iter_mut().zip(&bands) {
            let first = (low * duration).ceil() as usize;
            let last = (high * duration).floor() as usize;
            for n in first..=last {
                let omega = 2.0 * PI * n as f64 / duration;
                let (mut c, mut s) = (0.0, 0.0);
                for (i, u) in series.iter().enumerate() {
                    let angle = omega * i as f64 * step;
                    c += u * angle.cos();
                    s += u * angle.sin();
                }
                // One-sided: |U_n|² 2/N² is the variance in the bin 1/T wide.
                *power += 2.0 * (c * c + s * s) / (samples * samples) as f64 / f64::from(seeds as u32);
            }
        }
    }
    assert!((variance / band_variance - 1.0).abs() < 0.02, "variance {variance} against {band_variance}");
    for (power, &(low, high)) in band_power.iter().zip(&bands) {
        let expected = integral(low, high);
        println!("{low:.5}–{high:.5} Hz: {:+.2} %", 100.0 * (power / expected - 1.0));
        assert!((power / expected - 1.0).abs() < 0.02, "{low:.5}–{high:.5} Hz: {power} against {expected}");
    }
}

/// NPD's `∫ S df` [(m/s)²] from `low` to `high` \[Hz] at 10 m in a 20 m/s wind, by Simpson's rule
/// in log f (`∫ S f d ln f`).
fn integral(low: f64, high: f64) -> f64 {
    let density = |log_f: f64| {
        let f = log_f.exp();
        GustSpectrum::Npd.density(f, 10.0, 20.0, 20.0) * f
    };
    tether_test_support::simpson(density, low.ln(), high.ln(), 2000)
}

/// A rotor's steady thrust `½ ρ_a A C_T U²` at the hub's wind, against the static solve's
/// offset `F/k`: the power law carries 10 m's 11.4 m/s to the 90 m hub.
#[test]
fn a_rotors_mean_offset_is_its_thrust_over_the_stiffness() {
    let air = "air: Air(wind: Wind(speed: 8.0, height: 10.0, profile: PowerLaw(0.11)), ramp: 0.0),";
    let rotor =
        "rotor: Rotor(point: (0.0, 0.0, 80.0), area: 12469.0, thrust: Table([(3.0, 0.9), (11.4, 0.75), (25.0, 0.1)]))";
    let scene = tether_test_support::scene(&sprung_body(air, rotor, 4.0e4, 0.0));
    let system = scene.world.system();
    let held = [Direction::Roll, Direction::Pitch, Direction::Yaw].map(|direction| Dof { body: 0, direction });
    let solved = equilibrium::solve(system, system.initial_states(), &held, &Settings::default()).expect("a solve");
    let hub_speed = 8.0 * 9.0_f64.powf(0.11);
    let coefficient = 0.9 + (0.75 - 0.9) * (hub_speed - 3.0) / 8.4;
    let thrust = 0.5 * 1.225 * 12469.0 * coefficient * hub_speed * hub_speed;
    let offset = solved.states[0].position.x;
    assert!((offset / (thrust / 4.0e4) - 1.0).abs() < 1e-4, "{offset} against {}", thrust / 4.0e4);
}

/// The air's work is booked: a gusty run's energy balance closes as a calm one's does.
#[test]
fn the_winds_work_closes_the_energy_balance() {
    let air = "air: Air(wind: Wind(speed: 20.0, gusts: Npd(seed: 4)), ramp: 5.0),";
    let mut scene = tether_test_support::scene(&sprung_body(air, WINDAGE, 500.0, 0.0));
    let world = &mut scene.world;
    let mut largest = 0.0_f64;
    while world.time() < 60.0 {
        world.step().expect("a stable body");
        largest = largest.max(world.energy().external_work.abs());
    }
    let energy = world.energy();
    let balance = energy.total() + energy.dissipated - energy.external_work;
    assert!(largest > 100.0, "the wind did work: {largest} J");
    assert!(balance.abs() < 1e-6 * largest, "balance {balance} J of {largest} J of work");
}

/// Bad air and bad wind loads: one line at the field, no panic.
#[test]
fn bad_air_is_refused_at_its_field() {
    let good = sprung_body(STEADY, WINDAGE, 500.0, 0.0);
    let cases = [
        (good.replace("speed: 20.0", "speed: -1.0"), "speed must be ≥ 0 m/s, got -1"),
        (good.replace("ramp: 0.0", "ramp: -2.0"), "ramp must be ≥ 0 s, got -2"),
        (good.replace("height: 10.0)", "height: 10.0, profile: Logarithmic(20.0))"), "roughness z₀ = 20 m"),
        (
            good.replace("height: 10.0)", "height: 10.0, gusts: Npd(components: 0))"),
            "components must be 1 to 2000, got 0",
        ),
        (good.replace("areas: (4.0, 4.0, 1.0)", "areas: (-4.0, 4.0, 1.0)"), "windage: areas must be ≥ 0 m², got -4"),
        (
            sprung_body(
                STEADY,
                "rotor: Rotor(point: (0.0, 0.0, 1.0), area: 10.0, thrust: Table([(5.0, 0.8), (4.0, 0.7)]))",
                500.0,
                0.0,
            ),
            "rotor: thrust: table point 1: x must increase strictly (5 then 4)",
        ),
        (
            sprung_body(
                STEADY,
                "rotor: Rotor(point: (0.0, 0.0, 1.0), area: 10.0, thrust: Table([(5.0, 0.8), (6.0, -0.7)]))",
                500.0,
                0.0,
            ),
            "rotor: thrust: C_T must be ≥ 0, got -0.7",
        ),
        (good.replace("speed: 20.0", "speed: inf"), "finite"),
        // Finite numbers whose products overflow: refused where they are derived.
        (
            good.replace(
                "coefficients: (1.2, 1.2, 0.0), areas: (4.0, 4.0, 1.0)",
                "coefficients: (1e200, 1.2, 0.0), areas: (1e200, 4.0, 1.0)",
            ),
            "windage: C·A must be finite, got inf (from areas = 1e200)",
        ),
        (
            sprung_body(
                "air: Air(wind: Wind(speed: 20.0, height: 10.0, profile: PowerLaw(1e300)), ramp: 0.0),",
                "rotor: Rotor(point: (0.0, 0.0, 80.0), area: 10.0, thrust: Table([(3.0, 0.8), (25.0, 0.1)]))",
                500.0,
                0.0,
            ),
            "rotor: the mean wind at a load point must be finite, got inf (from speed = 20)",
        ),
    ];
    for (text, expected) in cases {
        let error = tether_test_support::error_of(&text);
        assert!(error.contains(expected) && !error.contains('\n'), "{expected}: {error}");
    }
    let warnings = tether_scene::parse(&sprung_body("", WINDAGE, 500.0, 0.0), std::path::Path::new("t.ron"))
        .expect("a scene without air")
        .warnings;
    assert!(
        warnings.iter().any(|w| w.contains("declares windage or a rotor but the scene has no air")),
        "{warnings:?}"
    );
}

/// The air replaced live (the window's knobs, PHYSICS.md §10): the sprung body built in a
/// 20 m/s steady wind, given a 25 m/s NPD wind (seed 7) at t = 0, runs as the body built in that
/// wind, bit for bit over 30 s, and unlike the one left in the steady wind. Bad air is refused
/// with the loader's message and leaves the world as it was; a world without air refuses air.
#[test]
fn the_air_replaced_live_runs_as_air_built_so() {
    use tether_scene::build::air_spec;
    let gusty = "air: Air(wind: Wind(speed: 25.0, height: 10.0, gusts: Npd(seed: 7)), ramp: 0.0),";
    let run = |mut world: tether_physics::world::World| {
        while world.time() < 30.0 {
            world.step().expect("a stable body");
        }
        world.synchronized_states()
    };
    let gusty_file = tether_test_support::scene(&sprung_body(gusty, WINDAGE, 500.0, 0.0)).file;
    let (spec, loads) = air_spec(&gusty_file).expect("good air");
    let mut replaced = tether_test_support::scene(&sprung_body(STEADY, WINDAGE, 500.0, 0.0)).world;
    let steady = replaced.clone();
    replaced.replace_air(spec, loads.clone()).expect("good air");
    let built = tether_test_support::scene(&sprung_body(gusty, WINDAGE, 500.0, 0.0)).world;
    let replaced = run(replaced);
    assert_eq!(replaced, run(built), "replaced live as built");
    let offset = replaced[0].position.x - run(steady)[0].position.x;
    println!("25 m/s NPD against 20 m/s steady at 30 s: {offset:.4} m further");
    assert!(offset.abs() > 1e-3, "{offset}");

    let mut bad_file = gusty_file.clone();
    bad_file.air.as_mut().expect("air").wind.speed = -3.0;
    let refused = air_spec(&bad_file).expect_err("a negative speed");
    assert!(
        refused.message.contains("speed must be ≥ 0 m/s, got -3") && !refused.message.contains('\n'),
        "{}",
        refused.message
    );
    let mut calm = tether_test_support::scene(&sprung_body("", WINDAGE, 500.0, 0.0)).world;
    let error = calm.replace_air(spec, loads).expect_err("no air to replace").to_string();
    assert!(error.contains("the system has no air"), "{error}");
}

/// `scenes/oc3_hywind_rated.ron`'s comment (the spar at the NREL 5 MW's rated wind): its steady
/// thrust and tower drag push G 20.6 m downwind and pitch it 5.59° (`tether equilibrium`'s
/// solve, the wind steady, no waves), further than F/K with the lines' stiffness at rest says.
#[test]
fn the_rated_spar_settles_where_its_comment_says() {
    let scene = tether_scene::load(&tether_test_support::repo("scenes/oc3_hywind_rated.ron")).expect("a shipped scene");
    let system = scene.world.system();
    let start = system.initial_states();
    let solved = equilibrium::solve(system, start, &[], &Settings::default()).expect("a solve");
    let spar = scene.world.bodies().iter().position(|b| b.name == "spar").expect("the spar");
    let (moved, state) = (solved.states[spar].position - start[spar].position, &solved.states[spar]);
    // The turn from the start, applied to the vertical.
    let turned = state.rotation_matrix() * start[spar].rotation_matrix().transpose() * tether_physics::math::Vec3::z();
    let pitch = turned.x.atan2(turned.z).to_degrees();
    println!("G moved {:.3} m downwind, pitched {pitch:.3}°", moved.x);
    assert!((moved.x - 20.6).abs() < 0.05, "{moved:?}");
    assert!((pitch - 5.59).abs() < 0.01, "{pitch}°");
}
