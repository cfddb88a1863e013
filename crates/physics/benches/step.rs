//! Steps per second of spring chains (speed targets on one core in release: chain100_air
//! ≥ 150,000 steps/s; chain100, the same chain lying on the ground with floor contact on every
//! sphere, ≥ 75,000 steps/s) and of floating bodies (moored_buoy in its regular wave ≥ 50,000
//! steps/s; the same buoy in a 50-component JONSWAP sea ≥ 20,000 steps/s; the barge hull of
//! 578 vertices in its 50-component sea, for scale). Criterion reports the throughput as
//! `elem/s` = steps/s.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::fmt::Write as _;
use std::path::Path;
use tether_scene as scene;

/// The chain100_air scene with `n` bodies: 1 kg spheres evenly spaced between world anchors
/// (0,0,30) and (15,0,30), n + 1 springs k = 1e4 N/m, k_d = 20 N·s/m, x0 = 0.2 m, dt = 2 ms.
fn chain_scene(n: usize) -> String {
    let mut text = String::from("Scene(dt: 0.002, bodies: [");
    for i in 1..=n {
        let x = 15.0 * i as f64 / (n + 1) as f64;
        let _ = write!(
            text,
            "Body(name: \"b{i}\", master: Node(position: ({x:e}, 0.0, 30.0), mass: 1.0, inertia: Inertia(xx: 0.001, yy: 0.001, zz: 0.001)), shape: Sphere(radius: 0.05)),"
        );
    }
    text.push_str("], couplings: [");
    let end = |i: usize| match i {
        0 => "World((0.0, 0.0, 30.0))".to_string(),
        i if i == n + 1 => "World((15.0, 0.0, 30.0))".to_string(),
        i => format!("Body(body: \"b{i}\")"),
    };
    for i in 0..=n {
        let _ = write!(
            text,
            "SpringDamper(name: \"s{i}\", end1: {}, end2: {}, law: Linear(stiffness: 1e4, rest_length: 0.2), damping: 20.0),",
            end(i),
            end(i + 1)
        );
    }
    text + "])"
}

fn bench_chains(c: &mut Criterion) {
    let mut group = c.benchmark_group("step");
    group.throughput(Throughput::Elements(1));
    let shipped = |name: &str| shipped_in(&format!("bench/{name}"));
    let mut chain100 = shipped("chain100.ron");
    // 6 s: the chain has fallen and its middle rests on the ground, every step pays for contact.
    for _ in 0..3000 {
        chain100.step().expect("the shipped scene is stable");
    }
    let cases = [
        ("chain100_air", shipped("chain100_air.ron")),
        ("chain100", chain100),
        ("chain10", scene::parse(&chain_scene(10), Path::new("chain10")).expect("generated scene").world),
        ("chain1000", scene::parse(&chain_scene(1000), Path::new("chain1000")).expect("generated scene").world),
    ];
    for (name, mut world) in cases {
        group.bench_function(name, |b| b.iter(|| world.step().expect("springs always give a force")));
    }
    // The buoy once the waves are fully ramped in (20 s: the ramp is 16 s), every step pays for
    // the waves.
    // At the leapfrog's one force evaluation per step (the shipped scene steps RK4 at 50 ms), so
    // that a step is one pass of the water stage.
    let shipped = std::fs::read_to_string(scenes().join("moored_buoy.ron")).expect("shipped scene");
    let buoy_text = shipped.replacen("dt: 0.05,\n    integrator: rk4,\n    substeps: Auto,", "dt: 0.002,", 1);
    assert_ne!(buoy_text, shipped, "the shipped buoy's timing lines changed: update the bench");
    let jonswap = buoy_text.replace(
        "waves: Regular(height: 2.0, period: 8.0, heading_deg: 0.0)",
        "waves: Jonswap(hs: 2.0, tp: 8.0, components: 50, seed: 1)",
    );
    assert_ne!(jonswap, buoy_text, "the shipped buoy's wave line changed: update the bench");
    let barge = shipped_in("barge_in_waves.ron");
    let floating = [
        (
            "moored_buoy_regular",
            scene::parse(&buoy_text, Path::new("moored_buoy.ron")).expect("shipped scene").world,
            10_000,
        ),
        (
            "moored_buoy_jonswap50",
            scene::parse(&jonswap, Path::new("moored_buoy.ron")).expect("edited scene").world,
            10_000,
        ),
        ("barge_jonswap50", barge, 1_000),
    ];
    for (name, mut world, warm_up) in floating {
        for _ in 0..warm_up {
            world.step().expect("the shipped scene is stable");
        }
        group.bench_function(name, |b| b.iter(|| world.step().expect("water always gives forces")));
    }
    group.finish();
}

/// The repository's `scenes/` (this crate is two levels below the workspace root).
fn scenes() -> std::path::PathBuf {
    std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join("../../scenes")
}

/// The world of the shipped scene `scenes/<name>`.
fn shipped_in(name: &str) -> tether_physics::world::World {
    scene::load(&scenes().join(name)).expect("shipped scene").world
}

criterion_group!(benches, bench_chains);
criterion_main!(benches);
