//! Rigid bodies against their closed forms for every integrator (PHYSICS.md §1 "Time integration", §5): the torque-free
//! symmetric top and intermediate-axis flip, the thin pole, the heavy symmetric top and the
//! compound pendulum.

use tether_test_support as common;

use approx::assert_relative_eq;
use nalgebra::Vector3;
use tether_physics::world::World;

type V = Vector3<f64>;

/// One free body of unit mass with principal moments `inertia` spinning at `omega` (world
/// axes, which are the principal axes here), no gravity; dopri45 at rtol 1e-10, atol 1e-12.
fn spinning(inertia: [f64; 3], omega: [f64; 3], integrator: &str, dt: f64) -> World {
    let adaptive = if integrator == "dopri45" { "adaptive: (rtol: 1e-10, atol: 1e-12)," } else { "" };
    common::scene(&format!(
        "Scene(gravity: (0, 0, 0), dt: {dt:e}, integrator: {integrator}, {adaptive} bodies: [Body(name: \"b\",
            master: Node(position: (0, 0, 0), mass: 1.0, inertia: Inertia(xx: {:e}, yy: {:e}, zz: {:e})),
            angular_velocity: ({:e}, {:e}, {:e}), shape: Sphere(radius: 0.1))])",
        inertia[0], inertia[1], inertia[2], omega[0], omega[1], omega[2]
    ))
    .world
}

/// Angular momentum in the world [kg·m²/s].
fn momentum(world: &World) -> V {
    let s = world.state(0);
    s.orientation * world.bodies()[0].principal_moments().component_mul(&s.angular_velocity)
}

/// Times at which the body-frame ω about the intermediate axis changes sign, to `until` [s].
fn flips(integrator: &str, dt: f64, until: f64) -> Vec<f64> {
    let mut world = spinning([1.0, 2.0, 3.0], [0.05, 1.0, 0.0], integrator, dt);
    // I = (1, 2, 3): E = ½(1·0.05² + 2·1²) = 1.00125 J, |L| = √(0.05² + 2²).
    assert_relative_eq!(world.energy().kinetic, 1.00125, max_relative = 1e-14);
    assert_relative_eq!(momentum(&world).norm(), 2.00062490237, max_relative = 1e-11);
    let mut previous = world.state(0).angular_velocity.y;
    let mut times = Vec::new();
    while world.time() < until {
        world.step().unwrap();
        let w2 = world.state(0).angular_velocity.y;
        if w2.signum() != previous.signum() {
            times.push(world.time() - dt * w2 / (w2 - previous));
        }
        previous = w2;
    }
    times
}

/// Intermediate-axis flip, I = (1, 2, 3), ω0 = (0.05, 1, 0): ω2 reverses first at 7.5862365 s,
/// then every 15.1724730133 s. The leapfrog's first flip is late by 1.5e-3 s at dt = 1e-3
/// (first order: 7.5e-4 s at 5e-4); the leapfrog2's period is within 6e-7 s, and second order.
#[test]
fn intermediate_axis_flip_leapfrogs() {
    let (first, half_period) = (7.5862365, 15.1724730133);
    let leapfrog = [flips("leapfrog", 1e-3, 25.0), flips("leapfrog", 5e-4, 25.0)];
    let errors = leapfrog.map(|f| f[0] - first);
    assert!(errors[0].abs() < 2e-3, "leapfrog first flip error {}", errors[0]);
    assert_relative_eq!(errors[0] / errors[1], 2.0, max_relative = 0.1);

    let leapfrog2 = [flips("leapfrog2", 1e-3, 25.0), flips("leapfrog2", 5e-4, 25.0)];
    assert!((leapfrog2[0][0] - first).abs() < 1e-6, "{:?}", leapfrog2[0]);
    let period_errors = leapfrog2.map(|f| f[1] - f[0] - half_period);
    assert!(period_errors[0].abs() < 1e-6, "leapfrog2 period error {}", period_errors[0]);
    let order = (period_errors[0] / period_errors[1]).log2();
    assert!((order - 2.0).abs() < 0.2, "leapfrog2 order {order}");
}

