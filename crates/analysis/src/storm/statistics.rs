//! A storm's statistics (docs/design-loads.md): per line its largest tension and per body its
//! largest offset in each seed that ran to its end, fitted with a Gumbel distribution by moments
//! and by maximum likelihood; the design value is the maximum-likelihood fit's most probable
//! maximum (the mode, `μ`), beside its 90 % quantile and the largest seed.
//!
//! The design check of a line with a minimum breaking load (MBL, the scene's `breaking_load`):
//! - API RP 2SK (3rd ed., intact, dynamic analysis): the safety factor `MBL / T_MPM` ≥ 1.67;
//! - DNV-OS-E301 (ULS): the design tension `T_d = γ_mean T_mean + γ_dyn (T_MPM − T_mean)`
//!   (`T_mean` the seeds' mean tension) against the capacity `S_C = 0.95 MBL`, with
//!   `γ_mean, γ_dyn` = 1.10, 1.50 in consequence class 1 and 1.40, 2.10 in class 2: the
//!   utilisation `T_d / S_C` ≤ 1.

use super::StormError;
use super::extremes::Gumbel;
use super::spec;
use crate::sweep::case::Status;
use crate::sweep::table::{Columns, Row};

/// The code of practice a line is checked by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Code {
    /// API RP 2SK, intact, dynamic analysis.
    ApiRp2sk,
    /// DNV-OS-E301 ULS, consequence class 1 or 2.
    DnvOsE301 { class: u8 },
}

impl Code {
    /// `API RP 2SK (intact, dynamic: MBL/T ≥ 1.67)`.
    pub fn describe(self) -> String {
        match self {
            Self::ApiRp2sk => "API RP 2SK, intact, dynamic analysis: MBL / T_MPM ≥ 1.67".into(),
            Self::DnvOsE301 { class } => {
                let (mean, dynamic) = dnv_factors(class);
                format!(
                    "DNV-OS-E301 ULS, consequence class {class}: ({mean} T_mean + {dynamic} (T_MPM − T_mean)) / (0.95 MBL) ≤ 1"
                )
            }
        }
    }
}

/// DNV-OS-E301's partial safety factors `(γ_mean, γ_dyn)` of consequence class `class`.
fn dnv_factors(class: u8) -> (f64, f64) {
    if class >= 2 { (1.40, 2.10) } else { (1.10, 1.50) }
}

/// API RP 2SK's intact safety factor with a dynamic analysis.
pub const API_SAFETY_FACTOR: f64 = 1.67;

/// What is measured: a line's tension \[N] or a body's offset \[m].
#[derive(Debug, Clone, PartialEq)]
pub enum Measured {
    Tension { line: String, breaking_load: Option<f64> },
    Offset { body: String },
}

impl Measured {
    /// The line or body measured.
    pub fn subject(&self) -> &str {
        match self {
            Self::Tension { line, .. } => line,
            Self::Offset { body } => body,
        }
    }

    /// `tension` or `offset`.
    pub fn quantity(&self) -> &'static str {
        match self {
            Self::Tension { .. } => "tension",
            Self::Offset { .. } => "offset",
        }
    }

    /// Its SI unit.
    pub fn unit(&self) -> &'static str {
        match self {
            Self::Tension { .. } => "N",
            Self::Offset { .. } => "m",
        }
    }

    /// `mooring1 tension [N]`, `buoy offset [m]`.
    pub fn label(&self) -> String {
        format!("{} {} [{}]", self.subject(), self.quantity(), self.unit())
    }

    /// `mooring1.tension`, the name the tables and the Parquet file give it.
    pub fn name(&self) -> String {
        format!("{}.{}", self.subject(), self.quantity())
    }
}

/// A line's design check: the code, its figure (safety factor or utilisation) and whether it
/// passes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DesignCheck {
    pub code: Code,
    /// API: the safety factor `MBL / T_MPM`; DNV: the utilisation `T_d / S_C`.
    pub figure: f64,
    pub passes: bool,
}

/// One quantity's storm statistics.
#[derive(Debug, Clone, PartialEq)]
pub struct QuantityStatistics {
    pub measured: Measured,
    /// The seeds that ran to their end, and each one's maximum.
    pub seeds: Vec<f64>,
    pub maxima: Vec<f64>,
    pub moments: Gumbel,
    pub likelihood: Gumbel,
    /// The maximum-likelihood fit's mode: the design value.
    pub most_probable_maximum: f64,
    /// Its 90 % quantile.
    pub quantile_90: f64,
    /// The mean over the seeds of the quantity's mean (a line's mean tension), when measured.
    pub mean: Option<f64>,
    pub check: Option<DesignCheck>,
}

