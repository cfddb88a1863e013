//! Stable time step of the world's integrator for each coupling and each spinning body.
//!
//! Each coupling is an oscillator along its axis: `ω² = k/m_eff` [1/s²] with the tangent
//! stiffness `k` [N/m] and the effective mass of both ends along the coupling, rotation about
//! the attachment points included: `1/m_eff = Σ_ends (1/m + (r × d)ᵀ I⁻¹ (r × d))` [1/kg]
//! (world ends and kinematic bodies add nothing), and `β = k_d/(2 m_eff)` [1/s], `ζ = β/ω`.
//! For a catenary `k` is the largest eigenvalue of its ends' tangent stiffnesses `−∂f_i/∂p_i`
//! and `d` its eigenvector; it has no damper. For a contact, the oscillator of stiffness `k1 A` and damping
//! `k2 A` over the effective mass of the two bodies' translation, `A` the larger of the
//! expected contact area and the area in contact now; and friction, which near rest is a damper
//! of `c = μ k_t Σ|f_n|` [N·s/m] (an oscillator with `k = 0`: `dt ≤ 2 m_e/c` for the leapfrog).
//! Stability is not enough for an impact: PHYSICS.md §4 asks for a step well below the
//! stopping time τ, and [`impact_limits`] gives `τ/10` per contact (stability alone would allow
//! `4τ/π`); `substeps: Auto` honours both.
//!
//! - Leapfrog, leapfrog2, splitting (the same central difference in translation, dampers seeing
//!   `v(t−½dt)`): stable for `dt ≤ 2/(√(ω² + β²) + β)`, which is `2(√(1+ζ²) − ζ)/ω`
//!   (Belytschko), `2/ω` undamped.
//! - RK4 and Dormand–Prince: a linear oscillator's step multiplies each eigenvalue's mode by the
//!   scheme's stability polynomial `R(z)`, `z = dt λ`, `λ = −β ± i√(ω² − β²)` (or the most
//!   negative real `−β − √(β² − ω²)` when overdamped). The limit is the first `dt` along that
//!   ray where `|R(dt λ)| = 1`, found by a scan and bisection: `2√2/ω` undamped for RK4
//!   (`R = 1 + z + z²/2 + z³/6 + z⁴/24`), `2.785/ω` critically damped. For the adaptive
//!   Dormand–Prince (`R = Σ_{k≤5} zᵏ/k! + z⁶/600`) this is no limit on the user's step but a
//!   stiffness warning: its steps will be held near it. Near critical damping (ζ ≈ 1) RK4's
//!   step map is nearly defective: below the limit the energy of a critically damped spring
//!   still swings up before it decays (19× at 0.9 of the limit, 2.5× at 0.8), which the
//!   divergence check stops; the leapfrog family has no such transient.
//! - Rotation, fixed-step schemes: `|ω| dt < 1` (Radioss aborts beyond).
//! - Water (PHYSICS.md §6), per floating body: along each body axis `b_j` an oscillator of the
//!   hydrostatic stiffness `ρ g A_wp (b_j·ẑ)²`, the linearised drag `w (ρ C_dj A_j |u_r·b_j| +
//!   c_j)` and the mass with its added mass `m + w ρ V C_aj` (with potential flow, §9:
//!   `m + b_jᵀ A∞ b_j`, `A∞` about G; the radiation memory adds no stiffness); about each, the righting
//!   stiffness `ρ g V max(GM_T, GM_L, 0)`, the linearised rotational drag
//!   `w (2 C_rj |ω_j| + d_j)` and the smallest principal moment (added inertia left out: the
//!   estimate errs short). The still-water hydrostatics at the current pose stand for the
//!   waves'.

use crate::body::{BodyFrame, BodyState};
use crate::coupling::LineModel;
use crate::coupling::contact::estimator::STEPS_PER_STOPPING_TIME;
use crate::coupling::{Contact, CouplingKind, Endpoint};
use crate::evaluation::Evaluation;
use crate::integrator::Integrator;
use crate::math::Vec3;
use crate::system::System;
use crate::water::hydrostatics::Hydrostatics;
use nalgebra::Complex;

/// What limits the time step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limiter {
    /// Coupling index in the world.
    Coupling(usize),
    /// Body index: its spin.
    Rotation(usize),
    /// Coupling index of a contact: the step that resolves its impact (not a stability limit).
    Impact(usize),
    /// Body index: the water's stiffness and drag on it.
    Water(usize),
    /// Body index: the air's drag and a rotor's thrust on it (their aerodynamic damping).
    Air(usize),
}

