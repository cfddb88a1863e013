//! Stable time step estimates against the integrators' real thresholds (springs, a catenary, a
//! contact: bounded at 0.99 of the estimate, growing at 1.01), the impact limit `substeps: Auto`
//! holds, and divergence detection (PHYSICS.md §1 "Stable time step", §5 "Health check").

use tether_test_support as common;

use approx::{assert_abs_diff_eq, assert_relative_eq};
use common::oscillator;
use tether_physics::stability;
use tether_physics::world::StepError;

/// Standard gravity [m/s²], the scenes' default.
const G: f64 = 9.80665;

/// Steps until the world reports an error, or `None` if it stays healthy for `steps`.
fn steps_to_failure(world: &mut tether_physics::world::World, steps: usize) -> Option<(usize, StepError)> {
    (0..steps).find_map(|i| world.step().err().map(|e| (i, e)))
}

/// m = 1 kg, k = 100 N/m (ω = 10 rad/s): undamped, and ζ = 0.1, 0.5, 1. The estimator gives
/// `2(√(1+ζ²) − ζ)/ω` = 0.2, 0.18100, 0.12361, 0.08284 s; the leapfrog stays bounded at 0.99
/// of it for 20 000 steps and blows up at 1.01 of it.
#[test]
fn leapfrog_thresholds_match_the_estimator_within_one_percent() {
    let omega: f64 = 10.0;
    for (zeta, expected) in [(0.0_f64, 0.2), (0.1, 0.18100), (0.5, 0.12361), (1.0, 0.08284)] {
        let damping = 2.0 * zeta * omega;
        let world = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", damping, 1.01, 0.0, 1e-3).world;
        let limit = stability::binding(&world.limits()).unwrap();
        // The table, to its five decimals, and the formula it was worked out from, to round-off.
        assert_abs_diff_eq!(limit.dt, expected, epsilon = 5e-6);
        assert_relative_eq!(limit.dt, 2.0 * ((1.0 + zeta * zeta).sqrt() - zeta) / omega, max_relative = 1e-12);

        let mut below =
            oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", damping, 1.01, 0.0, 0.99 * limit.dt).world;
        assert_eq!(steps_to_failure(&mut below, 20_000), None, "ζ = {zeta} at 0.99 of the limit");
        let amplitude = (below.state(0).position.x - 1.0).abs();
        assert!(amplitude <= 0.0101, "bounded: {amplitude}");

        let mut above =
            oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", damping, 1.01, 0.0, 1.01 * limit.dt).world;
        let (_, error) = steps_to_failure(&mut above, 20_000)
            .unwrap_or_else(|| panic!("ζ = {zeta} at 1.01 of the limit did not diverge"));
        let message = error.to_string();
        assert!(matches!(error, StepError::Diverged { ref body, .. } if body == "m"), "{message}");
        assert!(message.contains("set by coupling \"s\""), "{message}");
    }
}

/// The effective mass includes the rotation about the attachment point: a spring on the end
/// of a rod sees `1/m_eff = 1/m + r²/I`.
#[test]
fn effective_mass_includes_rotation_about_the_attachment() {
    // Rod along x, m = 2 kg, I_zz = 0.5 kg·m²; spring along y at r = 0.5 m from G.
    let world = common::scene(
        "Scene(gravity: (0, 0, 0), dt: 1e-3, bodies: [Body(name: \"rod\", master: Node(position: (0, 0, 0), mass: 2.0,
            inertia: Inertia(xx: 0.01, yy: 0.5, zz: 0.5)), shape: Box(size: (1.0, 0.05, 0.05)))],
         couplings: [SpringDamper(name: \"s\", end1: World((0.5, 1.0, 0.0)), end2: Body(body: \"rod\", point: (0.5, 0.0, 0.0)),
            law: Linear(stiffness: 300.0, rest_length: 1.0))])",
    )
    .world;
    let inverse_mass: f64 = 1.0 / 2.0 + 0.25 / 0.5;
    let limit = stability::binding(&world.limits()).unwrap();
    assert_relative_eq!(limit.dt, 2.0 / (300.0 * inverse_mass).sqrt(), max_relative = 1e-12);
}

