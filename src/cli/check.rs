//! `tether check SCENE`: what the scene is, in numbers.

use std::fmt::Write as _;
use tether_physics::body::{RigidBody, Support};
use tether_physics::coupling::contact::Opposing;
use tether_physics::coupling::lumped_line::{Discrete, statics};
use tether_physics::coupling::{
    Catenary, Contact, Coupling, CouplingForces, CouplingKind, ElasticLaw, Endpoint, LineModel, LumpedMass,
    SpringDamper,
};
use tether_physics::math::{Mat3, Vec3};
use tether_physics::potential::{
    DriftModel, DriftSource, LinearHydrostatics, PotentialBody, Radiation, RadiationStateSpace,
};
use tether_physics::stability;
use tether_physics::water::WaveSpec;
use tether_physics::water::dispersion::wavelength;
use tether_physics::water::hydrostatics::floating_equilibrium;
use tether_physics::water_stage::FloatingPotential;
use tether_physics::world::World;
use tether_scene::Scene;

pub fn run(scene: &Scene) -> anyhow::Result<()> {
    super::print(&report(&scene.world, &scene.path.display().to_string()))
}

fn report(world: &World, label: &str) -> String {
    let mut out = String::new();
    header_report(&mut out, world, label);
    for body in world.bodies() {
        body_report(&mut out, body);
    }
    water_report(&mut out, world);
    air_report(&mut out, world);
    for (index, (coupling, forces)) in world.couplings().iter().zip(world.coupling_forces()).enumerate() {
        coupling_report(&mut out, world, index, coupling, forces);
    }
    limits_report(&mut out, world);
    energy_report(&mut out, world);
    out
}

/// What the scene is: its size, its time step and integrator, gravity and the seabed.
fn header_report(out: &mut String, world: &World, label: &str) {
    let _ = writeln!(
        out,
        "{label}: ok — {} bodies, {} couplings, dt = {} s, integrator {}{}, {} substep(s) of {:.6e} s",
        world.bodies().len(),
        world.couplings().len(),
        world.dt(),
        world.integrator().name(),
        adaptive(world),
        world.substeps(),
        world.step_size()
    );
    let _ = writeln!(out, "gravity {} m/s²", vector(world.gravity()));
    if let Some(seabed) = world.system().seabed() {
        let _ =
            writeln!(out, "seabed at z_b = {} m, line friction C_B = {}", seabed.elevation(), seabed.line_friction());
    }
}

/// A body's mass properties in its principal frame, and its slave nodes.
fn body_report(out: &mut String, body: &RigidBody) {
    let p = &body.mass_properties;
    let _ = writeln!(out, "\nbody \"{}\" ({})", body.name, support(&body.support));
    let _ = writeln!(out, "  mass               {:.6} kg", p.mass);
    let _ = writeln!(out, "  centre of mass     {} m", vector(&p.center_of_mass));
    let _ = writeln!(out, "  inertia about G    {} kg·m²", matrix(&p.inertia_about_g));
    let _ = writeln!(out, "  principal moments  {} kg·m²", vector(&p.principal_moments));
    let axes = p.principal_axes.to_rotation_matrix().into_inner();
    for i in 0..3 {
        let _ = writeln!(out, "  principal axis {}   {}", i + 1, vector(&axes.column(i).into_owned()));
    }
    if !body.slave_nodes.is_empty() {
        let _ = writeln!(out, "  slave nodes        {}", body.slave_nodes.len());
    }
}

/// A coupling: its ends and what it is doing at t = 0.
fn coupling_report(out: &mut String, world: &World, index: usize, coupling: &Coupling, forces: &CouplingForces) {
    let [end1, end2] = coupling.ends();
    let _ = writeln!(out, "\ncoupling \"{}\" ({})", coupling.name, coupling.kind_name());
    let chord = (forces.point2 - forces.point1).norm();
    let ends = format!("  end 1 {}   end 2 {}", end(world, &end1), end(world, &end2));
    match &coupling.kind {
        CouplingKind::SpringDamper(spring) => spring_report(out, &ends, spring, chord, forces),
        CouplingKind::Catenary(line) => catenary_report(out, world, index, &ends, line, chord),
        CouplingKind::Contact(contact) => contact_report(out, world, contact),
    }
}