/// The statistics of every quantity in `measured` from `rows` (of a storm with `columns`), the
/// lines checked by `code`.
///
/// # Errors
/// Fewer than two seeds that ran to their end, or maxima no Gumbel fits (all equal).
pub fn compute(
    measured: &[Measured],
    columns: &Columns,
    rows: &[Row],
    code: Code,
) -> Result<Vec<QuantityStatistics>, StormError> {
    let finished: Vec<&Row> = rows.iter().filter(|r| r.ending.status == Status::Ok).collect();
    measured.iter().map(|m| quantity(m, columns, &finished, code)).collect()
}

fn quantity(
    measured: &Measured,
    columns: &Columns,
    rows: &[&Row],
    code: Code,
) -> Result<QuantityStatistics, StormError> {
    let (column, mean_column) = match measured {
        Measured::Tension { line, .. } => (spec::tension_max(line), Some(spec::tension_mean(line))),
        Measured::Offset { body } => (spec::offset_max(body), None),
    };
    let values = |name: &str| -> Vec<f64> {
        let Some(index) = columns.metric(name) else { return Vec::new() };
        rows.iter().filter_map(|row| row.metrics[index]).collect()
    };
    let maxima = values(&column);
    let seeds: Vec<f64> = rows
        .iter()
        .filter_map(|row| match row.values.first() {
            Some(crate::sweep::spec::Level::Number(seed)) => Some(*seed),
            _ => None,
        })
        .collect();
    let fit = |source| StormError::Fit { quantity: measured.label(), source };
    let moments = Gumbel::by_moments(&maxima).map_err(fit)?;
    let likelihood = Gumbel::by_maximum_likelihood(&maxima).map_err(fit)?;
    let most_probable_maximum = likelihood.most_probable_maximum();
    let means = mean_column.map(|name| values(&name));
    let mean = means.filter(|m| !m.is_empty()).map(|m| m.iter().sum::<f64>() / m.len() as f64);
    let check = match (measured, mean) {
        (Measured::Tension { breaking_load: Some(mbl), .. }, Some(mean)) => {
            Some(design_check(code, *mbl, most_probable_maximum, mean))
        }
        (Measured::Tension { .. } | Measured::Offset { .. }, _) => None,
    };
    Ok(QuantityStatistics {
        measured: measured.clone(),
        seeds,
        maxima,
        moments,
        likelihood,
        most_probable_maximum,
        quantile_90: likelihood.quantile(0.9),
        mean,
        check,
    })
}

/// The code's check of a line of breaking load `mbl` \[N] whose MPM and mean tension are
/// `mpm`, `mean` \[N] (module docs).
pub fn design_check(code: Code, mbl: f64, mpm: f64, mean: f64) -> DesignCheck {
    match code {
        Code::ApiRp2sk => {
            let figure = mbl / mpm;
            DesignCheck { code, figure, passes: figure >= API_SAFETY_FACTOR }
        }
        Code::DnvOsE301 { class } => {
            let (gamma_mean, gamma_dynamic) = dnv_factors(class);
            let design = gamma_mean * mean + gamma_dynamic * (mpm - mean);
            let figure = design / (0.95 * mbl);
            DesignCheck { code, figure, passes: figure <= 1.0 }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// API: 1.67 × T passes at the limit; DNV class 1: T_d = 1.1 × 600 + 1.5 × 400 = 1260 kN
    /// against 0.95 × 1500 kN.
    #[test]
    fn the_codes_checks_are_their_formulas() {
        let api = design_check(Code::ApiRp2sk, 1.67e6, 1.0e6, 6.0e5);
        assert!((api.figure - 1.67).abs() < 1e-12 && api.passes);
        let dnv = design_check(Code::DnvOsE301 { class: 1 }, 1.5e6, 1.0e6, 6.0e5);
        assert!((dnv.figure - 1.26e6 / 1.425e6).abs() < 1e-12 && dnv.passes, "{dnv:?}");
        let class2 = design_check(Code::DnvOsE301 { class: 2 }, 1.5e6, 1.0e6, 6.0e5);
        assert!((class2.figure - (1.4 * 6e5 + 2.1 * 4e5) / 1.425e6).abs() < 1e-12 && !class2.passes);
    }
}
