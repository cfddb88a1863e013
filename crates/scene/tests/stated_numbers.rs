//! Every number a shipped scene's comment states, held by a run of the scene file itself.
//!
//! Each test runs one scene (again with another seed, without its drag or without its seabed
//! friction where the comment states that case too) and asserts each figure the comment states,
//! within the rounding the comment writes it to. Where the figure has a closed form (a free fall, a pendulum period, a
//! decay ratio, a sum of energies) the test checks the closed form too: the comment's number
//! then stands on two independent legs.

use tether_test_support as common;

use nalgebra::Vector3;
use std::f64::consts::PI;
use tether_physics::body::BodyState;
use tether_physics::energy::EnergyReport;
use tether_physics::statics::{Equilibrium, Settings, equilibrium};
use tether_physics::world::World;

const G: f64 = 9.80665;
const RHO: f64 = 1025.0;

/// One step of a run: the time, each body's state, each coupling's end forces `f1`, `f2` [N]
/// and tension [N], the energy report.
struct Sample {
    t: f64,
    states: Vec<BodyState>,
    forces: Vec<(Vector3<f64>, Vector3<f64>, f64)>,
    energy: EnergyReport,
}

/// The scene at `scenes/{name}.ron`, its text edited by each `(from, to)` (each must occur).
fn world(name: &str, edits: &[(&str, &str)]) -> World {
    let path = common::repo(&format!("scenes/{name}.ron"));
    let mut text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    for (from, to) in edits {
        assert!(text.contains(from), "{name}: edit target {from:?} missing");
        text = text.replacen(from, to, 1);
    }
    tether_scene::parse(&text, &path).unwrap_or_else(|e| panic!("{e}")).world
}

fn sample(world: &World) -> Sample {
    Sample {
        t: world.time(),
        states: (0..world.bodies().len()).map(|i| world.state(i)).collect(),
        forces: world.coupling_forces().iter().map(|c| (c.f1, c.f2, c.tension)).collect(),
        energy: world.energy(),
    }
}

/// Runs `world` to `until` [s], sampling every step (t = 0 included).
fn run(world: &mut World, until: f64) -> Vec<Sample> {
    let mut samples = vec![sample(world)];
    while world.time() < until - 0.5 * world.dt() {
        world.step().unwrap_or_else(|e| panic!("{e}"));
        samples.push(sample(world));
    }
    samples
}

fn max_of(samples: &[Sample], f: impl Fn(&Sample) -> f64) -> f64 {
    samples.iter().map(f).fold(f64::NEG_INFINITY, f64::max)
}

fn min_of(samples: &[Sample], f: impl Fn(&Sample) -> f64) -> f64 {
    samples.iter().map(f).fold(f64::INFINITY, f64::min)
}

fn mean_of(samples: &[Sample], f: impl Fn(&Sample) -> f64) -> f64 {
    samples.iter().map(&f).sum::<f64>() / samples.len() as f64
}

/// The samples with `from ≤ t ≤ to`.
fn between(samples: &[Sample], from: f64, to: f64) -> &[Sample] {
    let start = samples.iter().position(|s| s.t >= from).expect("the run reaches `from`");
    let end = samples.iter().rposition(|s| s.t <= to).expect("the run starts before `to`");
    &samples[start..=end]
}

/// Times [s] at which `f` crosses `level` (either way), linearly interpolated.
fn crossings(samples: &[Sample], level: f64, f: impl Fn(&Sample) -> f64) -> Vec<f64> {
    samples
        .windows(2)
        .filter_map(|w| {
            let (a, b) = (f(&w[0]) - level, f(&w[1]) - level);
            ((a < 0.0) != (b < 0.0)).then(|| w[0].t + (w[1].t - w[0].t) * a / (a - b))
        })
        .collect()
}

/// The mean period [s] of the crossings `c` of a level (two per period).
fn period(c: &[f64]) -> f64 {
    assert!(c.len() >= 3, "too few crossings: {c:?}");
    2.0 * (c[c.len() - 1] - c[0]) / (c.len() - 1) as f64
}

/// Roll, pitch and yaw [rad] of body `i` (its principal axes are its reference axes in these
/// scenes: diagonal inertias, ordered): `atan2(−R₁₂, R₂₂)`, `atan2(R₀₂, R₂₂)`, `atan2(R₁₀, R₀₀)`.
fn attitude(s: &Sample, i: usize) -> Vector3<f64> {
    let r = s.states[i].rotation_matrix();
    Vector3::new((-r[(1, 2)]).atan2(r[(2, 2)]), r[(0, 2)].atan2(r[(2, 2)]), r[(1, 0)].atan2(r[(0, 0)]))
}

/// The figures a test checks; it fails at its end listing every one that is off.
#[derive(Default)]
struct Checks(Vec<String>);

impl Checks {
    /// `measured` is the `stated` figure within `tolerance` (the comment's rounding).
    fn close(&mut self, what: &str, measured: f64, stated: f64, tolerance: f64) {
        eprintln!("{what}: measured {measured:.6}, stated {stated}");
        let off = (measured - stated).abs();
        if off.is_nan() || off > tolerance {
            self.0.push(format!("{what}: measured {measured}, stated {stated} ± {tolerance}"));
        }
    }

