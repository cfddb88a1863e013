//! The couplings stage, the water stage and the leapfrog step are built for AVX-512, AVX2 and the
//! portable instruction set ([`tether_physics::simd`]). Every build this processor runs gives the
//! forces of the portable build, to 1e-12 relative, on a fixed set of states that covers every
//! path: plane contacts with friction (faces in range and out of it, one plane or the six walls
//! of a domain box), a body–body contact, linear and progressive springs with dampers, and a
//! catenary; and on a barge in an irregular sea, the water's forces.
//! On a processor without AVX2 there is only the portable build, and nothing to compare.

use tether_test_support as common;

use tether_physics::body::BodyState;
use tether_physics::coupling::{CouplingForces, CouplingKind};
use tether_physics::evaluation::Evaluation;
use tether_physics::math::{Rotation, Vec3};
use tether_physics::simd::Level;
use tether_physics::system::System;
use tether_physics::world::World;

/// A crate on the ground inside a domain box, a ball on and beside it, a block hanging on a
/// catenary tied to the crate, springs between them. Contact ranges are 1 cm.
const SCENE: &str = r#"Scene(dt: 1e-4, bodies: [
    Body(name: "crate", master: Node(position: (0, 0, 0.15), mass: 20.0, inertia: Inertia(xx: 0.417, yy: 0.75, zz: 0.867)),
        shape: Box(size: (0.6, 0.4, 0.3))),
    Body(name: "ball", master: Node(position: (0.1, 0, 0.4), mass: 2.0, inertia: Inertia(xx: 0.008, yy: 0.008, zz: 0.008)),
        shape: Sphere(radius: 0.1)),
    Body(name: "block", master: Node(position: (2.0, 0, 1.0), mass: 50.0, inertia: Inertia(xx: 1.0, yy: 1.5, zz: 2.0)),
        shape: Box(size: (0.4, 0.3, 0.2))),
],
couplings: [
    Contact(name: "crate_ground", body: "crate", against: Plane(point: (0, 0, 0), normal: (0, 0, 1)),
        stiffness: 2e7, damping: 2e4, range: 0.01, friction: 0.5, friction_sharpness: 50.0),
    Contact(name: "crate_walls", body: "crate", against: DomainBox(min: (-0.32, -0.5, -1.0), max: (3.0, 0.21, 5.0)),
        stiffness: 1e7, damping: 1e4, range: 0.01, friction: 0.3, friction_sharpness: 20.0),
    Contact(name: "ball_on_crate", body: "ball", against: Body("crate"),
        stiffness: 2e7, damping: 2e4, range: 0.01, friction: 0.3, friction_sharpness: 50.0, expected_area: 0.002),
    Contact(name: "ball_ground", body: "ball", against: Plane(point: (0, 0, 0), normal: (0, 0, 1)),
        stiffness: 2e7, damping: 2e4, range: 0.01, friction: 0.4, friction_sharpness: 50.0, expected_area: 0.002),
    SpringDamper(name: "link", end1: Body(body: "crate", point: (0.3, 0.1, 0.15)), end2: Body(body: "ball", point: (0, 0.05, 0)),
        law: Linear(stiffness: 500.0, rest_length: 0.2), damping: 5.0),
    SpringDamper(name: "progressive", end1: World((-1, 0, 1)), end2: Body(body: "crate", point: (-0.3, 0, 0.1)),
        law: Polynomial(a: 1000.0, b: 200.0, c: 5e4, rest_length: 1.0), damping: 20.0),
    Catenary(name: "line", end1: World((2.5, 0.5, 4.0)), end2: Body(body: "block", point: (0, 0, 0.1)),
        mass_per_length: 2.0, length: 3.5, stiffness: 1e6),
    SpringDamper(name: "tie", end1: Body(body: "block", point: (-0.2, 0, 0)), end2: Body(body: "crate", point: (0.3, 0, 0)),
        law: Linear(stiffness: 300.0, rest_length: 1.5), damping: 10.0),
])"#;

/// A deterministic stream of numbers in [−1, 1) (a 64-bit linear congruential generator), so
/// that the states are the same on every run and every machine.
struct Numbers(u64);

impl Numbers {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    fn vector(&mut self, scale: f64) -> Vec3 {
        Vec3::new(self.next(), self.next(), self.next()) * scale
    }
}

