//! The catenary coupling against closed forms, an independent reference, finite differences
//! and a generated sweep of every regime (PHYSICS.md §3).

use approx::assert_relative_eq;
use nalgebra::Vector3;
use proptest::prelude::*;
use tether_physics::coupling::Endpoint;
use tether_physics::coupling::catenary::equations::{Closure, rise};
use tether_physics::coupling::catenary::{Catenary, LineState};
use tether_physics::surroundings::Surroundings;

type V = Vector3<f64>;
const G: f64 = 9.80665;

fn dry() -> Surroundings {
    Surroundings::dry(V::new(0.0, 0.0, -G))
}

fn line(mass_per_length: f64, length: f64, stiffness: f64) -> Catenary {
    Catenary::new(Endpoint::World(V::zeros()), Endpoint::World(V::zeros()), mass_per_length, length, stiffness)
        .expect("the tests' lines have valid values")
}

fn solve(line: &Catenary, p1: V, p2: V) -> LineState {
    line.solve(&p1, &p2, &dry(), None).unwrap()
}

/// Span 10 m, length 12 m, ends level, inextensible: `a sinh(5/a) = 6` gives
/// a = 4.69541523127 m and the sag `a (cosh(5/a) − 1)` = 2.92343797601 m.
#[test]
fn inextensible_level_line() {
    let (lambda, length) = (2.0, 12.0);
    let l = line(lambda, length, 1e13);
    let s = solve(&l, V::new(1.0, 2.0, 3.0), V::new(11.0, 2.0, 3.0));
    let a = s.horizontal_tension / (lambda * G);
    assert_relative_eq!(a, 4.69541523127, max_relative = 1e-9);
    // Lowest point where the vertical force vanishes: depth rise(h, v1, 0)·L below end 1.
    let (h, v1) = (s.horizontal_tension / s.weight, s.vertical1 / s.weight);
    let sag = -rise(h, v1, 0.0) * length;
    assert_relative_eq!(sag, 2.92343797601, max_relative = 1e-9);
    // Symmetric: each end carries half the weight.
    assert_relative_eq!(s.vertical1, -0.5 * s.weight, max_relative = 1e-9);
    assert!(s.residual < 1e-12);
}

#[test]
fn end_forces_sum_to_the_weight_and_lie_along_the_end_tangents() {
    let cases = [
        (V::new(0.0, 0.0, 0.0), V::new(30.0, 10.0, -5.0), 3.0, 40.0, 1e5),
        (V::new(5.0, 1.0, 2.0), V::new(5.5, 1.0, 10.0), 1.0, 12.0, 1e4),
        (V::new(0.0, 0.0, 0.0), V::new(100.0, 0.0, 20.0), 50.0, 100.0, 5e6),
    ];
    for (p1, p2, lambda, length, stiffness) in cases {
        let s = solve(&line(lambda, length, stiffness), p1, p2);
        let (f1, f2) = s.end_forces();
        assert_relative_eq!(f1 + f2, V::new(0.0, 0.0, -lambda * G * length), epsilon = 1e-9 * s.weight);
        let points = s.sample(100_000);
        assert_relative_eq!(points[0].0, p1, epsilon = 1e-12 * length);
        assert_relative_eq!(points[points.len() - 1].0, p2, epsilon = 1e-9 * length);
        let tangent1 = (points[1].0 - points[0].0).normalize();
        let tangent2 = (points[points.len() - 1].0 - points[points.len() - 2].0).normalize();
        assert!((f1.normalize() - tangent1).norm() < 1e-4, "{f1:?} vs {tangent1:?}");
        assert!((f2.normalize() + tangent2).norm() < 1e-4, "{f2:?} vs {tangent2:?}");
        let (t1, t2) = s.end_tensions();
        assert_relative_eq!(points[0].1, t1, max_relative = 1e-12);
        assert_relative_eq!(points[points.len() - 1].1, t2, max_relative = 1e-12);
    }
}

