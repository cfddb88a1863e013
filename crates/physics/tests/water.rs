//! Water (PHYSICS.md §6): the closed forms of floating and sinking bodies, waves and
//! their convergence, added mass under every integrator, the energy balance with water.

use tether_test_support as common;

use approx::assert_relative_eq;
use common::scene;
use std::f64::consts::PI;
use tether_physics::body::BodyState;
use tether_physics::evaluation::Evaluation;
use tether_physics::integrator::Integrator;
use tether_physics::math::{Rotation, Vec3};
use tether_physics::stability::{Limiter, oscillator_limit};
use tether_physics::system::System;
use tether_physics::water::hydrostatics::{Hydrostatics, equilibrium_height};
use tether_physics::water::{Hull, WaterForces};
use tether_physics::world::World;

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;

/// The closed-form box of PHYSICS.md §6: 20 × 10 × 4 m, relative density 0.5 (m = 410 t),
/// solid (I = m (b² + c²)/12), G at `z` [m] below… above the still level 0, with `extra` RON
/// fields of the body (velocities) and `hydro` its coefficients.
fn floating_box(z: f64, extra: &str, hydro: &str, integrator: &str, dt: f64) -> World {
    let m = 0.5 * RHO * 800.0;
    let (ixx, iyy, izz) = (m * (100.0 + 16.0) / 12.0, m * (400.0 + 16.0) / 12.0, m * (400.0 + 100.0) / 12.0);
    scene(&format!(
        "Scene(dt: {dt:e}, integrator: {integrator}, water: Water(), bodies: [Body(name: \"box\",
            master: Node(position: (0.0, 0.0, {z:e}), mass: {m:e}, inertia: Inertia(xx: {ixx:e}, yy: {iyy:e}, zz: {izz:e})),
            {extra}
            shape: Box(size: (20.0, 10.0, 4.0), subdivisions: 1),
            hydro: Hydro({hydro}))])"
    ))
    .world
}

/// The water forces on the bodies of `system` at `states` and `time` [s].
fn water_at(system: &System, states: &[BodyState], time: f64) -> Vec<WaterForces> {
    let mut evaluation = Evaluation::new(system.bodies().len(), system.couplings());
    system.evaluate(states, &mut evaluation, time).expect("water always gives forces");
    evaluation.water().to_vec()
}

/// Body 0's initial state turned by `turn` about G.
fn turned(world: &World, turn: Rotation) -> Vec<BodyState> {
    let mut states = world.system().initial_states().to_vec();
    states[0].orientation = turn * states[0].orientation;
    states
}

