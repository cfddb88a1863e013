//! Added mass: the water a body must set moving as it accelerates (PHYSICS.md §6, Morison loads
//! per body).
//!
//! In the body axes `b_j`, `M_a = w ρ V diag(C_aj)` \[kg] and `J_a = w diag(J_j)` [kg·m²]; in the
//! principal frame `Q M_a Qᵀ` with `Q = [b_1 b_2 b_3]`. The equations of motion become
//! - `(m E + R M_a Rᵀ) γ = F + R M_a Rᵀ u̇` (world; `u̇` the water's acceleration at the drag
//!   centre: the diffraction part of the fluid inertia, the Froude–Krylov part being in the
//!   pressure), and
//! - `(I + J_a) α = M − ω × ((I + J_a) ω)` (principal frame; Kirchhoff's form for the body and
//!   the water it carries; the Munk moment of the translational added mass is neglected).
//!
//! Every integrator solves them unchanged: this stage, which runs after every other force of the
//! evaluation, adds the *reaction* `F_a = m γ − F`, `M_a = R (I α + ω × Iω) − M` to the body's
//! load, so that the rigid-body equations the integrators share ([`crate::dynamics`]) give `γ`
//! and `α` above. The reaction is a water force: its power is booked with the others. The
//! angular velocity is the one of the evaluation (for the leapfrogs, the lagged half step their
//! own gyroscopic term uses). Fixed components of a support get no reaction.

use crate::body::{BodyFrame, Load, RigidBody, Support};
use crate::math::{Mat3, Vec3};

/// Added mass \[kg] and inertia [kg·m²], principal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AddedMass {
    pub translational: Mat3,
    pub rotational: Mat3,
}

impl AddedMass {
    /// `Q w ρ V diag(C_a) Qᵀ` and `Q w diag(J) Qᵀ` for the body axes `axes` (`Q`), the
    /// coefficients `coefficients`, the added inertias `inertias` [kg·m²], the displaced volume
    /// `volume` \[m³] of the whole hull, density `density` [kg/m³], wetted fraction `wetted`.
    pub fn new(axes: &Mat3, coefficients: &Vec3, inertias: &Vec3, volume: f64, density: f64, wetted: f64) -> Self {
        let along = |diagonal: Vec3| axes * Mat3::from_diagonal(&diagonal) * axes.transpose();
        Self { translational: along(coefficients * (wetted * density * volume)), rotational: along(inertias * wetted) }
    }

    /// The reaction to add to the load `load` of `body` at `frame` for the water acceleration
    /// `water_acceleration` [m/s²] (world): see the module docs. Nothing for a kinematic body.
    pub fn reaction(&self, body: &RigidBody, frame: &BodyFrame, load: &Load, water_acceleration: &Vec3) -> Load {
        let (fixed_translation, fixed_rotation) = match &body.support {
            Support::Kinematic(_) => return Load::default(),
            Support::Free => ([false; 3], false),
            Support::Fixed { translation, rotation } => (*translation, *rotation),
        };
        let force =
            self.translational_reaction(body.mass(), &frame.rotation, load, water_acceleration, fixed_translation);
        let moment = if fixed_rotation { Vec3::zeros() } else { self.rotational_reaction(body, frame, &load.moment) };
        Load { force, moment }
    }

    /// `m γ − F` with `(m E + A) γ = F + A u̇`, `A = R M_a Rᵀ`, over the free components.
    fn translational_reaction(
        &self,
        mass: f64,
        rotation: &Mat3,
        load: &Load,
        water_acceleration: &Vec3,
        fixed: [bool; 3],
    ) -> Vec3 {
        let added = rotation * self.translational * rotation.transpose();
        let mut matrix = Mat3::identity() * mass + added;
        let mut right = load.force + added * water_acceleration;
        for axis in (0..3).filter(|&a| fixed[a]) {
            matrix.set_row(axis, &nalgebra::RowVector3::zeros());
            matrix.set_column(axis, &Vec3::zeros());
            matrix[(axis, axis)] = mass;
            right[axis] = 0.0;
        }
        // m E + A is symmetric positive definite (m > 0, A ≥ 0): Cholesky cannot fail but for
        // non-finite input, which the health check then reports.
        let Some(factor) = matrix.cholesky() else { return Vec3::zeros() };
        let mut reaction = factor.solve(&right) * mass - load.force;
        for axis in (0..3).filter(|&a| fixed[a]) {
            reaction[axis] = 0.0;
        }
        reaction
    }

