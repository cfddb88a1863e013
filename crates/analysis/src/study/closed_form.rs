//! The closed form of the damped linear oscillator, the study's exact reference where a scene is
//! one (PHYSICS.md §2, §5): one body that may only translate along one world axis, held against
//! rotation, on one linear spring-damper to a world point on that axis.
//!
//! With `y = x − x_eq` the body's offset from its equilibrium along the axis,
//! `m ÿ + c ẏ + k y = 0`, `ω0 = √(k/m)` [rad/s], `ζ = c/(2√(k m))`:
//! - `ζ < 1`: `y = e^(−ζω0 t) [y0 cos ωd t + (v0 + ζω0 y0)/ωd sin ωd t]`, `ωd = ω0 √(1 − ζ²)`;
//! - `ζ = 1`: `y = e^(−ω0 t) [y0 + (v0 + ω0 y0) t]`;
//! - `ζ > 1`: `y = C1 e^(r1 t) + C2 e^(r2 t)`, `r1,2 = −ω0 (ζ ∓ √(ζ² − 1))`,
//!   `C1 = (v0 − r2 y0)/(r1 − r2)`, `C2 = y0 − C1`.
//!
//! The equilibrium is where the spring holds the weight along the axis:
//! `x_eq = a − r + s L0 + m g/k` (`a` the anchor and `r` the end's offset from G along the axis,
//! `s` the side of the anchor the end is on, `L0` the rest length, `g` gravity along the axis).

use tether_physics::body::Support;
use tether_physics::coupling::{CouplingKind, ElasticLaw, Endpoint};
use tether_physics::math::{Rotation, Vec3};
use tether_scene::Scene;

/// A damped linear oscillator along one world axis, and its start.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Oscillator {
    /// m [kg].
    mass: f64,
    /// k [N/m] > 0.
    stiffness: f64,
    /// c [N·s/m] ≥ 0.
    damping: f64,
    /// L0 [m].
    rest_length: f64,
    /// The free world axis (0, 1, 2).
    axis: usize,
    /// `x_eq` [m], G's coordinate along the axis at equilibrium.
    equilibrium: f64,
    /// The spring's length at equilibrium [m] (its length is `this + s y`).
    length_at_equilibrium: f64,
    /// `s`: +1 when the body's end is on the positive side of the anchor along the axis, −1 when
    /// on the negative side.
    side: f64,
    /// G and the orientation at t = 0 (the other coordinates and the orientation stay).
    start: Vec3,
    orientation: Rotation,
    /// `y0` [m], `v0` [m/s].
    offset: f64,
    speed: f64,
}

/// The state of the oscillator at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Exact {
    /// G \[m], world.
    pub position: Vec3,
    pub orientation: Rotation,
    /// Kinetic energy `½ m v²` \[J].
    pub kinetic: f64,
    /// The spring's elastic energy `½ k (L − L0)²` \[J].
    pub elastic: f64,
}

