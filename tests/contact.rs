//! Face-based penalty contact (PHYSICS.md §4): impacts, rest, friction, body–body momentum.
//! Tolerances are stated for the time steps used.

mod common;

use approx::assert_relative_eq;
use common::scene;
use tether::physics::world::World;
use tether::physics::{Mat3, Vec3};

/// A 1 kg, 0.1 m box (bottom area A = 0.01 m²) at height `z` of its centre, falling at `vz`,
/// on the ground plane z = 0 with A·k1 = 1e5 N/m, damping ratio `zeta`, range d0 = 1 mm, friction
/// `mu` with sharpness `kt`, gravity `g`.
fn box_on_ground(z: f64, velocity: [f64; 3], zeta: f64, mu: f64, kt: f64, g: [f64; 3], dt: f64) -> World {
    let (m, area, k1): (f64, f64, f64) = (1.0, 0.01, 1e7);
    let k2 = 2.0 * zeta * (m * k1 / area).sqrt();
    scene(&format!(
        "Scene(gravity: ({:e}, {:e}, {:e}), dt: {dt:e}, bodies: [Body(name: \"box\",
            master: Node(position: (0.0, 0.0, {z:e}), mass: 1.0, inertia: Inertia(xx: 1.6666666666666667e-3, yy: 1.6666666666666667e-3, zz: 1.6666666666666667e-3)),
            velocity: ({:e}, {:e}, {:e}),
            shape: Box(size: (0.1, 0.1, 0.1)))],
        couplings: [Contact(name: \"ground\", body: \"box\", against: Plane(point: (0.0, 0.0, 0.0), normal: (0.0, 0.0, 1.0)),
            stiffness: {k1:e}, damping: {k2:e}, range: 0.001, friction: {mu:e}, friction_sharpness: {kt:e})])",
        g[0], g[1], g[2], velocity[0], velocity[1], velocity[2]
    ))
    .world
}

/// The time at which `f` (sampled after every step) first crosses zero from above, by linear
/// interpolation between steps; runs at most `max_steps`.
fn zero_crossing(world: &mut World, max_steps: usize, f: impl Fn(&World) -> f64) -> f64 {
    let (mut t0, mut f0) = (world.time(), f(world));
    for _ in 0..max_steps {
        world.step().expect("contact always gives a force");
        let (t1, f1) = (world.time(), f(world));
        if f0 > 0.0 && f1 <= 0.0 {
            return t0 + (t1 - t0) * f0 / (f0 - f1);
        }
        (t0, f0) = (t1, f1);
    }
    panic!("no zero crossing in {max_steps} steps");
}

#[test]
fn an_undamped_box_stops_in_the_stopping_time() {
    // τ = (π/2)√(m/(A k1)) = 4.96729e-3 s from first push (bottom at d0) to rest.
    let dt = 1e-6;
    let mut world = box_on_ground(0.0515, [0.0, 0.0, -1.0], 0.0, 0.0, 100.0, [0.0; 3], dt);
    let touch = zero_crossing(&mut world, 10_000, |w| w.state(0).position.z - 0.05 - 0.001);
    let rest = zero_crossing(&mut world, 10_000, |w| -w.state(0).velocity.z);
    assert_relative_eq!(rest - touch, 4.96729e-3, max_relative = 1e-5);
}

/// Rebound coefficient `|v_out|/|v_in|` of a box dropped at 1 m/s without gravity.
fn rebound(zeta: f64, dt: f64) -> f64 {
    let mut world = box_on_ground(0.0515, [0.0, 0.0, -1.0], zeta, 0.0, 100.0, [0.0; 3], dt);
    // Run until the box has left the range again (bottom above d0).
    while world.state(0).velocity.z < 0.0 || world.state(0).position.z < 0.0515 {
        world.step().expect("contact always gives a force");
    }
    world.state(0).velocity.z
}

