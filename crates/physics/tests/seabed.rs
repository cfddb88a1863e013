//! A catenary lying on the seabed (PHYSICS.md §7) against MoorPy's reference values,
//! an independent nested 1-D reference over a sweep of every regime, the energy gradient, the
//! tangent stiffness, continuity across the lift-off and the heap, and a swinging body whose
//! energy stays put.

use approx::assert_relative_eq;
use nalgebra::{Matrix3, Vector3};
use proptest::prelude::*;
use tether_physics::coupling::Endpoint;
use tether_physics::coupling::catenary::{Catenary, LineState};
use tether_physics::seabed::Seabed;
use tether_physics::surroundings::Surroundings;

type V = Vector3<f64>;
const G: f64 = 9.80665;

/// Surroundings with a seabed at `elevation` [m] with line friction `friction`, dry.
fn on_seabed(elevation: f64, friction: f64) -> Surroundings {
    Surroundings {
        gravity: V::new(0.0, 0.0, -G),
        fluid_density: 0.0,
        seabed: Some(Seabed::new(elevation, friction).unwrap()),
    }
}

/// A line of submerged weight `w` [N/m], unstretched `length` [m] and axial stiffness `ea` [N].
fn line(w: f64, length: f64, ea: f64) -> Catenary {
    Catenary::new(Endpoint::World(V::zeros()), Endpoint::World(V::zeros()), w / G, length, ea / length)
        .expect("the tests' lines have valid values")
}

fn solve(line: &Catenary, p1: V, p2: V, surroundings: &Surroundings) -> LineState {
    line.solve(&p1, &p2, surroundings, None).unwrap()
}

/// MoorPy 1.3's `catenary(XF=400, ZF=200, L=500, EA=7.51e12, W=800, CB)` (PHYSICS.md §7),
/// quoted to 7 significant digits: agreement to 1e-6 relative (MoorPy's own tolerance); L_B is
/// quoted to the millimetre, so to half of that.
#[test]
fn moorpy_reference_values() {
    let l = line(800.0, 500.0, 7.51e12);
    let (anchor, fairlead) = (V::new(10.0, -3.0, -80.0), V::new(410.0, -3.0, 120.0));
    let frictionless = solve(&l, anchor, fairlead, &on_seabed(-80.0, 0.0));
    assert_relative_eq!(frictionless.horizontal_tension, 96_643.45, max_relative = 1e-6);
    assert_relative_eq!(frictionless.vertical2(), 237_751.77, max_relative = 1e-6);
    assert_relative_eq!(frictionless.grounded_length(), 202.810, epsilon = 5e-4);
    let (f1, _) = frictionless.end_forces();
    assert_relative_eq!(f1.x, 96_643.45, max_relative = 1e-6);
    assert_eq!(f1.z, 0.0, "no vertical force at an anchor on the seabed");
    let some = solve(&l, anchor, fairlead, &on_seabed(-80.0, 0.1));
    assert_relative_eq!(some.end_forces().0.norm(), 80_418.63, max_relative = 1e-6);
    let strong = solve(&l, anchor, fairlead, &on_seabed(-80.0, 5.0));
    assert_eq!(strong.end_forces().0.norm(), 0.0);
    // Friction barely changes the suspended part of a nearly inextensible line: the grounded
    // part stretches C_B W L_B²/(2 EA) = 11 µm less, the fairlead tension rises by 7e-8.
    assert_relative_eq!(strong.horizontal_tension, frictionless.horizontal_tension, max_relative = 1e-6);
}

/// What the independent reference finds.
#[derive(Debug, Clone, Copy)]
enum Reference {
    /// `H`, `V_F`, `L_B`, `H_A` [N, N, m, N].
    Grounded {
        h: f64,
        v: f64,
        lb: f64,
        anchor: f64,
    },
    Lifted,
}

