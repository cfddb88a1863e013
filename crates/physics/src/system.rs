//! The system: what a scene declares and a run does not change — gravity, the bodies, the
//! couplings, what surrounds them (the fluid the lines weigh in, the seabed) and the bodies'
//! states at t = 0 (the start of prescribed motions) — and the force evaluation for given
//! states (MuJoCo's constant model beside its mutable data).
//!
//! An evaluation runs these stages, each its own function, in this order:
//! 1. *prescribe*: kinematic bodies are put where their motion says at the time
//!    ([`System::prescribe`]);
//! 2. *predict*: each body's kinematics for the force evaluation ([`BodyState::frame`]);
//! 3. *clear* the loads and add *gravity* ([`System::gravity_load`]);
//! 4. *couplings*: each coupling's forces, kept per coupling and summed into the bodies' loads
//!    ([`System::apply_couplings`]);
//! 5. *air*, an environment stage declared by the scene ([`System::with_air`]) and skipped when
//!    it declares none: the wind's drag and a rotor's thrust on each body they load, kept per
//!    body and summed into the loads ([`System::apply_air`], [`crate::air`], PHYSICS.md §10);
//! 6. *water*, the other environment stage ([`System::with_water`]), last because its added
//!    mass reacts to every other force: pressure, Morison loads, potential flow and added mass
//!    on each floating body, kept per body and summed into the loads ([`System::apply_water`],
//!    [`crate::water`]);
//! 7. *powers*: dissipated by the couplings, put in by prescribed motions and by the
//!    environment ([`System::external_power`]).
//!
//! [`System::evaluate`] runs 2–7 (5 and 6 as [`System::apply_environment`]); the leapfrog fuses
//! 1–3 into its pass over the bodies.

use crate::air::stage::AirStageInputs;
use crate::air::{AirError, AirForces, AirSpec, AirStage, AirStageError, WindLoadError, WindLoadSpec};
use crate::body::{BodyState, Load, RigidBody, Support};
use crate::coupling::catenary::ON_SEABED;
use crate::coupling::lumped_line::Discrete;
use crate::coupling::{Coupling, CouplingError, CouplingForces, CouplingKind, Endpoint, LineModel};
use crate::energy::{CouplingPower, Powers};
use crate::evaluation::Evaluation;
use crate::math::Vec3;
use crate::parameter::ParameterError;
use crate::potential::{
    DriftModel, HydrostaticsModel, LinearHydrostatics, PotentialBody, PotentialError, PotentialSpec,
};
use crate::seabed::Seabed;
use crate::simd::{Level, SupportedLevel};
use crate::surroundings::Surroundings;
use crate::water::WaterSpec;
use crate::water::environment::WaterError;
use crate::water::morison::HydroSpec;
use crate::water_stage::{FloatingBody, FloatingError, FloatingPotential, SwitchError, WaterStage, WaterStageInputs};

/// Bodies, couplings and gravity: what a run does not change (live edits aside).
#[derive(Debug, Clone)]
pub struct System {
    /// Gravity [m/s²], the fluid the lines weigh in (the water's density), the seabed.
    surroundings: Surroundings,
    bodies: Vec<RigidBody>,
    couplings: Vec<Coupling>,
    /// States at t = 0: the start of prescribed motions, and of a reset.
    initial_states: Vec<BodyState>,
    /// Indices of the kinematic bodies.
    kinematic_bodies: Vec<usize>,
    /// The build of the hot stages (couplings, water, the leapfrog step) this processor runs.
    level: SupportedLevel,
    /// The water and the bodies in it, if the scene has water.
    water: Option<WaterStage>,
    /// The air and the bodies it loads, if the scene has air.
    air: Option<AirStage>,
}

