//! Live tuning in the physics: a coupling replaced and the time step changed while running,
//! against closed forms, and the energy ledger kept continuous across the change.

use tether_test_support as common;

use common::oscillator;
use tether_physics::integrator::{Integrator, Substeps, Timing, Tolerances};
use tether_physics::world::World;
use tether_scene::{self as scene, build};

/// Runs until t ≈ `t`.
fn run_to(world: &mut World, t: f64) {
    while world.time() < t - 0.5 * world.dt() {
        world.step().unwrap();
    }
}

/// `x(t) − 1` of the undamped oscillator m = 1 released from `x`, `v` at t0 with stiffness k.
fn free_motion(x: f64, v: f64, k: f64, dt: f64) -> f64 {
    let omega = k.sqrt();
    x * (omega * dt).cos() + v / omega * (omega * dt).sin()
}

/// Swapping k = 100 → 400 N/m at t = 0.3 s: the motion goes on from the same state at the new
/// frequency, second order across the swap (error at dt = 1e-4 under 1e-7 m of a 1e-2 m
/// amplitude; a kick with the new force over the whole step would be off by ½dt Δγ/ω ≈ 6e-6 m),
/// and the balance jumps by nothing: the change of elastic energy is booked as external work.
#[test]
fn a_stiffer_spring_swapped_in_continues_the_motion_at_the_new_frequency() {
    let dt = 1e-4;
    let mut loaded = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", 0.0, 1.01, 0.0, dt);
    run_to(&mut loaded.world, 0.3);
    let world = &mut loaded.world;
    let (t0, state) = (world.time(), world.state(0));
    let before = world.energy();
    if let scene::file::CouplingDef::SpringDamper { law: scene::file::LawDef::Linear { stiffness, .. }, .. } =
        &mut loaded.file.couplings[0]
    {
        *stiffness = 400.0;
    }
    let stiffer = build::coupling(&loaded.file, 0, &mut loaded.bodies).unwrap();
    world.replace_coupling(0, stiffer).unwrap();
    let after = world.energy();
    let elastic_jump = 0.5 * 300.0 * (state.position.x - 1.0).powi(2);
    assert!((after.elastic - before.elastic - elastic_jump).abs() < 1e-12, "{before:?} → {after:?}");
    assert!((after.balance() - before.balance()).abs() < 1e-12, "balance jumped: {before:?} → {after:?}");
    assert_eq!(world.time(), t0, "the swap must not move time");
    assert!((world.state(0).velocity - state.velocity).norm() < 1e-15, "the swap must not move the velocity");
    for t in [0.35, 0.5, 0.8] {
        run_to(world, t);
        let exact = free_motion(state.position.x - 1.0, state.velocity.x, 400.0, world.time() - t0);
        let error = world.state(0).position.x - 1.0 - exact;
        assert!(error.abs() < 1e-7, "t = {t}: error {error:e} m");
    }
    assert!((world.energy().balance() - before.balance()).abs() < 1e-6, "drift after the swap");
}

/// A damper added while running dissipates from then on, and the balance still holds.
#[test]
fn a_damper_added_while_running_dissipates_and_the_balance_holds() {
    let mut loaded = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", 0.0, 1.01, 0.0, 1e-4);
    run_to(&mut loaded.world, 0.2);
    let balance = loaded.world.energy().balance();
    if let scene::file::CouplingDef::SpringDamper { damping, .. } = &mut loaded.file.couplings[0] {
        *damping = 5.0;
    }
    let damped = build::coupling(&loaded.file, 0, &mut loaded.bodies).unwrap();
    loaded.world.replace_coupling(0, damped).unwrap();
    run_to(&mut loaded.world, 1.2);
    let energy = loaded.world.energy();
    assert!(energy.dissipated > 0.5 * 0.5 * 100.0 * 1e-4, "dissipated only {} J", energy.dissipated);
    assert!((energy.balance() - balance).abs() < 1e-2 * 0.5 * 100.0 * 1e-4, "balance drifted: {energy:?}");
}

