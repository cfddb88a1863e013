//! A body's potential flow in the time domain (PHYSICS.md §9, Cummins' equation): its
//! coefficients, its reference point, `A∞` in its generalised mass, and its radiation model.
//!
//! Generalised coordinates are those of the reference point P (the panel code's origin, `r` from
//! G in world axes): `q̇ = (v_G + ω × r, ω)`, world axes, small rotations (the coefficients' axes
//! are the world's: the body's reference frame must start unrotated, as the panel code had it).
//! A 6-vector of forces at P, `(f, m_P)`, acts at G as `(f, m_P + r × f)` = `Tᵀ (f, m_P)`, with
//! `T = [[E, −[r]×], [0, E]]` taking G's accelerations `y = (a_G, α)` to P's
//! (`a_P = a_G + α × r + ω × (ω × r)`).
//!
//! **`A∞` in the generalised mass.** The equations of motion about G become
//! `(M_G + Tᵀ A∞ T) y = (F, M − ω × I ω) − Tᵀ A∞ (ω × (ω × r), 0)`, `M_G = diag(m E, I)` (world
//! axes), solved as one 6 × 6 system (`A∞` couples surge and pitch about G). As for Morison's
//! added mass (`crate::water::added_mass`), every integrator solves it unchanged: the water
//! stage adds the *reaction* `(m a_G − F, I α + ω × Iω − M)` to the body's load, so the rigid-body
//! equations give `y`. Its power is `−d/dt(½ q̇ᵀ A∞ q̇)`, booked with the water's.
//!
//! **Which `A∞`.** Not the file's ω = ∞ block as it stands but `A∞_eff`, consistent with the
//! file's `A(ω)` and the kernel the radiation memory uses (PHYSICS.md §9, "A∞ consistent with the
//! band"; [`super::kernel::consistent_with_band`]): the kernel has no damping beyond the file's
//! last frequency, so with the file's `A∞` the time domain's added mass falls short of the file's
//! over the whole band and its lightly damped resonances sit too high. Everything the time
//! domain's mass sees takes `A∞_eff`: the reaction, the stable time step's effective mass and
//! the natural periods "with A∞". When `M + A∞_eff` about G is not positive definite (a file
//! whose shift would make the mass indefinite) the file's `A∞` is kept instead, and
//! [`PotentialBody::infinite_is_the_files`] says so, for the adapters to warn.

use super::coefficients::{Coefficients, Matrix6, Vector6};
use super::drift::DriftModel;
use super::hydrostatics::HydrostaticsModel;
use super::kernel::{BandConsistency, SampledKernel, consistent_with_band};
use super::radiation::{Radiation, RadiationMethod};
use super::state_space::{FitError, FitSettings, RadiationStateSpace};
use crate::body::{BodyFrame, Load, RigidBody, Support};
use crate::math::{Mat3, Rotation, Vec3};
use crate::parameter::{Bound, ParameterError, require};

/// What a scene says of a body's potential flow.
#[derive(Debug, Clone, PartialEq)]
pub struct PotentialSpec {
    /// The panel code's data, about the reference point, world axes.
    pub coefficients: Coefficients,
    /// The reference point in the body's reference frame \[m].
    pub reference: Vec3,
    /// How the radiation force is evaluated.
    pub method: RadiationMethod,
    /// The state-space fit's error and highest order per pair.
    pub fit: FitSettings,
    /// The kernel's truncation `t_K` \[s] and sampling step \[s].
    pub kernel_duration: f64,
    pub kernel_step: f64,
    /// The mesh's hydrostatics or linear ones from the coefficients' `.hst` stiffness.
    pub hydrostatics: HydrostaticsModel,
    /// How the coefficients' mean drift loads the body (PHYSICS.md §10).
    pub drift: DriftModel,
}