/// Mean period [s] between upward crossings of `level` by the samples `(t, x)`.
fn period(samples: &[(f64, f64)], level: f64) -> f64 {
    let crossings: Vec<f64> = samples
        .windows(2)
        .filter(|w| w[0].1 < level && w[1].1 >= level)
        .map(|w| w[0].0 + (level - w[0].1) / (w[1].1 - w[0].1) * (w[1].0 - w[0].0))
        .collect();
    assert!(crossings.len() >= 3, "too few crossings: {crossings:?}");
    (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64
}

/// Samples of `observe(world)` over `duration` [s].
fn run(world: &mut World, duration: f64, observe: impl Fn(&World) -> f64) -> Vec<(f64, f64)> {
    let mut samples = vec![(world.time(), observe(world))];
    while world.time() < duration - 0.5 * world.dt() {
        world.step().expect("a stable floating body");
        samples.push((world.time(), observe(world)));
    }
    samples
}

/// At its draft of 2 m the box is in equilibrium: buoyancy equals its weight, to round-off.
#[test]
fn the_box_floats_at_its_closed_form_draft() {
    let world = floating_box(0.0, "", "", "leapfrog", 0.01);
    let weight = 0.5 * RHO * 800.0 * G;
    let water = world.water_forces()[0];
    assert_relative_eq!(water.pressure.force, Vec3::new(0.0, 0.0, weight), epsilon = 1e-12 * weight);
    assert_relative_eq!(water.submerged_volume, 400.0, max_relative = 1e-13);
    assert_relative_eq!(water.waterplane_area, 200.0, max_relative = 1e-13);
    assert!(world.load(0).force.norm() < 1e-9 * weight, "{:?}", world.load(0));
}

/// Metacentric height `1 + B²/(12 d) − 2` = 3.1667 m and the righting arm at 15° of heel
/// `GZ = sin φ (GM + ½ BM tan² φ)` = 0.85831 m (wall-sided, exact for the box: displacement
/// unchanged when heeled about G on the waterline), from the static moment of the pressure.
/// Tolerance 1e-9 relative: sums over 12 faces, each exact for a linear pressure.
#[test]
fn metacentric_height_and_righting_arm_from_the_static_moment() {
    let world = floating_box(0.0, "", "", "leapfrog", 0.01);
    let weight = 0.5 * RHO * 800.0 * G;
    let (bm, gm) = (100.0 / 24.0, 1.0 + 100.0 / 24.0 - 2.0);
    let gz = |phi: f64| {
        let water = water_at(world.system(), &turned(&world, Rotation::from_axis_angle(&Vec3::x_axis(), phi)), 0.0);
        // The displacement stays the box's half, and the moment rights the heel (about −x).
        assert_relative_eq!(water[0].submerged_volume, 400.0, max_relative = 1e-12);
        -water[0].pressure.moment.x / weight
    };
    let small = 1e-3_f64;
    assert_relative_eq!(gz(small) / small.sin() - 0.5 * bm * small.tan().powi(2), gm, max_relative = 1e-9);
    assert!((gm - 3.1667).abs() < 5e-5);
    let phi = 15.0_f64.to_radians();
    let expected = phi.sin() * (gm + 0.5 * bm * phi.tan().powi(2));
    assert_relative_eq!(gz(phi), expected, max_relative = 1e-9);
    assert!((expected - 0.85831).abs() < 5e-6, "{expected}");
    // The hydrostatics `check` prints agree.
    let statics = Hydrostatics::at(
        world.system().water().expect("water").floating[0].hull(),
        &Vec3::zeros(),
        &world.frames()[0].rotation,
        0.0,
    );
    assert_relative_eq!(statics.metacentric_heights(0.0)[0], gm, max_relative = 1e-12);
}

/// Free heave: released 0.1 m high, the box heaves at `2π √(d/g)` = 2.8375 s (no added mass;
/// light linear damping ζ ≈ 0.005 shifts it by 1.3e-5). Required within 0.5 %; asserted within
/// 0.05 % (measured period over 6 cycles, leapfrog at dt = 5 ms: phase error (ωh)²/24 ≈ 1e-5).
#[test]
fn free_heave_period_of_the_box() {
    let critical = 2.0 * (RHO * G * 200.0 * 0.5 * RHO * 800.0).sqrt();
    let mut world =
        floating_box(0.1, "", &format!("linear_damping: (0.0, 0.0, {:e})", 0.005 * critical), "leapfrog", 0.005);
    let samples = run(&mut world, 18.0, |w| w.state(0).position.z);
    let expected = 2.0 * PI * (2.0 / G).sqrt();
    assert!((expected - 2.8375).abs() < 5e-5);
    assert_relative_eq!(period(&samples, 0.0), expected, max_relative = 5e-4);
}

/// Free roll: started at 0.01 rad/s about x, the box rolls at `2π √(I_xx/(m g GM))` = 3.5056 s.
/// Required within 0.5 %; asserted within 0.1 % (amplitude 6e-3 rad: the wall-sided
/// nonlinearity shifts the period by ~1e-6; leapfrog phase error ~1e-5).
#[test]
fn free_roll_period_of_the_box() {
    let mut world = floating_box(0.0, "angular_velocity: (0.01, 0.0, 0.0),", "", "leapfrog", 0.005);
    let start = world.state(0).orientation;
    let samples = run(&mut world, 22.0, |w| {
        // The roll angle: how far the turn since t = 0 has tipped the up axis toward −y.
        let up = (w.state(0).orientation * start.inverse()) * Vec3::z();
        (-up.y).atan2(up.z)
    });
    let m = 0.5 * RHO * 800.0;
    let ixx = m * 116.0 / 12.0;
    let expected = 2.0 * PI * (ixx / (m * G * (1.0 + 100.0 / 24.0 - 2.0))).sqrt();
    assert!((expected - 3.5056).abs() < 5e-5);
    assert_relative_eq!(period(&samples, 0.0), expected, max_relative = 1e-3);
}

/// Root of `h²(3 − h) = 1`: the draft of a sphere of relative density 0.25, in radii.
fn sphere_draft() -> f64 {
    let mut h = 0.65_f64;
    for _ in 0..50 {
        h -= (h * h * (3.0 - h) - 1.0) / (6.0 * h - 3.0 * h * h);
    }
    h
}

/// A sphere of relative density 0.25 floats at 0.652704 R. An icosphere's draft converges to it
/// at second order in its edge length: Richardson's extrapolation of subdivisions 4 and 5 meets
/// the root within 1e-5 R (the next term of the error, fourth order, measured 1e-6 R).
#[test]
fn a_sphere_of_relative_density_a_quarter_floats_at_its_closed_form_draft() {
    let exact = sphere_draft();
    assert!((exact - 0.652704).abs() < 5e-7, "{exact}");
    let volume = 0.25 * 4.0 / 3.0 * PI;
    let draft = |subdivisions: u32| {
        let (vertices, triangles) = tether_physics::mesh::primitives::icosphere(1.0, &Vec3::zeros(), subdivisions);
        let hull = Hull::new(vertices, triangles).expect("closed");
        let z =
            equilibrium_height(&hull, &tether_physics::math::Mat3::identity(), 0.0, 0.0, 0.0, volume).expect("floats");
        1.0 - z
    };
    let (d3, d4, d5) = (draft(3), draft(4), draft(5));
    // Second order: each subdivision halves the edges and quarters the error.
    let ratio = (d3 - exact) / (d4 - exact);
    assert!((ratio - 4.0).abs() < 0.4, "error ratio {ratio}");
    assert!(((4.0 * d5 - d4) / 3.0 - exact).abs() < 1e-5, "{d4} {d5}");
}

/// The same sphere (subdivision 3), let go 0.3 m high with heavy damping, comes to rest where the
/// hydrostatics say its mesh floats, within 1e-6 R (the run ends after 40 damped periods).
#[test]
fn a_damped_sphere_comes_to_rest_at_its_hydrostatic_equilibrium() {
    let mass = 0.25 * RHO * 4.0 / 3.0 * PI;
    let mut world = scene(&format!(
        "Scene(dt: 0.002, water: Water(), bodies: [Body(name: \"ball\",
            master: Node(position: (0.0, 0.0, 0.3), mass: {mass:e}, inertia: Inertia(xx: {i:e}, yy: {i:e}, zz: {i:e})),
            shape: Sphere(radius: 1.0, subdivisions: 3),
            hydro: Hydro(linear_damping: (3000.0, 3000.0, 3000.0), rotational_damping: (500.0, 500.0, 500.0)))])",
        i = 0.4 * mass
    ))
    .world;
    for _ in 0..15000 {
        world.step().expect("stable");
    }
    let floating = &world.system().water().expect("water").floating[0];
    let state = world.state(0);
    let rest = equilibrium_height(
        floating.hull(),
        &world.frames()[0].rotation,
        0.0,
        state.position.x,
        state.position.y,
        mass / RHO,
    )
    .expect("floats");
    assert!((state.position.z - rest).abs() < 1e-6, "{} vs {rest}", state.position.z);
    assert!((1.0 - rest - sphere_draft()).abs() < 0.01, "icosphere 3 within 1 % of the sphere's draft");
}

