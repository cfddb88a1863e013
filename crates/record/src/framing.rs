//! The 3D view's default camera: what moves, framed (docs/window.md, "The view").
//!
//! A copy of the world is run over its first [`FRAMED_SECONDS`] (at most [`MAX_FRAMING_STEPS`]
//! world steps; up to a divergence, if one comes first) — or the run itself is followed as it
//! goes ([`MotionSweep`]: the same poses, no second run) — and every body that is not held fixed is
//! swept: the corners of its shape's bounding box at each sampled pose. A spring-damper's
//! world anchor near that box (within [`ANCHOR_REACH`] times its half-diagonal, plus a metre) is
//! framed with it (a short line's tie point: the chain's ends, the fender's ropes); a far one is
//! not, nor is a mooring line's anchor (hundreds of metres away, it would shrink the floater to
//! a few pixels: the line is drawn leaving the frame towards it) — unless a prescribed motion
//! drives the line (a catenary with an end on a kinematic body, `chain_forced_surge`): the line
//! is then what the scene is about, and its ends and a dynamic line's nodes are swept with the
//! bodies (the driver alone framed a big sphere over the seabed). The eye looks at the
//! centre of that box from [`VIEW_DIRECTION`], far enough for the box's bounding sphere to fit a
//! view narrower than it is tall; where a contact presses a body against a wall (a plane whose
//! normal is closer to horizontal than to vertical: a quay), from behind the wall instead, the
//! same way turned (the wall is drawn as a grid of lines and hides nothing; from the bodies' side
//! a ship's hull would hide the fender between it and the quay).
//!
//! Framing from a run rather than the pose at t = 0 is what shows a crate's hop, a ball rolling
//! away and a trolley travelling; a camera written in each scene file was considered, but it
//! would go stale with every edit of the scene, where the run frames what the scene does.

use tether_physics::body::{RigidBody, Shape, Support};
use tether_physics::coupling::contact::Opposing;
use tether_physics::coupling::{CouplingKind, Endpoint};
use tether_physics::math::{Vec3, bounding_box};
use tether_physics::world::World;

/// Simulated time over which what moves is swept \[s].
pub const FRAMED_SECONDS: f64 = 5.0;

/// At most this many world steps are run for the framing (a scene with a small step is framed
/// over a shorter time rather than delaying its start).
pub const MAX_FRAMING_STEPS: u64 = 10_000;

/// How far from what moves a spring's anchor is still framed, in half-diagonals of the box of
/// what moves (plus a metre): a spar's yaw springs tied 1.4 km away are not.
pub const ANCHOR_REACH: f64 = 2.0;

/// Poses sampled per simulated second.
const SAMPLES_PER_SECOND: f64 = 20.0;

/// From the target towards the eye (not normalised): in front (−y) and a little to the right
/// (+x), 25° above the horizon, so that x runs left to right and z up.
pub const VIEW_DIRECTION: [f64; 3] = [0.45, -1.0, 0.52];

/// Half the narrower opening angle of the view the box must fit \[rad]: Rerun's vertical field of
/// view is 55°; the 3D view beside the plots and the panel is often narrower than it is tall
/// (aspect 0.8: atan(0.8 tan 27.5°) = 22.6°).
const HALF_OPENING: f64 = 0.394;

/// The smallest radius framed \[m] (a point-like body at rest).
const MIN_RADIUS: f64 = 0.25;

/// Where the eye is and what it looks at, z up \[m].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Framing {
    pub eye: Vec3,
    pub target: Vec3,
}

impl Framing {
    /// The framing of `world`'s run from its current state (a copy of it is run).
    pub fn of(world: &World) -> Self {
        Self::around(&swept_box(world), &view_direction(world))
    }

    /// The eye looking at the centre of the box `(low, high)` from `direction` (towards the eye,
    /// any length), the box's bounding sphere filling the narrower opening of the view.
    pub fn around((low, high): &(Vec3, Vec3), direction: &Vec3) -> Self {
        let target = (low + high) / 2.0;
        let radius = ((high - low).norm() / 2.0).max(MIN_RADIUS);
        Self { eye: target + direction.normalize() * (radius / HALF_OPENING.sin()), target }
    }
}

