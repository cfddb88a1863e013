//! Contact parameters from the impact they must stop (PHYSICS.md §4 \[4959]–\[4964]).
//!
//! With `A` the expected contact area \[m²], `v` the normal impact speed [m/s] and `m_e` the
//! effective mass \[kg] (`m1` against the environment, `m1 m2/(m1 + m2)` between bodies), a face
//! set that first pushes at distance `d0` and must stop the impact by `d_min`:
//! - stiffness `k1 = m_e v² / (A (d0 − d_min)²)` [N/m³]: the impact's kinetic energy is stored
//!   over the penetration `d0 − d_min`;
//! - stopping time `τ = (π/2) √(m_e / (A k1))` \[s]: a quarter period of the contact oscillator;
//! - damping `k2 = 2ζ √(m_e k1 / A)` [N·s/m³] for a damping ratio `ζ ≪ 1`.
//!
//! The time step must be well below τ: [`STEPS_PER_STOPPING_TIME`] steps resolve it.

/// Integrator steps per stopping time τ for the recommended time step (the rebound
/// coefficient of a drop is then within about 1 % of the exact one).
pub const STEPS_PER_STOPPING_TIME: f64 = 10.0;

/// What the estimate starts from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impact {
    /// Mass of the body \[kg] > 0.
    pub mass: f64,
    /// Mass of the other body \[kg] > 0, or `None` against the environment.
    pub other_mass: Option<f64>,
    /// `A` \[m²] > 0.
    pub area: f64,
    /// `v` [m/s] > 0.
    pub speed: f64,
    /// `d0` \[m].
    pub range: f64,
    /// `d_min` \[m] < d0.
    pub min_distance: f64,
    /// `ζ` [-] ≥ 0.
    pub damping_ratio: f64,
}

/// The estimated parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEstimate {
    /// `m_e` \[kg].
    pub effective_mass: f64,
    /// `k1` [N/m³].
    pub stiffness: f64,
    /// `k2` [N·s/m³].
    pub damping: f64,
    /// `τ` \[s].
    pub stopping_time: f64,
    /// `τ / STEPS_PER_STOPPING_TIME` \[s].
    pub recommended_dt: f64,
}

