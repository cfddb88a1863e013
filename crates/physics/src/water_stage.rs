//! The water stage of a force evaluation (PHYSICS.md §6; the stages are listed in
//! [`crate::water`]): for each floating body, pressure, Morison loads and added mass, recorded
//! in its [`WaterForces`] and added to its load; returns their power.

use crate::body::{BodyFrame, Load, RigidBody};
use crate::math::Vec3;
use crate::mesh::MeshError;
use crate::potential::{
    DriftModel, HeadingMissing, LinearHydrostatics, PotentialBody, PotentialError, RadiationRun, WaveDrift,
    WaveExcitation,
};
use crate::simd::SupportedLevel;
use crate::water::environment::{Water, WaterError, WaterSpec};
use crate::water::forces::WaterForces;
use crate::water::hull::Hull;
use crate::water::morison::{Hydro, HydroError, HydroSpec};
use crate::water::pressure::integrate;
use crate::water::waves::SeaInstant;
use crate::water::waves::WaveComponent;
use std::sync::Arc;

/// A body in the water: its index, hull and coefficients, and its potential flow if it has any.
#[derive(Debug, Clone, PartialEq)]
pub struct FloatingBody {
    body: usize,
    hull: Arc<Hull>,
    hydro: Hydro,
    potential: PotentialFlow,
    /// Its potential flow's linear hydrostatics in a system at rest
    /// ([`crate::system::System::at_rest`]), which has no potential flow but keeps these, so
    /// that a static solve sees the restoring a run feels; `None` everywhere else.
    hydrostatics_at_rest: Option<LinearHydrostatics>,
}

/// A floating body's potential flow (PHYSICS.md §9), if it has panel data.
#[derive(Debug, Clone, PartialEq)]
pub enum PotentialFlow {
    /// No panel data: Morison's coefficients and the hull's pressure alone.
    Absent,
    /// On: the stage applies it.
    On(FloatingPotential),
    /// Switched off by a live edit ([`WaterStage::switch_potential_flow`]), kept with its fitted
    /// model to switch it on again without reading the files; the stage ignores it, so that the
    /// body is then exactly what it would be without potential data.
    SwitchedOff(FloatingPotential),
}

/// A floating body's potential flow (PHYSICS.md §9): its model, the mean horizontal position
/// of its reference point \[m], its excitation and drift (§10) in the water's sea, and its
/// linear hydrostatics when the scene asks for them (absent: the mesh's pressure, as without
/// potential flow).
#[derive(Debug, Clone, PartialEq)]
pub struct FloatingPotential {
    model: Arc<PotentialBody>,
    mean_position: [f64; 2],
    excitation: WaveExcitation,
    drift: WaveDrift,
    linear_hydrostatics: Option<LinearHydrostatics>,
}

impl FloatingPotential {
    /// `model` about the mean horizontal position `mean_position` \[m] of its reference point,
    /// excited by the sea of `components`.
    ///
    /// # Errors
    /// A sea heading the file's excitation or drift lacks.
    pub fn new(
        model: Arc<PotentialBody>,
        mean_position: [f64; 2],
        linear_hydrostatics: Option<LinearHydrostatics>,
        components: &[WaveComponent],
    ) -> Result<Self, HeadingMissing> {
        let mut potential = Self {
            model,
            mean_position,
            excitation: WaveExcitation::default(),
            drift: WaveDrift::default(),
            linear_hydrostatics,
        };
        potential.excite(components)?;
        Ok(potential)
    }

    /// The excitation and the drift built again for the sea of `components`.
    ///
    /// # Errors
    /// A sea heading the file's excitation or drift lacks; the body is then unchanged.
    fn excite(&mut self, components: &[WaveComponent]) -> Result<(), HeadingMissing> {
        let coefficients = self.model.coefficients();
        let excitation = WaveExcitation::new(coefficients.excitation(), components, self.mean_position)?;
        let drift = match coefficients.mean_drift() {
            Some(table) => WaveDrift::new(self.model.drift_model(), table, components, self.mean_position)?,
            None => WaveDrift::default(),
        };
        (self.excitation, self.drift) = (excitation, drift);
        Ok(())
    }

    /// The potential flow with its mean drift loading the body as `drift` (PHYSICS.md §10),
    /// the drift built again for the sea of `components`.
    ///
    /// # Errors
    /// A drift model without the file's drift coefficients, or a sea heading they lack.
    fn with_drift_model(&self, drift: DriftModel, components: &[WaveComponent]) -> Result<Self, SwitchError> {
        let model = Arc::new(self.model.with_drift_model(drift)?);
        let drift = match model.coefficients().mean_drift() {
            Some(table) => WaveDrift::new(drift, table, components, self.mean_position)?,
            None => WaveDrift::default(),
        };
        Ok(Self { model, drift, ..self.clone() })
    }