/// From the target towards the eye: [`VIEW_DIRECTION`], or from behind the first wall a contact
/// presses against, with [`VIEW_DIRECTION`]'s sideways and upward parts.
pub fn view_direction(world: &World) -> Vec3 {
    let [side, behind, up] = VIEW_DIRECTION;
    let wall = world.couplings().iter().find_map(|coupling| match &coupling.kind {
        CouplingKind::Contact(contact) => match &contact.against() {
            Opposing::Planes(planes) => planes.iter().map(|plane| plane.normal.normalize()).find(|n| n.z.abs() < 0.5),
            Opposing::Body { .. } => None,
        },
        CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => None,
    });
    match wall {
        Some(normal) => {
            let out_of_wall = Vec3::new(normal.x, normal.y, 0.0).normalize();
            let along_wall = out_of_wall.cross(&Vec3::z());
            -out_of_wall * behind.abs() + along_wall * side + Vec3::z() * up
        }
        None => Vec3::from(VIEW_DIRECTION),
    }
}

/// The box holding every moving body's shape over the first [`FRAMED_SECONDS`] of a copy of
/// `world`, and the spring-dampers' world anchors near it; every body's at its current pose when
/// none moves.
pub fn swept_box(world: &World) -> (Vec3, Vec3) {
    MotionSweep::start(world).finish(world)
}

/// What moves, swept as a run goes: every framed body's corners at its pose now, then 20 times
/// a simulated second over the first [`FRAMED_SECONDS`] (at most
/// [`MAX_FRAMING_STEPS`] world steps; up to a failed step, if one comes first). A caller that
/// steps the world anyway (`tether record`) feeds it its own steps and spares the copy's run,
/// which is as long as the first half of `chain100`'s bench run; [`swept_box`] runs a copy.
pub struct MotionSweep {
    /// The bodies framed: those that move, or all when none does.
    framed: Vec<usize>,
    /// The couplings framed whole: the lines a prescribed motion drives ([`driven_lines`]).
    lines: Vec<usize>,
    /// Each body's box corners (and slave nodes) in its principal frame \[m].
    corners: Vec<Vec<Vec3>>,
    /// The corners sampled so far, in the world \[m].
    points: Vec<Vec3>,
    /// World steps swept, and taken so far.
    steps: u64,
    taken: u64,
    /// Steps between samples.
    every: u64,
    /// A step failed: the sweep ends there.
    halted: bool,
}

impl MotionSweep {
    /// A sweep of a run starting at `world`'s current state, its first sample taken.
    pub fn start(world: &World) -> Self {
        let bodies = world.bodies();
        let moving: Vec<usize> = (0..bodies.len()).filter(|&i| !held_fixed(&bodies[i].support)).collect();
        let framed: Vec<usize> = if moving.is_empty() { (0..bodies.len()).collect() } else { moving };
        let dt = world.dt();
        let mut sweep = Self {
            framed,
            lines: driven_lines(world),
            corners: bodies.iter().map(corners_in_principal).collect(),
            points: Vec::new(),
            steps: ((FRAMED_SECONDS / dt).ceil() as u64).min(MAX_FRAMING_STEPS),
            taken: 0,
            every: ((1.0 / (SAMPLES_PER_SECOND * dt)).round() as u64).max(1),
            halted: false,
        };
        sweep.sample(world);
        sweep
    }

    /// Follows one more world step that succeeded, `world` its state after it.
    pub fn after_step(&mut self, world: &World) {
        if self.is_complete() {
            return;
        }
        self.taken += 1;
        if self.taken.is_multiple_of(self.every) {
            self.sample(world);
        }
    }

    /// Ends the sweep at a step that failed (the run's framing is what it did up to there).
    pub fn halt(&mut self) {
        self.halted = true;
    }

    /// Whether every step swept has been taken (or one failed).
    pub fn is_complete(&self) -> bool {
        self.halted || self.taken >= self.steps
    }

    /// The box of what was swept and of the spring-dampers' world anchors near it, the steps not
    /// taken yet (a run shorter than the sweep, or interrupted) run on a copy of `world`, the
    /// state after the steps taken.
    pub fn finish(mut self, world: &World) -> (Vec3, Vec3) {
        if !self.is_complete() {
            let mut run = world.clone();
            while !self.is_complete() {
                match run.step() {
                    Ok(()) => self.after_step(&run),
                    Err(_) => self.halt(),
                }
            }
        }
        let finite: Vec<Vec3> = self.points.into_iter().filter(|p| p.iter().all(|c| c.is_finite())).collect();
        if finite.is_empty() {
            return (Vec3::zeros(), Vec3::zeros());
        }
        let (low, high) = bounding_box(finite);
        let reach = ANCHOR_REACH * (high - low).norm() / 2.0 + 1.0;
        let near = |p: &Vec3| (p - p.sup(&low).inf(&high)).norm() <= reach;
        bounding_box(spring_anchors(world).filter(near).chain([low, high]))
    }

