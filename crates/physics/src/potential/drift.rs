//! Second-order wave drift on a body with potential-flow data (PHYSICS.md §10, "Mean drift
//! coefficients", "Newman's approximation"): the mean drift coefficients `D_i(ω, β)` from the
//! panel code (WAMIT `.8` or `.9`), and the drift force they give in a sea.
//!
//! `D_i` is the mean force [N/m²] (i = surge, sway, heave) or moment [N·m/m²] (roll, pitch, yaw)
//! per unit wave amplitude squared: a regular wave of amplitude `a` gives `F̄_i = a² D_i(ω, β)`.
//! For a sea of components `(a_n, ω_n, β_n, φ_n)` (§6), with `θ_n(t) = ω_n t − k_n e_n·x₀ − φ_n`
//! the phase of component n at the body's mean position `x₀`:
//! - [`DriftModel::Mean`]: the constant `Σ a_n² D_i(ω_n, β_n)`;
//! - [`DriftModel::Newman`]: `F_i(t) = Re{Z_s(t) Z(t)*}` with the envelopes
//!   `Z = Σ a_n √|D_n| e^{iθ_n}` and `Z_s = Σ s_n a_n √|D_n| e^{iθ_n}`, `s_n = sgn D_n`: the
//!   difference-frequency sum with Newman's QTF `T_mn = s_m √|D_m D_n|` in O(N) per evaluation
//!   (no N² double sum, no sum-frequency part). Its mean is the `Mean` model's; in a regular
//!   wave the two are the same constant.
//!
//! Both act at the body's reference point in the panel code's axes, which are the world's at the
//! body's mean heading (potential flow starts within 5° of them: [`super::body`]); the water stage
//! ramps the drift with the square of the waves' ramp (the drift is quadratic in amplitude).
//!
//! `D(ω, β)` is interpolated linearly in ω, the end values held outside the file's frequencies,
//! and linearly in β between the file's headings; a sea heading outside them is refused, as
//! for the excitation ([`super::excitation`]).

use super::tables::{
    CoefficientsError, HeadingMissing, bracket_frequency, bracket_heading, check_count, check_finite,
    check_frequencies, check_headings,
};
use crate::water::waves::WaveComponent;
use nalgebra::Complex;

/// A 6-vector over the body's degrees of freedom ([`super::Vector6`]).
type Vector6 = nalgebra::Vector6<f64>;

/// How a body's drift coefficients load it (PHYSICS.md §10).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum DriftModel {
    /// No drift force (the default).
    #[default]
    Off,
    /// The mean drift `Σ a_n² D(ω_n)`, constant.
    Mean,
    /// Newman's slow drift: the mean and its difference-frequency variation.
    Newman,
}

impl DriftModel {
    /// Every model, from none to the most complete.
    pub const ALL: [Self; 3] = [Self::Off, Self::Mean, Self::Newman];

    /// The name a scene spells it with.
    pub fn name(self) -> &'static str {
        match self {
            Self::Off => "Off",
            Self::Mean => "Mean",
            Self::Newman => "Newman",
        }
    }
}

/// The mean drift coefficients `D(ω, β)` [N/m², N·m/m²] at their frequencies and headings, in
/// the layout of [`super::Excitation`], checked once ([`MeanDrift::new`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MeanDrift {
    frequencies: Vec<f64>,
    headings: Vec<f64>,
    values: Vec<Vector6>,
    source: DriftSource,
}

/// The panel code's file the drift coefficients came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DriftSource {
    /// WAMIT `.8`: momentum conservation (far field: surge, sway, yaw).
    Momentum,
    /// WAMIT `.9`: pressure integration over the hull (all six).
    Pressure,
}

impl MeanDrift {
    /// `D` at `frequencies` `ω` [rad/s] (strictly increasing, > 0) and `headings` `β` \[rad]
    /// (strictly increasing; the direction the waves travel to), heading by heading:
    /// `values[h * frequencies.len() + f]`; `source` the file that gave them.
    ///
    /// # Errors
    /// No frequency or heading, either out of order, a count that is not one per frequency and
    /// heading, or a value that is not finite.
    pub fn new(
        frequencies: Vec<f64>,
        headings: Vec<f64>,
        values: Vec<Vector6>,
        source: DriftSource,
    ) -> Result<Self, CoefficientsError> {
        check_frequencies("mean drift", &frequencies)?;
        check_headings("mean drift", &headings)?;
        check_count("mean drift", values.len(), frequencies.len() * headings.len(), " and heading")?;
        check_finite("mean drift", values.iter().map(|d| d.iter().all(|v| v.is_finite())))?;
        Ok(Self { frequencies, headings, values, source })
    }

    /// The frequencies [rad/s].
    pub fn frequencies(&self) -> &[f64] {
        &self.frequencies
    }

    /// The headings \[rad].
    pub fn headings(&self) -> &[f64] {
        &self.headings
    }

