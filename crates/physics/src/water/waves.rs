//! Linear (Airy) waves: a sea is a sum of components (PHYSICS.md §6, Airy waves).
//!
//! A component of amplitude `a` [m], frequency `ω` [rad/s], wave number `k` [rad/m] (from
//! [`super::dispersion`]), heading unit vector `e` and phase `φ` [rad] has the phase
//! `θ = k e·x − ω t + φ` and the elevation `η = a cos θ`. With `ζ = min(z, z_w) − z_w` (the
//! kinematics above the still level are those at the still level), the depth `h` and
//! `ε = e^{−2 k h}` (0 in deep water), written without overflow for any `k h`:
//! - `K_c = cosh(k(ζ + h))/sinh(k h) = (e^{kζ} + ε e^{−kζ})/(1 − ε)`,
//! - `K_s = sinh(k(ζ + h))/sinh(k h) = (e^{kζ} − ε e^{−kζ})/(1 − ε)`,
//! - `K_p = cosh(k(ζ + h))/cosh(k h) = (e^{kζ} + ε e^{−kζ})/(1 + ε)`,
//!
//! all `e^{kζ}` in deep water. Velocity `u = Σ ω a (K_c cos θ e + K_s sin θ ẑ)` [m/s],
//! acceleration `u̇ = Σ ω² a (K_c sin θ e − K_s cos θ ẑ)` [m/s²], dynamic pressure
//! `p_d = ρ g Σ a K_p cos θ` [Pa]. Below the seabed the kinematics are those at the seabed.
//!
//! The pressure is evaluated at every hull vertex of every floating body at every evaluation,
//! for every component: [`Sea::pressure_head`] runs four components to a vector (`wide`'s
//! `f64x4` sine, cosine and exponential), with the time part of each phase, `φ − ω t`, worked
//! out once per evaluation ([`Sea::phases_at`]).

use crate::math::Vec3;
use wide::f64x4;

/// One regular wave.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveComponent {
    /// `a` [m].
    pub amplitude: f64,
    /// `ω` [rad/s].
    pub frequency: f64,
    /// `k` [rad/m].
    pub wave_number: f64,
    /// Direction of travel, counter-clockwise from +x [rad].
    pub heading: f64,
    /// `φ` [rad].
    pub phase: f64,
}

/// Four components side by side, for the vertex loop (unused lanes have zero amplitude).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Lanes {
    /// `a/(1 + ε)` [m]: the amplitude with `K_p`'s denominator folded in.
    amplitude: f64x4,
    /// `k e_x`, `k e_y`, `k` [rad/m].
    kx: f64x4,
    ky: f64x4,
    k: f64x4,
    /// `ε = e^{−2kh}` (0 in deep water).
    epsilon: f64x4,
}

/// `k ζ` is kept above this, so that `e^{kζ}` stays a normal number and `ε/e^{kζ}` finite.
const LOWEST_EXPONENT: f64 = -700.0;

/// A sea state: the sum of its components over water of a given level and depth.
#[derive(Debug, Clone, PartialEq)]
pub struct Sea {
    components: Vec<WaveComponent>,
    lanes: Vec<Lanes>,
    /// Still-water level `z_w` [m].
    level: f64,
    /// Depth `h` [m], `None` for deep water.
    depth: Option<f64>,
}

impl Sea {
    /// The sea of `components` on water at level `level` [m] with depth `depth` [m] (`None`:
    /// deep). The components' wave numbers must satisfy the dispersion relation at that depth.
    pub fn new(components: Vec<WaveComponent>, level: f64, depth: Option<f64>) -> Self {
        let epsilon = |c: &WaveComponent| depth.map_or(0.0, |h| (-2.0 * c.wave_number * h).exp());
        let lanes = components
            .chunks(4)
            .map(|chunk| {
                let lane = |f: &dyn Fn(&WaveComponent) -> f64| f64x4::new(std::array::from_fn(|i| chunk.get(i).map_or(0.0, f)));
                Lanes {
                    amplitude: lane(&|c| c.amplitude / (1.0 + epsilon(c))),
                    kx: lane(&|c| c.wave_number * c.heading.cos()),
                    ky: lane(&|c| c.wave_number * c.heading.sin()),
                    k: lane(&|c| c.wave_number),
                    epsilon: lane(&epsilon),
                }
            })
            .collect();
        Self { components, lanes, level, depth }
    }