#[test]
fn rebound_coefficients_match_the_clamped_damped_oscillator() {
    // Closed form of x'' + 2ζω x' + ω² x = 0 with the force clamped at ≥ 0: the box leaves
    // when the force vanishes, not when it is back at d0. The damping force jumps to k2·A·v at
    // first touch, so the error is first order with a sign that depends on where in a step the
    // touch falls: measured |Δe| ≤ 1.5e-4 at dt = τ/2000 and ≤ 6e-4 at dt = τ/125.
    for (zeta, exact) in [(0.1, 0.7440794), (0.3, 0.4509755)] {
        let fine = rebound(zeta, 2.5e-6);
        assert!((fine - exact).abs() < 2e-4, "ζ = {zeta}, dt = 2.5e-6 s: e = {fine}, exact {exact}");
        let coarse = rebound(zeta, 4e-5);
        assert!((coarse - exact).abs() < 1e-3, "ζ = {zeta}, dt = 4e-5 s: e = {coarse}, exact {exact}");
    }
}

#[test]
fn a_resting_box_sinks_by_its_weight_over_the_contact_stiffness() {
    // Critically damped; after 1 s the bottom is m g/(A k1) = 9.81e-5 m inside the range d0.
    let g = 9.81;
    let mut world = box_on_ground(0.0509, [0.0; 3], 1.0, 0.0, 100.0, [0.0, 0.0, -g], 1e-4);
    for _ in 0..10_000 {
        world.step().expect("contact always gives a force");
    }
    let bottom = world.state(0).position.z - 0.05;
    assert_relative_eq!(0.001 - bottom, g / 1e5, max_relative = 1e-9);
    assert_relative_eq!(world.coupling_forces()[0].tension, g, max_relative = 1e-9);
}

/// Velocity along x of a box on an incline of `theta` (gravity tilted by θ about y) with
/// friction `mu`, sharpness `kt`, starting at `v0` down the slope; returns (t, v) samples.
fn incline(theta: f64, mu: f64, kt: f64, v0: f64, dt: f64, duration: f64) -> Vec<(f64, f64)> {
    let g = 9.81;
    let gravity = [g * theta.sin(), 0.0, -g * theta.cos()];
    let rest = 0.05 + 0.001 - g * theta.cos() / 1e5;
    let mut world = box_on_ground(rest, [v0, 0.0, 0.0], 1.0, mu, kt, gravity, dt);
    let mut samples = Vec::new();
    while world.time() < duration {
        world.step().expect("contact always gives a force");
        samples.push((world.time(), world.state(0).velocity.x));
    }
    samples
}

#[test]
fn a_box_slides_down_a_30_degree_incline_at_g_sin_minus_mu_cos() {
    // θ = 30°, μ = 0.3, k_t = 1e4 s/m (tanh saturated above a few mm/s): a = 2.35628723666 m/s².
    let samples = incline(30f64.to_radians(), 0.3, 1e4, 0.5, 1e-5, 0.2);
    let (t0, v0) = samples[samples.len() / 2];
    let (t1, v1) = samples[samples.len() - 1];
    assert_relative_eq!((v1 - v0) / (t1 - t0), 2.35628723666, max_relative = 1e-6);
}

#[test]
fn a_box_on_a_20_degree_incline_creeps_at_the_tanh_velocity() {
    // θ = 20°, μ = 0.5 > tan θ: the tanh law creeps at v* = atanh(tan θ/μ)/k_t.
    let samples = incline(20f64.to_radians(), 0.5, 1000.0, 0.0, 1e-4, 0.5);
    let (_, v) = samples[samples.len() - 1];
    assert_relative_eq!(v, 9.2433229483e-4, max_relative = 1e-6);
}

/// Linear momentum [kg·m/s] and angular momentum about the origin [kg·m²/s] of every body.
fn momenta(world: &World) -> (Vec3, Vec3) {
    (0..world.bodies.len()).fold((Vec3::zeros(), Vec3::zeros()), |(p, l), i| {
        let (body, state) = (&world.bodies[i], world.state(i));
        let inertia = Mat3::from_diagonal(&body.principal_moments());
        let spin = state.orientation * (inertia * state.angular_velocity);
        (p + state.velocity * body.mass(), l + state.position.cross(&(state.velocity * body.mass())) + spin)
    })
}

