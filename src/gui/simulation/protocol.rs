//! What the GUI and the simulation thread say to each other: commands one way, reports the
//! other.

use super::status::Status;
use std::sync::mpsc::Sender;
use std::time::Instant;
use tether_physics::air::{AirSpec, WindLoadSpec};
use tether_physics::coupling::Coupling;
use tether_physics::integrator::Timing;
use tether_physics::potential::DriftModel;
use tether_physics::seabed::Seabed;
use tether_physics::statics::Direction;
use tether_physics::water::WaterSpec;
use tether_physics::water::morison::HydroSpec;
use tether_physics::world::World;

/// How fast simulated time runs.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Speed {
    /// Simulated seconds per wall-clock second (1 = real time).
    Factor(f64),
    /// As fast as the machine steps.
    Max,
}

/// A scene ready to run: its world, a label for recordings and messages, and the scene's
/// `duration` \[s], the run whose length Play checks first (`tether_analysis::run_length`).
pub struct Run {
    pub label: String,
    pub world: World,
    pub duration: f64,
}

/// What the GUI asks of the simulation thread.
pub enum Command {
    Play,
    Pause,
    /// One world step (paused).
    Step,
    /// Back to t = 0 with the current parameters, as a new recording.
    Reset,
    SetSpeed(Speed),
    /// Time step, integrator and substeps, applied at the current time.
    SetTiming(Timing),
    /// Coupling `index` replaced by `coupling` (already checked by the scene builder) without a
    /// restart; `sent` dates the request, to measure how long it took to apply.
    SetCoupling {
        index: usize,
        coupling: Coupling,
        sent: Instant,
    },
    /// Draw every contact's face forces as arrows in the recording (or not), from now on.
    SetFaceArrows(bool),
    /// The viewer's eye follows this body (by name), or frames the run again (`None`), in this
    /// run and the next ones.
    Follow(Option<String>),
    /// The water replaced by `spec` (checked by the scene builder), without a restart.
    SetWater(WaterSpec),
    /// Body `body`'s coefficients in the water replaced by `spec` (checked) and, with potential
    /// flow, its drift model set to `drift` (PHYSICS.md §10), without a restart.
    SetHydro {
        body: usize,
        spec: HydroSpec,
        drift: Option<DriftModel>,
    },
    /// The air replaced by `spec` (checked by the scene builder), loading `loads`, without a
    /// restart (PHYSICS.md §10).
    SetAir {
        spec: AirSpec,
        loads: Vec<(usize, WindLoadSpec)>,
    },
    /// Body `body`'s potential flow switched on or off (PHYSICS.md §9), without a restart; on,
    /// its radiation memory starts afresh.
    SetPotentialFlow {
        body: usize,
        on: bool,
    },
    /// The seabed replaced by this one (checked by the scene builder: its line friction `C_B`
    /// tuned), without a restart.
    SetSeabed(Seabed),
    /// Every free body placed at the static equilibrium found from where the bodies are, at
    /// rest (PHYSICS.md §7, `tether equilibrium`).
    Equilibrium,
    /// The offset curve of body `body` in `direction`, `steps` offsets up to `to` [m or rad]
    /// from its static equilibrium (`tether offsets`); the world is not changed.
    OffsetCurve {
        body: usize,
        direction: Direction,
        to: f64,
        steps: u32,
    },
    /// A fit's plots from now on, in this run's recording and the next ones of the same scene:
    /// each measured column's series (the record, drawn once), a plot each.
    ShowFit(Vec<Curve>),
    /// The model's curve of each measured column at the fit's latest values, drawn in place of
    /// the last ones.
    FitModel(Vec<Curve>),
    /// A new scene, paused at t = 0 (a fit's plots are dropped).
    Load(Box<Run>),
    /// The scene closed: its run stopped, its recording finished (a recording is played back
    /// in its place).
    Close,
    /// A copy of the running world, for inspection (tests, tools).
    Snapshot(Sender<Option<World>>),
}

/// What the simulation thread tells the GUI.
#[derive(Debug, Clone)]
pub enum Report {
    Status(Box<Status>),
    /// Something happened (a scene loaded, a value applied).
    Message(String),
    /// A command was refused, or a step failed (the run is paused).
    Error(String),
    /// An offset curve asked for with [`Command::OffsetCurve`].
    OffsetCurve(OffsetCurve),
}

/// One series of a fit's plot: a measured column's samples, or the model's signal for it.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// The measured column the plot is named after.
    pub column: String,
    /// Times [s] and values [the signal's unit].
    pub times: Vec<f64>,
    pub values: Vec<f64>,
}

/// A body's offset curve, as the panel draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetCurve {
    pub body: String,
    pub direction: Direction,
    /// `(offset [m or rad], restoring force [N or N·m])`, from the equilibrium outward.
    pub points: Vec<(f64, f64)>,
}
