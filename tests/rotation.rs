//! Torque-free rigid bodies against their closed forms, for the leapfrog (first order in
//! rotation) and the leapfrog2 (second order) — part of issue 5.

mod common;

use approx::assert_relative_eq;
use nalgebra::Vector3;
use tether::physics::world::World;

type V = Vector3<f64>;

/// One free body of unit mass with principal moments `inertia` spinning at `omega` (world
/// axes, which are the principal axes here), no gravity.
fn spinning(inertia: [f64; 3], omega: [f64; 3], integrator: &str, dt: f64) -> World {
    common::scene(&format!(
        "Scene(gravity: (0, 0, 0), dt: {dt:e}, integrator: {integrator}, bodies: [Body(name: \"b\",
            master: Node(position: (0, 0, 0), mass: 1.0, inertia: Inertia(xx: {:e}, yy: {:e}, zz: {:e})),
            angular_velocity: ({:e}, {:e}, {:e}), shape: Sphere(radius: 0.1))])",
        inertia[0], inertia[1], inertia[2], omega[0], omega[1], omega[2]
    ))
    .world
}

/// Angular momentum in the world [kg·m²/s].
fn momentum(world: &World) -> V {
    let s = world.state(0);
    s.orientation * world.bodies[0].principal_moments().component_mul(&s.angular_velocity)
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
fn intermediate_axis_flip() {
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

/// Thin pole I = (0.01, 1, 1), ω0 = (5, 1, 0), 50 s at dt = 1e-3: the leapfrog's lagged
/// gyroscopic term grows |L| by ×1.84; the leapfrog2 keeps it within 1e-5.
#[test]
fn thin_pole_extreme() {
    let growth = |integrator: &str| {
        let mut world = spinning([0.01, 1.0, 1.0], [5.0, 1.0, 0.0], integrator, 1e-3);
        let start = momentum(&world).norm();
        for _ in 0..50_000 {
            world.step().unwrap();
        }
        momentum(&world).norm() / start
    };
    assert_relative_eq!(growth("leapfrog"), 1.84, max_relative = 0.01);
    assert_relative_eq!(growth("leapfrog2"), 1.0, epsilon = 1e-5);
}

/// Torque-free symmetric top, I⊥ = 2, I3 = 1, ω0 = (0.5, 0, 3) (leapfrog2, dt = 1e-3, 10 s):
/// in the body, ω precesses about the symmetry axis at (I3 − I⊥)/I⊥ ω3 = −1.5 rad/s; in the
/// world the symmetry axis precesses about L at |L|/I⊥ = 1.58113883008 rad/s on a cone of
/// half-angle atan(I⊥ ω⊥ / (I3 ω3)) = 18.43494882°.
#[test]
fn symmetric_top_precession() {
    let dt = 1e-3;
    let mut world = spinning([2.0, 2.0, 1.0], [0.5, 0.0, 3.0], "leapfrog2", dt);
    // The symmetry axis is the principal axis of the distinct moment (I = 1).
    let moments = world.bodies[0].principal_moments();
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
    let (mut body_angle, mut world_angle) = (0.0_f64, 0.0_f64);
    let mut previous = (world.state(0).angular_velocity, axis_world(&world));
    let omega_sym = world.state(0).angular_velocity[sym];
    for _ in 0..10_000 {
        world.step().unwrap();
        let (omega, axis) = (world.state(0).angular_velocity, axis_world(&world));
        let angle = |w: &V| w[b].atan2(w[a]);
        body_angle += wrap(angle(&omega) - angle(&previous.0));
        world_angle += wrap(axis.dot(&e2).atan2(axis.dot(&e1)) - previous.1.dot(&e2).atan2(previous.1.dot(&e1)));
        let cone = axis.dot(&l.normalize()).acos().to_degrees();
        // Second order: (ω dt)² ≈ 1e-5 at dt = 1e-3 (measured 1.0e-6 relative).
        assert_relative_eq!(cone, 18.43494882, max_relative = 1e-5);
        previous = (omega, axis);
    }
    assert_relative_eq!(body_angle / world.time(), (1.0 - 2.0) / 2.0 * omega_sym, max_relative = 1e-6);
    assert_relative_eq!((body_angle / world.time()).abs(), 1.5, max_relative = 1e-6);
    assert_relative_eq!(world_angle / world.time(), 1.58113883008, max_relative = 1e-6);
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
    while crossings.len() < 4 {
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
