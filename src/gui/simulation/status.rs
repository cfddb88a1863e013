//! The running simulation at one instant, as the panel shows it: time, energies, the stable time
//! steps, the contacts the estimator needs, the bodies' states. Built from the world by the
//! simulation thread once per tick.

use crate::figures;
use crate::line_hint::{self, Measures};
use tether_physics::body::BodyState;
use tether_physics::coupling::contact::Opposing;
use tether_physics::coupling::{Coupling, CouplingKind};
use tether_physics::energy::EnergyReport;
use tether_physics::integrator::Timing;
use tether_physics::math::Vec3;
use tether_physics::potential::DriftModel;
use tether_physics::stability::Limiter;
use tether_physics::world::World;

/// The running simulation at one instant.
#[derive(Debug, Clone, Default)]
pub struct Status {
    pub label: String,
    /// Simulated time [s] and world steps since t = 0.
    pub time: f64,
    pub steps: u64,
    pub running: bool,
    /// Why the run stopped, if a step failed.
    pub failure: Option<String>,
    pub energy: EnergyReport,
    /// `balance()` at t = 0 [J]: the drift is measured from it.
    pub initial_balance: f64,
    pub timing: Option<Timing>,
    /// Integrator step `dt / substeps` [s] and substeps per world step.
    pub step_size: f64,
    pub substeps: u32,
    /// Stable time step of every coupling [s] (`None`: nothing limits it), in scene order.
    pub coupling_limits: Vec<(String, Option<f64>)>,
    /// Per coupling, in scene order: a dynamic line's own sub-steps, their count in the last
    /// evaluation's interval and their length [s] (its nodes step by them; PHYSICS.md §8),
    /// `None` otherwise.
    pub line_substeps: Vec<Option<(u32, f64)>>,
    /// Per coupling, in scene order: a driven quasi-static line's measures against its
    /// fairlead (`crate::line_hint`: likely wrong quasi-static, or holds), `None` otherwise.
    pub line_hints: Vec<Option<Measures>>,
    /// Stable time step set by the fastest spinning body, if any spins [s].
    pub rotation_limit: Option<(String, f64)>,
    /// Stable time step of each floating body under the water's stiffness and drag [s].
    pub water_limits: Vec<(String, f64)>,
    /// Stable time step of each wind-loaded body under its aerodynamic damping [s].
    pub air_limits: Vec<(String, f64)>,
    /// Each floating body with potential-flow data (PHYSICS.md §9): its index, and whether its
    /// potential flow runs (it may be switched off live).
    pub potential_flow: Vec<(usize, bool)>,
    /// Each floating body whose panel data hold mean drift coefficients (PHYSICS.md §10): its
    /// index, and the drift model it runs.
    pub drift: Vec<(usize, DriftModel)>,
    /// Time step that resolves each contact's impact, `τ/10` [s] (not a stability limit).
    pub impact_limits: Vec<(String, f64)>,
    /// What the contact estimator needs of each contact.
    pub contacts: Vec<ContactStatus>,
    pub bodies: Vec<BodyStatus>,
    /// Simulated seconds per wall second, and world steps per wall second, over the last half
    /// second.
    pub rate: f64,
    pub steps_per_second: f64,
    /// Whether the run waits for the embedded viewer, which is behind what it was sent.
    pub waiting_for_viewer: bool,
}

/// A contact coupling as the estimator sees it (PHYSICS.md §4).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactStatus {
    /// Coupling index in the scene, and name.
    pub index: usize,
    pub name: String,
    /// Mass of the body [kg], and of the opposing body (`None` against the environment).
    pub mass: f64,
    pub other_mass: Option<f64>,
    /// Expected contact area `A` [m²] and range `d0` [m].
    pub area: f64,
    pub range: f64,
}

/// A body's state, synchronised at the current time.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyStatus {
    pub name: String,
    /// Position of G [m], velocity of G [m/s], angular velocity [rad/s], world axes.
    pub position: Vec3,
    pub velocity: Vec3,
    pub angular_velocity: Vec3,
}

/// What the thread knows of the run beside its world.
#[derive(Debug, Clone)]
pub struct RunState {
    pub label: String,
    pub running: bool,
    pub failure: Option<String>,
    /// `balance()` at the start of the recording [J].
    pub initial_balance: f64,
    /// Simulated seconds and world steps over the last half second of wall time, and that wall
    /// time [s] (the runner's pace window).
    pub advanced: f64,
    pub steps: u64,
    pub wall: f64,
    /// Whether the run waits for the embedded viewer, which is behind what it was sent.
    pub waiting_for_viewer: bool,
}

