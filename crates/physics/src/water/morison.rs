//! A floating body's hydrodynamic coefficients and its Morison loads (PHYSICS.md §6, Morison
//! loads per body).
//!
//! In the body axes `b_j` (the scene's reference axes, carried by the body), with the relative
//! flow at the drag centre `u_r = U + u − (v_G + ω × r_c)` [m/s] and the wetted fraction `w`:
//! - drag `F_d = Σ_j (w ½ ρ C_dj A_j |u_r·b_j| + c_j) (u_r·b_j) b_j` \[N], at the drag centre,
//!   with the linear damping `c_j` [N·s/m] beside the quadratic drag;
//! - rotational drag `M_d = −Σ_j (w C_rj |ω_j| + d_j) ω_j b_j` [N·m], `ω_j = ω·b_j`, with the
//!   rotational drag `C_rj` [N·m·s²] and the rotational damping `d_j` [N·m·s].
//!
//! Only the drag-like terms (`C_dj`, `C_rj`: loads on the wetted surface) scale with `w`; the
//! declared dampers `c_j`, `d_j` act in full whenever the body is wet (`w > 0`; the stage skips a
//! dry body), as the coefficients the user asked for (PHYSICS.md §6, Morison loads per body).
//!
//! The drag areas `A_j` default to the hull's projected areas `½ Σ A_f |n_f·b_j|`; the drag
//! centre to G. The added-mass coefficients are applied by [`super::added_mass`].

use super::added_mass::AddedMass;
use super::hull::Hull;
use crate::body::{BodyFrame, Load, RigidBody};
use crate::math::{Mat3, Vec3};

/// What a scene declares of a body in water, in its reference axes (SI units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HydroSpec {
    /// `C_dj` [–] ≥ 0 per reference axis.
    pub drag: Vec3,
    /// `A_j` \[m²] > 0 per axis; `None`: the hull's projected areas.
    pub drag_areas: Option<Vec3>,
    /// `C_rj` [N·m·s²] ≥ 0.
    pub rotational_drag: Vec3,
    /// `c_j` [N·s/m] ≥ 0, in full while the body is wet (not scaled by the wetted fraction).
    pub linear_damping: Vec3,
    /// `d_j` [N·m·s] ≥ 0, in full while the body is wet (not scaled by the wetted fraction).
    pub rotational_damping: Vec3,
    /// `C_aj` [–] ≥ 0: added mass `w ρ V C_aj` along each axis.
    pub added_mass: Vec3,
    /// Added inertia [kg·m²] ≥ 0 about each axis (times the wetted fraction).
    pub added_inertia: Vec3,
    /// The drag centre in the reference frame \[m]; `None`: G.
    pub drag_center: Option<Vec3>,
}

/// Coefficients that cannot be.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HydroError {
    #[error("{field} must be finite and ≥ 0{unit} on every axis, got ({}, {}, {})", value.x, value.y, value.z)]
    Negative { field: &'static str, unit: &'static str, value: Vec3 },
    #[error("drag_areas must be finite and > 0 m² on every axis, got ({}, {}, {})", .0.x, .0.y, .0.z)]
    Area(Vec3),
    #[error("drag_center must be a finite point")]
    Center,
}

/// A body's coefficients, resolved into its principal frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Hydro {
    spec: HydroSpec,
    /// `b_j` as the columns, principal frame.
    axes: Mat3,
    /// `A_j` \[m²].
    drag_areas: Vec3,
    /// The drag centre, principal frame \[m].
    drag_center: Vec3,
}

impl Hydro {
    /// The coefficients as the scene declared them, in its reference axes.
    pub fn spec(&self) -> &HydroSpec {
        &self.spec
    }

    /// `b_j` as the columns, principal frame.
    pub fn axes(&self) -> &Mat3 {
        &self.axes
    }

    /// `A_j` \[m²].
    pub fn drag_areas(&self) -> &Vec3 {
        &self.drag_areas
    }

    /// The drag centre, principal frame \[m].
    pub fn drag_center(&self) -> &Vec3 {
        &self.drag_center
    }

