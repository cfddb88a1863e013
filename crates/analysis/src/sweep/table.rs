//! The results table: one row per case — its number, every factor's value, how it ended, what
//! it cost and every metric — as CSV (each run's own file, and `results.csv`) and, through
//! [`super::parquet`], Parquet.
//!
//! Numbers are written in their shortest form that reads back to the same `f64` (Rust's
//! formatting, exact both ways), so a row read back from a run file is the row that was
//! written, bit for bit. A metric a failed case has no value for is an empty cell (a null in
//! Parquet); NaN is never written.

use super::case::{Ending, Outcome, Status};
use super::spec::{Level, LevelKind};
use serde::{Deserialize, Serialize};

/// Columns between the factors and the metrics.
pub const OUTCOME_COLUMNS: [&str; 6] = ["status", "message", "end_time_s", "steps", "rejected_steps", "cpu_s"];

/// The first column.
pub const CASE_COLUMN: &str = "case";

/// The columns of a sweep's results.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Columns {
    pub factors: Vec<FactorColumn>,
    pub metrics: Vec<MetricColumn>,
}

/// A factor's column.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct FactorColumn {
    pub name: String,
    pub kind: LevelKind,
    /// Its values are spread in logarithm (plots use a log axis).
    pub log: bool,
}

/// A metric's column.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MetricColumn {
    pub name: String,
    pub unit: String,
}

/// One case's results: its number, its values, how it ended, and each metric's value (a cell
/// read back may be empty on its own, where the [`Outcome`] has all of them or none).
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub case: usize,
    pub values: Vec<Level>,
    pub ending: Ending,
    pub metrics: Vec<Option<f64>>,
}

impl Row {
    /// The row of case `case`, which took `values` and gave `outcome`.
    pub fn new(case: usize, values: Vec<Level>, outcome: Outcome, metric_count: usize) -> Self {
        let metrics =
            outcome.metrics.map_or_else(|| vec![None; metric_count], |values| values.into_iter().map(Some).collect());
        Self { case, values, ending: outcome.ending, metrics }
    }
}

impl Columns {
    /// The header row.
    pub fn header(&self) -> Vec<String> {
        let mut header = vec![CASE_COLUMN.to_string()];
        header.extend(self.factors.iter().map(|f| f.name.clone()));
        header.extend(OUTCOME_COLUMNS.iter().map(ToString::to_string));
        header.extend(self.metrics.iter().map(|m| m.name.clone()));
        header
    }

    /// `row` as CSV fields.
    pub fn record(&self, row: &Row) -> Vec<String> {
        let mut fields = vec![row.case.to_string()];
        fields.extend(row.values.iter().map(ToString::to_string));
        fields.extend([
            row.ending.status.name().to_string(),
            row.ending.message.clone(),
            number(row.ending.end_time),
            row.ending.steps.to_string(),
            row.ending.rejected_steps.to_string(),
            number(row.ending.cpu_seconds),
        ]);
        fields.extend(row.metrics.iter().map(|m| m.map(number).unwrap_or_default()));
        fields
    }

    /// The row in CSV fields `record`.
    ///
    /// # Errors
    /// A field that does not read as its column's type, named.
    pub fn parse(&self, record: &csv::StringRecord) -> Result<Row, String> {
        let expected = 1 + self.factors.len() + OUTCOME_COLUMNS.len() + self.metrics.len();
        if record.len() != expected {
            return Err(format!("{} fields where the sweep has {expected} columns", record.len()));
        }
        let field = |i: usize| &record[i];
        let real = |i: usize, name: &str| {
            field(i).parse::<f64>().map_err(|_| format!("{name} `{}` is not a number", field(i)))
        };
        let whole = |i: usize, name: &str| {
            field(i).parse::<u64>().map_err(|_| format!("{name} `{}` is not a whole number", field(i)))
        };
        let case = whole(0, CASE_COLUMN)? as usize;
        let mut values = Vec::with_capacity(self.factors.len());
        for (k, factor) in self.factors.iter().enumerate() {
            let text = field(1 + k);
            values.push(match factor.kind {
                LevelKind::Number => Level::Number(real(1 + k, &factor.name)?),
                LevelKind::Flag => {
                    Level::Flag(text.parse().map_err(|_| format!("{} `{text}` is not true or false", factor.name))?)
                }
                LevelKind::Text => Level::Text(text.to_string()),
            });
        }
        let at = 1 + self.factors.len();
        let status = Status::from_name(field(at))
            .ok_or_else(|| format!("status `{}` is not one of ok, diverged, refused, timed_out", field(at)))?;
        let mut metrics = Vec::with_capacity(self.metrics.len());
        for (k, metric) in self.metrics.iter().enumerate() {
            let i = at + OUTCOME_COLUMNS.len() + k;
            metrics.push(if field(i).is_empty() { None } else { Some(real(i, &metric.name)?) });
        }
        let ending = Ending {
            status,
            message: field(at + 1).to_string(),
            end_time: real(at + 2, "end_time_s")?,
            steps: whole(at + 3, "steps")?,
            rejected_steps: whole(at + 4, "rejected_steps")?,
            cpu_seconds: real(at + 5, "cpu_s")?,
        };
        Ok(Row { case, values, ending, metrics })
    }

