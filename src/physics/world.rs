//! The world: gravity, bodies, couplings and time, and the stages of one step.
//!
//! [`World::step`] advances `dt` in `substeps` integrator steps, each followed by the *health*
//! check (for the adaptive `dopri45`, each accepted step). An integrator step runs, in order (the
//! integrator decides how velocities enter, and may run the per-body stages 1–4 in one pass
//! over the bodies; the Runge–Kutta schemes run stages 2–6 once per stage):
//! 1. *advance*: the integrator moves positions and orientations;
//! 2. *prescribe*: kinematic bodies are put where their motion says at the (stage) time;
//! 3. *predict*: each body's kinematics for the force evaluation ([`BodyFrame`]);
//! 4. *clear* the loads and add *gravity*;
//! 5. *couplings*: each coupling's forces, kept per coupling and summed into the bodies' loads;
//! 6. *accelerations* (or, for the Runge–Kutta schemes, the rates of the integrated variables);
//! 7. *ledger*: dissipated and external work advance with the scheme's weights.

use super::body::{BodyState, RigidBody, Support, prescribed_state};
use super::coupling::{BodyFrame, Coupling, CouplingError, CouplingForces, Load};
use super::dynamics::Acceleration;
use super::energy::{EnergyLedger, EnergyReport};
use super::integrator::runge_kutta::Workspace;
use super::integrator::{Integrator, Substeps, Timing, Tolerances, dopri45, leapfrog, leapfrog2, rk4, splitting};
use super::stability::{self, Limit};
use super::Vec3;

/// A step that could not be completed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StepError {
    /// A coupling could not give its forces.
    #[error("coupling \"{coupling}\" at t = {time} s: {source}")]
    Coupling { coupling: String, time: f64, source: CouplingError },
    /// The state blew up: `body` is the body at fault (non-finite, or the most energetic),
    /// `advice` names the binding stable time step of the starting configuration.
    #[error("the simulation diverged at t = {time} s: body \"{body}\" {cause}; {advice}")]
    Diverged { time: f64, body: String, cause: String, advice: String },
}

/// `substeps: Auto` keeps each integrator step under this fraction of the stable time step.
const AUTO_SUBSTEP_MARGIN: f64 = 0.9;

/// `substeps: Auto` takes at most this many integrator steps per world step: a scene that needs
/// more (a stiffness typed a million times too high) runs unstable and the health check stops
/// it with the stable time step in the message, rather than seeming to hang.
pub const MAX_AUTO_SUBSTEPS: u32 = 10_000;

/// A time step setting refused by [`World::set_timing`].
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TimingError {
    #[error("time step dt must be > 0 s, got {0}")]
    Step(f64),
    #[error("substeps must be at least 1")]
    NoSubsteps,
    #[error(transparent)]
    Forces(StepError),
}

/// Energy balance drift, in multiples of the energy budget, taken as a blow-up.
const DIVERGENCE_FACTOR: f64 = 10.0;

/// Bodies, couplings and time.
#[derive(Debug, Clone)]
pub struct World {
    /// Gravity vector [m/s²].
    pub gravity: Vec3,
    pub bodies: Vec<RigidBody>,
    pub couplings: Vec<Coupling>,
    pub integrator: Integrator,
    dt: f64,
    tolerances: Tolerances,
    /// The substep setting, and the integrator steps per world step it resolved to.
    substep_setting: Substeps,
    substeps: u32,
    time: f64,
    steps: u64,
    /// Integrator steps accepted, and (adaptive schemes) rejected, since t = 0.
    integrator_steps: u64,
    rejected_steps: u64,
    /// States at t = 0 (start of prescribed motions, and reset).
    pub(crate) initial_states: Vec<BodyState>,
    /// Indices of the kinematic bodies.
    kinematic_bodies: Vec<usize>,
    /// The integrator's state: for the leapfrogs, positions at t and velocities at t − ½dt;
    /// synchronised for the others.
    pub(crate) states: Vec<BodyState>,
    /// Body kinematics at the last force evaluation (t), world axes.
    pub(crate) frames: Vec<BodyFrame>,
    pub(crate) loads: Vec<Load>,
    pub(crate) accelerations: Vec<Acceleration>,
    /// Stage buffers of the Runge–Kutta schemes (empty for the others).
    pub(crate) runge_kutta: Workspace,
    pub(crate) coupling_forces: Vec<CouplingForces>,
    pub(crate) ledger: EnergyLedger,
    /// Kinetic and gravity energy of the bodies at the current time [J], from the integrator.
    pub(crate) body_energy: (f64, f64),
    /// Energies at t = 0, the reference of the divergence check.
    initial_energy: EnergyReport,
    /// The binding stable time step at t = 0, for the divergence message.
    initial_limit: Option<Limit>,
    /// `Σ m |g| ℓ` [J] with ℓ the size of the scene at t = 0: the energy the bodies could gain by
    /// falling across it, part of the divergence budget whatever the height of the origin.
    fall_energy: f64,
}