/// PHYSICS.md §7 as written — unknowns `H` and `V_F`, `Z_F(H, V_F)` and `X_F(H, V_F)` in their
/// dimensional form — solved by nested bisection: `V_F` from `Z_F` (increasing in `V_F`) inside
/// a bisection of `X_F` over `ln H`. A different parametrisation (the solver's unknown is `h`
/// with closed-form suspended lengths) and a different algorithm (its Newton iteration).
fn reference(x: f64, z: f64, w: f64, length: f64, ea: f64, cb: f64) -> Reference {
    let rise = |h: f64, v: f64| (h / w) * ((1.0 + (v / h).powi(2)).sqrt() - 1.0) + v * v / (2.0 * ea * w);
    let span = |h: f64, v: f64| {
        let lb = length - v / w;
        let stretch = if h >= cb * w * lb { lb / ea * (h - 0.5 * cb * w * lb) } else { h * h / (2.0 * ea * cb * w) };
        lb + (h / w) * (v / h).asinh() + h * (length - lb) / ea + stretch
    };
    let bisect = |f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64| {
        for _ in 0..400 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if f(mid) < 0.0 { lo = mid } else { hi = mid }
        }
        0.5 * (lo + hi)
    };
    // V_F(H), or None where even the whole line suspended does not reach down (L_B < 0).
    let vertical = |h: f64| (rise(h, w * length) >= z).then(|| bisect(&|v| rise(h, v) - z, 0.0, w * length));
    let closure = |log_h: f64| {
        let h = log_h.exp();
        vertical(h).map_or(f64::INFINITY, |v| span(h, v) - x)
    };
    let weight = w * length;
    let log_h = bisect(&closure, (1e-12 * weight).ln(), (1e12 * weight).ln());
    let h = log_h.exp();
    match vertical(h) {
        Some(v) if (span(h, v) - x).abs() <= 1e-9 * length => {
            let lb = length - v / w;
            Reference::Grounded { h, v, lb, anchor: (h - cb * w * lb).max(0.0) }
        }
        _ => Reference::Lifted,
    }
}

#[test]
fn the_reference_reproduces_moorpy() {
    let Reference::Grounded { h, v, lb, .. } = reference(400.0, 200.0, 800.0, 500.0, 7.51e12, 0.0) else {
        panic!("grounded")
    };
    assert_relative_eq!(h, 96_643.45, max_relative = 1e-6);
    assert_relative_eq!(v, 237_751.77, max_relative = 1e-6);
    assert_relative_eq!(lb, 202.810, epsilon = 5e-4);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4000, ..ProptestConfig::default() })]

    /// Every grounded regime: lines from 10 m to 3 km, fairleads from 2 % to 60 % of the length
    /// above the bottom, EA from 1e5 to 1e13 N, compliances `ε = W/EA` from 1e-10 (a chain)
    /// to 1 (a line its own weight would stretch to twice its length; the weight per length
    /// follows), C_B from 0 to 10, spans from just off the heap to just short of the lift-off.
    /// The solver agrees with the reference to 1e-9 (its own stopping rule is 1e-12 in ln h;
    /// the reference bisects to the last bit).
    #[test]
    fn matches_the_nested_reference(
        log_length in 1.0f64..3.5,
        height_ratio in 0.02f64..0.6,
        log_ea in 5.0f64..13.0,
        log_epsilon in -10.0f64..0.0,
        friction_choice in 0usize..4,
        log_cb in -2.0f64..1.0,
        position in 0.001f64..0.999,
        heading in 0.0f64..std::f64::consts::TAU,
    ) {
        let (length, ea) = (10f64.powf(log_length), 10f64.powf(log_ea));
        let w = 10f64.powf(log_epsilon) * ea / length;
        let cb = if friction_choice == 0 { 0.0 } else { 10f64.powf(log_cb) };
        let z = height_ratio * length;
        // Spans between the heap (the part to the fairlead hanging vertically, stretched by its
        // own weight) and the lift-off (the whole line suspended, touching down at the anchor).
        let hanging = 2.0 * z / (1.0 + (1.0 + 2.0 * w * z / ea).sqrt());
        prop_assume!(hanging < length);
        let heap = length - hanging;
        let Reference::Grounded { .. } = reference(heap + 1e-9 * length, z, w, length, ea, cb) else { return Ok(()) };
        let lift = lift_off_span(z, w, length, ea);
        let x = heap + position * (lift - heap);
        let Reference::Grounded { h, v, lb, anchor } = reference(x, z, w, length, ea, cb) else {
            return Err(TestCaseError::fail(format!("the reference lifts off inside the band at x = {x}")));
        };
        let p1 = V::new(12.0, -7.0, -30.0);
        let p2 = p1 + V::new(x * heading.cos(), x * heading.sin(), z);
        let s = solve(&line(w, length, ea), p1, p2, &on_seabed(-30.0, cb));
        prop_assert!(s.ground.is_some(), "grounded by the reference, free by the solver: {s:?}");
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-9 * scale;
        prop_assert!(close(s.horizontal_tension, h, h), "H {} vs {h}", s.horizontal_tension);
        prop_assert!(close(s.vertical2(), v, v), "V_F {} vs {v}", s.vertical2());
        prop_assert!(close(s.grounded_length(), lb, length), "L_B {} vs {lb}", s.grounded_length());
        prop_assert!(close(s.end_forces().0.norm(), anchor, h), "H_A {} vs {anchor}", s.end_forces().0.norm());
    }
}