/// An impact the estimate cannot be made for.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
pub enum EstimateError {
    #[error("{name} must be a positive number, got {value}")]
    NotPositive { name: &'static str, value: f64 },
    #[error("the damping ratio must be ≥ 0, got {0}")]
    NegativeDamping(f64),
    #[error("d_min = {min_distance} m must be below d0 = {range} m")]
    NoPenetration { range: f64, min_distance: f64 },
}

/// `m1 m2 / (m1 + m2)` \[kg], or `m1` against the environment.
pub fn effective_mass(mass: f64, other_mass: Option<f64>) -> f64 {
    other_mass.map_or(mass, |other| mass * other / (mass + other))
}

/// `τ = (π/2) √(m_e / (A k1))` \[s] for stiffness `k1` [N/m³] over area `A` \[m²].
pub fn stopping_time(effective_mass: f64, area: f64, stiffness: f64) -> f64 {
    std::f64::consts::FRAC_PI_2 * (effective_mass / (area * stiffness)).sqrt()
}

/// Integrator steps per world step `dt` \[s] that keep each under the recommended time step.
pub fn substeps_for(dt: f64, recommended_dt: f64) -> u32 {
    (dt / recommended_dt).ceil().clamp(1.0, f64::from(u32::MAX)) as u32
}

/// k1, k2, τ and the recommended time step for `impact`.
///
/// # Errors
/// A non-positive mass, area or speed, a negative damping ratio, or `d_min ≥ d0`.
pub fn estimate(impact: &Impact) -> Result<ContactEstimate, EstimateError> {
    let positive = |name: &'static str, value: f64| {
        if value > 0.0 && value.is_finite() { Ok(value) } else { Err(EstimateError::NotPositive { name, value }) }
    };
    let mass = positive("mass", impact.mass)?;
    let other_mass = impact.other_mass.map(|m| positive("mass2", m)).transpose()?;
    let area = positive("area", impact.area)?;
    let speed = positive("speed", impact.speed)?;
    if !(impact.damping_ratio >= 0.0 && impact.damping_ratio.is_finite()) {
        return Err(EstimateError::NegativeDamping(impact.damping_ratio));
    }
    let penetration = impact.range - impact.min_distance;
    if !(penetration > 0.0 && penetration.is_finite()) {
        return Err(EstimateError::NoPenetration { range: impact.range, min_distance: impact.min_distance });
    }
    let effective_mass = effective_mass(mass, other_mass);
    let stiffness = effective_mass * speed * speed / (area * penetration * penetration);
    let stopping_time = stopping_time(effective_mass, area, stiffness);
    Ok(ContactEstimate {
        effective_mass,
        stiffness,
        damping: 2.0 * impact.damping_ratio * (effective_mass * stiffness / area).sqrt(),
        stopping_time,
        recommended_dt: stopping_time / STEPS_PER_STOPPING_TIME,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn the_estimate_follows_the_formulas() {
        // 2 kg on 1 kg: m_e = 2/3 kg; A = 0.01 m², v = 3 m/s, d0 − d_min = 0.005 m.
        let impact = Impact {
            mass: 2.0,
            other_mass: Some(1.0),
            area: 0.01,
            speed: 3.0,
            range: 0.004,
            min_distance: -0.001,
            damping_ratio: 0.1,
        };
        let e = estimate(&impact).expect("valid impact");
        let me = 2.0 / 3.0;
        assert_relative_eq!(e.effective_mass, me, epsilon = 1e-15);
        let k1 = me * 9.0 / (0.01 * 0.005 * 0.005);
        assert_relative_eq!(e.stiffness, k1, max_relative = 1e-14);
        assert_relative_eq!(e.damping, 0.2 * (me * k1 / 0.01).sqrt(), max_relative = 1e-14);
        assert_relative_eq!(
            e.stopping_time,
            std::f64::consts::FRAC_PI_2 * (me / (0.01 * k1)).sqrt(),
            max_relative = 1e-14
        );
        // τ = (π/2)(d0 − d_min)/v whatever the masses: the penetration is crossed at ~v.
        assert_relative_eq!(e.stopping_time, std::f64::consts::FRAC_PI_2 * 0.005 / 3.0, max_relative = 1e-14);
        assert_eq!(substeps_for(1e-3, e.recommended_dt), (1e-3 / e.recommended_dt).ceil() as u32);
    }

    #[test]
    fn the_box_drop_of_the_issue_stops_in_4_96729_ms() {
        // m = 1 kg, A·k1 = 1e5 N/m.
        assert_relative_eq!(stopping_time(1.0, 0.01, 1e7), 4.96729e-3, max_relative = 1e-6);
    }

    #[test]
    fn impossible_impacts_are_refused() {
        let good = Impact {
            mass: 1.0,
            other_mass: None,
            area: 0.01,
            speed: 1.0,
            range: 0.01,
            min_distance: 0.0,
            damping_ratio: 0.1,
        };
        assert!(estimate(&good).is_ok());
        assert_eq!(
            estimate(&Impact { mass: 0.0, ..good }),
            Err(EstimateError::NotPositive { name: "mass", value: 0.0 })
        );
        assert!(matches!(
            estimate(&Impact { other_mass: Some(-1.0), ..good }),
            Err(EstimateError::NotPositive { name: "mass2", .. })
        ));
        assert!(matches!(estimate(&Impact { min_distance: 0.01, ..good }), Err(EstimateError::NoPenetration { .. })));
        assert!(matches!(estimate(&Impact { damping_ratio: -0.1, ..good }), Err(EstimateError::NegativeDamping(_))));
        assert!(matches!(
            estimate(&Impact { speed: f64::NAN, ..good }),
            Err(EstimateError::NotPositive { name: "speed", .. })
        ));
    }
}