impl World {
    /// A world at t = 0 with `initial_states` (synchronised: velocities at t = 0) and time step
    /// `dt` [s] > 0. Forces and accelerations at t = 0 are evaluated here.
    ///
    /// # Errors
    /// A coupling that cannot give its forces at t = 0.
    pub fn new(
        gravity: Vec3,
        bodies: Vec<RigidBody>,
        couplings: Vec<Coupling>,
        initial_states: Vec<BodyState>,
        timing: Timing,
    ) -> Result<Self, StepError> {
        let n = bodies.len();
        let mut world = Self {
            gravity,
            bodies,
            couplings,
            integrator: timing.integrator,
            dt: timing.dt,
            tolerances: timing.tolerances,
            substep_setting: timing.substeps,
            substeps: match timing.substeps {
                Substeps::Fixed(n) => n.max(1),
                Substeps::Auto => 1,
            },
            time: 0.0,
            steps: 0,
            integrator_steps: 0,
            rejected_steps: 0,
            // Filled from `initial_states` by `start`.
            states: Vec::new(),
            initial_states,
            kinematic_bodies: Vec::new(),
            frames: vec![BodyFrame { position: Vec3::zeros(), rotation: super::Mat3::identity(), velocity: Vec3::zeros(), angular_velocity: Vec3::zeros() }; n],
            loads: vec![Load::default(); n],
            accelerations: vec![Acceleration::default(); n],
            runge_kutta: Workspace::default(),
            coupling_forces: Vec::new(),
            ledger: EnergyLedger::default(),
            body_energy: (0.0, 0.0),
            initial_energy: EnergyReport::default(),
            initial_limit: None,
            fall_energy: 0.0,
        };
        world.coupling_forces = vec![CouplingForces::default(); world.couplings.len()];
        world.kinematic_bodies = (0..n).filter(|&i| world.bodies[i].is_kinematic()).collect();
        world.start()?;
        world.initial_limit = stability::binding(&stability::limits(&world));
        if world.substep_setting == Substeps::Auto {
            let needed = world.auto_substeps();
            if needed > 1 {
                world.substeps = needed;
                world.start()?;
            }
        }
        world.initial_energy = world.energy();
        world.fall_energy = world.fall_energy();
        Ok(world)
    }

    /// The integrator's start at t = 0 from the initial states.
    fn start(&mut self) -> Result<(), StepError> {
        self.states.clone_from(&self.initial_states);
        self.start_integrator()
    }

    /// The integrator's start at the current time from `self.states` (synchronised velocities):
    /// forces, accelerations, energies, and an energy ledger from zero.
    fn start_integrator(&mut self) -> Result<(), StepError> {
        match self.integrator {
            Integrator::Leapfrog | Integrator::Leapfrog2 => leapfrog::start(self),
            Integrator::Splitting => splitting::start(self),
            Integrator::Rk4 => rk4::start(self),
            Integrator::Dopri45 => dopri45::start(self),
        }
    }