/// Two balls (isotropic inertia) in an oblique collision with friction `mu` and damping
/// `damping`, no gravity.
fn two_balls(mu: f64, damping: f64) -> World {
    scene(&format!(
        "Scene(gravity: (0.0, 0.0, 0.0), dt: 1e-5, bodies: [
            Body(name: \"a\", master: Node(position: (0.0, 0.0, 0.0), mass: 2.0, inertia: Inertia(xx: 0.008, yy: 0.008, zz: 0.008)),
                velocity: (1.0, 0.2, 0.0), angular_velocity: (0.0, 0.0, 3.0), shape: Sphere(radius: 0.1, subdivisions: 3)),
            Body(name: \"b\", master: Node(position: (0.3, 0.06, 0.02), mass: 1.0, inertia: Inertia(xx: 0.004, yy: 0.004, zz: 0.004)),
                velocity: (-0.5, 0.0, 0.1), shape: Sphere(radius: 0.1, subdivisions: 3))],
        couplings: [Contact(name: \"ab\", body: \"a\", against: Body(\"b\"), stiffness: 1e7, damping: {damping:e}, range: 0.002, friction: {mu:e}, friction_sharpness: 100.0)])"
    ))
    .world
}

#[test]
fn a_collision_with_friction_conserves_linear_and_angular_momentum() {
    let mut world = two_balls(0.5, 2000.0);
    let (p0, l0) = momenta(&world);
    let mut touched = false;
    for _ in 0..20_000 {
        world.step().expect("contact always gives a force");
        touched |= world.coupling_forces()[0].tension > 0.0;
    }
    assert!(touched, "the balls must collide");
    assert!(world.energy().dissipated > 1e-3, "friction and damping must dissipate");
    // Round-off over 20,000 steps (x × m v drifts by ~3e-15 per 1000 steps in free flight
    // alone): 1e-12 of p, 1e-11 of L.
    let (p, l) = momenta(&world);
    assert_relative_eq!(p, p0, epsilon = 1e-12 * p0.norm());
    assert_relative_eq!(l, l0, epsilon = 1e-11 * l0.norm());
}

#[test]
fn without_damping_or_friction_a_collision_never_gains_energy() {
    // The leapfrog's energy error is bounded (here by 1e-5 of the kinetic energy at dt = 1e-5 s).
    let mut world = two_balls(0.0, 0.0);
    let e0 = world.energy().total();
    let mut highest = e0;
    for _ in 0..20_000 {
        world.step().expect("contact always gives a force");
        highest = highest.max(world.energy().total());
    }
    assert!(highest <= e0 * (1.0 + 1e-5), "energy rose from {e0} to {highest}");
    assert_relative_eq!(world.energy().total(), e0, max_relative = 1e-5);
    assert_eq!(world.energy().dissipated, 0.0);
}

#[test]
fn with_friction_the_energy_balance_holds_and_energy_falls() {
    let mut world = two_balls(0.5, 0.0);
    let e0 = world.energy().total();
    for _ in 0..20_000 {
        world.step().expect("contact always gives a force");
    }
    let e = world.energy();
    assert!(e.total() < e0 * (1.0 - 1e-3), "friction must take energy out: {} → {}", e0, e.total());
    assert_relative_eq!(e.balance(), e0, max_relative = 1e-4);
}

#[test]
fn a_ball_in_a_domain_box_bounces_off_every_wall_it_meets() {
    // Undamped walls: the ball leaves each wall at the speed it came (leapfrog, dt = 1e-5 s).
    let mut world = scene(
        "Scene(gravity: (0.0, 0.0, 0.0), dt: 1e-5, bodies: [Body(name: \"ball\",
            master: Node(position: (0.0, 0.0, 0.0), mass: 1.0, inertia: Inertia(xx: 0.004, yy: 0.004, zz: 0.004)),
            velocity: (2.0, -1.0, 0.5), shape: Sphere(radius: 0.1))],
        couplings: [Contact(name: \"walls\", body: \"ball\", against: DomainBox(min: (-0.5, -0.5, -0.5), max: (0.5, 0.5, 0.5)), stiffness: 1e7)])",
    )
    .world;
    for _ in 0..200_000 {
        world.step().expect("contact always gives a force");
        let p = world.state(0).position;
        assert!(p.abs().max() < 0.5, "the ball left the domain at {p:?}");
    }
    let v = world.state(0).velocity;
    assert_relative_eq!(v.abs(), Vec3::new(2.0, 1.0, 0.5), max_relative = 1e-3);
    assert!(v.x < 0.0 || v.y > 0.0, "the ball must have bounced: {v:?}");
}