/// A spring-damper: its ends, its law, and its length and tension at t = 0.
fn spring_report(out: &mut String, ends: &str, spring: &SpringDamper, chord: f64, forces: &CouplingForces) {
    let _ = writeln!(out, "{ends}");
    let _ = writeln!(out, "  law {}, damping {} N·s/m", law(spring.law()), spring.damping());
    let _ = writeln!(out, "  length {chord:.6} m, tension {:.6} N", forces.tension);
}

/// A line: its ends, its values, its weight in the water, its model, and its solved shape at
/// t = 0.
fn catenary_report(out: &mut String, world: &World, index: usize, ends: &str, line: &Catenary, chord: f64) {
    let _ = writeln!(out, "{ends}");
    let _ = writeln!(
        out,
        "  λ0 = {} kg/m, L_eq = {} m, D = {} N/m (EA = {} N)",
        line.mass_per_length(),
        line.length(),
        line.stiffness(),
        line.stiffness() * line.length()
    );
    let fluid = world.system().surroundings().fluid_density;
    if line.displaced_area() > 0.0 {
        let _ = writeln!(
            out,
            "  A_d = {} m²: submerged weight {:.6} N/m",
            line.displaced_area(),
            line.submerged_mass_per_length(fluid) * world.gravity().norm()
        );
    }
    if let LineModel::Dynamic(parameters) = &line.model() {
        dynamic_line_report(out, world, index, line, parameters);
    }
    if let Some(measures) = tether::line_hint::measures(world, index) {
        let _ = writeln!(out, "  {}{measures}", if measures.suggests_dynamic() { "hint: " } else { "" });
    }
    if let Some(state) = world.line_state(index) {
        let (t1, t2) = state.end_tensions();
        let _ = writeln!(
            out,
            "  chord {chord:.6} m, H = {:.6} N, V1 = {:.6} N, V2 = {:.6} N, end tensions {t1:.6} / {t2:.6} N ({} Newton iterations)",
            state.horizontal_tension,
            state.vertical1,
            state.vertical2(),
            state.iterations
        );
        if state.ground.is_some() {
            let touchdowns: Vec<String> = state.touchdowns().iter().map(vector).collect();
            let _ = writeln!(
                out,
                "  on the seabed: L_B = {:.6} m, touchdown {}",
                state.grounded_length(),
                if touchdowns.is_empty() { "none".to_string() } else { touchdowns.join(", ") }
            );
        }
    }
}

/// The stable time steps and the contacts' impact resolutions against the integrator step.
fn limits_report(out: &mut String, world: &World) {
    let limits = world.limits();
    let adaptive = world.integrator().is_adaptive();
    let title = if adaptive {
        "stiffness limit (dopri45 adapts its step; explicit steps are held below these)"
    } else {
        "stable time step"
    };
    let _ = writeln!(out, "\n{title} ({}):", world.integrator().name());
    for limit in &limits {
        let _ = writeln!(out, "  {:<40} {:.6e} s", limit.describe(world.system()), limit.dt);
    }
    match stability::binding(&limits) {
        Some(binding) if adaptive => {
            let verdict =
                if world.step_size() <= binding.dt { "does not hold it back" } else { "holds its steps near this" };
            let _ = writeln!(
                out,
                "  binding: {} at {:.6e} s; with the integrator step {:.6e} s it {verdict}",
                binding.describe(world.system()),
                binding.dt,
                world.step_size()
            );
        }
        Some(binding) => {
            let verdict = if world.step_size() <= binding.dt { "stable" } else { "UNSTABLE: lower dt or add substeps" };
            let _ = writeln!(
                out,
                "  binding: {} at {:.6e} s; the integrator step {:.6e} s is {verdict}",
                binding.describe(world.system()),
                binding.dt,
                world.step_size()
            );
        }
        None => {
            let _ = writeln!(out, "  nothing limits the time step");
        }
    }
    for impact in world.impact_limits() {
        let verdict = if world.step_size() <= impact.dt {
            "resolved"
        } else {
            "UNDER-RESOLVED: the rebound will be wrong; lower dt or add substeps"
        };
        let _ = writeln!(
            out,
            "  {:<40} {:.6e} s; the integrator step is {verdict}",
            impact.describe(world.system()),
            impact.dt
        );
    }
}

