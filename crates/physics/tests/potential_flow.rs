//! Potential flow in the time domain (PHYSICS.md §9): Capytaine's floating cylinder
//! (`validation/potential-flow/cylinder.py`: R 3 m, draft 6 m, G 4 m below the still level, the
//! reference point) as a scene with `hydro: Hydro(potential: Wamit(...))`, its buoyancy from
//! Tether's 32-sided mesh. Checks: the settled response in regular waves against the
//! frequency-domain solve of the same files with the mesh's own linear stiffness and the
//! scene's mass; the state space against the convolution; the heave free decay against
//! `A(ω_n)`, `B(ω_n)`; the energy radiated in a free decay.

use tether_test_support as common;

use common::{repo, scene};
use nalgebra::Complex;
use std::f64::consts::PI;
use tether_physics::body::BodyState;
use tether_physics::evaluation::Evaluation;
use tether_physics::math::{Rotation, Vec3};
use tether_physics::potential::response::response;
use tether_physics::potential::{Coefficients, Matrix6, Vector6};
use tether_physics::system::System;
use tether_physics::world::World;
use tether_scene::wamit::{Scale, read};

const RHO: f64 = 1025.0;
const G: f64 = 9.80665;
const RADIUS: f64 = 3.0;
const DRAFT: f64 = 6.0;
const SIDES: f64 = 32.0;

/// The mesh's waterplane area \[m²]: the 32-gon inscribed in the circle.
fn waterplane() -> f64 {
    0.5 * SIDES * RADIUS * RADIUS * (2.0 * PI / SIDES).sin()
}

/// The mass that floats the mesh at its draft \[kg].
fn mass() -> f64 {
    RHO * waterplane() * DRAFT
}

/// Capytaine's cylinder as a scene: `water` the water's fields, `extra` the body's (velocities),
/// `radiation` the method, integrator RK4 at `dt`.
fn cylinder(water: &str, extra: &str, radiation: &str, dt: f64) -> World {
    let m = mass();
    let (ixx, izz) = (m * (3.0 * RADIUS * RADIUS + DRAFT * DRAFT) / 12.0, m * RADIUS * RADIUS / 2.0);
    let file = repo("validation/potential-flow/cylinder/cylinder");
    scene(&format!(
        "Scene(dt: {dt:e}, integrator: rk4, water: Water({water}), bodies: [Body(name: \"cylinder\",
            master: Node(position: (0.0, 0.0, -4.0), mass: {m:e}, inertia: Inertia(xx: {ixx:e}, yy: {ixx:e}, zz: {izz:e})),
            {extra}
            shape: Cylinder(radius: {RADIUS:e}, length: 8.0, center: (0.0, 0.0, 2.0)),
            hydro: Hydro(potential: Wamit(file: {file:?}, radiation: {radiation})))])"
    ))
    .world
}

fn coefficients() -> Coefficients {
    let stem = repo("validation/potential-flow/cylinder/cylinder");
    read(&stem, Scale { density: RHO, gravity: G, length: 1.0 }).expect("the shipped cylinder")
}

/// The body's 6 × 6 mass about G (the reference point), world axes.
fn mass_matrix(world: &World) -> Matrix6 {
    let body = &world.system().bodies()[0];
    let state = world.state(0);
    let r = state.orientation.to_rotation_matrix().into_inner();
    let inertia = r * nalgebra::Matrix3::from_diagonal(&body.principal_moments()) * r.transpose();
    let mut m = Matrix6::identity() * body.mass();
    m.fixed_view_mut::<3, 3>(3, 3).copy_from(&inertia);
    m
}

/// `−∂Q/∂q` of the pressure on the mesh (about G, world axes) at the initial pose, by central
/// differences of 1e-4 m and rad: the linear hydrostatic stiffness the time domain sees.
fn mesh_stiffness(system: &System) -> Matrix6 {
    let start = system.initial_states().to_vec();
    let pressure = |states: &[BodyState]| {
        let mut evaluation = Evaluation::new(1, system.couplings());
        system.evaluate(states, &mut evaluation, 0.0).expect("water always gives forces");
        let p = evaluation.water()[0].pressure;
        Vector6::new(p.force.x, p.force.y, p.force.z, p.moment.x, p.moment.y, p.moment.z)
    };
    let delta = 1e-4;
    let moved = |dof: usize, by: f64| {
        let mut states = start.clone();
        let mut axis = Vec3::zeros();
        axis[dof % 3] = by;
        if dof < 3 {
            states[0].position += axis;
        } else {
            states[0].orientation = Rotation::from_scaled_axis(axis) * states[0].orientation;
        }
        states
    };
    let mut c = Matrix6::zeros();
    for j in 0..6 {
        let column = (pressure(&moved(j, delta)) - pressure(&moved(j, -delta))) / (-2.0 * delta);
        c.set_column(j, &column);
    }
    c
}