    /// Advances the world by one time step `dt`.
    ///
    /// # Errors
    /// A coupling that cannot give its forces; the world is then left mid-step and should be
    /// reset.
    pub fn step(&mut self) -> Result<(), StepError> {
        for _ in 0..self.substeps {
            match self.integrator {
                Integrator::Leapfrog => leapfrog::step(self, leapfrog::Gyroscopic::Lagged)?,
                Integrator::Leapfrog2 => leapfrog2::step(self)?,
                Integrator::Splitting => splitting::step(self)?,
                Integrator::Rk4 => rk4::step(self)?,
                Integrator::Dopri45 => {
                    let end = self.time + self.step_size();
                    while !dopri45::step(self, end)? {
                        self.check_health()?;
                    }
                }
            }
            self.check_health()?;
            if !self.integrator.is_adaptive() {
                self.integrator_steps += 1;
            }
        }
        self.steps += 1;
        Ok(())
    }

    /// Stage *health*: every body's state is finite, and its mechanical energy less the work
    /// put in by prescribed motions has not drifted by more than [`DIVERGENCE_FACTOR`] times the
    /// energy budget (`|kinetic| + |gravity| + |elastic|` at t = 0, the energy of a fall across
    /// the scene, and the work put in by prescribed motions since). An unstable step grows the
    /// energy geometrically, so this stops a blow-up within a few steps of its start and long
    /// before anything overflows.
    ///
    /// The dissipated work is left out on both sides: dampers remove at most the budget, a
    /// blow-up with a damper dissipates as fast as it grows, and a scheme that resolves a damper
    /// poorly at a large but stable step (RK4 near its damped limit, where the physical decay
    /// per step is far faster than the scheme's) books more dissipation than its bounded state
    /// loses, which is inaccuracy, not divergence.
    fn check_health(&self) -> Result<(), StepError> {
        let energy = self.energy();
        let start = &self.initial_energy;
        let budget = start.kinetic.abs() + start.gravity.abs() + start.elastic.abs() + self.fall_energy + energy.external_work.abs();
        let drift = (energy.total() - energy.external_work - start.total()).abs();
        if drift <= DIVERGENCE_FACTOR * budget.max(f64::MIN_POSITIVE) {
            return Ok(());
        }
        // A non-finite position or velocity makes the energy non-finite, so this search only
        // runs once something is wrong.
        let dynamic = || (0..self.bodies.len()).filter(|&i| !self.bodies[i].is_kinematic());
        let not_finite = dynamic().find(|&i| {
            let s = &self.states[i];
            !(s.position.iter().chain(s.velocity.iter()).chain(s.angular_velocity.iter()).chain(s.orientation.coords.iter()).all(|x| x.is_finite()))
        });
        Err(match not_finite {
            Some(i) => self.diverged(i, "has a non-finite state".to_string()),
            None => self.diverged(
                self.most_energetic_body(),
                format!("carries the most kinetic energy as the energy drifts by {drift:.3e} J (budget {budget:.3e} J)"),
            ),
        })
    }

    /// The body that responds to forces with the most kinetic energy (0 if none does).
    fn most_energetic_body(&self) -> usize {
        (0..self.bodies.len()).filter(|&i| !self.bodies[i].is_kinematic()).max_by(|&a, &b| self.kinetic_energy(a).total_cmp(&self.kinetic_energy(b))).unwrap_or(0)
    }

    /// An adaptive step that had to shrink to `step` [s], below round-off of the time.
    pub(crate) fn stalled(&self, step: f64) -> StepError {
        self.diverged(self.most_energetic_body(), format!("carries the most kinetic energy as the adaptive step shrinks to {step:.3e} s (too stiff, or blown up)"))
    }

    /// [`StepError::Diverged`] naming body `body` and the binding stable time step at t = 0.
    fn diverged(&self, body: usize, cause: String) -> StepError {
        let advice = match self.initial_limit {
            Some(limit) => format!("the stable time step is {:.3e} s, set by {} (step {:.3e} s)", limit.dt, limit.describe(self), self.step_size()),
            None => format!("no coupling limits the time step (step {:.3e} s)", self.step_size()),
        };
        StepError::Diverged { time: self.time, body: self.bodies.get(body).map_or_else(String::new, |b| b.name.clone()), cause, advice }
    }