/// The flip with the splitting, RK4 and Dormand–Prince at dt = 1e-3 (dopri45 at rtol 1e-10):
/// first flip and half period within the crossing interpolation's error (the sign change is
/// located linearly, O(ω̇ dt²) ≈ 1e-7 s).
#[test]
fn intermediate_axis_flip_other_integrators() {
    let (first, half_period) = (7.5862365, 15.1724730133);
    // Measured errors at dt = 1e-3: splitting 3.2e-7 / 6.3e-7 s, rk4 and dopri45 6.6e-9 / 1.7e-10 s.
    for (integrator, tolerance) in [("splitting", 1e-6), ("rk4", 2e-7), ("dopri45", 2e-7)] {
        let times = flips(integrator, 1e-3, 25.0);
        assert!((times[0] - first).abs() < tolerance, "{integrator}: first flip {}", times[0]);
        assert!(
            (times[1] - times[0] - half_period).abs() < tolerance,
            "{integrator}: half period {}",
            times[1] - times[0]
        );
    }
}

/// Thin pole I = (0.01, 1, 1), ω0 = (5, 1, 0), 50 s at dt = 1e-3: the leapfrog's lagged
/// gyroscopic term grows |L| by ×1.84; the leapfrog2 keeps it within 1e-5; the splitting (every
/// sub-flow turns π), RK4 and Dormand–Prince (L is integrated, and constant) to round-off;
/// and every one but the leapfrog keeps the energy bounded.
#[test]
fn thin_pole_extreme() {
    let run = |integrator: &str| {
        let mut world = spinning([0.01, 1.0, 1.0], [5.0, 1.0, 0.0], integrator, 1e-3);
        let (start, energy) = (momentum(&world).norm(), world.energy().kinetic);
        let mut worst = 0.0_f64;
        for _ in 0..50_000 {
            world.step().unwrap();
            worst = worst.max((world.energy().kinetic / energy - 1.0).abs());
        }
        (momentum(&world).norm() / start, worst)
    };
    assert_relative_eq!(run("leapfrog").0, 1.84, max_relative = 0.01);
    // Measured: |L| of the splitting within 1.4e-14, of RK4 9.6e-12 (L is exact, its round trip
    // through ω is not), of dopri45 1.4e-11; energy deviation leapfrog2 1.2e-5, splitting
    // 1.6e-8, rk4 1.3e-11, dopri45 2.6e-11.
    for (integrator, momentum_tolerance, energy_tolerance) in
        [("leapfrog2", 1e-5, 3e-5), ("splitting", 1e-13, 1e-7), ("rk4", 1e-10, 1e-10), ("dopri45", 1e-10, 1e-8)]
    {
        let (growth, energy) = run(integrator);
        assert_relative_eq!(growth, 1.0, epsilon = momentum_tolerance);
        assert!(energy < energy_tolerance, "{integrator}: energy deviation {energy}");
    }
}

/// Torque-free symmetric top, I⊥ = 2, I3 = 1, ω0 = (0.5, 0, 3), dt = 1e-3, 10 s: in the body,
/// ω precesses about the symmetry axis at (I3 − I⊥)/I⊥ ω3 = −1.5 rad/s; in the world the
/// symmetry axis precesses about L at |L|/I⊥ = 1.58113883008 rad/s on a cone of half-angle
/// atan(I⊥ ω⊥ / (I3 ω3)) = 18.43494882°. Returns the largest relative cone-angle error and the
/// two mean precession rates.
fn symmetric_top(integrator: &str) -> (f64, f64, f64) {
    let dt = 1e-3;
    let mut world = spinning([2.0, 2.0, 1.0], [0.5, 0.0, 3.0], integrator, dt);
    // The symmetry axis is the principal axis of the distinct moment (I = 1).
    let moments = world.bodies()[0].principal_moments();
    let sym = (0..3).find(|&i| (moments[i] - 1.0).abs() < 1e-12).unwrap();
    let (a, b) = ((sym + 1) % 3, (sym + 2) % 3);
    let l = momentum(&world);
    let axis_world = |w: &World| w.state(0).orientation * V::ith(sym, 1.0);
    // Azimuth of the symmetry axis about L, and of ω⊥ about the symmetry axis (body frame).
    let (e1, e2) = {
        let n = l.normalize();
        let e1 = (axis_world(&world) - n * n.dot(&axis_world(&world))).normalize();
        (e1, n.cross(&e1))
    };
    let (mut body_angle, mut world_angle, mut cone_error) = (0.0_f64, 0.0_f64, 0.0_f64);
    let mut previous = (world.state(0).angular_velocity, axis_world(&world));
    let omega_sym = world.state(0).angular_velocity[sym];
    assert_relative_eq!(omega_sym.abs(), 3.0, max_relative = 1e-12);
    for _ in 0..10_000 {
        world.step().unwrap();
        let (omega, axis) = (world.state(0).angular_velocity, axis_world(&world));
        let angle = |w: &V| w[b].atan2(w[a]);
        body_angle += wrap(angle(&omega) - angle(&previous.0));
        world_angle += wrap(axis.dot(&e2).atan2(axis.dot(&e1)) - previous.1.dot(&e2).atan2(previous.1.dot(&e1)));
        let cone = axis.dot(&l.normalize()).acos().to_degrees();
        cone_error = cone_error.max((cone / 18.43494882 - 1.0).abs());
        previous = (omega, axis);
    }
    // The sign of the body rate follows the sign of ω3 along the chosen principal axis.
    (cone_error, body_angle / world.time() * omega_sym.signum(), world_angle / world.time())
}