/// A system that does not hold together.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SystemError {
    #[error("{bodies} bodies but {states} initial states")]
    StateCount { bodies: usize, states: usize },
    #[error("coupling \"{coupling}\" refers to body {body}, but the system has {count} bodies")]
    UnknownBody { coupling: String, body: usize, count: usize },
    #[error("floating body {body} of {count} does not exist or floats twice")]
    FloatingBody { body: usize, count: usize },
    #[error("wind-loaded body {body} does not exist: the system has {count} bodies")]
    UnknownWindBody { body: usize, count: usize },
    #[error(transparent)]
    Water(#[from] WaterError),
    #[error("body \"{body}\": {source}")]
    Hydro { body: String, source: FloatingError },
    #[error("the system has no water")]
    NoWater,
    #[error("body \"{body}\": potential flow cannot be switched: {source}")]
    Switch { body: String, source: SwitchError },
    #[error("body \"{body}\": its drift model cannot be changed: {source}")]
    Drift { body: String, source: SwitchError },
    #[error("the system has no air")]
    NoAir,
    #[error("coupling \"{coupling}\": {source}")]
    BelowSeabed { coupling: String, source: BelowSeabed },
    #[error("air: {0}")]
    Air(AirError),
    #[error("body \"{body}\": {source}")]
    Wind { body: String, source: WindLoadError },
    /// A line whose weight or dynamic constants, derived in its surroundings, are out of range
    /// ([`crate::coupling::Catenary::check_weight`], [`Discrete::check`]).
    #[error("coupling \"{coupling}\": {source}")]
    Line { coupling: String, source: ParameterError },
}

/// A catenary end fixed in the world below the seabed.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("end {end} is {depth} m below the seabed (z_b = {elevation} m): an anchor lies on the seabed or above it")]
pub struct BelowSeabed {
    /// 1 or 2.
    pub end: usize,
    /// How far below \[m].
    pub depth: f64,
    /// The seabed's `z_b` \[m].
    pub elevation: f64,
}

/// A coupling that could not give its forces: its index, and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EvaluationError {
    pub coupling: usize,
    pub source: CouplingError,
}

impl System {
    /// A system of `bodies` starting from `initial_states` (synchronised: velocities at t = 0),
    /// joined by `couplings`, under `gravity` [m/s²].
    ///
    /// # Errors
    /// As many states as bodies are needed, and every coupling's bodies must exist.
    pub fn new(
        gravity: Vec3,
        bodies: Vec<RigidBody>,
        couplings: Vec<Coupling>,
        initial_states: Vec<BodyState>,
    ) -> Result<Self, SystemError> {
        if bodies.len() != initial_states.len() {
            return Err(SystemError::StateCount { bodies: bodies.len(), states: initial_states.len() });
        }
        for coupling in &couplings {
            check_bodies(coupling, bodies.len())?;
        }
        let surroundings = Surroundings::dry(gravity);
        check_lines(&couplings, &surroundings, None)?;
        let kinematic_bodies = (0..bodies.len()).filter(|&i| bodies[i].is_kinematic()).collect();
        Ok(Self {
            surroundings,
            bodies,
            couplings,
            initial_states,
            kinematic_bodies,
            level: SupportedLevel::best(),
            water: None,
            air: None,
        })
    }

    /// The system with its lines lying on `seabed` where they reach it (PHYSICS.md §7).
    ///
    /// # Errors
    /// A catenary with an end fixed in the world below the seabed, named with the depth; a
    /// dynamic line whose constants on the seabed are out of range.
    pub fn with_seabed(mut self, seabed: Seabed) -> Result<Self, SystemError> {
        check_anchors(&self.couplings, &seabed, &self.surroundings.gravity)?;
        let surroundings = Surroundings { seabed: Some(seabed), ..self.surroundings };
        check_lines(&self.couplings, &surroundings, self.water_level())?;
        self.surroundings = surroundings;
        Ok(self)
    }

    /// The system in `water`, with the bodies `floating` in it: each a body index and its
    /// coefficients (PHYSICS.md §6). Without this the system has no water stage at all.
    ///
    /// # Errors
    /// Water that cannot be (bad values, a breaking wave, gravity not along −z), an unknown or
    /// repeated body, a body whose shape is not a closed outward hull or whose coefficients are
    /// bad, a line whose weight or constants in the water are out of range.
    pub fn with_water(mut self, water: WaterSpec, floating: Vec<(usize, HydroSpec)>) -> Result<Self, SystemError> {
        let water = crate::water::Water::new(water, &self.surroundings.gravity)?;
        let count = self.bodies.len();
        let mut bodies = Vec::with_capacity(floating.len());
        for (index, (body, spec)) in floating.iter().enumerate() {
            if *body >= count || floating[..index].iter().any(|(b, _)| b == body) {
                return Err(SystemError::FloatingBody { body: *body, count });
            }
            bodies.push(
                FloatingBody::new(&self.bodies, *body, *spec)
                    .map_err(|source| SystemError::Hydro { body: self.bodies[*body].name.clone(), source })?,
            );
        }
        // The lines weigh in the same water: `(λ0 − ρ A_d) g` (PHYSICS.md §7).
        let surroundings = Surroundings { fluid_density: water.density(), ..self.surroundings };
        check_lines(&self.couplings, &surroundings, Some(water.level()))?;
        self.surroundings = surroundings;
        self.water = Some(WaterStage { water, floating: bodies });
        Ok(self)
    }