/// The span at which the whole line is suspended with its touchdown at the anchor: `V_F = W L`
/// and `Z_F(H, W L) = z` solved for `H` by bisection, then `X_F`. A line whose stretch under its
/// own weight, `W L²/(2 EA)`, already reaches `z` never lifts off: then a span of twice its
/// length, which takes a tension of the order of EA.
fn lift_off_span(z: f64, w: f64, length: f64, ea: f64) -> f64 {
    let v = w * length;
    if v * length / (2.0 * ea) >= z {
        return 2.0 * length;
    }
    let rise = |h: f64| (h / w) * ((1.0 + (v / h).powi(2)).sqrt() - 1.0) + v * v / (2.0 * ea * w);
    let (mut lo, mut hi) = ((1e-12 * v).ln(), (1e12 * v).ln());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        // rise decreases with H.
        if rise(mid.exp()) > z { lo = mid } else { hi = mid }
    }
    let h = (0.5 * (lo + hi)).exp();
    (h / w) * (v / h).asinh() + h * length / ea
}

/// A line grounded at end 2 is the mirror of one grounded at end 1.
#[test]
fn end_two_on_the_seabed_mirrors_end_one() {
    let l = line(800.0, 500.0, 7.51e9);
    let surroundings = on_seabed(-80.0, 0.3);
    let (a, b) = (V::new(0.0, 0.0, -80.0), V::new(400.0, 30.0, 120.0));
    let forward = solve(&l, a, b, &surroundings);
    let backward = solve(&l, b, a, &surroundings);
    let (f1, f2) = forward.end_forces();
    let (g1, g2) = backward.end_forces();
    assert_relative_eq!(f1, g2, max_relative = 1e-12);
    assert_relative_eq!(f2, g1, max_relative = 1e-12);
    assert_relative_eq!(forward.grounded_length(), backward.grounded_length(), max_relative = 1e-12);
    assert_relative_eq!(forward.potential_energy(), backward.potential_energy(), max_relative = 1e-12);
}

/// Both ends above the bottom, the line sagging onto it: a grounded middle (no friction, which
/// has no direction there). Symmetric ends give equal parts, and the end forces plus the
/// weight of the grounded part balance the line's weight.
#[test]
fn a_line_between_two_raised_ends_rests_its_middle_on_the_seabed() {
    let (w, length) = (200.0, 100.0);
    let l = line(w, length, 1e8);
    let s = solve(&l, V::new(0.0, 0.0, 5.0), V::new(60.0, 0.0, 5.0), &on_seabed(0.0, 0.5));
    let ground = s.ground.expect("grounded");
    assert_relative_eq!(ground.profile.first.length, ground.profile.second.length, max_relative = 1e-12);
    let (f1, f2) = s.end_forces();
    let lb = s.grounded_length();
    assert!(lb > 10.0, "L_B = {lb}");
    assert_relative_eq!(f1 + f2, V::new(0.0, 0.0, -w * (length - lb)), epsilon = 1e-7 * w * length);
    assert_eq!(s.touchdowns().len(), 2);
    for point in s.sample(200) {
        assert!(point.0.z >= -1e-9, "the line stays on or above the seabed: {:?}", point.0);
    }
}

