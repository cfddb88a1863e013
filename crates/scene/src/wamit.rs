//! WAMIT's output files read into a body's potential-flow data (PHYSICS.md §9, "WAMIT files"):
//! `STEM.1` (added mass and damping), `STEM.3` (excitation) and, when they exist, `STEM.hst`
//! (linear hydrostatic stiffness) and the mean drift coefficients of `STEM.8` (momentum
//! conservation, far field), or of `STEM.9` (pressure integration) when there is no `.8`
//! (PHYSICS.md §10), dimensional with the scene's water density ρ, gravity g and
//! the file's length scale L, in WAMIT's time convention (Capytaine 3.0's export writes it).
//!
//! Every problem is one line naming the file, and the line and column where there is one; the
//! values are checked by [`Coefficients::new`], whose refusal is placed here (a file with the
//! ω = 0 and ω = ∞ blocks swapped, as Capytaine wrote them before 3.0, at its first ω = ∞ row).
//!
//! | file | row | scaled |
//! |---|---|---|
//! | `.1` | `PER I J Ā [B̄]` (PER = −1: ω = 0, PER = 0: ω = ∞, no `B̄`) | `A = Ā ρ L^k`, `B = B̄ ρ ω L^k` |
//! | `.3` | `PER β I \|X̄\| phase Re Im` (β, phase in degrees) | `X = (Re + i Im) ρ g L^m` |
//! | `.hst` | `I J C̄` | `C = C̄ ρ g L^k` |
//! | `.8`, `.9` | `PER β₁ β₂ I \|F̄\| phase Re Im` (or `PER β I …`, 7 columns) | `D = Re ρ g L^d` |
//!
//! `k = 3, 4, 5` for translation–translation, mixed and rotation–rotation pairs (`.hst`: 2, 3,
//! 4); `m = 2` for a force, 3 for a moment; `d = 1` for a force, 2 for a moment (the drift is per
//! unit wave amplitude squared). Pairs a file leaves out are 0. Of the drift, the rows of a
//! unidirectional sea (`β₁ = β₂`) are read; the bidirectional pairs of a spread sea are not used.

use nalgebra::Complex;
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use tether_physics::potential::coefficients::CoefficientsError;
use tether_physics::potential::{
    Coefficients, CoefficientsData, ComplexVector6, DriftSource, Excitation, Matrix6, MeanDrift, Vector6,
};

/// The scale the files' non-dimensional numbers are multiplied by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scale {
    /// Water density ρ \[kg/m³].
    pub density: f64,
    /// Gravity g \[m/s²].
    pub gravity: f64,
    /// WAMIT's length scale L \[m] (Capytaine writes 1).
    pub length: f64,
}

/// A WAMIT file that could not be read: `path:line:col: message`, or `path: message` for the
/// file as a whole.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path}{}: {message}", place(*line, *col))]
pub struct WamitError {
    pub path: String,
    /// 1-based line, when the problem is on one.
    pub line: Option<usize>,
    /// 1-based column (in characters), when the problem is in one field.
    pub col: Option<usize>,
    pub message: String,
}

fn place(line: Option<usize>, col: Option<usize>) -> String {
    match (line, col) {
        (Some(line), Some(col)) => format!(":{line}:{col}"),
        (Some(line), None) => format!(":{line}"),
        (None, _) => String::new(),
    }
}

/// Reads `STEM.1`, `STEM.3` and, if present, `STEM.hst` and `STEM.8` (else `STEM.9`) (`stem`
/// is the path without the extension).
///
/// # Errors
/// The first problem met, as one line with the file, and its line and column where it has them.
pub fn read(stem: &Path, scale: Scale) -> Result<Coefficients, WamitError> {
    let radiation_path = with_extension(stem, "1");
    let radiation = parse_radiation(&Text::read(&radiation_path)?, scale)?;
    let excitation = parse_excitation(&Text::read(&with_extension(stem, "3"))?, scale)?;
    let hst_path = with_extension(stem, "hst");
    let hydrostatic_stiffness =
        if hst_path.exists() { Some(parse_hydrostatics(&Text::read(&hst_path)?, scale)?) } else { None };
    let mean_drift = read_mean_drift(stem, scale)?;
    let infinite_line = radiation.infinite_line;
    Coefficients::new(CoefficientsData {
        frequencies: radiation.frequencies,
        added_mass: radiation.added_mass,
        damping: radiation.damping,
        added_mass_infinite: radiation.infinite,
        added_mass_zero: radiation.zero,
        excitation,
        hydrostatic_stiffness,
        mean_drift,
    })
    .map_err(|e| {
        let line = matches!(e, CoefficientsError::SwappedLimits { .. }).then_some(infinite_line);
        WamitError { path: radiation_path.display().to_string(), line, col: None, message: e.to_string() }
    })
}

