//! One measured signal as a fit reads it: named (time, value) samples, whatever file they came
//! from ([`super::measured`]: CSV, Parquet; [`super::recording_input`]: a recording).

/// One measured signal.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    /// Sample times \[s], increasing.
    pub times: Vec<f64>,
    pub values: Vec<f64>,
}