/// Straight elastic pulls on a line lying entirely on the bottom between two anchors, and a
/// heap when its ends are closer than its length.
#[test]
fn a_line_lying_on_the_seabed_is_a_rope_on_the_ground() {
    let (w, length, ea) = (100.0, 50.0, 1e6);
    let frictionless = solve(&line(w, length, ea), V::zeros(), V::new(50.5, 0.0, 0.0), &on_seabed(0.0, 0.0));
    assert_relative_eq!(frictionless.horizontal_tension, ea * 0.5 / length, max_relative = 1e-12);
    assert_relative_eq!(frictionless.end_forces().0.x, ea * 0.5 / length, max_relative = 1e-12);
    // With friction the tension falls toward the anchor; the stretch ∫ T/EA still spans 0.5 m.
    let cb = 1.0;
    let held = solve(&line(w, length, ea), V::zeros(), V::new(50.5, 0.0, 0.0), &on_seabed(0.0, cb));
    let (h, anchor) = (held.horizontal_tension, held.end_forces().0.x);
    assert_relative_eq!(h - anchor, cb * w * length, max_relative = 1e-12);
    assert_relative_eq!(length * (h + anchor) / (2.0 * ea), 0.5, max_relative = 1e-12);
    let heap = solve(&line(w, length, ea), V::zeros(), V::new(30.0, 0.0, 0.0), &on_seabed(0.0, 0.0));
    assert_eq!(heap.end_forces(), (V::zeros(), V::zeros()));
}

/// Lines of every grounded kind: anchor on the seabed (with friction or not), end 2 on it, both
/// ends raised, fully grounded and taut, nearly vertical over a long grounded part.
fn grounded_cases() -> Vec<(Catenary, V, V, f64)> {
    vec![
        (line(800.0, 500.0, 7.51e9), V::new(0.0, 0.0, -80.0), V::new(390.0, 40.0, 120.0), 0.0),
        (line(800.0, 500.0, 5e8), V::new(0.0, 0.0, -80.0), V::new(380.0, -60.0, 110.0), 0.7),
        (line(800.0, 500.0, 5e8), V::new(0.0, 0.0, -80.0), V::new(300.0, 10.0, 90.0), 5.0),
        (line(300.0, 200.0, 2e7), V::new(150.0, 20.0, -20.0), V::new(0.0, 0.0, -80.0), 0.4),
        (line(200.0, 100.0, 1e8), V::new(0.0, 0.0, -75.0), V::new(60.0, 10.0, -77.0), 0.0),
        (line(50.0, 100.0, 1e5), V::new(0.0, 0.0, -80.0), V::new(100.3, 0.0, -80.0), 0.2),
        (line(500.0, 300.0, 1e9), V::new(0.0, 0.0, -80.0), V::new(1.0, 0.5, -10.0), 0.0),
    ]
}

/// Where `C_B = 0`, the end forces are minus the gradient of the potential energy (central
/// differences of 1e-6 L; an anchor on the seabed is moved only horizontally, since lifting it
/// makes another line and pushing it down is refused by the model).
#[test]
fn forces_are_minus_the_energy_gradient_without_friction() {
    for (l, p1, p2, _) in grounded_cases() {
        let surroundings = on_seabed(-80.0, 0.0);
        let s = solve(&l, p1, p2, &surroundings);
        assert!(s.ground.is_some(), "{p1:?} {p2:?}");
        let (f1, f2) = s.end_forces();
        let scale = f1.norm().max(f2.norm());
        let d = 1e-6 * l.length();
        let energy = |a: V, b: V| solve(&l, a, b, &surroundings).potential_energy();
        for axis in 0..3 {
            let e = V::ith(axis, d);
            let on_bottom = |p: V| (p.z + 80.0).abs() < 1e-9;
            if !(axis == 2 && on_bottom(p1)) {
                let grad1 = (energy(p1 + e, p2) - energy(p1 - e, p2)) / (2.0 * d);
                assert!((grad1 + f1[axis]).abs() < 1e-6 * scale, "∂V/∂p1[{axis}] {grad1} vs −f1 {}", -f1[axis]);
            }
            if !(axis == 2 && on_bottom(p2)) {
                let grad2 = (energy(p1, p2 + e) - energy(p1, p2 - e)) / (2.0 * d);
                assert!((grad2 + f2[axis]).abs() < 1e-6 * scale, "∂V/∂p2[{axis}] {grad2} vs −f2 {}", -f2[axis]);
            }
        }
    }
}

