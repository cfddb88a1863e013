//! One dynamic line in its surroundings: the constants its nodes and segments share, and how
//! short its own time step must be (PHYSICS.md §8 "Discretisation", "Stable time step").

use super::parameters::{InternalDamping, LumpedMass};
use crate::coupling::catenary::Catenary;
use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require_derived};
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
        let segments = parameters.segments() as usize;
        let segment = line.length() / segments as f64;
        let ea = line.stiffness() * line.length();
        let g = surroundings.gravity.norm();
        let up = if g > 0.0 { -surroundings.gravity / g } else { Vec3::z() };
        Self {
            segments,
            segment,
            ea,
            ba: parameters.damping().coefficient(segment, ea, line.mass_per_length()),
            mass_per_length: line.mass_per_length(),
            displaced_area: line.displaced_area(),
            diameter: diameter(line.displaced_area()),
            bearing: bearing_diameter(line.displaced_area(), line.mass_per_length()),
            gravity: surroundings.gravity,
            up,
            density: if water_level.is_some() { surroundings.fluid_density } else { 0.0 },
            water_level,
            seabed: surroundings.seabed,
            parameters: *parameters,
        }
    }

    /// The constants derived here from `line` (the line they were made from), checked: the
    /// segment `l = L/N` \[m] and a node's mass `λ0 l` \[kg] finite and positive; `BA` \[N·s]
    /// finite (from a ratio, `ζ l √(EA λ0)`, PHYSICS.md §8 "Discretisation"); the axial stable
    /// step and, on a seabed, the seabed's spring's (§8 "Stable time step", [`Discrete::limits`])
    /// finite and positive; a node's seabed stiffness `k_b d l` [N/m], damping `c_b d l` [N·s/m]
    /// and friction damper at rest `C_B |w| l/v_s` [N·s/m] (§7, `w` the wet weight per length),
    /// and in water its drag `½ ρ C_dn d l`, `½ ρ C_dt π d l` [kg/m] and added mass `ρ A_d l
    /// max(C_an, C_at)` \[kg] (§8 "Node i"), finite. A value the line's own checks let through
    /// can overflow here (`λ0` of 10³⁰⁸ kg/m, a node of 10³⁰⁶ kg) or underflow (`λ0` of 10⁻³⁰⁸:
    /// an axial step of 0 s); the line is then refused, not run.
    ///
    /// # Errors
    /// [`ParameterError::Derived`], named with the value of `line` or its model that made it.
    pub fn check(&self, line: &Catenary) -> Result<(), ParameterError> {
        let p = &self.parameters;
        let (ba_quantity, ba) = match p.damping() {
            InternalDamping::Coefficient(ba) => ("BA", ba),
            InternalDamping::Ratio(zeta) => ("BA = ζ l √(EA λ0)", zeta),
        };
        let line_inputs = [
            ("length", line.length()),
            ("segments", self.segments as f64),
            ("mass_per_length", line.mass_per_length()),
            ("stiffness", line.stiffness()),
            ("displaced_area", line.displaced_area()),
            ("damping", ba),
        ];
        let with = |more: &[(&'static str, f64)]| [&line_inputs[..], more].concat();
        require_derived("the segment length l = L/N", self.segment, Bound::Positive, "m", &line_inputs[..2])?;
        let mass = self.mass_per_length * self.segment;
        require_derived("a node's mass λ0 l", mass, Bound::Positive, "kg", &line_inputs[..3])?;
        require_derived(ba_quantity, self.ba, Bound::NonNegative, "N·s", &line_inputs)?;
        let limits = self.limits();
        require_derived("the axial stable step", limits.axial, Bound::Positive, "s", &line_inputs)?;
        if let Some(seabed) = &self.seabed {
            let inputs = with(&[("seabed_stiffness", p.seabed_stiffness()), ("seabed_damping", p.seabed_damping())]);
            require_derived("the seabed's stable step", limits.seabed, Bound::Positive, "s", &inputs)?;
            let stiffness = p.seabed_stiffness() * self.bearing * self.segment;
            require_derived("a node's seabed stiffness k_b d l", stiffness, Bound::Finite, "N/m", &inputs)?;
            let damping = p.seabed_damping() * self.bearing * self.segment;
            require_derived("a node's seabed damping c_b d l", damping, Bound::Finite, "N·s/m", &inputs)?;
            let weight = line.submerged_mass_per_length(self.density) * self.gravity.norm();
            let friction = seabed.line_friction() * weight.abs() * self.segment / p.friction_speed();
            let inputs = with(&[("line_friction", seabed.line_friction()), ("friction_speed", p.friction_speed())]);
            require_derived("a node's friction damper C_B |w| l/v_s", friction, Bound::Finite, "N·s/m", &inputs)?;
        }
        if self.density > 0.0 {
            let drag = |c: f64| 0.5 * self.density * c * self.diameter * self.segment;
            let inputs = with(&[("drag_normal", p.drag_normal()), ("density", self.density)]);
            require_derived("a node's drag ½ ρ C_dn d l", drag(p.drag_normal()), Bound::Finite, "kg/m", &inputs)?;
            let inputs = with(&[("drag_tangential", p.drag_tangential()), ("density", self.density)]);
            let tangential = drag(p.drag_tangential()) * std::f64::consts::PI;
            require_derived("a node's drag ½ ρ C_dt π d l", tangential, Bound::Finite, "kg/m", &inputs)?;
            let coefficient = p.added_mass_normal().max(p.added_mass_tangential());
            let added = self.density * self.displaced_area * self.segment * coefficient;
            let inputs = with(&[
                ("added_mass_normal", p.added_mass_normal()),
                ("added_mass_tangential", p.added_mass_tangential()),
                ("density", self.density),
            ]);
            require_derived("a node's added mass ρ A_d l C_a", added, Bound::Finite, "kg", &inputs)?;
        }
        Ok(())
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
            oscillator((self.parameters.seabed_stiffness() * self.bearing / lambda).sqrt(), 0.0)
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
pub const STEEL_DENSITY: f64 = 7850.0;

/// The width \[m] the seabed bears a line on (PHYSICS.md §8 "Seabed width"), from its displaced
/// area `displaced_area` A_d \[m²] and mass per length `mass_per_length` λ0 [kg/m]: its diameter
/// `√(4 A_d/π)`, or, for a line without a displaced area (a dry line), a steel rod's of its mass,
/// `√(4 λ0/(π ρ_steel))`. MoorDyn's files write this as the line's diameter.
pub fn bearing_diameter(displaced_area: f64, mass_per_length: f64) -> f64 {
    diameter(if displaced_area > 0.0 { displaced_area } else { mass_per_length / STEEL_DENSITY })
}

/// `√(4 A/π)` \[m] of a circle of area `area` \[m²].
fn diameter(area: f64) -> f64 {
    (4.0 * area / std::f64::consts::PI).sqrt()
}

/// `2/(√(ω² + β²) + β)` \[s] for angular frequency `omega` [rad/s] and damping rate `rate` [1/s].
fn oscillator(omega: f64, rate: f64) -> f64 {
    2.0 / ((omega * omega + rate * rate).sqrt() + rate)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupling::ends::Endpoint;
    use crate::coupling::lumped_line::{LineModel, LumpedMassSpec};

    /// The values of a line that a test may change before [`Catenary::new`] checks them.
    struct LineValues {
        mass_per_length: f64,
        length: f64,
        stiffness: f64,
    }

    /// `lines.txt`'s OC3 line (λ0 = 77.7066 kg/m, d = 0.09 m, EA = 384.243 MN over 902.2 m, N =
    /// 20, ζ = 0.8, C_dn 1.6, C_dt 0.1, C_an 1) with `edit` made to its values and to its model's
    /// before their constructors check them, on a seabed in water of 1025 kg/m³: its constants'
    /// check.
    fn check(edit: impl Fn(&mut LineValues, &mut LumpedMassSpec)) -> Result<(), ParameterError> {
        let mut model = LumpedMassSpec {
            drag_normal: 1.6,
            drag_tangential: 0.1,
            added_mass_normal: 1.0,
            ..LumpedMassSpec::plain(20, InternalDamping::Ratio(0.8))
        };
        let mut values = LineValues { mass_per_length: 77.7066, length: 902.2, stiffness: 384.243e6 / 902.2 };
        edit(&mut values, &mut model);
        let model = LumpedMass::new(model).expect("a value its own check lets through");
        let ends = (Endpoint::World(Vec3::new(853.87, 0.0, -320.0)), Endpoint::World(Vec3::new(5.2, 0.0, -70.0)));
        let line = Catenary::new(ends.0, ends.1, values.mass_per_length, values.length, values.stiffness)
            .and_then(|line| line.with_displaced_area(std::f64::consts::PI * 0.09 * 0.09 / 4.0))
            .expect("a value its own check lets through")
            .with_model(LineModel::Dynamic(model));
        let seabed = Seabed::new(-320.0, 0.5).expect("valid");
        let surroundings = Surroundings { seabed: Some(seabed), ..Surroundings::dry(Vec3::new(0.0, 0.0, -9.80665)) };
        let surroundings = Surroundings { fluid_density: 1025.0, ..surroundings };
        Discrete::new(&line, &model, &surroundings, Some(0.0)).check(&line)
    }

    /// Issue 48: each value that its own check lets through but that makes a derived constant
    /// overflow or vanish is refused, naming the constant and the field at fault.
    #[test]
    fn each_overflowing_or_vanishing_constant_is_refused_naming_its_field() {
        assert_eq!(check(|_, _| {}), Ok(()));
        let refused = |edit: &dyn Fn(&mut LineValues, &mut LumpedMassSpec)| check(edit).unwrap_err().to_string();
        assert_eq!(
            refused(&|line, _| line.stiffness = 1e305),
            "BA = ζ l √(EA λ0) must be finite, got inf (from stiffness = 1e305)"
        );
        assert_eq!(
            refused(&|line, _| line.mass_per_length = 1e-308),
            "the axial stable step must be > 0 s, got 0 (from mass_per_length = 1e-308)"
        );
        assert_eq!(
            refused(&|line, _| line.mass_per_length = 0.0),
            "a node's mass λ0 l must be > 0 kg, got 0 (from mass_per_length = 0)"
        );
        assert_eq!(
            refused(&|line, _| {
                line.length = 1e308;
                line.stiffness = 1e-3;
            }),
            "a node's mass λ0 l must be finite, got inf (from length = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.damping = InternalDamping::Coefficient(1e308)),
            "the axial stable step must be > 0 s, got 0 (from damping = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.drag_normal = 1e308),
            "a node's drag ½ ρ C_dn d l must be finite, got inf (from drag_normal = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.drag_tangential = 1e308),
            "a node's drag ½ ρ C_dt π d l must be finite, got inf (from drag_tangential = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.added_mass_tangential = 1e308),
            "a node's added mass ρ A_d l C_a must be finite, got inf (from added_mass_tangential = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.seabed_stiffness = 1e308),
            "a node's seabed stiffness k_b d l must be finite, got inf (from seabed_stiffness = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.seabed_damping = 1e308),
            "a node's seabed damping c_b d l must be finite, got inf (from seabed_damping = 1e308)"
        );
        assert_eq!(
            refused(&|_, model| model.friction_speed = 1e-308),
            "a node's friction damper C_B |w| l/v_s must be finite, got inf (from friction_speed = 1e-308)"
        );
        let error = check(|line, _| line.mass_per_length = 1e308).unwrap_err();
        assert_eq!(error.field(), "mass_per_length", "{error}");
    }
}
