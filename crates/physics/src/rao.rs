//! A floating body's response amplitude operators (PHYSICS.md §9, "Closed forms and checks"):
//! the linear model the frequency-domain solve [`response`] needs, built from the system
//! itself, and `ξ(ω)` at a list of frequencies.
//!
//! Generalised coordinates are those of the body's reference point P (the panel code's origin,
//! `r = x_P − x_G`, world axes; [`crate::potential::body`]), small rotations:
//! - mass about P: `M_P = Jᵀ diag(m E, I_G) J`, `J = [[E, [r]×], [0, E]]` (so that
//!   `x_G = x_P + r × θ` for a small rotation θ about P) \[kg, kg·m, kg·m²];
//! - stiffness about P: `C = −∂Q/∂q` at the initial pose in still water, `Q` the mesh's
//!   pressure load (or the linear hydrostatics that replace it, [`crate::potential::hydrostatics`])
//!   plus the weight, both as `(f, m_P)` with `m_P = m_G − r × f`, by central
//!   differences of [`STEP`] in each translation of P and rotation about P
//!   [N/m, N, N·m/rad]. The weight adds nothing when P is G; about another point it gives the
//!   `−m g z_{G−P}` of roll and pitch. The same mesh the time domain floats, so a small regular
//!   wave settles to this `ξ`.

use crate::body::{BodyFrame, BodyState, Load};
use crate::coupling::CouplingError;
use crate::evaluation::Evaluation;
use crate::math::{Rotation, Vec3};
use crate::potential::body::{mass_at_center, transfer};
use crate::potential::response::response;
use crate::potential::{Coefficients, ComplexVector6, Matrix6, PotentialBody, Vector6};
use crate::system::System;
use std::f64::consts::TAU;
use std::sync::Arc;

/// The central-difference step of the stiffness \[m, rad].
pub const STEP: f64 = 1e-4;

/// Headings this close \[rad] to one of the file's are taken as it.
const SAME_HEADING: f64 = 1e-6;

/// Why a body has no RAO.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RaoError {
    #[error("no body named {name:?} (bodies: {known})")]
    UnknownBody { name: String, known: String },
    #[error("the scene has no water: RAOs need a body floating under potential flow")]
    NoWater,
    #[error("body {name:?} has no potential-flow data (hydro: Hydro(potential: Wamit(file: ...)))")]
    NoPotential { name: String },
    #[error("heading {heading:.3}° is not among the potential-flow file's headings ({known}°)")]
    Heading { heading: f64, known: String },
    #[error("coupling {coupling} cannot give its forces near the initial pose: {source}")]
    Evaluation { coupling: usize, source: CouplingError },
}

/// A body's linear model about its reference point: its data, mass and stiffness.
#[derive(Debug, Clone)]
pub struct LinearModel {
    /// The body's index in the system.
    index: usize,
    body: Arc<PotentialBody>,
    /// `M_P` (module docs).
    mass: Matrix6,
    /// `C` (module docs).
    stiffness: Matrix6,
    /// What is left on the body at its initial pose in still water — weight, mesh pressure,
    /// couplings — about G \[N, N·m]: zero for a body at rest, the pose the solve linearises
    /// about; a time-domain run settles about another pose otherwise.
    unbalanced: Load,
}

/// One frequency's response: `ξ` per unit wave amplitude (m/m, rad/m; WAMIT's phase).
#[derive(Debug, Clone, PartialEq)]
pub struct RaoRow {
    /// ω \[rad/s].
    pub omega: f64,
    /// `ξ(ω)`, or `None` where the system is singular.
    pub response: Option<ComplexVector6>,
}

impl LinearModel {
    /// `M_P` (module docs).
    pub fn mass(&self) -> &Matrix6 {
        &self.mass
    }

    /// `C` (module docs).
    pub fn stiffness(&self) -> &Matrix6 {
        &self.stiffness
    }

    /// What is left on the body at its initial pose in still water about G \[N, N·m].
    pub fn unbalanced(&self) -> Load {
        self.unbalanced
    }

    /// The model of the body named `name` in `system` at its initial pose.
    ///
    /// # Errors
    /// No such body, no water, a body without potential data, a coupling that fails.
    pub fn new(system: &System, name: &str) -> Result<Self, RaoError> {
        let bodies = system.bodies();
        let index = bodies.iter().position(|b| b.name == name).ok_or_else(|| RaoError::UnknownBody {
            name: name.to_string(),
            known: bodies.iter().map(|b| b.name.as_str()).collect::<Vec<_>>().join(", "),
        })?;
        let stage = system.water().ok_or(RaoError::NoWater)?;
        let model = stage
            .floating
            .iter()
            .find(|f| f.body() == index)
            .and_then(|f| f.potential())
            .ok_or_else(|| RaoError::NoPotential { name: name.to_string() })?
            .model()
            .clone();
        let state = &system.initial_states()[index];
        let arm = model.arm(&state.frame());
        let mass = mass_about(system, index, &arm);
        let stiffness = stiffness_about(system, index, &arm)?;
        let unbalanced = unbalanced(system, index)?;
        Ok(Self { index, body: model, mass, stiffness, unbalanced })
    }