    /// `R (I α + ω × Iω) − M` with `(I + J) α = Rᵀ M − ω × ((I + J) ω)`.
    fn rotational_reaction(&self, body: &RigidBody, frame: &BodyFrame, moment: &Vec3) -> Vec3 {
        if self.rotational == Mat3::zeros() {
            return Vec3::zeros();
        }
        let inertia = Mat3::from_diagonal(&body.principal_moments());
        let total = inertia + self.rotational;
        let omega = &frame.angular_velocity;
        let applied = frame.rotation.tr_mul(moment);
        let Some(factor) = total.cholesky() else { return Vec3::zeros() };
        let alpha = factor.solve(&(applied - omega.cross(&(total * omega))));
        frame.rotation * (inertia * alpha + omega.cross(&(inertia * omega))) - moment
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Shape;
    use crate::dynamics::accelerations;
    use crate::mass_properties::{MassProperties, Node};
    use approx::assert_relative_eq;

    fn body(support: Support) -> RigidBody {
        let inertia = Mat3::from_diagonal(&Vec3::new(2.0, 3.0, 4.0));
        let properties = MassProperties::from_nodes(&Node { position: Vec3::zeros(), mass: 5.0, inertia }, &[])
            .expect("a valid body");
        RigidBody::new(
            "b".into(),
            properties,
            Vec3::zeros(),
            &[],
            support,
            Shape::Sphere { radius: 1.0, center: Vec3::zeros(), subdivisions: 1 },
        )
    }

    #[test]
    fn the_rigid_equations_with_the_reaction_solve_the_equations_with_added_mass() {
        let body = body(Support::Free);
        let axes = nalgebra::Rotation3::from_euler_angles(0.2, 0.5, -0.3).into_inner();
        let added = AddedMass::new(&axes, &Vec3::new(0.5, 1.0, 2.0), &Vec3::new(0.3, 0.7, 1.1), 2.0, 1000.0, 0.6);
        let rotation = nalgebra::Rotation3::from_euler_angles(-0.4, 0.1, 0.9).into_inner();
        let frame = BodyFrame {
            position: Vec3::zeros(),
            rotation,
            velocity: Vec3::zeros(),
            angular_velocity: Vec3::new(0.3, -0.2, 0.5),
        };
        let load = Load { force: Vec3::new(10.0, -20.0, 30.0), moment: Vec3::new(1.0, 2.0, -3.0) };
        let u_dot = Vec3::new(0.4, 0.0, -0.2);
        let reaction = added.reaction(&body, &frame, &load, &u_dot);
        let total = Load { force: load.force + reaction.force, moment: load.moment + reaction.moment };
        let a = accelerations(&body, &rotation, &total, &frame.angular_velocity);
        // (m E + A) γ = F + A u̇, world.
        let big_a = rotation * added.translational * rotation.transpose();
        assert_relative_eq!((Mat3::identity() * 5.0 + big_a) * a.linear, load.force + big_a * u_dot, epsilon = 1e-12);
        // (I + J) α + ω × ((I + J) ω) = Rᵀ M, principal frame.
        let i_total = Mat3::from_diagonal(&body.principal_moments()) + added.rotational;
        let w = frame.angular_velocity;
        assert_relative_eq!(
            i_total * a.angular + w.cross(&(i_total * w)),
            rotation.tr_mul(&load.moment),
            epsilon = 1e-12
        );
    }

    #[test]
    fn fixed_components_get_no_reaction_and_the_others_still_the_added_mass() {
        let body = body(Support::Fixed { translation: [true, false, false], rotation: true });
        let added = AddedMass::new(&Mat3::identity(), &Vec3::new(1.0, 1.0, 1.0), &Vec3::repeat(1.0), 1.0, 5.0, 1.0);
        let frame = BodyFrame::default();
        let load = Load { force: Vec3::new(3.0, 0.0, 10.0), moment: Vec3::new(0.0, 1.0, 0.0) };
        let reaction = added.reaction(&body, &frame, &load, &Vec3::zeros());
        assert_eq!(reaction.force.x, 0.0);
        assert_eq!(reaction.moment, Vec3::zeros());
        // z: (5 + 5) γ = 10 → m γ − F = 5 − 10.
        assert_relative_eq!(reaction.force.z, -5.0, epsilon = 1e-14);
    }
}