/// The energies at t = 0 (PHYSICS.md §5).
fn energy_report(out: &mut String, world: &World) {
    let e = world.energy();
    let _ = writeln!(
        out,
        "\ninitial energy: kinetic {:.6} J, gravity {:.6} J, elastic {:.6} J, total {:.6} J",
        e.kinetic + 0.0,
        e.gravity + 0.0,
        e.elastic + 0.0,
        e.total() + 0.0
    );
}

/// The air (PHYSICS.md §10): the wind, and per body it loads its windage and rotor with the
/// mean wind at each and the steady force it gives on the body at rest.
fn air_report(out: &mut String, world: &World) {
    let Some(stage) = world.system().air() else { return };
    let air = stage.air();
    let spec = air.spec();
    let wind = &spec.wind;
    let _ = writeln!(
        out,
        "\nair: ρ_a {} kg/m³; wind {} m/s at {} m toward {}° ({:?}), gusts {:?}, ramp {} s",
        spec.density,
        wind.speed,
        wind.height,
        wind.heading.to_degrees(),
        wind.profile,
        wind.gusts,
        spec.ramp
    );
    if !air.gusts().is_steady() {
        let at = air.gusts().at(wind.height, air.mean_speed(10.0), wind.speed);
        let _ = writeln!(
            out,
            "  gusts at {} m: standard deviation {:.4} m/s (turbulence intensity {:.3}) over {} components, {} to {} Hz",
            wind.height,
            at.variance().sqrt(),
            at.variance().sqrt() / wind.speed.max(f64::MIN_POSITIVE),
            air.gusts().frequencies().len(),
            tether_physics::air::BAND.0,
            tether_physics::air::BAND.1
        );
    }
    for loaded in stage.bodies() {
        let name = &world.bodies()[loaded.body()].name;
        // Points from G in world axes at t = 0.
        let rotation = world.state(loaded.body()).frame().rotation;
        let (windage_speed, rotor_speed) = loaded.mean_speeds();
        if let (Some(windage), Some(speed)) = (loaded.windage(), windage_speed) {
            let areas = windage.drag_areas();
            let _ = writeln!(
                out,
                "  body \"{name}\" windage: C·A = ({:.4}, {:.4}, {:.4}) m² along its reference axes, centre {} m from G (world axes); mean wind there {speed:.4} m/s: steady drag along its x {:.6e} N",
                areas[0],
                areas[1],
                areas[2],
                vector(&(rotation * windage.center())),
                0.5 * air.density() * areas[0] * speed * speed
            );
        }
        if let (Some(rotor), Some(speed)) = (loaded.rotor(), rotor_speed) {
            let coefficient = rotor.thrust_coefficient(speed);
            let _ = writeln!(
                out,
                "  body \"{name}\" rotor: area {} m², hub {} m from G (world axes); mean wind there {speed:.4} m/s, C_T {coefficient:.4}: thrust {:.6e} N (quasi-steady, not an aeroelastic rotor)",
                rotor.area(),
                vector(&(rotation * rotor.hub())),
                0.5 * air.density() * rotor.area() * coefficient * speed * speed
            );
        }
    }
}