/// A sphere (relative density 0.5) under water, with added-mass coefficient 0.5 and no drag:
/// a constant acceleration `(ρV − m) g / (m + C_a ρ V)` (V the mesh's volume: a body fully under
/// water gets ρ g V whatever its mesh), which every integrator integrates exactly: the height
/// after 1 s is `½ a t²` to 1e-9 relative.
#[test]
fn every_integrator_solves_with_the_added_mass() {
    for integrator in ["leapfrog", "leapfrog2", "splitting", "rk4", "dopri45"] {
        let text = |mass: f64| {
            format!(
                "Scene(dt: 0.01, integrator: {integrator}, water: Water(), bodies: [Body(name: \"ball\",
                master: Node(position: (0.0, 0.0, -20.0), mass: {mass:e}, inertia: Inertia(xx: 100.0, yy: 100.0, zz: 100.0)),
                shape: Sphere(radius: 1.0, subdivisions: 2), hydro: Hydro(added_mass: (0.5, 0.5, 0.5)))])"
            )
        };
        let probe = scene(&text(1.0)).world;
        let volume = probe.system().water().expect("water").floating[0].hull().volume();
        let mass = 0.5 * RHO * volume;
        let mut world = scene(&text(mass)).world;
        let expected = (RHO * volume - mass) * G / (mass + 0.5 * RHO * volume);
        assert_relative_eq!(world.load(0).force.z / mass, expected, max_relative = 1e-9);
        for _ in 0..100 {
            world.step().expect("stable");
        }
        assert_relative_eq!(
            world.state(0).position.z + 20.0,
            0.5 * expected * world.time().powi(2),
            max_relative = 1e-9
        );
        assert_relative_eq!(world.state(0).velocity.z, expected * world.time(), max_relative = 1e-9);
    }
}

