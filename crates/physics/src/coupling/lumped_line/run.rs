//! What a run of a dynamic line remembers, and how it advances to the time of the next force
//! evaluation (PHYSICS.md §8 "Time integration").
//!
//! The line keeps the nodes of the last *accepted* integrator step (`committed`, at `t_c`).
//! An evaluation at `t ≥ t_c` with the ends at `p1`, `p2` starts again from them and steps the
//! nodes to `t` in `K = ⌈(t − t_c)/h_s⌉` equal sub-steps of velocity Verlet with its stiff part
//! implicit (kick `½h M⁻¹F` of every force but the segments', the drift under the segments and
//! the seabed's friction by the implicit midpoint rule, [`AxialSolve::step`], forces, kick: the
//! forces of one sub-step's end open the next, one evaluation per sub-step; `h_s` a margin under
//! the seabed's and the transverse stable steps, [`Discrete::substep`]), the ends moving on the
//! straight path from where they were at `t_c` to `p1`, `p2` — the leapfrog's own path for the
//! bodies over a step — and the water's kinematics held at each node's `t_c` position and
//! mid-interval time (in a harmonic sea by powers of one complex number, [`Water::flow_at`]:
//! PHYSICS.md §8 "The waves' kinematics at the nodes", the same sums to round-off at a fraction
//! of the cost; a Runge–Kutta step's two middle stages share their interval, nodes and water, so
//! the second takes the first's kinematics instead of computing the same numbers again (docs/speed.md
//! "Dynamic lines in a sea").
//! The bodies then feel each end node's force at `t`. Evaluating again at the same time or at a
//! stage of a Runge–Kutta step starts from the same committed nodes, so an integrator may
//! evaluate as often as it likes; the world commits the last evaluation when it accepts a step
//! ([`LineRun::commit`]).
//!
//! Energy: the coupling's `potential` is the nodes' kinetic energy (structural mass) with the
//! elastic, wet-weight and seabed energies; the work of everything else on the interior nodes
//! (internal damping, drag, the waves' inertia, the added mass's reaction, the seabed's damping
//! and friction) is summed over the sub-steps — against each kick's mean velocity, and in the
//! segments' solve against the mid-step velocity — with the work of the end nodes' share of the
//! drag and seabed forces on what the ends move with, and reported as the interval's mean
//! dissipated power. The exchange with the bodies is the partitioned scheme's first error: they
//! feel the end forces at `t` while the line felt the ends along their path, a balance error
//! that falls with the bodies' step; the line's own sub-steps add theirs (PHYSICS.md §8 gives the
//! balance `moored_buoy` closes to; the interval's mean force instead of the end force lags by
//! half a step and does worse).

use super::axial::AxialSolve;
use super::discrete::Discrete;
use super::nodes::{self, Damper, Flow, LineNodes, NodeForces};
use super::statics;
use crate::coupling::catenary::Catenary;
use crate::coupling::ends::EndMotion;
use crate::math::Vec3;
use crate::surroundings::Surroundings;
use crate::water::Water;
use crate::water::waves::FlowInstant;

/// Most sub-steps a dynamic line takes over one evaluation's interval: a line whose stable
/// sub-step is shorter than `1/MAX_SUBSTEPS` of the world's step is refused rather than stepped
/// (a stiffness of 10³⁰ N, or a length of 10⁻¹² m, asks for billions of sub-steps per step, a run
/// that never ends). A real mooring line sub-steps tens to a few thousand times per step (MoorDyn's
/// chains at 0.2 ms under a 50 ms step: 250).
pub const MAX_SUBSTEPS: u32 = 100_000;

/// Largest strain `|p₂ − p₁|/L − 1` of the chord at a dynamic line's start: ends more than twice
/// the line's unstretched length `L` apart are not a line that a scene means (steel strains by
/// about 1 %, nylon by at most about 40 % at break), but a length or an end mistyped.
pub const MAX_START_STRAIN: f64 = 1.0;

