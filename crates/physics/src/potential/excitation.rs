//! The first-order wave excitation of a body with potential-flow data (PHYSICS.md §9,
//! "Excitation"): each wave component (amplitude `a`, frequency `ω`, heading `β`, phase `φ`,
//! wave number `k`; §6's `η = a cos(k e·x − ωt + φ)`) loads the body's reference point with
//! `F_exc = Re{c e^{iωt}}`, `c = a e^{−iφ} e^{−i k e·x₀} X(ω, β)` [N, N·m] (WAMIT's convention),
//! `x₀` the reference point's mean horizontal position. `c` is computed once per sea: an
//! evaluation sums `Re{c e^{iωt}}` and the water stage ramps it as it ramps the waves.
//!
//! `X` is interpolated linearly in ω (the end value held outside the file's frequencies) and in
//! β between the file's headings; a sea heading outside them is refused, not replaced by the
//! nearest: an axisymmetric body's file with the single heading 0 serves every sea heading
//! only once rotated, which is the panel code's job.

use super::coefficients::{ComplexVector6, Excitation, Vector6};
pub use super::tables::HeadingMissing;
use super::tables::bracket_heading;
use crate::water::waves::WaveComponent;
use nalgebra::Complex;

/// The excitation of one body in one sea: `(ω, c)` per wave component.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WaveExcitation {
    components: Vec<(f64, ComplexVector6)>,
}

impl WaveExcitation {
    /// `c` of each of `components` for the body's `excitation` at the mean horizontal position
    /// `x0` \[m] of its reference point.
    ///
    /// # Errors
    /// A component's heading outside the file's headings.
    pub fn new(excitation: &Excitation, components: &[WaveComponent], x0: [f64; 2]) -> Result<Self, HeadingMissing> {
        let components = components
            .iter()
            .map(|wave| {
                let x = at_heading(excitation, wave.frequency, wave.heading)?;
                let along = x0[0] * wave.heading.cos() + x0[1] * wave.heading.sin();
                let c = Complex::from_polar(wave.amplitude, -wave.phase - wave.wave_number * along);
                Ok((wave.frequency, x * c))
            })
            .collect::<Result<_, _>>()?;
        Ok(Self { components })
    }

    /// `Σ Re{c e^{iωt}}` at time `time` \[s], before the ramp.
    pub fn force(&self, time: f64) -> Vector6 {
        self.components.iter().fold(Vector6::zeros(), |sum, (omega, c)| {
            let turn = Complex::from_polar(1.0, omega * time);
            sum + c.map(|x| (x * turn).re)
        })
    }
}

/// `X(ω, β)`: linear in ω at the bracketing headings, then linear in β between them.
fn at_heading(excitation: &Excitation, omega: f64, heading: f64) -> Result<ComplexVector6, HeadingMissing> {
    let bracket = bracket_heading(&excitation.headings, heading, "excitation")?;
    let lower = excitation.interpolate(omega, bracket.lower);
    if bracket.upper == bracket.lower {
        return Ok(lower);
    }
    let upper = excitation.interpolate(omega, bracket.upper);
    Ok(lower + (upper - lower) * Complex::from(bracket.fraction))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::TAU;

    fn excitation() -> Excitation {
        let x = |v: f64| ComplexVector6::from_fn(|i, _| if i == 2 { Complex::new(v, -v) } else { Complex::ZERO });
        Excitation {
            frequencies: vec![0.5, 1.5],
            headings: vec![0.0, 0.5],
            values: vec![x(1.0), x(3.0), x(5.0), x(7.0)],
        }
    }

    fn wave(heading: f64) -> WaveComponent {
        WaveComponent { amplitude: 2.0, frequency: 1.0, wave_number: 0.1, heading, phase: 0.3 }
    }

    /// Half way in ω and in β: the mean of the four corners, times `a e^{−iφ} e^{−ik e·x₀}`.
    #[test]
    fn the_force_is_the_interpolated_excitation_times_the_waves_complex_amplitude() {
        let x0 = [3.0, -1.0];
        let excitation = WaveExcitation::new(&excitation(), &[wave(0.25)], x0).expect("inside the headings");
        let along = 3.0 * 0.25_f64.cos() - 0.25_f64.sin();
        let c = Complex::new(4.0, -4.0) * Complex::from_polar(2.0, -0.3 - 0.1 * along);
        let t = 0.7;
        let expected = (c * Complex::from_polar(1.0, t)).re;
        assert!((excitation.force(t)[2] - expected).abs() < 1e-12, "{} vs {expected}", excitation.force(t)[2]);
    }

    #[test]
    fn a_heading_outside_the_file_is_refused_and_one_a_turn_away_is_not() {
        let error = WaveExcitation::new(&excitation(), &[wave(1.0)], [0.0; 2]).expect_err("outside");
        assert!(error.to_string().contains("57.296°"), "{error}");
        assert!(WaveExcitation::new(&excitation(), &[wave(0.5 + TAU)], [0.0; 2]).is_ok());
    }
}
