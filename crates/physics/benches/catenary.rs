//! Catenary solve time (issue 3's targets: median ≤ 1 µs warm-started with the end points moved
//! by about 1 % of the span, ≤ 5 µs cold). Before timing, prints the mean and maximum Newton
//! iterations over the same cases.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use tether_physics::coupling::catenary::equations::Closure;
use tether_physics::coupling::catenary::solver::{Unknowns, solve};

/// Representative lines as (span X, rise Y, ε), dimensionless: slack moorings, a taut tow
/// rope, nearly vertical crane cables, a sagging chain below its anchor, very soft and very
/// stiff lines.
fn cases() -> Vec<Closure> {
    let mut cases = Vec::new();
    for &(x, y) in &[(0.84, 0.49), (0.6, 0.2), (0.95, 0.1), (0.02, 0.99), (0.3, -0.8), (0.5, 0.0), (0.999, 0.03), (0.1, 0.3)] {
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
    let warm: Vec<u32> = warm_cases().iter().map(|(c, s)| solve(c, Some(*s)).expect("finite case").iterations).collect();
    let stats = |v: &[u32]| (v.iter().sum::<u32>() as f64 / v.len() as f64, v.iter().max().copied().unwrap_or(0));
    let (cold_mean, cold_max) = stats(&cold);
    let (warm_mean, warm_max) = stats(&warm);
    eprintln!("catenary Newton iterations over {} cases: cold mean {cold_mean:.2} max {cold_max}; warm (1 % move) mean {warm_mean:.2} max {warm_max}", cold.len());
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

criterion_group!(benches, bench_solver);
criterion_main!(benches);
