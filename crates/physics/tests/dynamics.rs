//! Closed-form and invariant checks of the leapfrog world (PHYSICS.md §5).

use tether_test_support as common;

use approx::assert_relative_eq;
use common::{oscillator, scene};

/// Leapfrog error against a closed form `exact` at t = 0.5 and 1 s, at time step `dt`.
fn oscillator_errors(damping: f64, dt: f64, exact: &dyn Fn(f64) -> f64) -> [f64; 2] {
    let mut world = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", damping, 1.01, 0.0, dt).world;
    let mut errors = [0.0; 2];
    for (slot, t) in [(0, 0.5), (1, 1.0)] {
        while world.time() < t - 0.5 * dt {
            world.step().unwrap();
        }
        errors[slot] = world.state(0).position.x - 1.0 - exact(t);
    }
    errors
}

/// Errors at dt = 1e-3 below `tolerance` [m], and the order measured against dt = 5e-4
/// within 0.1 of `order`.
fn assert_convergence(damping: f64, exact: &dyn Fn(f64) -> f64, tolerance: f64, order: f64) {
    let coarse = oscillator_errors(damping, 1e-3, exact);
    let fine = oscillator_errors(damping, 5e-4, exact);
    for i in 0..2 {
        assert!(coarse[i].abs() < tolerance, "error {} at dt = 1e-3", coarse[i]);
        let observed = (coarse[i] / fine[i]).abs().log2();
        assert!((observed - order).abs() < 0.1, "observed order {observed}, expected {order}");
    }
}

/// `x(t)` of the spring-mass-damper m = 1, k = 100, ζ = 0.05 released at rest from 0.01 m.
/// The leapfrog of PHYSICS.md §1 (as Radioss) feeds the damper `v(t−½dt)`, so the damping force — and the
/// solution — is first-order accurate: halving dt halves the error. Tolerance at dt = 1e-3:
/// 2e-5 m (measured 9.3e-6 m).
#[test]
fn spring_mass_damper_matches_the_closed_form_at_first_order() {
    let (omega0, zeta, x0) = (10.0_f64, 0.05_f64, 0.01_f64);
    let omega_d = omega0 * (1.0 - zeta * zeta).sqrt();
    let exact = |t: f64| {
        (-zeta * omega0 * t).exp() * (x0 * (omega_d * t).cos() + zeta * omega0 * x0 / omega_d * (omega_d * t).sin())
    };
    // Reference values of the closed form, checked against the formula first.
    assert_relative_eq!(exact(0.5), 1.787858062988e-3, max_relative = 1e-11);
    assert_relative_eq!(exact(1.0), -5.292088189070e-3, max_relative = 1e-11);
    assert_convergence(2.0 * zeta * omega0, &exact, 2e-5, 1.0);
}

/// Without the damper the same oscillator is second order: x(t) = x0 cos(ω t), error at
/// dt = 1e-3 below (ω dt)² x0 = 1e-6 m (measured 2.0e-7 and 2.3e-7 m), quartered by halving dt.
#[test]
fn undamped_spring_mass_is_second_order() {
    assert_convergence(0.0, &|t: f64| 0.01 * (10.0 * t).cos(), 1e-6, 2.0);
}

/// Duffing oscillator `f = −x − x³` (polynomial law a = 1, c = 1), m = 1, amplitude 1:
/// period 4.76802202910 s, from upward zero crossings.
#[test]
fn duffing_period() {
    let dt = 1e-4;
    let mut world = oscillator("Polynomial(a: 1.0, b: 0.0, c: 1.0, rest_length: 2.0)", 0.0, 3.0, 0.0, dt).world;
    let mut crossings = Vec::new();
    let mut previous = world.state(0).position.x - 2.0;
    // Four crossings take under four periods: an oscillator that stops fails.
    while crossings.len() < 4 {
        assert!(world.time() < 60.0, "{} crossings by t = 60 s", crossings.len());
        world.step().unwrap();
        let s = world.state(0).position.x - 2.0;
        if previous < 0.0 && s >= 0.0 {
            crossings.push(world.time() - dt * s / (s - previous));
        }
        previous = s;
    }
    let period = (crossings[3] - crossings[0]) / 3.0;
    assert_relative_eq!(period, 4.76802202910, max_relative = 1e-7);
}

