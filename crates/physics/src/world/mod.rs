//! The world: a [`System`] running in time. It owns the system, the bodies' states, the
//! integrator with its scratch, the buffers of the force evaluation, the clock, the energy
//! ledger, the health check and the live edits.
//!
//! [`World::step`] advances `dt` in `substeps` integrator steps, each followed by the *health*
//! check ([`health`]; for the adaptive `dopri45`, each accepted step). An integrator step runs the
//! system's stages ([`crate::system`]: prescribe, predict, clear + gravity, couplings, powers)
//! once or, for the Runge–Kutta schemes, once per stage, and then its own *accelerations*; the
//! world then books the step's work in the *ledger* and moves the *clock*.
//! Live edits ([`edits`]) change a coupling or the time step at the current time.

pub mod edits;
pub mod error;
pub mod health;

use crate::body::{BodyFrame, BodyState, Load, RigidBody};
use crate::coupling::catenary::LineState;
use crate::coupling::{Coupling, CouplingForces};
use crate::energy::{BodyEnergy, EnergyLedger, EnergyReport};
use crate::evaluation::Evaluation;
use crate::integrator::{
    Integrator, MAX_AUTO_SUBSTEPS, Scheme, StepContext, StepFailure, StepReport, Substeps, Timing, Tolerances,
};
use crate::math::Vec3;
use crate::stability::{self, Limit, Situation};
use crate::system::{EvaluationError, System};
pub use error::{EditError, StepError};
use health::Health;

/// `substeps: Auto` keeps each integrator step under this fraction of the stable time step.
const AUTO_SUBSTEP_MARGIN: f64 = 0.9;

/// Most attempts (accepted or rejected) the adaptive scheme makes over one integrator step:
/// past them the scene is refused as too stiff for it (a million attempts take about a second
/// on the shipped scenes; a scene that needs them wants a fixed step at its stable limit).
pub const MAX_ADAPTIVE_ATTEMPTS: u32 = 1_000_000;

/// Simulated time and what has been done to reach it.
#[derive(Debug, Clone, Copy, Default)]
struct Clock {
    /// Simulated time [s].
    time: f64,
    /// World steps since t = 0.
    steps: u64,
    /// Integrator steps accepted, and (adaptive schemes) rejected, since t = 0.
    integrator_steps: u64,
    rejected_steps: u64,
}

/// A system running in time.
#[derive(Debug, Clone)]
pub struct World {
    system: System,
    /// The integrator's state: for the leapfrogs, positions at t and velocities at t − ½dt;
    /// synchronised for the others.
    states: Vec<BodyState>,
    scheme: Scheme,
    evaluation: Evaluation,
    /// The time step settings (the substep setting as given).
    timing: Timing,
    /// Integrator steps per world step, `Substeps::Auto` resolved.
    substeps: u32,
    clock: Clock,
    ledger: EnergyLedger,
    /// Kinetic and gravity energy at the current time, from the integrator.
    body_energy: BodyEnergy,
    health: Health,
}

impl World {
    /// A world at t = 0 from the system's initial states, with time step settings `timing`
    /// (`dt` \[s] > 0). Forces and accelerations at t = 0 are evaluated here.
    ///
    /// # Errors
    /// A coupling that cannot give its forces at t = 0.
    pub fn new(system: System, timing: Timing) -> Result<Self, StepError> {
        let substeps = timing.first_substeps();
        let bodies = system.bodies().len();
        let mut world = Self {
            states: system.initial_states().to_vec(),
            scheme: Scheme::new(timing.integrator(), timing.tolerances(), timing.dt() / f64::from(substeps), bodies),
            evaluation: Evaluation::new(bodies, system.couplings()),
            system,
            timing,
            substeps,
            clock: Clock::default(),
            ledger: EnergyLedger::default(),
            body_energy: BodyEnergy::default(),
            health: Health::default(),
        };
        world.start_integrator()?;
        world.health.limit = stability::binding(&world.limits());
        let initial_states = world.system.initial_states().to_vec();
        world.plan_auto_substeps(initial_states)?;
        world.health.initial_energy = world.energy();
        let ends: Vec<Vec3> = world.evaluation.forces().iter().flat_map(|f| [f.point1, f.point2]).collect();
        world.health.fall_energy = health::fall_energy(&world.system, &world.states, ends.into_iter());
        Ok(world)
    }

    /// A fresh integrator for the current settings, started at the current time from
    /// `self.states` (synchronised velocities): forces, accelerations and energies.
    fn start_integrator(&mut self) -> Result<(), StepError> {
        let h = self.step_size();
        self.scheme = Scheme::new(self.timing.integrator(), self.timing.tolerances(), h, self.system.bodies().len());
        let time = self.clock.time;
        self.body_energy = self
            .scheme
            .start(StepContext {
                system: &self.system,
                states: &mut self.states,
                evaluation: &mut self.evaluation,
                time,
                h,
            })
            .map_err(|e| self.coupling_error(e))?;
        self.evaluation.commit_lines();
        self.evaluation.commit_radiation(self.system.water());
        Ok(())
    }