/// Why a dynamic line cannot be stepped.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum LineError {
    /// Its nodes stopped being finite.
    #[error("the dynamic line diverged at t = {time} s (node {node} not finite; its sub-step was {substep} s)")]
    Diverged { time: f64, node: usize, substep: f64 },
    /// Its stable sub-step `substep` \[s] divides the interval `interval` \[s] into more than
    /// [`MAX_SUBSTEPS`] sub-steps (at the largest segment tension `tension` \[N]).
    #[error(
        "the dynamic line needs {needed:.3e} sub-steps of {substep:.3e} s over a step of {interval:.3e} s (its largest segment tension {tension:.3e} N), more than {MAX_SUBSTEPS}: its stiffness, length or segments make it too stiff to step"
    )]
    TooStiff { needed: f64, substep: f64, interval: f64, tension: f64 },
    /// Its ends start `chord` \[m] apart, more than [`MAX_START_STRAIN`] beyond its length `length`
    /// \[m].
    #[error(
        "the dynamic line's ends are {chord:.6e} m apart, a strain of {strain:.3e} of its length {length:.6e} m (more than {MAX_START_STRAIN}): not a line; check its length and ends"
    )]
    Overstretched { chord: f64, length: f64, strain: f64 },
}

/// What a run of one dynamic line remembers.
#[derive(Debug, Clone, PartialEq)]
pub struct LineRun {
    /// Index of the line's coupling in the system.
    pub coupling: usize,
    /// How its nodes start at its first evaluation.
    start: Start,
    /// The nodes at the last accepted step (`None` before the first evaluation: the line then
    /// starts in its static equilibrium as `start` says).
    committed: Option<LineNodes>,
    /// The mean dissipated power over the interval that led to `committed` \[W].
    committed_power: f64,
    /// The nodes at the last evaluation, and their segments' tensions, end forces and potential
    /// energy there ([`nodes::evaluate_ends`]).
    current: Option<LineNodes>,
    forces: NodeForces,
    /// The mean dissipated power over the last evaluation's interval \[W].
    power: f64,
    /// Sub-steps of the last evaluation's interval, and their length \[s].
    substeps: u32,
    substep: f64,
    /// Scratch: the forces at a sub-step, the water's kinematics at each node, the sea's
    /// amplitudes at the interval's middle time.
    scratch: NodeForces,
    flow: Vec<Flow>,
    sea: FlowInstant,
    /// The middle time \[s] `flow` was filled for from the committed nodes (`None`: to be filled
    /// again; a commit moves the nodes), and the water it was filled in (kept across commits,
    /// cloned only when the water changes). A Runge–Kutta step's two middle stages share their
    /// interval, nodes and water: the second takes the first's flow, the same numbers.
    flow_time: Option<f64>,
    flow_water: Option<Water>,
    /// Scratch of the segments' implicit solve.
    axial: AxialSolve,
    /// Sub-steps taken per stable sub-step ([`Discrete::substep`]): 1; the tests refine it to
    /// measure the sub-step's error.
    refinement: f64,
}

/// How a dynamic line's nodes start (PHYSICS.md §8 "Initial state").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// At rest in the static shape: a world's start and a reset, as MoorDyn's lines start.
    AtRest,
    /// In the static shape, moving as it moves with the ends ([`LineRun::under_way`]): a line
    /// switched to dynamic, or edited, while the world runs.
    UnderWay,
}

/// Time over which the static shape's motion is taken at a start under way \[s] (a forward
/// difference: the ends move by `v δ`, millimetres at the speeds of moored bodies, far above
/// the static solve's precision).
const UNDER_WAY_DT: f64 = 1e-3;

/// Refuses a line whose ends start more than [`MAX_START_STRAIN`] beyond its length apart.
fn check_start_strain(line: &Catenary, ends: &[EndMotion; 2]) -> Result<(), LineError> {
    let chord = (ends[1].position - ends[0].position).norm();
    let strain = chord / line.length() - 1.0;
    if strain > MAX_START_STRAIN {
        return Err(LineError::Overstretched { chord, length: line.length(), strain });
    }
    Ok(())
}