/// Rising under water with drag `C_d = 1` on area π R², the sphere reaches the terminal speed
/// `√(2 (ρV − m) g / (ρ C_d A))` (added mass slows the approach, not the limit): to 1e-4 after
/// 12 s (the approach is exponential-like with a time scale of 0.7 s).
#[test]
fn a_rising_sphere_reaches_its_terminal_speed() {
    let text = |mass: f64| {
        format!(
            "Scene(dt: 0.005, integrator: rk4, water: Water(), bodies: [Body(name: \"ball\",
            master: Node(position: (0.0, 0.0, -200.0), mass: {mass:e}, inertia: Inertia(xx: 100.0, yy: 100.0, zz: 100.0)),
            shape: Sphere(radius: 1.0, subdivisions: 2),
            hydro: Hydro(drag: (1.0, 1.0, 1.0), drag_areas: ({a:e}, {a:e}, {a:e}), added_mass: (0.5, 0.5, 0.5)))])",
            a = PI
        )
    };
    let volume = scene(&text(1.0)).world.system().water().expect("water").floating[0].hull().volume();
    let mass = 0.5 * RHO * volume;
    let mut world = scene(&text(mass)).world;
    while world.time() < 12.0 {
        world.step().expect("stable");
    }
    let terminal = (2.0 * (RHO * volume - mass) * G / (RHO * PI)).sqrt();
    assert_relative_eq!(world.state(0).velocity.z, terminal, max_relative = 1e-4);
}