/// Exactly vertical: taut (end 2 above by more than L) and slack folded (end 2 below by 2 m).
#[test]
fn vertical_closed_forms() {
    let (lambda, length, stiffness) = (2.0, 10.0, 1e4);
    let (w, ea) = (lambda * G * length, stiffness * length);
    // Taut: the stretch d − L equals the mean tension (V1 + W/2) L / EA.
    let taut = solve(&line(lambda, length, stiffness), V::zeros(), V::new(0.0, 0.0, 10.5));
    assert_relative_eq!(taut.vertical1, ea * 0.5 / length - 0.5 * w, max_relative = 1e-12);
    assert_eq!(taut.horizontal_tension, 0.0);
    // Folded: the parts hanging from end 1 (l1) and end 2 (l2) satisfy l1 + l2 = L and, with
    // their stretch under their own weight, l2 − l1 + (V1 + V2) L/(2EA) = Δy.
    let folded = solve(&line(lambda, length, stiffness), V::zeros(), V::new(0.0, 0.0, -2.0));
    let expected_sum = -2.0 / (length / w + length / (2.0 * ea));
    assert_relative_eq!(folded.vertical1 + folded.vertical2(), expected_sum, max_relative = 1e-12);
    assert_relative_eq!(folded.vertical2() - folded.vertical1, w, max_relative = 1e-12);
    // Each end carries the weight of its part: end 1 pulled down, end 2 pulled down.
    let (f1, f2) = folded.end_forces();
    assert!(f1.z < 0.0 && f2.z < 0.0 && f1.x == 0.0 && f2.x == 0.0);
}

/// λ0 → 0: a straight elastic rope that pulls only when stretched.
#[test]
fn massless_limit_is_a_straight_spring() {
    let (p1, p2) = (V::new(1.0, 2.0, 3.0), V::new(7.0, -1.0, 11.0));
    let chord = (p2 - p1).norm();
    let stiffness = 1000.0;
    let length = chord / 1.05;
    let spring_tension = stiffness * (chord - length);
    for lambda in [1e-9, 0.0] {
        let s = solve(&line(lambda, length, stiffness), p1, p2);
        let (f1, f2) = s.end_forces();
        assert_relative_eq!(f1, (p2 - p1) / chord * spring_tension, max_relative = 1e-6);
        assert_relative_eq!(f2, -(p2 - p1) / chord * spring_tension, max_relative = 1e-6, epsilon = 1e-6);
    }
    let slack = solve(&line(0.0, chord * 1.1, stiffness), p1, p2);
    assert_eq!(slack.end_forces().0, V::zeros());
    let nearly_massless_slack = solve(&line(1e-9, chord * 1.1, stiffness), p1, p2);
    assert!(nearly_massless_slack.end_forces().0.norm() < 1e-6);
}

/// Finite differences of the potential give minus the end forces, and of the forces give the
/// tangent stiffness.
#[test]
fn forces_are_minus_the_energy_gradient_and_stiffness_is_their_derivative() {
    let cases = [
        (V::new(0.0, 0.0, 0.0), V::new(30.0, 10.0, -5.0), 3.0, 40.0, 1e5),
        (V::new(0.0, 0.0, 0.0), V::new(9.0, 3.0, 4.0), 1.0, 10.0, 2e3),
        (V::new(0.0, 0.0, 0.0), V::new(0.3, 0.0, -6.0), 1.0, 10.0, 1e4),
        (V::new(2.0, 0.0, 0.0), V::new(0.0, 0.0, 0.0), 0.0, 1.5, 100.0),
    ];
    for (p1, p2, lambda, length, stiffness) in cases {
        let l = line(lambda, length, stiffness);
        let s = solve(&l, p1, p2);
        let (f1, f2) = s.end_forces();
        let h = 1e-6 * length;
        let mut k_fd = nalgebra::Matrix3::zeros();
        for axis in 0..3 {
            let d = V::ith(axis, h);
            let energy = |a: V, b: V| solve(&l, a, b).potential_energy();
            let grad2 = (energy(p1, p2 + d) - energy(p1, p2 - d)) / (2.0 * h);
            let grad1 = (energy(p1 + d, p2) - energy(p1 - d, p2)) / (2.0 * h);
            let scale = f1.norm().max(f2.norm());
            assert!((grad2 + f2[axis]).abs() < 1e-6 * scale, "∂V/∂p2 {grad2} vs −f2 {}", -f2[axis]);
            assert!((grad1 + f1[axis]).abs() < 1e-6 * scale, "∂V/∂p1 {grad1} vs −f1 {}", -f1[axis]);
            let column = (solve(&l, p1, p2 + d).end_forces().0 - solve(&l, p1, p2 - d).end_forces().0) / (2.0 * h);
            k_fd.set_column(axis, &column);
        }
        assert_relative_eq!(s.tangent_stiffness(), k_fd, epsilon = 1e-5 * k_fd.norm(), max_relative = 1e-5);
    }
}

