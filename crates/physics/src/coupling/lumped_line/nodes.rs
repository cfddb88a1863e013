//! The nodes of a dynamic line and the forces on them (PHYSICS.md §8 "Segment i", "Node i").
//!
//! Segment `i` joins nodes `i` and `i + 1`: `Δ = r_{i+1} − r_i`, `l_s = |Δ|`, `q = Δ/l_s`,
//! `ε = l_s/l − 1`, `ε̇ = q·(v_{i+1} − v_i)/l`; it carries `T = EA max(ε, 0) + BA ε̇` \[N]
//! along `q`. Node `i` (length share `l_i`, mass `m_i = λ0 l_i`) feels its segments, its wet
//! weight `m_i g − ρ A_d l_i g` under the still surface (`m_i g` above it), and under water the
//! drag `½ρ C_dn d l_i |v_rn| v_rn + ½ρ C_dt π d l_i |v_rt| v_rt` and the waves' inertia
//! `ρ A_d l_i [(1 + C_an) u̇_n + (1 + C_at) u̇_t]` on the relative velocity `v_r = u − v` split
//! along the node's tangent `q̂`; below the seabed (penetration `δ`) `(k_b δ − c_b v_z) d l_i`
//! upward and the friction `−C_B F_z tanh(|v_h|/v_s) v_h/|v_h|` (on an interior node both
//! dissipative parts are kept apart, [`NodeForces::seabed_damping`], and taken implicitly: the
//! damping in the kicks, the friction in the segments' solve, [`Damper`]). Its mass matrix is
//! `M_i = m_i E + ρ A_d l_i [C_an (E − q̂q̂ᵀ) + C_at q̂q̂ᵀ]` under water: `a E + b q̂q̂ᵀ`,
//! inverted as `(E − b/(a + b) q̂q̂ᵀ)/a`.

use super::discrete::Discrete;
use crate::math::Vec3;
use crate::seabed::Seabed;

/// Where a line's nodes are and how fast they move, at `time`.
#[derive(Debug, Clone, PartialEq)]
pub struct LineNodes {
    /// \[s].
    pub time: f64,
    /// `r_0 … r_N` \[m], world.
    pub positions: Vec<Vec3>,
    /// `v_0 … v_N` [m/s], world.
    pub velocities: Vec<Vec3>,
}

impl LineNodes {
    /// `positions` at rest at `time`.
    pub fn at_rest(time: f64, positions: Vec<Vec3>) -> Self {
        let velocities = vec![Vec3::zeros(); positions.len()];
        Self { time, positions, velocities }
    }

    /// The unstretched length lying on `seabed` \[m] (`up` the upward unit vertical, `segment`
    /// each segment's unstretched length \[m]): a segment whose two nodes touch it (at or below
    /// its elevation, where it holds them up, PHYSICS.md §8) lies on it whole, one with a single
    /// node touching it half (the touchdown is somewhere along it). The dynamic line's `L_B`,
    /// as the quasi-static line's is its grounded arc.
    pub fn grounded_length(&self, seabed: &Seabed, up: &Vec3, segment: f64) -> f64 {
        let touching: Vec<bool> = self.positions.iter().map(|p| p.dot(up) <= seabed.elevation()).collect();
        let halves: usize = touching.windows(2).map(|pair| usize::from(pair[0]) + usize::from(pair[1])).sum();
        0.5 * segment * halves as f64
    }

    /// The largest elastic tension `EA max(ε, 0)` of the line's segments \[N].
    pub fn largest_elastic_tension(&self, line: &Discrete) -> f64 {
        let longest = self.positions.windows(2).map(|pair| (pair[1] - pair[0]).norm()).fold(0.0, f64::max);
        line.ea * (longest / line.segment - 1.0).max(0.0)
    }