    /// The index of the metric `name`.
    pub fn metric(&self, name: &str) -> Option<usize> {
        self.metrics.iter().position(|m| m.name == name)
    }
}

/// A level as the results table writes it (and every message names it).
impl std::fmt::Display for Level {
    /// Numbers in their shortest form that reads back to the same `f64`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Number(x) => f.write_str(&number(*x)),
            Self::Flag(flag) => write!(f, "{flag}"),
            Self::Text(text) => f.write_str(text),
        }
    }
}

/// `x` in the shortest form that reads back to the same `f64`: plain between 1e-4 and 1e15,
/// with an exponent outside (so 1e-12 is not written with twelve zeros).
pub fn number(x: f64) -> String {
    let magnitude = x.abs();
    if x == 0.0 || (1e-4..1e15).contains(&magnitude) { format!("{x}") } else { format!("{x:e}") }
}

/// `x` for people, in at most four significant digits: `0.25`, `1500`, `3.2e6`, `1e-9`.
pub fn compact(value: f64) -> String {
    if value == 0.0 {
        return "0".into();
    }
    if (1e-3..1e5).contains(&value.abs()) {
        let decimals = (3 - value.abs().log10().floor() as i32).max(0) as usize;
        let text = format!("{value:.decimals$}");
        let text = if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.') } else { &text };
        return text.to_string();
    }
    let text = format!("{value:.3e}");
    match text.split_once('e') {
        Some((mantissa, exponent)) => {
            let mantissa =
                if mantissa.contains('.') { mantissa.trim_end_matches('0').trim_end_matches('.') } else { mantissa };
            format!("{mantissa}e{exponent}")
        }
        None => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every f64 written reads back bit for bit; the row survives CSV both ways.
    #[test]
    fn numbers_and_rows_read_back_exactly() {
        for x in
            [0.1 + 0.2, 1e-12, 6.02214076e23, -3.5e-310, 1.0 / 3.0, 123456.789, 5e6, -0.0, f64::MAX, f64::MIN_POSITIVE]
        {
            let text = number(x);
            assert_eq!(text.parse::<f64>().unwrap().to_bits(), x.to_bits(), "{x:e} written as {text}");
        }
        assert_eq!((number(5e6), number(1e-12), number(0.25)), ("5000000".into(), "1e-12".into(), "0.25".into()));
        let people: Vec<String> = [0.25, 1500.0, 1778279.410038924, -1e-9, 12.34567, 0.0].map(compact).into();
        assert_eq!(people, ["0.25", "1500", "1.778e6", "-1e-9", "12.35", "0"]);
        let columns = Columns {
            factors: vec![
                FactorColumn { name: "k".into(), kind: LevelKind::Number, log: true },
                FactorColumn { name: "integrator".into(), kind: LevelKind::Text, log: false },
            ],
            metrics: vec![
                MetricColumn { name: "m".into(), unit: "N".into() },
                MetricColumn { name: "e".into(), unit: "–".into() },
            ],
        };
        let row = Row {
            case: 17,
            values: vec![Level::Number(1.0 / 3.0), Level::Text("rk4".into())],
            ending: Ending {
                status: Status::Diverged,
                message: "the simulation diverged at t = 1 s: body \"a, b\" spins".into(),
                end_time: 1.0,
                steps: 1000,
                rejected_steps: 0,
                cpu_seconds: 0.0123,
            },
            metrics: vec![Some(0.1 + 0.2), None],
        };
        let mut writer = csv::Writer::from_writer(Vec::new());
        writer.write_record(columns.header()).unwrap();
        writer.write_record(columns.record(&row)).unwrap();
        let bytes = writer.into_inner().unwrap();
        let mut reader = csv::Reader::from_reader(bytes.as_slice());
        assert_eq!(
            reader.headers().unwrap().iter().collect::<Vec<_>>(),
            [
                "case",
                "k",
                "integrator",
                "status",
                "message",
                "end_time_s",
                "steps",
                "rejected_steps",
                "cpu_s",
                "m",
                "e"
            ]
        );
        let record = reader.records().next().unwrap().unwrap();
        assert_eq!(columns.parse(&record).unwrap(), row);
    }
}
