//! Statics (PHYSICS.md §7 "Static equilibrium"): the assembled tangent stiffness against finite differences of the
//! system's loads, static equilibria against closed forms and against a damped run that settles,
//! unreachable equilibria named, offset curves against the stiffness.

use approx::assert_relative_eq;
use nalgebra::DMatrix;
use tether_physics::body::BodyState;
use tether_physics::evaluation::Evaluation;
use tether_physics::seabed::Seabed;
use tether_physics::statics::dofs::displace;
use tether_physics::statics::{Direction, Dof, EquilibriumError, Settings, equilibrium, offsets, stiffness};
use tether_physics::system::System;
use tether_physics::world::World;

const G: f64 = 9.80665;

fn world(text: &str) -> World {
    tether_scene::parse(text, std::path::Path::new("statics.ron")).unwrap().world
}

/// A 3 t buoy on three chains of scope 1.7:1 whose anchor ends lie on a seabed 50 m down, a
/// vertical spring for its buoyancy, lines attached 1 m off its axis.
const BUOY: &str = "Scene(dt: 0.002, bodies: [Body(name: \"buoy\",
        master: Node(position: (2.0, 1.0, 0.5), mass: 3000.0, inertia: Inertia(xx: 1750.0, yy: 1750.0, zz: 1500.0)),
        shape: Cylinder(radius: 1.0, length: 2.0))],
    couplings: [
        Catenary(name: \"m1\", end1: World((85.0, 0.0, -50.0)), end2: Body(body: \"buoy\", point: (1.0, 0.0, -1.0)), mass_per_length: 50.0, length: 100.0, stiffness: 5e6),
        Catenary(name: \"m2\", end1: World((-42.5, 73.6122, -50.0)), end2: Body(body: \"buoy\", point: (-0.5, 0.8660254, -1.0)), mass_per_length: 50.0, length: 100.0, stiffness: 5e6),
        Catenary(name: \"m3\", end1: World((-42.5, -73.6122, -50.0)), end2: Body(body: \"buoy\", point: (-0.5, -0.8660254, -1.0)), mass_per_length: 50.0, length: 100.0, stiffness: 5e6),
        SpringDamper(name: \"buoyancy\", end1: Body(body: \"buoy\"), end2: World((0.0, 0.0, 100.0)), law: Linear(stiffness: 31600.0, rest_length: 98.0), damping: 3000.0),
        // Dampers without springs, to far points, so that a run comes to rest (no static force).
        SpringDamper(name: \"surge_damper\", end1: Body(body: \"buoy\", point: (0.0, 1.0, 1.0)), end2: World((1000.0, 1.0, 1.0)), law: Linear(stiffness: 0.0, rest_length: 0.0), damping: 2000.0),
        SpringDamper(name: \"surge_damper2\", end1: Body(body: \"buoy\", point: (0.0, -1.0, -1.0)), end2: World((1000.0, -1.0, -1.0)), law: Linear(stiffness: 0.0, rest_length: 0.0), damping: 2000.0),
        SpringDamper(name: \"sway_damper\", end1: Body(body: \"buoy\", point: (1.0, 0.0, 1.0)), end2: World((1.0, 1000.0, 1.0)), law: Linear(stiffness: 0.0, rest_length: 0.0), damping: 2000.0),
        SpringDamper(name: \"sway_damper2\", end1: Body(body: \"buoy\", point: (-1.0, 0.0, -1.0)), end2: World((-1.0, 1000.0, -1.0)), law: Linear(stiffness: 0.0, rest_length: 0.0), damping: 2000.0),
    ])";

fn moored(friction: f64) -> System {
    world(BUOY).system().clone().with_seabed(Seabed::new(-50.0, friction).unwrap()).unwrap()
}

/// `−∂(F, M)/∂(x, θ)` by central differences of the whole evaluation (steps of 1e-6 m and rad).
fn finite_differences(system: &System, states: &[BodyState]) -> DMatrix<f64> {
    let n = states.len();
    let mut k = DMatrix::zeros(6 * n, 6 * n);
    let loads = |states: &[BodyState]| {
        let mut evaluation = Evaluation::new(n, system.couplings());
        system.evaluate(states, &mut evaluation, 0.0).unwrap();
        evaluation
            .loads()
            .iter()
            .flat_map(|l| [l.force.x, l.force.y, l.force.z, l.moment.x, l.moment.y, l.moment.z])
            .collect::<Vec<f64>>()
    };
    let step = 1e-6;
    for body in 0..n {
        for direction in Direction::ALL {
            let moved = |amount: f64| {
                let mut s = states.to_vec();
                displace(&mut s[body], direction, amount);
                loads(&s)
            };
            let (plus, minus) = (moved(step), moved(-step));
            for row in 0..6 * n {
                k[(row, 6 * body + direction.index())] = -(plus[row] - minus[row]) / (2.0 * step);
            }
        }
    }
    k
}

fn assert_stiffness_matches(system: &System, states: &[BodyState], what: &str) {
    let mut evaluation = Evaluation::new(states.len(), system.couplings());
    system.evaluate(states, &mut evaluation, 0.0).unwrap();
    let analytic = stiffness::tangent(system, &evaluation);
    let fd = finite_differences(system, states);
    // Central differences of 1e-6 on forces solved to 1e-12 of the line: about 1e-6 of K.
    let error = (&analytic - &fd).norm();
    assert!(
        error <= 1e-5 * fd.norm(),
        "{what}: |K − K_fd| = {error:.3e} of |K_fd| = {:.3e}\nanalytic {analytic:.4e}\nfd {fd:.4e}",
        fd.norm()
    );
}

#[test]
fn stiffness_of_lines_on_the_seabed_and_springs_matches_finite_differences() {
    for friction in [0.0, 0.8] {
        let system = moored(friction);
        let mut states = system.initial_states().to_vec();
        displace(&mut states[0], Direction::Roll, 0.2);
        displace(&mut states[0], Direction::Yaw, -0.3);
        assert_stiffness_matches(&system, &states, &format!("moored buoy, C_B = {friction}"));
    }
}

#[test]
fn stiffness_of_springs_free_lines_and_contacts_between_bodies_matches_finite_differences() {
    let system = world(
        "Scene(dt: 0.001, bodies: [
            Body(name: \"a\", master: Node(position: (0.0, 0.0, 0.0), mass: 500.0, inertia: Inertia(xx: 80.0, yy: 120.0, zz: 150.0, xy: 10.0)), shape: Box(size: (2.0, 1.0, 0.5))),
            Body(name: \"b\", master: Node(position: (6.0, 1.0, -1.5), mass: 300.0, inertia: Inertia(xx: 40.0, yy: 40.0, zz: 60.0)), shape: Sphere(radius: 0.7))],
         couplings: [
            SpringDamper(name: \"s\", end1: Body(body: \"a\", point: (1.0, 0.3, 0.2)), end2: Body(body: \"b\", point: (-0.5, 0.0, 0.4)), law: Polynomial(a: 2000.0, b: 300.0, c: 50.0, rest_length: 3.0)),
            Catenary(name: \"c\", end1: World((-4.0, 2.0, 3.0)), end2: Body(body: \"a\", point: (-1.0, -0.4, 0.25)), mass_per_length: 5.0, length: 6.0, stiffness: 2e5),
            Catenary(name: \"link\", end1: Body(body: \"a\", point: (1.0, -0.5, 0.0)), end2: Body(body: \"b\", point: (0.3, 0.3, 0.3)), mass_per_length: 8.0, length: 7.0, stiffness: 1e5),
            Contact(name: \"floor\", body: \"b\", against: Plane(point: (0.0, 0.0, -2.1), normal: (0.1, 0.0, 1.0)), stiffness: 1e6, range: 0.05, friction: 0.5),
         ])",
    )
    .system()
    .clone();
    let mut states = system.initial_states().to_vec();
    displace(&mut states[1], Direction::Pitch, 0.4);
    assert_stiffness_matches(&system, &states, "springs, lines and a contact");
}

/// A 100 kg body on a vertical linear spring: it rests where the spring carries its weight,
/// `x = x0 + m g/k`, with stiffness k in z; no stiffness sideways (a spring along z turns freely
/// at its tension over its length: `f/x` across).
#[test]
fn a_body_on_a_spring_rests_where_the_spring_carries_its_weight() {
    let system = world(
        "Scene(dt: 0.001, bodies: [Body(name: \"bob\", master: Node(position: (0.0, 0.0, -1.0), mass: 100.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
            support: Fixed(translation: (true, true, false), rotation: true), shape: Sphere(radius: 0.1))],
         couplings: [SpringDamper(name: \"s\", end1: World((0.0, 0.0, 0.0)), end2: Body(body: \"bob\"), law: Linear(stiffness: 5000.0, rest_length: 1.5))])",
    )
    .system()
    .clone();
    let eq = equilibrium::solve(&system, system.initial_states(), &[], &Settings::default()).unwrap();
    assert_eq!(eq.dofs.len(), 1, "only z is free");
    assert_relative_eq!(eq.states[0].position.z, -(1.5 + 100.0 * G / 5000.0), max_relative = 1e-12);
    assert_relative_eq!(eq.body_stiffness(0)[(2, 2)], 5000.0, max_relative = 1e-12);
    // A linear problem: Newton's step (0.7 m) is cut to the first trust radius (a quarter of the
    // 1 m scene), then taken whole.
    assert!(eq.iterations <= 2, "{} iterations", eq.iterations);
}

/// A start that no damping can take a step from (a pose that is not a number makes the
/// stiffness and the loads NaN) ends in one iteration with the error that says so, instead of
/// raising the damping λ for ever.
#[test]
fn a_start_without_a_finite_stiffness_ends_with_no_step() {
    let system = world(
        "Scene(dt: 0.001, bodies: [Body(name: \"bob\", master: Node(position: (0.0, 0.0, -1.0), mass: 100.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
            support: Fixed(translation: (true, true, false), rotation: true), shape: Sphere(radius: 0.1))],
         couplings: [SpringDamper(name: \"s\", end1: World((0.0, 0.0, 0.0)), end2: Body(body: \"bob\"), law: Linear(stiffness: 5000.0, rest_length: 1.5))])",
    )
    .system()
    .clone();
    let mut start = system.initial_states().to_vec();
    start[0].position.z = f64::NAN;
    let error = equilibrium::solve(&system, &start, &[], &Settings::default()).unwrap_err();
    assert_eq!(error, EquilibriumError::NoStep { iteration: 1 });
    assert!(error.to_string().contains("not finite"), "{error}");
}

/// The moored buoy at equilibrium carries no load, its stiffness is symmetric without
/// friction (a conservative system), and a damped run from a displaced start settles there.
#[test]
fn the_moored_buoy_settles_where_the_static_solve_says() {
    let system = moored(0.0);
    let eq = equilibrium::solve(&system, system.initial_states(), &[], &Settings::default()).unwrap();
    assert!(eq.residual_force <= 1e-9 * 3000.0 * G * 10.0, "{}", eq.residual_force);
    assert!(eq.unstable.is_none());
    let k = eq.body_stiffness(0);
    assert!((k - k.transpose()).norm() <= 1e-6 * k.norm(), "asymmetric stiffness {k:.4e}");
    for i in 0..3 {
        assert!(k[(i, i)] > 0.0, "restoring in {}: {k:.4e}", Direction::ALL[i]);
    }
    // The dynamic check: the spring's damper and the lines bring the buoy to rest.
    let mut world = World::new(system, world(BUOY).timing()).unwrap();
    for _ in 0..100_000 {
        world.step().unwrap();
    }
    let settled = world.state(0);
    assert!(settled.velocity.norm() < 1e-4, "still moving at {} m/s", settled.velocity.norm());
    assert!(
        (settled.position - eq.states[0].position).norm() < 1e-6,
        "settled at {:?}, equilibrium {:?}",
        settled.position,
        eq.states[0].position
    );
}

/// A body nothing holds up, and a cart on rails down a slope, have no equilibrium: the error names the
/// body and the direction.
#[test]
fn an_unreachable_equilibrium_names_the_body_and_the_direction() {
    let falling = world("Scene(dt: 0.01, bodies: [Body(name: \"rock\", master: Node(position: (0.0, 0.0, 0.0), mass: 10.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)), shape: Sphere(radius: 0.1))])").system().clone();
    match equilibrium::solve(&falling, falling.initial_states(), &[], &Settings::default()) {
        Err(EquilibriumError::Unreachable { body, direction, load, .. }) => {
            assert_eq!((body.as_str(), direction), ("rock", Direction::Z));
            assert_relative_eq!(load, -10.0 * G, max_relative = 1e-12);
        }
        other => panic!("expected unreachable, got {other:?}"),
    }
    // On a slope (gravity tilted) a cart that runs on rails along x has nothing to stop it.
    let sliding = world(
        "Scene(dt: 0.01, gravity: (1.5, 0.0, -9.7), bodies: [Body(name: \"cart\", master: Node(position: (1.0, 0.0, 0.0), mass: 10.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
            support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))])",
    )
    .system()
    .clone();
    let error = equilibrium::solve(&sliding, sliding.initial_states(), &[], &Settings::default()).unwrap_err();
    let message = error.to_string();
    assert!(
        message.contains("body \"cart\" has no restoring force in x") && message.contains("1.5000e1 N"),
        "{message}"
    );
}

/// A body held at offsets along x from equilibrium: the curve starts at zero load with the slope
/// of the stiffness the other directions settle to (the Schur complement of K over them).
#[test]
fn the_offset_curve_starts_with_the_condensed_stiffness() {
    let system = moored(0.3);
    let settings = Settings::default();
    let eq = equilibrium::solve(&system, system.initial_states(), &[], &settings).unwrap();
    let dof = Dof { body: 0, direction: Direction::X };
    let curve = offsets::curve(&system, &eq, dof, 0.01, 2, &settings).unwrap();
    assert!(curve.points[0].load.abs() < 1e-6 * 3000.0 * G, "{}", curve.points[0].load);
    let k = eq.body_stiffness(0);
    let (kxx, kxr, krr) = (k[(0, 0)], k.fixed_view::<1, 5>(0, 1).into_owned(), k.fixed_view::<5, 5>(1, 1).into_owned());
    let condensed = kxx - (kxr * krr.try_inverse().unwrap() * kxr.transpose())[(0, 0)];
    let slope = -(curve.points[1].load - curve.points[0].load) / 0.005;
    // Over 5 mm the curve bends by the third derivative: within 1 %.
    assert_relative_eq!(slope, condensed, max_relative = 1e-2);
    let far = offsets::curve(&system, &eq, dof, 20.0, 4, &settings).unwrap();
    let loads: Vec<f64> = far.points.iter().map(|p| p.load).collect();
    assert!(loads.windows(2).all(|w| w[1] < w[0]), "the restoring force grows with the offset: {loads:?}");
}

/// A box 20 × 10 × 4 m of 410 t floating in still water (ρ = 1025 kg/m³), on a slack vertical
/// spring pulling down at a point off its centre: at equilibrium its draft carries its weight
/// and the spring's pull, `T = (m g + F) / (ρ g A)`, and its heave stiffness is the waterplane's
/// `ρ g A` plus the spring's; the water's stiffness (central differences of its hull pressure)
/// matches finite differences of the whole evaluation. The scene's wave and added mass are not
/// seen by the static solve (the system at rest).
#[test]
fn a_floating_box_settles_at_the_draft_that_carries_it() {
    let text = "Scene(dt: 0.01, water: Water(waves: Regular(height: 1.0, period: 8.0)),
        bodies: [Body(name: \"box\", master: Node(position: (0.0, 0.0, 0.5), mass: 410000.0, inertia: Inertia(xx: 3963333.33, yy: 14213333.33, zz: 17083333.33)),
            shape: Box(size: (20.0, 10.0, 4.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0), added_mass: (1.0, 1.0, 1.0)))],
        couplings: [
            SpringDamper(name: \"pull\", end1: Body(body: \"box\", point: (0.0, 0.0, -2.0)), end2: World((0.0, 0.0, -50.0)), law: Linear(stiffness: 1000.0, rest_length: 20.0)),
            // Horizontal springs for surge, sway and yaw, which the water does not restore.
            SpringDamper(name: \"x1\", end1: Body(body: \"box\", point: (10.0, 0.0, 0.0)), end2: World((110.0, 0.0, 0.0)), law: Linear(stiffness: 100.0, rest_length: 100.0)),
            SpringDamper(name: \"x2\", end1: Body(body: \"box\", point: (-10.0, 0.0, 0.0)), end2: World((-110.0, 0.0, 0.0)), law: Linear(stiffness: 100.0, rest_length: 100.0)),
            SpringDamper(name: \"y1\", end1: Body(body: \"box\", point: (5.0, 5.0, 0.0)), end2: World((5.0, 105.0, 0.0)), law: Linear(stiffness: 100.0, rest_length: 100.0)),
            SpringDamper(name: \"y2\", end1: Body(body: \"box\", point: (-5.0, -5.0, 0.0)), end2: World((-5.0, -105.0, 0.0)), law: Linear(stiffness: 100.0, rest_length: 100.0)),
        ])";
    let system = world(text).system().clone();
    let eq = equilibrium::solve(&system, system.initial_states(), &[], &Settings::default()).unwrap();
    let (rho, area, mass) = (1025.0, 200.0, 410_000.0);
    let z = eq.states[0].position.z;
    // The spring (rest 20 m) from the box's bottom at z − 2 down to z = −50: pull k (48 + z − 20).
    let pull = 1000.0 * (z - 2.0 + 50.0 - 20.0);
    let draft = (mass * G + pull) / (rho * G * area);
    // The hull is a box of flat faces: its pressure integral is exact, the equilibrium solved to
    // 1e-9 of the weight.
    assert_relative_eq!(z, 2.0 - draft, max_relative = 1e-9);
    assert_relative_eq!(eq.body_stiffness(0)[(2, 2)], rho * G * area + 1000.0, max_relative = 1e-6);
    let at_rest = system.at_rest();
    assert_stiffness_matches(&at_rest, &eq.states, "floating box");
}