    /// Advances the world by one time step `dt`.
    ///
    /// # Errors
    /// A coupling that cannot give its forces, or a blow-up; the world is then left mid-step and
    /// should be reset.
    pub fn step(&mut self) -> Result<(), StepError> {
        let h = self.step_size();
        for _ in 0..self.substeps {
            if self.timing.integrator().is_adaptive() {
                self.adaptive_span(h)?;
            } else {
                let report = self
                    .scheme
                    .step(StepContext {
                        system: &self.system,
                        states: &mut self.states,
                        evaluation: &mut self.evaluation,
                        time: self.clock.time,
                        h,
                    })
                    .map_err(|e| self.failure(e))?;
                self.clock.time += h;
                self.book(&report);
                self.check_health()?;
            }
        }
        self.clock.steps += 1;
        Ok(())
    }

    /// The adaptive scheme's attempts over one integrator step `h` [s], each accepted one
    /// checked; the clock ends exactly at the span's end.
    fn adaptive_span(&mut self, h: f64) -> Result<(), StepError> {
        let (start, end) = (self.clock.time, self.clock.time + h);
        // Ends: a rejected attempt makes the next one shorter by the scheme's safety factor at
        // least, until `Dopri45::step` refuses one below round-off of the time (`Stalled`); an
        // accepted one moves the clock toward `end`, which the last one meets exactly — within
        // MAX_ADAPTIVE_ATTEMPTS, past which the scene is too stiff to be stepped so.
        for _ in 0..MAX_ADAPTIVE_ATTEMPTS {
            let report = self
                .scheme
                .step(StepContext {
                    system: &self.system,
                    states: &mut self.states,
                    evaluation: &mut self.evaluation,
                    time: self.clock.time,
                    h: end - self.clock.time,
                })
                .map_err(|e| self.failure(e))?;
            if !report.accepted {
                self.clock.rejected_steps += 1;
                continue;
            }
            self.clock.time = if report.reached { end } else { self.clock.time + report.advanced };
            self.book(&report);
            self.check_health()?;
            if report.reached {
                return Ok(());
            }
        }
        // The mean step the attempts took: what the adaptive step shrank to.
        let mean = (self.clock.time - start) / f64::from(MAX_ADAPTIVE_ATTEMPTS);
        Err(self.health.stalled(&self.system, &self.synchronized_states(), mean, self.clock.time, self.step_size()))
    }

    /// Stage *ledger*: an accepted integrator step's work and energies.
    fn book(&mut self, report: &StepReport) {
        self.evaluation.commit_lines();
        self.evaluation.commit_radiation(self.system.water());
        self.ledger.add(&report.work);
        self.body_energy = report.energy;
        self.clock.integrator_steps += 1;
    }

    /// Stage *health* ([`health`]).
    fn check_health(&self) -> Result<(), StepError> {
        match self.health.drift(&self.energy()) {
            None => Ok(()),
            Some(drift) => Err(self.health.diverged(
                &self.system,
                &self.synchronized_states(),
                drift,
                self.clock.time,
                self.step_size(),
            )),
        }
    }

    /// The step error of an integrator's failure, with names and the time.
    fn failure(&self, failure: StepFailure) -> StepError {
        match failure {
            StepFailure::Evaluation(error) => self.coupling_error(error),
            StepFailure::Stalled { step } => {
                self.health.stalled(&self.system, &self.synchronized_states(), step, self.clock.time, self.step_size())
            }
        }
    }

    fn coupling_error(&self, error: EvaluationError) -> StepError {
        StepError::Coupling {
            coupling: self.system.couplings()[error.coupling].name.clone(),
            time: self.clock.time,
            source: error.source,
        }
    }

    /// Integrator steps per world step that `Substeps::Auto` asks for at the current state:
    /// enough to keep each under [`AUTO_SUBSTEP_MARGIN`] of the binding stable time step of the
    /// integrator and of every contact's impact resolution, at most [`MAX_AUTO_SUBSTEPS`]; one
    /// for an adaptive scheme, whose steps adapt.
    fn auto_substeps(&self) -> u32 {
        if self.timing.integrator().is_adaptive() {
            return 1;
        }
        let limits = [self.limits(), self.impact_limits()].concat();
        stability::binding(&limits).map_or(1, |limit| {
            (self.timing.dt() / (AUTO_SUBSTEP_MARGIN * limit.dt)).ceil().clamp(1.0, f64::from(MAX_AUTO_SUBSTEPS)) as u32
        })
    }