    /// The system with body `body`, floating in its water, under potential flow (PHYSICS.md §9):
    /// its model built from `spec` and its excitation in the water's sea, about its reference
    /// point's position at t = 0.
    ///
    /// # Errors
    /// No water, a body that does not float, a kernel that cannot be sampled or fitted, a sea
    /// heading the file lacks.
    pub fn with_potential_flow(mut self, body: usize, spec: PotentialSpec) -> Result<Self, SystemError> {
        let count = self.bodies.len();
        let name = self.bodies.get(body).map(|b| b.name.clone()).unwrap_or_default();
        let hydro = |source: FloatingError| SystemError::Hydro { body: name.clone(), source };
        let stage = self.water.as_mut().ok_or(SystemError::NoWater)?;
        let position =
            stage.floating.iter().position(|f| f.body() == body).ok_or(SystemError::FloatingBody { body, count })?;
        crate::potential::body::check_start_axes(&self.bodies[body], &self.initial_states[body].orientation)
            .map_err(|e| hydro(e.into()))?;
        let hydrostatics = spec.hydrostatics;
        let model = PotentialBody::new(spec, &self.bodies[body]).map_err(|e| hydro(e.into()))?;
        let frame = self.initial_states[body].frame();
        let arm = model.arm(&frame);
        let reference = frame.position + arm;
        let mean_position = [reference.x, reference.y];
        let linear_hydrostatics = match hydrostatics {
            HydrostaticsModel::Mesh => None,
            HydrostaticsModel::Linear => {
                let stiffness = *model
                    .coefficients()
                    .hydrostatic_stiffness()
                    .ok_or_else(|| hydro(PotentialError::NoHydrostaticStiffness.into()))?;
                let pressure = stage.still_pressure(&stage.floating[position], &frame);
                Some(LinearHydrostatics::new(stiffness, &frame, &arm, &pressure))
            }
        };
        let components = stage.water.sea().components();
        let potential =
            FloatingPotential::new(std::sync::Arc::new(model), mean_position, linear_hydrostatics, components)
                .map_err(|e| hydro(e.into()))?;
        stage.floating[position].set_potential(potential);
        Ok(self)
    }

    /// The system in the air of `spec`, loading each `(body, spec)` of `loads` (PHYSICS.md §10):
    /// heights from the still water level (0 without water: give the system its water first),
    /// the load points' exposure from the bodies' poses at t = 0.
    ///
    /// # Errors
    /// Air that is bad, or a body whose windage or rotor is.
    pub fn with_air(mut self, spec: AirSpec, loads: Vec<(usize, WindLoadSpec)>) -> Result<Self, SystemError> {
        self.air = Some(self.air_stage(spec, loads)?);
        Ok(self)
    }

    /// Replaces the air and its loads (a live edit: the world restarts its integrator after it),
    /// built as [`System::with_air`] builds them: exposures from the poses at t = 0.
    pub(crate) fn replace_air(&mut self, spec: AirSpec, loads: Vec<(usize, WindLoadSpec)>) -> Result<(), SystemError> {
        if self.air.is_none() {
            return Err(SystemError::NoAir);
        }
        self.air = Some(self.air_stage(spec, loads)?);
        Ok(())
    }