/// Twelve sets of states around the scene's start: the crate pitched by 2.3° to 3.5° either way
/// (its bottom in range of the ground at one end, not at the other) and lowered by 1 to 3 mm,
/// touching
/// the domain box's y = 0.21 m wall in some; the ball pressed into the crate's top, or beside
/// it on the ground; the block swinging on its line. Velocities up to 1 m/s and 3 rad/s.
fn state_sets(system: &System) -> Vec<Vec<BodyState>> {
    let mut numbers = Numbers(14);
    (0..12)
        .map(|k| {
            let mut states = system.initial_states().to_vec();
            let (crate_, ball, block) = (0, 1, 2);
            states[crate_].position += Vec3::new(0.0, 0.0, -2e-3 + 1e-3 * numbers.next());
            let pitch = (0.05 + 0.01 * numbers.next()).copysign(numbers.next());
            let tilt = Vec3::new(0.02 * numbers.next(), pitch, 0.01 * numbers.next());
            states[crate_].orientation = Rotation::from_scaled_axis(tilt) * states[crate_].orientation;
            if k % 3 == 0 {
                // Beside the crate, on the ground.
                states[ball].position = Vec3::new(0.45 + 0.01 * numbers.next(), 0.0, 0.098 + 2e-3 * numbers.next());
            } else {
                states[ball].position +=
                    Vec3::new(0.05 * numbers.next(), 0.05 * numbers.next(), -3e-3 + 1e-3 * numbers.next());
            }
            states[block].position += numbers.vector(0.2);
            for state in &mut states {
                state.velocity = numbers.vector(1.0);
                state.angular_velocity = numbers.vector(3.0);
            }
            states
        })
        .collect()
}

/// Whether `a` and `b` agree to `1e-12` of the larger.
fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * a.abs().max(b.abs())
}

fn close_vectors(a: &Vec3, b: &Vec3) -> bool {
    (a - b).norm() <= 1e-12 * a.norm().max(b.norm())
}

/// What the couplings stage built for `level` gives on each set of states, in turn (the
/// contacts' face lists carried from one set to the next, as in a run): each coupling's record
/// and each body's load.
fn evaluations(system: &System, level: Level, sets: &[Vec<BodyState>]) -> Vec<Evaluation> {
    let mut system = system.clone();
    assert!(system.use_level(level), "{level:?} is listed as available");
    let mut evaluation = Evaluation::new(system.bodies().len(), system.couplings());
    sets.iter()
        .map(|states| {
            system.evaluate(states, &mut evaluation, 0.0).expect("every coupling gives its forces");
            evaluation.clone()
        })
        .collect()
}

fn same_record(a: &CouplingForces, b: &CouplingForces) -> bool {
    close_vectors(&a.f1, &b.f1)
        && close_vectors(&a.f2, &b.f2)
        && close_vectors(&a.point1, &b.point1)
        && close_vectors(&a.point2, &b.point2)
        && close(a.tension, b.tension)
        && close(a.potential, b.potential)
        && close(a.dissipated_power, b.dissipated_power)
}

#[test]
fn every_build_of_the_couplings_stage_gives_the_portable_forces() {
    let system = common::scene(SCENE).world.system().clone();
    let sets = state_sets(&system);
    let portable = evaluations(&system, Level::Portable, &sets);
    check_coverage(&system, &portable);
    for level in Level::available().into_iter().filter(|&l| l != Level::Portable) {
        for (k, (built, reference)) in evaluations(&system, level, &sets).iter().zip(&portable).enumerate() {
            for (i, (a, b)) in built.forces().iter().zip(reference.forces()).enumerate() {
                assert!(
                    same_record(a, b),
                    "{level:?}, state set {k}, coupling \"{}\": {a:?} vs {b:?}",
                    system.couplings()[i].name
                );
            }
            for (i, (a, b)) in built.loads().iter().zip(reference.loads()).enumerate() {
                assert!(
                    close_vectors(&a.force, &b.force) && close_vectors(&a.moment, &b.moment),
                    "{level:?}, state set {k}, body {i}: {a:?} vs {b:?}"
                );
            }
        }
    }
}