/// The symmetric top with every second- and higher-order integrator. Tolerances are relative:
/// second order, (ω dt)² ≈ 1e-5 (measured cone errors 1.0e-6 leapfrog2, 7e-7 splitting); the
/// rates are averaged over 10 s, so they carry the azimuth's start and end offsets (1e-6).
#[test]
fn symmetric_top_precession() {
    for (integrator, cone_tolerance, rate_tolerance) in
        [("leapfrog2", 1e-5, 1e-6), ("splitting", 1e-5, 1e-6), ("rk4", 1e-9, 1e-6), ("dopri45", 1e-8, 1e-6)]
    {
        let (cone_error, body_rate, world_rate) = symmetric_top(integrator);
        assert!(cone_error < cone_tolerance, "{integrator}: cone angle error {cone_error}");
        assert_relative_eq!(body_rate, -1.5, max_relative = rate_tolerance);
        assert_relative_eq!(world_rate, 1.58113883008, max_relative = rate_tolerance);
    }
}

fn wrap(angle: f64) -> f64 {
    (angle + std::f64::consts::PI).rem_euclid(2.0 * std::f64::consts::PI) - std::f64::consts::PI
}

/// Period of a compound pendulum: a 1 m, 1 kg rod (I_G = 1/12 kg·m²) on a penalty pivot at its
/// end (a zero-length spring k = 1e7 N/m to the world origin), released at rest from `amplitude`
/// [°], g = 9.81. Measured between the first and fourth upward zero crossings of the angle.
fn pendulum_period(amplitude: f64) -> f64 {
    let (theta, dt) = (amplitude.to_radians(), 1e-4);
    let u = V::new(theta.sin(), 0.0, -theta.cos());
    let g = u * 0.5;
    // Rod inertia about G: (1/12)(E − u uᵀ) plus a small axial part, in world components.
    let tensor = (nalgebra::Matrix3::identity() - u * u.transpose()) / 12.0 + u * u.transpose() * 1e-4;
    let mut world = common::scene(&format!(
        "Scene(gravity: (0, 0, -9.81), dt: {dt:e}, integrator: leapfrog2, bodies: [Body(name: \"rod\",
            master: Node(position: ({:e}, 0, {:e}), mass: 1.0, inertia: Inertia(xx: {:e}, yy: {:e}, zz: {:e}, xy: {:e}, yz: {:e}, xz: {:e})),
            shape: Cylinder(radius: 0.02, length: 1.0, axis: ({:e}, 0, {:e})))],
         couplings: [SpringDamper(name: \"pivot\", end1: World((0, 0, 0)), end2: Body(body: \"rod\", point: ({:e}, 0, {:e})),
            law: Linear(stiffness: 1e7, rest_length: 0.0))])",
        g.x, g.z, tensor[(0, 0)], tensor[(1, 1)], tensor[(2, 2)], tensor[(0, 1)], tensor[(1, 2)], tensor[(0, 2)], u.x, u.z, -g.x, -g.z
    ))
    .world;
    let angle = |w: &World| {
        let p = w.state(0).position;
        p.x.atan2(-p.z)
    };
    let mut previous = angle(&world);
    let mut crossings = Vec::new();
    // Four crossings take under four periods (4 s at 170°): a pendulum that stops fails.
    while crossings.len() < 4 {
        assert!(world.time() < 60.0, "{amplitude}°: {} crossings by t = 60 s", crossings.len());
        world.step().unwrap();
        let a = angle(&world);
        if previous < 0.0 && a >= 0.0 {
            crossings.push(world.time() - dt * a / (a - previous));
        }
        previous = a;
    }
    (crossings[3] - crossings[0]) / 3.0
}

