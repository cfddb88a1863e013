//! Face-based penalty contact (PHYSICS.md §4): impacts, rest, friction, body–body momentum.
//! Tolerances are stated for the time steps used.

use tether_test_support as common;

use approx::assert_relative_eq;
use common::scene;
use tether_physics::coupling::CouplingKind;
use tether_physics::math::{Mat3, Vec3};
use tether_physics::world::World;

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
    // Run until the box has left the range again (bottom above d0): within milliseconds, so a
    // box that never comes back fails at 1 s instead of running for ever.
    while world.state(0).velocity.z < 0.0 || world.state(0).position.z < 0.0515 {
        assert!(world.time() < 1.0, "ζ = {zeta}, dt = {dt}: no rebound by t = 1 s");
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
    (0..world.bodies().len()).fold((Vec3::zeros(), Vec3::zeros()), |(p, l), i| {
        let (body, state) = (&world.bodies()[i], world.state(i));
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

/// The normal force and friction a contact keeps from its step are those of its faces
/// evaluated again one by one: against two walls at once (where the friction comes from the
/// sums, `Σ f_f − Σ_p n_p N_p`, not from a sum over the faces) and against another body.
#[test]
fn a_contact_keeps_the_forces_its_step_summed() {
    // A spinning ball thrown into the corner of the walls x = 0.5 and y = 0.5 m, meeting both at
    // once (the same distance to go at the same speed along x and y).
    let corner = scene(
        "Scene(gravity: (0.0, 0.0, 0.0), dt: 1e-5, bodies: [Body(name: \"ball\",
            master: Node(position: (0.38, 0.38, 0.0), mass: 1.0, inertia: Inertia(xx: 0.004, yy: 0.004, zz: 0.004)),
            velocity: (1.0, 1.0, 0.3), angular_velocity: (3.0, -2.0, 20.0), shape: Sphere(radius: 0.1))],
        couplings: [Contact(name: \"walls\", body: \"ball\", against: DomainBox(min: (-0.5, -0.5, -0.5), max: (0.5, 0.5, 0.5)),
            stiffness: 1e7, damping: 1e3, range: 0.005, friction: 0.4, friction_sharpness: 50.0)])",
    )
    .world;
    for mut world in [corner, two_balls(0.5, 2000.0)] {
        let mut sliding = 0;
        // The balls meet after about 6,700 steps; every 10th step is compared.
        for step in 0..20_000 {
            world.step().expect("contact always gives a force");
            if step % 10 != 0 {
                continue;
            }
            let CouplingKind::Contact(contact) = &world.couplings()[0].kind else { panic!("coupling 0 is a contact") };
            let again = contact.totals(world.frames());
            let kept = world.evaluation().contact_forces(0).expect("a contact keeps its forces");
            // The same faces summed in another order (lanes, then across them): a few ulp of the
            // largest sum, far below 1e-12 of it. The friction is a difference of sums as large
            // as the normal force, so its round-off is relative to that force.
            assert_relative_eq!(kept.normal, again.normal, max_relative = 1e-12);
            assert_relative_eq!(kept.friction, again.friction, epsilon = 1e-12 * again.normal);
            sliding += usize::from(again.friction > 1e-3 * again.normal);
        }
        assert!(sliding > 20, "{sliding} compared steps with friction");
    }
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

/// Runs a shipped scene for its duration (every step healthy) and returns the world.
fn run_shipped(name: &str) -> World {
    let scene = tether_scene::load(&common::repo(&format!("scenes/{name}"))).unwrap_or_else(|e| panic!("{e}"));
    let (mut world, steps) = (scene.world, (scene.file.duration / scene.file.dt).round() as usize);
    for _ in 0..steps {
        world.step().unwrap_or_else(|e| panic!("{name}: {e}"));
    }
    world
}

#[test]
fn the_dropped_crate_comes_to_rest_on_a_face() {
    let world = run_shipped("box_drop.ron");
    let state = world.state(0);
    assert!(state.velocity.norm() < 1e-3 && state.angular_velocity.norm() < 1e-2, "still moving: {state:?}");
    // Resting on a face: G at half of one of the edge lengths (0.6, 0.4, 0.4 m) above the ground,
    // less the range and the sinking under the weight.
    let height = state.position.z;
    assert!([0.3, 0.2].iter().any(|h| (height - h).abs() < 0.003), "G at {height} m");
}

#[test]
fn the_barge_holds_on_the_slipway_until_the_tug_drags_it_down() {
    let scene = tether_scene::load(&common::repo("scenes/barge_slipway.ron")).unwrap_or_else(|e| panic!("{e}"));
    let mut world = scene.world;
    let (mut peak_tension, mut settled_at) = (0.0_f64, None);
    while world.time() < scene.file.duration - 1e-9 {
        world.step().unwrap_or_else(|e| panic!("{e}"));
        peak_tension = peak_tension.max(world.coupling_forces()[1].tension);
        let x = world.state(0).position.x;
        if (world.time() - 1.5).abs() < 1e-9 {
            settled_at = Some(x);
        }
        if (world.time() - 3.0).abs() < 1e-9 {
            // At rest on the ramp by 1.5 s (it starts lying on it), then held by friction until
            // the tug pulls (tan 3° < μ = 0.15; the tanh law creeps at 2.6 mm/s under the
            // barge's weight and the hanging rope's pull).
            let moved = x - settled_at.expect("passed 1.5 s");
            assert!(moved.abs() < 0.01, "the barge slid {moved} m before the pull");
        }
    }
    // Dragged for 22 s at 1 m/s: it follows the tug, and the rope had to overcome
    // μ N − m g sin 3° ≈ 28.7 kN of friction net of gravity.
    let x = world.state(0).position.x;
    assert!(x < -10.0, "barge at x = {x}");
    assert!(peak_tension > 2.87e4, "tow rope peak tension {peak_tension} N");
    assert!(world.energy().dissipated > 0.0);
}

#[test]
fn the_fender_is_squeezed_between_hull_and_quay_and_released() {
    let scene = tether_scene::load(&common::repo("scenes/fender.ron")).unwrap_or_else(|e| panic!("{e}"));
    let mut world = scene.world;
    let (mut quay_peak, mut hull_peak) = (0.0_f64, 0.0_f64);
    let balance = world.energy().balance();
    while world.time() < 4.0 {
        world.step().unwrap_or_else(|e| panic!("{e}"));
        quay_peak = quay_peak.max(world.coupling_forces()[2].tension);
        hull_peak = hull_peak.max(world.coupling_forces()[3].tension);
    }
    // Squeezed by about 0.1 m: both contacts carry tens of kN, the fender stays between them.
    assert!(quay_peak > 2e4 && hull_peak > 2e4, "peaks: quay {quay_peak} N, hull {hull_peak} N");
    let x = world.state(0).position.x;
    assert!(x > 0.3 && x < 0.5, "fender at x = {x}");
    while world.time() < 8.0 {
        world.step().unwrap_or_else(|e| panic!("{e}"));
    }
    assert_eq!(world.coupling_forces()[3].tension, 0.0, "the hull has left");
    // The balance holds through the squeeze (the hull's work is external work): within 1 J of
    // the 2.38 kJ the hull puts in (measured 0.2 J). With a friction sharpness past the friction
    // damper's stable step the faces flip their sliding direction every step and this drifts by
    // tens of kJ while the fender looks at rest.
    let drift = (world.energy().balance() - balance).abs();
    assert!(drift < 1.0, "balance drift {drift} J");
}

#[test]
fn the_rolling_ball_knocks_the_box_forwards() {
    let world = run_shipped("two_bodies.ron");
    let (ball, block) = (world.state(0), world.state(1));
    assert!(block.position.x > 0.05, "the box was not pushed: {:?}", block.position);
    assert!(ball.position.x < block.position.x, "the ball went through the box");
    assert!(block.position.z > 0.14 && block.position.z < 0.16, "the box left the ground: {:?}", block.position);
}