    /// The air stage of `spec` loading `loads`, heights from the still water level (or 0), the
    /// load points' exposure from the bodies' poses at t = 0.
    fn air_stage(&self, spec: AirSpec, loads: Vec<(usize, WindLoadSpec)>) -> Result<AirStage, SystemError> {
        let count = self.bodies.len();
        if let Some(&(body, _)) = loads.iter().find(|(body, _)| *body >= count) {
            return Err(SystemError::UnknownWindBody { body, count });
        }
        let frames: Vec<_> = self.initial_states.iter().map(BodyState::frame).collect();
        let level = self.water_level().unwrap_or(0.0);
        AirStage::new(spec, loads, &self.bodies, &frames, level).map_err(|error| match error {
            AirStageError::Air(air) => SystemError::Air(air),
            AirStageError::Body { index, source } => {
                SystemError::Wind { body: self.bodies[index].name.clone(), source }
            }
        })
    }

    /// The water stage, if the system has water.
    pub fn water(&self) -> Option<&WaterStage> {
        self.water.as_ref()
    }

    /// The air stage, if the system has air.
    pub fn air(&self) -> Option<&AirStage> {
        self.air.as_ref()
    }

    /// The system as a static solve sees it ([`crate::statics`]): nothing moves, so the water has
    /// no waves and no added mass, and its current flows at full strength from t = 0 (no ramp);
    /// a dynamic line is its quasi-static catenary (the limit of its discrete equilibrium as N
    /// grows, PHYSICS.md §8); hydrostatics, the current's drag and everything else as they are.
    /// Borrowed unchanged without water or dynamic lines.
    pub fn at_rest(&self) -> std::borrow::Cow<'_, System> {
        let dynamic =
            |c: &Coupling| matches!(&c.kind, CouplingKind::Catenary(line) if line.model() != LineModel::QuasiStatic);
        if self.water.is_none() && self.air.is_none() && !self.couplings.iter().any(dynamic) {
            return std::borrow::Cow::Borrowed(self);
        }
        let couplings = self
            .couplings
            .iter()
            .map(|coupling| match &coupling.kind {
                CouplingKind::Catenary(line) => Coupling {
                    kind: CouplingKind::Catenary(line.clone().with_model(LineModel::QuasiStatic)),
                    ..coupling.clone()
                },
                CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => coupling.clone(),
            })
            .collect();
        let water = self.water.as_ref().map(|stage| self.still(stage));
        let air = self.air.as_ref().map(AirStage::at_rest);
        std::borrow::Cow::Owned(Self { water, air, couplings, ..self.clone() })
    }

    /// `stage` as [`System::at_rest`] has it: no waves, no added mass, no ramp.
    fn still(&self, stage: &WaterStage) -> WaterStage {
        let spec = WaterSpec { waves: crate::water::WaveSpec::Calm, ramp: Some(0.0), ..*stage.water.spec() };
        // Still water with a ramp of 0 s passes every check the accepted water passed.
        let water =
            crate::water::Water::new(spec, &self.surroundings.gravity).expect("still water from accepted water");
        let floating = stage
            .floating
            .iter()
            .map(|entry| {
                let spec =
                    HydroSpec { added_mass: Vec3::zeros(), added_inertia: Vec3::zeros(), ..*entry.hydro().spec() };
                // Accepted coefficients with the added mass zeroed stay in range.
                let hydro = crate::water::Hydro::new(spec, &self.bodies[entry.body()], entry.hull())
                    .expect("accepted coefficients without added mass");
                // At rest nothing radiates and nothing accelerates: no potential flow, but its
                // linear hydrostatics, a static restoring, kept.
                entry.at_rest(hydro)
            })
            .collect();
        WaterStage { water, floating }
    }

    /// Replaces the water's spec (a live edit: the world restarts its integrator after it).
    pub(crate) fn replace_water(&mut self, spec: WaterSpec) -> Result<(), SystemError> {
        let mut stage = self.water.as_ref().ok_or(SystemError::NoWater)?.with_spec(spec, &self.surroundings.gravity)?;
        stage.excite().map_err(|(body, source)| SystemError::Hydro {
            body: self.bodies[body].name.clone(),
            source: FloatingError::Heading(source),
        })?;
        // The seabed stays at the water's depth (PHYSICS.md §7).
        let seabed = match (&self.surroundings.seabed, stage.water.seabed()) {
            (Some(seabed), Some(elevation)) => Some(seabed.at_water_bottom(elevation)),
            (seabed, _) => *seabed,
        };
        if let Some(seabed) = &seabed {
            check_anchors(&self.couplings, seabed, &self.surroundings.gravity)?;
        }
        let surroundings = Surroundings { seabed, fluid_density: stage.water.density(), ..self.surroundings };
        check_lines(&self.couplings, &surroundings, Some(stage.water.level()))?;
        self.surroundings = surroundings;
        self.water = Some(stage);
        Ok(())
    }

    /// Replaces the coefficients of floating body `body` (a live edit, as above).
    pub(crate) fn replace_hydro(&mut self, body: usize, spec: HydroSpec) -> Result<(), SystemError> {
        let count = self.bodies.len();
        let stage = self.water.as_mut().ok_or(SystemError::NoWater)?;
        let entry =
            stage.floating.iter_mut().find(|f| f.body() == body).ok_or(SystemError::FloatingBody { body, count })?;
        let hydro = crate::water::Hydro::new(spec, &self.bodies[body], entry.hull()).map_err(|e| {
            SystemError::Hydro { body: self.bodies[body].name.clone(), source: FloatingError::Hydro(e) }
        })?;
        entry.set_hydro(hydro);
        Ok(())
    }

    /// Switches body `body`'s potential flow on or off (a live edit, as above:
    /// [`WaterStage::switch_potential_flow`]); returns its index among the floating bodies when
    /// it switched.
    pub(crate) fn switch_potential_flow(&mut self, body: usize, on: bool) -> Result<Option<usize>, SystemError> {
        let stage = self.water.as_mut().ok_or(SystemError::NoWater)?;
        stage.switch_potential_flow(body, on).map_err(|source| SystemError::Switch {
            body: self.bodies.get(body).map(|b| b.name.clone()).unwrap_or_default(),
            source,
        })
    }

    /// Body `body`'s mean drift loading it as `drift` from now on (a live edit, as above:
    /// [`WaterStage::set_drift_model`]).
    pub(crate) fn set_drift_model(&mut self, body: usize, drift: DriftModel) -> Result<(), SystemError> {
        let stage = self.water.as_mut().ok_or(SystemError::NoWater)?;
        stage.set_drift_model(body, drift).map_err(|source| SystemError::Drift {
            body: self.bodies.get(body).map(|b| b.name.clone()).unwrap_or_default(),
            source,
        })
    }

    /// Gravity [m/s²].
    pub fn gravity(&self) -> &Vec3 {
        &self.surroundings.gravity
    }

    /// Gravity, the fluid the lines weigh in, the seabed.
    pub fn surroundings(&self) -> &Surroundings {
        &self.surroundings
    }

    /// The seabed, if the system has one.
    pub fn seabed(&self) -> Option<&Seabed> {
        self.surroundings.seabed.as_ref()
    }

    /// Replaces the seabed (a live edit: the world restarts its integrator after it).
    pub(crate) fn replace_seabed(&mut self, seabed: Seabed) -> Result<(), SystemError> {
        check_anchors(&self.couplings, &seabed, &self.surroundings.gravity)?;
        let surroundings = Surroundings { seabed: Some(seabed), ..self.surroundings };
        check_lines(&self.couplings, &surroundings, self.water_level())?;
        self.surroundings = surroundings;
        Ok(())
    }

    /// The still water surface's height \[m], if the system has water.
    fn water_level(&self) -> Option<f64> {
        self.water.as_ref().map(|stage| stage.water.level())
    }

    pub fn bodies(&self) -> &[RigidBody] {
        &self.bodies
    }

    pub fn couplings(&self) -> &[Coupling] {
        &self.couplings
    }

    /// The states at t = 0.
    pub fn initial_states(&self) -> &[BodyState] {
        &self.initial_states
    }

    /// Replaces coupling `index` (a live edit: the world restarts its integrator after it).
    pub(crate) fn replace_coupling(&mut self, index: usize, coupling: Coupling) -> Result<Coupling, SystemError> {
        check_bodies(&coupling, self.bodies.len())?;
        if let Some(seabed) = &self.surroundings.seabed {
            check_anchors(std::slice::from_ref(&coupling), seabed, &self.surroundings.gravity)?;
        }
        check_lines(std::slice::from_ref(&coupling), &self.surroundings, self.water_level())?;
        Ok(std::mem::replace(&mut self.couplings[index], coupling))
    }

    /// The build of the hot stages this system runs.
    pub fn level(&self) -> Level {
        self.level.level()
    }

    /// The same build, as the dispatch of [`SupportedLevel::run`] takes it.
    pub(crate) fn supported_level(&self) -> SupportedLevel {
        self.level
    }

    /// Runs the hot stages built for `level` from now on, if the processor has it (tests
    /// compare the builds); returns whether it does.
    pub fn use_level(&mut self, level: Level) -> bool {
        let Some(supported) = SupportedLevel::new(level) else { return false };
        self.level = supported;
        true
    }

    /// Stage *prescribe*: kinematic bodies to their pose and velocity at time `time` \[s].
    pub fn prescribe(&self, states: &mut [BodyState], time: f64) {
        for &index in &self.kinematic_bodies {
            if let Support::Kinematic(motion) = &self.bodies[index].support {
                states[index] = motion.state_at(&self.initial_states[index], time);
            }
        }
    }

    /// Stages *predict*, *clear*, *gravity*, *couplings*, *water* and *powers* at the
    /// (prescribed) `states` and time `time` \[s], into `evaluation`.
    ///
    /// # Errors
    /// A coupling that cannot give its forces (only non-finite states make one).
    pub fn evaluate(
        &self,
        states: &[BodyState],
        evaluation: &mut Evaluation,
        time: f64,
    ) -> Result<Powers, EvaluationError> {
        for (frame, state) in evaluation.frames.iter_mut().zip(states) {
            *frame = state.frame();
        }
        for (load, body) in evaluation.loads.iter_mut().zip(&self.bodies) {
            *load = self.gravity_load(body);
        }
        self.apply_lines(evaluation, time)?;
        let couplings = self.apply_couplings(evaluation)?;
        let environment = self.apply_environment(evaluation, time);
        Ok(Powers { couplings, external: self.external_power(evaluation), environment })
    }

    /// Stages *clear* and *gravity* for one body: `F = m g`, `M = 0` (nothing for a kinematic
    /// body, which forces do not move).
    #[inline(always)]
    pub fn gravity_load(&self, body: &RigidBody) -> Load {
        if body.is_kinematic() {
            Load::default()
        } else {
            Load { force: self.surroundings.gravity * body.mass(), moment: Vec3::zeros() }
        }
    }

    /// Stage *lines* at time `time` \[s] and the kinematics `evaluation.frames`: each dynamic
    /// line stepped from its last accepted state to `time`, its end forces added to the loads
    /// and its record written for the couplings stage to sum (PHYSICS.md §8).
    ///
    /// # Errors
    /// The first line whose nodes stopped being finite.
    #[inline]
    pub fn apply_lines(&self, evaluation: &mut Evaluation, time: f64) -> Result<(), EvaluationError> {
        if evaluation.lines.is_empty() {
            return Ok(());
        }
        self.step_lines(evaluation, time)
    }

    /// [`System::apply_lines`] for a scene that has dynamic lines.
    #[inline(never)]
    fn step_lines(&self, evaluation: &mut Evaluation, time: f64) -> Result<(), EvaluationError> {
        let Evaluation { frames, loads, forces, lines, .. } = evaluation;
        let water = self.water.as_ref().map(|stage| &stage.water);
        for run in lines.iter_mut() {
            let index = run.coupling;
            let CouplingKind::Catenary(line) = &self.couplings[index].kind else { continue };
            let LineModel::Dynamic(parameters) = &line.model() else { continue };
            let discrete = Discrete::new(line, parameters, &self.surroundings, water.map(|w| w.level()));
            let ends = [line.end1().motion(frames), line.end2().motion(frames)];
            let outcome = run
                .advance(line, &discrete, &self.surroundings, water, &ends, time)
                .map_err(|source| EvaluationError { coupling: index, source: CouplingError::Line(source) })?;
            ends[0].apply(&outcome.f1, loads);
            ends[1].apply(&outcome.f2, loads);
            forces[index] = CouplingForces {
                point1: ends[0].position,
                point2: ends[1].position,
                f1: outcome.f1,
                f2: outcome.f2,
                tension: outcome.f1.norm().max(outcome.f2.norm()),
                dissipated_power: outcome.dissipated_power,
                held_power: 0.0,
                potential: outcome.energy,
            };
        }
        Ok(())
    }

    /// Stage *couplings* at the kinematics `evaluation.frames`: each coupling's forces, kept per
    /// coupling and added to the loads; returns the power they dissipate and hold \[W].
    ///
    /// # Errors
    /// The first coupling that cannot give its forces.
    pub fn apply_couplings(&self, evaluation: &mut Evaluation) -> Result<CouplingPower, EvaluationError> {
        let Evaluation { frames, loads, forces, caches, elastic, .. } = evaluation;
        let stage = CouplingsStage {
            couplings: &self.couplings,
            surroundings: &self.surroundings,
            frames,
            caches,
            forces,
            loads,
        };
        let (power, potential) = self
            .level
            .run(
                #[inline(always)]
                || stage.run(),
            )
            .map_err(|(coupling, source)| EvaluationError { coupling, source })?;
        *elastic = potential;
        Ok(power)
    }

    /// Stages *air* and *water* at time `time` \[s], in that order; returns their power \[W].
    #[inline]
    pub fn apply_environment(&self, evaluation: &mut Evaluation, time: f64) -> f64 {
        self.apply_air(evaluation, time) + self.apply_water(evaluation, time)
    }

    /// Stage *air* at time `time` \[s]: each wind-loaded body's windage and rotor thrust, kept
    /// per body and added to the loads; returns their power \[W], external work. Nothing without
    /// air.
    #[inline]
    pub fn apply_air(&self, evaluation: &mut Evaluation, time: f64) -> f64 {
        let Some(stage) = &self.air else { return 0.0 };
        let Evaluation { frames, loads, air, .. } = evaluation;
        air.resize(stage.bodies().len(), AirForces::default());
        stage.apply(AirStageInputs { bodies: &self.bodies, frames, loads, records: air }, time)
    }

    /// Stage *water* at time `time` \[s] (after the couplings and the air: the added mass reacts
    /// to every other force): each floating body's water forces, kept per body and added to the loads;
    /// returns their power `Σ F·v + M·ω` \[W], external work. Nothing without water.
    #[inline]
    pub fn apply_water(&self, evaluation: &mut Evaluation, time: f64) -> f64 {
        let Some(stage) = &self.water else { return 0.0 };
        let Evaluation { frames, loads, water, radiation, water_scratch, .. } = evaluation;
        if water.len() != stage.floating.len() {
            water.resize(stage.floating.len(), crate::water::WaterForces::default());
            radiation.resize(stage.floating.len(), crate::potential::RadiationRun::default());
        }
        let on =
            WaterStageInputs { bodies: &self.bodies, frames, loads, records: water, radiation, scratch: water_scratch };
        stage.apply(self.level, on, time)
    }

    /// `Σ F·v + M·ω` \[W] of the water's and the air's forces still in `evaluation` (those of
    /// the previous evaluation) at the kinematics now in its frames: the left end of the
    /// staggered schemes' environment work (see [`crate::integrator::leapfrog`]).
    pub fn environment_power(&self, evaluation: &Evaluation) -> f64 {
        let power = crate::water_stage::power;
        let frames = &evaluation.frames;
        let water: f64 = match self.water {
            None => 0.0,
            Some(_) => evaluation.water.iter().map(|record| power(&record.total(), &frames[record.body])).sum(),
        };
        let air: f64 = match self.air {
            None => 0.0,
            Some(_) => evaluation.air.iter().map(|record| power(&record.total(), &frames[record.body])).sum(),
        };
        water + air
    }

    /// Stage *powers*: what the prescribed motions put in, `−Σ (F_k·v_k + M_k·ω_k)` \[W] (of
    /// the loads on them less the water's, whose power [`System::apply_water`] gives).
    pub fn external_power(&self, evaluation: &Evaluation) -> f64 {
        self.kinematic_bodies
            .iter()
            .map(|&i| {
                let (load, frame) = (&evaluation.loads[i], &evaluation.frames[i]);
                -(load.force.dot(&frame.velocity) + load.moment.dot(&(frame.rotation * frame.angular_velocity)))
            })
            .sum()
    }
}

