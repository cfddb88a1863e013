//! Every tunable field of a scene's sections, written once: its path below the section (the
//! sweep's value path continues the section's, `couplings.spring` + `law.stiffness`), its label
//! as the window's knob shows it and the catalogue lists it, and its unit. The window's panels
//! draw their knobs from these constants and the catalogue ([`super::parameters`]) lists them,
//! so a knob and its catalogue entry cannot read differently.

/// A tunable field: `path` below its section, `label` and `unit` as a person reads them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Field {
    pub path: &'static str,
    pub label: &'static str,
    pub unit: &'static str,
}

impl Field {
    const fn new(path: &'static str, label: &'static str, unit: &'static str) -> Self {
        Self { path, label, unit }
    }

    /// The field's component along body axis `axis` (0, 1, 2): path `drag.2`, label `drag C_d z`.
    pub fn axis(&self, axis: usize) -> (String, String) {
        (format!("{}.{axis}", self.path), format!("{} {}", self.label, AXES[axis]))
    }

    /// A table's `row`-th point's value (its second number): path `law.points.3.1`, label
    /// `point 4 f`.
    pub fn point(&self, row: usize) -> (String, String) {
        (format!("{}.{row}.1", self.path), format!("point {} {}", row + 1, self.label))
    }
}

/// The body axes' names, as [`Field::axis`] labels them.
pub const AXES: [&str; 3] = ["x", "y", "z"];

// A spring-damper's elastic law (PHYSICS.md §2) and damping.
pub const LAW_STIFFNESS: Field = Field::new("law.stiffness", "stiffness k", "N/m");
pub const LAW_REST_LENGTH: Field = Field::new("law.rest_length", "rest length x0", "m");
pub const LAW_A: Field = Field::new("law.a", "a", "N/m");
pub const LAW_B: Field = Field::new("law.b", "b", "N/m²");
pub const LAW_C: Field = Field::new("law.c", "c", "N/m³");
pub const LAW_REFERENCE_LENGTH: Field = Field::new("law.reference_length", "reference length x_r", "m");
pub const LAW_REFERENCE_FORCE: Field = Field::new("law.reference_force", "reference force f_r", "N");
/// A force curve's point: its elongation (not tuned by a fit) and its force.
pub const FORCE_CURVE_X: Field = Field::new("law.points", "x", "m");
pub const FORCE_CURVE_F: Field = Field::new("law.points", "f", "N");
/// A stiffness curve's point: its strain measure (not tuned by a fit) and its stiffness.
pub const STIFFNESS_CURVE_XI: Field = Field::new("law.points", "ξ", "m");
pub const STIFFNESS_CURVE_K: Field = Field::new("law.points", "k", "N/m");
pub const SPRING_DAMPING: Field = Field::new("damping", "damping k_d", "N·s/m");

// A catenary (PHYSICS.md §3) and a dynamic line's model (§8).
pub const MASS_PER_LENGTH: Field = Field::new("mass_per_length", "mass per length λ0", "kg/m");
pub const LENGTH: Field = Field::new("length", "length L_eq", "m");
pub const LINE_STIFFNESS: Field = Field::new("stiffness", "stiffness D", "N/m");
pub const DISPLACED_AREA: Field = Field::new("displaced_area", "displaced area A_d", "m²");
/// A count: the window tunes it, a fit does not.
pub const SEGMENTS: Field = Field::new("model.segments", "segments N", "–");
pub const DAMPING_RATIO: Field = Field::new("model.damping", "damping ratio ζ", "–");
pub const DAMPING_BA: Field = Field::new("model.damping", "damping BA", "N·s");
pub const DRAG_NORMAL: Field = Field::new("model.drag_normal", "drag C_dn", "–");
pub const DRAG_TANGENTIAL: Field = Field::new("model.drag_tangential", "drag C_dt", "–");
pub const ADDED_MASS_NORMAL: Field = Field::new("model.added_mass_normal", "added mass C_an", "–");
pub const ADDED_MASS_TANGENTIAL: Field = Field::new("model.added_mass_tangential", "added mass C_at", "–");

// A contact's law (PHYSICS.md §4).
pub const CONTACT_STIFFNESS: Field = Field::new("stiffness", "stiffness k1", "N/m³");
pub const CONTACT_DAMPING: Field = Field::new("damping", "damping k2", "N·s/m³");
pub const RANGE: Field = Field::new("range", "range d0", "m");
pub const FRICTION: Field = Field::new("friction", "friction μ", "–");
pub const FRICTION_SHARPNESS: Field = Field::new("friction_sharpness", "friction sharpness k_t", "s/m");
pub const EXPECTED_AREA: Field = Field::new("expected_area", "expected area A", "m²");

// The water (PHYSICS.md §6).
pub const WAVE_HEIGHT: Field = Field::new("waves.height", "wave height H", "m");
pub const WAVE_PERIOD: Field = Field::new("waves.period", "wave period T", "s");
pub const WAVE_HEADING: Field = Field::new("waves.heading_deg", "wave heading", "°");
pub const SIGNIFICANT_HEIGHT: Field = Field::new("waves.hs", "significant height Hs", "m");
pub const PEAK_PERIOD: Field = Field::new("waves.tp", "peak period Tp", "s");
pub const CURRENT_SPEED: Field = Field::new("current.speed", "current speed", "m/s");
pub const CURRENT_HEADING: Field = Field::new("current.heading_deg", "current heading", "°");
pub const WATER_DENSITY: Field = Field::new("density", "density ρ", "kg/m³");

// A floating body's coefficients in the water (PHYSICS.md §6), per body axis ([`Field::axis`]).
pub const HYDRO_DRAG: Field = Field::new("drag", "drag C_d", "–");
pub const HYDRO_ADDED_MASS: Field = Field::new("added_mass", "added mass C_a", "–");
pub const HYDRO_LINEAR_DAMPING: Field = Field::new("linear_damping", "linear damping", "N·s/m");

// The seabed (PHYSICS.md §7).
pub const LINE_FRICTION: Field = Field::new("line_friction", "line friction C_B", "–");

// The air (PHYSICS.md §10).
pub const WIND_SPEED: Field = Field::new("wind.speed", "wind speed U_r (at z_r)", "m/s");
pub const WIND_HEIGHT: Field = Field::new("wind.height", "reference height z_r", "m");
pub const WIND_HEADING: Field = Field::new("wind.heading_deg", "wind heading (toward)", "°");
pub const TURBULENCE_INTENSITY: Field = Field::new("wind.gusts.intensity", "turbulence intensity", "–");
/// A seed: the window sets it, a fit does not.
pub const GUST_SEED: Field = Field::new("wind.gusts.seed", "gust seed", "");
pub const AIR_DENSITY: Field = Field::new("density", "air density ρ_a", "kg/m³");
