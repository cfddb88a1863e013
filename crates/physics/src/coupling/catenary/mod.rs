//! Elastic quasi-static catenary coupling (PHYSICS.md §3 \[4952]–\[4955]), lying on
//! the seabed where it reaches it (PHYSICS.md §7).
//!
//! A line of mass per length `λ0` [kg/m], displaced volume per length `A_d` \[m²], unstretched
//! length `L_eq` \[m] and stiffness `D` [N/m] (`EA = D L_eq` \[N]) hangs between two ends in the
//! vertical plane of gravity. In a fluid of density `ρ` [kg/m³] it weighs
//! `w = (λ0 − ρ A_d) g` [N/m] (`W = w L_eq`); `e_y = −ĝ` (a buoyant line, `w < 0`, arches
//! upward: `e_y = ĝ`), `e_x` the horizontal unit vector from end 1 toward end 2. With the
//! horizontal tension `H` and the vertical force at end 1 `V1` solved from the end positions
//! ([`solver`]), the forces exerted by the free line are
//! `f1 = H e_x + V1 e_y`, `f2 = −H e_x − V2 e_y`, `V2 = V1 + W`
//! (PHYSICS.md writes `H = c`, `V1 = c sinh u1`, `V2 = c sinh u2`).
//!
//! With a seabed, a sinking line whose free shape would pass below the bottom lies on it
//! instead ([`grounded`]): a grounded length `L_B` with tangent touchdown, friction `C_B` toward
//! an end that lies on the bottom, the anchor tension `H_A = max(H − C_B W L_B, 0)`. The line
//! lifted off the bottom is the free one unchanged, continuously across the lift-off.
//!
//! A massless line (or one in zero gravity, or neutrally buoyant) is a straight elastic rope:
//! tension `T = D max(0, x − L_eq)` \[N], pulling only when stretched.
//!
//! - [`equations`], [`solver`]: the free line's closure and its solve;
//! - [`grounded`]: the line on the seabed, its closure and its solve;
//! - [`line_state`]: the solved line — end forces, energy, stiffness, shape.

pub mod equations;
pub mod grounded;
pub mod line_state;
pub mod solver;

use super::ends::{EndMotion, Endpoint};
use super::forces::CouplingForces;
use super::lumped_line::parameters::LineModel;
use crate::body::{BodyFrame, Load};
use crate::math::Vec3;
use crate::parameter::{Bound, ParameterError, require, require_derived};
use crate::seabed::Seabed;
use crate::surroundings::Surroundings;
use equations::Closure;
use grounded::{Grounding, Outcome};
pub use line_state::{EndStiffness, Ground, LineEnd, LineState};

/// Height above the seabed, a fraction of `L_eq`, within which an end lies on it.
pub const ON_SEABED: f64 = 1e-9;

/// A catenary line between two ends, built by [`Catenary::new`], which checks its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Catenary {
    end1: Endpoint,
    end2: Endpoint,
    mass_per_length: f64,
    length: f64,
    stiffness: f64,
    displaced_area: f64,
    model: LineModel,
}

/// What a line remembers: its last solution, the warm start of the next solve (and what the
/// recorder draws and the stable time step reads).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CatenaryCache {
    pub last: Option<LineState>,
}

/// A catenary solve that failed: only non-finite end positions (a diverged simulation) do this.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("the catenary has no solution for span {span} m, rise {rise} m (non-finite end positions?)")]
pub struct CatenaryError {
    pub span: f64,
    pub rise: f64,
}

