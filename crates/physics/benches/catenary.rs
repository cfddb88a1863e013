//! Catenary solve time (targets: median ≤ 1 µs warm-started with the end points moved
//! by about 1 % of the span, ≤ 5 µs cold), for free lines and for lines lying on the seabed
//! (PHYSICS.md §7): the grounded solve alone, and the whole line solve a step pays (the free solve
//! that finds the line grounded, or the grounded solve from the last step). Before timing,
//! prints the mean and maximum Newton iterations over the same cases.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use tether_physics::coupling::Endpoint;
use tether_physics::coupling::catenary::equations::Closure;
use tether_physics::coupling::catenary::grounded::{Grounding, Outcome, solver as grounded_solver};
use tether_physics::coupling::catenary::solver::{Unknowns, solve};
use tether_physics::coupling::catenary::{Catenary, LineState};
use tether_physics::math::Vec3;
use tether_physics::seabed::Seabed;
use tether_physics::surroundings::Surroundings;

/// Representative lines as (span X, rise Y, ε), dimensionless: slack moorings, a taut tow
/// rope, nearly vertical crane cables, a sagging chain below its anchor, very soft and very
/// stiff lines.
fn cases() -> Vec<Closure> {
    let mut cases = Vec::new();
    for &(x, y) in
        &[(0.84, 0.49), (0.6, 0.2), (0.95, 0.1), (0.02, 0.99), (0.3, -0.8), (0.5, 0.0), (0.999, 0.03), (0.1, 0.3)]
    {
        for &epsilon in &[1e-9, 1e-5, 1e-3, 0.1] {
            cases.push(Closure { x, y, epsilon });
        }
    }
    cases
}

/// Each case moved by 1 % of its span and rise, with the solution of the unmoved case as the
/// warm start.
fn warm_cases() -> Vec<(Closure, Unknowns)> {
    cases()
        .into_iter()
        .map(|c| {
            let start = solve(&c, None).expect("finite case").unknowns;
            (Closure { x: c.x * 1.01, y: c.y + 0.01 * c.x, epsilon: c.epsilon }, start)
        })
        .collect()
}

fn report_iterations() {
    let cold: Vec<u32> = cases().iter().map(|c| solve(c, None).expect("finite case").iterations).collect();
    let warm: Vec<u32> =
        warm_cases().iter().map(|(c, s)| solve(c, Some(*s)).expect("finite case").iterations).collect();
    let stats = |v: &[u32]| (v.iter().sum::<u32>() as f64 / v.len() as f64, v.iter().max().copied().unwrap_or(0));
    let (cold_mean, cold_max) = stats(&cold);
    let (warm_mean, warm_max) = stats(&warm);
    eprintln!(
        "catenary Newton iterations over {} cases: cold mean {cold_mean:.2} max {cold_max}; warm (1 % move) mean {warm_mean:.2} max {warm_max}",
        cold.len()
    );
}

fn bench_solver(c: &mut Criterion) {
    report_iterations();
    let cold = cases();
    let warm = warm_cases();
    let mut group = c.benchmark_group("catenary_solve");
    let mut index = 0;
    group.bench_function("cold", |b| {
        b.iter(|| {
            index = (index + 1) % cold.len();
            solve(black_box(&cold[index]), None)
        })
    });
    group.bench_function("warm_1pct", |b| {
        b.iter(|| {
            index = (index + 1) % warm.len();
            let (closure, start) = &warm[index];
            solve(black_box(closure), Some(*start))
        })
    });
    group.finish();
}

/// Grounded lines as (span X, anchor height, fairlead height, ε, C_B), dimensionless: moorings
/// of scope 2:1 to 10:1 from chain to synthetic rope, with and without friction, nearly heaped
/// and nearly lifted, and a line resting its middle between two raised ends.
fn grounded_cases() -> Vec<Grounding> {
    let mut cases = Vec::new();
    for &(x, z1, z2) in
        &[(0.8, 0.0, 0.4), (0.95, 0.0, 0.1), (0.85, 0.0, 0.25), (0.75, 0.0, 0.35), (0.9, 0.0, 0.2), (0.95, 0.05, 0.05)]
    {
        for &epsilon in &[1e-9, 1e-5, 1e-3] {
            for &friction in &[0.0, 1.0] {
                cases.push(Grounding { x, z1, z2, epsilon, friction });
            }
        }
    }
    cases
}