/// A body's potential-flow data that cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PotentialError {
    #[error(transparent)]
    Parameter(#[from] ParameterError),
    #[error("the kernel's step {step} s must be below its duration {duration} s")]
    KernelSamples { step: f64, duration: f64 },
    #[error(transparent)]
    Fit(#[from] FitError),
    #[error(
        "the body starts turned {degrees:.1}° from the panel code's axes (its reference frame's, which the coefficients are in); potential flow takes them as the world's at t = 0, to within {MAX_START_TURN_DEGREES}°: turn the hull in the panel code instead"
    )]
    TurnedAtStart { degrees: f64 },
    #[error(
        "hydrostatics: Linear needs the panel code's hydrostatic stiffness, and no .hst file was read beside the .1 and .3 files"
    )]
    NoHydrostaticStiffness,
    #[error(
        "drift: {} needs the panel code's mean drift coefficients, and no .8 or .9 file was read beside the .1 and .3 files (validation/potential-flow/drift.py writes one)",
        model.name()
    )]
    NoDriftData { model: DriftModel },
}

/// The largest turn \[deg] of a body's reference frame from the world's axes at t = 0 that its
/// potential flow accepts: the coefficients are applied in world axes at P (§9), which a start
/// this far off only perturbs as the linear theory's own small rotations do (a decay test's
/// initial heel); a body placed at another heading needs the panel code run at it.
pub const MAX_START_TURN_DEGREES: f64 = 5.0;

/// `Ok` if `body`'s reference frame, at the start orientation `orientation` (principal frame →
/// world), is within [`MAX_START_TURN_DEGREES`] of the world's axes.
///
/// # Errors
/// [`PotentialError::TurnedAtStart`] with the angle.
pub fn check_start_axes(body: &RigidBody, orientation: &Rotation) -> Result<(), PotentialError> {
    let degrees = (orientation * body.reference_in_principal.rotation).angle().to_degrees();
    if degrees > MAX_START_TURN_DEGREES {
        return Err(PotentialError::TurnedAtStart { degrees });
    }
    Ok(())
}

/// A body's potential flow, built once (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PotentialBody {
    coefficients: Coefficients,
    /// P in the principal frame \[m].
    reference: Vec3,
    radiation: Radiation,
    /// `A∞_eff` and Ogilvie's check before and after the shift (module docs).
    consistency: BandConsistency,
    /// The `A∞` the time domain's mass holds \[kg, kg·m, kg·m²] about P: `A∞_eff`, or the file's
    /// when `M + A∞_eff` is not positive definite.
    infinite: Matrix6,
    /// How the mean drift loads the body (PHYSICS.md §10).
    drift: DriftModel,
}

/// A drift model other than `Off` needs the file's mean drift coefficients (`.8`/`.9`).
fn check_drift_data(drift: DriftModel, coefficients: &Coefficients) -> Result<(), PotentialError> {
    match (drift, coefficients.mean_drift()) {
        (DriftModel::Mean | DriftModel::Newman, None) => Err(PotentialError::NoDriftData { model: drift }),
        (DriftModel::Off, _) | (DriftModel::Mean | DriftModel::Newman, Some(_)) => Ok(()),
    }
}

impl PotentialBody {
    /// The model of `spec` for `body`: the kernel sampled and, for the state space, fitted;
    /// `A∞_eff` from the kernel and the file's `A(ω)` (module docs).
    ///
    /// # Errors
    /// A kernel step or duration out of range, a kernel no order up to the limit fits, or a
    /// drift model without the file's drift coefficients.
    pub fn new(spec: PotentialSpec, body: &RigidBody) -> Result<Self, PotentialError> {
        check_drift_data(spec.drift, &spec.coefficients)?;
        let step = require("kernel_step", spec.kernel_step, Bound::Positive, "s")?;
        let duration = require("kernel_duration", spec.kernel_duration, Bound::Positive, "s")?;
        if step >= duration {
            return Err(PotentialError::KernelSamples { step, duration });
        }
        let kernel = SampledKernel::from_damping(&spec.coefficients, step, duration);
        let consistency = consistent_with_band(&spec.coefficients, &kernel);
        let radiation = match spec.method {
            RadiationMethod::StateSpace => Radiation::StateSpace(RadiationStateSpace::fit(
                &kernel,
                spec.coefficients.highest_frequency(),
                spec.fit,
            )?),
            RadiationMethod::Convolution => Radiation::Convolution(kernel),
        };
        let reference = body.reference_in_principal.transform_point(&spec.reference.into()).coords;
        let infinite = if positive_definite_with(body, &reference, &consistency.infinite) {
            consistency.infinite
        } else {
            *spec.coefficients.added_mass_infinite()
        };
        Ok(Self { coefficients: spec.coefficients, reference, radiation, consistency, infinite, drift: spec.drift })
    }