impl Catenary {
    /// A line of `mass_per_length` λ0 [kg/m] ≥ 0, unstretched `length` \[m] > 0 and `stiffness`
    /// D [N/m] > 0 that displaces no fluid, its axial stiffness `EA = D L_eq` \[N] (PHYSICS.md §3)
    /// finite and > 0.
    ///
    /// # Errors
    /// A value out of its range, named by its field; an `EA` that overflows or underflows, named
    /// with the value that made it.
    pub fn new(
        end1: Endpoint,
        end2: Endpoint,
        mass_per_length: f64,
        length: f64,
        stiffness: f64,
    ) -> Result<Self, ParameterError> {
        let mass_per_length = require("mass_per_length", mass_per_length, Bound::NonNegative, "kg/m")?;
        let length = require("length", length, Bound::Positive, "m")?;
        let stiffness = require("stiffness", stiffness, Bound::Positive, "N/m")?;
        let inputs = [("stiffness", stiffness), ("length", length)];
        require_derived("EA = stiffness × length", stiffness * length, Bound::Positive, "N", &inputs)?;
        Ok(Self { end1, end2, mass_per_length, length, stiffness, displaced_area: 0.0, model: LineModel::QuasiStatic })
    }

    /// The line modelled by `model` (its parameters already checked by their constructor).
    pub fn with_model(self, model: LineModel) -> Self {
        Self { model, ..self }
    }

    /// The line with displaced volume per length `displaced_area` A_d \[m²] ≥ 0.
    ///
    /// # Errors
    /// A negative or non-finite area.
    pub fn with_displaced_area(self, displaced_area: f64) -> Result<Self, ParameterError> {
        Ok(Self { displaced_area: require("displaced_area", displaced_area, Bound::NonNegative, "m²")?, ..self })
    }

    pub fn end1(&self) -> Endpoint {
        self.end1
    }

    pub fn end2(&self) -> Endpoint {
        self.end2
    }

    /// `λ0` [kg/m] ≥ 0.
    pub fn mass_per_length(&self) -> f64 {
        self.mass_per_length
    }

    /// `L_eq` \[m] > 0.
    pub fn length(&self) -> f64 {
        self.length
    }

    /// `D` [N/m] > 0: the stiffness of the whole line, `EA = D L_eq`.
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// `A_d` \[m²] ≥ 0: the line's displaced volume per length, for its submerged weight.
    pub fn displaced_area(&self) -> f64 {
        self.displaced_area
    }

    /// Quasi-static (this module) or dynamic ([`super::lumped_line`], PHYSICS.md §8).
    pub fn model(&self) -> LineModel {
        self.model
    }

    /// `λ0 − ρ A_d` [kg/m] in a fluid of density `fluid_density` ρ [kg/m³]: what weighs.
    pub fn submerged_mass_per_length(&self, fluid_density: f64) -> f64 {
        self.mass_per_length - fluid_density * self.displaced_area
    }

    /// The line's weight in `surroundings` (PHYSICS.md §3, §7), checked finite where it is
    /// made from the line's values, gravity and the fluid's density: per length `w = (λ0 − ρ
    /// A_d) g` [N/m], the whole line's `W = w L_eq` \[N] and its compliance `W/EA` [–], which the
    /// solve divides by. Its scene, loaded or edited, is refused rather than run with an infinite
    /// weight.
    ///
    /// # Errors
    /// [`ParameterError::Derived`], named with the value that made it.
    pub fn check_weight(&self, surroundings: &Surroundings) -> Result<(), ParameterError> {
        let (g, density) = (surroundings.gravity.norm(), surroundings.fluid_density);
        // Each quantity's inputs are the first 4, 5 and 6 of these.
        let inputs = [
            ("mass_per_length", self.mass_per_length),
            ("displaced_area", self.displaced_area),
            ("gravity", g),
            ("density", density),
            ("length", self.length),
            ("stiffness", self.stiffness),
        ];
        let per_length = require_derived(
            "the submerged weight per length (λ0 − ρ A_d) g",
            self.submerged_mass_per_length(density) * g,
            Bound::Finite,
            "N/m",
            &inputs[..4],
        )?;
        let weight = per_length.abs() * self.length;
        require_derived("the submerged weight |w| L_eq", weight, Bound::Finite, "N", &inputs[..5])?;
        let compliance = weight / (self.stiffness * self.length);
        require_derived("the compliance W/EA", compliance, Bound::Finite, "", &inputs)?;
        Ok(())
    }