/// The water (PHYSICS.md §6) and each floating body's hydrostatics at its free-floating
/// equilibrium: weight and the couplings' vertical pull at t = 0, heave only.
fn water_report(out: &mut String, world: &World) {
    let Some(stage) = world.system().water() else { return };
    let water = &stage.water;
    let spec = water.spec();
    let depth =
        spec.depth.map_or_else(|| "deep".to_string(), |h| format!("depth {h} m (seabed at {} m)", spec.level - h));
    let waves = match spec.waves {
        WaveSpec::Calm => "calm".to_string(),
        WaveSpec::Regular { height, period, heading, phase } => format!(
            "regular H = {height} m, T = {period} s (λ = {:.3} m), heading {}°, phase {}°",
            wavelength(period, spec.depth, water.gravity()),
            heading.to_degrees(),
            phase.to_degrees()
        ),
        WaveSpec::Jonswap { significant_height, peak_period, gamma, heading, components, seed } => {
            format!(
                "JONSWAP Hs = {significant_height} m, Tp = {peak_period} s, γ = {gamma}, heading {}°, {components} components (seed {seed})",
                heading.to_degrees()
            )
        }
    };
    let _ = writeln!(out, "\nwater: ρ = {} kg/m³, level {} m, {depth}", spec.density, spec.level);
    let _ = writeln!(out, "  waves {waves}; ramp {} s", water.ramp_time());
    if spec.current.speed > 0.0 {
        let _ = writeln!(
            out,
            "  current {} m/s toward {}° ({:?})",
            spec.current.speed,
            spec.current.heading.to_degrees(),
            spec.current.profile
        );
    }
    for (floating, record) in stage.floating.iter().zip(world.water_forces()) {
        let index = floating.body();
        let body = &world.bodies()[index];
        let gravity = world.system().gravity_load(body);
        let pull = world.load(index).force.z - gravity.force.z - record.total().force.z;
        let hull = &floating.hull();
        let _ = writeln!(
            out,
            "\nfloating body \"{}\" (hull of {} triangles, {:.6} m³)",
            body.name,
            hull.triangles().len(),
            hull.volume()
        );
        let _ = writeln!(
            out,
            "  at t = 0: submerged {:.6} m³, water force {} N",
            record.submerged_volume,
            vector(&record.total().force)
        );
        if let Some(potential) = &floating.potential() {
            potential_report(out, world, index, potential.model());
            drift_report(out, potential);
            hydrostatics_report(out, potential.linear_hydrostatics());
        }
        if body.is_kinematic() {
            let _ = writeln!(out, "  kinematic: its motion is prescribed and the water does not act on it");
            continue;
        }
        match floating_equilibrium(body, (floating.hull(), floating.hydro()), water, &world.state(index), pull) {
            None => {
                let _ = writeln!(
                    out,
                    "  no floating equilibrium: its whole hull displaces {:.6} N, its weight and the couplings' pull ask {:.6} N (it sinks, or is pulled out)",
                    water.specific_weight() * hull.volume(),
                    body.mass() * water.gravity() - pull
                );
            }
            Some(e) => {
                let s = &e.statics;
                let _ = writeln!(
                    out,
                    "  free-floating equilibrium (weight, and the couplings' vertical pull at t = 0 of {pull:.6} N), heave only:"
                );
                let _ = writeln!(out, "  displaced volume   {:.6} m³", s.displaced_volume);
                let _ = writeln!(out, "  draft              {:.6} m (G at z = {:.6} m)", s.draft, e.height);
                let _ = writeln!(out, "  centre of buoyancy {} m", vector(&s.center_of_buoyancy));
                let _ = writeln!(
                    out,
                    "  waterplane area    {:.6} m² (centre ({:.6}, {:.6}) m)",
                    s.waterplane_area,
                    s.waterplane_center[0] + 0.0,
                    s.waterplane_center[1] + 0.0
                );
                let _ = writeln!(
                    out,
                    "  GM transverse      {:.6} m (roll, about x), longitudinal {:.6} m (pitch, about y)",
                    e.metacentric_heights[0], e.metacentric_heights[1]
                );
                let period =
                    |p: Option<f64>| p.map_or_else(|| "none (no restoring)".to_string(), |p| format!("{p:.6} s"));
                let _ = writeln!(
                    out,
                    "  natural periods    heave {}, roll {}, pitch {} (with added mass)",
                    period(e.periods[0]),
                    period(e.periods[1]),
                    period(e.periods[2])
                );
            }
        }
    }
}

