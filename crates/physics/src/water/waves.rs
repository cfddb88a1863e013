//! Linear (Airy) waves: a sea is a sum of components (PHYSICS.md §6, Airy waves).
//!
//! A component of amplitude `a` \[m], frequency `ω` [rad/s], wave number `k` [rad/m] (from
//! [`super::dispersion`]), heading unit vector `e` and phase `φ` \[rad] has the phase
//! `θ = k e·x − ω t + φ` and the elevation `η = a cos θ`. With `ζ = min(z, z_w) − z_w` (the
//! kinematics above the still level are those at the still level), the depth `h` and
//! `ε = e^{−2 k h}` (0 in deep water), written without overflow for any `k h`:
//! - `K_c = cosh(k(ζ + h))/sinh(k h) = (e^{kζ} + ε e^{−kζ})/(1 − ε)`,
//! - `K_s = sinh(k(ζ + h))/sinh(k h) = (e^{kζ} − ε e^{−kζ})/(1 − ε)`,
//! - `K_p = cosh(k(ζ + h))/cosh(k h) = (e^{kζ} + ε e^{−kζ})/(1 + ε)`,
//!
//! all `e^{kζ}` in deep water. Velocity `u = Σ ω a (K_c cos θ e + K_s sin θ ẑ)` [m/s],
//! acceleration `u̇ = Σ ω² a (K_c sin θ e − K_s cos θ ẑ)` [m/s²], dynamic pressure
//! `p_d = ρ g Σ a K_p cos θ` \[Pa]. Below the seabed the kinematics are those at the seabed.
//!
//! The pressure is evaluated at every hull vertex of every floating body at every evaluation,
//! for every component. A sea whose components all travel one way with wave numbers on a grid,
//! `k_i = m_i k_0` for consecutive integers `m_i` (the scene's regular wave, `m = 1`, and its
//! JONSWAP seas, [`super::spectrum`]), is *harmonic*: with `s = e·x`,
//! `Σ a_i K_p,i cos θ_i = Re Σ_i b_i (w^{m_i} + ε_i' u^{m_i})` where `w = e^{k_0 ζ} e^{i k_0 s}`,
//! `u = e^{−k_0 (2h + ζ)} e^{i k_0 s}` (finite depth only: `u^m = ε e^{−kζ} e^{iks}`) and
//! `b_i = a_i e^{i(φ_i − ω_i t)}/(1 + ε_i)` worked out once per evaluation
//! ([`Sea::instant`]). A vertex then costs one sine, one cosine and one or two exponentials,
//! and two complex products per component (the powers taken four at a time, so that four
//! chains of products run side by side): no transcendental function per component. The
//! velocity and acceleration at a dynamic line's nodes are summed the same way
//! ([`Sea::kinematics_at`], with the amplitudes of [`Sea::flow_instant`]). Any other sea is
//! summed component by component.

use crate::math::Vec3;

/// One regular wave.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveComponent {
    /// `a` \[m].
    pub amplitude: f64,
    /// `ω` [rad/s].
    pub frequency: f64,
    /// `k` [rad/m].
    pub wave_number: f64,
    /// Direction of travel, counter-clockwise from +x \[rad].
    pub heading: f64,
    /// `φ` \[rad].
    pub phase: f64,
}

/// `k ζ` is kept above this, so that `e^{kζ}` stays a normal number and `ε/e^{kζ}` finite.
const LOWEST_EXPONENT: f64 = -700.0;

/// Lanes of Horner's rule run side by side in the harmonic sums (component `4j + l` in lane `l`).
const CHAINS: usize = 4;

/// A harmonic sea's layout: one heading, `k_i = (first + i) k_0`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Harmonic {
    /// `k_0` [rad/m].
    base: f64,
    /// `e` (horizontal unit vector).
    heading: [f64; 2],
    /// `m` of the first component.
    first: u32,
    /// `e^{−2 k_0 h}` (0 in deep water).
    epsilon: f64,
}