/// Refused values name the field with its unit, exactly as the loader would.
#[test]
fn tuned_values_are_checked_by_the_scene_builder() {
    let mut loaded = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", 0.0, 1.01, 0.0, 1e-3);
    if let scene::file::CouplingDef::SpringDamper { damping, .. } = &mut loaded.file.couplings[0] {
        *damping = -1.0;
    }
    let refused = build::coupling(&loaded.file, 0, &mut loaded.bodies).unwrap_err();
    assert_eq!(refused.message, "coupling \"s\": damping must be ≥ 0 N·s/m, got -1");
    assert!(build::coupling(&loaded.file, 7, &mut loaded.bodies).is_err());
}

/// Halving dt mid-run keeps the oscillator on its closed-form path (x0 cos ωt).
#[test]
fn the_time_step_changed_while_running_keeps_the_motion() {
    let mut world = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", 0.0, 1.01, 0.0, 1e-3).world;
    run_to(&mut world, 0.25);
    let halved = Timing::new(5e-4, Integrator::Leapfrog2, Substeps::Fixed(2), Tolerances::default());
    world.set_timing(halved.expect("a valid setting")).unwrap();
    assert_eq!((world.dt(), world.substeps()), (5e-4, 2));
    run_to(&mut world, 1.0);
    let error = world.state(0).position.x - 1.0 - 0.01 * (10.0 * world.time()).cos();
    assert!(error.abs() < 1e-6, "error {error:e} m");
    // Bad settings never reach the world: their constructor refuses them, naming the field.
    let refused = |dt: f64, substeps: u32| {
        Timing::new(dt, Integrator::Leapfrog, Substeps::Fixed(substeps), Tolerances::default()).unwrap_err().to_string()
    };
    assert_eq!(refused(0.0, 1), "dt must be > 0 s, got 0");
    assert_eq!(refused(1e-3, 0), "substeps must be at least 1, got 0");
    assert_eq!(world.dt(), 5e-4, "a refused setting leaves the world as it was");
}

/// A refused edit says what it is — an index the world does not have, a body it does not have —
/// and leaves the world as it was (a system error was once reported as "no such coupling").
#[test]
fn a_refused_coupling_edit_names_its_cause_and_leaves_the_world_as_it_was() {
    use tether_physics::coupling::{Coupling, CouplingKind, ElasticLaw, Endpoint, SpringDamper};
    use tether_physics::math::Vec3;
    use tether_physics::system::SystemError;
    use tether_physics::world::EditError;
    let mut world = oscillator("Linear(stiffness: 100.0, rest_length: 1.0)", 0.0, 1.01, 0.0, 1e-3).world;
    run_to(&mut world, 0.1);
    let (time, position, balance) = (world.time(), world.state(0).position, world.energy().balance());
    let to_body = |body: usize| {
        let law = ElasticLaw::Linear { stiffness: 400.0, rest_length: 1.0 };
        let spring = SpringDamper::new(Endpoint::World(Vec3::zeros()), Endpoint::Center { body }, law, 0.0);
        Coupling { name: "s".into(), kind: CouplingKind::SpringDamper(spring.expect("a valid spring")) }
    };
    let out_of_range = world.replace_coupling(7, to_body(0)).unwrap_err();
    assert_eq!(out_of_range, EditError::NoSuchCoupling { index: 7, count: 1 });
    assert_eq!(out_of_range.to_string(), "the world has no coupling 7 (it has 1)");
    let unknown_body = world.replace_coupling(0, to_body(3)).unwrap_err();
    assert_eq!(unknown_body, EditError::System(SystemError::UnknownBody { coupling: "s".into(), body: 3, count: 1 }));
    assert_eq!(unknown_body.to_string(), "coupling \"s\" refers to body 3, but the system has 1 bodies");
    assert_eq!((world.time(), world.state(0).position, world.energy().balance()), (time, position, balance));
    assert!(matches!(&world.couplings()[0].kind, CouplingKind::SpringDamper(s) if s.law().force(2.0) == 100.0));
}