/// Every body coupling `coupling` refers to (its [`Coupling::ends`], a contact's opposing body
/// among them) must be one of the `count` bodies.
fn check_bodies(coupling: &Coupling, count: usize) -> Result<(), SystemError> {
    match coupling.ends().iter().filter_map(|end| end.body()).find(|&body| body >= count) {
        Some(body) => Err(SystemError::UnknownBody { coupling: coupling.name.clone(), body, count }),
        None => Ok(()),
    }
}

/// Every catenary end fixed in the world must lie on `seabed` or above it (within
/// [`ON_SEABED`] of the line's length), heights along `−ĝ`.
fn check_anchors(couplings: &[Coupling], seabed: &Seabed, gravity: &Vec3) -> Result<(), SystemError> {
    let up = -gravity.try_normalize(0.0).unwrap_or_else(|| -Vec3::z());
    for coupling in couplings {
        let line = match &coupling.kind {
            CouplingKind::Catenary(line) => line,
            // Only a line lies on the seabed; a spring's world end may be anywhere, and a
            // contact against the seabed is made for it.
            CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => continue,
        };
        for (end, endpoint) in [(1, &line.end1()), (2, &line.end2())] {
            let Endpoint::World(point) = endpoint else { continue };
            let height = seabed.height(point, &up);
            if height < -ON_SEABED * line.length() {
                let source = BelowSeabed { end, depth: -height, elevation: seabed.elevation() };
                return Err(SystemError::BelowSeabed { coupling: coupling.name.clone(), source });
            }
        }
    }
    Ok(())
}