/// Out of the water nothing acts; fully under, a closed mesh of any shape at any angle gets
/// `ρ g V` through its volume's centroid (exact for a linear pressure: 1e-12 relative).
#[test]
fn bodies_out_of_the_water_feel_nothing_and_under_it_their_volume() {
    let world = scene(
        "Scene(dt: 0.01, water: Water(level: 2.0), bodies: [
            Body(name: \"up\", master: Node(position: (0.0, 0.0, 10.0), mass: 1.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
                 shape: Box(size: (1.0, 2.0, 3.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0))),
            Body(name: \"down\", master: Node(position: (3.0, 1.0, -30.0), mass: 1.0, inertia: Inertia(xx: 1.0, yy: 2.0, zz: 3.0, xy: 0.1)),
                 shape: Cylinder(radius: 0.7, length: 2.5, axis: (1.0, 2.0, 3.0), center: (0.2, -0.1, 0.3)), hydro: Hydro()),
        ])",
    )
    .world;
    let water = world.water_forces();
    assert_eq!(water[0].total().force, Vec3::zeros());
    assert_eq!(water[0].submerged_volume, 0.0);
    let hull = &world.system().water().expect("water").floating[1].hull();
    let volume = hull.volume();
    let buoyancy = RHO * G * volume;
    assert_relative_eq!(water[1].pressure.force, Vec3::new(0.0, 0.0, buoyancy), epsilon = 1e-12 * buoyancy);
    assert_relative_eq!(water[1].submerged_volume, volume, max_relative = 1e-12);
    assert_eq!(water[1].wetted_fraction, 1.0);
    // Through the centroid of the hull's volume (Σ over the tetrahedra from G).
    let centroid = hull
        .triangles()
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| hull.vertices()[i as usize]);
            (a + b + c) / 4.0 * (a.dot(&b.cross(&c)) / 6.0)
        })
        .sum::<Vec3>()
        / volume;
    let arm = world.frames()[1].rotation * centroid;
    assert_relative_eq!(water[1].pressure.moment, arm.cross(&water[1].pressure.force), epsilon = 1e-12 * buoyancy);
}

/// A small buoy (1 m cube, half immersed) in a long regular wave (T = 20 s, λ ≈ 625 m, H = 1 m)
/// heaves with the surface: response amplitude operator → 1. Its natural period is 1.4 s, so the
/// quasi-static response is `1/(1 − (T_n/T)²) · e^{−k d/2}` ≈ 1.004; asserted within 1 %.
#[test]
fn a_small_buoy_heaves_with_a_long_wave() {
    let mut world = scene(
        "Scene(dt: 0.01, water: Water(waves: Regular(height: 1.0, period: 20.0), ramp: 40.0), bodies: [
            Body(name: \"buoy\", master: Node(position: (0.0, 0.0, 0.0), mass: 512.5, inertia: Inertia(xx: 85.4, yy: 85.4, zz: 85.4)),
                 shape: Box(size: (1.0, 1.0, 1.0)), hydro: Hydro(linear_damping: (200.0, 200.0, 200.0), rotational_damping: (50.0, 50.0, 50.0)))])",
    )
    .world;
    let samples = run(&mut world, 120.0, |w| w.state(0).position.z);
    let last: Vec<f64> = samples.iter().filter(|(t, _)| *t > 80.0).map(|(_, z)| *z).collect();
    let amplitude =
        0.5 * (last.iter().copied().fold(f64::MIN, f64::max) - last.iter().copied().fold(f64::MAX, f64::min));
    assert_relative_eq!(amplitude / 0.5, 1.0, max_relative = 0.01);
}

