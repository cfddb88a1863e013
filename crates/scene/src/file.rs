//! What a scene file says: plain serde data, SI units (see the table in the crate docs).
//!
//! Points on a body are given in its *reference frame*: origin at the declared master node,
//! axes parallel to the world axes at t = 0. Vectors are RON tuples `(x, y, z)`. Every number
//! must be finite; unknown fields are rejected.

use super::air::{AirDef, RotorDef, WindageDef};
pub use super::finite::Triple;
use super::finite::{finite, finite_option, finite_pairs, finite_velocity_table, finite3};
use super::line_model::LineModelDef;
use super::spelling::{IntegratorForm, SubstepsForm};
use super::water::{HydroDef, WaterDef};
use serde::{Deserialize, Serialize};
use tether_physics::integrator::{Integrator, Substeps};

/// A whole scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Scene", deny_unknown_fields)]
pub struct SceneFile {
    /// Gravity [m/s²].
    #[serde(default = "default_gravity", deserialize_with = "finite3")]
    pub gravity: Triple,
    /// Time step \[s] > 0.
    #[serde(deserialize_with = "finite")]
    pub dt: f64,
    /// Default duration of a run \[s] > 0.
    #[serde(default = "default_duration", deserialize_with = "finite")]
    pub duration: f64,
    /// `leapfrog` (default), `leapfrog2`, `splitting`, `rk4` or `dopri45`.
    #[serde(default, with = "IntegratorForm")]
    pub integrator: Integrator,
    /// Settings of `dopri45`; defaults when absent.
    #[serde(default)]
    pub adaptive: Option<AdaptiveDef>,
    /// Integrator steps per `dt`: `Fixed(n)` or `Auto` (default `Fixed(1)`).
    #[serde(default, with = "SubstepsForm")]
    pub substeps: Substeps,
    pub bodies: Vec<BodyDef>,
    #[serde(default)]
    pub couplings: Vec<CouplingDef>,
    /// Water (PHYSICS.md §6, see [`crate::water`]); absent: none, and no body feels any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub water: Option<WaterDef>,
    /// Air: the wind (PHYSICS.md §10, see [`crate::air`]); absent: none, and no body feels any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air: Option<AirDef>,
    /// The bottom lines lie on and bodies touch (PHYSICS.md §7), at the water's depth when
    /// the scene has water; none when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seabed: Option<SeabedDef>,
}

/// A flat seabed (PHYSICS.md §7).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Seabed", deny_unknown_fields)]
pub struct SeabedDef {
    /// `z_b` \[m]: the bottom's height along the upward vertical (`z` with the default gravity).
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite_option")]
    pub elevation: Option<f64>,
    /// `C_B` [–] ≥ 0: friction of a line lying on the bottom, per unit of its submerged weight
    /// (default 0).
    #[serde(default, deserialize_with = "finite")]
    pub line_friction: f64,
    /// Bodies that touch the bottom, and how (a contact coupling each, named `seabed.<body>`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact: Option<SeabedContactDef>,
}

/// Penalty contact of bodies with the seabed (PHYSICS.md §4), with the parameters of a
/// [`CouplingDef::Contact`]: `stiffness` k1 [N/m³] > 0, `damping` k2 [N·s/m³] ≥ 0, `range` d0
/// \[m] ≥ 0, `friction` μ ≥ 0, `friction_sharpness` k_t [s/m] > 0 (default 100).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "SeabedContact", deny_unknown_fields)]
pub struct SeabedContactDef {
    /// The bodies, by name.
    pub bodies: Vec<String>,
    #[serde(deserialize_with = "finite")]
    pub stiffness: f64,
    #[serde(default, deserialize_with = "finite")]
    pub damping: f64,
    #[serde(default, deserialize_with = "finite")]
    pub range: f64,
    #[serde(default, deserialize_with = "finite")]
    pub friction: f64,
    #[serde(default = "default_friction_sharpness", deserialize_with = "finite")]
    pub friction_sharpness: f64,
}