    /// Calm water: no component.
    pub fn calm(level: f64, depth: Option<f64>) -> Self {
        Self::new(Vec::new(), level, depth)
    }

    pub fn components(&self) -> &[WaveComponent] {
        &self.components
    }

    /// Whether the sea has no wave.
    pub fn is_calm(&self) -> bool {
        self.components.is_empty()
    }

    /// `Σ a` [m]: no crest is higher above the still level.
    pub fn highest_crest(&self) -> f64 {
        self.components.iter().map(|c| c.amplitude).sum()
    }

    /// The time part of each component's phase at `time` [s], `φ − ω t` reduced to [0, 2π),
    /// four to a vector, into `phases` (resized to fit).
    pub fn phases_at(&self, time: f64, phases: &mut Vec<f64x4>) {
        phases.clear();
        phases.extend(self.components.chunks(4).map(|chunk| {
            f64x4::new(std::array::from_fn(|i| chunk.get(i).map_or(0.0, |c| (c.phase - c.frequency * time).rem_euclid(std::f64::consts::TAU))))
        }));
    }

    /// `ζ = min(z, z_w) − z_w`, not below the seabed [m].
    #[inline(always)]
    fn depth_below_level(&self, z: f64) -> f64 {
        let zeta = (z - self.level).min(0.0);
        match self.depth {
            Some(h) => zeta.max(-h),
            None => zeta,
        }
    }

    /// `Σ a K_p cos θ` [m] at the point `(x, y, z)`, with the phases of [`Sea::phases_at`]: the
    /// dynamic pressure divided by `ρ g` (unramped).
    #[inline(always)]
    pub fn pressure_head(&self, phases: &[f64x4], x: f64, y: f64, z: f64) -> f64 {
        let zeta = f64x4::splat(self.depth_below_level(z));
        let (x, y) = (f64x4::splat(x), f64x4::splat(y));
        let lowest = f64x4::splat(LOWEST_EXPONENT);
        let mut sum = f64x4::splat(0.0);
        for (lane, phase) in self.lanes.iter().zip(phases) {
            let theta = lane.kx * x + lane.ky * y + *phase;
            let decay = (lane.k * zeta).max(lowest).exp();
            sum += lane.amplitude * (decay + lane.epsilon / decay) * theta.cos();
        }
        sum.reduce_add()
    }

    /// The surface elevation `η = Σ a cos θ` [m] above the still level at `(x, y)` and `time`
    /// [s] (unramped).
    pub fn elevation(&self, x: f64, y: f64, time: f64) -> f64 {
        self.components.iter().map(|c| c.amplitude * self.phase(c, x, y, time).cos()).sum()
    }

    /// Velocity [m/s] and acceleration [m/s²] of the water at `point` and `time` [s]
    /// (unramped): the Morison loads' kinematics, one point per body.
    pub fn kinematics(&self, point: &Vec3, time: f64) -> (Vec3, Vec3) {
        let zeta = self.depth_below_level(point.z);
        let (mut velocity, mut acceleration) = (Vec3::zeros(), Vec3::zeros());
        for c in &self.components {
            let k = c.wave_number;
            let decay = (k * zeta).max(LOWEST_EXPONENT).exp();
            let (k_c, k_s) = match self.depth {
                Some(h) => {
                    let epsilon = (-2.0 * k * h).exp();
                    let rising = epsilon / decay;
                    ((decay + rising) / (1.0 - epsilon), (decay - rising) / (1.0 - epsilon))
                }
                None => (decay, decay),
            };
            let (sin, cos) = self.phase(c, point.x, point.y, time).sin_cos();
            let (w, horizontal) = (c.frequency, Vec3::new(c.heading.cos(), c.heading.sin(), 0.0));
            velocity += (horizontal * (k_c * cos) + Vec3::z() * (k_s * sin)) * (w * c.amplitude);
            acceleration += (horizontal * (k_c * sin) - Vec3::z() * (k_s * cos)) * (w * w * c.amplitude);
        }
        (velocity, acceleration)
    }

