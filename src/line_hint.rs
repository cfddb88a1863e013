//! Whether a quasi-static line is likely wrong (docs/dynamic-lines.md, "When a quasi-static
//! line is wrong"): the catenary of PHYSICS.md §3/§7 follows its fairlead instantly, which holds
//! while the fairlead moves slowly against the line's own dynamics. Two measures, each with its
//! numbers, for `tether check` and beside the window's model switch:
//!
//! - **period**: the suspended span's first transverse period `T₁ = 2 L_s / c`, the wave speed
//!   `c = √(T̄ / m)` of a taut string of mean tension `T̄` \[N] and mass per length
//!   `m = λ0 + ρ A_d` \[kg/m] (the water it displaces moving with it: `C_an = 1`), over the
//!   suspended length `L_s = L − L_B` \[m]; against the fairlead's period `T_e` \[s]. The span
//!   follows a harmonic fairlead quasi-statically to within `1/(1 − (T₁/T_e)²) − 1`: 4 % at
//!   `T_e = 5 T₁`, the threshold here.
//! - **speed**: the normal drag `½ ρ C_dn d v²` at the fairlead's speed amplitude `v` \[m/s] on
//!   the volume-equivalent diameter `d = √(4 A_d / π)` with a chain's `C_dn` = 2.4, against the
//!   line's submerged weight per length `w = (λ0 − ρ A_d) g` that shapes the catenary: past a
//!   tenth, drag holds the line out of its static shape.
//!
//! The fairlead's period and speed are the scene's own: a harmonic kinematic body's
//! (`T_e = T`, `v = |A| 2π/T`), or a free body's in waves (the wave's period or the sea's peak
//! period, and `v = π H / T`, the speed of the water's orbit at the surface, with `H_s` for a
//! sea). A line whose ends neither of these moves gets no hint.
//!
//! On `chain_forced_surge` (its chain as a catenary, fairlead surged 2 m at 10 s): T₁ = 6.7 s, so
//! `T_e / T₁` = 1.5, and drag at 1.26 m/s is 0.57 of the weight; the dynamic line's peak tension
//! is 1.58 times the catenary's (docs/dynamic-lines.md).

use std::f64::consts::PI;
use tether_physics::body::{Support, VelocityProfile};
use tether_physics::coupling::{Catenary, CouplingKind, Endpoint, LineModel};
use tether_physics::water::WaveSpec;
use tether_physics::world::World;

/// `T_e / T₁` under which the span no longer follows its fairlead quasi-statically.
const PERIOD_RATIO: f64 = 5.0;

/// Drag at the fairlead's speed over the wet weight past which drag shapes the line.
const DRAG_RATIO: f64 = 0.1;

/// The normal drag coefficient of a chain (MoorDyn's and `moored_buoy`'s dynamic chains).
const CHAIN_DRAG_NORMAL: f64 = 2.4;

/// How a fairlead is driven: its period \[s] and speed amplitude \[m/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Driving {
    pub period: f64,
    pub speed: f64,
    /// What drives it, as the message says it.
    pub by: &'static str,
}

/// A quasi-static line's measures against its fairlead's driving.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measures {
    /// The span's first transverse period `T₁` \[s].
    pub transverse_period: f64,
    pub driving: Driving,
    /// Drag at the fairlead's speed over the wet weight (`None`: the line is not in water or
    /// does not sink).
    pub drag_ratio: Option<f64>,
}

impl Measures {
    /// Whether the line is likely wrong quasi-static, by period or by speed.
    pub fn suggests_dynamic(&self) -> bool {
        self.driving.period < PERIOD_RATIO * self.transverse_period
            || self.drag_ratio.is_some_and(|ratio| ratio > DRAG_RATIO)
    }
}

impl std::fmt::Display for Measures {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let verdict =
            if self.suggests_dynamic() { "likely wrong quasi-static: try Dynamic" } else { "quasi-static holds" };
        write!(
            f,
            "{verdict}: first transverse period T₁ = {:.3} s against the fairlead's {:.3} s ({}), ratio {:.2} (under {PERIOD_RATIO} is dynamic)",
            self.transverse_period,
            self.driving.period,
            self.driving.by,
            self.driving.period / self.transverse_period
        )?;
        if let Some(ratio) = self.drag_ratio {
            write!(
                f,
                "; drag at its {:.3} m/s is {ratio:.3} of the wet weight (over {DRAG_RATIO} is dynamic)",
                self.driving.speed
            )?;
        }
        Ok(())
    }
}

/// The measures of coupling `index` of `world` if it is a quasi-static line with a driven
/// fairlead and its static state; `None` otherwise.
pub fn measures(world: &World, index: usize) -> Option<Measures> {
    let CouplingKind::Catenary(line) = &world.couplings()[index].kind else { return None };
    if line.model() != LineModel::QuasiStatic {
        return None;
    }
    let driving = [line.end1(), line.end2()].iter().find_map(|end| driving(world, end))?;
    let state = world.line_state(index)?;
    let (t1, t2) = state.end_tensions();
    let fluid = world.system().surroundings().fluid_density;
    let in_water = world.system().water().is_some();
    let mass = line.mass_per_length() + if in_water { fluid * line.displaced_area() } else { 0.0 };
    let suspended = line.length() - state.grounded_length();
    let wave_speed = (0.5 * (t1 + t2) / mass).sqrt();
    let transverse_period = 2.0 * suspended / wave_speed;
    if !transverse_period.is_finite() || transverse_period <= 0.0 {
        return None;
    }
    let drag_ratio = in_water.then(|| drag_ratio(line, fluid, world.gravity().norm(), driving.speed)).flatten();
    Some(Measures { transverse_period, driving, drag_ratio })
}

/// `½ ρ C_dn d v² / ((λ0 − ρ A_d) g)`; `None` for a line without displaced area or that floats.
fn drag_ratio(line: &Catenary, fluid: f64, gravity: f64, speed: f64) -> Option<f64> {
    let wet_weight = line.submerged_mass_per_length(fluid) * gravity;
    let diameter = (4.0 * line.displaced_area() / PI).sqrt();
    (wet_weight > 0.0 && diameter > 0.0)
        .then(|| 0.5 * fluid * CHAIN_DRAG_NORMAL * diameter * speed * speed / wet_weight)
}

/// How the body at `end` is driven, if it is: a harmonic kinematic body, or a free body in waves.
fn driving(world: &World, end: &Endpoint) -> Option<Driving> {
    let body = match *end {
        Endpoint::World(_) => return None,
        Endpoint::Body { body, .. } | Endpoint::Center { body } => &world.bodies()[body],
    };
    match &body.support {
        Support::Kinematic(motion) => match &motion.velocity {
            VelocityProfile::Harmonic(harmonic) => Some(Driving {
                period: harmonic.period(),
                speed: harmonic.amplitude().norm() * 2.0 * PI / harmonic.period(),
                by: "harmonic motion",
            }),
            VelocityProfile::Constant(_) | VelocityProfile::Table(_) => None,
        },
        Support::Fixed { translation: [true, true, true], .. } => None,
        Support::Free | Support::Fixed { .. } => {
            let waves = world.system().water()?.water.spec().waves;
            match waves {
                WaveSpec::Calm => None,
                WaveSpec::Regular { height, period, .. } => {
                    Some(Driving { period, speed: PI * height / period, by: "the wave" })
                }
                WaveSpec::Jonswap { significant_height, peak_period, .. } => Some(Driving {
                    period: peak_period,
                    speed: PI * significant_height / peak_period,
                    by: "the sea's peak",
                }),
            }
        }
    }
}
