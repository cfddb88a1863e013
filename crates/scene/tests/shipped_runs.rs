//! Every shipped scene runs its whole `duration` within the physical bounds declared for it
//! below: no body's centre of mass leaves its box, the energy balance (PHYSICS.md §5) drifts by
//! no more than its budget, the dissipated work never decreases (a dissipation is never
//! negative), and the run never diverges (every step healthy, every state finite).
//!
//! The boxes are the extents each scene's comment states, with a margin of a few millimetres to
//! centimetres (about 1 % of the motion): they fail when a scene or the physics changes what the
//! scene shows. The budgets are the drift a run of the scene's integrator measures, with about
//! half as much again: the drift is the integrator's error (first order where dampers, contact
//! dampers or friction work, which the leapfrog books at `v(t − ½dt)`), so a budget this tight
//! fails when the scheme or a law changes, not when an addition is reordered.
//!
//! All shipped scenes together take about 7 s of CPU (release build; `spread_moored_barge`'s 600 s
//! of a 1152-panel hull take most of it); none is shortened.

use tether_test_support as common;

use nalgebra::Vector3;
use tether_physics::world::World;

/// A box `[low, high]` [m] that the G of each body named `bodies` stays in: a body's name, or a
/// prefix followed by `*`.
struct Region {
    bodies: &'static str,
    low: [f64; 3],
    high: [f64; 3],
}

/// What a shipped scene declares: the boxes of its bodies and the budget of its energy balance.
struct Bounds {
    /// Path under `scenes/`.
    scene: &'static str,
    regions: &'static [Region],
    /// Largest `|B(t) − B(0)|` [J] allowed, `B = kinetic + gravity + elastic + dissipated −
    /// external work`.
    balance_budget: f64,
}

const fn region(bodies: &'static str, low: [f64; 3], high: [f64; 3]) -> Region {
    Region { bodies, low, high }
}

