//! Dynamic lines (PHYSICS.md §8) through the scene file: `moored_buoy` with its chains dynamic
//! keeps its energy balance, a taut dry line conserves energy at second order, and each bad
//! value reads its constructor's message at its line and column.

use tether_test_support as common;

/// `scenes/moored_buoy.ron` with its three chains dynamic at `segments`, stepped by `integrator`
/// at time step `dt`.
fn dynamic_buoy(segments: u32, integrator: &str, dt: f64) -> String {
    let text = std::fs::read_to_string(common::repo("scenes/moored_buoy.ron")).unwrap();
    let dynamic = format!(
        "model: Dynamic(segments: {segments}, damping: Ratio(0.8), drag_normal: 2.4, \
         drag_tangential: 1.15, added_mass_normal: 1.0, added_mass_tangential: 0.5),"
    );
    let text = text
        .replace("model: QuasiStatic,", &dynamic)
        .replace("integrator: rk4,", &format!("integrator: {integrator},"));
    let text = regex_dt(&text, dt);
    assert_eq!(text.matches(&dynamic).count(), 3, "three chains made dynamic");
    text
}

/// `text` with its scene's `dt` set to `dt`.
fn regex_dt(text: &str, dt: f64) -> String {
    let start = text.find("    dt: ").expect("a scene with a dt");
    let end = start + text[start..].find(',').expect("dt ends with a comma");
    format!("{}    dt: {dt:e}{}", &text[..start], &text[end..])
}

/// Over 60 s of the buoy's gust release in its wave and current (drag, damping, seabed
/// friction on every node), the balance closes to 2.5e-4 of the largest energy the run
/// exchanges (kinetic, dissipated or put in): at 2.5 ms it drifts 121 J of 0.67 MJ (1.8e-4,
/// printed) — the partitioned exchange with the buoy, first order in the bodies' step (32 J when
/// the chains sub-stepped explicitly at 1.2 ms), and the chains' own sub-steps, 18 ms since
/// their segments are taken implicitly (PHYSICS.md §8).
#[test]
fn the_moored_buoy_on_dynamic_chains_keeps_its_energy_balance() {
    let mut scene = common::scene(&dynamic_buoy(20, "leapfrog", 0.0025));
    let world = &mut scene.world;
    let start = world.energy();
    let mut worst: f64 = 0.0;
    let mut exchanged: f64 = 0.0;
    while world.time() < 60.0 - 1e-9 {
        world.step().unwrap();
        let now = world.energy();
        worst = worst.max((now.balance() - start.balance()).abs());
        exchanged = exchanged.max(now.kinetic).max(now.dissipated.abs()).max(now.external_work.abs());
    }
    eprintln!("balance drift {worst:.1} J of {exchanged:.0} J exchanged");
    assert!(worst < 2.5e-4 * exchanged.max(1.0), "balance drift {worst} J of {exchanged} J exchanged");
}

/// `text` with the first `from` after its `couplings:` replaced by `to` (the comment above
/// quotes the same fields).
fn in_couplings(text: &str, from: &str, to: &str) -> String {
    let start = text.find("couplings:").expect("a scene with couplings");
    format!("{}{}", &text[..start], text[start..].replacen(from, to, 1))
}

#[test]
fn each_bad_dynamic_value_is_refused_at_its_place() {
    let good = dynamic_buoy(20, "leapfrog", 0.01);
    common::scene(&good);
    for (edit, expected) in [
        ("segments: 20", "segments must be at least 1, got 0"),
        ("damping: Ratio(0.8)", "damping ratio must be ≥ 0 and ≤ 1, got 1.5"),
        ("drag_normal: 2.4", "drag_normal must be ≥ 0, got -1"),
        ("added_mass_tangential: 0.5", "added_mass_tangential must be ≥ 0, got -0.5"),
    ] {
        let bad = match edit {
            "segments: 20" => "segments: 0",
            "damping: Ratio(0.8)" => "damping: Ratio(1.5)",
            "drag_normal: 2.4" => "drag_normal: -1.0",
            _ => "added_mass_tangential: -0.5",
        };
        let error = common::error_of(&in_couplings(&good, edit, bad));
        assert!(
            error.starts_with("bad.ron:") && error.contains("coupling \"mooring1\"") && error.ends_with(expected),
            "{error}"
        );
        assert_eq!(error.lines().count(), 1, "{error}");
    }
    let error = common::error_of(&in_couplings(&good, "segments: 20", "segments: 20000"));
    assert!(error.ends_with("segments must be at most 10000, got 20000"), "{error}");
}

/// One of issue 48's lines that ran for ever (and ignored SIGTERM): `chain_forced_surge`'s
/// chain 10⁻¹² m long is refused as the scene loads, in one line at the coupling, naming the
/// strain that makes it no line (the other, 10³⁰ N stiff, is refused as it runs:
/// tests/reliability.rs).
#[test]
fn a_line_whose_ends_start_far_beyond_its_length_is_refused_as_the_scene_loads() {
    let good = std::fs::read_to_string(common::repo("scenes/chain_forced_surge.ron")).unwrap();
    common::scene(&good);
    let error = common::error_of(&in_couplings(&good, "length: 250.0", "length: 1e-12"));
    assert!(error.starts_with("bad.ron:") && error.contains("coupling \"chain\""), "{error}");
    assert!(error.contains("a strain of 2.420e14 of its length 1.000000e-12 m (more than 1)"), "{error}");
    assert_eq!(error.lines().count(), 1, "{error}");
}

/// A 100 kg ball swinging on a 10 m dynamic rope (λ0 = 2 kg/m, EA = 2 MN) from a world
/// point, dry, no damping, no seabed: a conservative system.
fn pendulum(dt: f64) -> String {
    format!(
        "Scene(dt: {dt:e}, duration: 10.0, bodies: [Body(name: \"ball\",
            master: Node(position: (6.0, 0.0, 2.0), mass: 100.0, inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
            shape: Sphere(radius: 0.2))],
        couplings: [Catenary(name: \"rope\", end1: World((0.0, 0.0, 10.0)), end2: Body(body: \"ball\"),
            mass_per_length: 2.0, length: 10.0, stiffness: 2.0e5,
            model: Dynamic(segments: 20, damping: Coefficient(0.0)))])"
    )
}

/// Its energy is conserved at second order: the largest drift over 10 s of swinging, 0.053 J of
/// the 2.0 kJ of kinetic energy at its peak at 1 ms, falls 5.4 times at 0.5 ms (order 2.4).
#[test]
fn a_conservative_dynamic_line_keeps_its_energy_at_second_order() {
    let drift = |dt: f64| {
        let mut scene = common::scene(&pendulum(dt));
        let world = &mut scene.world;
        let start = world.energy();
        let (mut worst, mut peak) = (0.0_f64, 0.0_f64);
        while world.time() < 10.0 - 1e-9 {
            world.step().unwrap();
            let now = world.energy();
            assert!(now.dissipated.abs() < 1e-6 * peak.max(1.0), "nothing dissipates: {now:?}");
            worst = worst.max((now.balance() - start.balance()).abs());
            peak = peak.max(now.kinetic);
        }
        (worst, peak)
    };
    let (coarse, peak) = drift(1e-3);
    let (fine, _) = drift(5e-4);
    assert!(coarse < 1e-4 * peak, "drift {coarse} J of {peak} J");
    let order = (coarse / fine).log2();
    assert!((1.8..3.0).contains(&order), "order {order}: {coarse} J at 1 ms, {fine} J at 0.5 ms");
}