/// The line's static shape between its ends where they are (PHYSICS.md §8 "Initial state"),
/// each node moving as that shape moves while the ends go on at their velocities: `v_i =
/// (r_i(p + v δ) − r_i(p)) / δ`. A line started under way — switched to dynamic, or edited,
/// while its body moves — thus starts as the quasi-static line it replaces was moving, not at
/// rest under ends that move (which jerked the end segments taut: a jolt of tension and of the
/// body's pitch no line has). Ends at rest give the shape at rest.
fn start_under_way(
    line: &Catenary,
    discrete: &Discrete,
    surroundings: &Surroundings,
    ends: &[EndMotion; 2],
    time: f64,
) -> LineNodes {
    let (p1, p2) = (ends[0].position, ends[1].position);
    let mut nodes = statics::solve(line, discrete, surroundings, &p1, &p2, time).nodes;
    let (v1, v2) = (ends[0].velocity, ends[1].velocity);
    if v1 == Vec3::zeros() && v2 == Vec3::zeros() {
        return nodes;
    }
    let moved = (p1 + v1 * UNDER_WAY_DT, p2 + v2 * UNDER_WAY_DT);
    let later = statics::solve(line, discrete, surroundings, &moved.0, &moved.1, time).nodes;
    for (velocity, (now, then)) in nodes.velocities.iter_mut().zip(nodes.positions.iter().zip(&later.positions)) {
        *velocity = (then - now) / UNDER_WAY_DT;
    }
    nodes
}

/// What the line did at an evaluation, for its coupling's record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineOutcome {
    /// Forces exerted on the end bodies \[N].
    pub f1: Vec3,
    pub f2: Vec3,
    /// Kinetic, elastic, wet-weight and seabed energy \[J].
    pub energy: f64,
    /// Mean power taken out by damping, drag and the seabed over the interval \[W].
    pub dissipated_power: f64,
}

impl LineRun {
    /// A run of coupling `coupling` from the start of a world: at its first evaluation, at rest
    /// in its static shape (as MoorDyn's lines start, after its relaxation).
    pub fn new(coupling: usize) -> Self {
        Self::starting(coupling, Start::AtRest)
    }

    /// A run of coupling `coupling` started by a live edit (a line switched to dynamic, or its
    /// values changed, while the world runs): at its first evaluation, in its static shape and
    /// moving as that shape does with the ends ([`Start::UnderWay`]).
    pub fn under_way(coupling: usize) -> Self {
        Self::starting(coupling, Start::UnderWay)
    }

    fn starting(coupling: usize, start: Start) -> Self {
        Self {
            coupling,
            start,
            committed: None,
            committed_power: 0.0,
            current: None,
            forces: NodeForces::default(),
            power: 0.0,
            substeps: 0,
            substep: 0.0,
            scratch: NodeForces::default(),
            flow: Vec::new(),
            sea: FlowInstant::default(),
            flow_time: None,
            flow_water: None,
            axial: AxialSolve::default(),
            refinement: 1.0,
        }
    }

    /// The nodes at the last evaluation.
    pub fn nodes(&self) -> Option<&LineNodes> {
        self.current.as_ref()
    }

    /// The segment tensions at the last evaluation \[N].
    pub fn tensions(&self) -> &[f64] {
        &self.forces.tensions
    }

    /// Sub-steps of the last evaluation's interval and their length \[s].
    pub fn substeps(&self) -> (u32, f64) {
        (self.substeps, self.substep)
    }

    /// Keeps the last evaluation's nodes as the start of the next interval (the world calls it
    /// when it accepts an integrator step).
    pub fn commit(&mut self) {
        if let Some(current) = &self.current {
            match &mut self.committed {
                Some(committed) => committed.clone_from(current),
                None => self.committed = Some(current.clone()),
            }
            self.committed_power = self.power;
            self.flow_time = None;
        }
    }