const BOUNDS: &[Bounds] = &[
    // Heaves, rolls and pitches in the 50-component sea: G between 1.62 m below and 1.52 m above
    // its floating position (z = 1.0 m); the ramp-in leaves this seed's barge drifting 10.9 m to
    // −y and 4.3 m to +x in 120 s (nothing moors it). Measured drift 1.97 kJ (first-order
    // dampers).
    Bounds {
        scene: "barge_in_waves.ron",
        regions: &[region("barge", [-0.44, -10.92, -0.64], [4.36, 0.45, 2.54])],
        balance_budget: 3.0e3,
    },
    // Dropped 0.5 m, undershoots to −0.397 m, settles at G = 0 (draft 2 m); the heave damper,
    // along the heeled body's z axis, walks it 0.45 m sideways. Measured drift 30.8 J
    // (first-order dampers).
    Bounds {
        scene: "floating_box.ron",
        regions: &[region("box", [-1e-6, -0.46, -0.41], [1e-6, 1e-6, 0.5 + 1e-6])],
        balance_budget: 46.0,
    },
    // Falls 2 m, sinks at 5.16 m/s, lands on the seabed's contact at z = −30 m (G 2.4 cm into
    // the contact's range at the first impact), bounces and rests at G = −29.494 m. Measured
    // drift 0.78 kJ, the contact damper's first-order work at the 13.3 kJ impact.
    Bounds {
        scene: "sinking_sphere.ron",
        regions: &[region("ball", [-0.01, -0.01, -29.53], [0.01, 0.01, 2.5 + 1e-6])],
        balance_budget: 1.2e3,
    },
    // Rests on the ramp, creeps 8 mm, then is dragged 24.4 m down it behind the tug, which rides
    // the ramp 24.5 m. Measured drift 18.6 J (the contact damper and friction, first order) of
    // the 373 kJ of gravity energy it gives up.
    Bounds {
        scene: "barge_slipway.ron",
        regions: &[
            region("barge", [-24.45, -0.01, -0.56], [-0.03, 0.01, 0.75]),
            region("tug", [-54.49, -1e-9, -1.87], [-30.01, 1e-9, -0.57]),
        ],
        balance_budget: 28.0,
    },
    // The fairlead driven 2 m at 10 s on the dynamic chain (N = 40): the driver puts in 0.96 MJ
    // over 60 s, the line's drag and damping take it out; measured drift 303 J (3.2e-4): the
    // partitioned exchange between the kinematic body and the line's sub-steps, first order in
    // the step, and the sub-steps' own error (PHYSICS.md §8; 250 J when the line sub-stepped
    // explicitly, then 123 J at 5 ms and 58 J at 2.5 ms).
    Bounds {
        scene: "chain_forced_surge.ron",
        regions: &[region("fairlead", [-2.0 - 1e-9, -1e-9, -1.0 - 1e-9], [2.0 + 1e-9, 1e-9, -1.0 + 1e-9])],
        balance_budget: 375.0,
    },
    // Released straight, bounded by the slack it can take up; measured drift 0.0107 J (the
    // springs' first-order dampers) of the 28 J it dissipates.
    Bounds {
        scene: "chain.ron",
        regions: &[region("ball*", [0.12, -1e-9, 2.03], [2.08, 1e-9, 3.04])],
        balance_budget: 0.016,
    },
    // The trolley's 7 m move and the load's ±4.5 m swing under it. Conservative: measured drift
    // 2.3 mJ of 98 kJ.
    Bounds {
        scene: "crane.ron",
        regions: &[
            region("tip", [-1e-9, -1e-9, 20.0 - 1e-9], [7.0 + 1e-9, 1e-9, 20.0 + 1e-9]),
            region("load", [-0.02, -1e-9, 4.28], [11.55, 1e-9, 4.99]),
        ],
        balance_budget: 3.5e-3,
    },
    // Dropped from 1 m, hops and comes to rest 3.1 m away on a long face. Measured drift 17.4 J
    // of the 241 J (the first corner impact at 4.4 m/s: contact damper and friction, first order).
    Bounds {
        scene: "box_drop.ron",
        regions: &[region("crate", [-0.01, -2.22, 0.195], [2.2, 0.01, 1.2 + 1e-9])],
        balance_budget: 26.0,
    },
    // Hangs against the quay, squeezed by 8 cm and released. Measured drift 0.20 J against the
    // 2.38 kJ the hull puts in.
    Bounds {
        scene: "fender.ron",
        regions: &[
            region("fender", [0.355, -0.01, -0.025], [0.425, 0.01, 0.005]),
            region("hull", [2.725 - 1e-9, -1e-9, 0.5 - 1e-9], [3.7 + 1e-9, 1e-9, 0.5 + 1e-9]),
        ],
        balance_budget: 0.3,
    },
    // Held by its four chains for 600 s within 3.98 m in surge, 5.57 m in sway of its rest, G
    // between −0.99 and 2.99 m. Measured drift 4.54 kJ (first-order dampers, over five times the
    // free barge's 120 s).
    Bounds {
        scene: "spread_moored_barge.ron",
        regions: &[region("barge", [-3.96, -5.52, -1.01], [3.64, 5.53, 3.01])],
        balance_budget: 6.8e3,
    },
    // Swings back from its 5 m push to x = −3.59 m, surging under the 8 s wave, heaving 0.93 m
    // below and 1.01 m above its rest at z = −0.203 m; no roll or sway in a head sea. Measured
    // drift 412 J: the seabed's friction law (C_B = 1) is not a potential (8.7 mJ with C_B = 0).
    Bounds {
        scene: "moored_buoy.ron",
        regions: &[region("buoy", [-3.60, -0.01, -1.15], [5.097 + 1e-6, 0.01, 0.82])],
        balance_budget: 620.0,
    },
    // moored_buoy on dynamic chains: their drag damps the swing back to x = −0.83 m; heaves 0.93 m
    // below and 1.01 m above its rest (z = −0.203 m). Measured drift 698 J, 0.10 % of the energy
    // the run moves (the stated_numbers test holds the fraction).
    Bounds {
        scene: "buoy_on_dynamic_chains.ron",
        regions: &[region("buoy", [-0.84, -0.01, -1.20], [5.097 + 1e-6, 0.01, 0.85])],
        balance_budget: 850.0,
    },
    // b swings between x = 18.6 and 22.9 m on the chain and its rope, a moves 0.25 m; z held.
    // Conservative: measured drift 1.9 mJ of the 2.6 kJ of motion.
    Bounds {
        scene: "sagging_chain.ron",
        regions: &[
            region("a", [-0.2, -0.85, -1e-9], [0.26, 1.0, 1e-9]),
            region("b", [18.55, -1.78, -1e-9], [22.96, 1.85, 1e-9]),
        ],
        balance_budget: 3e-3,
    },
    // OC3-Hywind (potential flow) pushed at 0.5 m/s in surge from its equilibrium (G at
    // x = −0.005 m, z = −78.0005 m): surges to 8.19 m, back to −5.38 m, heave within 51 mm below
    // its rest (the lines pull it down as they tighten); no sway. Measured drift 0.95 J of the
    // 1.01 MJ of kinetic energy it starts with (first-order dampers; the radiation's work, 1.04
    // MJ over 300 s, booked as external).
    // The buoy in its storm's first 600 s: surges from −2.41 to 4.75 m (the wave-frequency motion
    // about the slow drift and the mean push), heaves from −1.83 to +1.97 m about its rest
    // (z = −0.203 m), a millimetre of sway. Measured drift 0.85 J of the water's and the air's
    // work (RK4).
    Bounds {
        scene: "buoy_in_a_storm.ron",
        regions: &[region("buoy", [-2.42, -0.001, -2.045], [4.76, 0.001, 1.775])],
        balance_budget: 1.3,
    },
    // OC3-Hywind at rated wind in Hs 6 m: the thrust carries it from x = 0 to 28.40 m, about its
    // mean offset of 20.6 m; heave between −80.04 and −75.76 m (G at −78.0 at rest). Measured
    // drift 1.26 kJ of the MJ the wind and the waves put in.
    Bounds {
        scene: "oc3_hywind_rated.ron",
        regions: &[region("spar", [-0.03, -6e-4, -80.05], [28.41, 6e-4, -75.75])],
        balance_budget: 1.9e3,
    },
    Bounds {
        scene: "oc3_hywind.ron",
        regions: &[region("spar", [-5.39, -1e-5, -78.06], [8.19, 1e-5, -77.99])],
        balance_budget: 1.5,
    },
    // The closed form's envelope: |x − 1| ≤ 0.01 m. Measured drift 2.3e-6 J of the 5 mJ the
    // first-order damper takes.
    Bounds {
        scene: "spring_mass.ron",
        regions: &[region("mass", [0.99, -1e-9, -1e-9], [1.01 + 1e-9, 1e-9, 1e-9])],
        balance_budget: 3.5e-6,
    },
    // The body dips 74 mm and rebounds 34 mm. Measured drift 0.16 J of the 128 J the dampers
    // take (first order).
    Bounds {
        scene: "suspension.ron",
        regions: &[
            region("wheel", [-1e-9, -1e-9, 0.272], [1e-9, 1e-9, 0.32]),
            region("car", [-1e-9, -1e-9, 0.823], [1e-9, 1e-9, 0.937]),
        ],
        balance_budget: 0.24,
    },
    // Torque-free: G stays at the origin. Measured drift 8.4e-8 J of 1.00125 J (leapfrog2).
    Bounds { scene: "t_handle.ron", regions: &[region("handle", [-1e-9; 3], [1e-9; 3])], balance_budget: 1.3e-7 },
    // The ball knocks the box 0.167 m on and rolls back. Measured drift 0.097 J of the 12.6 J.
    Bounds {
        scene: "two_bodies.ron",
        regions: &[
            region("ball", [-1.0 - 1e-9, -0.29, 0.094], [-0.23, 0.01, 0.145]),
            region("box", [-0.001, 0.035, 0.15], [0.172, 0.06, 0.16]),
        ],
        balance_budget: 1.5,
    },
    // 20.2 m of chain across 15 m: it bulges 1.3 m past its anchors; 74 balls land on the soft
    // ground, sink up to 30 mm and roll up to 0.16 m sideways. Measured drift 821 J of the
    // 4.28 kJ: contact dampers and friction with c dt/m ≈ 0.2, first order (see its comment).
    Bounds {
        scene: "bench/chain100.ron",
        regions: &[region("ball*", [-1.35, -0.2, 0.015], [16.35, 0.2, 3.1])],
        balance_budget: 1.2e3,
    },
    // Falls 13.5 m at the middle and swings, bulging 1.3 m past its anchors. Measured drift 70 J
    // (the springs' first-order dampers) of the 3.4 kJ they take.
    Bounds {
        scene: "bench/chain100_air.ron",
        regions: &[region("ball*", [-1.35, -1e-9, 16.45], [16.35, 1e-9, 30.93])],
        balance_budget: 105.0,
    },
];

