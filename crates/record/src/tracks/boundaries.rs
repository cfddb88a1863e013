//! What the bodies are held by and pressed against, drawn once, statically:
//!
//! - `world/boundaries/<contact>`: each half-space a contact pushes its body away from (a ground,
//!   a quay wall, a domain box's walls; PHYSICS.md §4), under the first contact against it (a
//!   ground under a hundred balls is drawn once), as a square of its plane, covering what
//!   moves over the first seconds ([`crate::framing::swept_box`]) projected onto it, 20 % wider,
//!   at least [`MIN_HALF_SIDE`] from its centre, drawn as a grid of lines: a wall seen from
//!   behind hides nothing of what presses against it; a body a contact is against is drawn as a
//!   body already;
//! - `world/anchors`: every coupling end fixed in the world (a spring's or a line's anchor) as a
//!   point, so that no rope is tied to nothing (the lines' ends: a contact has none).

use super::{Settings, Track, f32x3};
use crate::frames::Frames;
use crate::rerun;
use crate::stats::KindStats;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use tether_physics::coupling::contact::{Opposing, Plane};
use tether_physics::coupling::{CouplingKind, Endpoint};
use tether_physics::math::Vec3;
use tether_physics::world::World;

/// Concrete grey for the walls and grounds; dark red for the anchors.
const BOUNDARY_RGB: [u8; 3] = [175, 170, 160];
const ANCHOR_RGB: [u8; 3] = [150, 40, 30];

/// Half the side of the smallest patch drawn \[m].
const MIN_HALF_SIDE: f64 = 1.0;

/// Cells along each side of a patch's grid.
const GRID_CELLS: u32 = 8;

/// A grid line's width [UI points].
const LINE_POINTS: f32 = 1.5;

/// An anchor's radius on screen [UI points]: seen at any distance (a mooring line's anchor is
/// hundreds of metres away).
const ANCHOR_POINTS: f32 = 6.0;

/// The world's contact planes and anchors (`None` when it has neither).
pub(super) struct Boundaries {
    /// Each contact's name and the planes no earlier contact is against.
    planes: Vec<(String, Vec<Plane>)>,
    anchors: Vec<Vec3>,
}

impl Boundaries {
    pub(super) fn new(world: &World) -> Option<Self> {
        // Each plane once, with the first contact against it: chain100's hundred balls each
        // have a contact against the same ground, drawn as one grid rather than a hundred
        // identical ones (a hundred chunks for the file writer, a hundred grids for the viewer).
        let mut drawn: Vec<Plane> = Vec::new();
        let mut planes: Vec<(String, Vec<Plane>)> = Vec::new();
        for coupling in world.couplings() {
            let against = match &coupling.kind {
                CouplingKind::Contact(contact) => match &contact.against() {
                    Opposing::Planes(planes) => planes,
                    Opposing::Body { .. } => continue,
                },
                CouplingKind::SpringDamper(_) | CouplingKind::Catenary(_) => continue,
            };
            let new: Vec<Plane> = against.iter().filter(|plane| !drawn.contains(plane)).copied().collect();
            if !new.is_empty() {
                drawn.extend(&new);
                planes.push((coupling.name.clone(), new));
            }
        }
        let anchors: Vec<Vec3> = world
            .couplings()
            .iter()
            .flat_map(|coupling| match &coupling.kind {
                CouplingKind::SpringDamper(spring) => vec![spring.end1(), spring.end2()],
                CouplingKind::Catenary(line) => vec![line.end1(), line.end2()],
                // A contact's ends are its bodies' centres, or the origin for its planes.
                CouplingKind::Contact(_) => Vec::new(),
            })
            .filter_map(|end| match end {
                Endpoint::World(point) => Some(point),
                Endpoint::Body { .. } | Endpoint::Center { .. } => None,
            })
            .collect();
        (!planes.is_empty() || !anchors.is_empty()).then_some(Self { planes, anchors })
    }

    /// Entities: a patch per contact with planes, the anchors.
    pub(super) fn entities(&self) -> usize {
        self.planes.len() + usize::from(!self.anchors.is_empty())
    }
}

/// Logs, statically, each contact plane of `world` as a patch covering `swept` (the box of what
/// moves over the run's first seconds, [`crate::framing`]).
pub(crate) fn log_planes(stream: &RecordingStream, world: &World, swept: &(Vec3, Vec3)) -> Result<(), RecordError> {
    let Some(boundaries) = Boundaries::new(world) else { return Ok(()) };
    let [r, g, b] = BOUNDARY_RGB;
    for (name, planes) in &boundaries.planes {
        let lines: Vec<Vec<[f32; 3]>> = planes
            .iter()
            .flat_map(|plane| grid(&patch(plane, swept)))
            .map(|[a, b]| vec![f32x3(&a), f32x3(&b)])
            .collect();
        stream.log_static(
            paths::boundary(name),
            &rerun::LineStrips3D::new(lines)
                .with_colors([rerun::Color::from_rgb(r, g, b)])
                .with_radii([rerun::Radius::new_ui_points(LINE_POINTS)]),
        )?;
    }
    Ok(())
}

/// Whether `world` has a contact against planes (whose patches [`log_planes`] draws).
pub(crate) fn has_planes(world: &World) -> bool {
    Boundaries::new(world).is_some_and(|boundaries| !boundaries.planes.is_empty())
}