/// The drift file read: `STEM.8` when it exists, else `STEM.9`.
fn drift_path(stem: &Path) -> PathBuf {
    let momentum = with_extension(stem, "8");
    if momentum.exists() { momentum } else { with_extension(stem, "9") }
}

/// `STEM.8`, or `STEM.9` without it, as mean drift coefficients; `None` with neither.
fn read_mean_drift(stem: &Path, scale: Scale) -> Result<Option<MeanDrift>, WamitError> {
    let path = drift_path(stem);
    if !path.exists() {
        return Ok(None);
    }
    let source = if path.extension().is_some_and(|e| e == "8") { DriftSource::Momentum } else { DriftSource::Pressure };
    parse_mean_drift(&Text::read(&path)?, scale, source).map(Some)
}

/// `stem` with `.extension` appended (a stem may itself hold dots: `hydro/buoy.v2`).
fn with_extension(stem: &Path, extension: &str) -> PathBuf {
    let mut name = stem.as_os_str().to_os_string();
    name.push(".");
    name.push(extension);
    PathBuf::from(name)
}

/// A file's text and its path, to place errors.
struct Text {
    path: String,
    text: String,
}

/// One field of a row: its text and its 1-based column.
#[derive(Clone, Copy)]
struct Field<'a> {
    text: &'a str,
    col: usize,
}

/// A row of a file: its 1-based line number and its whitespace-separated fields.
struct Row<'a> {
    line: usize,
    fields: Vec<Field<'a>>,
}

impl Text {
    fn read(path: &Path) -> Result<Self, WamitError> {
        let shown = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| WamitError {
            path: shown.clone(),
            line: None,
            col: None,
            message: format!("cannot read WAMIT file: {e}"),
        })?;
        Ok(Self { path: shown, text })
    }

    /// The non-blank rows, each of `columns` fields (or of one of the counts `columns` allows).
    fn rows(&self, columns: &[usize], layout: &str) -> Result<Vec<Row<'_>>, WamitError> {
        let mut rows = Vec::new();
        for (index, line) in self.text.lines().enumerate() {
            let fields = fields(line);
            if fields.is_empty() {
                continue;
            }
            if !columns.contains(&fields.len()) {
                return Err(self.error(
                    index + 1,
                    None,
                    format!("expected {layout}, found {} column(s) (a truncated or foreign file?)", fields.len()),
                ));
            }
            rows.push(Row { line: index + 1, fields });
        }
        if rows.is_empty() {
            return Err(WamitError {
                path: self.path.clone(),
                line: None,
                col: None,
                message: "the file is empty".into(),
            });
        }
        Ok(rows)
    }

    fn error(&self, line: usize, col: Option<usize>, message: String) -> WamitError {
        WamitError { path: self.path.clone(), line: Some(line), col, message }
    }

    /// A finite number.
    fn number(&self, row: &Row<'_>, at: usize, what: &str) -> Result<f64, WamitError> {
        let field = row.fields[at];
        match field.text.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            _ => Err(self.error(
                row.line,
                Some(field.col),
                format!("{what} must be a finite number, got {:?}", field.text),
            )),
        }
    }

    /// A degree-of-freedom index 1–6, 0-based; an index above 6 is a coupled multi-body file.
    fn dof(&self, row: &Row<'_>, at: usize) -> Result<usize, WamitError> {
        let field = row.fields[at];
        let refuse = |message: String| Err(self.error(row.line, Some(field.col), message));
        match field.text.parse::<usize>() {
            Ok(index @ 1..=6) => Ok(index - 1),
            Ok(index) if index > 6 => refuse(format!(
                "dof index {index} > 6: a coupled multi-body file (12 × 12 or more); Tether reads one body per \
                 file for now — export each body on its own"
            )),
            _ => refuse(format!("dof index must be an integer from 1 to 6, got {:?}", field.text)),
        }
    }

    /// A period: `Period::Zero` (−1), `Period::Infinite` (0) or a finite one (> 0) \[s].
    fn period(&self, row: &Row<'_>) -> Result<Period, WamitError> {
        let value = self.number(row, 0, "the period PER")?;
        if value == -1.0 {
            Ok(Period::Zero)
        } else if value == 0.0 {
            Ok(Period::Infinite)
        } else if value > 0.0 {
            Ok(Period::Finite(value))
        } else {
            Err(self.error(
                row.line,
                Some(row.fields[0].col),
                format!("the period PER must be > 0 s, −1 (ω = 0) or 0 (ω = ∞), got {value}"),
            ))
        }
    }

    /// A finite period (PER > 0) of `what`, which has no ω = 0 or ω = ∞ rows.
    fn finite_period(&self, row: &Row<'_>, what: &str) -> Result<f64, WamitError> {
        match self.period(row)? {
            Period::Finite(p) => Ok(p),
            Period::Zero | Period::Infinite => Err(self.error(
                row.line,
                Some(row.fields[0].col),
                format!("{what} is defined at finite periods only (PER > 0)"),
            )),
        }
    }
}