/// Undamped spring, ω dt = 0.1, 10⁴ periods: the leapfrog's energy error oscillates, bounded
/// by (ω dt)²/4 of the energy (it conserves ½v² + ½ω²x²(1 − (ω dt)²/4) exactly), and is no
/// larger at the end than in the first periods.
#[test]
fn leapfrog_energy_has_no_trend_over_ten_thousand_periods() {
    let dt = 0.01;
    let mut world = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", 0.0, 1.1, 0.0, dt).world;
    let e0 = world.energy().balance();
    let period = 2.0 * std::f64::consts::PI / 10.0;
    let steps = (1e4 * period / dt) as usize;
    let early_window = (10.0 * period / dt) as usize;
    let (mut early, mut late) = (0.0_f64, 0.0_f64);
    for step in 0..steps {
        world.step().unwrap();
        let deviation = (world.energy().balance() - e0).abs() / e0;
        if step < early_window {
            early = early.max(deviation);
        } else if step >= steps - early_window {
            late = late.max(deviation);
        }
    }
    assert!(early > 0.0 && early <= 1.001 * 0.1 * 0.1 / 4.0, "early deviation {early}");
    assert!(late <= 1.05 * early, "energy drifted: early {early}, late {late}");
}

/// Two free spinning bodies joined by a damped spring: total linear momentum is conserved to
/// round-off, and energy + dissipated work is conserved to the scheme's accuracy.
#[test]
fn two_bodies_conserve_momentum_and_energy_balance() {
    let mut world = scene(
        "Scene(gravity: (0.0, 0.0, 0.0), dt: 1e-4, bodies: [
            Body(name: \"a\", master: Node(position: (0, 0, 0), mass: 2.0, inertia: Inertia(xx: 0.1, yy: 0.2, zz: 0.3)),
                 velocity: (0.3, -0.2, 0.1), angular_velocity: (1.0, 2.0, -0.5), shape: Box(size: (0.2, 0.3, 0.4))),
            Body(name: \"b\", master: Node(position: (1.0, 0.2, 0.1), mass: 3.0, inertia: Inertia(xx: 0.2, yy: 0.2, zz: 0.1)),
                 velocity: (-0.1, 0.4, 0.0), angular_velocity: (0.0, -1.0, 3.0), shape: Sphere(radius: 0.2)),
        ], couplings: [
            SpringDamper(name: \"s\", end1: Body(body: \"a\", point: (0.1, 0.1, 0.0)), end2: Body(body: \"b\", point: (-0.1, 0.0, 0.1)),
                         law: Linear(stiffness: 500.0, rest_length: 0.8), damping: 3.0),
        ])",
    )
    .world;
    let momentum = |w: &tether_physics::world::World| -> nalgebra::Vector3<f64> {
        (0..2).map(|i| w.state(i).velocity * w.bodies()[i].mass()).sum()
    };
    let p0 = momentum(&world);
    let e0 = world.energy().balance();
    for _ in 0..20_000 {
        world.step().unwrap();
    }
    assert_relative_eq!(momentum(&world), p0, epsilon = 1e-13);
    let energy = world.energy();
    assert!(energy.dissipated > 0.01, "the damper worked: {}", energy.dissipated);
    // Balance error at dt = 1e-4 over 2 s of spinning bodies: measured ≈ 1e-5 of e0.
    assert_relative_eq!(energy.balance(), e0, max_relative = 1e-4);
}

/// Kinematic body pulling a mass through a spring: the driver's work enters the balance.
#[test]
fn prescribed_motion_work_closes_the_energy_balance() {
    let mut world = scene(
        "Scene(gravity: (0.0, 0.0, -9.81), dt: 1e-4, bodies: [
            Body(name: \"tug\", master: Node(position: (0, 0, 0), mass: 1.0, inertia: Inertia(xx: 1, yy: 1, zz: 1)),
                 support: Kinematic(velocity: Table([(0.0, (0, 0, 0)), (1.0, (1.0, 0, 0.5))]), angular_velocity: (0, 0, 0.3)),
                 shape: Box(size: (1, 1, 1))),
            Body(name: \"load\", master: Node(position: (-1.0, 0, -0.5), mass: 5.0, inertia: Inertia(xx: 0.5, yy: 0.5, zz: 0.5)),
                 shape: Sphere(radius: 0.2)),
        ], couplings: [
            SpringDamper(name: \"rope\", end1: Body(body: \"tug\", point: (0.5, 0, 0)), end2: Body(body: \"load\"),
                         law: Linear(stiffness: 2000.0, rest_length: 1.0), damping: 10.0),
        ])",
    )
    .world;
    let e0 = world.energy().balance();
    for _ in 0..30_000 {
        world.step().unwrap();
    }
    let energy = world.energy();
    assert!(energy.external_work > 1.0, "the tug did work: {}", energy.external_work);
    assert_relative_eq!(energy.balance(), e0, epsilon = 1e-3 * energy.external_work);
    // The tug is where its table says: x = ∫v = 0.5 + 2·1 m at t = 3 s.
    assert_relative_eq!(world.state(0).position.x, 2.5, epsilon = 1e-9);
}