    /// How the mean drift loads the body (PHYSICS.md §10).
    pub fn drift_model(&self) -> DriftModel {
        self.drift
    }

    /// The model with the mean drift loading the body as `drift` (a live edit, PHYSICS.md §10);
    /// the rest as built.
    ///
    /// # Errors
    /// A drift model without the file's drift coefficients.
    pub fn with_drift_model(&self, drift: DriftModel) -> Result<Self, PotentialError> {
        check_drift_data(drift, &self.coefficients)?;
        Ok(Self { drift, ..self.clone() })
    }

    /// The `A∞` the time domain's mass holds, about P \[kg, kg·m, kg·m²]: `A∞_eff` (module docs),
    /// or the file's when [`Self::infinite_is_the_files`].
    pub fn infinite_added_mass(&self) -> &Matrix6 {
        &self.infinite
    }

    /// `A∞_eff` and Ogilvie's check of the kernel's added mass with the file's `A∞` and with it
    /// (what `tether check` reports, with [`BandConsistency::relative_shift`]).
    pub fn band_consistency(&self) -> &BandConsistency {
        &self.consistency
    }

    /// Whether the mass holds the file's `A∞` because `M + A∞_eff` about G is not positive
    /// definite (a warning for the adapters to give; never for a panel code's consistent data).
    pub fn infinite_is_the_files(&self) -> bool {
        self.infinite != self.consistency.infinite
    }

    /// The panel code's data.
    pub fn coefficients(&self) -> &Coefficients {
        &self.coefficients
    }

    /// The radiation model.
    pub fn radiation(&self) -> &Radiation {
        &self.radiation
    }

    /// `r = x_P − x_G` \[m], world axes, at `frame`.
    pub fn arm(&self, frame: &BodyFrame) -> Vec3 {
        frame.rotation * self.reference
    }

    /// `q̇ = (v_G + ω × r, ω)` [m/s, rad/s] at `frame`.
    pub fn velocity(&self, frame: &BodyFrame) -> Vector6 {
        let omega = frame.rotation * frame.angular_velocity;
        let v = frame.velocity + omega.cross(&self.arm(frame));
        Vector6::new(v.x, v.y, v.z, omega.x, omega.y, omega.z)
    }

    /// The forces `q` at P [N, N·m] as a load about G: `(f, m_P + r × f)`.
    pub fn at_center(&self, frame: &BodyFrame, q: &Vector6) -> Load {
        let force = Vec3::new(q[0], q[1], q[2]);
        Load { force, moment: Vec3::new(q[3], q[4], q[5]) + self.arm(frame).cross(&force) }
    }

