//! The segments' tensions over one sub-step, taken implicitly with the seabed's friction they
//! pull against (PHYSICS.md §8 "The axial stiffness implicit").
//!
//! The line's axial modes are its fastest by far (`ω = 2√(EA/(λ0 l²))`, 663 rad/s on
//! `moored_buoy`'s chains against 24 rad/s for the transverse ones at their largest tension):
//! stepped explicitly they bind the sub-step to ~1 ms, where the wave-frequency motion an
//! engineer watches needs tens. Over a sub-step of `h` the interior nodes therefore drift under
//! their segments by the implicit midpoint rule, with the seabed's friction `C_i`
//! ([`super::nodes::Damper::Friction`]) at the closing velocity (backward Euler in it):
//!
//! - segment `j` at the iterate's mid-step `r + ½h (v + δ)`: `q̃_j`, `ε̃_j` and
//!   `T̃_j = EA max(ε̃_j, 0) + BA q̃_j·(v + δ)_{j+1} − (v + δ)_j)/l`;
//! - the mid-step tension `T_j = T̃_j + κ_j (w_j − w̃_j)`, `κ_j = (s_j ½h EA + BA)/l` (`s_j` = 1
//!   taut, 0 slack), `w_j = q̃_j·(δ_{j+1} − δ_j)` the change of the segment's stretch rate;
//! - the velocity change to mid-step `(M_i + hC_i) δ_i = ½h (q̃_i T_i − q̃_{i−1} T_{i−1} − C_i v_i)`
//!   (zero at the end nodes, which move as their bodies do);
//! - eliminating `δ`: `(I + ½h K G) T = T̃ − K w̃ + ½h K B p`, `K = diag κ`, `G = B M̃⁻¹ Bᵀ`,
//!   `p = M̃⁻¹(−C v)` — tridiagonal (`G_jj = q̃_j·(M̃_j⁻¹ + M̃_{j+1}⁻¹) q̃_j`,
//!   `G_{j,j+1} = −q̃_j·M̃_{j+1}⁻¹ q̃_{j+1}`), solved by the Thomas algorithm in `O(N)`
//!   (`I + ½h K G` is similar to the symmetric positive definite `I + ½h K^½ G K^½`, so no
//!   pivoting is needed);
//! - two Newton iterations, each re-taking the directions and stretches at the new
//!   mid-step (one alone is unstable past ~10 ms on a chain: the stretch a segment's rotation
//!   adds is second order in the step);
//! - then `v_mid = v + δ`, `r ← r + h v_mid`, `v ← v + 2δ`.
//!
//! The midpoint rule is A-stable: no step length makes the axial modes grow, and for linear
//! springs it conserves their energy, so a line without damping keeps its energy at second order
//! as the explicit Verlet did. Modes the step does not resolve (`ω h ≫ 1`) are not damped by the
//! scheme: the internal damping `BA` (taken implicitly too) damps them. The transverse stiffness
//! `T/l_s` is explicit in the predictor's directions and bounds the sub-step
//! ([`super::Discrete::transverse_limit`]). A segment predicted taut that goes slack within the
//! step keeps its linearised elastic tension for that step.
//!
//! Written here rather than taken from a crate: the system is a scalar tridiagonal solve of a
//! few dozen rows per sub-step, which `nalgebra`'s dense LU would do in `O(N³)` and sparse
//! solvers (`faer`'s, `nalgebra-sparse`) with set-up costs above the solve itself.

use super::discrete::Discrete;
use super::nodes::{Damper, NodeForces, segment_strain};
use crate::math::Vec3;

/// Scratch for the axial solve, kept by a line's run across its sub-steps.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct AxialSolve {
    /// Per segment: `q̃_j`, the right-hand side `T̃_j` then the solved `T_j` \[N], `κ_j` [N·s/m],
    /// and the Thomas algorithm's modified upper diagonal.
    directions: Vec<Vec3>,
    tensions: Vec<f64>,
    stiffness: Vec<f64>,
    upper: Vec<f64>,
    /// Per node: `M̃_i⁻¹ q̃_{i−1}` and `M̃_i⁻¹ q̃_i` [1/kg] (zero at the end nodes).
    behind: Vec<Vec3>,
    ahead: Vec<Vec3>,
    /// Per node: the velocity change to mid-step `δ_i` [m/s] of the current iterate, and
    /// `M̃_i⁻¹ (−C_i v_i)` [m/s²], the seabed damper's pull (zero off the seabed and at the ends).
    change: Vec<Vec3>,
    damper: Vec<Vec3>,
}

/// Newton iterations of the mid-step solve (module doc).
const ITERATIONS: usize = 2;