/// The `A∞` the time domain's mass holds (PHYSICS.md §9 "A∞ consistent with the band"): the
/// largest relative change from the file's per dof, and the largest misfit of the time domain's
/// added mass to the file's `A(ω)` before and after; or that the file's `A∞` is kept.
fn infinite_added_mass_report(out: &mut String, model: &PotentialBody) {
    let consistency = model.band_consistency();
    if model.infinite_is_the_files() {
        let _ = writeln!(
            out,
            "  A∞: the file's (M + A∞ made consistent with the band is not positive definite: the time domain's added mass keeps the band's misfit, up to {:.2} %)",
            100.0 * consistency.misfit_file.max()
        );
        return;
    }
    let shifts = consistency.relative_shift(model.coefficients().added_mass_infinite());
    let per_dof: Vec<String> = tether_analysis::rao_chart::DOFS
        .iter()
        .zip(shifts)
        .map(|((name, _), shift)| format!("{name} {:.2} %", 100.0 * shift))
        .collect();
    let _ = writeln!(
        out,
        "  A∞: made consistent with the band (the largest change from the file's per dof: {}); the time domain's added mass within {:.2} % of the file's A(ω) (was {:.2} %)",
        per_dof.join(", "),
        100.0 * consistency.misfit_consistent.max(),
        100.0 * consistency.misfit_file.max()
    );
}

/// Pairs of the radiation fit printed on one line.
const PAIRS_PER_LINE: usize = 4;

/// A body's potential flow (PHYSICS.md §9): the panel data's extent, and how its radiation
/// memory is evaluated — the state space's order and fit error per kernel pair, or the direct
/// convolution's samples per evaluation.
fn potential_report(out: &mut String, world: &World, index: usize, model: &PotentialBody) {
    let coefficients = model.coefficients();
    let omegas = coefficients.frequencies();
    let headings: Vec<String> =
        coefficients.excitation().headings.iter().map(|b| format!("{}", b.to_degrees())).collect();
    let frame = world.state(index).frame();
    let _ = writeln!(
        out,
        "  potential flow: {} frequencies, {:.4} to {:.4} rad/s; headings {}°; reference point at {} m",
        omegas.len(),
        omegas.first().copied().unwrap_or(0.0),
        omegas.last().copied().unwrap_or(0.0),
        headings.join(", "),
        vector(&(frame.position + model.arm(&frame)))
    );
    infinite_added_mass_report(out, model);
    match model.radiation() {
        Radiation::StateSpace(fit) => state_space_report(out, fit),
        Radiation::Convolution(kernel) => {
            let samples = (kernel.duration() / world.step_size()).ceil() + 1.0;
            let _ = writeln!(
                out,
                "  radiation: direct convolution with K(t) sampled over {} s every {} s: about {samples} velocity samples, each times the 6 × 6 kernel, per evaluation (t_K over the {} s step)",
                kernel.duration(),
                kernel.step(),
                world.step_size()
            );
        }
    }
}

/// A potential-flow body's wave drift (PHYSICS.md §10): which file's coefficients, which model,
/// and the mean drift in the scene's sea.
fn drift_report(out: &mut String, potential: &FloatingPotential) {
    let model = potential.model().drift_model();
    let Some(table) = potential.model().coefficients().mean_drift() else {
        let _ = writeln!(out, "  wave drift: none (no .8 or .9 file beside the .1 and .3)");
        return;
    };
    let source = match table.source() {
        DriftSource::Momentum => ".8, momentum conservation (far field)",
        DriftSource::Pressure => ".9, pressure integration",
    };
    let omegas = table.frequencies();
    let _ = writeln!(
        out,
        "  wave drift: {} from {source}, {} frequencies, {:.4} to {:.4} rad/s",
        model.name(),
        omegas.len(),
        omegas.first().copied().unwrap_or(0.0),
        omegas.last().copied().unwrap_or(0.0),
    );
    let mean = potential.drift().mean();
    if model != DriftModel::Off {
        let _ = writeln!(
            out,
            "  mean drift in this sea: ({:.6e}, {:.6e}) N, yaw {:.6e} N·m (at the reference point, world axes)",
            mean[0], mean[1], mean[5]
        );
    }
}

/// Which hydrostatics a potential-flow body feels (PHYSICS.md §9 "Linear hydrostatics"): its
/// mesh's, or the `.hst`'s linear ones with their heave, roll and pitch stiffness.
fn hydrostatics_report(out: &mut String, linear: Option<&LinearHydrostatics>) {
    let _ = match linear {
        None => writeln!(out, "  hydrostatics: the still water's pressure on the mesh at its actual pose"),
        Some(linear) => {
            let c = linear.stiffness();
            writeln!(
                out,
                "  hydrostatics: linear from the .hst, about the reference point and the pose at t = 0: C33 {:.6e} N/m, C44 {:.6e} N·m/rad, C55 {:.6e} N·m/rad (the free-floating figures below are the mesh's)",
                c[(2, 2)],
                c[(3, 3)],
                c[(4, 4)]
            )
        }
    };
}