/// A sea at one instant: the complex amplitudes `b_i` \[m] of [`Sea::instant`], padded with
/// zeros to a multiple of four components.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SeaInstant {
    real: Vec<f64>,
    imaginary: Vec<f64>,
    /// The time [s].
    time: f64,
}

/// The flow of a sea at one instant: the complex amplitudes `c_i = ω_i a_i e^{i(φ_i − ω_i t)}/(1 − ε_i)`
/// [m/s] of the velocity and `d_i = ω_i c_i` [m/s²] of the acceleration ([`Sea::flow_instant`]),
/// padded with zeros to a multiple of four components.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct FlowInstant {
    velocity: SeaInstant,
    acceleration: SeaInstant,
}

impl FlowInstant {
    /// The time \[s].
    pub fn time(&self) -> f64 {
        self.velocity.time
    }
}

/// A sea state: the sum of its components over water of a given level and depth.
#[derive(Debug, Clone, PartialEq)]
pub struct Sea {
    components: Vec<WaveComponent>,
    harmonic: Option<Harmonic>,
    /// Still-water level `z_w` [m].
    level: f64,
    /// Depth `h` [m], `None` for deep water.
    depth: Option<f64>,
}

impl Sea {
    /// The sea of `components` on water at level `level` \[m] with depth `depth` \[m] (`None`:
    /// deep). The components' wave numbers must satisfy the dispersion relation at that depth.
    pub fn new(components: Vec<WaveComponent>, level: f64, depth: Option<f64>) -> Self {
        let harmonic = harmonic_layout(&components)
            .map(|h| Harmonic { epsilon: depth.map_or(0.0, |d| (-2.0 * h.base * d).exp()), ..h });
        Self { components, harmonic, level, depth }
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

    /// Whether the vertex sums take the harmonic path.
    pub fn is_harmonic(&self) -> bool {
        self.harmonic.is_some()
    }

    /// Whether [`Sea::elevation_at`] is the same at every `y` for a given `x`, to the bit: a
    /// harmonic sea heading along x (`e_y` exactly 0, its phase `k_0 (e_x x + 0·y)`), whose
    /// surface a grid can sum once per column.
    pub fn elevation_ignores_y(&self) -> bool {
        self.harmonic.as_ref().is_some_and(|harmonic| harmonic.heading[1] == 0.0)
    }

    /// `Σ a` \[m]: no crest is higher above the still level.
    pub fn highest_crest(&self) -> f64 {
        self.components.iter().map(|c| c.amplitude).sum()
    }

    /// `ε_i = e^{−2 k_i h}` (0 in deep water).
    fn epsilon(&self, c: &WaveComponent) -> f64 {
        self.depth.map_or(0.0, |h| (-2.0 * c.wave_number * h).exp())
    }

    /// The sea at `time` \[s] into `instant`: `b_i = a_i e^{i(φ_i − ω_i t)}/(1 + ε_i)`, for
    /// [`Sea::pressure_head`].
    pub fn instant(&self, time: f64, instant: &mut SeaInstant) {
        self.fill_instant(time, instant, |c| c.amplitude / (1.0 + self.epsilon(c)));
    }

    /// The surface at `time` \[s] into `instant`: `a_i e^{i(φ_i − ω_i t)}`, for
    /// [`Sea::elevation_at`].
    pub fn surface_instant(&self, time: f64, instant: &mut SeaInstant) {
        self.fill_instant(time, instant, |c| c.amplitude);
    }

    /// `A_i e^{i(φ_i − ω_i t)}` into `instant` with `A_i = amplitude(component i)` \[m].
    fn fill_instant(&self, time: f64, instant: &mut SeaInstant, amplitude: impl Fn(&WaveComponent) -> f64) {
        let padded = self.components.len().div_ceil(CHAINS) * CHAINS;
        instant.real.clear();
        instant.imaginary.clear();
        for c in &self.components {
            let (sin, cos) = (c.phase - c.frequency * time).rem_euclid(std::f64::consts::TAU).sin_cos();
            let amplitude = amplitude(c);
            instant.real.push(amplitude * cos);
            instant.imaginary.push(amplitude * sin);
        }
        instant.real.resize(padded, 0.0);
        instant.imaginary.resize(padded, 0.0);
        instant.time = time;
    }

    /// The sea's flow at `time` \[s] into `instant`: `c_i = ω_i a_i e^{i(φ_i − ω_i t)}/(1 − ε_i)`
    /// and `d_i = ω_i c_i`, for [`Sea::kinematics_at`].
    pub fn flow_instant(&self, time: f64, instant: &mut FlowInstant) {
        let padded = self.components.len().div_ceil(CHAINS) * CHAINS;
        let FlowInstant { velocity, acceleration } = instant;
        for part in [&mut *velocity, &mut *acceleration] {
            part.real.clear();
            part.imaginary.clear();
            part.time = time;
        }
        for c in &self.components {
            let (sin, cos) = (c.phase - c.frequency * time).rem_euclid(std::f64::consts::TAU).sin_cos();
            let speed = c.frequency * c.amplitude / (1.0 - self.epsilon(c));
            velocity.real.push(speed * cos);
            velocity.imaginary.push(speed * sin);
            acceleration.real.push(c.frequency * speed * cos);
            acceleration.imaginary.push(c.frequency * speed * sin);
        }
        for part in [velocity, acceleration] {
            part.real.resize(padded, 0.0);
            part.imaginary.resize(padded, 0.0);
        }
    }

    /// Velocity [m/s] and acceleration [m/s²] of the water at `point` at the sea's `instant`
    /// (unramped): [`Sea::kinematics`], by powers of one complex number in a harmonic sea.
    ///
    /// With `w = e^{k_0 ζ} e^{i k_0 s}` and `u = e^{−k_0 (2h + ζ)} e^{i k_0 s}` (`s = e·x`; no `u`
    /// in deep water), `c_i w^{m_i}` is `ω_i a_i e^{k_i ζ} e^{iθ_i}/(1 − ε_i)` and `c_i u^{m_i}`
    /// is `ω_i a_i ε_i e^{−k_i ζ} e^{iθ_i}/(1 − ε_i)`, so with `V_± = Σ c_i (w^{m_i} ± u^{m_i})`
    /// and `A_± = Σ d_i (w^{m_i} ± u^{m_i})`: `u = Re V_+ e + Im V_− ẑ`,
    /// `u̇ = Im A_+ e − Re A_− ẑ`, the sums of [`Sea::kinematics`] to round-off (a few ulps of
    /// `Σ ω a` per product in the chains, 1e-13 relative for 50 components).
    #[inline(always)]
    pub fn kinematics_at(&self, instant: &FlowInstant, point: &Vec3) -> (Vec3, Vec3) {
        let Some(harmonic) = &self.harmonic else { return self.kinematics(point, instant.velocity.time) };
        let zeta = self.depth_below_level(point.z);
        let k0 = harmonic.base;
        let (sin, cos) = (k0 * (harmonic.heading[0] * point.x + harmonic.heading[1] * point.y)).sin_cos();
        let decay = (k0 * zeta).max(LOWEST_EXPONENT).exp();
        let falling = [decay * cos, decay * sin];
        let ([mut v_plus, mut a_plus], rising) = if self.depth.is_some() {
            // e^{−k0(2h + ζ)} ≤ e^{−k0 h}: no overflow, as ζ ≥ −h.
            let rising = harmonic.epsilon / decay;
            let [falling, rising] = harmonic_sums(instant, [falling, [rising * cos, rising * sin]], harmonic.first);
            (falling, Some(rising))
        } else {
            let [falling] = harmonic_sums(instant, [falling], harmonic.first);
            (falling, None)
        };
        let [mut v_minus, mut a_minus] = [v_plus, a_plus];
        if let Some([v_rising, a_rising]) = rising {
            for (plus, minus, rising) in [(&mut v_plus, &mut v_minus, v_rising), (&mut a_plus, &mut a_minus, a_rising)]
            {
                *plus = [plus[0] + rising[0], plus[1] + rising[1]];
                *minus = [minus[0] - rising[0], minus[1] - rising[1]];
            }
        }
        let horizontal = Vec3::new(harmonic.heading[0], harmonic.heading[1], 0.0);
        let velocity = horizontal * v_plus[0] + Vec3::z() * v_minus[1];
        let acceleration = horizontal * a_plus[1] - Vec3::z() * a_minus[0];
        (velocity, acceleration)
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

    /// `Σ a K_p cos θ` \[m] at the point `(x, y, z)` at the sea's `instant`: the dynamic
    /// pressure divided by `ρ g` (unramped).
    #[inline(always)]
    pub fn pressure_head(&self, instant: &SeaInstant, x: f64, y: f64, z: f64) -> f64 {
        let zeta = self.depth_below_level(z);
        let Some(harmonic) = &self.harmonic else { return self.pressure_head_by_component(instant.time, x, y, zeta) };
        let k0 = harmonic.base;
        let (sin, cos) = (k0 * (harmonic.heading[0] * x + harmonic.heading[1] * y)).sin_cos();
        let decay = (k0 * zeta).max(LOWEST_EXPONENT).exp();
        let mut sum = harmonic_sum(instant, [decay * cos, decay * sin], harmonic.first);
        if self.depth.is_some() {
            // e^{−k0(2h + ζ)} ≤ e^{−k0 h}: no overflow, as ζ ≥ −h.
            let rising = harmonic.epsilon / decay;
            sum += harmonic_sum(instant, [rising * cos, rising * sin], harmonic.first);
        }
        sum
    }

    /// The surface elevation `η = Σ a cos θ` \[m] above the still level at `(x, y)` at the
    /// surface `instant` ([`Sea::surface_instant`]; unramped): [`Sea::elevation`], by powers of
    /// one complex number in a harmonic sea — one sum per point, where the pressure head at the
    /// level, the same number to round-off (`K_p = 1` there), takes two in finite depth.
    #[inline(always)]
    pub fn elevation_at(&self, instant: &SeaInstant, x: f64, y: f64) -> f64 {
        let Some(harmonic) = &self.harmonic else { return self.elevation(x, y, instant.time) };
        let (sin, cos) = (harmonic.base * (harmonic.heading[0] * x + harmonic.heading[1] * y)).sin_cos();
        harmonic_sum(instant, [cos, sin], harmonic.first)
    }

    /// `Σ a K_p cos θ` [m] one component at a time, for a sea that is not harmonic.
    fn pressure_head_by_component(&self, time: f64, x: f64, y: f64, zeta: f64) -> f64 {
        self.components
            .iter()
            .map(|c| {
                let decay = (c.wave_number * zeta).max(LOWEST_EXPONENT).exp();
                let epsilon = self.epsilon(c);
                c.amplitude * (decay + epsilon / decay) / (1.0 + epsilon) * self.phase(c, x, y, time).cos()
            })
            .sum()
    }

    /// The surface elevation `η = Σ a cos θ` \[m] above the still level at `(x, y)` and `time`
    /// \[s] (unramped).
    pub fn elevation(&self, x: f64, y: f64, time: f64) -> f64 {
        self.components.iter().map(|c| c.amplitude * self.phase(c, x, y, time).cos()).sum()
    }

    /// Velocity [m/s] and acceleration [m/s²] of the water at `point` and `time` \[s]
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

/// `k_0`, `e` and the first `m` if every component heads the same way and `k_i = (m_0 + i) k_0`
/// to round-off (1e-12 relative).
fn harmonic_layout(components: &[WaveComponent]) -> Option<Harmonic> {
    let first = components.first()?;
    let same_heading = components.iter().all(|c| c.heading == first.heading);
    if !same_heading {
        return None;
    }
    let base = match components.get(1) {
        Some(second) => second.wave_number - first.wave_number,
        None => first.wave_number,
    };
    let m0 = (first.wave_number / base).round();
    let on_grid = base > 0.0
        && (1.0..1e6).contains(&m0)
        && components
            .iter()
            .enumerate()
            .all(|(i, c)| ((m0 + i as f64) * base - c.wave_number).abs() <= 1e-12 * c.wave_number);
    on_grid.then(|| Harmonic {
        base: first.wave_number / m0,
        heading: [first.heading.cos(), first.heading.sin()],
        first: m0 as u32,
        epsilon: 0.0,
    })
}

/// `a b` of two complex numbers `[re, im]`.
#[inline(always)]
fn multiply(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]
}

/// `z^first` by squaring.
#[inline(always)]
fn power(z: [f64; 2], first: u32) -> [f64; 2] {
    let (mut power, mut base, mut exponent) = ([1.0, 0.0], z, first);
    // Ends: `exponent` loses a bit each pass.
    while exponent > 0 {
        if exponent & 1 == 1 {
            power = multiply(power, base);
        }
        base = multiply(base, base);
        exponent >>= 1;
    }
    power
}

/// `z^first Σ_l z^l P_l` of the [`CHAINS`] lanes' complex values `P_l` (`lanes`: real parts,
/// imaginary parts).
#[inline(always)]
fn gather(lanes: &[[f64; CHAINS]; 2], z: [f64; 2], first: u32) -> [f64; 2] {
    let mut sum = [0.0, 0.0];
    let mut shift = [1.0, 0.0];
    for (&real, &imaginary) in lanes[0].iter().zip(&lanes[1]) {
        let term = multiply(shift, [real, imaginary]);
        sum = [sum[0] + term[0], sum[1] + term[1]];
        shift = multiply(shift, z);
    }
    multiply(power(z, first), sum)
}

/// `P ← P z⁴ + c` on each lane, the lanes' `P` as (real parts, imaginary parts): one step of
/// Horner's rule in `z⁴` for the chunk of coefficients `c` (real, imaginary).
#[inline(always)]
fn horner_step(p: &mut [[f64; CHAINS]; 2], z4: [f64; 2], c_real: &[f64], c_imaginary: &[f64]) {
    for lane in 0..CHAINS {
        let (r, i) = (p[0][lane], p[1][lane]);
        p[0][lane] = (r * z4[0] - i * z4[1]) + c_real[lane];
        p[1][lane] = (r * z4[1] + i * z4[0]) + c_imaginary[lane];
    }
}

/// `Σ_i c_i z^{first + i}` and `Σ_i d_i z^{first + i}` (complex) over the velocity and
/// acceleration amplitudes of `instant`, at each of the `P` points `z`: component `4j + l` in
/// lane `l`, each lane a polynomial in `z⁴` by Horner's rule (two complex products and two sums
/// per component for both sets, where powers of `z` cost a third product), then [`gather`]ed.
/// The points share one pass over the amplitudes (a node's `w` and `u` in finite depth: each
/// amplitude loaded once for both), each point's sums the same operations in the same order as
/// alone.
#[inline(always)]
fn harmonic_sums<const P: usize>(instant: &FlowInstant, z: [[f64; 2]; P], first: u32) -> [[[f64; 2]; 2]; P] {
    let z4 = z.map(|z| {
        let square = multiply(z, z);
        multiply(square, square)
    });
    let (v, a) = (&instant.velocity, &instant.acceleration);
    let mut velocity = [[[0.0; CHAINS]; 2]; P];
    let mut acceleration = [[[0.0; CHAINS]; 2]; P];
    let chunks = v.real.chunks_exact(CHAINS).zip(v.imaginary.chunks_exact(CHAINS));
    let chunks = chunks.zip(a.real.chunks_exact(CHAINS).zip(a.imaginary.chunks_exact(CHAINS)));
    for ((v_real, v_imaginary), (a_real, a_imaginary)) in chunks.rev() {
        for point in 0..P {
            horner_step(&mut velocity[point], z4[point], v_real, v_imaginary);
            horner_step(&mut acceleration[point], z4[point], a_real, a_imaginary);
        }
    }
    std::array::from_fn(|point| {
        [gather(&velocity[point], z[point], first), gather(&acceleration[point], z[point], first)]
    })
}

/// `Re Σ_i b_i z^{first + i}` over the components of `instant`, by Horner's rule in `z⁴` on
/// four lanes as [`harmonic_sums`].
#[inline(always)]
fn harmonic_sum(instant: &SeaInstant, z: [f64; 2], first: u32) -> f64 {
    let square = multiply(z, z);
    let z4 = multiply(square, square);
    let mut lanes = [[0.0; CHAINS]; 2];
    for (b_real, b_imaginary) in instant.real.chunks_exact(CHAINS).zip(instant.imaginary.chunks_exact(CHAINS)).rev() {
        horner_step(&mut lanes, z4, b_real, b_imaginary);
    }
    gather(&lanes, z, first)[0]
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

    /// Nine components of 0.7 m on the grid `k_i = (3 + i) k_0`, `k_0` = 0.013 rad/m, heading
    /// 0.7 rad, phases `0.37 i`, in water of `depth`.
    fn grid_components(depth: Option<f64>) -> Vec<WaveComponent> {
        let base = 0.013;
        (0..9)
            .map(|i| {
                let wave_number = f64::from(3 + i) * base;
                let frequency = (G * wave_number * depth.map_or(1.0, |h: f64| (wave_number * h).tanh())).sqrt();
                WaveComponent { amplitude: 0.7, frequency, wave_number, heading: 0.7, phase: 0.37 * f64::from(i) }
            })
            .collect()
    }

    /// Nine components on the grid `k_i = (3 + i) k_0`, heading 0.7 rad: the harmonic path
    /// (powers of one complex number) against the textbook sum, to 1e-12 m of 6.3 m of amplitude
    /// (round-off of nine products per chain and of phases of ~1e3 rad).
    #[test]
    fn the_harmonic_sum_matches_the_closed_form() {
        for depth in [None, Some(20.0), Some(3.0)] {
            let components = grid_components(depth);
            let sea = Sea::new(components.clone(), 0.0, depth);
            assert!(sea.is_harmonic());
            let time = 987.6;
            let mut instant = SeaInstant::default();
            sea.instant(time, &mut instant);
            for (x, y, z) in [(0.0, 0.0, 0.0), (130.0, -70.0, -1.5), (-400.0, 2.0, -2.9), (5.0, 5.0, 0.4)] {
                let expected: f64 = components.iter().map(|c| textbook_head(c, depth, x, y, z, time)).sum();
                assert_relative_eq!(sea.pressure_head(&instant, x, y, z), expected, epsilon = 1e-12);
            }
        }
    }

    /// The velocity and acceleration by powers of one complex number against the sums component
    /// by component, on the nine-component grid above, deep, finite and shallow, at points below
    /// the level, above it (the still level's kinematics) and below the seabed (the seabed's).
    #[test]
    fn the_harmonic_kinematics_match_the_sum_by_component() {
        for depth in [None, Some(20.0), Some(3.0)] {
            let components = grid_components(depth);
            let sea = Sea::new(components, 0.0, depth);
            assert!(sea.is_harmonic());
            let time = 987.6;
            let mut instant = FlowInstant::default();
            sea.flow_instant(time, &mut instant);
            assert_eq!(instant.time(), time);
            for point in
                [(0.0, 0.0, 0.0), (130.0, -70.0, -1.5), (-400.0, 2.0, -2.9), (5.0, 5.0, 0.4), (1.0, 2.0, -30.0)]
            {
                let point = Vec3::new(point.0, point.1, point.2);
                let (velocity, acceleration) = sea.kinematics(&point, time);
                let (harmonic_velocity, harmonic_acceleration) = sea.kinematics_at(&instant, &point);
                // Nine terms of up to ω a ≈ 1.7 m/s and ω² a ≈ 4 m/s²: round-off of the phases
                // (~1e3 rad) and of nine products per chain.
                assert_relative_eq!(harmonic_velocity, velocity, epsilon = 1e-11);
                assert_relative_eq!(harmonic_acceleration, acceleration, epsilon = 1e-11);
                assert!(velocity.norm() > 1e-3 || point.z < -20.0, "{velocity} at {point}");
            }
        }
    }

    /// The elevation at the surface instant against the textbook sum and against the pressure
    /// head at the still level, harmonic (the nine-component grid, deep, finite and shallow)
    /// and not (one component heading across), to 1e-12 m of 6.3 m of amplitude.
    #[test]
    fn the_elevation_at_an_instant_is_the_surface_s_sum() {
        for depth in [None, Some(20.0), Some(3.0)] {
            let mut across = grid_components(depth);
            across.push(WaveComponent { heading: 2.0, ..across[0] });
            for components in [grid_components(depth), across] {
                let sea = Sea::new(components.clone(), 0.0, depth);
                let time = 987.6;
                let (mut surface, mut instant) = (SeaInstant::default(), SeaInstant::default());
                sea.surface_instant(time, &mut surface);
                sea.instant(time, &mut instant);
                for (x, y) in [(0.0, 0.0), (130.0, -70.0), (-400.0, 2.0)] {
                    let expected: f64 = components.iter().map(|c| textbook_head(c, depth, x, y, 0.0, time)).sum();
                    assert_relative_eq!(sea.elevation_at(&surface, x, y), expected, epsilon = 1e-12);
                    assert_relative_eq!(
                        sea.elevation_at(&surface, x, y),
                        sea.pressure_head(&instant, x, y, 0.0),
                        epsilon = 1e-12
                    );
                }
            }
        }
    }

    #[test]
    fn pressure_head_by_component_matches_the_closed_form() {
        for depth in [None, Some(20.0), Some(3.0)] {
            // Six components: one full vector and a part-filled one.
            let components: Vec<_> =
                (0..6).map(|i| component(4.0 + f64::from(i), depth, 0.3 * f64::from(i), 1.1 * f64::from(i))).collect();
            let sea = Sea::new(components.clone(), 0.0, depth);
            assert!(!sea.is_harmonic());
            let time = 1234.567;
            let mut instant = SeaInstant::default();
            sea.instant(time, &mut instant);
            for (x, y, z) in [(0.0, 0.0, 0.0), (13.0, -7.0, -1.5), (-40.0, 2.0, -2.9), (5.0, 5.0, 0.4)] {
                let expected: f64 = components.iter().map(|c| textbook_head(c, depth, x, y, z, time)).sum();
                // Sums of six terms of 0.7 m: round-off of the phase at t ≈ 1e3 s.
                assert_relative_eq!(sea.pressure_head(&instant, x, y, z), expected, epsilon = 1e-11);
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

    /// A JONSWAP sea heading along x sums its surface once per column: the elevation is the
    /// same at every y to the bit; heading 30°, it is not, and the sea says so.
    #[test]
    fn a_sea_heading_along_x_has_the_same_elevation_at_every_y() {
        let sea = |heading: f64| {
            let waves = crate::water::WaveSpec::Jonswap {
                significant_height: 2.5,
                peak_period: 9.0,
                gamma: 3.3,
                heading,
                components: 50,
                seed: 1,
            };
            let spec = crate::water::WaterSpec { depth: Some(50.0), waves, ..crate::water::WaterSpec::default() };
            let water = crate::water::Water::new(spec, &crate::math::Vec3::new(0.0, 0.0, -G)).expect("a valid sea");
            water.sea().clone()
        };
        let (along, across) = (sea(0.0), sea(30.0));
        assert!(along.is_harmonic() && along.elevation_ignores_y());
        assert!(across.is_harmonic() && !across.elevation_ignores_y());
        let mut instant = SeaInstant::default();
        along.surface_instant(12.3, &mut instant);
        for x in [-80.0, -3.25, 0.0, 41.5] {
            let first = along.elevation_at(&instant, x, -60.0);
            for y in [-17.5, 0.0, 33.0, 60.0] {
                assert_eq!(along.elevation_at(&instant, x, y).to_bits(), first.to_bits(), "x = {x}, y = {y}");
            }
        }
        across.surface_instant(12.3, &mut instant);
        assert_ne!(across.elevation_at(&instant, 10.0, -60.0), across.elevation_at(&instant, 10.0, 60.0));
    }
}