    /// The model.
    pub fn model(&self) -> &Arc<PotentialBody> {
        &self.model
    }

    /// The mean horizontal position of the reference point \[m].
    pub fn mean_position(&self) -> [f64; 2] {
        self.mean_position
    }

    /// The drift in the water's sea (PHYSICS.md §10).
    pub fn drift(&self) -> &WaveDrift {
        &self.drift
    }

    /// The linear hydrostatics, when the scene asks for them.
    pub fn linear_hydrostatics(&self) -> Option<&LinearHydrostatics> {
        self.linear_hydrostatics.as_ref()
    }
}

/// A body that cannot float, and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FloatingError {
    #[error("its shape as a hull in water: {0}")]
    Hull(#[from] MeshError),
    #[error("hydro: {0}")]
    Hydro(#[from] HydroError),
    #[error("hydro: potential: {0}")]
    Potential(#[from] PotentialError),
    #[error("hydro: potential: {0}")]
    Heading(#[from] HeadingMissing),
}

impl FloatingBody {
    /// Body `index` of `bodies` with coefficients `spec`: its hull from its shape.
    ///
    /// # Errors
    /// A shape that is not a closed hull ([`Hull::new`]), or bad coefficients.
    pub fn new(bodies: &[RigidBody], index: usize, spec: HydroSpec) -> Result<Self, FloatingError> {
        let body = &bodies[index];
        let hull = Hull::of_body(body)?;
        let hydro = Hydro::new(spec, body, &hull)?;
        Ok(Self {
            body: index,
            hull: Arc::new(hull),
            hydro,
            potential: PotentialFlow::Absent,
            hydrostatics_at_rest: None,
        })
    }

    /// The body's index in the system.
    pub fn body(&self) -> usize {
        self.body
    }

    /// Its hull, principal frame.
    pub fn hull(&self) -> &Arc<Hull> {
        &self.hull
    }

    /// Its Morison coefficients, resolved.
    pub fn hydro(&self) -> &Hydro {
        &self.hydro
    }

    /// Its potential flow while on, which the stage applies.
    pub fn potential(&self) -> Option<&FloatingPotential> {
        match &self.potential {
            PotentialFlow::On(potential) => Some(potential),
            PotentialFlow::Absent | PotentialFlow::SwitchedOff(_) => None,
        }
    }

    /// Whether the body has potential-flow data, on or switched off.
    pub fn has_potential_data(&self) -> bool {
        match &self.potential {
            PotentialFlow::On(_) | PotentialFlow::SwitchedOff(_) => true,
            PotentialFlow::Absent => false,
        }
    }

    /// Its potential-flow model, on or switched off.
    pub fn potential_model(&self) -> Option<&Arc<PotentialBody>> {
        match &self.potential {
            PotentialFlow::On(potential) | PotentialFlow::SwitchedOff(potential) => Some(&potential.model),
            PotentialFlow::Absent => None,
        }
    }

    /// Its potential flow's linear hydrostatics in a system at rest, if kept there.
    pub fn hydrostatics_at_rest(&self) -> Option<&LinearHydrostatics> {
        self.hydrostatics_at_rest.as_ref()
    }

    /// Gives the body its potential flow `potential`, on (the system's build, PHYSICS.md §9).
    pub(crate) fn set_potential(&mut self, potential: FloatingPotential) {
        self.potential = PotentialFlow::On(potential);
    }

    /// The body with the coefficients `hydro` (a live edit; checked by [`Hydro::new`]).
    pub(crate) fn set_hydro(&mut self, hydro: Hydro) {
        self.hydro = hydro;
    }

    /// The body as a system at rest has it ([`crate::system::System::at_rest`]): coefficients
    /// `hydro`, no potential flow, but its linear hydrostatics kept, a static restoring.
    pub(crate) fn at_rest(&self, hydro: Hydro) -> Self {
        Self {
            body: self.body,
            hull: Arc::clone(&self.hull),
            hydro,
            potential: PotentialFlow::Absent,
            hydrostatics_at_rest: self.potential().and_then(|p| p.linear_hydrostatics.clone()),
        }
    }
}

/// A floating body whose potential flow cannot be switched, and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SwitchError {
    #[error("body {body} does not float")]
    NotFloating { body: usize },
    #[error("it has no potential-flow data (hydro: Hydro(potential: Wamit(...)))")]
    NoPotentialData,
    #[error("hydro: potential: {0}")]
    Heading(#[from] HeadingMissing),
    #[error("hydro: potential: {0}")]
    Potential(#[from] PotentialError),
}

/// The water and the bodies in it.
#[derive(Debug, Clone, PartialEq)]
pub struct WaterStage {
    pub water: Water,
    pub floating: Vec<FloatingBody>,
}

/// What the water stage works on at one evaluation: the bodies, their kinematics and loads, the
/// records it writes (one per floating body) and its buffers.
pub struct WaterStageInputs<'a> {
    pub bodies: &'a [RigidBody],
    pub frames: &'a [BodyFrame],
    pub loads: &'a mut [Load],
    pub records: &'a mut [WaterForces],
    /// The radiation memory of each floating body (unused without potential flow).
    pub radiation: &'a mut [RadiationRun],
    pub scratch: &'a mut WaterScratch,
}

/// One floating body at an evaluation: its kinematics, its load from every other force and its
/// radiation memory.
struct BodyInputs<'a> {
    body: &'a RigidBody,
    frame: &'a BodyFrame,
    load: &'a Load,
    run: &'a mut RadiationRun,
}

/// The water at an evaluation's time `time` [s]: the ramp `r` (0 to 1) of its waves and
/// current (PHYSICS.md §6), and whether there are waves to sum.
#[derive(Debug, Clone, Copy)]
struct Instant {
    time: f64,
    ramp: f64,
    waves: bool,
}

/// The stage's buffers, kept with the evaluation (sized on first use, then reused).
#[derive(Debug, Clone, Default)]
pub struct WaterScratch {
    /// The sea at the evaluation's time.
    sea: SeaInstant,
    /// Pressure [Pa] and head below the still level `z_w − z` [m] of each hull vertex.
    pressures: Vec<f64>,
    heads: Vec<f64>,
}

impl WaterStage {
    /// The stage with `water` replaced by `spec` (a live edit), under gravity `gravity`.
    ///
    /// # Errors
    /// See [`Water::new`].
    pub fn with_spec(&self, spec: WaterSpec, gravity: &Vec3) -> Result<Self, WaterError> {
        Ok(Self { water: Water::new(spec, gravity)?, floating: self.floating.clone() })
    }

    /// Each potential-flow body's excitation and drift rebuilt for the water's sea (after it
    /// changed).
    ///
    /// # Errors
    /// The index of the first floating body whose file lacks the sea's heading, and why.
    pub fn excite(&mut self) -> Result<(), (usize, HeadingMissing)> {
        let components = self.water.sea().components();
        for floating in &mut self.floating {
            if let PotentialFlow::On(potential) = &mut floating.potential {
                potential.excite(components).map_err(|error| (floating.body, error))?;
            }
        }
        Ok(())
    }

    /// Switches body `body`'s potential flow on or off (a live edit, PHYSICS.md §9); returns its
    /// index among the floating bodies when it switched (its radiation memory is then the
    /// caller's to start afresh), `None` when it already was so. Off, the body is what it would
    /// be without potential data: the incident wave's pressure on its hull and Morison's added
    /// mass back, `A∞` out of its generalised mass. On, the model kept when it was switched off,
    /// its excitation built again for the water's sea as it is now, about the same mean position
    /// as at t = 0.
    ///
    /// # Errors
    /// A body that does not float or has no potential-flow data, or (on) a sea heading the
    /// file lacks; the stage is then unchanged.
    pub fn switch_potential_flow(&mut self, body: usize, on: bool) -> Result<Option<usize>, SwitchError> {
        let components = self.water.sea().components();
        let (index, floating) = self
            .floating
            .iter_mut()
            .enumerate()
            .find(|(_, f)| f.body == body)
            .ok_or(SwitchError::NotFloating { body })?;
        if !floating.has_potential_data() {
            return Err(SwitchError::NoPotentialData);
        }
        match (&mut floating.potential, on) {
            (PotentialFlow::SwitchedOff(potential), true) => {
                potential.excite(components)?;
                floating.potential = PotentialFlow::On(potential.clone());
            }
            (PotentialFlow::On(potential), false) => floating.potential = PotentialFlow::SwitchedOff(potential.clone()),
            (PotentialFlow::On(_), true) | (PotentialFlow::SwitchedOff(_), false) | (PotentialFlow::Absent, _) => {
                return Ok(None);
            }
        }
        Ok(Some(index))
    }

    /// Body `body`'s mean drift loading it as `drift` from now on (a live edit, PHYSICS.md §10),
    /// its potential flow on or switched off (nothing to do when it already does).
    ///
    /// # Errors
    /// A body that does not float or has no potential-flow data, a drift model without the
    /// file's drift coefficients, or a sea heading they lack; the stage is then unchanged.
    pub fn set_drift_model(&mut self, body: usize, drift: DriftModel) -> Result<(), SwitchError> {
        let components = self.water.sea().components();
        let floating = self.floating.iter_mut().find(|f| f.body == body).ok_or(SwitchError::NotFloating { body })?;
        let potential = match &mut floating.potential {
            PotentialFlow::On(potential) | PotentialFlow::SwitchedOff(potential) => potential,
            PotentialFlow::Absent => return Err(SwitchError::NoPotentialData),
        };
        if potential.model.drift_model() != drift {
            *potential = potential.with_drift_model(drift, components)?;
        }
        Ok(())
    }

    /// The floating entry of body `body`, if it floats.
    pub fn floating_body(&self, body: usize) -> Option<&FloatingBody> {
        self.floating.iter().find(|f| f.body == body)
    }

    /// Stage *water* at `time` \[s] and the kinematics `on.frames`: each floating body's water
    /// forces into `on.records` (one per floating body) and added to `on.loads` (which must hold
    /// every other force of the evaluation: the added mass reacts to the total); returns their
    /// power `Σ F·v + M·ω` \[W].
    ///
    /// Built for AVX-512 and AVX2 as well as the portable build, chosen by `level`
    /// ([`SupportedLevel::run`]; the same IEEE arithmetic: the same results, bit for bit): the
    /// four chains of complex powers of the waves' sums run in one vector instruction each.
    pub fn apply(&self, level: SupportedLevel, on: WaterStageInputs<'_>, time: f64) -> f64 {
        level.run(
            #[inline(always)]
            || self.apply_built(on, time),
        )
    }

    #[inline(always)]
    fn apply_built(&self, on: WaterStageInputs<'_>, time: f64) -> f64 {
        let WaterStageInputs { bodies, frames, loads, records, radiation, scratch } = on;
        let water = &self.water;
        let ramp = water.ramp(time);
        let waves = ramp > 0.0 && !water.sea().is_calm();
        if waves {
            water.sea().instant(time, &mut scratch.sea);
        }
        let instant = Instant { time, ramp, waves };
        let mut power = 0.0;
        for ((floating, record), run) in self.floating.iter().zip(records.iter_mut()).zip(radiation.iter_mut()) {
            let (body, frame) = (&bodies[floating.body], &frames[floating.body]);
            // A prescribed motion is not moved by forces: the water does nothing to it.
            if body.is_kinematic() {
                *record = WaterForces { body: floating.body, ..WaterForces::default() };
                continue;
            }
            let on = BodyInputs { body, frame, load: &loads[floating.body], run };
            *record = self.body_forces(floating, on, scratch, &instant);
            let total = record.total();
            loads[floating.body].force += total.force;
            loads[floating.body].moment += total.moment;
            power += record.power;
        }
        power
    }

    /// The water's forces on one body, whose load from every other force is `load`.
    #[inline(always)]
    fn body_forces(
        &self,
        floating: &FloatingBody,
        on: BodyInputs<'_>,
        scratch: &mut WaterScratch,
        instant: &Instant,
    ) -> WaterForces {
        let BodyInputs { body, frame, load, run } = on;
        let Instant { time, ramp, waves } = *instant;
        let water = &self.water;
        let hull = &floating.hull;
        let mut record = WaterForces { body: floating.body, ..WaterForces::default() };
        // No vertex can be wet: above the highest crest the sea can raise.
        let crest = if waves { ramp * water.sea().highest_crest() } else { 0.0 };
        if frame.position.z - hull.bounding_radius() > water.level() + crest {
            return record;
        }
        // With potential flow the incident wave's pressure is in the excitation (PHYSICS.md §9).
        let froude_krylov = waves && floating.potential().is_none();
        self.vertex_pressures(hull, frame, scratch, ramp, froude_krylov);
        let integral = integrate(hull, &scratch.pressures, &scratch.heads);
        let up = frame.rotation.row(2).transpose();
        record.submerged_volume = (-up.dot(&integral.head_flux)).max(0.0);
        record.waterplane_area = (-up.dot(&integral.wet_normal)).max(0.0);
        record.wetted_fraction = (record.submerged_volume / hull.volume()).min(1.0);
        record.pressure = Load { force: frame.rotation * integral.force, moment: frame.rotation * integral.moment };
        let linear = match floating.potential() {
            Some(potential) => potential.linear_hydrostatics(),
            None => floating.hydrostatics_at_rest.as_ref(),
        };
        // Linear hydrostatics replace the mesh's pressure; its wetted part still sets the drag's.
        if let Some(linear) = linear {
            record.pressure = linear.load(frame);
        }
        let hydro = &floating.hydro;
        let (flow, acceleration) = water.flow(&(frame.position + hydro.drag_arm(&frame.rotation)), time);
        if record.wetted_fraction > 0.0 {
            record.drag = hydro.load(frame, &flow, water.density(), record.wetted_fraction);
            if hydro.has_added_mass() && floating.potential().is_none() {
                let added = hydro.added_mass(hull.volume(), water.density(), record.wetted_fraction);
                let before = Load {
                    force: load.force + record.pressure.force + record.drag.force,
                    moment: load.moment + record.pressure.moment + record.drag.moment,
                };
                record.added_mass = added.reaction(body, frame, &before, &acceleration);
            }
        }
        if let Some(potential) = floating.potential() {
            potential_forces(potential, &mut record, BodyInputs { body, frame, load, run }, instant);
        }
        record.power = power(&record.total(), frame);
        record
    }

    /// The still water's pressure over `floating`'s hull at `frame` (about G, world axes \[N,
    /// N·m]): its buoyancy at that pose, what linear hydrostatics start from (§9).
    pub fn still_pressure(&self, floating: &FloatingBody, frame: &BodyFrame) -> Load {
        let mut scratch = WaterScratch::default();
        self.vertex_pressures(&floating.hull, frame, &mut scratch, 0.0, false);
        let integral = integrate(&floating.hull, &scratch.pressures, &scratch.heads);
        Load { force: frame.rotation * integral.force, moment: frame.rotation * integral.moment }
    }

    /// Stage *pressure* of one body: `p = ρ g (z_w − z + r Σ a K_p cos θ)` at each hull vertex,
    /// once per vertex, and its head `z_w − z`, into the scratch buffers.
    #[inline(always)]
    fn vertex_pressures(&self, hull: &Hull, frame: &BodyFrame, scratch: &mut WaterScratch, ramp: f64, waves: bool) {
        let water = &self.water;
        let (level, rho_g) = (water.level(), water.specific_weight());
        let count = hull.vertices().len();
        scratch.pressures.resize(count, 0.0);
        scratch.heads.resize(count, 0.0);
        let each = hull.vertices().iter().zip(scratch.pressures.iter_mut()).zip(scratch.heads.iter_mut());
        for ((vertex, pressure), head) in each {
            let x = frame.position + frame.rotation * vertex;
            *head = level - x.z;
            let dynamic = if waves { ramp * water.sea().pressure_head(&scratch.sea, x.x, x.y, x.z) } else { 0.0 };
            *pressure = rho_g * (*head + dynamic);
        }
    }
}

/// A potential-flow body's radiation force, excitation (ramped with the waves), drift (ramped
/// with the square of the waves' ramp, §10) and `A∞` reaction (PHYSICS.md §9) into `record`, which holds its pressure and drag already.
#[inline(always)]
fn potential_forces(potential: &FloatingPotential, record: &mut WaterForces, on: BodyInputs<'_>, instant: &Instant) {
    let BodyInputs { body, frame, load, run } = on;
    let model = &potential.model;
    let radiation = run.force(model.radiation(), instant.time, &model.velocity(frame));
    record.radiation = model.at_center(frame, &radiation);
    if instant.waves {
        record.excitation = model.at_center(frame, &(potential.excitation.force(instant.time) * instant.ramp));
        if !potential.drift.is_zero() {
            let drift = potential.drift.force(instant.time) * instant.ramp.powi(2);
            record.drift = model.at_center(frame, &drift);
        }
    }
    let others = record.total();
    let before = Load { force: load.force + others.force, moment: load.moment + others.moment };
    record.added_mass = model.reaction(body, frame, &before);
}

/// `F·v + M·ω` \[W] of `load` on a body moving as `frame`.
#[inline(always)]
pub fn power(load: &Load, frame: &BodyFrame) -> f64 {
    load.force.dot(&frame.velocity) + load.moment.dot(&(frame.rotation * frame.angular_velocity))
}