    /// The line (`line`, constants `discrete`) at `time` \[s] with its ends at `ends`, in the
    /// water `water` if any: steps the nodes from the committed ones and gives the end forces.
    ///
    /// # Errors
    /// A node that is no longer finite.
    pub fn advance(
        &mut self,
        line: &Catenary,
        discrete: &Discrete,
        surroundings: &Surroundings,
        water: Option<&Water>,
        ends: &[EndMotion; 2],
        time: f64,
    ) -> Result<LineOutcome, LineError> {
        let committed = match self.committed.take() {
            Some(committed) if committed.time <= time => committed,
            _ => {
                self.committed_power = 0.0;
                self.flow_time = None;
                check_start_strain(line, ends)?;
                match self.start {
                    Start::AtRest => {
                        let (p1, p2) = (ends[0].position, ends[1].position);
                        statics::solve(line, discrete, surroundings, &p1, &p2, time).nodes
                    }
                    Start::UnderWay => start_under_way(line, discrete, surroundings, ends, time),
                }
            }
        };
        let mut nodes = self.current.take().unwrap_or_else(|| committed.clone());
        nodes.clone_from(&committed);
        let start = committed.time;
        self.committed = Some(committed);
        let interval = time - start;
        let n = discrete.segments;
        if interval > 0.0 {
            let tension = nodes.largest_elastic_tension(discrete);
            let substep = discrete.substep(tension) / self.refinement;
            let needed = (interval / substep).ceil();
            // NaN (a non-finite tension) is refused too: the nodes' check would not see it.
            if !(needed <= f64::from(MAX_SUBSTEPS)) {
                return Err(LineError::TooStiff { needed, substep, interval, tension });
            }
            // At least one sub-step, at most MAX_SUBSTEPS (checked above).
            let count = needed.max(1.0) as u32;
            let h = interval / f64::from(count);
            self.fill_flow(water, &nodes, start + 0.5 * interval);
            let work = self.step_nodes(discrete, &mut nodes, ends, count, h)?;
            self.power = -work / interval;
            (self.substeps, self.substep) = (count, h);
        } else {
            self.power = self.committed_power;
            self.substeps = 0;
        }
        for (end, node) in [(0, 0), (1, n)] {
            nodes.positions[node] = ends[end].position;
            nodes.velocities[node] = ends[end].velocity;
        }
        nodes.time = time;
        nodes::evaluate_ends(discrete, &nodes, &self.flow, &mut self.forces);
        let outcome = LineOutcome {
            f1: self.forces.total[0],
            f2: self.forces.total[n],
            energy: self.forces.potential + nodes.kinetic_energy(discrete),
            dissipated_power: self.power,
        };
        self.current = Some(nodes);
        Ok(outcome)
    }

    /// The water's velocity and acceleration at each node at `time` (none without water),
    /// unless they were filled for the same committed nodes, time and water.
    fn fill_flow(&mut self, water: Option<&Water>, nodes: &LineNodes, time: f64) {
        let same_water = self.flow_water.as_ref() == water;
        if same_water && self.flow_time == Some(time) && self.flow.len() == nodes.positions.len() {
            return;
        }
        if !same_water {
            self.flow_water = water.cloned();
        }
        self.flow_time = Some(time);
        let Some(water) = water else {
            self.flow.clear();
            return;
        };
        water.flow_instant(time, &mut self.sea);
        self.flow.clear();
        self.flow.extend(nodes.positions.iter().map(|p| water.flow_at(&self.sea, p)));
    }