/// Small amplitude: 2π√(I/(m g d)) = 1.63794658591 s; 90° → 1.93333485437 s; 170° →
/// 3.99554583849 s. The penalty pivot stretches by m g/k ≈ 1e-6 m, so 1e-5 relative.
#[test]
fn compound_pendulum_periods() {
    for (amplitude, period) in [(0.5, 1.63794658591), (90.0, 1.93333485437), (170.0, 3.99554583849)] {
        let measured = pendulum_period(amplitude);
        // At 0.5° the finite-amplitude correction is (θ0²/16) = 4.8e-6 of the period.
        let expected = if amplitude < 1.0 { period * (1.0 + amplitude.to_radians().powi(2) / 16.0) } else { period };
        assert_relative_eq!(measured, expected, max_relative = 1e-5);
    }
}

/// A heavy symmetric top: a disc R = 0.05 m, m = 0.5 kg (I3 = m R²/2, I⊥ = m R²/4 about G) whose
/// symmetry axis, tilted `theta` [rad] from the vertical toward +x, passes through a pivot at
/// the world origin 0.05 m below G: a penalty pivot (zero-length spring, k = 1e7 N/m). The
/// disc spins at `spin` [rad/s] about its axis and the axis precesses about z at `precession`
/// [rad/s] (G moves accordingly); g = 9.81.
fn heavy_top(integrator: &str, theta: f64, spin: f64, precession: f64, dt: f64) -> World {
    let (mass, radius, arm) = (0.5, 0.05, 0.05);
    let u = V::new(theta.sin(), 0.0, theta.cos());
    let (i3, i_perp) = (0.5 * mass * radius * radius, 0.25 * mass * radius * radius);
    let tensor = nalgebra::Matrix3::identity() * i_perp + u * u.transpose() * (i3 - i_perp);
    let g = u * arm;
    // ω = Ω z + ψ̇ u with ω·u = spin; v_G = ω × (G − pivot).
    let omega = V::z() * precession + u * (spin - precession * theta.cos());
    let v = omega.cross(&g);
    let adaptive = if integrator == "dopri45" { "adaptive: (rtol: 1e-10, atol: 1e-12)," } else { "" };
    common::scene(&format!(
        "Scene(gravity: (0, 0, -9.81), dt: {dt:e}, integrator: {integrator}, {adaptive} bodies: [Body(name: \"top\",
            master: Node(position: ({:e}, 0, {:e}), mass: {mass:e}, inertia: Inertia(xx: {:e}, yy: {:e}, zz: {:e}, xy: {:e}, yz: {:e}, xz: {:e})),
            velocity: ({:e}, {:e}, {:e}), angular_velocity: ({:e}, {:e}, {:e}),
            shape: Cylinder(radius: {radius:e}, length: 0.01, axis: ({:e}, 0, {:e})))],
         couplings: [SpringDamper(name: \"pivot\", end1: World((0, 0, 0)), end2: Body(body: \"top\", point: ({:e}, 0, {:e})),
            law: Linear(stiffness: 1e7, rest_length: 0.0))])",
        g.x, g.z, tensor[(0, 0)], tensor[(1, 1)], tensor[(2, 2)], tensor[(0, 1)], tensor[(1, 2)], tensor[(0, 2)],
        v.x, v.y, v.z, omega.x, omega.y, omega.z, u.x, u.z, -g.x, -g.z
    ))
    .world
}