/// The states reach every path: every coupling acts in some set; in every set the crate's bottom
/// is partly within the ground contact's range and partly not; a contact in range has friction.
fn check_coverage(system: &System, evaluations: &[Evaluation]) {
    for (i, coupling) in system.couplings().iter().enumerate() {
        let active = evaluations.iter().filter(|e| e.forces()[i].f1.norm() + e.forces()[i].f2.norm() > 0.0).count();
        assert!(active > 0, "coupling \"{}\" never acts", coupling.name);
        let CouplingKind::Contact(contact) = &coupling.kind else { continue };
        for (k, evaluation) in evaluations.iter().enumerate() {
            let totals = contact.totals(evaluation.frames());
            assert!(
                totals.faces == 0 || totals.friction > 0.0,
                "contact \"{}\" in range without friction in set {k}",
                coupling.name
            );
            if coupling.name == "crate_ground" {
                let frame = &evaluation.frames()[contact.body()];
                let bottom = contact.boundary().faces().iter().filter(|f| (frame.rotation * f.normal).z < -0.99);
                let heights: Vec<f64> = bottom.map(|f| frame.position.z + (frame.rotation * f.centroid).z).collect();
                let in_range = heights.iter().filter(|&&z| z < contact.law().range()).count();
                assert!(
                    in_range > 0 && in_range < heights.len(),
                    "set {k}: {in_range} of the {} bottom faces in range",
                    heights.len()
                );
            }
        }
    }
}

/// A whole run with each build (the leapfrog step is built per level too): the same states
/// after 2000 steps of 0.1 ms from the first set of states, to 1e-12 relative.
#[test]
fn every_build_runs_the_portable_motion() {
    let world = common::scene(SCENE).world;
    let run = |level: Level| {
        let mut system = world.system().clone();
        assert!(system.use_level(level));
        let mut world = World::new(system, world.timing()).expect("the scene starts");
        for _ in 0..2000 {
            world.step().expect("a healthy run");
        }
        world.synchronized_states()
    };
    let portable = run(Level::Portable);
    for level in Level::available().into_iter().filter(|&l| l != Level::Portable) {
        for (i, (a, b)) in run(level).iter().zip(&portable).enumerate() {
            let same = close_vectors(&a.position, &b.position)
                && close_vectors(&a.velocity, &b.velocity)
                && close_vectors(&a.angular_velocity, &b.angular_velocity);
            assert!(same && a.orientation.angle_to(&b.orientation) <= 1e-12, "{level:?}, body {i}: {a:?} vs {b:?}");
        }
    }
}

/// The water stage is built per level too: on the barge in its JONSWAP sea with a current
/// (`scenes/barge_in_waves.ron`: 50 wave components, 1152 hull panels), heaved, rolled and
/// moving in twelve ways at twelve times after the ramp, every build gives the portable water
/// forces, wetted volume and power, to 1e-12 relative.
#[test]
fn every_build_of_the_water_stage_gives_the_portable_forces() {
    let system = tether_scene::load(&common::repo("scenes/barge_in_waves.ron")).expect("a shipped scene").world;
    let system = system.system().clone();
    let mut numbers = Numbers(3);
    let cases: Vec<(f64, Vec<BodyState>)> = (0..12)
        .map(|k| {
            let mut states = system.initial_states().to_vec();
            states[0].position += Vec3::new(5.0 * numbers.next(), 5.0 * numbers.next(), numbers.next());
            states[0].orientation = Rotation::from_scaled_axis(numbers.vector(0.05)) * states[0].orientation;
            states[0].velocity = numbers.vector(1.0);
            states[0].angular_velocity = numbers.vector(0.05);
            (20.0 + 7.5 * f64::from(k), states)
        })
        .collect();
    let water_forces = |level: Level| {
        let mut system = system.clone();
        assert!(system.use_level(level), "{level:?} is listed as available");
        let mut evaluation = Evaluation::new(system.bodies().len(), system.couplings());
        cases
            .iter()
            .map(|(time, states)| {
                system.evaluate(states, &mut evaluation, *time).expect("no coupling to fail");
                evaluation.water()[0]
            })
            .collect::<Vec<_>>()
    };
    let portable = water_forces(Level::Portable);
    assert!(portable.iter().all(|w| w.submerged_volume > 100.0 && w.drag.force.norm() > 0.0), "{portable:?}");
    for level in Level::available().into_iter().filter(|&l| l != Level::Portable) {
        for (k, (a, b)) in water_forces(level).iter().zip(&portable).enumerate() {
            let (total_a, total_b) = (a.total(), b.total());
            let same = close_vectors(&total_a.force, &total_b.force)
                && close_vectors(&total_a.moment, &total_b.moment)
                && close_vectors(&a.pressure.force, &b.pressure.force)
                && close(a.submerged_volume, b.submerged_volume)
                && close(a.power, b.power);
            assert!(same, "{level:?}, case {k}: {a:?} vs {b:?}");
        }
    }
}