    /// `½ Σ m_i |v_i|²` \[J] of the nodes between the ends (the ends move with what they are
    /// attached to; their half-segment inertia is left out, as in MoorDyn's coupled points).
    pub fn kinetic_energy(&self, line: &Discrete) -> f64 {
        let interior = 1..line.segments;
        interior.map(|i| 0.5 * line.mass_per_length * line.share(i) * self.velocities[i].norm_squared()).sum()
    }
}

/// The water's velocity and acceleration at a node [m/s, m/s²] (zero without water).
pub type Flow = (Vec3, Vec3);

/// The forces on a line's nodes at one instant, with what they store.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct NodeForces {
    /// Every force on node `i` \[N].
    pub total: Vec<Vec3>,
    /// The part of `total` with no potential (internal damping, drag, the waves' inertia, the
    /// seabed's damping and friction) \[N]: its work is booked.
    pub unbooked: Vec<Vec3>,
    /// Segment tensions `EA max(ε, 0) + BA ε̇` \[N].
    pub tensions: Vec<f64>,
    /// Node mass matrices as `(a, b, q̂)`: `M = a E + b q̂q̂ᵀ` \[kg].
    pub masses: Vec<(f64, f64, Vec3)>,
    /// The seabed's damping of an interior node on it, `(c_n, c_f)` [N·s/m]: `c_n = c_b d l_i`
    /// across the bottom and the friction's secant `c_f = C_B F_z tanh(|v_h|/v_s)/|v_h|`
    /// (`C_B F_z/v_s` at rest) along it, so that the seabed's dissipative force is
    /// `−(c_n ûûᵀ + c_f (E − ûûᵀ)) v`, taken at a step's closing velocity: the normal part in
    /// the kicks, the friction in the segments' solve ([`Damper`], [`NodeForces::solve_damped`]);
    /// `(0, 0)` off the seabed. It is not in `total` or `unbooked`. The
    /// end nodes keep theirs in `total`: their bodies take it.
    pub seabed_damping: Vec<(f64, f64)>,
    /// Elastic `Σ ½ EA l ε²` over taut segments, wet weight and seabed `Σ ½ k_b d l_i δ²` \[J].
    pub potential: f64,
}

impl NodeForces {
    /// Buffers for a line of `segments` segments.
    fn resize(&mut self, segments: usize) {
        self.total.resize(segments + 1, Vec3::zeros());
        self.unbooked.resize(segments + 1, Vec3::zeros());
        self.tensions.resize(segments, 0.0);
        self.masses.resize(segments + 1, (0.0, 0.0, Vec3::z()));
        self.seabed_damping.resize(segments + 1, (0.0, 0.0));
    }

    /// `(M_i + τC_i)⁻¹ y` of node `i` (`up` the upward unit vertical, `C_i` the `part` of its
    /// [`NodeForces::seabed_damping`], `τ` \[s]): with `y = F − C v` the acceleration that
    /// takes that damping at the closing velocity of a step of `τ` (backward Euler in it), which
    /// no step length makes overshoot (PHYSICS.md §8 "Stable time
    /// step"). `M + τC = αE + b q̂q̂ᵀ + ε ûûᵀ` (`α = a + τ c_f`, `ε = τ (c_n − c_f)`) is inverted
    /// by two rank-one updates of `αE` (Sherman–Morrison), each denominator positive as the
    /// matrix is positive definite; off the seabed it is `M⁻¹ y`.
    #[inline(always)]
    pub fn solve_damped(&self, node: usize, part: Damper, up: &Vec3, tau: f64, y: &Vec3) -> Vec3 {
        let (c_n, c_f) = part.of(self.seabed_damping[node]);
        let (a, b, q) = self.masses[node];
        let alpha = a + tau * c_f;
        let (inverse_alpha, along) = (1.0 / alpha, b / (alpha + b));
        // B⁻¹ = (E − b/(α + b) q̂q̂ᵀ)/α, then (B + ε ûûᵀ)⁻¹ y = B⁻¹y − B⁻¹û ε ûᵀB⁻¹y/(1 + ε ûᵀB⁻¹û).
        let solve_b = |y: &Vec3| (y - q * (along * q.dot(y))) * inverse_alpha;
        if c_n == 0.0 && c_f == 0.0 {
            return solve_b(y);
        }
        let epsilon = tau * (c_n - c_f);
        let (b_y, b_up) = (solve_b(y), solve_b(up));
        b_y - b_up * (epsilon * up.dot(&b_y) / (1.0 + epsilon * up.dot(&b_up)))
    }