    /// `Σ m |g| ℓ` [J], ℓ the diagonal of the box around the bodies' centres of mass and the
    /// coupling ends at the current time.
    fn fall_energy(&self) -> f64 {
        let points = self.states.iter().map(|s| s.position).chain(self.coupling_forces.iter().flat_map(|f| [f.point1, f.point2]));
        let (low, high) = super::bounding_box(points);
        let size = if low.x.is_finite() { (high - low).norm() } else { 0.0 };
        let mass: f64 = self.bodies.iter().filter(|b| !b.is_kinematic()).map(|b| b.mass()).sum();
        mass * self.gravity.norm() * size
    }

    /// `½ m |v|² + ½ ωᵀ I ω` of body `index` [J].
    fn kinetic_energy(&self, index: usize) -> f64 {
        let state = self.state(index);
        self.bodies[index].kinetic_energy(&state.velocity, &state.angular_velocity)
    }

    /// Body kinematics at the last force evaluation, world axes.
    pub fn frames(&self) -> &[BodyFrame] {
        &self.frames
    }

    /// Restarts from t = 0 with the current parameters; on error the world is unchanged.
    pub fn reset(&mut self) -> Result<(), StepError> {
        *self = Self::new(self.gravity, self.bodies.clone(), self.couplings.clone(), self.initial_states.clone(), self.timing())?;
        Ok(())
    }

    /// Integrator steps per world step that `Substeps::Auto` asks for at the current state:
    /// enough to keep each under [`AUTO_SUBSTEP_MARGIN`] of the binding stable time step of the
    /// integrator and of every contact's impact resolution, at most [`MAX_AUTO_SUBSTEPS`]; one
    /// for an adaptive scheme, whose steps adapt.
    fn auto_substeps(&self) -> u32 {
        if self.integrator.is_adaptive() {
            return 1;
        }
        let limits = [stability::limits(self), stability::impact_limits(self)].concat();
        stability::binding(&limits).map_or(1, |limit| (self.dt / (AUTO_SUBSTEP_MARGIN * limit.dt)).ceil().clamp(1.0, f64::from(MAX_AUTO_SUBSTEPS)) as u32)
    }

    /// The synchronised state of every body at the current time (velocities at t).
    fn synchronized_states(&self) -> Vec<BodyState> {
        (0..self.bodies.len()).map(|i| self.state(i)).collect()
    }

    /// Starts the integrator again at the current time from `self.states`, which the caller has
    /// set to [`World::synchronized_states`] before changing anything, keeping the energy
    /// integrals: the motion goes on from the same positions and velocities under what changed
    /// (a coupling, the time step, the integrator).
    fn restart(&mut self) -> Result<(), StepError> {
        let ledger = self.ledger;
        self.start_integrator()?;
        self.ledger.add(ledger.dissipated, ledger.external_work);
        Ok(())
    }

    /// Replaces coupling `index` while running, without a restart (live tuning): the integrator
    /// starts again at the current time from the synchronised state (positions and velocities at
    /// t do not move, as after a change of time step), with the forces of the new coupling, so
    /// the motion goes on under them at the scheme's order across the change. Its energy does
    /// jump: the elastic energy of the new parameters at the same positions differs from the old
    /// one. That jump is booked as external work (PHYSICS.md §5), so `balance()` stays continuous
    /// across the swap and keeps checking the motion after it; the divergence message then
    /// quotes the stable time step of the new parameters.
    ///
    /// # Errors
    /// The new coupling cannot give its forces here, or `index` is out of range; the world is
    /// then unchanged.
    pub fn replace_coupling(&mut self, index: usize, coupling: Coupling) -> Result<(), StepError> {
        if index >= self.couplings.len() {
            return Err(StepError::Coupling { coupling: coupling.name, time: self.time, source: CouplingError::NoSuchCoupling(index) });
        }
        let before = self.clone();
        self.states = self.synchronized_states();
        self.couplings[index] = coupling;
        if let Err(error) = self.restart() {
            *self = before;
            return Err(error);
        }
        self.ledger.add(0.0, self.energy().total() - before.energy().total());
        self.initial_limit = stability::binding(&stability::limits(self));
        Ok(())
    }

