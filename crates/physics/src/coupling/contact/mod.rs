//! Face-based penalty contact with tanh friction (PHYSICS.md §4 \[4956]–\[4965]).
//!
//! A contact coupling pushes the faces of one body's [`BoundaryMesh`] away from an opposing
//! boundary: half-spaces of the environment (a ground plane, quay walls, the walls of a domain
//! box) or another body's [`Surface`]. For each face within the range `d0` of the opposing
//! boundary the [`ContactLaw`] gives `f_f = f_n + f_t` at its centroid `r_f`; the body receives
//! `Σ f_f` and the moment about G `Σ (r_f − x_G) × f_f` (\[4956]–\[4957]); another body receives
//! `−f_f` at the same points, so momentum is conserved.
//!
//! Cost: a body whose bounding ball is out of range of a plane costs one dot product; a pair of
//! bodies whose bounding balls are apart costs one distance. Then, against a plane, each face on
//! the plane's shortlist (`shortlist.rs`) costs a dot product (the list is drawn up again, by
//! culling groups of faces, only when the body has moved or turned by its margin); against a
//! body, each face in a group near the other's bounding box costs a BVH query.

mod batch;
pub mod estimator;
pub mod law;
mod normals;
mod shortlist;

use super::forces::CouplingForces;
use crate::body::{BodyFrame, Load};
use crate::math::{Mat3, Vec3};
use crate::mesh::{BoundaryMesh, Face, Surface};
use crate::parameter::{Bound, ParameterError, require};
use batch::{Accumulated, FaceBatch, LaneSums, PlaneView};
pub use law::{ContactLaw, FaceContact};
use normals::NormalForces;
use shortlist::Shortlist;
use std::sync::Arc;

/// A half-space boundary: the plane through `point` \[m] with unit `normal` pointing to the side
/// the bodies are on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    pub point: Vec3,
    pub normal: Vec3,
}

impl Plane {
    /// The six inward walls of the axis-aligned box `[low, high]` \[m], the boundary of the
    /// computational domain.
    pub fn domain_box(low: &Vec3, high: &Vec3) -> [Self; 6] {
        let wall = |point: &Vec3, axis: usize, sign: f64| Self { point: *point, normal: Vec3::ith(axis, sign) };
        [
            wall(low, 0, 1.0),
            wall(low, 1, 1.0),
            wall(low, 2, 1.0),
            wall(high, 0, -1.0),
            wall(high, 1, -1.0),
            wall(high, 2, -1.0),
        ]
    }
}

/// What the faces are pushed away from.
#[derive(Debug, Clone, PartialEq)]
pub enum Opposing {
    /// Half-spaces of the environment; each acts on every face in its range.
    Planes(Vec<Plane>),
    /// The boundary of body `body` (index in the world).
    Body { body: usize, surface: Arc<Surface> },
}

/// One face in contact, in the body's principal frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ActiveFace {
    /// `r_f − x_G` \[m], principal frame.
    pub centroid: Vec3,
    /// `f_f` on the body \[N], principal frame.
    pub force: Vec3,
}

/// Totals of the last evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactTotals {
    /// `Σ |f_n|` \[N].
    pub normal: f64,
    /// `|Σ f_t|` \[N].
    pub friction: f64,
    /// `Σ a_f` of the faces in range \[m²].
    pub area: f64,
    /// Faces in range.
    pub faces: usize,
}

/// A contact coupling between the faces of body `body` and an opposing boundary, built by
/// [`Contact::new`], which checks its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Contact {
    body: usize,
    boundary: Arc<BoundaryMesh>,
    against: Opposing,
    law: ContactLaw,
    /// `A`, the expected contact area \[m²] (PHYSICS.md §4) behind the time step limit.
    expected_area: f64,
}

/// A contact's resultant normal force and friction at an evaluation, as the step summed them
/// (PHYSICS.md §4).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactForces {
    /// `Σ |f_n|` \[N].
    pub normal: f64,
    /// `|Σ f_t|` \[N].
    pub friction: f64,
}