/// Froude–Krylov force on a fixed box under a deep-water wave, against its closed form
/// (`F_x = −4 ρ g a b (e^{k z2} − e^{k z1}) sin(k l) sin(ω t)/k`, `F_z = 4 ρ g a b (e^{k z1} −
/// e^{k z2}) sin(k l) cos(ω t)/k` + buoyancy, box `[−l, l] × [−b, b] × [z1, z2]`): the error
/// falls at second order as the faces are refined (ratio 4 ± 0.4 per halving).
#[test]
fn wave_forces_on_a_fixed_box_converge_at_second_order() {
    let (l, b, z1, z2, period, height) = (3.0, 2.0, -5.0, -1.0, 6.0, 1.0);
    let omega = 2.0 * PI / period;
    let k = omega * omega / G;
    let a = 0.5 * height;
    let error = |subdivisions: u32, time: f64| {
        let world = scene(&format!(
            "Scene(dt: 0.01, water: Water(waves: Regular(height: {height:e}, period: {period:e}), ramp: 0.0), bodies: [
                Body(name: \"box\", master: Node(position: (0.0, 0.0, {zc:e}), mass: 1e5, inertia: Inertia(xx: 1e5, yy: 1e5, zz: 1e5)),
                     support: Fixed(translation: (true, true, true), rotation: true),
                     shape: Box(size: ({sx:e}, {sy:e}, {sz:e}), subdivisions: {subdivisions}), hydro: Hydro())])",
            zc = 0.5 * (z1 + z2),
            sx = 2.0 * l,
            sy = 2.0 * b,
            sz = z2 - z1
        ))
        .world;
        let force = water_at(world.system(), world.system().initial_states(), time)[0].pressure.force;
        let decay = ((k * z2).exp() - (k * z1).exp()) / k;
        let fx = -4.0 * RHO * G * a * b * decay * (k * l).sin() * (omega * time).sin();
        let fz = 4.0 * RHO * G * a * b * -decay * (k * l).sin() * (omega * time).cos()
            + RHO * G * 2.0 * l * 2.0 * b * (z2 - z1);
        (force - Vec3::new(fx, 0.0, fz)).norm()
    };
    let time = 1.3;
    let errors: Vec<f64> = [2, 4, 8, 16].iter().map(|&n| error(n, time)).collect();
    for pair in errors.windows(2) {
        let ratio = pair[0] / pair[1];
        assert!((ratio - 4.0).abs() < 0.4, "errors {errors:?}");
    }
}

/// Dropped 0.5 m high and set rolling, the box's energy balance (water work booked as external
/// work) checks the integrator: with drag and damping, RK4 at dt = 10 ms keeps it to 1e-8 of the
/// fall energy after 10 s (measured 3e-10: fourth order); undamped, the splitting's drift is
/// second order (a quarter when dt halves, ratio asserted above 3).
#[test]
fn the_energy_balance_holds_with_water() {
    let drift = |integrator: &str, hydro: &str, dt: f64| {
        let mut world = floating_box(0.5, "angular_velocity: (0.05, 0.0, 0.0),", hydro, integrator, dt);
        let start = world.energy().balance();
        while world.time() < 10.0 - 0.5 * dt {
            world.step().expect("stable");
        }
        (world.energy().balance() - start).abs()
    };
    let fall = 0.5 * RHO * 800.0 * G * 0.5;
    let damped = "drag: (1.0, 1.0, 1.0), linear_damping: (1e4, 1e4, 1e4), rotational_drag: (1e6, 1e6, 1e6)";
    let rk4 = drift("rk4", damped, 0.01);
    assert!(rk4 < 1e-8 * fall, "{rk4}");
    let (coarse, fine) = (drift("splitting", "", 0.01), drift("splitting", "", 0.005));
    assert!(coarse < 1e-3 * fall && coarse / fine > 3.0, "{coarse} {fine}");
}

/// The stable time step sees the water: for the box, the leapfrog's `2/ω` of its stiffest
/// water mode, the righting stiffness `ρ g V GM_L` over the smallest moment `I_xx` (the heave's
/// `ρ g A_wp / m` is softer).
#[test]
fn the_stable_time_step_includes_the_hydrostatic_stiffness() {
    let world = floating_box(0.0, "", "", "leapfrog", 0.01);
    let limit = world.limits().into_iter().find(|l| l.limiter == Limiter::Water(0)).expect("a water limit");
    let m = 0.5 * RHO * 800.0;
    let righting = RHO * G * 400.0 * (1.0 + 400.0 / 24.0 - 2.0);
    let expected = oscillator_limit(Integrator::Leapfrog, righting, 0.0, 12.0 / (m * 116.0)).min(oscillator_limit(
        Integrator::Leapfrog,
        RHO * G * 200.0,
        0.0,
        1.0 / m,
    ));
    assert_relative_eq!(limit.dt, expected, max_relative = 1e-9);
}