    /// The reaction that makes the rigid-body equations solve those with `A∞` for a body
    /// `body` at `frame` whose load from every other force is `load` (module docs). Nothing for
    /// a kinematic body; fixed components of a support get none.
    pub fn reaction(&self, body: &RigidBody, frame: &BodyFrame, load: &Load) -> Load {
        let (fixed_translation, fixed_rotation) = match &body.support {
            Support::Kinematic(_) => return Load::default(),
            Support::Free => ([false; 3], false),
            Support::Fixed { translation, rotation } => (*translation, *rotation),
        };
        let r = self.arm(frame);
        let omega = frame.rotation * frame.angular_velocity;
        let inertia = frame.rotation * Mat3::from_diagonal(&body.principal_moments()) * frame.rotation.transpose();
        let gyroscopic = omega.cross(&(inertia * omega));
        let transfer = transfer(&r);
        let infinite = &self.infinite;
        let mut matrix = transfer.transpose() * infinite * transfer;
        let mut block = matrix.fixed_view_mut::<3, 3>(0, 0);
        block += Mat3::identity() * body.mass();
        let mut block = matrix.fixed_view_mut::<3, 3>(3, 3);
        block += inertia;
        let centripetal = omega.cross(&omega.cross(&r));
        let centripetal = Vector6::new(centripetal.x, centripetal.y, centripetal.z, 0.0, 0.0, 0.0);
        let moment = load.moment - gyroscopic;
        let applied = Vector6::new(load.force.x, load.force.y, load.force.z, moment.x, moment.y, moment.z);
        let mut right = applied - transfer.transpose() * infinite * centripetal;
        let fixed: Vec<usize> =
            (0..3).filter(|&a| fixed_translation[a]).chain((3..6).filter(|_| fixed_rotation)).collect();
        for &dof in &fixed {
            matrix.set_row(dof, &nalgebra::RowVector6::zeros());
            matrix.set_column(dof, &Vector6::zeros());
            matrix[(dof, dof)] = 1.0;
            right[dof] = 0.0;
        }
        // M_G + Tᵀ A∞ T is positive definite for a body with mass and A∞ from a panel code; a
        // singular one (non-finite input) gives no reaction, and the health check reports the
        // non-finite state.
        let Some(y) = matrix.lu().solve(&right) else { return Load::default() };
        let (a, alpha) = (Vec3::new(y[0], y[1], y[2]), Vec3::new(y[3], y[4], y[5]));
        let mut force = a * body.mass() - load.force;
        for axis in (0..3).filter(|&a| fixed_translation[a]) {
            force[axis] = 0.0;
        }
        let moment = if fixed_rotation { Vec3::zeros() } else { inertia * alpha + gyroscopic - load.moment };
        Load { force, moment }
    }

    /// `Tᵀ A∞ T` \[kg, kg·m, kg·m²]: the `A∞` the time domain's mass holds
    /// ([`Self::infinite_added_mass`]) about G, world axes, at `frame` (the stable time step's
    /// effective mass, the natural periods with `A∞`).
    pub fn infinite_added_mass_at_center(&self, frame: &BodyFrame) -> Matrix6 {
        self.added_mass_at_center(frame, &self.infinite)
    }

    /// `Tᵀ A T`: an added mass `A` about P moved to G, world axes, at `frame`
    /// (`crate::natural_periods` with `A(ω)`).
    pub fn added_mass_at_center(&self, frame: &BodyFrame, added_mass: &Matrix6) -> Matrix6 {
        let transfer = transfer(&self.arm(frame));
        transfer.transpose() * added_mass * transfer
    }
}

/// Whether `M_G + Tᵀ A T` (symmetrised) is positive definite for `body` at the start, its
/// reference frame on the world's axes (as [`check_start_axes`] has it within 5°), `reference`
/// P in the principal frame \[m], `A` the added mass about P.
fn positive_definite_with(body: &RigidBody, reference: &Vec3, added_mass: &Matrix6) -> bool {
    let rotation = body.reference_in_principal.rotation.inverse().to_rotation_matrix().into_inner();
    let at_center = transfer(&(rotation * reference));
    let total = mass_at_center(body, &rotation) + at_center.transpose() * added_mass * at_center;
    ((total + total.transpose()) * 0.5).cholesky().is_some()
}