/// Tolerances of the adaptive `dopri45` (PHYSICS.md §1; see [`tether_physics::integrator::Tolerances`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Adaptive", deny_unknown_fields)]
pub struct AdaptiveDef {
    /// Relative tolerance [–], 0 < rtol < 1 (default 1e-6).
    #[serde(default = "default_rtol", deserialize_with = "finite")]
    pub rtol: f64,
    /// Absolute tolerance [SI unit of each component] > 0 (default 1e-9).
    #[serde(default = "default_atol", deserialize_with = "finite")]
    pub atol: f64,
    /// Largest adaptive step \[s] > 0 (default: the integrator step `dt / substeps`).
    #[serde(default, deserialize_with = "finite_option")]
    pub max_step: Option<f64>,
}

fn default_rtol() -> f64 {
    tether_physics::integrator::Tolerances::default().rtol()
}

fn default_atol() -> f64 {
    tether_physics::integrator::Tolerances::default().atol()
}

fn default_gravity() -> Triple {
    [0.0, 0.0, -9.80665]
}

fn default_duration() -> f64 {
    10.0
}

/// A rigid body: master node, slave nodes, initial velocity, support and display shape.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Body", deny_unknown_fields)]
pub struct BodyDef {
    pub name: String,
    pub master: NodeDef,
    #[serde(default)]
    pub slaves: Vec<NodeDef>,
    /// Initial velocity of G [m/s], world.
    #[serde(default, deserialize_with = "finite3")]
    pub velocity: Triple,
    /// Initial angular velocity [rad/s], world.
    #[serde(default, deserialize_with = "finite3")]
    pub angular_velocity: Triple,
    /// Rotation vector \[rad] (axis × angle, world) turning the body about its master node at
    /// t = 0: its nodes, shape and coupling points are given unturned (default none).
    #[serde(default, skip_serializing_if = "is_zero3", deserialize_with = "finite3")]
    pub rotation: Triple,
    #[serde(default)]
    pub support: SupportDef,
    pub shape: ShapeDef,
    /// Hydrodynamic coefficients: only a body that declares them feels the scene's water, and
    /// its shape must then be a closed, outward hull.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hydro: Option<HydroDef>,
    /// The wind's drag on the body (PHYSICS.md §10): only a body that declares it (or a rotor)
    /// feels the scene's air.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub windage: Option<WindageDef>,
    /// A wind turbine's rotor on the body: its quasi-steady thrust (PHYSICS.md §10).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotor: Option<RotorDef>,
}

/// A node: position at t = 0 \[m], mass \[kg], and inertia about itself [kg·m²].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename = "Node", deny_unknown_fields)]
pub struct NodeDef {
    #[serde(deserialize_with = "finite3")]
    pub position: Triple,
    #[serde(deserialize_with = "finite")]
    pub mass: f64,
    #[serde(default)]
    pub inertia: InertiaDef,
}

/// Inertia tensor components [kg·m²] in the tensor convention (`xy = −Σ m x y`).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename = "Inertia", deny_unknown_fields)]
pub struct InertiaDef {
    #[serde(deserialize_with = "finite")]
    pub xx: f64,
    #[serde(deserialize_with = "finite")]
    pub yy: f64,
    #[serde(deserialize_with = "finite")]
    pub zz: f64,
    #[serde(default, deserialize_with = "finite")]
    pub xy: f64,
    #[serde(default, deserialize_with = "finite")]
    pub yz: f64,
    #[serde(default, deserialize_with = "finite")]
    pub xz: f64,
}

/// Master-node boundary conditions.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum SupportDef {
    #[default]
    Free,
    /// Fixed world translation components (x, y, z), and rotation if `rotation`.
    Fixed {
        #[serde(default)]
        translation: (bool, bool, bool),
        #[serde(default)]
        rotation: bool,
    },
    /// Prescribed motion: velocity of G [m/s] and a constant angular velocity [rad/s], world.
    Kinematic {
        velocity: VelocityDef,
        #[serde(default, deserialize_with = "finite3")]
        angular_velocity: Triple,
    },
}