    /// `spec` for `body` with hull `hull`.
    ///
    /// # Errors
    /// A negative or non-finite coefficient, an area ≤ 0.
    pub fn new(spec: HydroSpec, body: &RigidBody, hull: &Hull) -> Result<Self, HydroError> {
        for (field, unit, value) in [
            ("drag", "", spec.drag),
            ("rotational_drag", " N·m·s²", spec.rotational_drag),
            ("linear_damping", " N·s/m", spec.linear_damping),
            ("rotational_damping", " N·m·s", spec.rotational_damping),
            ("added_mass", "", spec.added_mass),
            ("added_inertia", " kg·m²", spec.added_inertia),
        ] {
            if !value.iter().all(|x| *x >= 0.0 && x.is_finite()) {
                return Err(HydroError::Negative { field, unit, value });
            }
        }
        let axes = body.reference_in_principal.rotation.to_rotation_matrix().into_inner();
        let drag_areas = match spec.drag_areas {
            Some(areas) if areas.iter().all(|a| *a > 0.0 && a.is_finite()) => areas,
            Some(areas) => return Err(HydroError::Area(areas)),
            None => Vec3::from_fn(|j, _| hull.projected_area(&axes.column(j).into_owned())),
        };
        let drag_center = match spec.drag_center {
            Some(c) if c.iter().all(|x| x.is_finite()) => body.principal_point(&c),
            Some(_) => return Err(HydroError::Center),
            None => Vec3::zeros(),
        };
        Ok(Self { spec, axes, drag_areas, drag_center })
    }

    /// Whether any added mass or inertia is declared.
    pub fn has_added_mass(&self) -> bool {
        self.spec.added_mass != Vec3::zeros() || self.spec.added_inertia != Vec3::zeros()
    }

    /// The declared added mass and inertia (§6) on a hull of displaced volume `volume` \[m³] when
    /// whole, wetted by the fraction `wetted`, in water of density `density` [kg/m³].
    pub fn added_mass(&self, volume: f64, density: f64, wetted: f64) -> AddedMass {
        AddedMass::new(&self.axes, &self.spec.added_mass, &self.spec.added_inertia, volume, density, wetted)
    }

    /// `r_c` in world axes \[m] for a body turned by `rotation`.
    pub fn drag_arm(&self, rotation: &Mat3) -> Vec3 {
        rotation * self.drag_center
    }

    /// The Morison load (about G, world axes) for the water velocity `flow` [m/s] at the drag
    /// centre, density `density` [kg/m³] and wetted fraction `wetted`.
    pub fn load(&self, frame: &BodyFrame, flow: &Vec3, density: f64, wetted: f64) -> Load {
        let arm = self.drag_arm(&frame.rotation);
        let omega_world = frame.rotation * frame.angular_velocity;
        let relative = frame.rotation.tr_mul(&(flow - frame.velocity - omega_world.cross(&arm)));
        let along = self.axes.tr_mul(&relative);
        let s = &self.spec;
        let drag = Vec3::from_fn(|j, _| {
            (wetted * 0.5 * density * s.drag[j] * self.drag_areas[j] * along[j].abs() + s.linear_damping[j]) * along[j]
        });
        let spin = self.axes.tr_mul(&frame.angular_velocity);
        let turning =
            Vec3::from_fn(|j, _| -(wetted * s.rotational_drag[j] * spin[j].abs() + s.rotational_damping[j]) * spin[j]);
        let force = frame.rotation * (self.axes * drag);
        Load { force, moment: arm.cross(&force) + frame.rotation * (self.axes * turning) }
    }

    /// The linearised drag along each body axis, `w ρ C_dj A_j s + c_j` [N·s/m], and about
    /// each, `2 w C_rj |ω_j| + d_j` [N·m·s], for a relative flow speed of at most `speed`
    /// [m/s]: the dampers the stable time step sees.
    pub fn linearised(&self, frame: &BodyFrame, speed: f64, density: f64, wetted: f64) -> (Vec3, Vec3) {
        let spin = self.axes.tr_mul(&frame.angular_velocity);
        let s = &self.spec;
        (
            Vec3::from_fn(|j, _| wetted * density * s.drag[j] * self.drag_areas[j] * speed + s.linear_damping[j]),
            Vec3::from_fn(|j, _| 2.0 * wetted * s.rotational_drag[j] * spin[j].abs() + s.rotational_damping[j]),
        )
    }
}