/// The four blocks `∂f_i/∂p_j` against central differences of the end forces, with friction.
#[test]
fn end_stiffness_matches_finite_differences() {
    for (l, p1, p2, cb) in grounded_cases() {
        let surroundings = on_seabed(-80.0, cb);
        let s = solve(&l, p1, p2, &surroundings);
        let blocks = s.end_stiffness();
        let d = 1e-6 * l.length();
        let on_bottom = |p: V| (p.z + 80.0).abs() < 1e-9;
        for (j, p) in [p1, p2].into_iter().enumerate() {
            let mut fd = [Matrix3::zeros(), Matrix3::zeros()];
            for axis in 0..3 {
                if axis == 2 && on_bottom(p) {
                    // The bottom holds an end lying on it: no vertical stiffness to compare.
                    continue;
                }
                let e = V::ith(axis, d);
                let moved = |sign: f64| {
                    if j == 0 {
                        solve(&l, p1 + e * sign, p2, &surroundings)
                    } else {
                        solve(&l, p1, p2 + e * sign, &surroundings)
                    }
                };
                let (plus, minus) = (moved(1.0).end_forces(), moved(-1.0).end_forces());
                fd[0].set_column(axis, &((plus.0 - minus.0) / (2.0 * d)));
                fd[1].set_column(axis, &((plus.1 - minus.1) / (2.0 * d)));
            }
            for i in 0..2 {
                let mut analytic = blocks[i][j];
                if on_bottom(p) {
                    analytic.set_column(2, &V::zeros());
                }
                let scale = fd[i].norm().max(blocks[i][j].norm()).max(1e-9);
                assert!(
                    (analytic - fd[i]).norm() <= 1e-5 * scale,
                    "∂f{}/∂p{} with C_B = {cb}:\n{analytic}\nvs\n{}",
                    i + 1,
                    j + 1,
                    fd[i]
                );
            }
        }
    }
}

/// Across the lift-off (the fairlead moving out until the line leaves the bottom) and across the
/// heap (moving in until the grounded part goes slack) the forces and the energy change
/// continuously: no jump between neighbouring positions 1 mm apart exceeds what the largest
/// stiffness allows over 1 mm, several times over.
#[test]
fn continuous_across_the_lift_off_and_the_heap() {
    let (w, length, ea) = (800.0, 500.0, 7.51e9);
    let l = line(w, length, ea);
    for cb in [0.0, 0.5] {
        let surroundings = on_seabed(-80.0, cb);
        let anchor = V::new(0.0, 0.0, -80.0);
        for (from, to) in [(440.0, 470.0), (295.0, 305.0)] {
            let mut previous: Option<LineState> = None;
            let (mut grounded, mut free, mut slack) = (false, false, false);
            let steps = ((to - from) / 1e-3) as usize;
            for i in 0..=steps {
                let x = from + (to - from) * i as f64 / steps as f64;
                let last = previous.as_ref();
                let s = l.solve(&anchor, &V::new(x, 0.0, 120.0), &surroundings, last).unwrap();
                grounded |= s.ground.is_some();
                free |= s.ground.is_none();
                slack |= s.ground.is_some_and(|g| g.profile.h == 0.0);
                if let Some(p) = previous {
                    let stiffness = s.end_stiffness().iter().flatten().map(|k| k.norm()).fold(0.0, f64::max).max(w);
                    let (a, b) = (s.end_forces(), p.end_forces());
                    let jump = (a.0 - b.0).norm().max((a.1 - b.1).norm());
                    assert!(jump <= 10.0 * stiffness * 1e-3, "force jump {jump} N at x = {x} (C_B = {cb})");
                    let energy_jump = (s.potential_energy() - p.potential_energy()).abs();
                    assert!(energy_jump <= 10.0 * a.1.norm() * 1e-3, "energy jump {energy_jump} J at x = {x}");
                }
                previous = Some(s);
            }
            assert!(grounded, "the band [{from}, {to}] reaches the bottom");
            assert!(free || slack, "the band [{from}, {to}] crosses the lift-off or the heap");
        }
    }
}