/// An independent reference: PHYSICS.md's parametric form `(c, u1, u2)` evaluated with the
/// textbook formulas (sinh, cosh, no rearrangement) and solved by nested bisection — a
/// different parametrisation and a different algorithm from the solver's Newton iteration.
fn reference(dx: f64, dy: f64, w: f64, length: f64, ea: f64) -> (f64, f64) {
    let weight = w * length;
    // Given c and sinh u1: the end-point offsets from PHYSICS.md §3.
    let ends = |c: f64, s1: f64| {
        let s2 = s1 + weight / c;
        let (u1, u2) = (s1.asinh(), s2.asinh());
        let a = c / w;
        let b = c * a / ea;
        (a * (u2 - u1) + b * (s2 - s1), a * (u2.cosh() - u1.cosh()) + 0.5 * b * (s2 * s2 - s1 * s1))
    };
    let bisect = |f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64| {
        for _ in 0..300 {
            let mid = 0.5 * (lo + hi);
            if f(mid) < 0.0 { lo = mid } else { hi = mid }
        }
        0.5 * (lo + hi)
    };
    let s1_for = |c: f64| bisect(&|s1| ends(c, s1).1 - dy, -1e6, 1e6);
    let log_c = bisect(&|lc: f64| ends(lc.exp(), s1_for(lc.exp())).0 - dx, (1e-6 * weight).ln(), (1e6 * weight).ln());
    let c = log_c.exp();
    (c, c * s1_for(c))
}

