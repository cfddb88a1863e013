//! Stable time step estimates against the leapfrog's real thresholds, and divergence detection
//! (issues 5 and 6).

mod common;

use approx::assert_relative_eq;
use common::oscillator;
use tether::physics::stability;
use tether::physics::world::StepError;

/// Steps until the world reports an error, or `None` if it stays healthy for `steps`.
fn steps_to_failure(world: &mut tether::physics::world::World, steps: usize) -> Option<(usize, StepError)> {
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
        let limit = stability::binding(&stability::limits(&world)).unwrap();
        assert_relative_eq!(limit.dt, expected, max_relative = 1e-4);
        assert_relative_eq!(limit.dt, 2.0 * ((1.0 + zeta * zeta).sqrt() - zeta) / omega, max_relative = 1e-12);

        let mut below = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", damping, 1.01, 0.0, 0.99 * limit.dt).world;
        assert_eq!(steps_to_failure(&mut below, 20_000), None, "ζ = {zeta} at 0.99 of the limit");
        let amplitude = (below.state(0).position.x - 1.0).abs();
        assert!(amplitude <= 0.0101, "bounded: {amplitude}");

        let mut above = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", damping, 1.01, 0.0, 1.01 * limit.dt).world;
        let (_, error) = steps_to_failure(&mut above, 20_000).unwrap_or_else(|| panic!("ζ = {zeta} at 1.01 of the limit did not diverge"));
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
    let limit = stability::binding(&stability::limits(&world)).unwrap();
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