    /// Changes the time step, the integrator, the substeps and the adaptive tolerances at the
    /// current time, keeping the state: the new integrator starts from the synchronised
    /// positions and velocities, so the motion goes on where it was. `Substeps::Auto` is
    /// resolved from the stable time steps of the current state.
    ///
    /// # Errors
    /// `dt` not finite and positive, zero substeps, or forces that cannot be evaluated; the
    /// world is then unchanged.
    pub fn set_timing(&mut self, timing: Timing) -> Result<(), TimingError> {
        if !(timing.dt.is_finite() && timing.dt > 0.0) {
            return Err(TimingError::Step(timing.dt));
        }
        if timing.substeps == Substeps::Fixed(0) {
            return Err(TimingError::NoSubsteps);
        }
        let before = self.clone();
        self.states = self.synchronized_states();
        (self.dt, self.integrator, self.substep_setting, self.tolerances) = (timing.dt, timing.integrator, timing.substeps, timing.tolerances);
        self.substeps = match timing.substeps {
            Substeps::Fixed(n) => n,
            Substeps::Auto => self.auto_substeps(),
        };
        if let Err(error) = self.restart() {
            *self = before;
            return Err(TimingError::Forces(error));
        }
        Ok(())
    }

    /// The time step settings.
    pub fn timing(&self) -> Timing {
        Timing { dt: self.dt, integrator: self.integrator, substeps: self.substep_setting, tolerances: self.tolerances }
    }

    /// Simulated time [s].
    pub fn time(&self) -> f64 {
        self.time
    }

    /// World steps taken since t = 0.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// World step [s]: what one [`World::step`] advances.
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Integrator steps accepted since t = 0 (for `dopri45`, its adaptive steps).
    pub fn integrator_steps(&self) -> u64 {
        self.integrator_steps
    }

    /// Adaptive steps rejected since t = 0 (always 0 for the fixed-step schemes).
    pub fn rejected_steps(&self) -> u64 {
        self.rejected_steps
    }

    /// Counts one adaptive step, accepted or rejected.
    pub(crate) fn count_integrator_step(&mut self, rejected: bool) {
        if rejected {
            self.rejected_steps += 1;
        } else {
            self.integrator_steps += 1;
        }
    }

    /// The adaptive scheme's settings.
    pub fn tolerances(&self) -> Tolerances {
        self.tolerances
    }

    /// Integrator steps per world step.
    pub fn substeps(&self) -> u32 {
        self.substeps
    }

    /// The integrator's step `dt / substeps` [s], the one the stable time step bounds.
    pub fn step_size(&self) -> f64 {
        self.dt / f64::from(self.substeps)
    }

    /// State of body `index` at the current time, velocities included.
    pub fn state(&self, index: usize) -> BodyState {
        if self.integrator.is_staggered() { leapfrog::synchronized_state(self, index) } else { self.states[index] }
    }

    /// Load (force and moment about G, world) on body `index` at the current time: couplings,
    /// plus gravity for bodies that respond to forces.
    pub fn load(&self, index: usize) -> &Load {
        &self.loads[index]
    }

    /// What each coupling did at the current time, in the order of [`World::couplings`].
    pub fn coupling_forces(&self) -> &[CouplingForces] {
        &self.coupling_forces
    }

    /// Energies at the current time (PHYSICS.md §5).
    pub fn energy(&self) -> EnergyReport {
        let (kinetic, gravity) = self.body_energy;
        EnergyReport {
            kinetic,
            gravity,
            elastic: self.coupling_forces.iter().map(|f| f.potential).sum(),
            dissipated: self.ledger.dissipated,
            external_work: self.ledger.external_work,
        }
    }