    /// The seabed's damping (`part` [`Damper::Normal`]) or friction ([`Damper::Friction`]) on
    /// node `i` at `velocity` [m/s] (`up` the upward unit vertical): `−C v` \[N] with that part
    /// of its [`NodeForces::seabed_damping`], zero off the seabed.
    #[inline(always)]
    pub fn seabed_force(&self, node: usize, part: Damper, velocity: &Vec3, up: &Vec3) -> Vec3 {
        -seabed_damping_force(part.of(self.seabed_damping[node]), up, velocity)
    }

    /// `(M_i − m_i E) a` \[N]: the force that accelerates the water node `i` carries with it.
    #[inline(always)]
    pub fn added_mass_force(&self, node: usize, mass: f64, acceleration: &Vec3) -> Vec3 {
        let (a, b, q) = self.masses[node];
        acceleration * (a - mass) + q * (b * q.dot(acceleration))
    }
}

/// A part of the seabed's damper `C = c_n ûûᵀ + c_f (E − ûûᵀ)` on a node: the damping across
/// the bottom, which the kicks take with the seabed's spring, or the friction along it, which
/// the segments' solve takes with the tensions it resists ([`super::axial`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Damper {
    /// `c_n ûûᵀ`.
    Normal,
    /// `c_f (E − ûûᵀ)`.
    Friction,
}

impl Damper {
    /// `(c_n, c_f)` with the other part zeroed.
    #[inline(always)]
    fn of(self, (c_n, c_f): (f64, f64)) -> (f64, f64) {
        match self {
            Self::Normal => (c_n, 0.0),
            Self::Friction => (0.0, c_f),
        }
    }
}

/// The forces on every node of `line` at `nodes` in the water's `flow` at each node (empty:
/// none), into `out`, with the potential energy. The end nodes move with their bodies and pass
/// them everything, their half segment's drag included (as MoorDyn's coupled points); only
/// their inertia is left out.
pub fn evaluate(line: &Discrete, nodes: &LineNodes, flow: &[Flow], out: &mut NodeForces) {
    evaluate_into::<true, true, true>(line, nodes, flow, out);
}

/// What an evaluation's outcome reads of [`evaluate`], into `out`: the segments' tensions, every
/// force on the two end nodes (`total[0]`, `total[N]`) and the potential energy, the same numbers
/// to the bit. The interior nodes' own forces are not taken (their drag, wave and seabed forces:
/// the sub-steps have kicked them already), so their entries hold their segments' share alone.
pub fn evaluate_ends(line: &Discrete, nodes: &LineNodes, flow: &[Flow], out: &mut NodeForces) {
    evaluate_into::<true, true, false>(line, nodes, flow, out);
}

/// [`evaluate`] without the segments' tensions (`out.tensions` untouched) and without the
/// potential energy (`out.potential` is 0): what a sub-step kicks the nodes with explicitly,
/// their segments being taken implicitly ([`super::axial`]).
pub fn evaluate_surroundings(line: &Discrete, nodes: &LineNodes, flow: &[Flow], out: &mut NodeForces) {
    evaluate_into::<false, false, true>(line, nodes, flow, out);
}

