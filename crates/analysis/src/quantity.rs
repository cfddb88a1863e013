//! The quantities of a running world that a sweep's metric reduces and a fit compares with a
//! measured record, by the names the recording and the scene use: a body's position, velocity,
//! roll/pitch/yaw and angular velocity, a coupling's tension, end tensions, end forces and
//! length, the energy account.
//!
//! | quantity | what | unit |
//! |---|---|---|
//! | `Tension("c")` | the coupling's scalar force: a spring's `f_e + k_d ẋ`, a catenary's larger end tension, a contact's normal force (PHYSICS.md §2–§4) | N |
//! | `EndTension("c", End1 \| End2)` | `\|f₁\|` or `\|f₂\|`: a line's anchor or fairlead tension (the recording's `c end1`, `c end2`) | N |
//! | `EndForce("c", End1 \| End2, X \| Y \| Z)` | a component of the force the coupling exerts on that end, world | N |
//! | `Length("c")` | the distance between the coupling's ends (a spring's length) | m |
//! | `Position("b", X \| Y \| Z)`, `Velocity("b", …)` | a coordinate of G and of its velocity, world | m, m/s |
//! | `Angle("b", Roll \| Pitch \| Yaw)` | the turn since t = 0 as roll–pitch–yaw angles about the world x, y, z axes (the recording's `plots/water/<b>/angles`) | rad |
//! | `AngularVelocity("b", X \| Y \| Z)` | a component of ω, world | rad/s |
//! | `Speed("b")`, `AngularSpeed("b")` | `\|v_G\|`, `\|ω\|` | m/s, rad/s |
//! | `Excursion("b")`, `Rotation("b")` | `\|x_G(t) − x_G(0)\|`, the angle of `q(0)⁻¹ q(t)` | m, rad |
//! | `Energy(part)` | a part of the energy account, PHYSICS.md §5 | J |

use serde::{Deserialize, Serialize};
use tether_physics::body::BodyState;
use tether_physics::math::{Rotation, Vec3};
use tether_physics::world::World;

/// A quantity of a run at one instant, as a spec names it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub enum Quantity {
    /// A coupling's scalar force \[N].
    Tension(String),
    /// The magnitude of the force on one end of a coupling \[N].
    EndTension(String, End),
    /// A component of the force a coupling exerts on one end, world \[N].
    EndForce(String, End, Axis),
    /// The distance between a coupling's ends \[m].
    Length(String),
    /// A coordinate of a body's G, world \[m].
    Position(String, Axis),
    /// A component of a body's velocity of G, world [m/s].
    Velocity(String, Axis),
    /// A body's turn since t = 0 as roll, pitch or yaw \[rad].
    Angle(String, Turn),
    /// A component of a body's angular velocity, world [rad/s].
    AngularVelocity(String, Axis),
    /// `|v_G|` [m/s].
    Speed(String),
    /// `|ω|` [rad/s].
    AngularSpeed(String),
    /// `|x_G(t) − x_G(0)|` \[m].
    Excursion(String),
    /// The angle of `q(0)⁻¹ q(t)` \[rad].
    Rotation(String),
    /// A part of the energy account, PHYSICS.md §5 \[J].
    Energy(EnergyPart),
}

impl Quantity {
    /// Its unit, SI as the recording and the scene use it: what every table, chart and choice
    /// that shows the quantity writes after it.
    pub fn unit(&self) -> &'static str {
        match self {
            Self::Tension(_) | Self::EndTension(..) | Self::EndForce(..) => "N",
            Self::Length(_) | Self::Position(..) | Self::Excursion(_) => "m",
            Self::Velocity(..) | Self::Speed(_) => "m/s",
            Self::AngularVelocity(..) | Self::AngularSpeed(_) => "rad/s",
            Self::Angle(..) | Self::Rotation(_) => "rad",
            Self::Energy(_) => "J",
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Axis {
    X,
    Y,
    Z,
}

/// A coupling's end.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum End {
    End1,
    End2,
}

/// Roll, pitch and yaw of `q(t) q(0)⁻¹` (nalgebra's `euler_angles`: about world x, then y, then z).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Turn {
    Roll,
    Pitch,
    Yaw,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum EnergyPart {
    Kinetic,
    Gravity,
    Elastic,
    Dissipated,
    ExternalWork,
    /// kinetic + gravity + elastic.
    Total,
    /// total + dissipated − external work.
    Balance,
}

/// A quantity with its body or coupling found in a world, by index.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Probe {
    Tension(usize),
    EndTension(usize, End),
    EndForce(usize, End, Axis),
    Length(usize),
    Position(usize, Axis),
    Velocity(usize, Axis),
    Angle(usize, Turn),
    AngularVelocity(usize, Axis),
    Speed(usize),
    AngularSpeed(usize),
    Excursion(usize),
    Rotation(usize),
    Energy(EnergyPart),
}

