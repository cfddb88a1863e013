//! Stable time step of the leapfrog for each coupling and each spinning body.
//!
//! - Spring-damper: the axial mode of the two ends, `ω² = k/m_eff` with the tangent stiffness
//!   `k` [N/m] and the effective mass of both ends along the spring, rotation about the
//!   attachment points included: `1/m_eff = Σ_ends (1/m + (r × d)ᵀ I⁻¹ (r × d))` [1/kg]
//!   (world ends and kinematic bodies add nothing). With `β = k_d/(2 m_eff)` [1/s] the central
//!   difference is stable for `dt ≤ 2/(√(ω² + β²) + β)`, which is `2(√(1+ζ²) − ζ)/ω` with
//!   `ζ = β/ω`, and `2/ω` undamped.
//! - Catenary: the same with `k` the largest eigenvalue of the line's tangent stiffness and `d`
//!   its eigenvector.
//! - Contact: the oscillator of stiffness `k1 A` and damping `k2 A` over the effective mass
//!   of the two bodies' translation, `A` the larger of the expected contact area and the area in
//!   contact now; and friction, which near rest is a damper of `c = μ k_t Σ|f_n|` [N·s/m]
//!   (stable for `dt ≤ 2 m_e/c`). Stability is not enough for an impact: PHYSICS.md §4 asks
//!   for a step well below the stopping time τ, and [`impact_limits`] gives `τ/10` per contact
//!   (stability alone would allow `4τ/π`); `substeps: Auto` honours both.
//! - Rotation: `|ω| dt < 1` (Radioss aborts beyond).

use super::coupling::contact::estimator::STEPS_PER_STOPPING_TIME;
use super::coupling::{BodyFrame, CouplingKind, Endpoint};
use super::world::World;
use super::Vec3;

/// What limits the time step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Limiter {
    /// Coupling index in the world.
    Coupling(usize),
    /// Body index: its spin.
    Rotation(usize),
    /// Coupling index of a contact: the step that resolves its impact (not a stability limit).
    Impact(usize),
}

/// A stable time step [s] and what sets it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limit {
    pub limiter: Limiter,
    pub dt: f64,
}

impl Limit {
    /// "coupling \"name\"", "rotation of body \"name\"" or "impact of contact \"name\" (τ/10)".
    pub fn describe(&self, world: &World) -> String {
        match self.limiter {
            Limiter::Coupling(i) => format!("coupling \"{}\"", world.couplings[i].name),
            Limiter::Rotation(i) => format!("rotation of body \"{}\"", world.bodies[i].name),
            Limiter::Impact(i) => format!("impact of contact \"{}\" (τ/10)", world.couplings[i].name),
        }
    }
}

/// `2/(√(ω² + β²) + β)` for stiffness `k` [N/m], damping `damping` [N·s/m] and inverse
/// effective mass `inverse_mass` [1/kg]; infinite when nothing oscillates.
pub fn damped_oscillator_limit(k: f64, damping: f64, inverse_mass: f64) -> f64 {
    let omega_squared = k.max(0.0) * inverse_mass;
    let beta = 0.5 * damping.max(0.0) * inverse_mass;
    let denominator = (omega_squared + beta * beta).sqrt() + beta;
    if denominator > 0.0 { 2.0 / denominator } else { f64::INFINITY }
}

/// Every finite limit of the world at its current state.
pub fn limits(world: &World) -> Vec<Limit> {
    let frames = world.frames();
    let mut limits = Vec::new();
    for (index, (coupling, forces)) in world.couplings.iter().zip(world.coupling_forces()).enumerate() {
        let [end1, end2] = coupling.ends();
        let chord = forces.point2 - forces.point1;
        let dt = match &coupling.kind {
            CouplingKind::SpringDamper(spring) => {
                let length = chord.norm();
                let Some(d) = chord.try_normalize(0.0) else { continue };
                let inverse = inverse_mass_along(world, frames, &end1, &d) + inverse_mass_along(world, frames, &end2, &d);
                damped_oscillator_limit(spring.law.tangent_stiffness(length), spring.damping, inverse)
            }
            CouplingKind::Catenary(line) => {
                let Some(state) = line.state() else { continue };
                let k = state.tangent_stiffness();
                let eigen = nalgebra::SymmetricEigen::new(0.5 * (k + k.transpose()));
                let (largest, _) = eigen.eigenvalues.argmax();
                let d = eigen.eigenvectors.column(largest).into_owned();
                let inverse = inverse_mass_along(world, frames, &end1, &d) + inverse_mass_along(world, frames, &end2, &d);
                damped_oscillator_limit(eigen.eigenvalues[largest], 0.0, inverse)
            }
            CouplingKind::Contact(contact) => {
                let inverse: f64 = [Some(contact.body), contact.other_body()].into_iter().flatten().map(|i| translational_inverse_mass(world, i)).sum();
                let area = contact.limit_area(frames);
                let normal = damped_oscillator_limit(contact.law.stiffness * area, contact.law.damping * area, inverse);
                let friction = contact.law.friction * contact.law.friction_sharpness * contact.normal_force();
                normal.min(damped_oscillator_limit(0.0, friction, inverse))
            }
        };
        if dt.is_finite() {
            limits.push(Limit { limiter: Limiter::Coupling(index), dt });
        }
    }
    for index in (0..world.bodies.len()).filter(|&i| !world.bodies[i].is_kinematic()) {
        let spin = world.state(index).angular_velocity.norm();
        if spin > 0.0 {
            limits.push(Limit { limiter: Limiter::Rotation(index), dt: 1.0 / spin });
        }
    }
    limits
}

/// The time step that resolves an impact of each contact, `τ/10` [s] (PHYSICS.md §4).
pub fn impact_limits(world: &World) -> Vec<Limit> {
    let inverse_mass = |i: usize| translational_inverse_mass(world, i);
    world
        .couplings
        .iter()
        .enumerate()
        .filter_map(|(index, coupling)| match &coupling.kind {
            CouplingKind::Contact(contact) => {
                let inverse = inverse_mass(contact.body) + contact.other_body().map_or(0.0, inverse_mass);
                Some(Limit { limiter: Limiter::Impact(index), dt: contact.stopping_time(contact.limit_area(world.frames()), inverse) / STEPS_PER_STOPPING_TIME })
            }
            _ => None,
        })
        .filter(|limit| limit.dt.is_finite())
        .collect()
}

/// The smallest limit, if any.
pub fn binding(limits: &[Limit]) -> Option<Limit> {
    limits.iter().copied().min_by(|a, b| a.dt.total_cmp(&b.dt))
}

/// `1/m` [1/kg] of a body that responds to forces, 0 for a kinematic one.
fn translational_inverse_mass(world: &World, index: usize) -> f64 {
    let body = &world.bodies[index];
    if body.is_kinematic() { 0.0 } else { body.inverse_mass }
}

/// `1/m + (r × d)ᵀ I⁻¹ (r × d)` of the body an end is on, for a unit force direction `d`.
fn inverse_mass_along(world: &World, frames: &[BodyFrame], end: &Endpoint, d: &Vec3) -> f64 {
    let Some(index) = end.body() else { return 0.0 };
    let body = &world.bodies[index];
    if body.is_kinematic() {
        return 0.0;
    }
    let frame = &frames[index];
    let arm = frame.rotation * end.point();
    // r × d in the principal frame, where I⁻¹ is diagonal.
    let lever = frame.rotation.tr_mul(&arm.cross(d));
    body.inverse_mass + lever.dot(&lever.component_mul(&body.inverse_principal_moments))
}