    /// Solves the line for end positions `p1`, `p2` \[m] in `surroundings`, warm-started from
    /// the solution `last` (the previous one of the same line), if any.
    ///
    /// With a seabed and a sinking line: a line grounded at the last solve is solved grounded
    /// first; otherwise (or if it has lifted off) the free line is solved, and laid on the
    /// seabed if its lowest point is below it.
    pub fn solve(
        &self,
        p1: &Vec3,
        p2: &Vec3,
        surroundings: &Surroundings,
        last: Option<&LineState>,
    ) -> Result<LineState, CatenaryError> {
        let gravity = &surroundings.gravity;
        let chord = p2 - p1;
        let g = gravity.norm();
        let sinking = self.submerged_mass_per_length(surroundings.fluid_density);
        let weight = sinking.abs() * g * self.length;
        let axial_stiffness = self.stiffness * self.length;
        let straight = |e_x: Vec3, e_y: Vec3, x: f64| {
            let tension = self.stiffness * (x - self.length).max(0.0);
            LineState {
                origin: *p1,
                e_x,
                e_y,
                span: x,
                rise: 0.0,
                horizontal_tension: tension,
                vertical1: 0.0,
                weight: 0.0,
                length: self.length,
                axial_stiffness,
                iterations: 0,
                residual: 0.0,
                ground: None,
            }
        };
        if !(weight > 0.0) {
            let x = chord.norm();
            let e_x = chord.try_normalize(0.0).unwrap_or_else(|| last.map_or(Vec3::x(), |s| s.e_x));
            return Ok(straight(e_x, any_perpendicular(&e_x), x));
        }
        let e_y = if sinking > 0.0 { -gravity / g } else { gravity / g };
        let rise = chord.dot(&e_y);
        let horizontal = chord - e_y * rise;
        let span = horizontal.norm();
        let vertical = span <= 1e-14 * self.length;
        let e_x = if vertical { last.map_or_else(|| any_perpendicular(&e_y), |s| s.e_x) } else { horizontal / span };
        let free = LineState {
            origin: *p1,
            e_x,
            e_y,
            span,
            rise,
            horizontal_tension: 0.0,
            vertical1: 0.0,
            weight,
            length: self.length,
            axial_stiffness,
            iterations: 0,
            residual: 0.0,
            ground: None,
        };
        match surroundings.seabed {
            Some(seabed) if sinking > 0.0 => self.solve_on_seabed(free, &seabed, vertical, last),
            _ => self.solve_free(free, vertical, last),
        }
    }

    /// The free line (PHYSICS.md §3) in the frame of `frame` (its tensions are filled in).
    fn solve_free(
        &self,
        frame: LineState,
        vertical: bool,
        last: Option<&LineState>,
    ) -> Result<LineState, CatenaryError> {
        let LineState { span, rise, weight, axial_stiffness, .. } = frame;
        let closure = Closure {
            x: if vertical { 0.0 } else { span / self.length },
            y: rise / self.length,
            epsilon: weight / axial_stiffness,
        };
        let solved = solver::solve(&closure, last.and_then(LineState::unknowns)).ok_or(CatenaryError { span, rise })?;
        Ok(LineState {
            horizontal_tension: solved.unknowns.h * weight,
            vertical1: solved.unknowns.v * weight,
            iterations: solved.iterations,
            residual: solved.residual,
            ..frame
        })
    }

    /// The line above `seabed`: grounded where it reaches the bottom (PHYSICS.md §7), free
    /// elsewhere.
    fn solve_on_seabed(
        &self,
        frame: LineState,
        seabed: &Seabed,
        vertical: bool,
        last: Option<&LineState>,
    ) -> Result<LineState, CatenaryError> {
        if let Some(ground) = last.and_then(|s| s.ground.as_ref())
            && let Some(state) = self.solve_grounded(&frame, seabed, Warm::Grounded(ground))
        {
            return Ok(state);
        }
        let free = self.solve_free(frame, vertical, last)?;
        if free.lowest_height() >= seabed.elevation() {
            return Ok(free);
        }
        Ok(self.solve_grounded(&frame, seabed, Warm::Tension(free.horizontal_tension / free.weight)).unwrap_or(free))
    }