fn grounded(outcome: Option<Outcome>) -> grounded_solver::Solved {
    match outcome {
        Some(Outcome::Grounded(solved)) if solved.profile.h > 0.0 => solved,
        other => panic!("a bench case lifts off or lies heaped: {other:?}"),
    }
}

/// Each grounded case with its span moved by 1 %, warm-started from the unmoved solution.
fn grounded_warm_cases() -> Vec<(Grounding, f64)> {
    grounded_cases()
        .into_iter()
        .map(|g| (Grounding { x: g.x * 1.01, ..g }, grounded(grounded_solver::solve(&g, None)).profile.h))
        .collect()
}

/// MoorPy's reference line (PHYSICS.md §7) moved by 1 % of its span each step, whole-line
/// solves from the last state.
fn moving_mooring() -> (Catenary, Surroundings, Vec<(Vec3, LineState)>) {
    let g = 9.80665;
    let line =
        Catenary::new(Endpoint::World(Vec3::zeros()), Endpoint::World(Vec3::zeros()), 800.0 / g, 500.0, 7.51e9 / 500.0)
            .expect("MoorPy's line has valid values");
    let surroundings = Surroundings {
        gravity: Vec3::new(0.0, 0.0, -g),
        fluid_density: 0.0,
        seabed: Some(Seabed::new(-80.0, 0.5).expect("a valid seabed")),
    };
    let anchor = Vec3::new(0.0, 0.0, -80.0);
    let steps = (0..64)
        .map(|i| {
            let fairlead = Vec3::new(380.0 + 4.0 * (f64::from(i) * 0.3).sin(), 2.0 * (f64::from(i) * 0.2).cos(), 120.0);
            let moved = fairlead + Vec3::new(4.0, 0.0, 0.0);
            (moved, line.solve(&anchor, &fairlead, &surroundings, None).expect("finite ends"))
        })
        .collect();
    (line, surroundings, steps)
}

fn bench_grounded(c: &mut Criterion) {
    let cold = grounded_cases();
    let warm = grounded_warm_cases();
    let counts = |v: &[u32]| (v.iter().sum::<u32>() as f64 / v.len() as f64, v.iter().max().copied().unwrap_or(0));
    let (cold_mean, cold_max) =
        counts(&cold.iter().map(|g| grounded(grounded_solver::solve(g, None)).iterations).collect::<Vec<_>>());
    let (warm_mean, warm_max) =
        counts(&warm.iter().map(|(g, h)| grounded(grounded_solver::solve(g, Some(*h))).iterations).collect::<Vec<_>>());
    eprintln!(
        "grounded catenary Newton iterations over {} cases: cold mean {cold_mean:.2} max {cold_max}; warm (1 % move) mean {warm_mean:.2} max {warm_max}",
        cold.len()
    );
    let mut group = c.benchmark_group("catenary_grounded");
    let mut index = 0;
    group.bench_function("cold", |b| {
        b.iter(|| {
            index = (index + 1) % cold.len();
            grounded_solver::solve(black_box(&cold[index]), None)
        })
    });
    group.bench_function("warm_1pct", |b| {
        b.iter(|| {
            index = (index + 1) % warm.len();
            let (g, h) = &warm[index];
            grounded_solver::solve(black_box(g), Some(*h))
        })
    });
    let (line, surroundings, steps) = moving_mooring();
    let anchor = Vec3::new(0.0, 0.0, -80.0);
    group.bench_function("line_on_seabed_cold", |b| {
        b.iter(|| {
            index = (index + 1) % steps.len();
            line.solve(&anchor, black_box(&steps[index].0), &surroundings, None)
        })
    });
    group.bench_function("line_on_seabed_warm_1pct", |b| {
        b.iter(|| {
            index = (index + 1) % steps.len();
            let (fairlead, last) = &steps[index];
            line.solve(&anchor, black_box(fairlead), &surroundings, Some(last))
        })
    });
    group.finish();
}

criterion_group!(benches, bench_solver, bench_grounded);
criterion_main!(benches);