/// The bounds of the shipped scene at `path`, if declared.
fn bounds_of(path: &std::path::Path) -> Option<&'static Bounds> {
    BOUNDS.iter().find(|b| common::repo(&format!("scenes/{}", b.scene)) == path)
}

#[test]
fn every_shipped_scene_declares_its_bounds() {
    let files = common::scene_files();
    let undeclared: Vec<_> = files.iter().filter(|f| bounds_of(f).is_none()).collect();
    assert!(undeclared.is_empty(), "declare the bounds of {undeclared:?} in {}", file!());
    for bounds in BOUNDS {
        assert!(
            files.contains(&common::repo(&format!("scenes/{}", bounds.scene))),
            "no shipped scene {}",
            bounds.scene
        );
    }
}

/// What a run reached: each body's G extents, the largest energy balance drift, and the largest
/// fall of the dissipated work over a step.
struct Reached {
    low: Vec<Vector3<f64>>,
    high: Vec<Vector3<f64>>,
    drift: f64,
    dissipated_fall: f64,
}

/// The largest fall of the dissipated work over a step [J] allowed: its round-off, 10⁻¹² of
/// what it holds (Dormand–Prince's fifth weight is negative, so a step's quadrature of powers
/// each ≥ 0 is ≥ 0 only to its own order; no shipped scene runs it).
fn dissipated_round_off(dissipated: f64) -> f64 {
    1e-12 * dissipated.abs().max(1.0)
}