    /// The grounded line in the frame of `frame`, from the warm start `warm`; `None` when it
    /// does not reach the bottom. The anchor is the end that lies on the seabed (within
    /// [`ON_SEABED`]; an end below it counts as on it), else end 1.
    fn solve_grounded(&self, frame: &LineState, seabed: &Seabed, warm: Warm) -> Option<LineState> {
        let height = |y: f64| {
            let z = (y - seabed.elevation()) / self.length;
            if z <= ON_SEABED { 0.0 } else { z }
        };
        let y1 = frame.origin.dot(&frame.e_y);
        let (z1, z2) = (height(y1), height(y1 + frame.rise));
        let (anchor, z_anchor, z_other) =
            if z1 == 0.0 || z2 > 0.0 { (LineEnd::First, z1, z2) } else { (LineEnd::Second, z2, z1) };
        let grounding = Grounding {
            x: frame.span / self.length,
            z1: z_anchor,
            z2: z_other,
            epsilon: frame.weight / frame.axial_stiffness,
            friction: seabed.line_friction(),
        };
        let start = match warm {
            Warm::Tension(h) => h,
            Warm::Grounded(last) if last.anchor == anchor => last.profile.predict(&last.grounding, &grounding),
            Warm::Grounded(last) => last.profile.h,
        };
        let Outcome::Grounded(solved) = grounded::solver::solve(&grounding, Some(start))? else { return None };
        let profile = solved.profile;
        let ground = Ground { anchor, grounding, profile, seabed: seabed.elevation() };
        let mut state = LineState {
            horizontal_tension: profile.h * frame.weight,
            iterations: solved.iterations,
            residual: solved.residual,
            ground: Some(ground),
            ..*frame
        };
        state.vertical1 = state.end_forces().0.dot(&frame.e_y);
        Some(state)
    }

    /// Forces at the kinematics `frames` in `surroundings` (the line is quasi-static: end
    /// velocities do not enter), added to the end bodies' `loads` and written to `out`; the
    /// solution is kept in `cache` as the next warm start.
    pub fn apply(
        &self,
        cache: &mut CatenaryCache,
        frames: &[BodyFrame],
        surroundings: &Surroundings,
        loads: &mut [Load],
        out: &mut CouplingForces,
    ) -> Result<(), CatenaryError> {
        if let LineModel::Dynamic(_) = self.model {
            // The lines stage has written a dynamic line's forces and record already.
            return Ok(());
        }
        let (end1, end2) = (self.end1.motion(frames), self.end2.motion(frames));
        let state = self.solve(&end1.position, &end2.position, surroundings, cache.last.as_ref())?;
        let (f1, f2) = state.end_forces();
        end1.apply(&f1, loads);
        end2.apply(&f2, loads);
        let (t1, t2) = state.end_tensions();
        let potential = state.potential_energy();
        *out = CouplingForces {
            point1: end1.position,
            point2: end2.position,
            f1,
            f2,
            tension: t1.max(t2),
            dissipated_power: 0.0,
            held_power: self.seabed_friction_power(&state, [&end1, &end2], [&f1, &f2], surroundings),
            potential,
        };
        cache.last = Some(state);
        Ok(())
    }
}