impl AxialSolve {
    /// One sub-step of `h` \[s] of `line`'s nodes under their segments and the seabed's
    /// friction (module doc), the mass matrices and dampers those of `masses` (the last
    /// evaluation's). `positions` and `velocities` are the nodes' at the sub-step's start (the end
    /// nodes' at their constant speed along their path); on return the interior positions are at
    /// the sub-step's end and their velocities at mid-step, `v + δ` — the velocity the forces
    /// that depend on it are evaluated at — which [`Self::close`] then takes to the end.
    /// Returns the work of the internal damping, the friction and the added mass's reaction over
    /// the sub-step \[J].
    pub fn step(
        &mut self,
        line: &Discrete,
        masses: &NodeForces,
        positions: &mut [Vec3],
        velocities: &mut [Vec3],
        h: f64,
    ) -> f64 {
        let n = line.segments;
        self.resize(n);
        let half = 0.5 * h;
        self.change.fill(Vec3::zeros());
        self.damp(line, masses, velocities, h);
        for _ in 0..ITERATIONS {
            self.linearise(line, positions, velocities, half);
            self.couple_to_masses(line, masses, h);
            self.solve(n, half);
            self.update_change(n, half);
        }
        self.drift(positions, velocities, n, h);
        self.damping_work(line, masses, velocities, h)
    }

    /// `M̃_i⁻¹ (−C_i v_i)` at each interior node, `M̃ = M + hC` ([`NodeForces::solve_damped`]).
    fn damp(&mut self, line: &Discrete, masses: &NodeForces, velocities: &[Vec3], h: f64) {
        let interior = velocities.iter().enumerate().take(line.segments).skip(1);
        for (i, velocity) in interior {
            let pull = masses.seabed_force(i, Damper::Friction, velocity, &line.up);
            self.damper[i] = masses.solve_damped(i, Damper::Friction, &line.up, h, &pull);
        }
    }

    fn resize(&mut self, segments: usize) {
        self.change.resize(segments + 1, Vec3::zeros());
        self.damper.resize(segments + 1, Vec3::zeros());
        for buffer in [&mut self.tensions, &mut self.stiffness, &mut self.upper] {
            buffer.resize(segments, 0.0);
        }
        self.directions.resize(segments, Vec3::z());
        self.behind.resize(segments + 1, Vec3::zeros());
        self.ahead.resize(segments + 1, Vec3::zeros());
    }

    /// `q̃_j`, `κ_j` and the right-hand side `T̃_j + κ_j q̃_j·(½h (p_{j+1} − p_j) − (δ_{j+1} − δ_j))`
    /// at the current iterate's mid-step `r + ½h (v + δ)`, `v + δ` (`p` the dampers' pull).
    fn linearise(&mut self, line: &Discrete, positions: &[Vec3], velocities: &[Vec3], half: f64) {
        let n = line.segments;
        let per_length = 1.0 / line.segment;
        let mut previous = Vec3::z();
        for j in 0..n {
            let change = self.change[j + 1] - self.change[j];
            let relative = velocities[j + 1] - velocities[j] + change;
            let delta = (positions[j + 1] - positions[j]) + relative * half;
            let (q, strain, rate) = segment_strain(&delta, &relative, &mut previous, per_length);
            let taut = if strain > 0.0 { half * line.ea } else { 0.0 };
            let stiffness = (taut + line.ba) * per_length;
            self.directions[j] = q;
            self.stiffness[j] = stiffness;
            let pulled = (self.damper[j + 1] - self.damper[j]) * half;
            self.tensions[j] = line.ea * strain.max(0.0) + line.ba * rate + stiffness * q.dot(&(pulled - change));
        }
    }

    /// `M̃_i⁻¹ q̃_{i−1}` and `M̃_i⁻¹ q̃_i` at each interior node (`M̃ = M + hC`,
    /// [`NodeForces::solve_damped`]).
    fn couple_to_masses(&mut self, line: &Discrete, masses: &NodeForces, h: f64) {
        for i in 1..line.segments {
            self.behind[i] = masses.solve_damped(i, Damper::Friction, &line.up, h, &self.directions[i - 1]);
            self.ahead[i] = masses.solve_damped(i, Damper::Friction, &line.up, h, &self.directions[i]);
        }
    }