/// In water of density ρ the line weighs `(λ0 − ρ A_d) g`: the end forces of a free line sum to
/// that weight; a line lighter than the water it displaces arches upward.
#[test]
fn submerged_weight_and_a_buoyant_line() {
    let chain = Catenary::new(Endpoint::World(V::zeros()), Endpoint::World(V::zeros()), 100.0, 50.0, 1e6)
        .and_then(|line| line.with_displaced_area(0.0127))
        .expect("a valid chain");
    let water = Surroundings { gravity: V::new(0.0, 0.0, -G), fluid_density: 1025.0, seabed: None };
    let s = chain.solve(&V::zeros(), &V::new(40.0, 0.0, 10.0), &water, None).unwrap();
    let (f1, f2) = s.end_forces();
    assert_relative_eq!(f1 + f2, V::new(0.0, 0.0, -(100.0 - 1025.0 * 0.0127) * G * 50.0), max_relative = 1e-10);
    let float = Catenary::new(Endpoint::World(V::zeros()), Endpoint::World(V::zeros()), 5.0, 50.0, 1e6)
        .and_then(|line| line.with_displaced_area(0.01))
        .expect("a valid line");
    let arch = float.solve(&V::zeros(), &V::new(40.0, 0.0, 0.0), &water, None).unwrap();
    let (f1, f2) = arch.end_forces();
    assert_relative_eq!(f1 + f2, V::new(0.0, 0.0, (1025.0 * 0.01 - 5.0) * G * 50.0), max_relative = 1e-10);
    assert!(arch.sample(10)[5].0.z > 5.0, "the middle rises: {:?}", arch.sample(10)[5]);
}

/// Non-finite end positions are an error on the seabed too, never NaN forces.
#[test]
fn non_finite_ends_are_an_error() {
    let l = line(800.0, 500.0, 1e9);
    let surroundings = on_seabed(-80.0, 0.5);
    assert!(l.solve(&V::new(0.0, 0.0, -80.0), &V::new(f64::NAN, 0.0, 1.0), &surroundings, None).is_err());
    assert!(l.solve(&V::new(0.0, 0.0, -80.0), &V::new(300.0, 0.0, f64::INFINITY), &surroundings, None).is_err());
}

/// A 2 t ball moored by a frictionless chain lying on the seabed, swinging out and back across
/// touchdown changes: kinetic + gravity + line energy stays constant to the leapfrog's O(dt²).
#[test]
fn a_ball_moored_on_a_grounded_chain_conserves_energy() {
    let scene = tether_scene::parse(
        "Scene(dt: 2e-3, bodies: [Body(name: \"ball\", master: Node(position: (80.0, 0.0, -20.0), mass: 2000.0,
            inertia: Inertia(xx: 500.0, yy: 500.0, zz: 500.0)), velocity: (1.5, 1.0, 0.0), shape: Sphere(radius: 0.5))],
         couplings: [Catenary(name: \"chain\", end1: World((0.0, 0.0, -50.0)), end2: Body(body: \"ball\"),
            mass_per_length: 20.0, length: 100.0, stiffness: 1e6),
            SpringDamper(name: \"float\", end1: Body(body: \"ball\"), end2: World((80.0, 0.0, 100.0)),
            law: Linear(stiffness: 2e4, rest_length: 119.0))])",
        std::path::Path::new("moored.ron"),
    )
    .unwrap();
    let system = scene.world.system().clone().with_seabed(Seabed::new(-50.0, 0.0).unwrap()).unwrap();
    let mut world = tether_physics::world::World::new(system, scene.world.timing()).unwrap();
    assert!(world.line_state(0).unwrap().ground.is_some(), "the chain starts on the bottom");
    let e0 = world.energy();
    let (mut largest_kinetic, mut worst) = (0.0_f64, 0.0_f64);
    let mut lengths = (f64::INFINITY, 0.0_f64);
    for _ in 0..10_000 {
        world.step().unwrap();
        let e = world.energy();
        largest_kinetic = largest_kinetic.max(e.kinetic);
        worst = worst.max((e.balance() - e0.balance()).abs());
        let lb = world.line_state(0).unwrap().grounded_length();
        lengths = (lengths.0.min(lb), lengths.1.max(lb));
    }
    assert!(lengths.1 - lengths.0 > 5.0, "the touchdown moves: L_B from {} to {} m", lengths.0, lengths.1);
    assert!(largest_kinetic > 1000.0, "it swings: {largest_kinetic} J");
    assert!(worst < 1e-3 * largest_kinetic, "balance drift {worst} J against {largest_kinetic} J of motion");
}