    // ----- stages, shared by the integrators -----

    /// Stage *prescribe*: kinematic bodies to their pose and velocity at time `time` [s].
    pub(crate) fn prescribe_kinematic_bodies(&mut self, time: f64) {
        for &index in &self.kinematic_bodies {
            if let Support::Kinematic(motion) = &self.bodies[index].support {
                self.states[index] = prescribed_state(motion, &self.initial_states[index], time);
            }
        }
    }

    /// Stages *clear*, *gravity* and *couplings* for kinematics `self.frames`; returns the power
    /// dissipated [W].
    pub(crate) fn evaluate_loads(&mut self) -> Result<f64, StepError> {
        for (load, body) in self.loads.iter_mut().zip(&self.bodies) {
            *load = gravity_load(&self.gravity, body);
        }
        self.apply_couplings()
    }

    /// Stage *couplings*: each coupling's forces, kept per coupling and added to the loads;
    /// returns the power dissipated [W].
    pub(crate) fn apply_couplings(&mut self) -> Result<f64, StepError> {
        apply_each_coupling(&mut self.couplings, &mut self.coupling_forces, &self.frames, &self.gravity, &mut self.loads)
            .map_err(|(index, source)| StepError::Coupling { coupling: self.couplings[index].name.clone(), time: self.time, source })
    }

    /// Power the prescribed motions put into the system, `−Σ (F_k·v_k + M_k·ω_k)` [W].
    pub(crate) fn external_power(&self) -> f64 {
        self.kinematic_bodies
            .iter()
            .map(|&i| {
                let (load, frame) = (&self.loads[i], &self.frames[i]);
                -(load.force.dot(&frame.velocity) + load.moment.dot(&(frame.rotation * frame.angular_velocity)))
            })
            .sum()
    }

    pub(crate) fn advance_clock(&mut self) {
        self.time += self.step_size();
    }

    /// Sets the clock (the adaptive scheme's steps do not divide the integrator step).
    pub(crate) fn set_time(&mut self, time: f64) {
        self.time = time;
    }
}

/// Stages *clear* and *gravity* for one body: `F = m g`, `M = 0` (nothing for a kinematic body,
/// which forces do not move).
pub(crate) fn gravity_load(gravity: &Vec3, body: &RigidBody) -> Load {
    if body.is_kinematic() { Load::default() } else { Load { force: gravity * body.mass(), moment: Vec3::zeros() } }
}

/// Stage *couplings* over `couplings`: see [`World::apply_couplings`]; the error names the index
/// of the coupling that failed.
///
/// Built for AVX-512 and for AVX2 as well, chosen at run time by what the processor has
/// (AVX-512 only with the Ice Lake / Zen 4 feature set, where `multiversion` deems it fast): the
/// couplings' forces are inlined here, so the contact faces run four to a vector instruction
/// ([`super::coupling::contact`]) and what each coupling computes stays in registers from one
/// stage of its evaluation to the next. AVX-512's 32 vector registers hold the face batch's
/// constants and sums that AVX2's 16 cannot (about 160 instructions per batch instead of about
/// 190, by the disassembly of the bench binary). The arithmetic is the same IEEE arithmetic in every build
/// (no fused multiply–add is introduced), so the results are too, bit for bit.
#[multiversion::multiversion(targets("x86_64+avx512f+avx512vl+avx2+fma", "x86_64+avx2+fma"))]
fn apply_each_coupling(couplings: &mut [Coupling], forces: &mut [CouplingForces], frames: &[BodyFrame], gravity: &Vec3, loads: &mut [Load]) -> Result<f64, (usize, CouplingError)> {
    let mut dissipated = 0.0;
    for (index, (coupling, out)) in couplings.iter_mut().zip(forces.iter_mut()).enumerate() {
        coupling.apply(frames, gravity, loads, out).map_err(|source| (index, source))?;
        dissipated += out.dissipated_power;
    }
    Ok(dissipated)
}