    /// `(I + ½h K G) T = rhs` by the Thomas algorithm, in place in `tensions`.
    fn solve(&mut self, n: usize, half: f64) {
        let mut previous_upper = 0.0;
        let mut previous_rhs = 0.0;
        for j in 0..n {
            let q = self.directions[j];
            let scale = half * self.stiffness[j];
            // G_jj from node j (interior when j > 0) and node j + 1 (interior when j < n − 1).
            let mut diagonal = 0.0;
            let mut lower = 0.0;
            if j > 0 {
                diagonal += q.dot(&self.ahead[j]);
                lower = -scale * q.dot(&self.behind[j]);
            }
            let mut upper = 0.0;
            if j + 1 < n {
                diagonal += q.dot(&self.behind[j + 1]);
                upper = -scale * q.dot(&self.ahead[j + 1]);
            }
            let pivot = 1.0 + scale * diagonal - lower * previous_upper;
            previous_upper = upper / pivot;
            previous_rhs = (self.tensions[j] - lower * previous_rhs) / pivot;
            self.upper[j] = previous_upper;
            self.tensions[j] = previous_rhs;
        }
        for j in (0..n.saturating_sub(1)).rev() {
            self.tensions[j] -= self.upper[j] * self.tensions[j + 1];
        }
    }

    /// `δ_i = ½h (M̃_i⁻¹(q̃_i T_i − q̃_{i−1} T_{i−1}) + p_i)` at the interior nodes (zero at the ends).
    fn update_change(&mut self, n: usize, half: f64) {
        for i in 1..n {
            self.change[i] =
                (self.ahead[i] * self.tensions[i] - self.behind[i] * self.tensions[i - 1] + self.damper[i]) * half;
        }
    }

    /// The interior nodes to the sub-step's end: `r ← r + h (v + δ)`; `velocities` then holds
    /// the mid-step velocities `v + δ` until [`Self::close`].
    fn drift(&self, positions: &mut [Vec3], velocities: &mut [Vec3], n: usize, h: f64) {
        for i in 1..n {
            velocities[i] += self.change[i];
            positions[i] += velocities[i] * h;
        }
    }

    /// The work \[J] over the sub-step of the internal damping at the mid-step velocities, and
    /// over the nodes' drift `h v_mid` of the seabed's friction at the closing velocities
    /// `v_mid + δ` and of the added mass's reaction to the change `2δ`.
    fn damping_work(&self, line: &Discrete, masses: &NodeForces, velocities: &[Vec3], h: f64) -> f64 {
        let n = line.segments;
        let per_length = 1.0 / line.segment;
        let mut work = 0.0;
        for j in 0..n {
            let rate = self.directions[j].dot(&(velocities[j + 1] - velocities[j]));
            work -= h * line.ba * per_length * rate * rate;
        }
        for (i, middle) in velocities.iter().enumerate().take(n).skip(1) {
            let closing = middle + self.change[i];
            let friction = masses.seabed_force(i, Damper::Friction, &closing, &line.up);
            // The water the node carries takes its share of the change `2δ` (§8 "Energy").
            let mass = line.mass_per_length * line.share(i);
            let carried = masses.added_mass_force(i, mass, &(self.change[i] * (2.0 / h)));
            work += h * (friction - carried).dot(middle);
        }
        work
    }