    /// `count` sub-steps of `h` \[s] from `nodes`, the ends moving straight from where they are
    /// to `ends`: each a half kick of the forces but the segments', the nodes' drift under their
    /// segments taken implicitly ([`AxialSolve::step`]), the forces at the new places, the
    /// closing half kick (one evaluation per sub-step: a sub-step's closing forces open the
    /// next). Returns the work of the forces without potential on the nodes \[J].
    fn step_nodes(
        &mut self,
        line: &Discrete,
        nodes: &mut LineNodes,
        ends: &[EndMotion; 2],
        count: u32,
        h: f64,
    ) -> Result<f64, LineError> {
        let n = line.segments;
        let interval = h * f64::from(count);
        let from = [nodes.positions[0], nodes.positions[n]];
        let speed = [(ends[0].position - from[0]) / interval, (ends[1].position - from[1]) / interval];
        let place_ends = |nodes: &mut LineNodes, elapsed: f64| {
            for (end, node) in [(0, 0), (1, n)] {
                nodes.positions[node] = from[end] + speed[end] * elapsed;
                nodes.velocities[node] = speed[end];
            }
        };
        place_ends(nodes, 0.0);
        nodes::evaluate_surroundings(line, nodes, &self.flow, &mut self.scratch);
        let mut work = self.half_kick(line, nodes, 0.5 * h);
        let mut start_unbooked = [self.scratch.unbooked[0], self.scratch.unbooked[n]];
        for k in 1..=count {
            let elapsed = h * f64::from(k);
            work += self.axial.step(line, &self.scratch, &mut nodes.positions, &mut nodes.velocities, h);
            place_ends(nodes, elapsed);
            nodes::evaluate_surroundings(line, nodes, &self.flow, &mut self.scratch);
            self.axial.close(&mut nodes.velocities[..n]);
            // The closing half kick of this step and, but for the last, the opening one of
            // the next: one evaluation per sub-step.
            work += self.half_kick(line, nodes, if k == count { 0.5 * h } else { h });
            // What the ends' share of the seabed's damping and friction and of the drag does to
            // the bodies they move with (trapezoid over the sub-step, the ends at constant speed).
            work += 0.5
                * h
                * (speed[0].dot(&(start_unbooked[0] + self.scratch.unbooked[0]))
                    + speed[1].dot(&(start_unbooked[1] + self.scratch.unbooked[n])));
            start_unbooked = [self.scratch.unbooked[0], self.scratch.unbooked[n]];
            if let Some(i) =
                (1..n).find(|&i| !nodes.positions[i].iter().chain(&nodes.velocities[i]).all(|c| c.is_finite()))
            {
                return Err(LineError::Diverged { time: nodes.time + elapsed, node: i, substep: h });
            }
        }
        Ok(work)
    }