/// A stable time step \[s] and what sets it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limit {
    pub limiter: Limiter,
    pub dt: f64,
}

impl Limit {
    /// "coupling \"name\"", "rotation of body \"name\"" or "impact of contact \"name\" (τ/10)".
    pub fn describe(&self, system: &System) -> String {
        match self.limiter {
            Limiter::Coupling(i) => format!("coupling \"{}\"", system.couplings()[i].name),
            Limiter::Rotation(i) => format!("rotation of body \"{}\"", system.bodies()[i].name),
            Limiter::Impact(i) => format!("impact of contact \"{}\" (τ/10)", system.couplings()[i].name),
            Limiter::Water(i) => format!("water on body \"{}\"", system.bodies()[i].name),
            Limiter::Air(i) => format!("air on body \"{}\"", system.bodies()[i].name),
        }
    }
}

/// What the limits are estimated from: the system, its last force evaluation, and the bodies'
/// synchronised states at that instant.
#[derive(Debug, Clone, Copy)]
pub struct Situation<'a> {
    pub system: &'a System,
    pub evaluation: &'a Evaluation,
    pub states: &'a [BodyState],
}

/// The stable step \[s] of `integrator` for an oscillator of stiffness `k` [N/m], damping
/// `damping` [N·s/m] and inverse effective mass `inverse_mass` [1/kg]; infinite when nothing
/// oscillates.
pub fn oscillator_limit(integrator: Integrator, k: f64, damping: f64, inverse_mass: f64) -> f64 {
    let omega_squared = k.max(0.0) * inverse_mass;
    let beta = 0.5 * damping.max(0.0) * inverse_mass;
    match integrator {
        Integrator::Leapfrog | Integrator::Leapfrog2 | Integrator::Splitting => {
            let denominator = (omega_squared + beta * beta).sqrt() + beta;
            if denominator > 0.0 { 2.0 / denominator } else { f64::INFINITY }
        }
        Integrator::Rk4 => polynomial_limit(&RK4, omega_squared, beta),
        Integrator::Dopri45 => polynomial_limit(&DORMAND_PRINCE, omega_squared, beta),
    }
}

/// Coefficients of the stability polynomial `R(z) = Σ c_k zᵏ` of RK4.
pub const RK4: [f64; 5] = [1.0, 1.0, 1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0];
/// Of the fifth-order Dormand–Prince solution.
pub const DORMAND_PRINCE: [f64; 7] = [1.0, 1.0, 1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0, 1.0 / 600.0];

/// `R(z)` for the coefficients `c`.
pub fn amplification(c: &[f64], z: Complex<f64>) -> Complex<f64> {
    c.iter().rev().fold(Complex::new(0.0, 0.0), |acc, &ck| acc * z + ck)
}

/// The first `dt` [s] at which `|R(dt λ)|` exceeds 1 for the oscillator eigenvalue `λ` of
/// `ω²` [1/s²] and `β` [1/s]: a scan of `|z|` by 1/64 up to 8 (beyond every explicit
/// scheme's region), then bisection to round-off.
fn polynomial_limit(c: &[f64], omega_squared: f64, beta: f64) -> f64 {
    let lambda = if beta * beta < omega_squared {
        Complex::new(-beta, (omega_squared - beta * beta).sqrt())
    } else {
        Complex::new(-beta - (beta * beta - omega_squared).sqrt(), 0.0)
    };
    let modulus = lambda.norm();
    if !(modulus > 0.0) {
        return f64::INFINITY;
    }
    let direction = lambda / modulus;
    let grows = |s: f64| amplification(c, direction * s).norm() > 1.0;
    const SCAN: f64 = 1.0 / 64.0;
    let Some(first) = (1..=512).map(|i| f64::from(i) * SCAN).find(|&s| grows(s)) else { return f64::INFINITY };
    let (mut stable, mut unstable) = (first - SCAN, first);
    for _ in 0..60 {
        let middle = 0.5 * (stable + unstable);
        if grows(middle) {
            unstable = middle;
        } else {
            stable = middle;
        }
    }
    stable / modulus
}

