//! The linear dispersion relation of surface gravity waves (PHYSICS.md §6, Airy waves):
//! `ω² = g k tanh(k h)` [1/s²], deep water `k = ω²/g` [rad/m].

/// Wave number `k` [rad/m] of frequency `omega` [rad/s] in water of depth `depth` \[m] (`None`:
/// deep) under gravity `gravity` [m/s²].
///
/// Newton's method on `f(k) = g k tanh(k h) − ω²`, which is increasing and concave in `k`:
/// started above the root (from the deep-water value divided by `√tanh(ω² h/g)`, Eckart's
/// estimate, which is never below it) it descends monotonically, and stops when a step no
/// longer changes `k` beyond round-off (a few iterations).
pub fn wave_number(omega: f64, depth: Option<f64>, gravity: f64) -> f64 {
    let deep = omega * omega / gravity;
    let Some(h) = depth else { return deep };
    let mut k = deep / (deep * h).tanh().sqrt();
    for _ in 0..100 {
        let t = (k * h).tanh();
        let f = gravity * k * t - omega * omega;
        let slope = gravity * (t + k * h * (1.0 - t * t));
        let next = k - f / slope;
        if !(next > 0.0) || (next - k).abs() <= 4.0 * f64::EPSILON * k {
            return if next > 0.0 { next } else { k };
        }
        k = next;
    }
    k
}

/// Wavelength `λ = 2π/k` \[m] of period `period` \[s].
pub fn wavelength(period: f64, depth: Option<f64>, gravity: f64) -> f64 {
    std::f64::consts::TAU / wave_number(std::f64::consts::TAU / period, depth, gravity)
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    const G: f64 = 9.80665;

    #[test]
    fn wavelengths_of_a_ten_second_wave_deep_and_twenty_metres_deep() {
        // PHYSICS.md §6: 156.078 m deep, 121.210 m at h = 20 m (both quoted to six figures).
        assert_relative_eq!(wavelength(10.0, None, G), G * 100.0 / std::f64::consts::TAU, max_relative = 1e-15);
        assert!((wavelength(10.0, None, G) - 156.078).abs() < 5e-4);
        assert!((wavelength(10.0, Some(20.0), G) - 121.210).abs() < 5e-4);
    }

    #[test]
    fn the_root_satisfies_the_relation_from_shallow_to_deep() {
        for h in [0.1, 1.0, 20.0, 1e3, 1e5] {
            for omega in [0.05, 0.5, 2.0, 10.0] {
                let k = wave_number(omega, Some(h), G);
                assert_relative_eq!(G * k * (k * h).tanh(), omega * omega, max_relative = 1e-13);
            }
        }
    }
}