    /// `v ← v + τ M⁻¹F` on the interior nodes with the forces in the scratch, the seabed's
    /// damping across the bottom at the closing velocity (`(M + τ c_n ûûᵀ)⁻¹`,
    /// [`NodeForces::solve_damped`]; its friction is the segments' solve's, [`AxialSolve::step`]);
    /// returns the work of the forces without potential over the kick, against the kick's mean
    /// velocity \[J].
    fn half_kick(&self, line: &Discrete, nodes: &mut LineNodes, tau: f64) -> f64 {
        let mut work = 0.0;
        for i in 1..line.segments {
            let before = nodes.velocities[i];
            let pushed = self.scratch.total[i] + self.scratch.seabed_force(i, Damper::Normal, &before, &line.up);
            let acceleration = self.scratch.solve_damped(i, Damper::Normal, &line.up, tau, &pushed);
            let after = before + acceleration * tau;
            let mass = line.mass_per_length * line.share(i);
            let unbooked = self.scratch.unbooked[i] + self.scratch.seabed_force(i, Damper::Normal, &after, &line.up)
                - self.scratch.added_mass_force(i, mass, &acceleration);
            work += tau * 0.5 * (before + after).dot(&unbooked);
            nodes.velocities[i] = after;
        }
        work
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupling::catenary::Catenary;
    use crate::coupling::ends::{Attachment, Endpoint};
    use crate::coupling::lumped_line::{InternalDamping, LineModel, LumpedMass, LumpedMassSpec};
    use crate::seabed::Seabed;
    use crate::water::{CurrentProfile, CurrentSpec, WaterSpec, WaveSpec};

    /// One of `moored_buoy`'s chains (MoorDyn's chain of docs/dynamic-lines.md, N = 40) from its
    /// anchor at (−237, 0, −50) m to a fairlead at (0, 0, −1) m, on sand under the scene's
    /// current, in a 50-component JONSWAP sea (H_s 2.5 m, T_p 9 s).
    fn chain_in_a_jonswap_sea() -> (Catenary, Discrete, Surroundings, Water) {
        let gravity = Vec3::new(0.0, 0.0, -9.80665);
        let spec = WaterSpec {
            depth: Some(50.0),
            current: CurrentSpec { speed: 0.5, heading: 0.0, profile: CurrentProfile::PowerLaw },
            waves: WaveSpec::Jonswap {
                significant_height: 2.5,
                peak_period: 9.0,
                gamma: 3.3,
                heading: 0.0,
                components: 50,
                seed: 1,
            },
            ..WaterSpec::default()
        };
        let water = Water::new(spec, &gravity).expect("the scene's water");
        let chain = LumpedMass::new(LumpedMassSpec {
            drag_normal: 2.4,
            drag_tangential: 1.15,
            added_mass_normal: 1.0,
            added_mass_tangential: 0.5,
            ..LumpedMassSpec::plain(40, InternalDamping::Ratio(0.8))
        })
        .expect("valid");
        let (anchor, fairlead) = (Vec3::new(-237.0, 0.0, -50.0), Vec3::new(0.0, 0.0, -1.0));
        let line = Catenary::new(Endpoint::World(anchor), Endpoint::World(fairlead), 25.79, 250.0, 442714.0)
            .and_then(|l| l.with_displaced_area(0.003298))
            .expect("the scene's chain")
            .with_model(LineModel::Dynamic(chain));
        let seabed = Seabed::new(-50.0, 1.0).expect("sand at the water's depth");
        let surroundings = Surroundings { fluid_density: 1025.0, seabed: Some(seabed), ..Surroundings::dry(gravity) };
        let discrete = Discrete::new(&line, &chain, &surroundings, Some(0.0));
        (line, discrete, surroundings, water)
    }

    /// [`chain_in_a_jonswap_sea`]'s fairlead driven `x = 2 sin(2πt/10)` m: the fairlead tension
    /// with the waves' kinematics by powers of one complex number ([`Water::flow_at`],
    /// harmonic) against the same sea summed component by component (the way the nodes'
    /// kinematics were computed before), 60 s at the scene's 50 ms evaluations.
    #[test]
    fn the_harmonic_kinematics_give_the_fairlead_tensions_of_the_sum_by_component() {
        let (line, discrete, surroundings, harmonic) = chain_in_a_jonswap_sea();
        let by_component = harmonic.summed_by_component();
        assert!(harmonic.sea().is_harmonic() && !by_component.sea().is_harmonic());
        let (anchor, fairlead) = (Vec3::new(-237.0, 0.0, -50.0), Vec3::new(0.0, 0.0, -1.0));
        let mut runs = [LineRun::new(0), LineRun::new(0)];
        let (mut largest, mut peak) = (0.0_f64, 0.0_f64);
        for step in 1..=1200 {
            let time = 0.05 * f64::from(step);
            let omega = std::f64::consts::TAU / 10.0;
            let driven = EndMotion {
                position: fairlead + Vec3::x() * (2.0 * (omega * time).sin()),
                velocity: Vec3::x() * (2.0 * omega * (omega * time).cos()),
                attachment: Attachment::World,
            };
            let fixed = EndMotion { position: anchor, velocity: Vec3::zeros(), attachment: Attachment::World };
            let tension = |run: &mut LineRun, water: &Water| {
                let outcome = run.advance(&line, &discrete, &surroundings, Some(water), &[fixed, driven], time);
                run.commit();
                outcome.expect("the chain stays finite").f2.norm()
            };
            let [first, second] = &mut runs;
            let (a, b) = (tension(first, &harmonic), tension(second, &by_component));
            largest = largest.max((a - b).abs() / b);
            peak = peak.max(b);
        }
        eprintln!("fairlead tension: peak {peak} N, harmonic against by component {largest:.2e} relative at most");
        // The sea's pull shows: the peak is well above the 33 kN at rest.
        assert!(peak > 40.0e3, "peak {peak} N");
        assert!(largest < 1e-3, "{largest:.2e}");
    }

    /// [`chain_in_a_jonswap_sea`]'s fairlead driven `x = 2 sin(2πt/10)` m for 60 s at 50 ms
    /// evaluations, the fairlead tensions from each evaluation at `refinement` sub-steps per
    /// stable sub-step.
    fn driven_fairlead_tensions(refinement: f64) -> Vec<f64> {
        let (line, discrete, surroundings, water) = chain_in_a_jonswap_sea();
        let (anchor, fairlead) = (Vec3::new(-237.0, 0.0, -50.0), Vec3::new(0.0, 0.0, -1.0));
        let mut run = LineRun { refinement, ..LineRun::new(0) };
        let omega = std::f64::consts::TAU / 10.0;
        (1..=1200)
            .map(|step| {
                let time = 0.05 * f64::from(step);
                let driven = EndMotion {
                    position: fairlead + Vec3::x() * (2.0 * (omega * time).sin()),
                    velocity: Vec3::x() * (2.0 * omega * (omega * time).cos()),
                    attachment: Attachment::World,
                };
                let fixed = EndMotion { position: anchor, velocity: Vec3::zeros(), attachment: Attachment::World };
                let outcome = run.advance(&line, &discrete, &surroundings, Some(&water), &[fixed, driven], time);
                run.commit();
                outcome.expect("the chain stays finite").f2.norm()
            })
            .collect()
    }

    /// The segments taken implicitly let the chain sub-step at its seabed limit (18 ms, 3
    /// sub-steps per 50 ms; the explicit axial limit is 1.45 ms): over the last 50 s of
    /// [`driven_fairlead_tensions`], the fairlead tension at that sub-step stays within 1.5 % of
    /// the peak of the same run at 8 sub-steps per stable one (1.4 %, where the tension turns in
    /// the trough), its peak and mean within 0.5 % (+0.09 %, +0.04 %).
    #[test]
    fn the_chain_sub_stepped_at_its_seabed_limit_gives_the_refined_tensions() {
        let (_, discrete, _, _) = chain_in_a_jonswap_sea();
        assert!(discrete.limits().axial < 1.5e-3 && discrete.substep(4.0e4) > 18e-3, "{:?}", discrete.limits());
        let (coarse, fine) = (driven_fairlead_tensions(1.0), driven_fairlead_tensions(8.0));
        let settled = 200..coarse.len();
        let peak = |t: &[f64]| t[settled.clone()].iter().copied().fold(0.0, f64::max);
        let mean = |t: &[f64]| t[settled.clone()].iter().sum::<f64>() / settled.len() as f64;
        let largest = settled.clone().map(|i| (coarse[i] - fine[i]).abs()).fold(0.0, f64::max) / peak(&fine);
        let (peak_error, mean_error) = (peak(&coarse) / peak(&fine) - 1.0, mean(&coarse) / mean(&fine) - 1.0);
        eprintln!(
            "fairlead tension, 18 ms sub-steps against 2.3 ms: peak {:.0} / {:.0} N ({peak_error:+.2e}), mean \
             {:.0} / {:.0} N ({mean_error:+.2e}), largest difference {largest:.2e} of the peak",
            peak(&coarse),
            peak(&fine),
            mean(&coarse),
            mean(&fine)
        );
        assert!(largest < 1.5e-2, "{largest:.2e}");
        assert!(peak_error.abs() < 5e-3 && mean_error.abs() < 5e-3, "{peak_error:.2e} {mean_error:.2e}");
    }

    /// [`chain_in_a_jonswap_sea`]'s chain with another length or stiffness, its ends held, over
    /// ten evaluations 50 ms apart: the first error, if any.
    fn ten_steps_of(length: f64, stiffness: f64) -> Result<(), LineError> {
        let (line, _, surroundings, water) = chain_in_a_jonswap_sea();
        let LineModel::Dynamic(chain) = line.model() else { unreachable!("the chain is dynamic") };
        let (anchor, fairlead) = (Vec3::new(-237.0, 0.0, -50.0), Vec3::new(0.0, 0.0, -1.0));
        let line = Catenary::new(Endpoint::World(anchor), Endpoint::World(fairlead), 25.79, length, stiffness)
            .expect("finite positive values")
            .with_model(line.model());
        let discrete = Discrete::new(&line, &chain, &surroundings, Some(0.0));
        let at = |position| EndMotion { position, velocity: Vec3::zeros(), attachment: Attachment::World };
        let mut run = LineRun::new(0);
        let ends = [at(anchor), at(fairlead)];
        for step in 0..=10 {
            run.advance(&line, &discrete, &surroundings, Some(&water), &ends, 0.05 * f64::from(step))?;
            run.commit();
        }
        Ok(())
    }

    /// The two lines of issue 48 that ran for ever: a chain 10⁻¹² m long between ends 237 m
    /// apart (a strain of 2.4·10¹⁴) is refused at its start, naming the strain; one 10³⁰ N
    /// stiff (whose round-off strain of 10⁻¹⁶ is a tension of 10¹⁴ N that grows with each
    /// interval) is refused within ten, naming the sub-steps it would need. The chain itself
    /// steps in 3 sub-steps of 16.7 ms, far inside the bound.
    #[test]
    fn a_line_that_cannot_be_stepped_is_refused_not_stepped_for_ever() {
        match ten_steps_of(1e-12, 442714.0) {
            Err(LineError::Overstretched { strain, .. }) => assert!((strain / 2.41e14 - 1.0).abs() < 1e-2, "{strain}"),
            other => panic!("{other:?}"),
        }
        let refused = ten_steps_of(250.0, 1e30).unwrap_err();
        let LineError::TooStiff { needed, .. } = refused else { panic!("{refused:?}") };
        assert!(needed > f64::from(MAX_SUBSTEPS), "{needed}");
        assert!(refused.to_string().contains("more than 100000"), "{refused}");
        let (line, discrete, surroundings, water) = chain_in_a_jonswap_sea();
        let at = |position| EndMotion { position, velocity: Vec3::zeros(), attachment: Attachment::World };
        let ends = [at(Vec3::new(-237.0, 0.0, -50.0)), at(Vec3::new(0.0, 0.0, -1.0))];
        let mut run = LineRun::new(0);
        run.advance(&line, &discrete, &surroundings, Some(&water), &ends, 0.0).expect("the chain starts");
        run.commit();
        run.advance(&line, &discrete, &surroundings, Some(&water), &ends, 0.05).expect("the chain steps");
        assert!(run.substeps().0 <= 3, "{:?}", run.substeps());
    }

    /// A Runge–Kutta step's evaluations of [`chain_in_a_jonswap_sea`] 12 s in (its middle twice
    /// with the fairlead at two places, then its end): the second middle stage takes the
    /// first's flow, and its end forces are those of a run that fills the flow afresh, to the
    /// bit; after the step is committed, or in other water, the flow is filled again.
    #[test]
    fn a_second_stage_at_the_same_time_takes_the_first_stage_s_flow() {
        let (line, discrete, surroundings, water) = chain_in_a_jonswap_sea();
        let anchor = EndMotion {
            position: Vec3::new(-237.0, 0.0, -50.0),
            velocity: Vec3::zeros(),
            attachment: Attachment::World,
        };
        let fairlead = |x: f64| EndMotion {
            position: Vec3::new(x, 0.0, -1.0),
            velocity: Vec3::x() * (x / 0.025),
            attachment: Attachment::World,
        };
        let (start, middle) = (12.0, 12.025);
        // The interval's middle time and whether the flow was filled in `water`.
        let filled_for =
            |run: &LineRun, water: &Water| run.flow_time.map(|time| (time, run.flow_water.as_ref() == Some(water)));
        let mut run = LineRun::new(0);
        let evaluate = |run: &mut LineRun, water: &Water, x: f64, time: f64| {
            run.advance(&line, &discrete, &surroundings, Some(water), &[anchor, fairlead(x)], time)
                .expect("the chain stays finite")
        };
        evaluate(&mut run, &water, 0.0, start);
        run.commit();
        assert_eq!(filled_for(&run, &water), None);
        evaluate(&mut run, &water, 0.01, middle);
        assert_eq!(filled_for(&run, &water), Some((12.0125, true)));
        let mut fresh = run.clone();
        fresh.flow_time = None;
        fresh.flow.clear();
        let (second, afresh) = (evaluate(&mut run, &water, 0.02, middle), evaluate(&mut fresh, &water, 0.02, middle));
        assert_eq!((second.f1, second.f2, second.energy), (afresh.f1, afresh.f2, afresh.energy));
        assert_ne!(second.f2, evaluate(&mut run.clone(), &water, 0.01, middle).f2, "the fairlead's place shows");
        let calmer = Water::new(WaterSpec { waves: WaveSpec::Calm, ..*water.spec() }, &surroundings.gravity)
            .expect("the same water without waves");
        let calm = evaluate(&mut run, &calmer, 0.02, middle);
        assert_eq!(filled_for(&run, &calmer), Some((12.0125, true)));
        assert_ne!(calm.f2, second.f2, "the waves' pull is gone");
        evaluate(&mut run, &water, 0.04, 12.05);
        run.commit();
        assert_eq!(filled_for(&run, &water), None);
    }
}