/// [`evaluate`], the potential energy summed when `POTENTIAL`, the segments' tensions taken
/// when `SEGMENTS`, the interior nodes' own forces when `INTERIOR` (else their potential alone).
/// The slices are cut to the line's `N + 1` nodes and `N` segments up front, so that the loops
/// index them without checks.
#[inline(always)]
fn evaluate_into<const POTENTIAL: bool, const SEGMENTS: bool, const INTERIOR: bool>(
    line: &Discrete,
    nodes: &LineNodes,
    flow: &[Flow],
    out: &mut NodeForces,
) {
    let n = line.segments;
    out.resize(n);
    let (x, v) = (&nodes.positions[..=n], &nodes.velocities[..=n]);
    let (total, unbooked) = (&mut out.total[..=n], &mut out.unbooked[..=n]);
    let (tensions, masses) = (&mut out.tensions[..n], &mut out.masses[..=n]);
    let seabed_damping = &mut out.seabed_damping[..=n];
    total.fill(Vec3::zeros());
    unbooked.fill(Vec3::zeros());
    seabed_damping.fill((0.0, 0.0));
    let mut potential = if SEGMENTS { add_segments::<POTENTIAL>(line, x, v, total, unbooked, tensions) } else { 0.0 };
    let g = line.gravity.norm();
    let p = &line.parameters;
    for node in 0..=n {
        let share = line.share(node);
        let mass = line.mass_per_length * share;
        let position = &x[node];
        let height = position.dot(&line.up);
        let displaced = line.density * line.displaced_area * share;
        // The seabed and the node's depth into it, when the node is below it.
        let grounded =
            line.seabed.map(|seabed| (seabed, seabed.elevation() - height)).filter(|&(_, depth)| depth > 0.0);
        let area = line.bearing * share;
        if POTENTIAL {
            potential += mass * g * height;
            if let Some(level) = line.water_level {
                // The buoyancy's potential −ρ A_d l_i g min(h − h_w, 0) is continuous at the surface.
                potential -= displaced * g * (height - level).min(0.0);
            }
            if let Some((_, depth)) = grounded {
                potential += 0.5 * p.seabed_stiffness() * area * depth * depth;
            }
        }
        if !INTERIOR && node != 0 && node != n {
            continue;
        }
        total[node] += line.gravity * mass;
        let tangent = tangent(x, node, n);
        let submerged = line.submerged(position);
        let mut matrix = (mass, 0.0, tangent);
        if submerged {
            total[node] += line.up * (displaced * g);
            matrix = (
                mass + displaced * p.added_mass_normal(),
                displaced * (p.added_mass_tangential() - p.added_mass_normal()),
                tangent,
            );
            if let Some((water_velocity, water_acceleration)) = flow.get(node) {
                let water = water_forces(line, share, &tangent, &(water_velocity - v[node]), water_acceleration);
                total[node] += water;
                unbooked[node] += water;
            }
        }
        if let Some((seabed, depth)) = grounded {
            let sinking = v[node].dot(&line.up);
            total[node] += line.up * (p.seabed_stiffness() * area * depth);
            let normal = (p.seabed_stiffness() * depth - p.seabed_damping() * sinking).max(0.0) * area;
            let sliding = v[node] - line.up * sinking;
            let speed = sliding.norm();
            // tanh(s/v_s)/s, 1/v_s at s = 0.
            let secant = if speed > 0.0 {
                (speed / p.friction_speed()).tanh() * (1.0 / speed)
            } else {
                1.0 / p.friction_speed()
            };
            let damping = (p.seabed_damping() * area, seabed.line_friction() * normal * secant);
            if node == 0 || node == n {
                let force = -seabed_damping_force(damping, &line.up, &v[node]);
                total[node] += force;
                unbooked[node] += force;
            } else {
                seabed_damping[node] = damping;
            }
        }
        masses[node] = matrix;
    }
    out.potential = potential;
}