/// The status of `world` in the run `run`.
pub fn status(world: &World, run: &RunState) -> Status {
    let limits = world.limits();
    let coupling_limit = |i: usize| limits.iter().find(|l| l.limiter == Limiter::Coupling(i)).map(|l| l.dt);
    let rotation_limit = limits
        .iter()
        .filter_map(|l| match l.limiter {
            Limiter::Rotation(body) => Some((world.bodies()[body].name.clone(), l.dt)),
            Limiter::Coupling(_) | Limiter::Impact(_) | Limiter::Water(_) | Limiter::Air(_) => None,
        })
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let water_limits = limits
        .iter()
        .filter_map(|l| match l.limiter {
            Limiter::Water(body) => Some((world.bodies()[body].name.clone(), l.dt)),
            Limiter::Coupling(_) | Limiter::Impact(_) | Limiter::Rotation(_) | Limiter::Air(_) => None,
        })
        .collect();
    let air_limits = limits
        .iter()
        .filter_map(|l| match l.limiter {
            Limiter::Air(body) => Some((world.bodies()[body].name.clone(), l.dt)),
            Limiter::Coupling(_) | Limiter::Impact(_) | Limiter::Rotation(_) | Limiter::Water(_) => None,
        })
        .collect();
    let wall = run.wall.max(1e-6);
    Status {
        label: run.label.clone(),
        time: world.time(),
        steps: world.steps(),
        running: run.running,
        failure: run.failure.clone(),
        energy: world.energy(),
        initial_balance: run.initial_balance,
        timing: Some(world.timing()),
        step_size: world.step_size(),
        substeps: world.substeps(),
        coupling_limits: world
            .couplings()
            .iter()
            .enumerate()
            .map(|(i, c)| (c.name.clone(), coupling_limit(i)))
            .collect(),
        line_substeps: (0..world.couplings().len())
            .map(|i| world.evaluation().line_run(i).map(|run| run.substeps()))
            .collect(),
        line_hints: (0..world.couplings().len()).map(|i| line_hint::measures(world, i)).collect(),
        rotation_limit,
        water_limits,
        air_limits,
        potential_flow: world.system().water().map_or_else(Vec::new, |stage| {
            let with_data = stage.floating.iter().filter(|f| f.has_potential_data());
            with_data.map(|f| (f.body(), f.potential().is_some())).collect()
        }),
        drift: world.system().water().map_or_else(Vec::new, |stage| {
            let models = stage.floating.iter().filter_map(|f| f.potential_model().map(|model| (f.body(), model)));
            let with_drift = models.filter(|(_, model)| model.coefficients().mean_drift().is_some());
            with_drift.map(|(body, model)| (body, model.drift_model())).collect()
        }),
        impact_limits: world.impact_limits().iter().map(|l| (l.describe(world.system()), l.dt)).collect(),
        contacts: contacts(world),
        bodies: (0..world.bodies().len()).map(|i| body_status(world, i)).collect(),
        rate: if run.running { run.advanced / wall } else { 0.0 },
        steps_per_second: if run.running { run.steps as f64 / wall } else { 0.0 },
        waiting_for_viewer: run.running && run.waiting_for_viewer,
    }
}

fn contacts(world: &World) -> Vec<ContactStatus> {
    let contact = |(index, coupling): (usize, &Coupling)| match &coupling.kind {
        CouplingKind::Contact(contact) => Some(ContactStatus {
            index,
            name: coupling.name.clone(),
            mass: world.bodies()[contact.body()].mass(),
            other_mass: match &contact.against() {
                Opposing::Body { body, .. } => Some(world.bodies()[*body].mass()),
                Opposing::Planes(_) => None,
            },
            area: contact.expected_area(),
            range: contact.law().range(),
        }),
        CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => None,
    };
    world.couplings().iter().enumerate().filter_map(contact).collect()
}

fn body_status(world: &World, index: usize) -> BodyStatus {
    let BodyState { position, orientation, velocity, angular_velocity } = world.state(index);
    BodyStatus {
        name: world.bodies()[index].name.clone(),
        position,
        velocity,
        angular_velocity: orientation * angular_velocity,
    }
}

/// A warning when line `index` of `world` is shorter, unstretched, than the distance between its
/// ends where they are now: it is then stretched by `EA = D L_eq` at once (PHYSICS.md §3), a
/// jolt the run may not survive at its time step.
pub fn short_line(world: &World, index: usize) -> Option<String> {
    let coupling = world.couplings().get(index)?;
    let line = match &coupling.kind {
        CouplingKind::Catenary(line) => line,
        CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => return None,
    };
    let frames = world.frames();
    let span = (line.end2().motion(frames).position - line.end1().motion(frames).position).norm();
    (line.length() < span).then(|| {
        format!(
            "warning: line \"{}\" is {} long, shorter than the {} between its ends: it is stretched by EA = {} at once",
            coupling.name,
            figures::quantity(line.length(), "m", 4),
            figures::quantity(span, "m", 4),
            figures::quantity(line.stiffness() * line.length(), "N", 3)
        )
    })
}

/// Whether everything the recorder logs of `world` is finite: the bodies' states, the energy
/// account, each coupling's ends, forces and energy (a diverged step may be shown only then).
pub fn finite(world: &World) -> bool {
    let vector = |v: &Vec3| v.iter().all(|x| x.is_finite());
    let states = world.synchronized_states().iter().all(|s| {
        vector(&s.position)
            && vector(&s.velocity)
            && vector(&s.angular_velocity)
            && s.orientation.coords.iter().all(|x| x.is_finite())
    });
    let e = world.energy();
    let energy = [e.kinetic, e.gravity, e.elastic, e.dissipated, e.external_work].iter().all(|x| x.is_finite());
    let couplings = world.coupling_forces().iter().all(|c| {
        [&c.point1, &c.point2, &c.f1, &c.f2].into_iter().all(vector)
            && [c.tension, c.dissipated_power, c.potential].iter().all(|x| x.is_finite())
    });
    states && energy && couplings
}