impl Catenary {
    /// The power \[W] of the seabed's friction on a grounded line (PHYSICS.md §7), which the
    /// line's energy `U` (of `state`) leaves out: the quasi-static friction law makes the end
    /// forces `f_i` differ from minus the gradient of `U`, by
    /// `P_h = −(f1·v1 + f2·v2 + dU/dt)`. The law gives the forces from the ends' positions alone
    /// (the friction always toward the anchor, no slip history), so `P_h` takes the sign of the
    /// ends' motion and what it takes out it gives back in: it is held, not dissipated
    /// ([`crate::energy`]). `dU/dt` along the ends' velocities is a central
    /// difference of the line solved with its ends moved by `±v δ`, `δ |v| = 10⁻⁶ L_eq`
    /// (the solves converge to 10⁻¹² in `ln H`, so the difference is exact to about 10⁻⁶ W per
    /// MJ of `U`). Zero without friction, off the bottom, at rest, or where a moved end leaves
    /// the grounded branch (a line lifting off: its grounded length, and friction, vanish).
    fn seabed_friction_power(
        &self,
        state: &LineState,
        ends: [&EndMotion; 2],
        forces: [&Vec3; 2],
        surroundings: &Surroundings,
    ) -> f64 {
        let grounded_with_friction = state.ground.as_ref().is_some_and(|g| g.grounding.friction > 0.0);
        let speed = ends[0].velocity.norm().hypot(ends[1].velocity.norm());
        if !grounded_with_friction || speed == 0.0 {
            return 0.0;
        }
        let delta = FRICTION_PROBE * self.length / speed;
        let moved = |sign: f64| {
            let (p1, p2) = (
                ends[0].position + ends[0].velocity * (sign * delta),
                ends[1].position + ends[1].velocity * (sign * delta),
            );
            self.solve(&p1, &p2, surroundings, Some(state))
                .ok()
                .filter(|s| s.ground.is_some())
                .map(|s| s.potential_energy())
        };
        let (Some(ahead), Some(behind)) = (moved(1.0), moved(-1.0)) else { return 0.0 };
        let rate = (ahead - behind) / (2.0 * delta);
        -(forces[0].dot(&ends[0].velocity) + forces[1].dot(&ends[1].velocity) + rate)
    }
}

/// The displacement of the ends, in units of `L_eq`, over which the friction's power takes the
/// rate of the line's energy.
const FRICTION_PROBE: f64 = 1e-6;

/// Where a grounded solve starts.
#[derive(Debug, Clone, Copy)]
enum Warm<'a> {
    /// From `h = H/W` (of the free line that turned out to reach the bottom).
    Tension(f64),
    /// From the last grounded solution, moved along its tangent to the new ends.
    Grounded(&'a Ground),
}