/// Every finite limit of `integrator` in `situation`.
pub fn limits(situation: &Situation, integrator: Integrator) -> Vec<Limit> {
    let Situation { system, evaluation, states } = *situation;
    let frames = evaluation.frames();
    let mut limits = Vec::new();
    for (index, (coupling, forces)) in system.couplings().iter().zip(evaluation.forces()).enumerate() {
        let [end1, end2] = coupling.ends();
        let along =
            |d: &Vec3| inverse_mass_along(system, frames, &end1, d) + inverse_mass_along(system, frames, &end2, d);
        let dt = match &coupling.kind {
            CouplingKind::SpringDamper(spring) => {
                let chord = forces.point2 - forces.point1;
                let length = chord.norm();
                let Some(d) = chord.try_normalize(0.0) else { continue };
                oscillator_limit(integrator, spring.law().tangent_stiffness(length), spring.damping(), along(&d))
            }
            CouplingKind::Catenary(line) if line.model() != LineModel::QuasiStatic => {
                // An end body is held by its first segment, a spring EA/l with its internal
                // damper BA/l against the next node (PHYSICS.md §8): the bodies' step must
                // resolve both (a light body on a stiffly damped chain is held by the damper).
                let Some(nodes) = evaluation.line_run(index).and_then(|run| run.nodes()) else { continue };
                let n = nodes.positions.len() - 1;
                let stiffness = line.stiffness() * n as f64;
                let segment = line.length() / n as f64;
                let damping = match &line.model() {
                    LineModel::Dynamic(lumped) => {
                        lumped.damping().coefficient(segment, line.stiffness() * line.length(), line.mass_per_length())
                            / segment
                    }
                    LineModel::QuasiStatic => 0.0,
                };
                let first = [
                    (end1, nodes.positions[1] - nodes.positions[0]),
                    (end2, nodes.positions[n - 1] - nodes.positions[n]),
                ];
                first
                    .iter()
                    .filter_map(|(end, along_segment)| {
                        let d = along_segment.try_normalize(0.0)?;
                        Some(oscillator_limit(
                            integrator,
                            stiffness,
                            damping,
                            inverse_mass_along(system, frames, end, &d),
                        ))
                    })
                    .fold(f64::INFINITY, f64::min)
            }
            CouplingKind::Catenary(_) => {
                let Some(state) = evaluation.line_state(index) else { continue };
                // The stiffer of the ends' own stiffnesses −∂f_i/∂p_i (both K for a free line;
                // on the seabed the bottom holds what the anchor does not feel).
                let blocks = state.end_stiffness();
                let eigen = |k: nalgebra::Matrix3<f64>| nalgebra::SymmetricEigen::new(-0.5 * (k + k.transpose()));
                let (first, second) = (eigen(blocks[0][0]), eigen(blocks[1][1]));
                let eigen = if first.eigenvalues.max() > second.eigenvalues.max() { first } else { second };
                let (largest, _) = eigen.eigenvalues.argmax();
                let d = eigen.eigenvectors.column(largest).into_owned();
                oscillator_limit(integrator, eigen.eigenvalues[largest], 0.0, along(&d))
            }
            CouplingKind::Contact(contact) => {
                let inverse: f64 = [Some(contact.body()), contact.other_body()]
                    .into_iter()
                    .flatten()
                    .map(|i| translational_inverse_mass(system, i))
                    .sum();
                let area = contact.limit_area(frames);
                let normal = oscillator_limit(
                    integrator,
                    contact.law().stiffness() * area,
                    contact.law().damping() * area,
                    inverse,
                );
                let friction = contact.law().friction()
                    * contact.law().friction_sharpness()
                    * evaluation.contact_forces(index).map_or(0.0, |forces| forces.normal);
                // Without a normal force friction damps nothing (an infinite limit): the faces
                // need not be evaluated again.
                if friction > 0.0 {
                    normal.min(oscillator_limit(
                        integrator,
                        0.0,
                        friction,
                        sliding_inverse_mass(system, frames, contact),
                    ))
                } else {
                    normal
                }
            }
        };
        if dt.is_finite() {
            limits.push(Limit { limiter: Limiter::Coupling(index), dt });
        }
    }
    limits.extend(water_limits(situation, integrator));
    limits.extend(air_limits(situation, integrator));
    // The adaptive scheme keeps its own rotation accurate.
    let spinning = if integrator.is_adaptive() { 0 } else { system.bodies().len() };
    for index in (0..spinning).filter(|&i| !system.bodies()[i].is_kinematic()) {
        let spin = states[index].angular_velocity.norm();
        if spin > 0.0 {
            limits.push(Limit { limiter: Limiter::Rotation(index), dt: 1.0 / spin });
        }
    }
    limits
}