/// The state space's size and fit: what it was fitted to (the spectrum of the sampled kernel
/// over the data's band), total states, pairs, the worst pair's error (the spectrum's weighted
/// relative error, `potential::state_space`) against the scene's `fit_error`, then each pair's
/// order and error.
fn state_space_report(out: &mut String, fit: &RadiationStateSpace) {
    let (duration, step) = fit.kernel_sampling();
    let settings = fit.settings();
    let worst = fit.pairs().iter().max_by(|a, b| a.error.total_cmp(&b.error));
    let worst = worst.map_or_else(
        || "no pair to fit".to_string(),
        |p| format!("worst error {:.3e} (K{}{})", p.error, p.i + 1, p.j + 1),
    );
    let _ = writeln!(
        out,
        "  radiation: state space fitted to the spectrum B(ω) + iω(A(ω) − A∞) of K(t) (over {duration} s every {step} s) from 0 to {:.4} rad/s: {} states over {} pairs, {worst} (weighted relative error of the spectrum); fit_error {:e}, max_order {}",
        fit.band(),
        fit.state_count(),
        fit.pairs().len(),
        settings.tolerance(),
        settings.max_order()
    );
    for line in fit.pairs().chunks(PAIRS_PER_LINE) {
        let pairs: Vec<String> =
            line.iter().map(|p| format!("K{}{} {:>2} states {:.2e}", p.i + 1, p.j + 1, p.states(), p.error)).collect();
        let _ = writeln!(out, "    {}", pairs.join("   "));
    }
}

/// ` (rtol …, atol …, max step …)` for the adaptive scheme, nothing for the others.
fn adaptive(world: &World) -> String {
    if !world.integrator().is_adaptive() {
        return String::new();
    }
    let t = world.tolerances();
    let max_step = t.max_step().map_or_else(|| "the integrator step".to_string(), |m| format!("{m} s"));
    format!(" (rtol {:e}, atol {:e}, max step {max_step})", t.rtol(), t.atol())
}

fn contact_report(out: &mut String, world: &World, contact: &Contact) {
    let body = &world.bodies()[contact.body()];
    let against = match &contact.against() {
        Opposing::Planes(planes) if planes.len() == 1 => {
            format!("the plane through {} m with normal {}", vector(&planes[0].point), vector(&planes[0].normal))
        }
        Opposing::Planes(planes) => format!("{} walls of the domain box", planes.len()),
        Opposing::Body { body, .. } => format!("body \"{}\"", world.bodies()[*body].name),
    };
    let boundary = &contact.boundary();
    let _ = writeln!(
        out,
        "  faces of body \"{}\" ({} faces, {:.6} m²) against {against}",
        body.name,
        boundary.faces().len(),
        boundary.area()
    );
    let law = &contact.law();
    let _ = writeln!(
        out,
        "  k1 = {} N/m³, k2 = {} N·s/m³, d0 = {} m, μ = {}, k_t = {} s/m, expected area {:.6e} m²",
        law.stiffness(),
        law.damping(),
        law.range(),
        law.friction(),
        law.friction_sharpness(),
        contact.expected_area()
    );
    let mass = |i: usize| if world.bodies()[i].is_kinematic() { 0.0 } else { world.bodies()[i].inverse_mass };
    let inverse_mass = mass(contact.body()) + contact.other_body().map_or(0.0, mass);
    let totals = contact.totals(world.frames());
    let _ = writeln!(
        out,
        "  stopping time τ = {:.6e} s; now {} faces in contact over {:.6e} m², normal force {:.6} N, friction {:.6} N",
        contact.stopping_time(contact.limit_area(world.frames()), inverse_mass),
        totals.faces,
        totals.area,
        totals.normal,
        totals.friction
    );
}

/// `(x, y, z)` with 6 decimals; `+ 0.0` prints −0 as 0.
fn vector(x: &Vec3) -> String {
    format!("({:.6}, {:.6}, {:.6})", x.x + 0.0, x.y + 0.0, x.z + 0.0)
}