/// Every line's weight in `surroundings` ([`crate::coupling::Catenary::check_weight`]) and, for a dynamic one,
/// its constants there with the still water surface at `water_level` ([`Discrete::check`]): what
/// is derived from values each checked alone, checked where the line meets its surroundings.
fn check_lines(
    couplings: &[Coupling],
    surroundings: &Surroundings,
    water_level: Option<f64>,
) -> Result<(), SystemError> {
    for coupling in couplings {
        let line = match &coupling.kind {
            CouplingKind::Catenary(line) => line,
            // A spring's and a contact's values are checked whole by their constructors.
            CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => continue,
        };
        let refused = |source| SystemError::Line { coupling: coupling.name.clone(), source };
        line.check_weight(surroundings).map_err(refused)?;
        match &line.model() {
            LineModel::Dynamic(parameters) => {
                Discrete::new(line, parameters, surroundings, water_level).check(line).map_err(refused)?;
            }
            LineModel::QuasiStatic => {}
        }
    }
    Ok(())
}

/// The couplings stage's arguments, borrowed apart from the system and the evaluation.
struct CouplingsStage<'a> {
    couplings: &'a [Coupling],
    surroundings: &'a Surroundings,
    frames: &'a [crate::body::BodyFrame],
    caches: &'a mut [crate::coupling::CouplingCache],
    forces: &'a mut [crate::coupling::CouplingForces],
    loads: &'a mut [Load],
}