/// The stable step of each wind-loaded body that responds to forces under its aerodynamic
/// damping (PHYSICS.md §10): `ρ_a C_i A_i |u_r|` per axis of its windage and `ρ_a A C_T |U_r|`
/// of its rotor, linearised at the mean wind at the load point plus four of its gusts' standard
/// deviations and the body's own speed, against the body's mass.
fn air_limits(situation: &Situation, integrator: Integrator) -> Vec<Limit> {
    let Situation { system, states, .. } = *situation;
    let Some(stage) = system.air() else { return Vec::new() };
    let density = stage.air().density();
    let mut limits = Vec::new();
    for loaded in stage.bodies().iter().filter(|b| !system.bodies()[b.body()].is_kinematic()) {
        let (body, state) = (&system.bodies()[loaded.body()], &states[loaded.body()]);
        let own = state.velocity.norm() + state.angular_velocity.norm() * body_extent(loaded);
        let (windage_speed, rotor_speed) = loaded.speeds_for_damping();
        let mut damping = 0.0;
        if let (Some(windage), Some(speed)) = (loaded.windage(), windage_speed) {
            damping += density * windage.drag_areas().into_iter().fold(0.0, f64::max) * (speed + own);
        }
        if let (Some(rotor), Some(speed)) = (loaded.rotor(), rotor_speed) {
            damping += density * rotor.area() * rotor.largest_thrust_coefficient() * (speed + own);
        }
        let dt = oscillator_limit(integrator, 0.0, damping, 1.0 / body.mass());
        if dt.is_finite() {
            limits.push(Limit { limiter: Limiter::Air(loaded.body()), dt });
        }
    }
    limits
}

/// The farthest of a wind-loaded body's load points from G \[m].
fn body_extent(loaded: &crate::air::WindBody) -> f64 {
    let windage = loaded.windage().map_or(0.0, |w| w.center().norm());
    let rotor = loaded.rotor().map_or(0.0, |r| r.hub().norm());
    windage.max(rotor)
}

/// The stable step of each floating body that responds to forces, under the water's stiffness
/// and linearised drag (see the module docs).
fn water_limits(situation: &Situation, integrator: Integrator) -> Vec<Limit> {
    let Situation { system, states, .. } = *situation;
    let Some(stage) = system.water() else { return Vec::new() };
    let water = &stage.water;
    let rho = water.density();
    let rho_g = water.specific_weight();
    let mut limits = Vec::new();
    for floating in stage.floating.iter().filter(|f| !system.bodies()[f.body()].is_kinematic()) {
        let (body, state) = (&system.bodies()[floating.body()], &states[floating.body()]);
        let frame = state.frame();
        let hull = &floating.hull();
        let statics = Hydrostatics::at(hull, &frame.position, &frame.rotation, water.level());
        let wetted = (statics.displaced_volume / hull.volume()).min(1.0);
        if !(wetted > 0.0) {
            continue;
        }
        let hydro = &floating.hydro();
        let speed = water.peak_flow_speed()
            + frame.velocity.norm()
            + state.angular_velocity.norm() * hydro.drag_center().norm();
        let (drag, turning) = hydro.linearised(&frame, speed, rho, wetted);
        let righting = rho_g
            * statics.displaced_volume
            * statics.metacentric_heights(frame.position.z).into_iter().fold(0.0, f64::max);
        let smallest_moment = body.principal_moments().min();
        let mut dt = f64::INFINITY;
        for j in 0..3 {
            let axis = frame.rotation * hydro.axes().column(j);
            let heave = rho_g * statics.waterplane_area * axis.z * axis.z;
            let mass = match &floating.potential() {
                // Potential flow: `A∞` about G along the axis (PHYSICS.md §9).
                Some(potential) => {
                    let infinite = potential.model().infinite_added_mass_at_center(&frame);
                    body.mass() + axis.dot(&(infinite.fixed_view::<3, 3>(0, 0) * axis))
                }
                None => body.mass() + wetted * rho * hull.volume() * hydro.spec().added_mass[j],
            };
            dt = dt.min(oscillator_limit(integrator, heave, drag[j], 1.0 / mass));
            dt = dt.min(oscillator_limit(integrator, righting, turning[j], 1.0 / smallest_moment));
        }
        if dt.is_finite() {
            limits.push(Limit { limiter: Limiter::Water(floating.body()), dt });
        }
    }
    limits
}