/// `diag(m E, I_G)` \[kg, kg·m²]: `body`'s own mass about G, world axes, for the principal frame
/// → world rotation `rotation` (`I_G = R diag(I₁, I₂, I₃) Rᵀ`); what `rao::mass_about` moves to
/// P and `natural_periods` adds the added mass to.
pub(crate) fn mass_at_center(body: &RigidBody, rotation: &Mat3) -> Matrix6 {
    let inertia = rotation * Mat3::from_diagonal(&body.principal_moments()) * rotation.transpose();
    let mut mass = Matrix6::identity() * body.mass();
    mass.fixed_view_mut::<3, 3>(3, 3).copy_from(&inertia);
    mass
}

/// `T = [[E, −[r]×], [0, E]]`: G's accelerations `(a_G, α)` to P's, `r = x_P − x_G` (with `−r`,
/// P's to G's: `rao::mass_about`).
pub(crate) fn transfer(r: &Vec3) -> Matrix6 {
    let mut t = Matrix6::identity();
    t.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-r.cross_matrix()));
    t
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::Shape;
    use crate::dynamics::accelerations;
    use crate::mass_properties::{MassProperties, Node};
    use crate::potential::coefficients::{CoefficientsData, ComplexVector6, Excitation};

    fn coefficients(infinite: Matrix6) -> Coefficients {
        Coefficients::new(CoefficientsData {
            frequencies: vec![1.0, 2.0],
            added_mass: vec![infinite; 2],
            damping: vec![Matrix6::zeros(); 2],
            added_mass_infinite: infinite,
            added_mass_zero: infinite,
            excitation: Excitation {
                frequencies: vec![1.0],
                headings: vec![0.0],
                values: vec![ComplexVector6::zeros()],
            },
            hydrostatic_stiffness: None,
            mean_drift: None,
        })
        .expect("valid data")
    }

    /// `A∞_eff` is what the mass holds, unless it would make `M + A∞` indefinite: a heave
    /// added mass of −1e6 kg over the band (no panel code's) shifts `A33∞` to about that, against
    /// the body's 500 kg, and the file's `A∞` is kept, said so; with +1e3 kg the shift is used.
    #[test]
    fn the_band_consistent_infinite_added_mass_is_held_unless_the_mass_would_be_indefinite() {
        let body = RigidBody::new(
            "b".into(),
            MassProperties::from_nodes(
                &Node { position: Vec3::zeros(), mass: 5.0e2, inertia: Mat3::identity() * 1.0e2 },
                &[],
            )
            .expect("a valid body"),
            Vec3::zeros(),
            &[],
            Support::Free,
            Shape::Sphere { radius: 1.0, center: Vec3::zeros(), subdivisions: 1 },
        );
        let heave = |v: f64| Matrix6::from_diagonal(&Vector6::new(0.0, 0.0, v, 0.0, 0.0, 0.0));
        let model = |added: f64| {
            let coefficients = Coefficients::new(CoefficientsData {
                frequencies: vec![1.0, 2.0],
                added_mass: vec![heave(added); 2],
                damping: vec![heave(1.0e2); 2],
                added_mass_infinite: heave(0.0),
                added_mass_zero: heave(-added),
                excitation: Excitation {
                    frequencies: vec![1.0],
                    headings: vec![0.0],
                    values: vec![ComplexVector6::zeros()],
                },
                hydrostatic_stiffness: None,
                mean_drift: None,
            })
            .expect("valid data");
            let spec = PotentialSpec {
                coefficients,
                reference: Vec3::zeros(),
                method: RadiationMethod::Convolution,
                fit: FitSettings::new(1e-3, 10).expect("valid"),
                kernel_duration: 20.0,
                kernel_step: 0.05,
                hydrostatics: HydrostaticsModel::Mesh,
                drift: DriftModel::Off,
            };
            PotentialBody::new(spec, &body).expect("valid")
        };
        let indefinite = model(-1.0e6);
        assert!(indefinite.band_consistency().infinite[(2, 2)] < -9.0e5, "{}", indefinite.band_consistency().infinite);
        assert!(indefinite.infinite_is_the_files());
        assert_eq!(indefinite.infinite_added_mass(), indefinite.coefficients().added_mass_infinite());
        let definite = model(1.0e3);
        assert!(!definite.infinite_is_the_files());
        assert_eq!(definite.infinite_added_mass(), &definite.band_consistency().infinite);
        assert!(definite.infinite_added_mass()[(2, 2)] > 9.0e2, "{}", definite.infinite_added_mass());
    }

    /// The rigid-body equations with the reaction solve `(M + A∞) q̈ = Q` at P: P's accelerations
    /// from the accelerations the integrators compute, against the forces moved to P.
    #[test]
    fn the_rigid_equations_with_the_reaction_solve_cummins_mass_about_the_reference_point() {
        let inertia = Mat3::from_diagonal(&Vec3::new(2.0e3, 3.0e3, 4.0e3));
        let properties =
            MassProperties::from_nodes(&Node { position: Vec3::new(0.0, 0.0, -4.0), mass: 5.0e2, inertia }, &[])
                .expect("a valid body");
        let body = RigidBody::new(
            "b".into(),
            properties,
            Vec3::new(0.0, 0.0, -4.0),
            &[],
            Support::Free,
            Shape::Sphere { radius: 1.0, center: Vec3::zeros(), subdivisions: 1 },
        );
        let mut infinite = Matrix6::from_diagonal(&Vector6::new(300.0, 300.0, 700.0, 900.0, 800.0, 50.0));
        (infinite[(0, 4)], infinite[(4, 0)], infinite[(1, 3)], infinite[(3, 1)]) = (-150.0, -150.0, 150.0, 150.0);
        let spec = PotentialSpec {
            coefficients: coefficients(infinite),
            reference: Vec3::new(0.5, 0.0, 4.0),
            method: RadiationMethod::Convolution,
            fit: FitSettings::new(1e-3, 10).expect("valid"),
            kernel_duration: 1.0,
            kernel_step: 0.1,
            hydrostatics: HydrostaticsModel::Mesh,
            drift: DriftModel::Off,
        };
        let potential = PotentialBody::new(spec, &body).expect("valid");
        let rotation = nalgebra::Rotation3::from_euler_angles(0.05, -0.03, 0.2).into_inner();
        let frame = BodyFrame {
            position: Vec3::new(0.0, 0.0, -4.0),
            rotation,
            velocity: Vec3::new(0.1, 0.0, -0.2),
            angular_velocity: Vec3::new(0.3, -0.2, 0.5),
        };
        let load = Load { force: Vec3::new(1.0e3, -2.0e3, 3.0e3), moment: Vec3::new(1.0e2, 2.0e2, -3.0e2) };
        let reaction = potential.reaction(&body, &frame, &load);
        let total = Load { force: load.force + reaction.force, moment: load.moment + reaction.moment };
        let a = accelerations(&body, &rotation, &total, &frame.angular_velocity);
        let omega = rotation * frame.angular_velocity;
        let alpha = rotation * a.angular;
        let r = potential.arm(&frame);
        assert!((r - rotation * Vec3::new(0.5, 0.0, 4.0)).norm() < 1e-12, "P is 4 m above G, 0.5 m aside");
        // Newton–Euler about G with the A∞ force at P, −A∞ q̈_P, moved to G.
        let a_p = a.linear + alpha.cross(&r) + omega.cross(&omega.cross(&r));
        let q_p = infinite * Vector6::new(a_p.x, a_p.y, a_p.z, alpha.x, alpha.y, alpha.z);
        let added = potential.at_center(&frame, &q_p);
        let inertia_world = rotation * Mat3::from_diagonal(&body.principal_moments()) * rotation.transpose();
        let force_error = a.linear * body.mass() + added.force - load.force;
        let moment_error = inertia_world * alpha + omega.cross(&(inertia_world * omega)) + added.moment - load.moment;
        assert!(force_error.norm() < 1e-9 * load.force.norm(), "{force_error}");
        assert!(moment_error.norm() < 1e-9 * load.moment.norm(), "{moment_error}");
    }
}