/// Segment `i`'s tension `T = EA max(ε, 0) + BA ε̇` on its two nodes, into `total` (its damping
/// part into `unbooked` too) and `tensions`; returns the elastic energy when `POTENTIAL` \[J].
#[inline(always)]
fn add_segments<const POTENTIAL: bool>(
    line: &Discrete,
    x: &[Vec3],
    v: &[Vec3],
    total: &mut [Vec3],
    unbooked: &mut [Vec3],
    tensions: &mut [f64],
) -> f64 {
    let mut potential = 0.0;
    let mut previous = Vec3::z();
    // One division per line and per segment: the rest are products by reciprocals.
    let per_length = 1.0 / line.segment;
    for i in 0..line.segments {
        let (q, strain, rate) = segment_strain(&(x[i + 1] - x[i]), &(v[i + 1] - v[i]), &mut previous, per_length);
        let elastic = line.ea * strain.max(0.0);
        let damping = line.ba * rate;
        tensions[i] = elastic + damping;
        if POTENTIAL && strain > 0.0 {
            potential += 0.5 * line.ea * line.segment * strain * strain;
        }
        total[i] += q * (elastic + damping);
        total[i + 1] -= q * (elastic + damping);
        unbooked[i] += q * damping;
        unbooked[i + 1] -= q * damping;
    }
    potential
}

/// A segment's unit direction `q = Δ/|Δ|`, strain `ε = |Δ|/l − 1` and strain rate
/// `ε̇ = q·Δv/l` (PHYSICS.md §8 "Segment i") for its chord `delta` = `Δ`, its ends' relative
/// velocity `relative` = `Δv` and `per_length` = `1/l`; where `Δ` vanishes the direction is the
/// `previous` segment's, and `previous` becomes this one's.
#[inline(always)]
pub(super) fn segment_strain(delta: &Vec3, relative: &Vec3, previous: &mut Vec3, per_length: f64) -> (Vec3, f64, f64) {
    let stretched = delta.norm();
    let q = if stretched > 0.0 { delta * (1.0 / stretched) } else { *previous };
    *previous = q;
    (q, stretched * per_length - 1.0, q.dot(relative) * per_length)
}

/// `C v = c_n (û·v) û + c_f (v − (û·v) û)` \[N]: the seabed's damper `(c_n, c_f)` [N·s/m]
/// across and along the bottom (`up` = `û`) at `velocity` [m/s] ([`NodeForces::seabed_damping`]).
#[inline(always)]
fn seabed_damping_force((c_n, c_f): (f64, f64), up: &Vec3, velocity: &Vec3) -> Vec3 {
    let sinking = up.dot(velocity);
    up * (c_n * sinking) + (velocity - up * sinking) * c_f
}

/// Drag and the waves' inertia \[N] on a node of length share `share` with tangent `tangent`,
/// relative velocity `relative` = u − v and water acceleration `acceleration`.
#[inline(always)]
fn water_forces(line: &Discrete, share: f64, tangent: &Vec3, relative: &Vec3, acceleration: &Vec3) -> Vec3 {
    let p = &line.parameters;
    let tangential = tangent.dot(relative);
    let along = tangent * tangential;
    let across = relative - along;
    let half_rho = 0.5 * line.density;
    // |v_rt| = |q̂·v_r|, q̂ a unit vector: no square root.
    let drag = across * (half_rho * p.drag_normal() * line.diameter * share * across.norm())
        + along * (half_rho * p.drag_tangential() * std::f64::consts::PI * line.diameter * share * tangential.abs());
    let accel_along = tangent * tangent.dot(acceleration);
    let accel_across = acceleration - accel_along;
    let displaced = line.density * line.displaced_area * share;
    let inertia =
        (accel_across * (1.0 + p.added_mass_normal()) + accel_along * (1.0 + p.added_mass_tangential())) * displaced;
    drag + inertia
}