    /// The interior velocities from mid-step to the sub-step's end, `v_mid + δ`.
    pub fn close(&self, velocities: &mut [Vec3]) {
        for (velocity, change) in velocities.iter_mut().zip(&self.change).skip(1) {
            *velocity += change;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupling::catenary::Catenary;
    use crate::coupling::ends::Endpoint;
    use crate::coupling::lumped_line::{InternalDamping, LineModel, LumpedMass, nodes};
    use crate::surroundings::Surroundings;

    /// `moored_buoy`'s chain (λ0 = 25.79 kg/m, EA = 1.107e8 N, N = 40 segments of 6.25 m)
    /// stretched 1e-3 along x between fixed ends in empty space, without internal damping.
    fn taut_chain() -> Discrete {
        let model = LumpedMass::plain(40, InternalDamping::Coefficient(0.0)).expect("valid");
        let line =
            Catenary::new(Endpoint::World(Vec3::zeros()), Endpoint::World(Vec3::x() * 250.25), 25.79, 250.0, 442714.0)
                .expect("valid")
                .with_model(LineModel::Dynamic(model));
        Discrete::new(&line, &model, &Surroundings::dry(Vec3::zeros()), None)
    }

    /// `Σ ½ m_i |v_i|² + Σ ½ EA l ε²` \[J].
    fn energy(line: &Discrete, x: &[Vec3], v: &[Vec3]) -> f64 {
        let kinetic: f64 =
            (1..line.segments).map(|i| 0.5 * line.mass_per_length * line.segment * v[i].norm_squared()).sum();
        let elastic: f64 = x
            .windows(2)
            .map(|pair| ((pair[1] - pair[0]).norm() / line.segment - 1.0).max(0.0))
            .map(|strain| 0.5 * line.ea * line.segment * strain * strain)
            .sum();
        kinetic + elastic
    }

    /// `steps` sub-steps of `h` of the nodes under their segments alone from `x`, `v`.
    fn run(line: &Discrete, x: &mut [Vec3], v: &mut [Vec3], h: f64, steps: usize) {
        let (mut solve, mut masses) = (AxialSolve::default(), NodeForces::default());
        for _ in 0..steps {
            let at = nodes::LineNodes { time: 0.0, positions: x.to_vec(), velocities: v.to_vec() };
            nodes::evaluate_surroundings(line, &at, &[], &mut masses);
            let work = solve.step(line, &masses, x, v, h);
            assert_eq!(work, 0.0, "no internal damping, no work booked");
            solve.close(v);
        }
    }

    /// A node of the taut chain struck across and along (1, 0.5, 0) m/s, stepped 1 s at 2, 5,
    /// 10 and 20 times the explicit axial limit (3.02 ms undamped): the energy stays within 1e-4 of its
    /// start (the midpoint rule on the segments), where the explicit Verlet diverges.
    #[test]
    fn the_segments_keep_their_energy_far_past_the_explicit_limit() {
        let line = taut_chain();
        let limit = line.limits().axial;
        assert!((limit - 3.02e-3).abs() < 1e-5, "{limit}");
        let start: Vec<Vec3> = (0..=40).map(|i| Vec3::x() * (6.25 * 1.001 * i as f64)).collect();
        let mut struck = vec![Vec3::zeros(); 41];
        struck[3] = Vec3::new(1.0, 0.5, 0.0);
        let initial = energy(&line, &start, &struck);
        for multiple in [2.0, 5.0, 10.0, 20.0] {
            let h = multiple * limit;
            let (mut x, mut v) = (start.clone(), struck.clone());
            run(&line, &mut x, &mut v, h, (1.0 / h).ceil() as usize);
            let drift = energy(&line, &x, &v) / initial - 1.0;
            assert!(drift.abs() < 1e-4, "{multiple} × the limit: energy {drift:+.2e}");
        }
    }

    /// The taut chain's lowest axial mode `ω_1 = 2√(EA/(λ0 l²)) sin(π/2N)` (26.0 rad/s),
    /// stepped at `h` with `ω_1 h` = 0.5 and 1: its period is the midpoint rule's,
    /// `Ω h = 2 atan(ω_1 h/2)`, to 1e-3 — the closed form of the scheme on a linear mode.
    #[test]
    fn the_lowest_axial_mode_oscillates_at_the_midpoint_rule_s_frequency() {
        let line = taut_chain();
        let n = line.segments;
        let omega = 2.0
            * (line.ea / (line.mass_per_length * line.segment * line.segment)).sqrt()
            * (std::f64::consts::PI / (2.0 * n as f64)).sin();
        for omega_h in [0.5, 1.0] {
            let h = omega_h / omega;
            // The mode's shape `sin(π i/N)` along x in the velocities, from the stretched rest.
            let mut x: Vec<Vec3> = (0..=n).map(|i| Vec3::x() * (6.25 * 1.001 * i as f64)).collect();
            let mut v: Vec<Vec3> =
                (0..=n).map(|i| Vec3::x() * (1e-3 * (std::f64::consts::PI * i as f64 / n as f64).sin())).collect();
            // The middle node's velocity changes sign downward twice a period: time 20 periods.
            let (mut crossings, mut first, mut last, mut previous) = (0, 0.0, 0.0, v[n / 2].x);
            for step in 1..=((40.0 * std::f64::consts::TAU / omega / h) as usize) {
                run(&line, &mut x, &mut v, h, 1);
                let now = v[n / 2].x;
                if previous > 0.0 && now <= 0.0 {
                    // Linear interpolation of the crossing within the step.
                    let at = h * (step as f64 - 1.0 + previous / (previous - now));
                    if crossings == 0 {
                        first = at
                    } else {
                        last = at
                    }
                    crossings += 1;
                }
                previous = now;
            }
            let period = (last - first) / f64::from(crossings - 1);
            let expected = std::f64::consts::TAU * h / (2.0 * (0.5 * omega_h).atan());
            eprintln!(
                "ω1 h = {omega_h}: period {period:.6} s, midpoint rule {expected:.6} s, ω1 {:.6} s",
                std::f64::consts::TAU / omega
            );
            assert!((period / expected - 1.0).abs() < 1e-3, "{period} against {expected}");
        }
    }
}