    /// Adds the framed bodies' corners at `world`'s poses, and the driven lines' ends and nodes.
    fn sample(&mut self, world: &World) {
        for &index in &self.framed {
            let state = world.state(index);
            self.points.extend(self.corners[index].iter().map(|corner| state.point(corner)));
        }
        for &index in &self.lines {
            let ends = &world.coupling_forces()[index];
            self.points.extend([ends.point1, ends.point2]);
            if let Some(nodes) = world.evaluation().line_run(index).and_then(|run| run.nodes()) {
                self.points.extend(nodes.positions.iter().copied());
            }
        }
    }
}

/// Whether a support holds the body still: every translation and the rotation fixed.
fn held_fixed(support: &Support) -> bool {
    match support {
        Support::Fixed { translation, rotation } => translation.iter().all(|&fixed| fixed) && *rotation,
        Support::Free | Support::Kinematic(_) => false,
    }
}

/// The catenaries (quasi-static or dynamic) with an end on a kinematic body, by coupling index.
fn driven_lines(world: &World) -> Vec<usize> {
    let kinematic = |end: &Endpoint| end.body().is_some_and(|body| world.bodies()[body].is_kinematic());
    (0..world.couplings().len())
        .filter(|&index| match &world.couplings()[index].kind {
            CouplingKind::Catenary(line) => kinematic(&line.end1()) || kinematic(&line.end2()),
            CouplingKind::SpringDamper(_) | CouplingKind::Contact(_) => false,
        })
        .collect()
}

/// The world ends of the spring-dampers \[m].
fn spring_anchors(world: &World) -> impl Iterator<Item = Vec3> + '_ {
    world.couplings().iter().flat_map(|coupling| {
        let ends = match &coupling.kind {
            CouplingKind::SpringDamper(spring) => vec![spring.end1(), spring.end2()],
            CouplingKind::Catenary(_) | CouplingKind::Contact(_) => Vec::new(),
        };
        ends.into_iter().filter_map(|end| match end {
            Endpoint::World(point) => Some(point),
            Endpoint::Body { .. } | Endpoint::Center { .. } => None,
        })
    })
}

/// The corners of the box bounding `body`'s shape and slave nodes, in its principal frame \[m].
fn corners_in_principal(body: &RigidBody) -> Vec<Vec3> {
    let (low, high) = match &body.shape {
        Shape::Box { size, center, .. } => (center - size / 2.0, center + size / 2.0),
        Shape::Sphere { radius, center, .. } => (center - Vec3::repeat(*radius), center + Vec3::repeat(*radius)),
        Shape::Cylinder { radius, length, axis, center } => {
            let half = axis * (length / 2.0);
            let (a, b) = (center - half, center + half);
            (a.inf(&b) - Vec3::repeat(*radius), a.sup(&b) + Vec3::repeat(*radius))
        }
        Shape::Mesh { vertices, .. } => bounding_box(vertices.iter().copied()),
    };
    let in_principal = |p: Vec3| body.reference_in_principal.transform_point(&p.into()).coords;
    let mut corners: Vec<Vec3> = (0..8)
        .filter(|_| low.iter().all(|c| c.is_finite()))
        .map(|i| Vec3::new(pick(i & 1, low.x, high.x), pick(i & 2, low.y, high.y), pick(i & 4, low.z, high.z)))
        .map(in_principal)
        .collect();
    corners.extend(body.slave_nodes.iter().copied());
    if corners.is_empty() {
        corners.push(Vec3::zeros());
    }
    corners
}

/// `high` when `bit` is set, `low` otherwise.
fn pick(bit: usize, low: f64, high: f64) -> f64 {
    if bit == 0 { low } else { high }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_eye_sees_the_box_within_the_opening() {
        let direction = Vec3::from(VIEW_DIRECTION);
        let framing = Framing::around(&(Vec3::new(-1.0, -2.0, 0.0), Vec3::new(3.0, 2.0, 2.0)), &direction);
        assert_eq!(framing.target, Vec3::new(1.0, 0.0, 1.0));
        // Half-diagonal 3 m: the sphere of radius 3 is seen under exactly the half opening.
        let distance = (framing.eye - framing.target).norm();
        assert!(((3.0 / distance).asin() - HALF_OPENING).abs() < 1e-12);
        let towards_eye = (framing.eye - framing.target).normalize();
        assert!((towards_eye - direction.normalize()).norm() < 1e-12);
    }

    #[test]
    fn a_point_is_framed_at_the_smallest_radius() {
        let framing = Framing::around(&(Vec3::new(1.0, 1.0, 1.0), Vec3::new(1.0, 1.0, 1.0)), &Vec3::x());
        assert!(((framing.eye - framing.target).norm() - MIN_RADIUS / HALF_OPENING.sin()).abs() < 1e-12);
    }
}