    /// Which file gave them (`.8`: momentum conservation, far field; `.9`: pressure integration).
    pub fn source(&self) -> DriftSource {
        self.source
    }

    fn at(&self, heading: usize, frequency: usize) -> Vector6 {
        self.values[heading * self.frequencies.len() + frequency]
    }

    /// `D(ω, β_h)` linear in ω at heading index `heading`; outside the frequencies, the end value.
    fn interpolate(&self, omega: f64, heading: usize) -> Vector6 {
        let bracket = bracket_frequency(&self.frequencies, omega);
        let lower = self.at(heading, bracket.lower);
        if bracket.upper == bracket.lower {
            return lower;
        }
        lower * (1.0 - bracket.fraction) + self.at(heading, bracket.upper) * bracket.fraction
    }

    /// `D(ω, β)`: linear in ω at the bracketing headings, then linear in β.
    ///
    /// # Errors
    /// A heading outside the file's.
    pub fn coefficient(&self, omega: f64, heading: f64) -> Result<Vector6, HeadingMissing> {
        let bracket = bracket_heading(&self.headings, heading, "mean drift")?;
        let lower = self.interpolate(omega, bracket.lower);
        if bracket.upper == bracket.lower {
            return Ok(lower);
        }
        Ok(lower * (1.0 - bracket.fraction) + self.interpolate(omega, bracket.upper) * bracket.fraction)
    }
}

/// One wave component as Newman's envelopes use it, per degree of freedom.
#[derive(Debug, Clone, PartialEq)]
struct Envelope {
    /// `ω_n` [rad/s].
    frequency: f64,
    /// `−k_n e_n·x₀ − φ_n` \[rad].
    phase: f64,
    /// `a_n √|D_i(ω_n)|` per degree of freedom (its square is a force \[N] or moment \[N·m]).
    weight: Vector6,
    /// `s_n a_n √|D_i(ω_n)|`.
    signed: Vector6,
}

/// The drift force of one body in one sea (module docs), built once per sea.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WaveDrift {
    /// `Σ a_n² D(ω_n, β_n)` [N, N·m]: the mean, and the whole force of the `Mean` model.
    mean: Vector6,
    /// The components of the `Newman` model; empty for `Mean` and `Off`.
    envelopes: Vec<Envelope>,
    /// The degrees of freedom with a drift (a `.8` gives surge, sway and yaw): the others are
    /// not summed.
    dofs: Vec<usize>,
}

impl WaveDrift {
    /// The drift of `model` from `drift` in the sea of `components`, at the mean horizontal
    /// position `x0` \[m] of the body's reference point. Nothing for [`DriftModel::Off`].
    ///
    /// # Errors
    /// A component's heading outside the file's headings.
    pub fn new(
        model: DriftModel,
        drift: &MeanDrift,
        components: &[WaveComponent],
        x0: [f64; 2],
    ) -> Result<Self, HeadingMissing> {
        if model == DriftModel::Off {
            return Ok(Self::default());
        }
        let mut mean = Vector6::zeros();
        let mut envelopes = Vec::with_capacity(components.len());
        for wave in components {
            let d = drift.coefficient(wave.frequency, wave.heading)?;
            mean += d * wave.amplitude.powi(2);
            let along = x0[0] * wave.heading.cos() + x0[1] * wave.heading.sin();
            let weight = d.map(|v| wave.amplitude * v.abs().sqrt());
            let signed = weight.zip_map(&d, |w, v| w * v.signum());
            envelopes.push(Envelope {
                frequency: wave.frequency,
                phase: -wave.wave_number * along - wave.phase,
                weight,
                signed,
            });
        }
        if model == DriftModel::Mean {
            envelopes.clear();
        }
        let dofs = (0..6).filter(|&dof| envelopes.iter().any(|e| e.weight[dof] != 0.0)).collect();
        Ok(Self { mean, envelopes, dofs })
    }

    /// Whether the drift is zero at every time (the `Off` model, or no waves).
    pub fn is_zero(&self) -> bool {
        self.envelopes.is_empty() && self.mean == Vector6::zeros()
    }

    /// `Σ a_n² D(ω_n, β_n)` [N, N·m]: the mean drift.
    pub fn mean(&self) -> &Vector6 {
        &self.mean
    }