/// Surge \[m], heave \[m] and pitch \[rad] of the body from its start.
fn motion(world: &World, start: &BodyState) -> [f64; 3] {
    let state = world.state(0);
    let turn = (state.orientation * start.orientation.inverse()).scaled_axis();
    [state.position.x - start.position.x, state.position.z - start.position.z, turn.y]
}

/// The least-squares fit of `c0 + c1 t + A cos ωt + B sin ωt` to `(t, x)`: `A − iB`.
fn harmonic(samples: &[(f64, f64)], omega: f64) -> Complex<f64> {
    let rows = samples.len();
    let basis = nalgebra::DMatrix::from_fn(rows, 4, |r, c| {
        let t = samples[r].0;
        [1.0, t, (omega * t).cos(), (omega * t).sin()][c]
    });
    let values = nalgebra::DVector::from_fn(rows, |r, _| samples[r].1);
    let fit = (basis.transpose() * &basis).lu().solve(&(basis.transpose() * values)).expect("a regular fit");
    Complex::new(fit[2], -fit[3])
}

/// Wave amplitude of the regular-wave runs \[m]: small enough to be linear.
const AMPLITUDE: f64 = 0.05;

/// Runs the cylinder in regular waves of period `period`, ramped over 60 s, and returns the
/// settled surge, heave and pitch per unit wave amplitude (`ξ`, WAMIT's convention), fitted over
/// the last `max(3 T, 40 s)` of 300 s.
fn settled(period: f64, radiation: &str) -> [Complex<f64>; 3] {
    let water = format!("waves: Regular(height: {:e}, period: {period:e}), ramp: 60.0", 2.0 * AMPLITUDE);
    let mut world = cylinder(&water, "", radiation, 0.02);
    let start = world.state(0);
    let end = 300.0;
    let from = end - (3.0 * period).max(40.0);
    let mut samples: [Vec<(f64, f64)>; 3] = Default::default();
    while world.time() < end - 0.5 * world.dt() {
        world.step().expect("a stable cylinder");
        if world.time() >= from {
            for (dof, x) in motion(&world, &start).into_iter().enumerate() {
                samples[dof].push((world.time(), x));
            }
        }
    }
    let omega = 2.0 * PI / period;
    std::array::from_fn(|dof| harmonic(&samples[dof], omega) / AMPLITUDE)
}

/// Check 2 of issue 33: at eight periods from 4 to 30 s, the settled surge, heave and pitch in
/// small regular waves are the frequency-domain solve's `ξ` (the same files, the mesh's linear
/// stiffness, the scene's mass) within 2 % in amplitude and 3° in phase.
#[test]
fn the_settled_response_in_regular_waves_is_the_frequency_domain_solve() {
    let world = cylinder("", "", "Convolution", 0.02);
    let (c, m) = (mesh_stiffness(world.system()), mass_matrix(&world));
    let coefficients = coefficients();
    for period in [4.0, 6.0, 8.0, 10.0, 13.0, 17.0, 22.0, 30.0] {
        let omega = 2.0 * PI / period;
        let xi = response(&coefficients, &m, &c, omega, 0).expect("damped");
        let measured = settled(period, "StateSpace");
        for (k, dof) in [0, 2, 4].into_iter().enumerate() {
            let (expected, got) = (xi[dof], measured[k]);
            let amplitude = (got.norm() - expected.norm()) / expected.norm();
            let phase = (got / expected).arg().to_degrees();
            println!(
                "T = {period:>4} s dof {}: time domain {:.5} ∠{:>7.2}°, frequency domain {:.5} ∠{:>7.2}°: {:+.2} %, {:+.2}°",
                dof + 1,
                got.norm(),
                got.arg().to_degrees(),
                expected.norm(),
                expected.arg().to_degrees(),
                100.0 * amplitude,
                phase
            );
            assert!(amplitude.abs() < 0.02, "T = {period} s dof {}: amplitude off by {amplitude:e}", dof + 1);
            assert!(phase.abs() < 3.0, "T = {period} s dof {}: phase off by {phase}°", dof + 1);
        }
    }
}