/// The heavy top's axis: (tilt from the vertical [rad], azimuth [rad]) of G seen from the pivot.
fn top_axis(world: &World) -> (f64, f64) {
    let p = world.state(0).position;
    (p.xy().norm().atan2(p.z), p.y.atan2(p.x))
}

/// Steady precession at spin ω3 = 200 rad/s, θ = 30°: the slow root of
/// `m g l = Ω (I3 ω3 − I⊥' Ω cos θ)` (I⊥' = I⊥ + m l² about the pivot) is Ω = 2.00554155917
/// rad/s. Started exactly on it, the axis keeps θ = 30° and turns at Ω; 1 s at dt = 1e-4.
#[test]
fn heavy_top_slow_precession() {
    let (theta, spin, precession): (f64, f64, f64) = (30f64.to_radians(), 200.0, 2.00554155917);
    let (mass, arm, i3, i_perp): (f64, f64, f64, f64) = (0.5, 0.05, 6.25e-4, 3.125e-4 + 0.5 * 0.05 * 0.05);
    let root = (i3 * spin - ((i3 * spin).powi(2) - 4.0 * i_perp * theta.cos() * mass * 9.81 * arm).sqrt())
        / (2.0 * i_perp * theta.cos());
    assert_relative_eq!(root, precession, max_relative = 1e-10);
    // Measured rate errors: leapfrog 1.6e-3 (its lagged gyroscopic term is first order in
    // ω dt), leapfrog2 6.8e-6, the others 4.4e-6 (the penalty pivot stretches by m g/k ≈ 5e-7 m
    // of 0.05 m); tilt within 1e-5 rad. The leapfrogs run at dt = 2e-5: at 1e-4 the leapfrog2's
    // predicted ω(t), fed by the stiff pivot's moment, diverges (see its module docs).
    for (integrator, dt, tolerance) in [
        ("leapfrog", 2e-5, 3e-3),
        ("leapfrog2", 2e-5, 2e-5),
        ("splitting", 1e-4, 2e-5),
        ("rk4", 1e-4, 2e-5),
        ("dopri45", 1e-4, 2e-5),
    ] {
        let mut world = heavy_top(integrator, theta, spin, precession, dt);
        let (mut azimuth, mut previous, mut tilt_error) = (0.0, top_axis(&world).1, 0.0_f64);
        while world.time() < 1.0 - 0.5 * dt {
            world.step().unwrap();
            let (tilt, now) = top_axis(&world);
            azimuth += wrap(now - previous);
            previous = now;
            tilt_error = tilt_error.max((tilt - theta).abs());
        }
        assert_relative_eq!(azimuth / world.time(), precession, max_relative = tolerance);
        let tilt_tolerance = if integrator == "leapfrog" { 5e-3 } else { 3e-5 };
        assert!(tilt_error < tilt_tolerance, "{integrator}: nutation {tilt_error} rad");
    }
}

/// A top spinning upright sleeps (stays upright) above ω3 = 2√(I⊥' m g l)/I3 = 62.6418390 rad/s
/// and falls below: tilted 0.02 rad at 1.05× it stays within 0.1 rad for 3 s, at 0.95× it
/// passes 0.5 rad.
#[test]
fn heavy_top_sleeping_threshold() {
    let threshold = 2.0 * ((3.125e-4 + 0.5 * 0.05 * 0.05) * 0.5 * 9.81 * 0.05_f64).sqrt() / 6.25e-4;
    assert_relative_eq!(threshold, 62.6418390, max_relative = 1e-9);
    for integrator in ["splitting", "rk4"] {
        let largest_tilt = |factor: f64| {
            let mut world = heavy_top(integrator, 0.02, factor * threshold, 0.0, 1e-4);
            (0..30_000)
                .map(|_| {
                    world.step().unwrap();
                    top_axis(&world).0
                })
                .fold(0.0_f64, f64::max)
        };
        let (above, below) = (largest_tilt(1.05), largest_tilt(0.95));
        assert!(above < 0.1, "{integrator}: a sleeping top tilted to {above} rad");
        assert!(below > 0.5, "{integrator}: a top below the threshold only tilted to {below} rad");
    }
}