/// What a contact remembers between evaluations of one run: for each plane of
/// [`Opposing::Planes`], the faces that may be in its range, and what the friction at the last
/// evaluation is found from (for plots and recordings, which so need not evaluate the faces
/// again).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ContactCache {
    shortlists: Vec<Shortlist>,
    /// `Σ_f n_f |f_n|` at the last [`Contact::apply`].
    normals: NormalForces,
}

impl ContactCache {
    /// The normal force and friction of the contact whose last evaluation this cache kept, and
    /// that wrote `record`.
    pub fn forces(&self, record: &CouplingForces) -> ContactForces {
        ContactForces { normal: record.tension, friction: self.normals.friction(&record.f1, record.tension) }
    }
}

impl Contact {
    /// The body whose faces push.
    pub fn body(&self) -> usize {
        self.body
    }

    pub fn boundary(&self) -> &Arc<BoundaryMesh> {
        &self.boundary
    }

    pub fn against(&self) -> &Opposing {
        &self.against
    }

    pub fn law(&self) -> ContactLaw {
        self.law
    }

    /// `A`, the expected contact area \[m²] (PHYSICS.md §4) behind the time step limit.
    pub fn expected_area(&self) -> f64 {
        self.expected_area
    }

    /// The faces of body `body`'s `boundary` against `against` under `law`, with the expected
    /// contact area `expected_area` A \[m²] > 0.
    ///
    /// # Errors
    /// An expected area out of its range.
    pub fn new(
        body: usize,
        boundary: Arc<BoundaryMesh>,
        against: Opposing,
        law: ContactLaw,
        expected_area: f64,
    ) -> Result<Self, ParameterError> {
        let expected_area = require("expected_area", expected_area, Bound::Positive, "m²")?;
        Ok(Self { body, boundary, against, law, expected_area })
    }

    /// A fresh cache for a run: one empty face list per plane.
    pub fn new_cache(&self) -> ContactCache {
        let planes = match &self.against {
            Opposing::Planes(planes) => planes.len(),
            Opposing::Body { .. } => 0,
        };
        ContactCache { shortlists: vec![Shortlist::new(); planes], normals: NormalForces::default() }
    }

    /// The faces in contact at the kinematics `frames`, with their forces: the evaluation of
    /// [`Contact::apply`] again, for display (the step itself keeps only the sums it needs).
    pub fn active_faces(&self, frames: &[BodyFrame]) -> Vec<ActiveFace> {
        let mut active = Vec::new();
        self.evaluate(frames, |face, contact| {
            active.push(ActiveFace { centroid: face.centroid, force: contact.force })
        });
        active
    }

    /// Normal force, friction, area and number of the faces in contact at the kinematics
    /// `frames` (evaluated again, for display and the time step limit).
    pub fn totals(&self, frames: &[BodyFrame]) -> ContactTotals {
        let (mut totals, mut friction) = (ContactTotals::default(), Vec3::zeros());
        self.evaluate(frames, |face, contact| {
            totals.normal += contact.normal_force;
            totals.area += face.area;
            totals.faces += 1;
            friction += contact.friction;
        });
        ContactTotals { friction: friction.norm(), ..totals }
    }

    /// Calls `on_face` with each face in contact and what the law gave it, face by face, from
    /// face lists drawn up afresh (they hold exactly the faces a run's lists hold).
    fn evaluate(&self, frames: &[BodyFrame], mut on_face: impl FnMut(&Face, &FaceContact)) {
        let frame = &frames[self.body];
        match &self.against {
            Opposing::Planes(planes) => {
                let faces = self.boundary.faces();
                for plane in planes {
                    let mut shortlist = Shortlist::new();
                    let shortlist = &mut shortlist;
                    let Some((view, batches)) = plane_view(&self.boundary, &self.law, plane, shortlist, frame) else {
                        continue;
                    };
                    for batch in batches {
                        let (contacts, mut in_range) = batch.contacts(&self.law, &view);
                        // Ends: each pass clears the lowest set bit.
                        while in_range != 0 {
                            let lane = in_range.trailing_zeros() as usize;
                            in_range &= in_range - 1;
                            on_face(&faces[batch.index[lane]], &contacts[lane]);
                        }
                    }
                }
            }
            Opposing::Body { body, surface } => {
                against_body(
                    &self.boundary,
                    &self.law,
                    surface,
                    frame,
                    &frames[*body],
                    &mut Accumulated::default(),
                    on_face,
                );
            }
        }
    }