/// A prescribed velocity [m/s], world.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum VelocityDef {
    Constant(#[serde(deserialize_with = "finite3")] Triple),
    /// `(t [s], (vx, vy, vz) [m/s])`, t strictly increasing; linear between, held beyond.
    Table(#[serde(deserialize_with = "finite_velocity_table")] Vec<(f64, Triple)>),
    /// Per world axis `x(t) = x0 + A sin(2π t / T + φ)` (PHYSICS.md §1 [BC section]): amplitude
    /// `A` \[m], one period `T` \[s] (> 0), phase `φ` \[rad] (default 0); the body starts at its
    /// master position, so `x0 = position − A sin φ`. Checked by the physics' `Harmonic::new`.
    Harmonic {
        #[serde(deserialize_with = "finite3")]
        amplitude: Triple,
        #[serde(deserialize_with = "finite")]
        period: f64,
        #[serde(default, deserialize_with = "finite3")]
        phase: Triple,
    },
}

/// Display shape in the body's reference frame \[m].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ShapeDef {
    /// Full edge lengths along x, y, z; as a contact boundary, each face is split into
    /// `subdivisions × subdivisions` squares (default 4).
    Box {
        #[serde(deserialize_with = "finite3")]
        size: Triple,
        #[serde(default, deserialize_with = "finite3")]
        center: Triple,
        #[serde(default = "default_box_subdivisions")]
        subdivisions: u32,
    },
    /// A sphere; its contact boundary is an icosphere split `subdivisions` times (20·4ⁿ
    /// triangles, default 2: 320).
    Sphere {
        #[serde(deserialize_with = "finite")]
        radius: f64,
        #[serde(default, deserialize_with = "finite3")]
        center: Triple,
        #[serde(default = "default_subdivisions")]
        subdivisions: u32,
    },
    Cylinder {
        #[serde(deserialize_with = "finite")]
        radius: f64,
        #[serde(deserialize_with = "finite")]
        length: f64,
        #[serde(default = "z_axis", deserialize_with = "finite3")]
        axis: Triple,
        #[serde(default, deserialize_with = "finite3")]
        center: Triple,
    },
    /// A closed triangle mesh from a Wavefront OBJ or STL `file` (relative to the scene file),
    /// its coordinates multiplied by `scale` and then moved by `center`.
    Mesh {
        file: String,
        #[serde(default = "one", deserialize_with = "finite")]
        scale: f64,
        #[serde(default, deserialize_with = "finite3")]
        center: Triple,
    },
}

fn default_box_subdivisions() -> u32 {
    4
}

fn default_subdivisions() -> u32 {
    2
}

fn one() -> f64 {
    1.0
}

fn is_zero(value: &f64) -> bool {
    *value == 0.0
}

fn is_zero3(value: &Triple) -> bool {
    value.iter().all(|v| *v == 0.0)
}

fn z_axis() -> Triple {
    [0.0, 0.0, 1.0]
}

/// One end of a coupling.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum EndDef {
    /// A fixed world point \[m].
    World(#[serde(deserialize_with = "finite3")] Triple),
    /// A point on body `body`, in its reference frame \[m].
    Body {
        body: String,
        #[serde(default, deserialize_with = "finite3")]
        point: Triple,
    },
}