impl Probe {
    /// The probe of `quantity` in `world`, its names resolved.
    ///
    /// # Errors
    /// A body or coupling the world does not have, with the names it has.
    pub fn find(world: &World, quantity: &Quantity) -> Result<Self, String> {
        let body = |name: &str| {
            world.bodies().iter().position(|b| b.name == name).ok_or_else(|| {
                let names: Vec<&str> = world.bodies().iter().map(|b| b.name.as_str()).collect();
                format!("the scene has no body \"{name}\" (bodies: {})", names.join(", "))
            })
        };
        let coupling = |name: &str| {
            world.couplings().iter().position(|c| c.name == name).ok_or_else(|| {
                let names: Vec<&str> = world.couplings().iter().map(|c| c.name.as_str()).collect();
                format!(
                    "the scene has no coupling \"{name}\" (couplings: {})",
                    if names.is_empty() { "none".into() } else { names.join(", ") }
                )
            })
        };
        Ok(match quantity {
            Quantity::Tension(name) => Self::Tension(coupling(name)?),
            Quantity::EndTension(name, end) => Self::EndTension(coupling(name)?, *end),
            Quantity::EndForce(name, end, axis) => Self::EndForce(coupling(name)?, *end, *axis),
            Quantity::Length(name) => Self::Length(coupling(name)?),
            Quantity::Position(name, axis) => Self::Position(body(name)?, *axis),
            Quantity::Velocity(name, axis) => Self::Velocity(body(name)?, *axis),
            Quantity::Angle(name, turn) => Self::Angle(body(name)?, *turn),
            Quantity::AngularVelocity(name, axis) => Self::AngularVelocity(body(name)?, *axis),
            Quantity::Speed(name) => Self::Speed(body(name)?),
            Quantity::AngularSpeed(name) => Self::AngularSpeed(body(name)?),
            Quantity::Excursion(name) => Self::Excursion(body(name)?),
            Quantity::Rotation(name) => Self::Rotation(body(name)?),
            Quantity::Energy(part) => Self::Energy(*part),
        })
    }

    /// The body whose state it reads.
    pub fn body(self) -> Option<usize> {
        match self {
            Self::Position(b, _)
            | Self::Velocity(b, _)
            | Self::Angle(b, _)
            | Self::AngularVelocity(b, _)
            | Self::Speed(b)
            | Self::AngularSpeed(b)
            | Self::Excursion(b)
            | Self::Rotation(b) => Some(b),
            Self::Tension(_) | Self::EndTension(..) | Self::EndForce(..) | Self::Length(_) | Self::Energy(_) => None,
        }
    }
}

/// What a probe reads of a world besides the world itself: the states of the bodies probes
/// read this step (synchronised once for all of them), and each body's pose at t = 0.
pub struct Readings {
    states: Vec<Option<BodyState>>,
    read: Vec<usize>,
    start: Vec<(Vec3, Rotation)>,
}

impl Readings {
    /// For `probes` of `world` at t = 0.
    pub fn new<'p>(world: &World, probes: impl IntoIterator<Item = &'p Probe>) -> Self {
        let bodies = world.bodies().len();
        let mut read: Vec<usize> = probes.into_iter().filter_map(|p| p.body()).collect();
        read.sort_unstable();
        read.dedup();
        let start = (0..bodies).map(|i| world.state(i)).map(|s| (s.position, s.orientation)).collect();
        Self { states: vec![None; bodies], read, start }
    }

    /// Reads the bodies' states of this step: call once per step before [`Readings::value`].
    pub fn update(&mut self, world: &World) {
        for &body in &self.read {
            self.states[body] = Some(world.state(body));
        }
    }

    /// The probe's value now.
    pub fn value(&self, probe: Probe, world: &World) -> f64 {
        let component = |v: &Vec3, a: Axis| match a {
            Axis::X => v.x,
            Axis::Y => v.y,
            Axis::Z => v.z,
        };
        // Bodies a probe reads were read this step (`Readings::update`).
        let body = |b: usize, f: &dyn Fn(&BodyState) -> f64| self.states[b].as_ref().map_or(0.0, f);
        let end_force = |c: usize, end: End| {
            let forces = &world.coupling_forces()[c];
            match end {
                End::End1 => forces.f1,
                End::End2 => forces.f2,
            }
        };
        match probe {
            Probe::Tension(c) => world.coupling_forces()[c].tension,
            Probe::EndTension(c, end) => end_force(c, end).norm(),
            Probe::EndForce(c, end, axis) => component(&end_force(c, end), axis),
            Probe::Length(c) => {
                let forces = &world.coupling_forces()[c];
                (forces.point2 - forces.point1).norm()
            }
            Probe::Position(b, a) => body(b, &|s| component(&s.position, a)),
            Probe::Velocity(b, a) => body(b, &|s| component(&s.velocity, a)),
            Probe::Angle(b, turn) => body(b, &|s| {
                let (roll, pitch, yaw) = (s.orientation * self.start[b].1.inverse()).euler_angles();
                match turn {
                    Turn::Roll => roll,
                    Turn::Pitch => pitch,
                    Turn::Yaw => yaw,
                }
            }),
            Probe::AngularVelocity(b, a) => body(b, &|s| component(&s.angular_velocity, a)),
            Probe::Speed(b) => body(b, &|s| s.velocity.norm()),
            Probe::AngularSpeed(b) => body(b, &|s| s.angular_velocity.norm()),
            Probe::Excursion(b) => body(b, &|s| (s.position - self.start[b].0).norm()),
            Probe::Rotation(b) => body(b, &|s| (self.start[b].1.inverse() * s.orientation).angle()),
            Probe::Energy(part) => {
                let e = world.energy();
                match part {
                    EnergyPart::Kinetic => e.kinetic,
                    EnergyPart::Gravity => e.gravity,
                    EnergyPart::Elastic => e.elastic,
                    EnergyPart::Dissipated => e.dissipated,
                    EnergyPart::ExternalWork => e.external_work,
                    EnergyPart::Total => e.total(),
                    EnergyPart::Balance => e.balance(),
                }
            }
        }
    }
}