    /// Whether any of `planes` is in range of the body's bounding ball at its kinematics `frame`,
    /// and the sums over the faces in contact in the body's principal frame, batch by batch,
    /// bringing the `shortlists` up to date; `normals` keeps each plane's share of the normal
    /// force for the friction (only a corner, two planes in range at once, adds a reduction of
    /// the lane sums). (Not an `Option` of the sums: that went through memory, where the
    /// processor stalled reading back parts of what it had just written.)
    #[inline(always)]
    fn against_planes(
        &self,
        planes: &[Plane],
        shortlists: &mut [Shortlist],
        normals: &mut NormalForces,
        frame: &BodyFrame,
    ) -> (bool, Accumulated) {
        let (mut last_in_range, mut lanes) = (None::<&Plane>, LaneSums::default());
        normals.start();
        for (plane, shortlist) in planes.iter().zip(shortlists) {
            let Some((view, batches)) = plane_view(&self.boundary, &self.law, plane, shortlist, frame) else {
                continue;
            };
            if let Some(previous) = last_in_range {
                normals.close(&previous.normal, lanes.normal());
            }
            batch::accumulate(batches, &self.law, &view, &mut lanes);
            last_in_range = Some(plane);
        }
        if let Some(last) = last_in_range {
            normals.last_plane(&last.normal);
        }
        (last_in_range.is_some(), lanes.total())
    }

    /// The area behind the time step limit \[m²]: the larger of the expected contact area and
    /// the area in contact at the kinematics `frames`.
    pub fn limit_area(&self, frames: &[BodyFrame]) -> f64 {
        self.expected_area.max(self.totals(frames).area)
    }

    /// Stopping time `τ` \[s] of an impact on an area `area` \[m²] for the effective mass
    /// `1/inverse_mass` (PHYSICS.md §4); infinite when neither side responds to forces.
    pub fn stopping_time(&self, area: f64, inverse_mass: f64) -> f64 {
        if inverse_mass > 0.0 {
            estimator::stopping_time(inverse_mass.recip(), area, self.law.stiffness())
        } else {
            f64::INFINITY
        }
    }

    /// The other body, if the opposing boundary is one.
    pub fn other_body(&self) -> Option<usize> {
        match self.against {
            Opposing::Planes(_) => None,
            Opposing::Body { body, .. } => Some(body),
        }
    }

    /// Evaluates the faces at the kinematics `frames`, adds the forces to the bodies' `loads`
    /// and writes the totals to `out` (`f1` on the body at its G, `f2 = −f1` on the opposing
    /// side at its G or, for planes, at the body's; `tension` = `Σ |f_n|`); `cache` keeps the
    /// face lists up to date.
    #[inline(always)]
    pub fn apply(&self, cache: &mut ContactCache, frames: &[BodyFrame], loads: &mut [Load], out: &mut CouplingForces) {
        let frame = &frames[self.body];
        let ContactCache { shortlists, normals } = cache;
        match &self.against {
            Opposing::Planes(planes) => {
                let (in_range, sums) = self.against_planes(planes, shortlists, normals, frame);
                self.add_sums(in_range, &sums, frame, frame.position, loads, out);
            }
            Opposing::Body { body, surface } => {
                let (other, mut sums) = (&frames[*body], Accumulated::default());
                let in_range = against_body(&self.boundary, &self.law, surface, frame, other, &mut sums, |_, _| {});
                let (force, moment) = self.add_sums(in_range, &sums, frame, other.position, loads, out);
                *normals = NormalForces::summed(frame.rotation * (sums.force - sums.friction), sums.normal);
                if in_range {
                    // The reaction −f_f at the same points: moment (r_f − x_B) × (−f_f).
                    let lever = frame.position - other.position;
                    loads[*body].force -= force;
                    loads[*body].moment -= lever.cross(&force) + moment;
                }
            }
        }
    }