/// A coupling between two ends.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum CouplingDef {
    /// Spring with elastic law `law` and linear damping `damping` [N·s/m] (PHYSICS.md §2).
    SpringDamper {
        name: String,
        end1: EndDef,
        end2: EndDef,
        law: LawDef,
        #[serde(default, deserialize_with = "finite")]
        damping: f64,
    },
    /// Elastic catenary line (PHYSICS.md §3, on the seabed §7): `mass_per_length` λ0 [kg/m]
    /// ≥ 0, unstretched `length` L_eq \[m] > 0, `stiffness` D [N/m] > 0 of the whole line
    /// (EA = D L_eq), `displaced_area` A_d \[m²] ≥ 0, its displaced volume per length: in water
    /// it weighs `(λ0 − ρ A_d) g` per metre (default 0); `model` `QuasiStatic` (default) or
    /// `Dynamic(…)` (PHYSICS.md §8, [`LineModelDef`]).
    Catenary {
        name: String,
        end1: EndDef,
        end2: EndDef,
        #[serde(deserialize_with = "finite")]
        mass_per_length: f64,
        #[serde(deserialize_with = "finite")]
        length: f64,
        #[serde(deserialize_with = "finite")]
        stiffness: f64,
        #[serde(default, skip_serializing_if = "is_zero", deserialize_with = "finite")]
        displaced_area: f64,
        #[serde(default, skip_serializing_if = "LineModelDef::is_quasi_static")]
        model: LineModelDef,
        /// The line's minimum breaking load \[N] > 0, for the design check of `tether storm`
        /// (docs/design-loads.md); the physics does not use it.
        #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite_option")]
        breaking_load: Option<f64>,
    },
    /// Penalty contact with tanh friction (PHYSICS.md §4) between the faces of body `body`'s
    /// shape and `against`. Per unit face area: `stiffness` k1 [N/m³] > 0, `damping` k2
    /// [N·s/m³] ≥ 0; `range` d0 \[m] ≥ 0 where pushing starts; `friction` μ ≥ 0;
    /// `friction_sharpness` k_t [s/m] > 0 of the tanh law (default 100); `expected_area` A \[m²]
    /// > 0 behind the time step limit (default: a sixth of the body's boundary area).
    Contact {
        name: String,
        body: String,
        against: AgainstDef,
        #[serde(deserialize_with = "finite")]
        stiffness: f64,
        #[serde(default, deserialize_with = "finite")]
        damping: f64,
        #[serde(default, deserialize_with = "finite")]
        range: f64,
        #[serde(default, deserialize_with = "finite")]
        friction: f64,
        #[serde(default = "default_friction_sharpness", deserialize_with = "finite")]
        friction_sharpness: f64,
        #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "finite_option")]
        expected_area: Option<f64>,
    },
}

fn default_friction_sharpness() -> f64 {
    100.0
}

/// What a contact's faces are pushed away from.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum AgainstDef {
    /// The half-space above the plane through `point` \[m] with `normal` (towards the bodies).
    Plane {
        #[serde(deserialize_with = "finite3")]
        point: Triple,
        #[serde(deserialize_with = "finite3")]
        normal: Triple,
    },
    /// The inside of the axis-aligned box `[min, max]` \[m]: the computational domain's walls.
    DomainBox {
        #[serde(deserialize_with = "finite3")]
        min: Triple,
        #[serde(deserialize_with = "finite3")]
        max: Triple,
    },
    /// Another body's boundary.
    Body(String),
}

impl CouplingDef {
    /// The coupling's name.
    pub fn name(&self) -> &str {
        match self {
            Self::SpringDamper { name, .. } | Self::Catenary { name, .. } | Self::Contact { name, .. } => name,
        }
    }
}

/// Elastic law of a spring (PHYSICS.md §2). Lengths \[m], forces \[N], stiffnesses [N/m].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum LawDef {
    Linear {
        #[serde(deserialize_with = "finite")]
        stiffness: f64,
        #[serde(deserialize_with = "finite")]
        rest_length: f64,
    },
    /// `k_eff = a + b s + c s²`, `s = x − x0`: a [N/m], b [N/m²], c [N/m³].
    Polynomial {
        #[serde(deserialize_with = "finite")]
        a: f64,
        #[serde(default, deserialize_with = "finite")]
        b: f64,
        #[serde(default, deserialize_with = "finite")]
        c: f64,
        #[serde(deserialize_with = "finite")]
        rest_length: f64,
    },
    /// `(x [m], f_e [N])` points, x strictly increasing.
    ForceCurve {
        #[serde(deserialize_with = "finite_pairs")]
        points: Vec<(f64, f64)>,
    },
    /// `(ξ [m], k [N/m])` points, ξ strictly increasing; `f_e = ∫_{x0}^{x} k`.
    StiffnessCurve {
        #[serde(deserialize_with = "finite_pairs")]
        points: Vec<(f64, f64)>,
        #[serde(deserialize_with = "finite")]
        rest_length: f64,
    },
    /// `f_e = f_r + ∫_{x_r}^{x} k`, for a rest length outside the operating range.
    ReferenceForce {
        #[serde(deserialize_with = "finite_pairs")]
        points: Vec<(f64, f64)>,
        #[serde(deserialize_with = "finite")]
        reference_length: f64,
        #[serde(deserialize_with = "finite")]
        reference_force: f64,
        #[serde(deserialize_with = "finite")]
        rest_length: f64,
    },
}