impl Oscillator {
    /// The oscillator `scene` is, or why it is none.
    ///
    /// # Errors
    /// A sentence naming what the scene has that the closed form does not cover.
    pub fn of_scene(scene: &Scene) -> Result<Self, String> {
        let world = &scene.world;
        let system = world.system();
        let [body] = system.bodies() else {
            return Err(format!("it has {} bodies, the closed form one", system.bodies().len()));
        };
        let [coupling] = system.couplings() else {
            return Err(format!("it has {} couplings, the closed form one spring-damper", system.couplings().len()));
        };
        let Support::Fixed { translation, rotation: true } = body.support else {
            return Err(format!("body \"{}\" must be held against rotation and free along one axis only", body.name));
        };
        let free: Vec<usize> = (0..3).filter(|&axis| !translation[axis]).collect();
        let [axis] = free[..] else {
            return Err(format!(
                "body \"{}\" must be free along exactly one axis, it is along {}",
                body.name,
                free.len()
            ));
        };
        let CouplingKind::SpringDamper(spring) = &coupling.kind else {
            return Err(format!("coupling \"{}\" is not a spring-damper", coupling.name));
        };
        let &ElasticLaw::Linear { stiffness, rest_length } = spring.law() else {
            return Err(format!("coupling \"{}\" has no linear law", coupling.name));
        };
        if !(stiffness > 0.0) {
            return Err(format!("coupling \"{}\" has no stiffness", coupling.name));
        }
        let anchor = match (spring.end1(), spring.end2()) {
            (Endpoint::World(anchor), Endpoint::Body { .. } | Endpoint::Center { .. })
            | (Endpoint::Body { .. } | Endpoint::Center { .. }, Endpoint::World(anchor)) => anchor,
            _ => return Err(format!("coupling \"{}\" must join the body to a world point", coupling.name)),
        };
        let initial = system.initial_states()[0];
        let on_body = match (spring.end1(), spring.end2()) {
            (Endpoint::World(_), end) | (end, Endpoint::World(_)) => initial.point(&end.point()),
            _ => unreachable!("one end is the world point found above"),
        };
        let chord = on_body - anchor;
        if (0..3).any(|k| k != axis && chord[k].abs() > 1e-12 * (1.0 + chord.norm())) {
            return Err(format!("coupling \"{}\" does not lie along the body's free axis", coupling.name));
        }
        let side = chord[axis].signum();
        let (mass, damping) = (body.mass(), spring.damping());
        let gravity = system.gravity()[axis];
        let offset_of_end = on_body[axis] - initial.position[axis];
        let equilibrium = anchor[axis] - offset_of_end + side * rest_length + mass * gravity / stiffness;
        let length_at_equilibrium = side * (equilibrium + offset_of_end - anchor[axis]);
        let oscillator = Self {
            mass,
            stiffness,
            damping,
            rest_length,
            axis,
            equilibrium,
            length_at_equilibrium,
            side,
            start: initial.position,
            orientation: initial.orientation,
            offset: initial.position[axis] - equilibrium,
            speed: initial.velocity[axis],
        };
        // The energy of the motion about equilibrium never grows: |y| ≤ √(y0² + m v0²/k).
        let reach = (oscillator.offset.powi(2) + mass * oscillator.speed.powi(2) / stiffness).sqrt();
        if !(length_at_equilibrium > reach) {
            return Err(format!(
                "coupling \"{}\" could pass through zero length, where the closed form ends",
                coupling.name
            ));
        }
        Ok(oscillator)
    }

    /// `ω0` [rad/s] and `ζ` [–].
    fn frequency_and_damping_ratio(&self) -> (f64, f64) {
        let omega = (self.stiffness / self.mass).sqrt();
        (omega, self.damping / (2.0 * (self.stiffness * self.mass).sqrt()))
    }

    /// `(y, ẏ)` [m, m/s] at time `t` [s].
    fn offset_and_speed(&self, t: f64) -> (f64, f64) {
        let (omega, zeta) = self.frequency_and_damping_ratio();
        let (y0, v0) = (self.offset, self.speed);
        if zeta < 1.0 {
            let omega_d = omega * (1.0 - zeta * zeta).sqrt();
            let (a, b) = (y0, (v0 + zeta * omega * y0) / omega_d);
            let (sin, cos) = (omega_d * t).sin_cos();
            let decay = (-zeta * omega * t).exp();
            (
                decay * (a * cos + b * sin),
                decay * ((b * omega_d - zeta * omega * a) * cos - (a * omega_d + zeta * omega * b) * sin),
            )
        } else if zeta == 1.0 {
            let b = v0 + omega * y0;
            let decay = (-omega * t).exp();
            (decay * (y0 + b * t), decay * (b - omega * (y0 + b * t)))
        } else {
            let root = (zeta * zeta - 1.0).sqrt();
            let (r1, r2) = (-omega * (zeta - root), -omega * (zeta + root));
            let c1 = (v0 - r2 * y0) / (r1 - r2);
            let c2 = y0 - c1;
            let (e1, e2) = ((r1 * t).exp(), (r2 * t).exp());
            (c1 * e1 + c2 * e2, c1 * r1 * e1 + c2 * r2 * e2)
        }
    }

    /// The exact state at time `t` \[s].
    pub fn at(&self, t: f64) -> Exact {
        let (y, v) = self.offset_and_speed(t);
        let mut position = self.start;
        position[self.axis] = self.equilibrium + y;
        let stretch = self.length_at_equilibrium + self.side * y - self.rest_length;
        Exact {
            position,
            orientation: self.orientation,
            kinetic: 0.5 * self.mass * v * v,
            elastic: 0.5 * self.stiffness * stretch * stretch,
        }
    }
}