/// Runs `world` for `duration` [s], checking every step.
fn run(world: &mut World, duration: f64) -> Result<Reached, String> {
    let bodies = world.bodies().len();
    let start = world.energy().balance();
    let mut reached = Reached {
        low: vec![Vector3::repeat(f64::INFINITY); bodies],
        high: vec![Vector3::repeat(f64::NEG_INFINITY); bodies],
        drift: 0.0,
        dissipated_fall: 0.0,
    };
    let steps = (duration / world.dt()).round() as u64;
    for _ in 0..steps {
        let dissipated = world.energy().dissipated;
        world.step().map_err(|e| e.to_string())?;
        let fall = dissipated - world.energy().dissipated;
        if fall > dissipated_round_off(dissipated) {
            reached.dissipated_fall = reached.dissipated_fall.max(fall);
        }
        for i in 0..bodies {
            let state = world.state(i);
            if !state.is_finite() {
                return Err(format!("body {i} has a non-finite state at t = {}", world.time()));
            }
            reached.low[i] = reached.low[i].inf(&state.position);
            reached.high[i] = reached.high[i].sup(&state.position);
        }
        reached.drift = reached.drift.max((world.energy().balance() - start).abs());
    }
    Ok(reached)
}

/// Where `reached` breaks `bounds` in `world`, one line each.
fn breaches(bounds: &Bounds, world: &World, reached: &Reached) -> Vec<String> {
    let mut out = Vec::new();
    for (i, body) in world.bodies().iter().enumerate() {
        let matches = |r: &&Region| {
            r.bodies.strip_suffix('*').map_or(r.bodies == body.name, |prefix| body.name.starts_with(prefix))
        };
        let Some(region) = bounds.regions.iter().find(matches) else {
            out.push(format!("body \"{}\" has no declared box", body.name));
            continue;
        };
        let (low, high) = (Vector3::from(region.low), Vector3::from(region.high));
        if (0..3).any(|k| reached.low[i][k] < low[k] || reached.high[i][k] > high[k]) {
            out.push(format!(
                "body \"{}\" reached {:?} .. {:?}, outside {:?} .. {:?}",
                body.name,
                reached.low[i].as_slice(),
                reached.high[i].as_slice(),
                region.low,
                region.high
            ));
        }
    }
    if reached.dissipated_fall > 0.0 {
        out.push(format!("the dissipated work fell by {:.4e} J over a step", reached.dissipated_fall));
    }
    if reached.drift > bounds.balance_budget {
        out.push(format!(
            "the energy balance drifted by {:.4e} J, over its budget of {:.4e} J",
            reached.drift, bounds.balance_budget
        ));
    }
    out
}

#[test]
fn every_shipped_scene_runs_its_duration_within_its_bounds() {
    let mut failures = Vec::new();
    for file in common::scene_files() {
        let Some(bounds) = bounds_of(&file) else { continue };
        let scene = tether_scene::load(&file).unwrap_or_else(|e| panic!("{e}"));
        let mut world = scene.world;
        match run(&mut world, scene.file.duration) {
            Err(error) => failures.push(format!("{}: {error}", bounds.scene)),
            Ok(reached) => {
                assert!(
                    world.time() >= scene.file.duration - 0.5 * world.dt(),
                    "{} ran its whole duration",
                    bounds.scene
                );
                failures
                    .extend(breaches(bounds, &world, &reached).into_iter().map(|b| format!("{}: {b}", bounds.scene)));
            }
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}