/// The spring-mass (ω = 10 rad/s, stable step 0.2 s) with a world step of 0.3 s: `substeps:
/// Auto` takes ⌈0.3/(0.9·0.2)⌉ = 2 integrator steps per world step and stays bounded, exactly as
/// a run at dt = 0.15 s; without sub-steps the same dt diverges.
#[test]
fn auto_substeps_make_a_too_large_step_stable() {
    let scene = |dt: f64, substeps: &str| {
        common::scene(&format!(
            "Scene(gravity: (0, 0, 0), dt: {dt:e}, substeps: {substeps}, bodies: [Body(name: \"m\",
                master: Node(position: (1.01, 0, 0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
                support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
             couplings: [SpringDamper(name: \"s\", end1: World((0, 0, 0)), end2: Body(body: \"m\"), law: Linear(stiffness: 100.0, rest_length: 1.0))])"
        ))
        .world
    };
    let mut auto = scene(0.3, "Auto");
    assert_eq!(auto.substeps(), 2);
    assert_relative_eq!(auto.step_size(), 0.15, max_relative = 1e-15);
    let mut fine = scene(0.15, "Fixed(1)");
    for _ in 0..1000 {
        auto.step().unwrap();
        fine.step().unwrap();
        fine.step().unwrap();
        assert_eq!(auto.state(0).position, fine.state(0).position);
    }
    assert_eq!(auto.steps(), 1000);
    assert!((auto.state(0).position.x - 1.0).abs() <= 0.0101);
    let mut plain = scene(0.3, "Fixed(1)");
    assert!(steps_to_failure(&mut plain, 1000).is_some());
    let mut fixed = scene(0.3, "Fixed(3)");
    assert_eq!(fixed.substeps(), 3);
    assert_eq!(steps_to_failure(&mut fixed, 1000), None);
}

/// A live edit re-plans `substeps: Auto` (docs/scenes.md): the spring-mass at dt = 0.3 s runs
/// ⌈0.3/(0.9·0.2)⌉ = 2 sub-steps; its spring stiffened to 400 N/m (stable step 2/20 = 0.1 s)
/// takes ⌈0.3/(0.9·0.1)⌉ = 4 and stays bounded, where `Fixed(2)` under the same edit diverges;
/// softened to 25 N/m (0.4 s) it needs ⌈0.3/0.36⌉ = 1.
#[test]
fn auto_substeps_are_planned_again_after_a_live_edit() {
    let scene = |substeps: &str, stiffness: f64| {
        common::scene(&format!(
            "Scene(gravity: (0, 0, 0), dt: 0.3, substeps: {substeps}, bodies: [Body(name: \"m\",
                master: Node(position: (1.01, 0, 0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
                support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
             couplings: [SpringDamper(name: \"s\", end1: World((0, 0, 0)), end2: Body(body: \"m\"), law: Linear(stiffness: {stiffness:e}, rest_length: 1.0))])"
        ))
        .world
    };
    let spring = |stiffness: f64| scene("Auto", stiffness).couplings()[0].clone();
    let mut auto = scene("Auto", 100.0);
    let mut fixed = scene("Fixed(2)", 100.0);
    assert_eq!((auto.substeps(), fixed.substeps()), (2, 2));
    for _ in 0..10 {
        auto.step().unwrap();
        fixed.step().unwrap();
    }
    auto.replace_coupling(0, spring(400.0)).unwrap();
    fixed.replace_coupling(0, spring(400.0)).unwrap();
    assert_eq!(auto.substeps(), 4);
    assert_relative_eq!(auto.step_size(), 0.075, max_relative = 1e-15);
    assert_eq!(fixed.substeps(), 2, "a fixed count is the user's");
    assert_eq!(steps_to_failure(&mut auto, 1000), None);
    assert!((auto.state(0).position.x - 1.0).abs() <= 0.0101, "bounded: {}", auto.state(0).position.x);
    assert!(steps_to_failure(&mut fixed, 1000).is_some(), "0.15 s steps on a 0.1 s stable step diverge");

    auto.replace_coupling(0, spring(25.0)).unwrap();
    assert_eq!(auto.substeps(), 1);
    assert_eq!(steps_to_failure(&mut auto, 1000), None);
}

/// |R(z)|² of RK4, `R = 1 + z + z²/2 + z³/6 + z⁴/24`, for `z = x + iy`, written out here apart
/// from the estimator's.
fn rk4_gain(x: f64, y: f64) -> f64 {
    let (mut re, mut im, mut term_re, mut term_im) = (1.0, 0.0, 1.0, 0.0);
    for k in 1..=4 {
        let (r, i) = ((term_re * x - term_im * y) / f64::from(k), (term_re * y + term_im * x) / f64::from(k));
        (term_re, term_im) = (r, i);
        re += r;
        im += i;
    }
    (re * re + im * im).sqrt()
}

/// RK4 on the same oscillators: the estimator's limit is where `|R(dt λ)| = 1` along the
/// oscillator's eigenvalue `λ = ω(−ζ ± i√(1−ζ²))` (real `−ω` at ζ = 1): 2√2/ω = 0.282843 s
/// undamped, 0.295085 s at ζ = 0.1 (the region bulges left of the imaginary axis), 0.262254 s
/// at ζ = 0.5 and 0.278529 s at ζ = 1 (RK4's real-axis limit 2.78529). RK4 stays bounded at
/// 0.99 of it for 20 000 steps (it damps) and blows up at 1.01. At ζ = 1 the step map is
/// defective (a double eigenvalue): below the limit the energy still swings up by
/// ~n·|R|ⁿ before it decays — 2600× at 0.99, 19× at 0.9, 2.5× at 0.8 of the limit — so the
/// health check stops 0.99× as it should stop any such swing; there it is checked at 0.8×.
#[test]
fn rk4_thresholds_match_the_estimator_within_one_percent() {
    let omega: f64 = 10.0;
    for (zeta, expected, below_factor) in
        [(0.0_f64, 0.2828427, 0.99), (0.1, 0.295085, 0.99), (0.5, 0.262254, 0.99), (1.0, 0.2785294, 0.8)]
    {
        let damping = 2.0 * zeta * omega;
        let scene = |dt: f64| {
            common::scene(&format!(
                "Scene(gravity: (0, 0, 0), dt: {dt:e}, integrator: rk4, bodies: [Body(name: \"m\",
                    master: Node(position: (1.01, 0, 0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
                    support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
                 couplings: [SpringDamper(name: \"s\", end1: World((0, 0, 0)), end2: Body(body: \"m\"),
                    law: Linear(stiffness: 100.0, rest_length: 1.0), damping: {damping:e})])"
            ))
            .world
        };
        let limit = stability::binding(&scene(1e-3).limits()).unwrap();
        assert_relative_eq!(limit.dt, expected, max_relative = 2e-6);
        let (x, y) = if zeta < 1.0 { (-zeta * omega, omega * (1.0 - zeta * zeta).sqrt()) } else { (-omega, 0.0) };
        assert_relative_eq!(rk4_gain(x * limit.dt, y * limit.dt), 1.0, epsilon = 1e-9);

        let mut below = scene(below_factor * limit.dt);
        assert_eq!(steps_to_failure(&mut below, 20_000), None, "ζ = {zeta} at {below_factor} of the limit");
        assert!((below.state(0).position.x - 1.0).abs() <= 0.0101);
        let mut above = scene(1.01 * limit.dt);
        let (_, error) = steps_to_failure(&mut above, 20_000)
            .unwrap_or_else(|| panic!("ζ = {zeta} at 1.01 of the limit did not diverge"));
        assert!(error.to_string().contains("set by coupling \"s\""), "{error}");
    }
}

/// The splitting and the leapfrog2 move translation exactly as the leapfrog: Belytschko's limit
/// `2(√(1+ζ²) − ζ)/ω` holds for them too (ζ = 0 and 0.5, at 0.99× and 1.01×).
#[test]
fn splitting_and_leapfrog2_share_the_leapfrog_threshold() {
    let omega: f64 = 10.0;
    for integrator in ["splitting", "leapfrog2"] {
        for zeta in [0.0_f64, 0.5] {
            let scene = |dt: f64| {
                common::scene(&format!(
                    "Scene(gravity: (0, 0, 0), dt: {dt:e}, integrator: {integrator}, bodies: [Body(name: \"m\",
                        master: Node(position: (1.01, 0, 0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
                        support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
                     couplings: [SpringDamper(name: \"s\", end1: World((0, 0, 0)), end2: Body(body: \"m\"),
                        law: Linear(stiffness: 100.0, rest_length: 1.0), damping: {:e})])",
                    2.0 * zeta * omega
                ))
                .world
            };
            let limit = stability::binding(&scene(1e-3).limits()).unwrap();
            assert_relative_eq!(limit.dt, 2.0 * ((1.0 + zeta * zeta).sqrt() - zeta) / omega, max_relative = 1e-12);
            assert_eq!(steps_to_failure(&mut scene(0.99 * limit.dt), 20_000), None, "{integrator}, ζ = {zeta}, 0.99×");
            assert!(steps_to_failure(&mut scene(1.01 * limit.dt), 20_000).is_some(), "{integrator}, ζ = {zeta}, 1.01×");
        }
    }
}

/// `substeps: Auto` uses the scene's integrator's limit: at dt = 0.5 s on ω = 10 rad/s, RK4 takes
/// ⌈0.5/(0.9·0.28284)⌉ = 2 sub-steps where the leapfrog takes ⌈0.5/(0.9·0.2)⌉ = 3, and the
/// adaptive dopri45 takes one (its own steps adapt) and stays on the closed form.
#[test]
fn auto_substeps_follow_the_integrator() {
    let scene = |integrator: &str| {
        common::scene(&format!(
            "Scene(gravity: (0, 0, 0), dt: 0.5, integrator: {integrator}, substeps: Auto, adaptive: (rtol: 1e-9, atol: 1e-12), bodies: [Body(name: \"m\",
                master: Node(position: (1.01, 0, 0), mass: 1.0, inertia: Inertia(xx: 0.01, yy: 0.01, zz: 0.01)),
                support: Fixed(translation: (false, true, true), rotation: true), shape: Sphere(radius: 0.1))],
             couplings: [SpringDamper(name: \"s\", end1: World((0, 0, 0)), end2: Body(body: \"m\"), law: Linear(stiffness: 100.0, rest_length: 1.0))])"
        ))
        .world
    };
    for (integrator, substeps) in [("leapfrog", 3), ("splitting", 3), ("rk4", 2), ("dopri45", 1)] {
        let mut world = scene(integrator);
        assert_eq!(world.substeps(), substeps, "{integrator}");
        for _ in 0..20 {
            world.step().unwrap();
        }
        assert!((world.state(0).position.x - 1.0).abs() <= 0.0101, "{integrator} bounded");
        if integrator == "dopri45" {
            // x = 0.01 cos(10 t) at t = 10 s; every world step ends exactly on its boundary.
            assert_relative_eq!(world.state(0).position.x - 1.0, 0.01 * 100f64.cos(), epsilon = 1e-8);
            assert_eq!(world.time(), 10.0);
            assert!(
                world.integrator_steps() > 20 && world.rejected_steps() < world.integrator_steps(),
                "{} / {}",
                world.integrator_steps(),
                world.rejected_steps()
            );
        }
    }
}

/// A 100 kg body hanging on a vertical catenary (λ0 = 1 kg/m, L = 10 m, D = 1e5 N/m) from the
/// world point (0, 0, 10), free only along z. The line's tangent stiffness along the vertical is
/// exactly `D` (its stretch `(T_b L + ½ λ0 g L²)/(D L)` is linear in the bottom tension `T_b`),
/// so the leapfrog's limit is `2/ω`, `ω = √(D/m)`: 0.0632456 s. Started 1 mm above its static
/// position (the line 10.3 mm stretched, so it stays taut), the body stays within 1 mm of it
/// for 20 000 steps at 0.99 of the limit and blows up at 1.01 of it.
#[test]
fn catenary_threshold_matches_the_estimator_within_one_percent() {
    let (mass, weight_per_length, length, stiffness) = (100.0_f64, 1.0 * G, 10.0, 1e5);
    let stretch = (mass * G * length + 0.5 * weight_per_length * length * length) / (stiffness * length);
    let rest = 10.0 - length - stretch;
    let scene = |dt: f64| {
        common::scene(&format!(
            "Scene(dt: {dt:e}, bodies: [Body(name: \"m\",
                master: Node(position: (0, 0, {z:e}), mass: {mass:e}, inertia: Inertia(xx: 1, yy: 1, zz: 1)),
                support: Fixed(translation: (true, true, false), rotation: true), shape: Sphere(radius: 0.1))],
             couplings: [Catenary(name: \"line\", end1: World((0, 0, 10)), end2: Body(body: \"m\"),
                mass_per_length: 1.0, length: {length:e}, stiffness: {stiffness:e})])",
            z = rest + 1e-3
        ))
        .world
    };
    let limit = stability::binding(&scene(1e-3).limits()).unwrap();
    assert_eq!(limit.limiter, stability::Limiter::Coupling(0));
    // The tangent stiffness comes from the solver's vertical closed form: exact to round-off.
    assert_relative_eq!(limit.dt, 2.0 / (stiffness / mass).sqrt(), max_relative = 1e-12);

    let (swing, _) =
        vertical_swing(&mut scene(0.99 * limit.dt), 20_000, rest).unwrap_or_else(|e| panic!("0.99 of the limit: {e}"));
    // Started at rest 1 mm off, the leapfrog on a linear oscillator gives x_n = x0 cos(nθ),
    // cos θ = 1 − (ωh)²/2, exactly: the swing stays 1 mm (the taut line is linear; the margin is
    // round-off).
    assert!(swing <= 1e-3 * (1.0 + 1e-6), "bounded: {swing}");

    let (_, error) = steps_to_failure(&mut scene(1.01 * limit.dt), 20_000).expect("1.01 of the limit diverges");
    assert!(error.to_string().contains("set by coupling \"line\""), "{error}");
}

/// Runs `world` for `steps` steps; returns its largest `|z − rest|` [m] over the run and over
/// the last 1000 steps, or the error that stopped it.
fn vertical_swing(world: &mut tether_physics::world::World, steps: usize, rest: f64) -> Result<(f64, f64), StepError> {
    let (mut swing, mut late) = (0.0_f64, 0.0_f64);
    for i in 0..steps {
        world.step()?;
        let offset = (world.state(0).position.z - rest).abs();
        swing = swing.max(offset);
        if i + 1000 >= steps {
            late = late.max(offset);
        }
    }
    Ok((swing, late))
}

/// A 10 kg box (0.3 m cube, its bottom split into 16 faces) resting on the ground, free only
/// along z, without friction: the bottom faces in range push with `k1 A (d0 − d) − k2 A ḋ`,
/// `A` = 0.09 m², an oscillator of `k = k1 A` = 9e4 N/m over m (ω = 94.87 rad/s) with damping
/// `c = k2 A`. The expected area is the bottom, so the estimator's area is exact; the side faces
/// are 37.5 mm up, out of range. At ζ = 0, 0.1, 0.3, 0.5 the leapfrog's limit is
/// `2(√(1+ζ²) − ζ)/ω` = 0.021082, 0.019079, 0.015686, 0.013029 s.
///
/// Started 0.5 mm above its resting height (1.09 mm deep, so it stays in range), at 0.99 of the
/// limit the box never strays further than that in 20 000 steps. At 1.01 of it the motion grows:
/// undamped and at ζ = 0.1 it blows up and the health check names the contact; at ζ = 0.3 and 0.5
/// the mode that grows (the step-to-step flip) is capped by the contact's one-sidedness (no
/// adhesion: the force is clamped at ≥ 0) and keeps swinging at 0.46–0.70 mm, where the stable
/// run has decayed to round-off (1e-16 m).
#[test]
fn contact_threshold_matches_the_estimator_within_one_percent() {
    let (mass, k1, area, range) = (10.0_f64, 1e6_f64, 0.09, 5e-3);
    let omega = (k1 * area / mass).sqrt();
    let rest = 0.15 + range - mass * G / (k1 * area);
    let start = 5e-4;
    for (zeta, expected) in [(0.0_f64, 0.021082), (0.1, 0.019079), (0.3, 0.015686), (0.5, 0.013029)] {
        let k2 = 2.0 * zeta * (k1 * area * mass).sqrt() / area;
        let scene = |dt: f64| {
            common::scene(&format!(
                "Scene(dt: {dt:e}, bodies: [Body(name: \"box\",
                    master: Node(position: (0, 0, {z:e}), mass: {mass:e}, inertia: Inertia(xx: 0.15, yy: 0.15, zz: 0.15)),
                    support: Fixed(translation: (true, true, false), rotation: true), shape: Box(size: (0.3, 0.3, 0.3)))],
                 couplings: [Contact(name: \"ground\", body: \"box\", against: Plane(point: (0, 0, 0), normal: (0, 0, 1)),
                    stiffness: {k1:e}, damping: {k2:e}, range: {range:e}, expected_area: {area:e})])",
                z = rest + start
            ))
            .world
        };
        let limit = stability::binding(&scene(1e-4).limits()).unwrap();
        assert_eq!(limit.limiter, stability::Limiter::Coupling(0));
        assert_relative_eq!(limit.dt, expected, max_relative = 5e-5);
        assert_relative_eq!(limit.dt, 2.0 * ((1.0 + zeta * zeta).sqrt() - zeta) / omega, max_relative = 1e-12);

        let (swing, late) = vertical_swing(&mut scene(0.99 * limit.dt), 20_000, rest)
            .unwrap_or_else(|e| panic!("ζ = {zeta} at 0.99 of the limit: {e}"));
        // Undamped, x_n = x0 cos(nθ) exactly (see the catenary above); damped, it only decays.
        assert!(swing <= start * (1.0 + 1e-9), "ζ = {zeta} at 0.99: bounded: {swing}");
        if zeta > 0.0 {
            assert!(late < 1e-12, "ζ = {zeta} at 0.99: decays: {late}");
        }

        match vertical_swing(&mut scene(1.01 * limit.dt), 20_000, rest) {
            Err(error) => {
                assert!(zeta < 0.2 && error.to_string().contains("set by coupling \"ground\""), "ζ = {zeta}: {error}")
            }
            // Grown from round-off to most of the start offset, and held there.
            Ok((_, late)) => {
                assert!(zeta > 0.2 && late > 0.8 * start, "ζ = {zeta} at 1.01 of the limit: late swing {late}")
            }
        }
    }
}

/// The same box dropped flat at 1 m/s from 5 cm onto an undamped ground (k1 = 1e6 N/m³ over its
/// 0.09 m² bottom: ω = 94.87 rad/s, stopping time τ = (π/2)/ω = 16.56 ms, PHYSICS.md §4) with a
/// world step dt = τ. That step is stable (the limit is 2/ω = 1.27 τ) but resolves no impact;
/// `substeps: Auto` takes ⌈dt/(0.9 τ/10)⌉ = 12 integrator steps per world step, so each is
/// below τ/10 at every step of the run, and the box leaves the ground with the energy it came
/// with (the law is conservative: restitution 1).
#[test]
fn auto_substeps_hold_the_impact_limit() {
    let (mass, k1, area, range) = (10.0_f64, 1e6_f64, 0.09, 5e-3);
    let omega = (k1 * area / mass).sqrt();
    let tau = std::f64::consts::FRAC_PI_2 / omega;
    let scene = |substeps: &str| {
        common::scene(&format!(
            "Scene(dt: {tau:e}, substeps: {substeps}, bodies: [Body(name: \"box\",
                master: Node(position: (0, 0, {z:e}), mass: {mass:e}, inertia: Inertia(xx: 0.15, yy: 0.15, zz: 0.15)),
                velocity: (0, 0, -1), support: Fixed(translation: (true, true, false), rotation: true), shape: Box(size: (0.3, 0.3, 0.3)))],
             couplings: [Contact(name: \"ground\", body: \"box\", against: Plane(point: (0, 0, 0), normal: (0, 0, 1)),
                stiffness: {k1:e}, range: {range:e}, expected_area: {area:e})])",
            z = 0.15 + range + 0.05
        ))
        .world
    };
    // Energy in free flight before and after the bounce (kinetic + gravity: the leapfrog is exact
    // for a constant force), and whether the impact limit held at every step.
    let bounce = |world: &mut tether_physics::world::World| {
        let before = world.energy().total();
        let mut held = true;
        let mut touched = false;
        // The box is back in the air within a second: one that stays on the ground fails.
        loop {
            assert!(world.time() < 2.0, "no rebound by t = 2 s");
            world.step().unwrap();
            let limit = stability::binding(&world.impact_limits()).unwrap();
            held &= world.step_size() <= limit.dt;
            let in_range = world.state(0).position.z < 0.15 + range;
            touched |= in_range;
            if touched && !in_range && world.coupling_forces()[0].tension == 0.0 {
                return (before, world.energy().total(), held);
            }
        }
    };
    let mut auto = scene("Auto");
    assert_eq!(auto.substeps(), 12);
    assert!(auto.step_size() <= tau / 10.0);
    let limit = stability::binding(&auto.impact_limits()).unwrap();
    assert_eq!(limit.limiter, stability::Limiter::Impact(0));
    assert_relative_eq!(limit.dt, tau / 10.0, max_relative = 1e-12);
    let impact = 0.5 * mass * 1.0_f64.powi(2) + mass * G * 0.05;
    let (before, after, held) = bounce(&mut auto);
    assert!(held, "an integrator step exceeded τ/10 during the impact");
    // Through a contact the leapfrog's energy differs from the exact one by at most about
    // (ωh)²/4 of it (its shadow energy): 4.3e-3 at h = τ/12; measured 1.2e-3.
    let error = (after - before) / impact;
    let bound = (omega * auto.step_size()).powi(2) / 4.0;
    assert!(error.abs() < bound, "rebound energy error {error} (bound {bound})");
    // One step per τ: stable, but it loses 9.6 % of the energy in one bounce.
    let mut single = scene("Fixed(1)");
    let (before, after, held) = bounce(&mut single);
    assert!(!held);
    assert!(((after - before) / impact).abs() > 10.0 * bound, "{}", (after - before) / impact);
}