    fn done(self) {
        assert!(self.0.is_empty(), "\n{}", self.0.join("\n"));
    }
}

/// The largest drift of the energy balance from its start [J] (PHYSICS.md §5).
fn balance_drift(samples: &[Sample]) -> f64 {
    let start = samples[0].energy.balance();
    max_of(samples, |s| (s.energy.balance() - start).abs())
}

/// floating_box: the closed-form heave and roll, and its damped release.
#[test]
fn floating_box() {
    let mut checks = Checks::default();
    let s = run(&mut world("floating_box", &[]), 40.0);
    let z = |s: &Sample| s.states[0].position.z;
    let omega_heave = (G / 2.0).sqrt();
    // Heave period from the run, against 2π √(d/g) = 2.8375 s: the 5 % damper lengthens it by
    // 1/√(1 − ζ²) (0.13 %), the drag a little more.
    checks.close("heave period [s]", period(&crossings(between(&s, 0.0, 20.0), 0.0, z)), 2.84, 0.005);
    assert!((2.0 * PI / omega_heave - 2.8375).abs() < 5e-5);
    checks.close("undershoot below the floating position [m]", min_of(&s, z), -0.40, 0.005);
    checks.close("off its floating position at 40 s [m]", z(s.last().expect("samples")).abs(), 0.003, 0.0005);
    let roll = |s: &Sample| attitude(s, 0).x;
    let omega_roll = 2.0 * PI / 3.5056;
    checks.close("0.1 rad/s over ω_n [°]", (0.1 / omega_roll).to_degrees(), 3.20, 0.005);
    checks.close("first roll peak [°]", max_of(between(&s, 0.0, 2.0), roll).to_degrees(), 2.95, 0.005);
    checks.close("walked to −y [m]", min_of(&s, |s| s.states[0].position.y), -0.45, 0.005);
    checks.close("energy balance [J]", balance_drift(&s), 31.0, 0.5);
    checks.done();
}