/// The unit tangent at node `node` of `n + 1`: along `r_{i+1} − r_{i−1}`, an end's along its
/// segment.
#[inline(always)]
fn tangent(x: &[Vec3], node: usize, n: usize) -> Vec3 {
    let (a, b) = (node.saturating_sub(1), (node + 1).min(n));
    let chord = x[b] - x[a];
    let length = chord.norm();
    if length > 0.0 { chord * (1.0 / length) } else { Vec3::z() }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A node on the seabed (mass `a = 30 kg`, `b = −2 kg` along a tangent tilted off the
    /// vertical, the seabed's `c_n` = 2e4 and `c_f` = 5e5 N·s/m) stepped 10 ms from 0.3 m/s
    /// sliding with 0.1 m/s sinking under a force: [`NodeForces::solve_damped`] solves
    /// `(M + τC) a = F − C v` to round-off for each part of the damper (the kicks' `c_n ûûᵀ`
    /// and the segments' solve's `c_f (E − ûûᵀ)`); with the friction alone and no other force,
    /// for τ from 1 µs to 1 s, the
    /// sliding never reverses and slows, and the kinetic energy `½ vᵀMv` falls (the explicit step,
    /// `v − τ M⁻¹ C v`, reverses the sliding from τ = 2a/c_f = 0.12 ms).
    #[test]
    fn the_seabed_damper_is_solved_implicitly_and_never_overshoots() {
        let (a, b, q) = (30.0, -2.0, Vec3::new(0.6, 0.0, 0.8));
        let (c_n, c_f) = (2.0e4, 5.0e5);
        let up = Vec3::z();
        let node = NodeForces { masses: vec![(a, b, q)], seabed_damping: vec![(c_n, c_f)], ..NodeForces::default() };
        let velocity = Vec3::new(0.3, 0.0, -0.1);
        let force = Vec3::new(-40.0, 15.0, 120.0);
        let tau = 0.01;
        let mass = |y: Vec3| y * a + q * (b * q.dot(&y));
        let normal = |y: Vec3| up * (c_n * up.dot(&y));
        let friction = |y: Vec3| (y - up * up.dot(&y)) * c_f;
        for (part, part_damper) in [(Damper::Normal, &normal as &dyn Fn(Vec3) -> Vec3), (Damper::Friction, &friction)] {
            let pushed = force - part_damper(velocity);
            let acceleration = node.solve_damped(0, part, &up, tau, &pushed);
            let residual = mass(acceleration) + part_damper(acceleration) * tau - pushed;
            assert!(residual.norm() < 1e-9 * force.norm().max(part_damper(velocity).norm()), "{part:?}: {residual}");
        }
        let damper = friction;
        for tau in [1e-6, 1e-4, 1e-3, 1e-2, 1.0] {
            let after = velocity + node.solve_damped(0, Damper::Friction, &up, tau, &-damper(velocity)) * tau;
            assert!(after.x > 0.0 && after.x < velocity.x, "τ = {tau}: {after}");
            assert!(after.dot(&mass(after)) < velocity.dot(&mass(velocity)), "τ = {tau}: {after}");
        }
        let explicit = velocity - (damper(velocity) - q * (b / (a + b) * q.dot(&damper(velocity)))) * (2e-4 / a);
        assert!(explicit.x < 0.0, "the explicit step overshoots: {explicit}");
    }

    /// Five nodes 10 m apart, three on a seabed at z = −50 (one sunk into it), the fourth 1 cm
    /// above: two segments lie on it whole, the touchdown segment half: 25 m.
    #[test]
    fn the_grounded_length_counts_the_segments_on_the_seabed() {
        let seabed = Seabed::new(-50.0, 0.5).expect("valid");
        let heights = [-50.002, -50.0, -50.001, -49.99, -45.0];
        let positions = heights.iter().enumerate().map(|(i, &z)| Vec3::new(10.0 * i as f64, 0.0, z)).collect();
        let nodes = LineNodes::at_rest(0.0, positions);
        assert_eq!(nodes.grounded_length(&seabed, &Vec3::z(), 10.0), 25.0);
        assert_eq!(nodes.grounded_length(&Seabed::new(-60.0, 0.5).expect("valid"), &Vec3::z(), 10.0), 0.0);
    }
}