    /// Under `Substeps::Auto`, the integrator steps per world step planned again for the
    /// current state ([`World::auto_substeps`]); when the plan differs from the steps it was
    /// started with, the integrator starts again from `states` (synchronised velocities) with
    /// the new step. Under `Fixed`, nothing. The one place `Auto` is resolved: at t = 0, on a
    /// change of the time step settings and after a live edit.
    fn plan_auto_substeps(&mut self, states: Vec<BodyState>) -> Result<(), StepError> {
        if self.timing.substeps() != Substeps::Auto {
            return Ok(());
        }
        let needed = self.auto_substeps();
        if needed != self.substeps {
            self.substeps = needed;
            self.states = states;
            self.start_integrator()?;
        }
        Ok(())
    }

    // ----- what a world shows -----

    pub fn system(&self) -> &System {
        &self.system
    }

    pub fn bodies(&self) -> &[RigidBody] {
        self.system.bodies()
    }

    pub fn couplings(&self) -> &[Coupling] {
        self.system.couplings()
    }

    /// Gravity [m/s²].
    pub fn gravity(&self) -> &Vec3 {
        self.system.gravity()
    }

    /// The time step settings.
    pub fn timing(&self) -> Timing {
        self.timing
    }

    pub fn integrator(&self) -> Integrator {
        self.timing.integrator()
    }

    /// The adaptive scheme's settings.
    pub fn tolerances(&self) -> Tolerances {
        self.timing.tolerances()
    }

    /// Simulated time \[s].
    pub fn time(&self) -> f64 {
        self.clock.time
    }

    /// World steps taken since t = 0.
    pub fn steps(&self) -> u64 {
        self.clock.steps
    }

    /// World step \[s]: what one [`World::step`] advances.
    pub fn dt(&self) -> f64 {
        self.timing.dt()
    }

    /// Integrator steps accepted since t = 0 (for `dopri45`, its adaptive steps).
    pub fn integrator_steps(&self) -> u64 {
        self.clock.integrator_steps
    }

    /// Adaptive steps rejected since t = 0 (always 0 for the fixed-step schemes).
    pub fn rejected_steps(&self) -> u64 {
        self.clock.rejected_steps
    }

    /// Integrator steps per world step.
    pub fn substeps(&self) -> u32 {
        self.substeps
    }

    /// The integrator's step `dt / substeps` \[s], the one the stable time step bounds.
    pub fn step_size(&self) -> f64 {
        self.timing.dt() / f64::from(self.substeps)
    }

    /// State of body `index` at the current time, velocities included.
    pub fn state(&self, index: usize) -> BodyState {
        self.scheme.synchronized(&self.system, &self.states, index, self.step_size())
    }

    /// The synchronised state of every body at the current time.
    pub fn synchronized_states(&self) -> Vec<BodyState> {
        (0..self.states.len()).map(|i| self.state(i)).collect()
    }

    /// Body kinematics at the last force evaluation, world axes.
    pub fn frames(&self) -> &[BodyFrame] {
        self.evaluation.frames()
    }

    /// Load (force and moment about G, world) on body `index` at the current time: couplings and
    /// water, plus gravity for bodies that respond to forces.
    pub fn load(&self, index: usize) -> &Load {
        &self.evaluation.loads()[index]
    }

    /// What each coupling did at the current time, in the order of [`World::couplings`].
    pub fn coupling_forces(&self) -> &[CouplingForces] {
        self.evaluation.forces()
    }

    /// What the water did to each floating body at the current time, in the order of the
    /// system's floating bodies (empty without water).
    pub fn water_forces(&self) -> &[crate::water::WaterForces] {
        self.evaluation.water()
    }

    /// What the air did to each wind-loaded body at the current time, in the order of the
    /// system's wind-loaded bodies (empty without air).
    pub fn air_forces(&self) -> &[crate::air::AirForces] {
        self.evaluation.air()
    }

    /// The buffers of the last force evaluation.
    pub fn evaluation(&self) -> &Evaluation {
        &self.evaluation
    }

    /// The solved shape of catenary coupling `index` at the current time.
    pub fn line_state(&self, index: usize) -> Option<&LineState> {
        self.evaluation.line_state(index)
    }

    /// Energies at the current time (PHYSICS.md §5).
    pub fn energy(&self) -> EnergyReport {
        EnergyReport {
            kinetic: self.body_energy.kinetic,
            gravity: self.body_energy.gravity,
            elastic: self.evaluation.elastic_energy() + self.ledger.held,
            dissipated: self.ledger.dissipated,
            external_work: self.ledger.external_work,
        }
    }

    /// Every finite stable time step of the integrator at the current state.
    pub fn limits(&self) -> Vec<Limit> {
        let states = self.synchronized_states();
        stability::limits(
            &Situation { system: &self.system, evaluation: &self.evaluation, states: &states },
            self.timing.integrator(),
        )
    }

    /// The step that resolves each contact's impact, `τ/10`, at the current state.
    pub fn impact_limits(&self) -> Vec<Limit> {
        let states = self.synchronized_states();
        stability::impact_limits(&Situation { system: &self.system, evaluation: &self.evaluation, states: &states })
    }
}
