//! One dynamic line in its surroundings: the constants its nodes and segments share, and how
//! short its own time step must be (PHYSICS.md §8 "Discretisation", "Stable time step").

use super::parameters::LumpedMass;
use crate::coupling::catenary::Catenary;
use crate::math::Vec3;
use crate::seabed::Seabed;
use crate::surroundings::Surroundings;

/// Fraction of the stable sub-step a line steps by.
pub const SUBSTEP_MARGIN: f64 = 0.8;

/// How much a line's largest tension may grow over an evaluation's interval with its sub-steps
/// staying stable ([`Discrete::substep`]): the transverse limit, bound by `√T`, is taken at
/// twice the tension the interval starts with (so 0.8/√2 of it at the start).
pub const TENSION_GROWTH: f64 = 2.0;

/// A line's constants in SI units, made at each evaluation from its coupling and what surrounds
/// it (a live edit of either is seen at the next).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Discrete {
    /// `N`.
    pub segments: usize,
    /// `l = L/N` \[m].
    pub segment: f64,
    /// `EA` \[N].
    pub ea: f64,
    /// `BA` \[N·s].
    pub ba: f64,
    /// `λ0` [kg/m].
    pub mass_per_length: f64,
    /// `A_d` \[m²] and the volume-equivalent diameter `d = √(4 A_d/π)` \[m].
    pub displaced_area: f64,
    pub diameter: f64,
    /// The width `d` \[m] the seabed pushes on: the diameter, or for a line that declares no
    /// displaced area, that of a steel rod (7850 kg/m³) of its mass per length.
    pub bearing: f64,
    /// Gravity [m/s²], and the unit upward vertical `−ĝ`.
    pub gravity: Vec3,
    pub up: Vec3,
    /// `ρ` [kg/m³] of the water the line is in (0 without water).
    pub density: f64,
    /// Height of the still water surface along `up` \[m], if the scene has water.
    pub water_level: Option<f64>,
    pub seabed: Option<Seabed>,
    pub parameters: LumpedMass,
}

impl Discrete {
    /// The constants of `line` modelled by `parameters` in `surroundings`, with the still water
    /// surface at `water_level` \[m] if there is water.
    pub fn new(
        line: &Catenary,
        parameters: &LumpedMass,
        surroundings: &Surroundings,
        water_level: Option<f64>,
    ) -> Self {
        let segments = parameters.segments as usize;
        let segment = line.length / segments as f64;
        let ea = line.stiffness * line.length;
        let g = surroundings.gravity.norm();
        let up = if g > 0.0 { -surroundings.gravity / g } else { Vec3::z() };
        Self {
            segments,
            segment,
            ea,
            ba: parameters.damping.coefficient(segment, ea, line.mass_per_length),
            mass_per_length: line.mass_per_length,
            displaced_area: line.displaced_area,
            diameter: diameter(line.displaced_area),
            bearing: if line.displaced_area > 0.0 {
                diameter(line.displaced_area)
            } else {
                diameter(line.mass_per_length / STEEL_DENSITY)
            },
            gravity: surroundings.gravity,
            up,
            density: if water_level.is_some() { surroundings.fluid_density } else { 0.0 },
            water_level,
            seabed: surroundings.seabed,
            parameters: *parameters,
        }
    }

    /// `l_i` \[m]: the length of line node `i` carries (`l/2` at an end).
    #[inline(always)]
    pub fn share(&self, node: usize) -> f64 {
        if node == 0 || node == self.segments { 0.5 * self.segment } else { self.segment }
    }

    /// Whether a node at `position` is under the still water surface.
    #[inline(always)]
    pub fn submerged(&self, position: &Vec3) -> bool {
        self.water_level.is_some_and(|level| position.dot(&self.up) < level)
    }

    /// The line's stable time steps \[s] (`2/(√(ω² + β²) + β)` for a mode `ω` damped at rate
    /// `β`, PHYSICS.md §8): the axial one of its highest mode, `ω = 2√(EA/(λ0 l²))`, `β = 2
    /// BA/(λ0 l²)`, which an explicit integrator (MoorDyn's) must resolve and the sub-steps take
    /// implicitly ([`super::axial`]); and the seabed's spring's, `2/ω` with `ω² = k_b d/λ0` (its
    /// damping and friction are taken implicitly, [`super::nodes::NodeForces::solve_damped`],
    /// and bound no step).
    pub fn limits(&self) -> LineLimits {
        let lambda = self.mass_per_length.max(f64::MIN_POSITIVE);
        let l2 = self.segment * self.segment;
        let axial = oscillator(2.0 * (self.ea / (lambda * l2)).sqrt(), 2.0 * self.ba / (lambda * l2));
        let seabed = self.seabed.map_or(f64::INFINITY, |_| {
            oscillator((self.parameters.seabed_stiffness * self.bearing / lambda).sqrt(), 0.0)
        });
        LineLimits { axial, seabed }
    }

    /// The stable step \[s] of the transverse modes under a largest segment tension `tension`
    /// \[N]: `2/ω`, `ω = 2√(T/(λ0 l²))` (the segments' directions are explicit in a sub-step;
    /// a stretched segment and the added mass only slow these modes). Infinite for a slack line.
    pub fn transverse_limit(&self, tension: f64) -> f64 {
        let lambda = self.mass_per_length.max(f64::MIN_POSITIVE);
        if tension > 0.0 {
            oscillator(2.0 * (tension / (lambda * self.segment * self.segment)).sqrt(), 0.0)
        } else {
            f64::INFINITY
        }
    }

    /// The sub-step the line takes over an evaluation's interval that starts with its largest
    /// segment tension at `tension` \[N]: [`SUBSTEP_MARGIN`] of the shorter of its seabed limit
    /// and its transverse limit at [`TENSION_GROWTH`] times that tension (infinite when neither
    /// binds: one sub-step per evaluation).
    pub fn substep(&self, tension: f64) -> f64 {
        SUBSTEP_MARGIN * self.limits().seabed.min(self.transverse_limit(TENSION_GROWTH * tension))
    }
}

/// A line's own stable time steps \[s] (infinite where nothing limits).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineLimits {
    pub axial: f64,
    pub seabed: f64,
}

/// Density of steel [kg/m³], for the bearing width of a line without a displaced area.
const STEEL_DENSITY: f64 = 7850.0;

/// `√(4 A/π)` \[m] of a circle of area `area` \[m²].
fn diameter(area: f64) -> f64 {
    (4.0 * area / std::f64::consts::PI).sqrt()
}

/// `2/(√(ω² + β²) + β)` \[s] for angular frequency `omega` [rad/s] and damping rate `rate` [1/s].
fn oscillator(omega: f64, rate: f64) -> f64 {
    2.0 / ((omega * omega + rate * rate).sqrt() + rate)
}