fn fields(line: &str) -> Vec<Field<'_>> {
    let mut found = Vec::new();
    let mut start = None;
    for (col, (byte, c)) in line.char_indices().enumerate() {
        match (c.is_whitespace(), start) {
            (false, None) => start = Some((byte, col + 1)),
            (true, Some((from, at))) => {
                found.push(Field { text: &line[from..byte], col: at });
                start = None;
            }
            _ => {}
        }
    }
    if let Some((from, at)) = start {
        found.push(Field { text: &line[from..], col: at });
    }
    found
}

/// A `.1` file's period.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Period {
    /// PER = −1: ω = 0.
    Zero,
    /// PER = 0: ω = ∞.
    Infinite,
    /// PER > 0 \[s]: ω = 2π/PER.
    Finite(f64),
}

/// The exponent of L for a pair: `base` for translation–translation, `base + 1` mixed, `base + 2`
/// rotation–rotation.
fn pair_power(i: usize, j: usize, base: i32) -> i32 {
    base + i32::from(i >= 3) + i32::from(j >= 3)
}

/// A `.1` file in SI units, frequencies increasing, and the line of its first ω = ∞ row.
struct Radiation {
    frequencies: Vec<f64>,
    added_mass: Vec<Matrix6>,
    damping: Vec<Matrix6>,
    infinite: Matrix6,
    zero: Matrix6,
    infinite_line: usize,
}

fn parse_radiation(file: &Text, scale: Scale) -> Result<Radiation, WamitError> {
    let mut zero: Option<(Matrix6, usize)> = None;
    let mut infinite: Option<(Matrix6, usize)> = None;
    // Finite periods by their bits (positive floats order as their bits): (A, B).
    let mut finite: BTreeMap<u64, (f64, Matrix6, Matrix6)> = BTreeMap::new();
    let mut seen = std::collections::HashSet::new();
    for row in file.rows(&[4, 5], "PER I J A [B] (4 columns at PER = −1 or 0, else 5)")? {
        let period = file.period(&row)?;
        let (i, j) = (file.dof(&row, 1)?, file.dof(&row, 2)?);
        let a = file.number(&row, 3, "the added mass")? * scale.density * scale.length.powi(pair_power(i, j, 3));
        let key = match period {
            Period::Zero => -1.0_f64,
            Period::Infinite => 0.0,
            Period::Finite(p) => p,
        };
        if !seen.insert((key.to_bits(), i, j)) {
            return Err(file.error(row.line, None, format!("pair ({}, {}) given twice at PER = {key}", i + 1, j + 1)));
        }
        let columns = if matches!(period, Period::Finite(_)) { 5 } else { 4 };
        if row.fields.len() != columns {
            return Err(file.error(
                row.line,
                None,
                format!(
                    "expected {columns} columns at PER = {key} (PER I J A{}), found {}",
                    if columns == 5 { " B" } else { "" },
                    row.fields.len()
                ),
            ));
        }
        match period {
            Period::Zero => zero.get_or_insert((Matrix6::zeros(), row.line)).0[(i, j)] = a,
            Period::Infinite => infinite.get_or_insert((Matrix6::zeros(), row.line)).0[(i, j)] = a,
            Period::Finite(p) => {
                let omega = 2.0 * PI / p;
                let b = file.number(&row, 4, "the damping")?
                    * scale.density
                    * omega
                    * scale.length.powi(pair_power(i, j, 3));
                let entry = finite.entry(p.to_bits()).or_insert((omega, Matrix6::zeros(), Matrix6::zeros()));
                entry.1[(i, j)] = a;
                entry.2[(i, j)] = b;
            }
        }
    }
    let missing = |what: &str| WamitError {
        path: file.path.clone(),
        line: None,
        col: None,
        message: format!("no {what} block: Tether needs both limits of the added mass (PHYSICS.md §9)"),
    };
    let (infinite, infinite_line) = infinite.ok_or_else(|| missing("ω = ∞ (PER = 0)"))?;
    let (zero, _) = zero.ok_or_else(|| missing("ω = 0 (PER = −1)"))?;
    // Longest period first is lowest frequency first.
    let blocks: Vec<_> = finite.into_values().rev().collect();
    Ok(Radiation {
        frequencies: blocks.iter().map(|b| b.0).collect(),
        added_mass: blocks.iter().map(|b| b.1).collect(),
        damping: blocks.iter().map(|b| b.2).collect(),
        infinite,
        zero,
        infinite_line,
    })
}