    /// The drift force at the reference point at time `time` \[s], before the ramp [N, N·m].
    pub fn force(&self, time: f64) -> Vector6 {
        if self.envelopes.is_empty() {
            return self.mean;
        }
        let mut z = [Complex::<f64>::ZERO; 6];
        let mut z_signed = [Complex::<f64>::ZERO; 6];
        for envelope in &self.envelopes {
            let turn = Complex::from_polar(1.0, envelope.frequency * time + envelope.phase);
            for &dof in &self.dofs {
                z[dof] += turn * envelope.weight[dof];
                z_signed[dof] += turn * envelope.signed[dof];
            }
        }
        Vector6::from_fn(|dof, _| (z_signed[dof] * z[dof].conj()).re)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn drift() -> MeanDrift {
        let d = |surge: f64, yaw: f64| Vector6::new(surge, 0.0, 0.0, 0.0, 0.0, yaw);
        let values = vec![d(100.0, -5.0), d(300.0, 5.0), d(500.0, 20.0)];
        MeanDrift::new(vec![0.5, 1.0, 1.5], vec![0.0], values, DriftSource::Momentum).expect("valid")
    }

    /// The table is checked as the excitation is: its headings, its count, its numbers.
    #[test]
    fn bad_tables_are_refused() {
        let table = |values: Vec<Vector6>| MeanDrift::new(vec![0.5, 1.0], vec![0.0], values, DriftSource::Pressure);
        assert!(table(vec![Vector6::repeat(1.0); 2]).is_ok());
        let error = table(vec![Vector6::repeat(1.0); 3]).expect_err("three values for two frequencies");
        assert_eq!(error.to_string(), "mean drift: 3 values given for 2 (one per frequency and heading)");
        let error = table(vec![Vector6::repeat(1.0), Vector6::repeat(f64::INFINITY)]).expect_err("inf");
        assert_eq!(error.to_string(), "mean drift at index 1 is not finite");
        let error = MeanDrift::new(vec![1.0, 0.5], vec![0.0], vec![Vector6::zeros(); 2], DriftSource::Pressure)
            .expect_err("decreasing");
        assert!(error.to_string().starts_with("mean drift: frequencies must increase strictly"), "{error}");
    }

    fn wave(amplitude: f64, frequency: f64, phase: f64) -> WaveComponent {
        WaveComponent { amplitude, frequency, wave_number: frequency * frequency / 9.81, heading: 0.0, phase }
    }

    /// A regular wave: both models give the constant `a² D(ω)`, interpolated in ω.
    #[test]
    fn a_regular_wave_gives_the_constant_a_squared_d() {
        let sea = [wave(1.5, 0.75, 0.4)];
        for model in [DriftModel::Mean, DriftModel::Newman] {
            let force = WaveDrift::new(model, &drift(), &sea, [3.0, 1.0]).expect("heading 0");
            for t in [0.0, 1.3, 17.0] {
                let f = force.force(t);
                assert!((f[0] - 2.25 * 200.0).abs() < 1e-9, "{model:?}: {f}");
                assert!(f[5].abs() < 1e-9, "{model:?}: yaw {}", f[5]);
            }
        }
    }

    /// Two components: Newman's force is the double sum `Σ_mn a_m a_n s_m √|D_m D_n|
    /// cos(θ_m − θ_n)`, whose time average is the mean `Σ a_n² D_n`; one of the signs negative.
    #[test]
    fn two_components_give_the_difference_frequency_double_sum() {
        let sea = [wave(1.0, 0.6, 0.2), wave(0.5, 1.4, -1.1)];
        let force = WaveDrift::new(DriftModel::Newman, &drift(), &sea, [0.0, 0.0]).expect("heading 0");
        let d: Vec<Vector6> = sea.iter().map(|w| drift().coefficient(w.frequency, 0.0).expect("in")).collect();
        let theta = |w: &WaveComponent, t: f64| w.frequency * t - w.phase;
        for t in [0.0, 2.0, 9.5] {
            for dof in [0, 5] {
                let mut expected = 0.0;
                for (m, wm) in sea.iter().enumerate() {
                    for (n, wn) in sea.iter().enumerate() {
                        let t_mn = d[m][dof].signum() * (d[m][dof] * d[n][dof]).abs().sqrt();
                        expected += wm.amplitude * wn.amplitude * t_mn * (theta(wm, t) - theta(wn, t)).cos();
                    }
                }
                let got = force.force(t)[dof];
                assert!(
                    (got - expected).abs() < 1e-9 * expected.abs().max(1.0),
                    "dof {dof} t {t}: {got} vs {expected}"
                );
            }
        }
        // The mean over the beat period 2π/(ω₂ − ω₁).
        let period = 2.0 * PI / 0.8;
        let samples = 4000;
        let average =
            (0..samples).map(|i| force.force(period * i as f64 / samples as f64)[0]).sum::<f64>() / samples as f64;
        let mean = 1.0 * d[0][0] + 0.25 * d[1][0];
        assert!((average - mean).abs() < 1e-9 * mean, "{average} vs {mean}");
        assert!((force.mean()[0] - mean).abs() < 1e-12 * mean);
    }

    #[test]
    fn off_is_zero_and_a_missing_heading_is_refused() {
        let sea = [wave(1.0, 1.0, 0.0)];
        assert!(WaveDrift::new(DriftModel::Off, &drift(), &sea, [0.0; 2]).expect("off").is_zero());
        let turned = [WaveComponent { heading: 0.5, ..sea[0] }];
        let error = WaveDrift::new(DriftModel::Mean, &drift(), &turned, [0.0; 2]).expect_err("outside");
        assert!(error.to_string().contains("mean drift covers headings 0.000° to 0.000°"), "{error}");
    }
}