/// The time step that resolves an impact of each contact, `τ/10` \[s] (PHYSICS.md §4).
pub fn impact_limits(situation: &Situation) -> Vec<Limit> {
    let system = situation.system;
    let inverse_mass = |i: usize| translational_inverse_mass(system, i);
    system
        .couplings()
        .iter()
        .enumerate()
        .filter_map(|(index, coupling)| match &coupling.kind {
            CouplingKind::Contact(contact) => {
                let inverse = inverse_mass(contact.body()) + contact.other_body().map_or(0.0, inverse_mass);
                Some(Limit {
                    limiter: Limiter::Impact(index),
                    dt: contact.stopping_time(contact.limit_area(situation.evaluation.frames()), inverse)
                        / STEPS_PER_STOPPING_TIME,
                })
            }
            // Their forces grow with the stretch, not at an impact: no stopping time to resolve.
            CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => None,
        })
        .filter(|limit| limit.dt.is_finite())
        .collect()
}

/// The smallest limit, if any.
pub fn binding(limits: &[Limit]) -> Option<Limit> {
    limits.iter().copied().min_by(|a, b| a.dt.total_cmp(&b.dt))
}

/// The inverse effective mass [1/kg] that friction sees at the faces of `contact` in contact at
/// the kinematics `frames`: friction acts across the surface there, so it turns the bodies as
/// much as it pushes them.
fn sliding_inverse_mass(system: &System, frames: &[BodyFrame], contact: &Contact) -> f64 {
    let faces = contact.active_faces(frames);
    let frame = &frames[contact.body()];
    let on_body = faces.iter().map(|face| face.centroid);
    let mut sliding_inverse =
        translational_inverse_mass(system, contact.body()) + turning_inverse_mass(system, contact.body(), on_body);
    if let Some(other) = contact.other_body() {
        let to_other =
            |c: Vec3| frames[other].rotation.tr_mul(&(frame.position + frame.rotation * c - frames[other].position));
        sliding_inverse += translational_inverse_mass(system, other)
            + turning_inverse_mass(system, other, faces.iter().map(|face| to_other(face.centroid)));
    }
    sliding_inverse
}

/// `1/m` [1/kg] of a body that responds to forces, 0 for a kinematic one.
fn translational_inverse_mass(system: &System, index: usize) -> f64 {
    let body = &system.bodies()[index];
    if body.is_kinematic() { 0.0 } else { body.inverse_mass }
}

/// `max over the points r and unit directions t of (r × t)ᵀ I⁻¹ (r × t)` [1/kg]: the most a unit
/// force at one of `points` (principal frame of body `index`, relative to G) adds to the
/// acceleration of its point through rotation, the largest eigenvalue of `[r]×ᵀ I⁻¹ [r]×`;
/// 0 for a kinematic body.
fn turning_inverse_mass(system: &System, index: usize, points: impl Iterator<Item = Vec3>) -> f64 {
    let body = &system.bodies()[index];
    if body.is_kinematic() {
        return 0.0;
    }
    let inverse_inertia = nalgebra::Matrix3::from_diagonal(&body.inverse_principal_moments);
    points
        .map(|r| {
            let cross = r.cross_matrix();
            nalgebra::SymmetricEigen::new(cross.transpose() * inverse_inertia * cross).eigenvalues.max()
        })
        .fold(0.0, f64::max)
}

/// `1/m + (r × d)ᵀ I⁻¹ (r × d)` of the body an end is on, for a unit force direction `d`.
fn inverse_mass_along(system: &System, frames: &[BodyFrame], end: &Endpoint, d: &Vec3) -> f64 {
    let Some(index) = end.body() else { return 0.0 };
    let body = &system.bodies()[index];
    if body.is_kinematic() {
        return 0.0;
    }
    let frame = &frames[index];
    let arm = frame.rotation * end.point();
    // r × d in the principal frame, where I⁻¹ is diagonal.
    let lever = frame.rotation.tr_mul(&arm.cross(d));
    body.inverse_mass + lever.dot(&lever.component_mul(&body.inverse_principal_moments))
}