    /// The panel code's data.
    pub fn coefficients(&self) -> &Coefficients {
        self.body.coefficients()
    }

    /// The body's index in the system.
    pub fn body(&self) -> usize {
        self.index
    }

    /// `r = x_P − x_G` \[m], world axes, at `frame`.
    pub fn arm(&self, frame: &BodyFrame) -> Vec3 {
        self.body.arm(frame)
    }

    /// The index of `heading` \[rad] among the file's excitation headings (modulo 2π).
    ///
    /// # Errors
    /// A heading the file lacks (the panel code's job to add, not interpolated here).
    pub fn heading_index(&self, heading: f64) -> Result<usize, RaoError> {
        let headings = &self.coefficients().excitation().headings;
        headings
            .iter()
            .position(|&b| {
                let turn = (heading - b).rem_euclid(TAU);
                turn.min(TAU - turn) <= SAME_HEADING
            })
            .ok_or_else(|| RaoError::Heading {
                heading: heading.to_degrees(),
                known: headings.iter().map(|b| format!("{:.3}", b.to_degrees())).collect::<Vec<_>>().join(", "),
            })
    }

    /// `ξ` at each of `omegas` \[rad/s] for heading index `heading`.
    pub fn rao(&self, omegas: &[f64], heading: usize) -> Vec<RaoRow> {
        omegas
            .iter()
            .map(|&omega| RaoRow {
                omega,
                response: response(self.coefficients(), &self.mass, &self.stiffness, omega, heading)
                    .filter(|xi| xi.iter().all(|x| x.re.is_finite() && x.im.is_finite())),
            })
            .collect()
    }
}

/// `M_P` of body `index` (module docs) with `arm` = `r` \[m], world axes, at the initial pose.
pub fn mass_about(system: &System, index: usize, arm: &Vec3) -> Matrix6 {
    let rotation = system.initial_states()[index].orientation.to_rotation_matrix().into_inner();
    let about_g = mass_at_center(&system.bodies()[index], &rotation);
    // P's accelerations to G's.
    let to_center = transfer(&-arm);
    to_center.transpose() * about_g * to_center
}

/// The load on body `index` at the initial pose in still water, at rest (`System::at_rest`):
/// weight, mesh pressure and couplings \[N, N·m about G].
///
/// # Errors
/// A coupling that cannot give its forces there.
fn unbalanced(system: &System, index: usize) -> Result<Load, RaoError> {
    let still = system.at_rest();
    let states = still.initial_states();
    let mut evaluation = Evaluation::new(states.len(), still.couplings());
    still
        .evaluate(states, &mut evaluation, 0.0)
        .map_err(|e| RaoError::Evaluation { coupling: e.coupling, source: e.source })?;
    Ok(evaluation.loads()[index])
}

/// `C` of body `index` (module docs) about P, `arm` = `r` \[m] at the initial pose.
///
/// # Errors
/// A water evaluation that fails at a displaced pose.
pub fn stiffness_about(system: &System, index: usize, arm: &Vec3) -> Result<Matrix6, RaoError> {
    let still = system.at_rest();
    let start = still.initial_states().to_vec();
    let Some(record) = still.water().and_then(|stage| stage.floating.iter().position(|f| f.body() == index)) else {
        return Err(RaoError::NoWater);
    };
    let reference = start[index].position + arm;
    let weight = still.gravity_load(&still.bodies()[index]).force;
    let load = |(states, reference): (Vec<BodyState>, Vec3)| -> Result<Vector6, RaoError> {
        let mut evaluation = Evaluation::new(states.len(), still.couplings());
        still
            .evaluate(&states, &mut evaluation, 0.0)
            .map_err(|e| RaoError::Evaluation { coupling: e.coupling, source: e.source })?;
        let pressure = evaluation.water()[record].pressure;
        let force = pressure.force + weight;
        let r = reference - states[index].position;
        let moment = pressure.moment - r.cross(&force);
        Ok(Vector6::new(force.x, force.y, force.z, moment.x, moment.y, moment.z))
    };
    // The states with P moved by `by` along, or turned by `by` about, world axis `dof % 3`, and
    // where P is then.
    let moved = |dof: usize, by: f64| {
        let mut states = start.clone();
        let mut axis = Vec3::zeros();
        axis[dof % 3] = by;
        let state = &mut states[index];
        if dof < 3 {
            state.position += axis;
            (states, reference + axis)
        } else {
            let turn = Rotation::from_scaled_axis(axis);
            state.position = reference + turn * (state.position - reference);
            state.orientation = turn * state.orientation;
            (states, reference)
        }
    };
    let mut c = Matrix6::zeros();
    for dof in 0..6 {
        let column = (load(moved(dof, STEP))? - load(moved(dof, -STEP))?) / (-2.0 * STEP);
        c.set_column(dof, &column);
    }
    Ok(c)
}