impl CouplingsStage<'_> {
    /// Each coupling in turn; returns the power the couplings dissipate and hold [W] and their
    /// elastic energy [J] (the sums of their records' `dissipated_power`, `held_power` and
    /// `potential`), or the index of the one that failed.
    ///
    /// Built for AVX-512 and AVX2 as well as the portable build ([`SupportedLevel::run`]): the
    /// couplings' forces are inlined here, so the contact faces run four to a vector instruction
    /// ([`crate::coupling::contact`]) and what each coupling computes stays in registers from one
    /// stage of its evaluation to the next. AVX-512's 32 vector registers hold the face batch's
    /// constants and sums that AVX2's 16 cannot (docs/speed.md, "The contact batch").
    #[inline(always)]
    fn run(self) -> Result<(CouplingPower, f64), (usize, CouplingError)> {
        let (mut power, mut potential) = (CouplingPower::default(), 0.0);
        let each = self.couplings.iter().zip(self.caches.iter_mut()).zip(self.forces.iter_mut());
        for (index, ((coupling, cache), out)) in each.enumerate() {
            coupling.apply(cache, self.frames, self.surroundings, self.loads, out).map_err(|source| (index, source))?;
            power.dissipated += out.dissipated_power;
            power.held += out.held_power;
            potential += out.potential;
        }
        Ok((power, potential))
    }
}