impl Track for Boundaries {
    /// The anchors; the planes wait for the framing's box ([`log_planes`]).
    fn log_static(&self, stream: &RecordingStream, _world: &World) -> Result<(), RecordError> {
        if !self.anchors.is_empty() {
            let [r, g, b] = ANCHOR_RGB;
            stream.log_static(
                paths::ANCHORS,
                &rerun::Points3D::new(self.anchors.iter().map(f32x3))
                    .with_colors([rerun::Color::from_rgb(r, g, b)])
                    .with_radii([rerun::Radius::new_ui_points(ANCHOR_POINTS)]),
            )?;
        }
        Ok(())
    }

    fn capture(&mut self, _world: &World, _frame: usize, _settings: &Settings) -> usize {
        0
    }

    fn send(&mut self, _stream: &RecordingStream, _frames: &Frames, _sent: &mut KindStats) -> Result<(), RecordError> {
        Ok(())
    }
}

/// The four corners, in turn, of the square of `plane` covering the box `swept` projected onto
/// it, 20 % wider, at least [`MIN_HALF_SIDE`] from its centre \[m].
fn patch(plane: &Plane, (low, high): &(Vec3, Vec3)) -> [Vec3; 4] {
    let normal = plane.normal.normalize();
    // Two directions in the plane: the normal's cross product with the axis it is least along.
    let least = normal.iamin();
    let u = normal.cross(&Vec3::ith(least, 1.0)).normalize();
    let v = normal.cross(&u);
    let corners = (0..8).map(|i| {
        Vec3::new(
            if i & 1 == 0 { low.x } else { high.x },
            if i & 2 == 0 { low.y } else { high.y },
            if i & 4 == 0 { low.z } else { high.z },
        )
    });
    let (mut a, mut b) = ((f64::INFINITY, f64::NEG_INFINITY), (f64::INFINITY, f64::NEG_INFINITY));
    for corner in corners {
        let offset = corner - plane.point;
        let (x, y) = (u.dot(&offset), v.dot(&offset));
        a = (a.0.min(x), a.1.max(x));
        b = (b.0.min(y), b.1.max(y));
    }
    let center = plane.point + u * ((a.0 + a.1) / 2.0) + v * ((b.0 + b.1) / 2.0);
    let half = (0.6 * (a.1 - a.0).max(b.1 - b.0)).max(MIN_HALF_SIDE);
    [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(s, t)| center + u * (s * half) + v * (t * half))
}

/// The [`GRID_CELLS`] × [`GRID_CELLS`] grid of the square with `corners` (in turn): its lines
/// along both sides, edges included.
fn grid(corners: &[Vec3; 4]) -> Vec<[Vec3; 2]> {
    let [a, b, _, d] = corners;
    let (along, across) = (b - a, d - a);
    (0..=GRID_CELLS)
        .map(|i| f64::from(i) / f64::from(GRID_CELLS))
        .flat_map(|s| [[a + across * s, a + across * s + along], [a + along * s, a + along * s + across]])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quay_patch_lies_in_its_plane_and_covers_what_moves() {
        let quay = Plane { point: Vec3::new(0.0, 0.0, 0.0), normal: Vec3::new(1.0, 0.0, 0.0) };
        let swept = (Vec3::new(0.2, -4.0, -1.0), Vec3::new(4.0, 4.0, 2.0));
        let corners = patch(&quay, &swept);
        for corner in &corners {
            assert!(corner.x.abs() < 1e-12, "in the plane x = 0: {corner}");
        }
        // Projected: y in [−4, 4], z in [−1, 2]; centre (0, 0, 0.5); half side 0.6 × 8 = 4.8.
        let (low, high) = tether_physics::math::bounding_box(corners);
        assert!((low - Vec3::new(0.0, -4.8, 0.5 - 4.8)).norm() < 1e-12, "{low}");
        assert!((high - Vec3::new(0.0, 4.8, 0.5 + 4.8)).norm() < 1e-12, "{high}");
    }

    #[test]
    fn the_grid_has_its_edges_and_equal_cells() {
        let square = [Vec3::zeros(), Vec3::new(4.0, 0.0, 0.0), Vec3::new(4.0, 4.0, 0.0), Vec3::new(0.0, 4.0, 0.0)];
        let lines = grid(&square);
        assert_eq!(lines.len(), 2 * (GRID_CELLS as usize + 1));
        // Every line spans the square, and the lines along x sit at y = 0, 0.5, …, 4.
        for [a, b] in &lines {
            assert!(((b - a).norm() - 4.0).abs() < 1e-12);
        }
        let heights: Vec<f64> = lines.iter().filter(|[a, b]| a.y == b.y).map(|[a, _]| a.y).collect();
        let expected: Vec<f64> = (0..=GRID_CELLS).map(|i| 0.5 * f64::from(i)).collect();
        assert_eq!(heights, expected);
    }

    #[test]
    fn a_point_gets_the_smallest_patch() {
        let ground = Plane { point: Vec3::new(0.0, 0.0, -2.0), normal: Vec3::new(0.0, 0.0, 1.0) };
        let p = Vec3::new(3.0, 1.0, 5.0);
        let (low, high) = tether_physics::math::bounding_box(patch(&ground, &(p, p)));
        assert!((low - Vec3::new(2.0, 0.0, -2.0)).norm() < 1e-12, "{low}");
        assert!((high - Vec3::new(4.0, 2.0, -2.0)).norm() < 1e-12, "{high}");
    }
}