/// A unit vector perpendicular to `axis` (unit).
fn any_perpendicular(axis: &Vec3) -> Vec3 {
    let helper = if axis.x.abs() < 0.9 { Vec3::x() } else { Vec3::y() };
    (helper - axis * axis.dot(&helper)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(mass_per_length: f64, length: f64, stiffness: f64) -> Result<Catenary, ParameterError> {
        Catenary::new(
            Endpoint::World(Vec3::zeros()),
            Endpoint::World(Vec3::x() * 100.0),
            mass_per_length,
            length,
            stiffness,
        )
    }

    /// Issue 48: `EA = D L_eq` that overflows (or underflows to 0) from values each in range is
    /// refused by the constructor, naming the one that made it.
    #[test]
    fn an_axial_stiffness_that_overflows_is_refused() {
        assert_eq!(line(25.79, 250.0, 442714.0).map(|l| l.stiffness * l.length), Ok(110_678_500.0));
        assert_eq!(
            line(25.79, 1000.0, 1e306).unwrap_err().to_string(),
            "EA = stiffness × length must be finite, got inf (from stiffness = 1e306)"
        );
        let refused = line(25.79, 1e-200, 1e-200).unwrap_err();
        assert_eq!(refused.to_string(), "EA = stiffness × length must be > 0 N, got 0 (from length = 1e-200)");
    }

    /// Issue 47: a grounded chain's seabed friction (C_B = 1) pulled out and let back in, the
    /// fairlead's span 230 ± 5 m over one 20 s cycle: what the friction takes going out
    /// (`P_h ≥ 0`) it gives back coming in (`P_h ≤ 0`): 97.5 J out from the middle, 110.6 J
    /// back in to the near end, 13.05 J out to the middle again, the cycle's net 2.2·10⁻⁷ J
    /// (the trapezoid's error over 4000 steps). The law holds energy; nothing of it is booked
    /// as dissipated.
    #[test]
    fn a_grounded_lines_friction_gives_back_what_it_takes() {
        let water = Surroundings {
            fluid_density: 1025.0,
            seabed: Some(Seabed::new(-50.0, 1.0).expect("valid")),
            ..Surroundings::dry(Vec3::new(0.0, 0.0, -9.81))
        };
        let chain = Catenary::new(
            Endpoint::World(Vec3::new(0.0, 0.0, -50.0)),
            Endpoint::Center { body: 0 },
            25.79,
            250.0,
            442714.0,
        )
        .and_then(|l| l.with_displaced_area(0.003298))
        .expect("valid");
        let (steps, period, amplitude) = (4000, 20.0, 5.0);
        let omega = std::f64::consts::TAU / period;
        let dt = period / steps as f64;
        let (mut cache, mut out) = (CatenaryCache::default(), CouplingForces::default());
        let mut power_at = |t: f64| {
            let frame = BodyFrame {
                position: Vec3::new(230.0 + amplitude * (omega * t).sin(), 0.0, -1.0),
                velocity: Vec3::new(amplitude * omega * (omega * t).cos(), 0.0, 0.0),
                ..BodyFrame::default()
            };
            let mut loads = [Load::default()];
            chain.apply(&mut cache, &[frame], &water, &mut loads, &mut out).expect("solves");
            assert_eq!(out.dissipated_power, 0.0, "nothing dissipates");
            out.held_power
        };
        let powers: Vec<f64> = (0..=steps).map(|i| power_at(i as f64 * dt)).collect();
        let leg =
            |range: std::ops::Range<usize>| -> f64 { range.map(|i| 0.5 * dt * (powers[i] + powers[i + 1])).sum() };
        // Out from the middle to the far end, in to the near end, out to the middle again.
        let (quarter, three_quarters) = (steps / 4, 3 * steps / 4);
        let (out_first, inward, out_last) = (leg(0..quarter), leg(quarter..three_quarters), leg(three_quarters..steps));
        assert!(powers[..quarter].iter().all(|&p| p >= 0.0), "takes while pulled out");
        assert!(powers[quarter + 1..three_quarters].iter().all(|&p| p <= 0.0), "gives back while let in");
        assert!(out_first > 1.0, "the friction works: {out_first} J");
        let net = out_first + inward + out_last;
        assert!(net.abs() < 1e-7 * inward.abs(), "the cycle's net {net} J of {inward} J in");
    }

    /// The line's weight in its surroundings: finite per length, whole, and over `EA`.
    #[test]
    fn a_weight_that_overflows_is_refused_naming_its_field() {
        let water = Surroundings { fluid_density: 1025.0, ..Surroundings::dry(Vec3::new(0.0, 0.0, -9.81)) };
        let chain = line(25.79, 250.0, 442714.0).and_then(|l| l.with_displaced_area(0.003298)).expect("valid");
        assert_eq!(chain.check_weight(&water), Ok(()));
        let heavy = Catenary { mass_per_length: 1e308, ..chain.clone() };
        assert_eq!(
            heavy.check_weight(&water).unwrap_err().to_string(),
            "the submerged weight per length (λ0 − ρ A_d) g must be finite, got inf (from mass_per_length = 1e308)"
        );
        let long = Catenary { mass_per_length: 1e300, length: 1e10, stiffness: 1e-300, ..chain.clone() };
        assert_eq!(long.check_weight(&water).unwrap_err().field(), "mass_per_length");
        let soft = Catenary { stiffness: 1e-310, ..chain };
        assert_eq!(
            soft.check_weight(&water).unwrap_err().to_string(),
            "the compliance W/EA must be finite, got inf (from stiffness = 1e-310)"
        );
    }
}
