//! What a force evaluation leaves behind, per run: the kinematics the forces saw, the loads on
//! the bodies, what each coupling did, and what each coupling remembers for the next evaluation
//! (MuJoCo's mutable data, beside the constant system of bodies and couplings).

use crate::air::AirForces;
use crate::body::{BodyFrame, Load};
use crate::coupling::catenary::LineState;
use crate::coupling::contact::ContactForces;
use crate::coupling::lumped_line::LineRun;
use crate::coupling::{Coupling, CouplingCache, CouplingForces, CouplingKind, LineModel};
use crate::potential::RadiationRun;
use crate::water::WaterForces;
use crate::water_stage::{WaterScratch, WaterStage};

/// The buffers of the force evaluation, one entry per body or coupling of a [`System`](crate::system::System).
#[derive(Debug, Clone)]
pub struct Evaluation {
    /// Body kinematics at the last evaluation, world axes.
    pub(crate) frames: Vec<BodyFrame>,
    /// Force and moment about G on each body [N, N·m], world axes.
    pub(crate) loads: Vec<Load>,
    /// What each coupling did.
    pub(crate) forces: Vec<CouplingForces>,
    /// `Σ` of the couplings' `potential` [J], summed by the couplings stage as it wrote them.
    pub(crate) elastic: f64,
    /// What each coupling remembers (warm starts, face lists).
    pub(crate) caches: Vec<CouplingCache>,
    /// The nodes of each dynamic line (PHYSICS.md §8), in the order of their couplings.
    pub(crate) lines: Vec<LineRun>,
    /// What the water did to each floating body (empty without water).
    pub(crate) water: Vec<WaterForces>,
    /// The radiation memory of each floating body (PHYSICS.md §9; empty without water).
    pub(crate) radiation: Vec<RadiationRun>,
    /// The water stage's buffers.
    pub(crate) water_scratch: WaterScratch,
    /// What the air did to each wind-loaded body (empty without air).
    pub(crate) air: Vec<AirForces>,
}

impl Evaluation {
    /// Empty buffers for `bodies` bodies and `couplings`, each coupling's cache fresh.
    pub fn new(bodies: usize, couplings: &[Coupling]) -> Self {
        Self {
            frames: vec![BodyFrame::default(); bodies],
            loads: vec![Load::default(); bodies],
            forces: vec![CouplingForces::default(); couplings.len()],
            elastic: 0.0,
            caches: couplings.iter().map(Coupling::new_cache).collect(),
            lines: (0..couplings.len()).filter(|&i| is_dynamic(&couplings[i])).map(LineRun::new).collect(),
            water: Vec::new(),
            radiation: Vec::new(),
            water_scratch: WaterScratch::default(),
            air: Vec::new(),
        }
    }

    /// Starts coupling `index`'s cache afresh for `coupling`, which replaced it.
    /// A dynamic line starts again in its static equilibrium where it is now, moving as that
    /// shape moves with its ends ([`LineRun::under_way`]: no jolt from a live edit).
    pub(crate) fn forget(&mut self, index: usize, coupling: &Coupling) {
        self.caches[index] = coupling.new_cache();
        self.lines.retain(|run| run.coupling != index);
        if is_dynamic(coupling) {
            let at = self.lines.partition_point(|run| run.coupling < index);
            self.lines.insert(at, LineRun::under_way(index));
        }
    }

    /// Keeps every dynamic line's last evaluation as the start of its next interval: the world
    /// calls it when it accepts an integrator step ([`LineRun::commit`]).
    pub(crate) fn commit_lines(&mut self) {
        for run in &mut self.lines {
            run.commit();
        }
    }

    /// Keeps every potential-flow body's last evaluation as the start of its radiation memory's
    /// next interval: the world calls it when it accepts an integrator step
    /// ([`RadiationRun::commit`]).
    pub(crate) fn commit_radiation(&mut self, stage: Option<&WaterStage>) {
        let Some(stage) = stage else { return };
        for (floating, run) in stage.floating.iter().zip(&mut self.radiation) {
            if let Some(potential) = &floating.potential() {
                run.commit(potential.model().radiation());
            }
        }
    }

    /// Starts the radiation memory of floating body `index` (in the system's order) afresh: the
    /// body at rest before the next evaluation (its potential flow switched on or off).
    pub(crate) fn forget_radiation(&mut self, index: usize) {
        if let Some(run) = self.radiation.get_mut(index) {
            *run = RadiationRun::default();
        }
    }

    /// The run of dynamic line coupling `index` (`None` for another kind or model).
    pub fn line_run(&self, index: usize) -> Option<&LineRun> {
        self.lines.iter().find(|run| run.coupling == index)
    }

    /// Body kinematics at the last evaluation, world axes.
    pub fn frames(&self) -> &[BodyFrame] {
        &self.frames
    }

    /// The load on each body at the last evaluation: couplings and water, plus gravity for
    /// bodies that respond to forces.
    pub fn loads(&self) -> &[Load] {
        &self.loads
    }

    /// What each coupling did at the last evaluation.
    pub fn forces(&self) -> &[CouplingForces] {
        &self.forces
    }

    /// The couplings' elastic energy \[J] at the last evaluation: the sum of their records'
    /// `potential`.
    pub fn elastic_energy(&self) -> f64 {
        self.elastic
    }

    /// What the water did to each floating body at the last evaluation, in the order of the
    /// system's floating bodies (empty without water).
    pub fn water(&self) -> &[WaterForces] {
        &self.water
    }

    /// What the air did to each wind-loaded body at the last evaluation, in the order of the
    /// system's wind-loaded bodies (empty without air).
    pub fn air(&self) -> &[AirForces] {
        &self.air
    }

    /// What each coupling remembers.
    pub fn caches(&self) -> &[CouplingCache] {
        &self.caches
    }

    /// The solved shape of catenary coupling `index` at the last evaluation (`None` for another
    /// kind, or before the first).
    pub fn line_state(&self, index: usize) -> Option<&LineState> {
        match self.caches.get(index) {
            Some(CouplingCache::Catenary(cache)) => cache.last.as_ref(),
            _ => None,
        }
    }

    /// The normal force and friction of contact coupling `index` at the last evaluation, as the
    /// step summed them (`None` for another kind).
    pub fn contact_forces(&self, index: usize) -> Option<ContactForces> {
        match self.caches.get(index) {
            Some(CouplingCache::Contact(cache)) => Some(cache.forces(&self.forces[index])),
            _ => None,
        }
    }
}

/// Whether `coupling` is a dynamic line.
fn is_dynamic(coupling: &Coupling) -> bool {
    match &coupling.kind {
        CouplingKind::Catenary(line) => matches!(line.model(), LineModel::Dynamic(_)),
        CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => false,
    }
}