/// A table read row by row, one value per degree of freedom at each period and heading, gathered
/// into the physics' layout: frequencies increasing, heading by heading, a pair a file leaves
/// out 0.
struct HeadingTable<T> {
    values: BTreeMap<(u64, i64), T>,
    periods: BTreeMap<u64, f64>,
    headings: BTreeMap<i64, f64>,
}

impl<T: Copy> HeadingTable<T> {
    fn new() -> Self {
        Self { values: BTreeMap::new(), periods: BTreeMap::new(), headings: BTreeMap::new() }
    }

    /// The entry at `period` \[s] and `heading` \[deg] (`zero` until set), to set a dof of.
    fn entry(&mut self, period: f64, heading: f64, zero: T) -> &mut T {
        // Headings keyed in millidegrees: the same heading written alike by every row.
        let heading_key = (heading * 1000.0).round() as i64;
        self.periods.insert(period.to_bits(), 2.0 * PI / period);
        self.headings.insert(heading_key, heading.to_radians());
        self.values.entry((period.to_bits(), heading_key)).or_insert(zero)
    }

    fn is_empty(&self) -> bool {
        self.values.is_empty()
    }

    /// Frequencies [rad/s] increasing, headings \[rad] and the values heading by heading.
    fn finish(self, zero: T) -> (Vec<f64>, Vec<f64>, Vec<T>) {
        // Longest period first is lowest frequency first.
        let frequencies: Vec<f64> = self.periods.values().rev().copied().collect();
        let period_keys: Vec<u64> = self.periods.keys().rev().copied().collect();
        let mut grid = Vec::with_capacity(frequencies.len() * self.headings.len());
        for heading in self.headings.keys() {
            for period in &period_keys {
                grid.push(self.values.get(&(*period, *heading)).copied().unwrap_or(zero));
            }
        }
        (frequencies, self.headings.into_values().collect(), grid)
    }
}

fn parse_excitation(file: &Text, scale: Scale) -> Result<Excitation, WamitError> {
    let mut table = HeadingTable::new();
    for row in file.rows(&[7], "PER β I |X| phase Re Im (7 columns)")? {
        let period = file.finite_period(&row, "the excitation")?;
        let heading = file.number(&row, 1, "the heading β")?;
        let i = file.dof(&row, 2)?;
        let m = scale.density * scale.gravity * scale.length.powi(if i < 3 { 2 } else { 3 });
        let x = Complex::new(file.number(&row, 5, "Re X")?, file.number(&row, 6, "Im X")?) * m;
        table.entry(period, heading, ComplexVector6::zeros())[i] = x;
    }
    let (frequencies, headings, values) = table.finish(ComplexVector6::zeros());
    Ok(Excitation { frequencies, headings, values })
}

fn parse_mean_drift(file: &Text, scale: Scale, source: DriftSource) -> Result<MeanDrift, WamitError> {
    let mut table = HeadingTable::new();
    for row in file.rows(&[7, 8], "PER β₁ β₂ I |F| phase Re Im (8 columns, or 7 with one heading)")? {
        let period = file.finite_period(&row, "the mean drift")?;
        let bidirectional = row.fields.len() == 8;
        let heading = file.number(&row, 1, "the heading β₁")?;
        if bidirectional && file.number(&row, 2, "the heading β₂")? != heading {
            continue;
        }
        let first_value = if bidirectional { 4 } else { 3 };
        let i = file.dof(&row, first_value - 1)?;
        let unit = scale.density * scale.gravity * scale.length.powi(if i < 3 { 1 } else { 2 });
        table.entry(period, heading, Vector6::zeros())[i] = file.number(&row, first_value + 2, "Re F̄")? * unit;
    }
    if table.is_empty() {
        return Err(WamitError {
            path: file.path.clone(),
            line: None,
            col: None,
            message: "no row with β₁ = β₂: Tether reads the drift of a unidirectional sea".into(),
        });
    }
    let (frequencies, headings, values) = table.finish(Vector6::zeros());
    MeanDrift::new(frequencies, headings, values, source).map_err(|e| WamitError {
        path: file.path.clone(),
        line: None,
        col: None,
        message: e.to_string(),
    })
}

fn parse_hydrostatics(file: &Text, scale: Scale) -> Result<Matrix6, WamitError> {
    let mut stiffness = Matrix6::zeros();
    for row in file.rows(&[3], "I J C (3 columns)")? {
        let (i, j) = (file.dof(&row, 0)?, file.dof(&row, 1)?);
        stiffness[(i, j)] = file.number(&row, 2, "the stiffness")?
            * scale.density
            * scale.gravity
            * scale.length.powi(pair_power(i, j, 2));
    }
    Ok(stiffness)
}