/// A driver moved harmonically, `x = 3 + A (sin(ωt + φ) − sin φ)` (A = 0.5 m, T = 2 s,
/// φ = 0.7 rad), stretches a spring-damper (k = 400 N/m, rest 2.5 m, c = 20 N·s/m) from a world
/// point, under every integrator: the driver is where the closed form puts it, and the work the
/// ledger books for it is the closed form `W(t) = ½ k [(l − L0)² − (l(0) − L0)²] + c A² ω²
/// [t/2 + (sin 2(ωt + φ) − sin 2φ) / (4ω)]` (the spring's energy gained plus what the damper
/// dissipated at v = A ω cos(ωt + φ)).
#[test]
fn harmonic_motion_books_the_closed_form_work() {
    let (amplitude, period, phase, start, k, rest, c) = (0.5_f64, 2.0_f64, 0.7_f64, 3.0_f64, 400.0, 2.5, 20.0);
    let omega = std::f64::consts::TAU / period;
    let length = |t: f64| start + amplitude * ((omega * t + phase).sin() - phase.sin());
    let dissipated = |t: f64| {
        c * (amplitude * omega).powi(2)
            * (t / 2.0 + ((2.0 * (omega * t + phase)).sin() - (2.0 * phase).sin()) / (4.0 * omega))
    };
    let work = |t: f64| 0.5 * k * ((length(t) - rest).powi(2) - (start - rest).powi(2)) + dissipated(t);
    let duration = 3.3;
    // The closed form's value, checked by hand: l(3.3) = 3 + 0.5 (sin(3.3π + 0.7) − sin 0.7).
    assert_relative_eq!(length(duration), 3.0 + 0.5 * ((3.3 * std::f64::consts::PI + 0.7).sin() - 0.7_f64.sin()));
    for integrator in ["leapfrog", "leapfrog2", "splitting", "rk4", "dopri45"] {
        let mut world = scene(&format!(
            "Scene(gravity: (0.0, 0.0, 0.0), dt: 1e-3, integrator: {integrator}, bodies: [
                Body(name: \"driver\", master: Node(position: ({start}, 0, 0), mass: 1.0, inertia: Inertia(xx: 1, yy: 1, zz: 1)),
                     support: Kinematic(velocity: Harmonic(amplitude: ({amplitude}, 0, 0), period: {period}, phase: ({phase}, 0, 0))),
                     shape: Sphere(radius: 0.2)),
            ], couplings: [
                SpringDamper(name: \"spring\", end1: World((0, 0, 0)), end2: Body(body: \"driver\"),
                             law: Linear(stiffness: {k}, rest_length: {rest}), damping: {c}),
            ])"
        ))
        .world;
        while world.time() < duration - 0.5e-3 {
            world.step().unwrap();
        }
        let t = world.time();
        assert_relative_eq!(t, duration, epsilon = 1e-9);
        let state = world.state(0);
        assert_relative_eq!(state.position.x, length(t), epsilon = 1e-12);
        assert_relative_eq!(state.velocity.x, amplitude * omega * (omega * t + phase).cos(), epsilon = 1e-12);
        let energy = world.energy();
        let (booked, exact) = (energy.external_work, work(t));
        // Measured at dt = 1e-3: 6.9e-7 relative for the leapfrogs and splitting (trapezoid rule of
        // the powers), 4e-13 for rk4, 1e-16 for dopri45.
        assert_relative_eq!(booked, exact, max_relative = 1e-5);
        assert_relative_eq!(energy.dissipated, dissipated(t), max_relative = 1e-5);
    }
}

/// `reset` puts the world back at t = 0 exactly as built.
#[test]
fn reset_returns_to_the_initial_state() {
    let fresh = scene(&std::fs::read_to_string(common::repo("scenes/suspension.ron")).unwrap()).world;
    let mut world = fresh.clone();
    for _ in 0..500 {
        world.step().unwrap();
    }
    assert!(world.state(1).position != fresh.state(1).position);
    world.reset().unwrap();
    assert_eq!(world.time(), 0.0);
    assert_eq!(world.steps(), 0);
    for i in 0..2 {
        assert_eq!(world.state(i), fresh.state(i));
    }
    assert_eq!(world.energy(), fresh.energy());
}