/// floating_box's declared heave damper alone (no drag): the undershoot of a linear oscillator
/// at ζ = 0.05, `0.5 e^(−πζ/√(1−ζ²))` = 0.427 m (the box is wall-sided over the whole heave,
/// so its heave is linear). With the old scaling by the wetted fraction (ζ = 0.025) it would be
/// 0.461 m: this test tells the two apart.
#[test]
fn floating_box_damper_alone_is_five_percent_of_critical() {
    let mut checks = Checks::default();
    let s = run(&mut world("floating_box", &[("drag: (1.0, 1.0, 1.0)", "drag: (0.0, 0.0, 0.0)")]), 4.0);
    let (m, area) = (410_000.0, 200.0);
    let critical = 2.0 * (RHO * G * area * m).sqrt();
    let zeta = 9.1e4 / critical;
    checks.close("ζ of the declared heave damper", zeta, 0.05, 0.0005);
    let expected = -0.5 * (-PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
    checks.close("undershoot, damper alone [m]", min_of(&s, |s| s.states[0].position.z), expected, 0.003);
    checks.close("undershoot, closed form [m]", expected, -0.427, 0.0005);
    checks.done();
}

/// sinking_sphere: free fall, entry, terminal speed, landing on the seabed contact.
#[test]
fn sinking_sphere() {
    let mut checks = Checks::default();
    let s = run(&mut world("sinking_sphere", &[]), 12.0);
    let z = |s: &Sample| s.states[0].position.z;
    let down = |s: &Sample| -s.states[0].velocity.z;
    let at = |level: f64| s.iter().find(|x| z(x) <= level).expect("it sinks");
    // Its bottom touches the water after a 2 m free fall: √(2 g h) = 6.26 m/s.
    checks.close("free fall 2 m, closed form [m/s]", (2.0 * G * 2.0).sqrt(), 6.26, 0.005);
    checks.close("speed as it touches the water [m/s]", down(at(0.5)), 6.26, 0.01);
    checks.close("fastest, half in [m/s]", max_of(&s, down), 6.83, 0.005);
    checks.close("speed when just under [m/s]", down(at(-0.5)), 6.73, 0.005);
    // Terminal speed √(2 (m − ρV) g / (ρ C_d A)) of the exact sphere; the mesh's smaller
    // volume and area give a little more.
    let (m, r) = (1073.0, 0.5);
    let volume = 4.0 / 3.0 * PI * r * r * r;
    let terminal = (2.0 * (m - RHO * volume) * G / (RHO * 0.5 * PI * r * r)).sqrt();
    checks.close("terminal speed, closed form [m/s]", terminal, 5.11, 0.005);
    checks.close("speed at t = 4 s [m/s]", down(s.iter().find(|x| x.t >= 4.0).expect("4 s")), 5.16, 0.005);
    let landed = s.iter().position(|x| z(x) <= -29.5).expect("it lands");
    checks.close("lands at [s]", s[landed].t, 6.24, 0.005);
    checks.close("bounces [m]", max_of(&s[landed..], z) + 29.5, 0.92, 0.01);
    checks.close("rests with G at [m]", z(s.last().expect("samples")), -29.494, 0.0005);
    checks.close("lands with kinetic energy [kJ]", s[landed].energy.kinetic / 1e3, 13.3, 0.05);
    checks.close("energy balance [kJ]", balance_drift(&s) / 1e3, 0.78, 0.01);
    checks.done();
}

/// The height of G [m] at which the barge floats in still water: its hull displaces m/ρ.
fn barge_floats_at(world: &World) -> f64 {
    let hull = &world.system().water().expect("water").floating[0].hull();
    let volume = world.bodies()[0].mass() / RHO;
    tether_physics::water::hydrostatics::equilibrium_height(
        hull,
        &tether_physics::math::Mat3::identity(),
        0.0,
        0.0,
        0.0,
        volume,
    )
    .expect("it floats")
}

/// barge_in_waves: heave, roll, pitch and yaw in the JONSWAP sea, and the free barge's drift,
/// whose direction changes with the sea's seed (a start-up transient, not wave drift).
#[test]
fn barge_in_waves() {
    let mut checks = Checks::default();
    let mut w = world("barge_in_waves", &[]);
    let rest = barge_floats_at(&w);
    checks.close("floats with G at [m]", rest, 1.0, 0.0005);
    let s = run(&mut w, 120.0);
    let z = |s: &Sample| s.states[0].position.z - rest;
    checks.close("heave trough [m]", min_of(&s, z), -1.62, 0.005);
    checks.close("heave crest [m]", max_of(&s, z), 1.52, 0.005);
    let angle = |i: usize| move |s: &Sample| attitude(s, 0)[i].to_degrees();
    checks.close("largest roll [°]", max_of(&s, |s| angle(0)(s).abs()), 1.7, 0.05);
    checks.close("largest pitch [°]", max_of(&s, |s| angle(1)(s).abs()), 3.2, 0.05);
    checks.close("yaw [°]", min_of(&s, angle(2)), -3.6, 0.05);
    let end = s.last().expect("samples").states[0].position;
    checks.close("drift along y, seed 7 [m]", end.y, -10.9, 0.05);
    checks.close("energy balance [kJ]", balance_drift(&s) / 1e3, 2.0, 0.05);
    let s = run(&mut world("barge_in_waves", &[("seed: 7", "seed: 11")]), 120.0);
    let end = s.last().expect("samples").states[0].position;
    checks.close("drift along x, seed 11 [m]", end.x, 13.9, 0.05);
    checks.done();
}

/// spread_moored_barge: the mean offset, the slow surge and sway, and the peak fairlead tension
/// against the chain's breaking load.
#[test]
fn spread_moored_barge() {
    let mut checks = Checks::default();
    let mut w = world("spread_moored_barge", &[]);
    let duration = 600.0;
    let s = run(&mut w, duration);
    let rest = s[0].states[0].position;
    let settled = between(&s, 120.0, duration);
    let p = |i: usize| move |s: &Sample| s.states[0].position[i] - rest[i];
    checks.close("mean surge offset [m]", mean_of(settled, p(0)), -0.08, 0.005);
    checks.close("mean sway offset [m]", mean_of(settled, p(1)), -0.34, 0.005);
    checks.close("surge within [m]", max_of(&s, |s| p(0)(s).abs()), 4.0, 0.05);
    checks.close("sway within [m]", max_of(&s, |s| p(1)(s).abs()), 5.6, 0.05);
    // The slow periods 2π √((m + m_a)/k) with k = 19.3 kN/m each way and the added mass C_a ρ V.
    let (m, volume, k) = (2.214e6, 2.214e6 / RHO, 19.3e3);
    let surge = 2.0 * PI * ((m + 0.05 * RHO * volume) / k).sqrt();
    let sway = 2.0 * PI * ((m + 0.3 * RHO * volume) / k).sqrt();
    checks.close("surge period, closed form [s]", surge, 69.0, 0.5);
    checks.close("sway period, closed form [s]", sway, 77.0, 0.5);
    // A 20 s moving average keeps the slow motion: its mean crossing period.
    let slow = |i: usize| {
        let window = (20.0 / w.dt()).round() as usize;
        let values: Vec<f64> = settled.iter().map(p(i)).collect();
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        let averaged: Vec<f64> = values.windows(window).map(|v| v.iter().sum::<f64>() / window as f64 - mean).collect();
        let c: Vec<f64> = averaged
            .windows(2)
            .enumerate()
            .filter(|(_, v)| (v[0] < 0.0) != (v[1] < 0.0))
            .map(|(j, _)| j as f64 * w.dt())
            .collect();
        period(&c)
    };
    checks.close("slow surge period, from the run [s]", slow(0), 66.0, 0.5);
    checks.close("slow sway period, from the run [s]", slow(1), 82.0, 0.5);
    let fairleads: Vec<f64> = (0..4).map(|c| s[0].forces[c].1.norm() / 1e3).collect();
    for (c, stated) in fairleads.iter().zip([99.7, 100.3, 101.2, 100.6]) {
        checks.close("fairlead tension at rest [kN]", *c, stated, 0.05);
    }
    let peak = max_of(&s, |s| (0..4).map(|c| s.forces[c].1.norm()).fold(0.0, f64::max));
    checks.close("peak fairlead tension [kN]", peak / 1e3, 247.0, 0.5);
    // Minimum breaking load of 76 mm grade R3 chain: 0.0223 d² (44 − 0.08 d) kN, d in mm.
    let d = 76.0;
    let breaking = 0.0223 * d * d * (44.0 - 0.08 * d) * 1e3;
    checks.close("breaking load [MN]", breaking / 1e6, 4.88, 0.005);
    checks.close("peak over breaking load [%]", 100.0 * peak / breaking, 5.1, 0.05);
    checks.close("energy balance [kJ]", balance_drift(&s) / 1e3, 5.22, 0.05);
    checks.done();
}

/// The line of `moored_buoy.ron` that potential flow follows, and with it.
const POTENTIAL_OFF: &str = "// potential: Wamit(file: \"meshes/buoy\"),";
const POTENTIAL_ON: &str = "potential: Wamit(file: \"meshes/buoy\"),";

/// moored_buoy: released 5 m off its equilibrium in the wave and current.
#[test]
fn moored_buoy() {
    let mut checks = Checks::default();
    let s = run(&mut world("moored_buoy", &[]), 60.0);
    let p = |i: usize| move |s: &Sample| s.states[0].position[i];
    let rest_z = -0.2034;
    checks.close("swings back to x [m]", min_of(&s, p(0)), -3.59, 0.005);
    checks.close("heave below its rest [m]", min_of(between(&s, 20.0, 60.0), p(2)) - rest_z, -0.93, 0.005);
    checks.close("heave above its rest [m]", max_of(between(&s, 20.0, 60.0), p(2)) - rest_z, 1.01, 0.005);
    checks.close("sway [m]", max_of(&s, |s| s.states[0].position.y.abs()), 0.0, 0.005);
    checks.close("energy balance, C_B = 1 [mJ]", balance_drift(&s) * 1e3, 12.9, 1.0);
    let s = run(&mut world("moored_buoy", &[("line_friction: 1.0", "line_friction: 0.0")]), 60.0);
    checks.close("energy balance, C_B = 0 [mJ]", balance_drift(&s) * 1e3, 8.7, 0.05);
    // The scene's comment: the same buoy under potential flow from its Capytaine files.
    let s = run(&mut world("moored_buoy", &[(POTENTIAL_OFF, POTENTIAL_ON)]), 60.0);
    checks.close("potential flow: swings back to x [m]", min_of(&s, p(0)), -2.54, 0.005);
    checks.close(
        "potential flow: heave below its rest [m]",
        min_of(between(&s, 20.0, 60.0), p(2)) - rest_z,
        -0.94,
        0.005,
    );
    checks.close(
        "potential flow: heave above its rest [m]",
        max_of(between(&s, 20.0, 60.0), p(2)) - rest_z,
        0.94,
        0.005,
    );
    checks.close("potential flow: sway [m]", max_of(&s, |s| s.states[0].position.y.abs()), 0.0, 0.001);
    checks.close("potential flow: energy balance [mJ]", balance_drift(&s) * 1e3, 15.0, 1.0);
    checks.done();
}

/// buoy_on_dynamic_chains (the window's default scene): moored_buoy on 20-segment dynamic
/// chains; the fairlead tensions over 30–60 s, the swing and heave, the balance.
#[test]
fn buoy_on_dynamic_chains() {
    let mut checks = Checks::default();
    let s = run(&mut world("buoy_on_dynamic_chains", &[]), 60.0);
    let late = between(&s, 30.0, 60.0);
    // The fairlead is each chain's end 2, on the buoy.
    let fairlead = |line: usize| move |s: &Sample| s.forces[line].1.norm() / 1e3;
    checks.close("mooring1 peak [kN]", max_of(late, fairlead(0)), 39.5, 0.05);
    checks.close("mooring2 peak [kN]", max_of(late, fairlead(1)), 47.9, 0.05);
    checks.close("mooring3 peak [kN]", max_of(late, fairlead(2)), 47.9, 0.05);
    checks.close("mooring2 minimum [kN]", min_of(late, fairlead(1)), 21.9, 0.05);
    let p = |i: usize| move |s: &Sample| s.states[0].position[i];
    let rest_z = -0.2034;
    checks.close("swings back to x [m]", min_of(&s, p(0)), -0.83, 0.005);
    checks.close("heave below its rest [m]", min_of(between(&s, 20.0, 60.0), p(2)) - rest_z, -0.93, 0.005);
    checks.close("heave above its rest [m]", max_of(between(&s, 20.0, 60.0), p(2)) - rest_z, 1.01, 0.005);
    let exchanged = max_of(&s, |x| (x.energy.external_work - s[0].energy.external_work).abs())
        .max(max_of(&s, |x| x.energy.dissipated));
    checks.close("balance drift over the energy moved [%]", 100.0 * balance_drift(&s) / exchanged, 0.10, 0.005);
    let dissipated: Vec<f64> = s.iter().map(|x| x.energy.dissipated).collect();
    assert!(dissipated.windows(2).all(|w| w[1] >= w[0]), "dissipated never falls");
    checks.done();
}

/// crane: the static rope, the swing after the trolley stops, the peak tension and its ringing.
#[test]
fn crane() {
    let mut checks = Checks::default();
    let s = run(&mut world("crane", &[]), 20.0);
    let (m, lambda, length, stiffness) = (2000.0, 8.0, 15.0, 6666666.7);
    checks.close("static tension at the load, m g [kN]", m * G / 1e3, 19.6, 0.05);
    checks.close("static tension at the trolley, (m + λ L) g [kN]", (m + lambda * length) * G / 1e3, 20.8, 0.05);
    let x = |s: &Sample| s.states[1].position.x - 7.0;
    let swinging = between(&s, 6.0, 20.0);
    checks.close("swing ahead of the trolley [m]", max_of(swinging, x), 4.5, 0.05);
    checks.close("swing behind it [m]", min_of(swinging, x), -4.5, 0.05);
    let angle = |s: &Sample| {
        let d = s.states[0].position - s.states[1].position;
        d.x.atan2(d.z).to_degrees().abs()
    };
    checks.close("swing angle [°]", max_of(swinging, angle), 17.0, 0.5);
    let pendulum = 2.0 * PI * (15.5 / G).sqrt();
    checks.close("pendulum period 2π √(ℓ/g) [s]", pendulum, 7.9, 0.05);
    checks.close("swing period from the run [s]", period(&crossings(swinging, 0.0, x)), 7.9, 0.1);
    let tip = |s: &Sample| s.forces[0].0.norm();
    checks.close("peak rope tension at the trolley [kN]", max_of(&s, tip) / 1e3, 23.3, 0.05);
    // The swing alone: m g (3 − 2 cos θ) at the bottom, plus the rope's weight.
    let theta = max_of(swinging, angle).to_radians();
    let swing_peak = m * G * (3.0 - 2.0 * theta.cos()) + lambda * length * G;
    checks.close("peak of the swing alone [kN]", swing_peak / 1e3, 22.4, 0.05);
    let axial = (stiffness / m).sqrt() / (2.0 * PI);
    checks.close("axial mode √(D/m)/2π [Hz]", axial, 9.2, 0.05);
    let still = between(&s, 0.0, 1.0);
    checks.close("ringing at rest, ± [kN]", 0.5 * (max_of(still, tip) - min_of(still, tip)) / 1e3, 0.2, 0.05);
    checks.close("energy balance [mJ]", balance_drift(&s) * 1e3, 2.3, 0.05);
    checks.done();
}

/// two_bodies: the energy it starts with and what the knock does.
#[test]
fn two_bodies() {
    let mut checks = Checks::default();
    let s = run(&mut world("two_bodies", &[]), 3.0);
    // ½ m v² + ½ I ω² of the ball, m g z of both.
    let energy = 0.5 * 2.0 * 9.0 + 0.5 * 0.008 * 900.0 + G * (2.0 * 0.09985 + 5.0 * 0.1519728);
    checks.close("energy at the start, closed form [J]", energy, 22.0, 0.05);
    checks.close("energy at the start, the run's [J]", s[0].energy.total(), 22.0, 0.05);
    let ball_x = |s: &Sample| s.states[0].position.x;
    let box_x = |s: &Sample| s.states[1].position.x;
    let hit = s.iter().position(|x| x.forces[0].2 > 0.0).expect("the ball hits the box");
    checks.close("hits at [s]", s[hit].t, 0.25, 0.005);
    checks.close("at [m/s]", s[hit].states[0].velocity.x, 2.94, 0.005);
    checks.close("box leaves at [m/s]", max_of(&s, |s| s.states[1].velocity.x), 1.09, 0.005);
    checks.close("box slides [m]", box_x(s.last().expect("samples")), 0.167, 0.0005);
    let stopped = s.iter().rposition(|x| x.states[1].velocity.norm() > 1e-3).expect("it moved");
    checks.close("box stops by [s]", s[stopped].t, 0.57, 0.005);
    checks.close("ball rebounds at [m/s]", -min_of(&s, |s| s.states[0].velocity.x), 0.64, 0.005);
    checks.close("ball rolls back to [m]", ball_x(s.last().expect("samples")), -0.94, 0.005);
    checks.close("energy balance [J]", balance_drift(&s), 0.1, 0.005);
    checks.done();
}

/// box_drop: what the ground takes, against what the integrator books.
#[test]
fn box_drop() {
    let mut checks = Checks::default();
    let s = run(&mut world("box_drop", &[]), 5.0);
    let first = s.iter().position(|x| x.forces[0].2 > 0.0).expect("it lands");
    checks.close("first impact at [s]", s[first].t, 0.41, 0.005);
    // Free fall from rest height, 0.5 m/s sideways: |v_G| = √(0.5² + (g t)²).
    checks.close("G falling at, closed form [m/s]", (0.25 + (G * s[first].t).powi(2)).sqrt(), 4.07, 0.005);
    checks.close("G falling at [m/s]", s[first].states[0].velocity.norm(), 4.05, 0.005);
    let end = s.last().expect("samples");
    checks.close("rests with G at [m]", end.states[0].position.z, 0.202, 0.0005);
    let moving = s.iter().rposition(|x| x.states[0].velocity.norm() > 1e-3).expect("it moved");
    checks.close("at rest by [s]", s[moving].t, 4.2, 0.05);
    checks.close("away from where it fell [m]", end.states[0].position.xy().norm(), 3.1, 0.05);
    // m g h + ½ m v² + ½ ωᵀ I ω at the start.
    let start = 20.0 * G * 1.2 + 0.5 * 20.0 * 0.25 + 0.5 * (0.5333333 * 2.25 + 0.8666667 * 6.25 + 0.8666667 * 0.25);
    checks.close("energy at the start, closed form [J]", start, 241.3, 0.05);
    checks.close("energy at the start, the run's [J]", s[0].energy.total(), 241.3, 0.05);
    checks.close("lost, start less rest [J]", s[0].energy.total() - end.energy.total(), 202.0, 0.5);
    checks.close("booked as dissipated [J]", end.energy.dissipated, 219.0, 0.5);
    checks.close("energy balance [J]", balance_drift(&s), 17.0, 0.5);
    checks.done();
}

/// suspension: the static loads, the bounce's frequency and damping against the quarter car's
/// two modes, and how it settles.
#[test]
fn suspension() {
    let mut checks = Checks::default();
    let s = run(&mut world("suspension", &[]), 3.0);
    // Compressed: negative tensions; the suspension's damper adds k_d v = 2000 × 0.8 N at t = 0.
    checks.close("tyre load at rest, (m + m_w) g [kN]", -s[0].forces[0].2 / 1e3, 440.0 * G / 1e3, 1e-4);
    checks.close("suspension load at rest, m g [kN]", (-s[0].forces[1].2 - 1600.0) / 1e3, 400.0 * G / 1e3, 1e-4);
    checks.close("tyre load [kN]", 440.0 * G / 1e3, 4.31, 0.005);
    checks.close("suspension load [kN]", 400.0 * G / 1e3, 3.92, 0.005);
    // Tangent stiffness at the static deflection s: a + 3 c s², with a s + c s³ = m g.
    let (a, c, rest_length, tyre, m, wheel, damping): (f64, f64, f64, f64, f64, f64, f64) =
        (15000.0, 80000.0, 0.81124, 2e5, 400.0, 40.0, 2000.0);
    let deflection = rest_length - 0.6;
    checks.close("static deflection balances the weight [N]", a * deflection + c * deflection.powi(3), m * G, 5.0);
    let k = a + 3.0 * c * deflection * deflection;
    // The undamped modes of the two masses: m_w m ω⁴ − (m_w k + m (k_t + k)) ω² + k_t k = 0.
    let (p, q) = (wheel * k + m * (tyre + k), tyre * k);
    let bounce = ((p - (p * p - 4.0 * wheel * m * q).sqrt()) / (2.0 * wheel * m)).sqrt();
    checks.close("bounce frequency, closed form [Hz]", bounce / (2.0 * PI), 1.2, 0.005);
    let k_series = k * tyre / (k + tyre);
    checks.close("damping ratio k_d/(2 √(k m)) [–]", damping / (2.0 * (k_series * m).sqrt()), 0.33, 0.005);
    let z = |s: &Sample| s.states[1].position.z - 0.9;
    let c = crossings(&s, 0.0, z);
    checks.close("bounce period, closed form [s]", 2.0 * PI / bounce, 0.83, 0.005);
    checks.close("bounce period from the run [s]", c[2] - c[0], 0.84, 0.005);
    checks.close("dips [mm]", -min_of(&s, z) * 1e3, 74.0, 0.5);
    checks.close("rebounds [mm]", max_of(&s, z) * 1e3, 34.0, 0.5);
    checks.close(
        "within 1 mm after [s]",
        s[s.iter().rposition(|x| z(x).abs() > 1e-3).expect("it moved")].t,
        2.33,
        0.005,
    );
    let end = s.last().expect("samples");
    checks.close("kinetic energy at the start [J]", s[0].energy.kinetic, 128.0, 0.05);
    checks.close("dampers take [J]", end.energy.dissipated, 128.2, 0.05);
    checks.close("energy balance [J]", balance_drift(&s), 0.16, 0.005);
    checks.done();
}

/// sagging_chain: the static catenary in the closed form, and the pontoon's swing.
#[test]
fn sagging_chain() {
    let mut checks = Checks::default();
    let s = run(&mut world("sagging_chain", &[]), 30.0);
    // Inextensible catenary, length L across the span S: L = 2a sinh(S/(2a)), H = λ g a,
    // sag a (cosh(S/(2a)) − 1).
    let (span, length, lambda): (f64, f64, f64) = (16.0, 30.0, 20.0);
    let (mut low, mut high): (f64, f64) = (0.1, 100.0);
    for _ in 0..200 {
        let a = 0.5 * (low + high);
        if 2.0 * a * (span / (2.0 * a)).sinh() > length {
            low = a;
        } else {
            high = a;
        }
    }
    let a = 0.5 * (low + high);
    checks.close("H, closed form [N]", lambda * G * a, 761.0, 0.5);
    checks.close("sag, closed form [m]", a * ((span / (2.0 * a)).cosh() - 1.0), 11.6, 0.05);
    let chain = |s: &Sample| s.forces[0].0;
    checks.close("H at the start [N]", chain(&s[0]).x, 761.0, 1.0);
    checks.close("vertical at each end [kN]", chain(&s[0]).z.abs() / 1e3, 2.94, 0.005);
    let b = |s: &Sample| s.states[1].position.x;
    let far = s.iter().enumerate().max_by(|x, y| b(x.1).total_cmp(&b(y.1))).expect("samples").0;
    checks.close("b stopped out at [m]", b(&s[far]) - 20.0, 2.9, 0.05);
    checks.close("at [s]", s[far].t, 5.4, 0.05);
    checks.close("H then [kN]", chain(&s[far]).x.abs() / 1e3, 1.04, 0.005);
    checks.close("b swings to [m]", max_of(&s, b), 22.9, 0.05);
    checks.close("and back to [m]", min_of(&s, b), 18.6, 0.05);
    let rope = |s: &Sample| s.forces[2].2;
    let pull = s.iter().enumerate().max_by(|x, y| rope(x.1).total_cmp(&rope(y.1))).expect("samples").0;
    checks.close("b's rope peaks [kN]", rope(&s[pull]) / 1e3, 3.8, 0.05);
    checks.close("at [s]", s[pull].t, 13.2, 0.05);
    let mean = mean_of(&s, b);
    checks.close("swing period [s]", period(&crossings(&s, mean, b)), 15.9, 0.05);
    checks.close("a moves [m]", max_of(&s, |s| s.states[0].position.x.abs()), 0.24, 0.005);
    checks.close("energy balance [mJ]", balance_drift(&s) * 1e3, 1.9, 0.05);
    checks.done();
}

/// barge_slipway: nothing passes through anything; the barge holds, then follows the tug in
/// surges on the elastic rope.
#[test]
fn barge_slipway() {
    let mut checks = Checks::default();
    let mut w = world("barge_slipway", &[]);
    let (sin3, cos3) = 3.0_f64.to_radians().sin_cos();
    let normal = Vector3::new(-sin3, 0.0, cos3);
    let along = Vector3::new(cos3, 0.0, sin3);
    let mut s = vec![sample(&w)];
    let mut rope_above = f64::INFINITY;
    while w.time() < 30.0 - 0.5 * w.dt() {
        w.step().unwrap_or_else(|e| panic!("{e}"));
        let line = w.line_state(1).expect("the tow rope is a catenary");
        let lowest = line.sample(50).iter().map(|(p, _)| normal.dot(p)).fold(f64::INFINITY, f64::min);
        rope_above = rope_above.min(lowest);
        s.push(sample(&w));
    }
    checks.close("the rope's lowest point above the ramp [m]", rope_above, 0.84, 0.005);
    let height = |s: &Sample, i: usize| normal.dot(&s.states[i].position);
    checks.close("the tug's keel above the ramp [m]", min_of(&s, |s| height(s, 1)) - 1.0, 0.0, 1e-6);
    checks.close("the barge's keel above the ramp [m]", min_of(&s, |s| height(s, 0)) - 0.75, -0.025, 0.0005);
    let u = |s: &Sample| along.dot(&s.states[0].position);
    checks.close(
        "creeps before the pull [mm]",
        (u(between(&s, 3.0, 30.0).first().expect("3 s")) - u(&s[0])) * 1e3,
        -8.0,
        0.5,
    );
    // The tanh law's creep: atanh(F/(μ N))/k_t, F the barge's weight down the slope and the
    // hanging rope's pull, N its weight and the rope's across it.
    let (early, late) = (&between(&s, 1.5, 30.0)[0], &between(&s, 3.0, 30.0)[0]);
    let rope = early.forces[1].1;
    checks.close("the slack rope pulls down the slope [kN]", -along.dot(&rope) / 1e3, 5.7, 0.05);
    let weight = 30000.0 * G;
    let creep = ((weight * sin3 - along.dot(&rope)) / (0.15 * (weight * cos3 - normal.dot(&rope)))).atanh() / 200.0;
    checks.close("creep, closed form [mm/s]", creep * 1e3, 2.6, 0.05);
    checks.close("creep from 1.5 to 3 s [mm/s]", (u(early) - u(late)) / 1.5 * 1e3, 2.6, 0.05);
    let tension = |s: &Sample| s.forces[1].2;
    let taut = s.iter().find(|x| tension(x) > 10e3).expect("the rope comes taut");
    checks.close("rope taut at [s]", taut.t, 3.9, 0.05);
    checks.close("peak rope tension [kN]", max_of(&s, tension) / 1e3, 88.0, 0.5);
    let speed = |s: &Sample| -along.dot(&s.states[0].velocity);
    checks.close("surges at up to [m/s]", max_of(&s, speed), 1.19, 0.005);
    let towed = between(&s, 10.0, 30.0);
    checks.close("the rope falls to [kN]", min_of(towed, tension) / 1e3, 9.4, 0.05);
    checks.close("the last surges peak at [kN]", max_of(between(&s, 25.0, 30.0), tension) / 1e3, 76.0, 0.5);
    let surges: Vec<f64> = towed
        .windows(3)
        .filter(|w| speed(&w[1]) > speed(&w[0]) && speed(&w[1]) >= speed(&w[2]) && speed(&w[1]) > 1.0)
        .map(|w| w[1].t)
        .collect();
    let cycle = (surges[surges.len() - 1] - surges[0]) / (surges.len() - 1) as f64;
    checks.close("surge cycle [s]", cycle, 1.1, 0.05);
    checks.close("down the ramp at 30 s [m]", -u(s.last().expect("samples")), 24.4, 0.05);
    // Friction net of gravity: μ m g cos 3° − m g sin 3°.
    checks.close("μ N − m g sin 3° [kN]", 30000.0 * G * (0.15 * cos3 - sin3) / 1e3, 28.7, 0.05);
    checks.close("energy balance [J]", balance_drift(&s), 19.0, 0.5);
    checks.done();
}

/// The static equilibrium `tether equilibrium` prints (still water, the current at full
/// strength) of a moored scene: G, each fairlead's tension [kN] and grounded length [m], stated
/// to within `rounding`.
fn mooring_statics(
    checks: &mut Checks,
    name: &str,
    g: [f64; 3],
    fairleads: &[f64],
    grounded: &[f64],
    rounding: f64,
) -> Equilibrium {
    let w = world(name, &[]);
    let system = w.system();
    let eq = equilibrium::solve(system, system.initial_states(), &[], &Settings::default())
        .unwrap_or_else(|e| panic!("{e}"));
    for (k, stated) in g.iter().enumerate() {
        checks.close("G at equilibrium [m]", eq.states[0].position[k], *stated, 0.0005);
    }
    for (c, stated) in fairleads.iter().enumerate() {
        checks.close("fairlead tension [kN]", eq.evaluation.forces()[c].f2.norm() / 1e3, *stated, rounding);
        checks.close("anchor tension [N]", eq.evaluation.forces()[c].f1.norm(), 0.0, 1e-6);
    }
    for (c, stated) in grounded.iter().enumerate() {
        let line = eq.evaluation.line_state(c).expect("a catenary");
        checks.close("grounded length [m]", line.grounded_length(), *stated, rounding);
    }
    eq
}

/// moored_buoy's equilibrium, its stiffness and the energy of its 5 m push.
#[test]
fn moored_buoy_at_rest() {
    let mut checks = Checks::default();
    let eq = mooring_statics(
        &mut checks,
        "moored_buoy",
        [0.0972, 0.0, -0.2034],
        &[32.34, 32.82, 32.82],
        &[140.55, 139.59, 139.59],
        0.005,
    );
    let pitch =
        attitude(&Sample { t: 0.0, states: eq.states.clone(), forces: vec![], energy: EnergyReport::default() }, 0).y;
    checks.close("pitched by the current [°]", pitch.to_degrees(), 0.019, 0.0005);
    let k = eq.body_stiffness(0);
    checks.close("surge stiffness [kN/m]", k[(0, 0)] / 1e3, 5.05, 0.005);
    checks.close("heave stiffness [kN/m]", k[(2, 2)] / 1e3, 128.0, 0.5);
    checks.close("the 5 m push stores ½ k x² [kJ]", 0.5 * k[(0, 0)] * 25.0 / 1e3, 63.0, 0.5);
    checks.done();
}

/// spread_moored_barge's equilibrium: it starts there.
#[test]
fn spread_moored_barge_at_rest() {
    let mut checks = Checks::default();
    let eq = mooring_statics(
        &mut checks,
        "spread_moored_barge",
        [0.041, 0.066, 0.972],
        &[99.7, 100.3, 101.2, 100.6],
        &[217.6, 217.3, 216.9, 217.2],
        0.05,
    );
    let k = eq.body_stiffness(0);
    checks.close("surge stiffness [kN/m]", k[(0, 0)] / 1e3, 19.3, 0.05);
    checks.close("sway stiffness [kN/m]", k[(1, 1)] / 1e3, 19.3, 0.05);
    checks.done();
}