#[test]
fn matches_an_independent_reference_to_1e_9() {
    let cases = [
        (10.0, 0.0, 1.0, 12.0, 1e6),
        (30.0, 10.0, 3.0, 40.0, 1e5),
        (84.0, 49.0, 50.0, 100.0, 5e8 / 100.0),
        (5.0, -3.0, 0.5, 7.0, 200.0),
        (50.0, 20.0, 0.1, 52.0, 1e3),
        (1.0, 0.5, 2.0, 1.5, 1e7),
    ];
    for (dx, dy, lambda, length, stiffness) in cases {
        let s = solve(&line(lambda, length, stiffness), V::zeros(), V::new(dx, 0.0, dy));
        let (c, v1) = reference(dx, dy, lambda * G, length, stiffness * length);
        assert_relative_eq!(s.horizontal_tension, c, max_relative = 1e-9);
        assert_relative_eq!(s.vertical1, v1, max_relative = 1e-9, epsilon = 1e-9 * c);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 5000, ..ProptestConfig::default() })]

    /// Every regime: spans from millimetres to kilometres, slack to stretched (chord 0.2–1.6
    /// L_eq), nearly and exactly vertical, end 2 above or below, very light to very heavy,
    /// very soft to very stiff. The closure residual stays below 1e-9 L_eq, nothing is NaN,
    /// and the end forces sum to the weight.
    #[test]
    fn every_regime_converges(
        log_length in -3.0f64..4.0,
        chord_ratio in 0.2f64..1.6,
        angle in -std::f64::consts::FRAC_PI_2..std::f64::consts::FRAC_PI_2,
        vertical_choice in 0usize..6,
        log_lambda in -6.0f64..3.5,
        log_stretch in -12.0f64..0.0,
    ) {
        let length = 10f64.powf(log_length);
        let lambda = 10f64.powf(log_lambda);
        // D from the line's compliance: ε = λ0 g / D between 1e-12 (very stiff) and 1 (very soft).
        let stiffness = lambda * G / 10f64.powf(log_stretch);
        // Exactly vertical, nearly vertical (1e-10 of the chord), or any angle.
        let angle = match vertical_choice { 0 => std::f64::consts::FRAC_PI_2.copysign(angle), 1 => (std::f64::consts::FRAC_PI_2 - 1e-10).copysign(angle), _ => angle };
        let chord = chord_ratio * length;
        let p1 = V::new(3.0, -2.0, 7.0);
        let p2 = p1 + V::new(chord * angle.cos(), 0.0, chord * angle.sin());
        let l = line(lambda, length, stiffness);
        let s = solve(&l, p1, p2);
        let closure = Closure { x: s.span / length, y: s.rise / length, epsilon: s.weight / s.axial_stiffness };
        let [x, y] = closure.ends(s.horizontal_tension / s.weight, s.vertical1 / s.weight);
        prop_assert!((x - closure.x).abs() < 1e-9 && (y - closure.y).abs() < 1e-9, "residual {} {}", x - closure.x, y - closure.y);
        let (f1, f2) = s.end_forces();
        prop_assert!(f1.iter().chain(f2.iter()).all(|c| c.is_finite()));
        let sum = f1 + f2 + V::new(0.0, 0.0, s.weight);
        prop_assert!(sum.norm() <= 1e-9 * (s.weight + f1.norm()), "force sum {sum:?}");
        prop_assert!(s.potential_energy().is_finite());
    }
}

/// A non-finite end position (a diverged simulation) is an error, never NaN forces.
#[test]
fn non_finite_ends_are_an_error() {
    let l = line(1.0, 10.0, 1e4);
    assert!(l.solve(&V::zeros(), &V::new(f64::NAN, 0.0, 1.0), &dry(), None).is_err());
    assert!(l.solve(&V::zeros(), &V::new(f64::INFINITY, 0.0, 1.0), &dry(), None).is_err());
}

/// A ball swinging on a heavy elastic line from a world point, no damper: the line is
/// conservative, so kinetic + gravity + line energy stays constant (to the leapfrog's O(dt²)).
#[test]
fn a_ball_swinging_on_a_catenary_conserves_energy() {
    let mut world = tether_scene::parse(
        "Scene(dt: 5e-4, bodies: [Body(name: \"ball\", master: Node(position: (6.0, 0.0, -8.05), mass: 50.0,
            inertia: Inertia(xx: 0.5, yy: 0.5, zz: 0.5)), velocity: (0.0, 2.0, 0.0), shape: Sphere(radius: 0.25))],
         couplings: [Catenary(name: \"line\", end1: World((0.0, 0.0, 0.0)), end2: Body(body: \"ball\"),
            mass_per_length: 2.0, length: 10.0, stiffness: 2e5)])",
        std::path::Path::new("swing.ron"),
    )
    .unwrap()
    .world;
    let e0 = world.energy();
    let mut largest_kinetic = 0.0_f64;
    let mut worst = 0.0_f64;
    for _ in 0..20_000 {
        world.step().unwrap();
        let e = world.energy();
        largest_kinetic = largest_kinetic.max(e.kinetic);
        worst = worst.max((e.balance() - e0.balance()).abs());
    }
    assert!(largest_kinetic > 100.0, "it swung: {largest_kinetic} J");
    // Measured 4.2e-5 of the largest kinetic energy at dt = 0.5 ms.
    assert!(worst < 2e-4 * largest_kinetic, "balance drift {worst} J against {largest_kinetic} J of motion");
}