    /// `θ = k e·x − ω t + φ` [rad].
    fn phase(&self, c: &WaveComponent, x: f64, y: f64, time: f64) -> f64 {
        c.wave_number * (c.heading.cos() * x + c.heading.sin() * y) - c.frequency * time + c.phase
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::water::dispersion::wave_number;
    use approx::assert_relative_eq;

    const G: f64 = 9.80665;

    fn component(period: f64, depth: Option<f64>, heading: f64, phase: f64) -> WaveComponent {
        let frequency = std::f64::consts::TAU / period;
        WaveComponent { amplitude: 0.7, frequency, wave_number: wave_number(frequency, depth, G), heading, phase }
    }

    /// The closed forms with `cosh`, `sinh` of PHYSICS.md §6, where they do not overflow.
    fn textbook_head(c: &WaveComponent, depth: Option<f64>, x: f64, y: f64, z: f64, t: f64) -> f64 {
        let zeta = z.min(0.0);
        let k = c.wave_number;
        let factor = match depth {
            Some(h) => (k * (zeta + h)).cosh() / (k * h).cosh(),
            None => (k * zeta).exp(),
        };
        c.amplitude * factor * (k * (c.heading.cos() * x + c.heading.sin() * y) - c.frequency * t + c.phase).cos()
    }

    #[test]
    fn vector_pressure_head_matches_the_closed_form_for_every_lane() {
        for depth in [None, Some(20.0), Some(3.0)] {
            // Six components: one full vector and a part-filled one.
            let components: Vec<_> = (0..6).map(|i| component(4.0 + f64::from(i), depth, 0.3 * f64::from(i), 1.1 * f64::from(i))).collect();
            let sea = Sea::new(components.clone(), 0.0, depth);
            let time = 1234.567;
            let mut phases = Vec::new();
            sea.phases_at(time, &mut phases);
            for (x, y, z) in [(0.0, 0.0, 0.0), (13.0, -7.0, -1.5), (-40.0, 2.0, -2.9), (5.0, 5.0, 0.4)] {
                let expected: f64 = components.iter().map(|c| textbook_head(c, depth, x, y, z, time)).sum();
                // Sums of six terms of 0.7 m: round-off of the phase reduction at t ≈ 1e3 s.
                assert_relative_eq!(sea.pressure_head(&phases, x, y, z), expected, epsilon = 1e-12);
            }
        }
    }

    #[test]
    fn kinematics_satisfy_the_free_surface_and_the_time_derivative() {
        for depth in [None, Some(20.0)] {
            let c = component(8.0, depth, 0.4, 0.2);
            let sea = Sea::new(vec![c], 0.0, depth);
            let (x, y, t) = (3.0, -2.0, 5.0);
            // At the surface the vertical velocity is ∂η/∂t (linear kinematic condition).
            let dt = 1e-5;
            let deta = (sea.elevation(x, y, t + dt) - sea.elevation(x, y, t - dt)) / (2.0 * dt);
            let (velocity, acceleration) = sea.kinematics(&Vec3::new(x, y, 0.0), t);
            // Central difference of a 0.7 m, 8 s wave: error ~ ω³ a dt²/6 ≈ 1e-11.
            assert_relative_eq!(velocity.z, deta, epsilon = 1e-8);
            let below = Vec3::new(x, y, -4.0);
            let ahead = (sea.kinematics(&below, t + dt).0 - sea.kinematics(&below, t - dt).0) / (2.0 * dt);
            assert_relative_eq!(sea.kinematics(&below, t).1, ahead, epsilon = 1e-8);
            assert!(acceleration.norm() > 0.0);
        }
    }
}