    /// The `sums` over the faces (in the principal frame of the body moving as `frame`) in
    /// world axes, added to the body's load and written to `out` with the opposing side's point
    /// `point2`; no force, and nothing added, unless `in_range`. Returns the force and moment
    /// [N, N·m].
    #[inline(always)]
    fn add_sums(
        &self,
        in_range: bool,
        sums: &Accumulated,
        frame: &BodyFrame,
        point2: Vec3,
        loads: &mut [Load],
        out: &mut CouplingForces,
    ) -> (Vec3, Vec3) {
        if !in_range {
            *out = CouplingForces { point1: frame.position, point2, ..CouplingForces::default() };
            return (Vec3::zeros(), Vec3::zeros());
        }
        let (force, moment) = (frame.rotation * sums.force, frame.rotation * sums.moment);
        loads[self.body].force += force;
        loads[self.body].moment += moment;
        *out = CouplingForces {
            point1: frame.position,
            point2,
            f1: force,
            f2: -force,
            tension: sums.normal,
            dissipated_power: sums.dissipated_power,
            held_power: 0.0,
            potential: sums.potential,
        };
        (force, moment)
    }
}

/// Plane `plane` as the faces of `boundary` see it (PHYSICS.md §4: a plane at height
/// `h = n·(x_G − p)` is at distance `d_f = h + n_b·r_f` from face f, `n_b = Rᵀ n`), with the
/// batches of faces on its `shortlist`; `None` when the plane is out of range of the boundary's
/// bounding ball.
#[inline(always)]
fn plane_view<'a>(
    boundary: &BoundaryMesh,
    law: &ContactLaw,
    plane: &Plane,
    shortlist: &'a mut Shortlist,
    frame: &BodyFrame,
) -> Option<(PlaneView, &'a [FaceBatch])> {
    let height = plane.normal.dot(&(frame.position - plane.point));
    if height - boundary.bounding_radius() >= law.range() {
        return None;
    }
    let rotation: &Mat3 = &frame.rotation;
    let normal = rotation.tr_mul(&plane.normal);
    let view = PlaneView { height, normal, velocity: rotation.tr_mul(&frame.velocity), spin: frame.angular_velocity };
    Some((view, shortlist.batches(boundary, height, &normal, law.range())))
}

/// Every face of body A's `boundary` against body B's `surface`, evaluated in B's principal
/// frame (where the surface is) and returned in A's; a group of faces whose ball is out of range
/// of B's bounding box is skipped whole. The faces in contact are added to `sums`; returns
/// whether the bodies' bounding balls are in range.
fn against_body(
    boundary: &BoundaryMesh,
    law: &ContactLaw,
    surface: &Surface,
    a: &BodyFrame,
    b: &BodyFrame,
    sums: &mut Accumulated,
    mut on_face: impl FnMut(&Face, &FaceContact),
) -> bool {
    if (a.position - b.position).norm() >= boundary.bounding_radius() + surface.bounding_radius() + law.range() {
        return false;
    }
    // B's frame: x_B = b.position, axes b.rotation; A's faces are carried into it.
    let a_to_b = b.rotation.tr_mul(&a.rotation);
    let offset = b.rotation.tr_mul(&(a.position - b.position));
    let velocity_a = b.rotation.tr_mul(&(a.velocity - b.velocity));
    let spin_a = a_to_b * a.angular_velocity;
    let faces = boundary.faces();
    let groups = boundary
        .groups()
        .iter()
        .filter(|group| surface.near_bounds(&(offset + a_to_b * group.center), law.range() + group.radius));
    for face in groups.flat_map(|group| &faces[group.faces()]) {
        let arm = a_to_b * face.centroid;
        let point = offset + arm;
        let Some(nearest) = surface.nearest(&point, law.range()) else { continue };
        if nearest.distance >= law.range() {
            continue;
        }
        let relative_velocity = velocity_a + spin_a.cross(&arm) - b.angular_velocity.cross(&point);
        let contact = law.face_force(face.area, nearest.distance, &nearest.normal, &relative_velocity);
        // Back into A's principal frame.
        let in_a =
            FaceContact { force: a_to_b.tr_mul(&contact.force), friction: a_to_b.tr_mul(&contact.friction), ..contact };
        sums.add(&face.centroid, &in_a);
        on_face(face, &in_a);
    }
    true
}