fn matrix(x: &Mat3) -> String {
    let rows: Vec<String> = (0..3).map(|r| vector(&x.row(r).transpose())).collect();
    format!("[{}]", rows.join(", "))
}

fn support(s: &Support) -> String {
    match s {
        Support::Free => "free".into(),
        Support::Fixed { translation, rotation } => {
            let axes: String = ["x", "y", "z"].iter().zip(translation).filter(|(_, f)| **f).map(|(a, _)| *a).collect();
            format!("fixed translation [{axes}]{}", if *rotation { ", fixed rotation" } else { "" })
        }
        Support::Kinematic(_) => "kinematic".into(),
    }
}

fn end(world: &World, e: &Endpoint) -> String {
    match e.body() {
        None => format!("world {} m", vector(&e.point())),
        Some(body) => {
            let b = &world.bodies()[body];
            let reference = b.reference_in_principal.inverse_transform_point(&e.point().into()).coords;
            format!("body \"{}\" at {} m", b.name, vector(&reference))
        }
    }
}

fn law(l: &ElasticLaw) -> String {
    match l {
        ElasticLaw::Linear { stiffness, rest_length } => format!("linear k = {stiffness} N/m, x0 = {rest_length} m"),
        ElasticLaw::Polynomial { a, b, c, rest_length } => {
            format!("polynomial k_eff = {a} + {b} s + {c} s² N/m, x0 = {rest_length} m")
        }
        ElasticLaw::ForceCurve { curve } => {
            format!("force curve ({} points), x0 = {:.6} m", curve.points().len(), l.rest_length())
        }
        ElasticLaw::StiffnessCurve { stiffness, rest_length } => {
            format!("stiffness curve ({} points), x0 = {rest_length} m", stiffness.points().len())
        }
        ElasticLaw::ReferenceForce { stiffness, reference_length, reference_force, .. } => {
            format!(
                "reference force f_r = {reference_force} N at x_r = {reference_length} m, stiffness curve ({} points)",
                stiffness.points().len()
            )
        }
    }
}

/// A dynamic line's segments, damping, drag and added mass, its own stable time steps (axial,
/// seabed) and the sub-step it takes, and its end forces at t = 0 (PHYSICS.md §8).
fn dynamic_line_report(out: &mut String, world: &World, index: usize, line: &Catenary, parameters: &LumpedMass) {
    let system = world.system();
    let water = system.water().map(|stage| stage.water.level());
    let discrete = Discrete::new(line, parameters, system.surroundings(), water);
    let limits = discrete.limits();
    let _ = writeln!(
        out,
        "  dynamic: N = {} segments of {:.6} m, BA = {:.6} N·s, C_dn {} C_dt {} C_an {} C_at {}",
        discrete.segments,
        discrete.segment,
        discrete.ba,
        parameters.drag_normal(),
        parameters.drag_tangential(),
        parameters.added_mass_normal(),
        parameters.added_mass_tangential()
    );
    let seabed = if limits.seabed.is_finite() { format!("{:.6e} s", limits.seabed) } else { "none".to_string() };
    let forces = &world.coupling_forces()[index];
    let started = std::time::Instant::now();
    let shape = statics::solve(line, &discrete, system.surroundings(), &forces.point1, &forces.point2, 0.0);
    let elapsed = started.elapsed();
    let tension = shape.nodes.largest_elastic_tension(&discrete);
    let _ = writeln!(
        out,
        "  line's own stable steps: axial {:.6e} s (taken implicitly), seabed {seabed}, transverse {:.6e} s at its \
         largest tension at rest ({:.1} N); it sub-steps by {:.6e} s",
        limits.axial,
        discrete.transverse_limit(tension),
        tension,
        discrete.substep(tension)
    );
    let _ = writeln!(
        out,
        "  initial shape: Newton on the discrete statics, {} iterations, largest residual {:.3e} N, {:.3} ms",
        shape.iterations,
        shape.residual,
        elapsed.as_secs_f64() * 1e3
    );
    let _ = writeln!(
        out,
        "  at t = 0 (the nodes at rest in their discrete equilibrium): end forces {:.6} / {:.6} N",
        forces.f1.norm(),
        forces.f2.norm()
    );
}
