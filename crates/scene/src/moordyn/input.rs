//! What a MoorDyn input file says, typed and checked: its line types, points, bodies, lines and
//! options (MoorDyn v2's columns, and v1's where OpenFAST's files order them differently), each
//! with the line of the file it was read from. Everything Tether cannot model is refused here or
//! noted as a warning (the list is in `docs/moordyn-files.md`).

use super::Located;
use super::reader::{Field, Row, Section, SectionKind};
use tether_physics::coupling::LumpedMassSpec;

/// A line type (`LINE TYPES`): SI units.
#[derive(Debug, Clone, PartialEq)]
pub struct LineType {
    pub name: String,
    /// Volume-equivalent diameter `d` \[m].
    pub diameter: f64,
    /// Mass per length in air `λ0` [kg/m].
    pub mass_per_length: f64,
    /// Axial stiffness `EA` \[N].
    pub axial_stiffness: f64,
    /// Internal damping: `BA` [N·s] when ≥ 0, minus the damping ratio `ζ` when negative.
    pub damping: f64,
    /// Bending stiffness `EI` [N·m²].
    pub bending_stiffness: f64,
    pub drag_normal: f64,
    pub added_mass_normal: f64,
    pub drag_tangential: f64,
    pub added_mass_tangential: f64,
    pub line: usize,
}

/// What a point is attached to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Attachment {
    /// `Fixed`, `Fix`, `Anchor`: the world.
    Fixed,
    /// `Free`, `Connect`, `Point`: moves under its forces.
    Free,
    /// `Coupled`, `Vessel`, `Fairlead`: moved by the program that drives MoorDyn.
    Coupled,
    /// `Body<n>`: body `n` (1-based), the point given in its frame.
    Body(usize),
    /// `Turbine<n>`: FAST.Farm's turbine `n`, the point given relative to its reference.
    Turbine(usize),
}

/// A point (`POINTS`): position \[m], mass \[kg], volume \[m³], drag area `CdA` \[m²], added-mass
/// coefficient `Ca` [–].
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    pub id: usize,
    pub attachment: Attachment,
    pub position: [f64; 3],
    pub mass: f64,
    pub volume: f64,
    pub drag_area: f64,
    pub added_mass: f64,
    pub line: usize,
}

/// How a body moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BodyKind {
    Fixed,
    Free,
    Coupled,
}

/// A body (`BODIES`): reference point \[m] and roll, pitch, yaw \[deg], mass \[kg], centre of
/// gravity in its frame \[m], moments of inertia about it [kg·m²], volume \[m³], drag areas
/// (translation, rotation) \[m²], added-mass coefficients [–].
#[derive(Debug, Clone, PartialEq)]
pub struct Body {
    pub id: usize,
    pub kind: BodyKind,
    pub position: [f64; 3],
    pub angles_deg: [f64; 3],
    pub mass: f64,
    pub center_of_gravity: [f64; 3],
    pub inertia: [f64; 3],
    pub volume: f64,
    pub drag_area: [f64; 6],
    pub added_mass: [f64; 3],
    pub line: usize,
}

/// A line (`LINES`): its type and end points (indices into the points), unstretched length \[m]
/// and segments.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    pub id: usize,
    pub line_type: usize,
    pub end_a: usize,
    pub end_b: usize,
    pub length: f64,
    pub segments: u32,
    pub line: usize,
}

/// The options Tether uses (MoorDyn's defaults where absent), and those it read but does not use.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// `g` [m/s²].
    pub gravity: f64,
    /// `WtrDnsty` ρ [kg/m³].
    pub density: f64,
    /// `WtrDpth` \[m]: at least the depth of the lowest point, as MoorDyn makes it.
    pub depth: f64,
    /// `kBot` [Pa/m].
    pub seabed_stiffness: f64,
    /// `cBot` [Pa·s/m].
    pub seabed_damping: f64,
    /// `FrictionCoefficient` μ [–].
    pub friction: f64,
    /// `FricDamp` (MoorDyn-F's `CV`) [N·s/m]: below its Coulomb limit `μ F_n` MoorDyn's seabed
    /// friction on a node is the damper `μ CV |v_h|` (`Line.cpp`, `getStateDeriv`).
    pub friction_damping: f64,
    /// The options read but not used (`dtM 0.0002`, …), for the scene's opening comment.
    pub unused: Vec<String>,
}

/// A MoorDyn input file, read.
#[derive(Debug, Clone, PartialEq)]
pub struct Input {
    pub line_types: Vec<LineType>,
    pub points: Vec<Point>,
    pub bodies: Vec<Body>,
    pub lines: Vec<Line>,
    pub options: Options,
    /// What was left out because it does not change the result, each with its file line.
    pub warnings: Vec<Located>,
}

/// Reads the sections of a file whose last line is `last`.
///
/// # Errors
/// The first problem, at its line and column: a missing or malformed value, a reference to a
/// type, point or body that does not exist, a feature Tether does not model.
pub fn read(sections: &[Section], last: usize) -> Result<Input, Located> {
    let mut warnings = Vec::new();
    let table = |kind: SectionKind| sections.iter().find(|s| s.kind == kind);
    let options = match table(SectionKind::Options) {
        Some(section) => read_options(section, &mut warnings)?,
        None => Options::default(),
    };
    refuse_sections(sections, &mut warnings)?;
    let line_types = match table(SectionKind::LineTypes) {
        Some(section) => {
            let v1 = is_v1_line_types(section);
            data_rows(section)?.iter().map(|row| line_type(row, v1)).collect::<Result<Vec<_>, _>>()?
        }
        None => return Err(ends_early(last, "LINE TYPES")),
    };
    let bodies = match table(SectionKind::Bodies) {
        Some(section) => {
            data_rows(section)?.iter().map(|row| body(row, &mut warnings)).collect::<Result<Vec<_>, _>>()?
        }
        None => Vec::new(),
    };
    let points = match table(SectionKind::Points) {
        Some(section) => {
            data_rows(section)?.iter().map(|row| point(row, bodies.len())).collect::<Result<Vec<_>, _>>()?
        }
        None => return Err(ends_early(last, "POINTS")),
    };
    let lines = match table(SectionKind::Lines) {
        Some(section) => {
            let order = LineColumns::of(section)?;
            data_rows(section)?
                .iter()
                .map(|row| line(row, order, &line_types, &points))
                .collect::<Result<Vec<_>, _>>()?
        }
        None => return Err(ends_early(last, "LINES")),
    };
    check_unique(points.iter().map(|p| (p.id, p.line)), "point")?;
    check_unique(lines.iter().map(|l| (l.id, l.line)), "line")?;
    check_unique(bodies.iter().map(|b| (b.id, b.line)), "body")?;
    let deepest = points.iter().map(|p| -p.position[2]).fold(options.depth, f64::max);
    Ok(Input { line_types, points, bodies, lines, options: Options { depth: deepest, ..options }, warnings })
}

impl Default for Options {
    /// MoorDyn v2's defaults (`MoorDyn2.cpp`): g 9.80665, ρ 1025, no depth (the lowest point's),
    /// kBot 3e6, cBot 3e5, no friction, FricDamp 200 N·s/m.
    fn default() -> Self {
        Self {
            gravity: 9.80665,
            density: 1025.0,
            depth: 0.0,
            seabed_stiffness: LumpedMassSpec::SEABED_STIFFNESS,
            seabed_damping: LumpedMassSpec::SEABED_DAMPING,
            friction: 0.0,
            friction_damping: 200.0,
            unused: Vec::new(),
        }
    }
}

fn ends_early(last: usize, section: &str) -> Located {
    Located { line: last, col: 1, message: format!("the file ends without a {section} section") }
}

/// Sections Tether cannot model are refused at their first row; rod types alone and outputs
/// are noted.
fn refuse_sections(sections: &[Section], warnings: &mut Vec<Located>) -> Result<(), Located> {
    for section in sections {
        let first = section.rows.first();
        match section.kind {
            SectionKind::Rods | SectionKind::Failure | SectionKind::SyropeInitial => {
                let rows = match section.kind {
                    SectionKind::Rods => data_rows(section)?,
                    _ => section.rows.iter().collect(),
                };
                if let Some(row) = rows.first() {
                    let what = match section.kind {
                        SectionKind::Rods => {
                            "rods are not modelled by Tether (refused: the lines they hold would be wrong)"
                        }
                        SectionKind::Failure => "line failures are not modelled by Tether (refused)",
                        _ => "synthetic-rope (Syrope) lines are not modelled by Tether (refused)",
                    };
                    return Err(Located { line: row.line, col: 1, message: what.to_string() });
                }
            }
            SectionKind::RodTypes if first.is_some() => warnings.push(Located {
                line: section.line,
                col: 1,
                message: "rod types ignored: the file has no rods".to_string(),
            }),
            SectionKind::Outputs if first.is_some() => warnings.push(Located {
                line: section.line,
                col: 1,
                message: "output channels ignored: a Tether recording has every line's tensions".to_string(),
            }),
            SectionKind::RodTypes
            | SectionKind::Outputs
            | SectionKind::LineTypes
            | SectionKind::Bodies
            | SectionKind::Points
            | SectionKind::Lines
            | SectionKind::Options => {}
        }
    }
    Ok(())
}

/// A table's data rows: after OpenFAST's count line (`3  NLines - number of lines`), the column
/// names and the units line (in parentheses).
fn data_rows<'s, 'a>(section: &'s Section<'a>) -> Result<Vec<&'s Row<'a>>, Located> {
    let mut rows = section.rows.iter().peekable();
    while rows.peek().is_some_and(|row| is_count(row)) {
        rows.next();
    }
    if rows.next().is_none() {
        return Err(Located {
            line: section.line,
            col: 1,
            message: format!("section {} ends before its column names", section.title),
        });
    }
    if rows.peek().is_some_and(|row| row.fields[0].text.starts_with('(')) {
        rows.next();
    }
    Ok(rows.collect())
}

/// OpenFAST's count line: an integer, then a name such as `NTypes`, `NConnects`, `NLines`.
fn is_count(row: &Row) -> bool {
    let name = row.fields.get(1).map_or("", |f| f.text);
    row.fields[0].text.parse::<u64>().is_ok()
        && name.len() > 1
        && name.starts_with('N')
        && name.chars().nth(1).is_some_and(|c| c.is_ascii_uppercase())
}

/// Field `index` of `row`, named `what` in the error when it is missing.
fn field<'a>(row: &Row<'a>, index: usize, what: &str) -> Result<Field<'a>, Located> {
    row.fields.get(index).copied().ok_or_else(|| Located {
        line: row.line,
        col: row.fields.last().map_or(1, |f| f.col + f.text.len()),
        message: format!("{what} missing: the row has {} fields, {what} is field {}", row.fields.len(), index + 1),
    })
}

/// A finite number.
fn number(field: Field, what: &str) -> Result<f64, Located> {
    field.text.parse::<f64>().ok().filter(|v| v.is_finite()).ok_or_else(|| Located {
        line: field.line,
        col: field.col,
        message: format!("{what}: expected a number, found \"{}\"", field.text),
    })
}

/// A number ≥ 0.
fn non_negative(field: Field, what: &str) -> Result<f64, Located> {
    let value = number(field, what)?;
    if value < 0.0 {
        return Err(Located {
            line: field.line,
            col: field.col,
            message: format!("{what} must be ≥ 0, found {value}"),
        });
    }
    Ok(value)
}

/// One to `count` numbers separated by `|` (MoorDyn's per-axis values).
fn numbers(field: Field, what: &str) -> Result<Vec<f64>, Located> {
    field.text.split('|').map(|part| number(Field { text: part, ..field }, what)).collect()
}

/// A positive whole number (an ID, a segment count).
fn whole(field: Field, what: &str) -> Result<usize, Located> {
    field.text.parse::<usize>().ok().filter(|v| *v > 0).ok_or_else(|| Located {
        line: field.line,
        col: field.col,
        message: format!("{what}: expected a whole number ≥ 1, found \"{}\"", field.text),
    })
}

/// Whether a line-type table has v1's columns (Diam, MassDen, EA, BA, Can, Cat, Cdn, Cdt), told
/// by its sixth column's name (`Can` in v1, `EI` in v2): OpenFAST's v1 files title it `LINE
/// DICTIONARY` or, as the IEA 15 MW semi's of 2021, `LINE TYPES` with a count line above.
fn is_v1_line_types(section: &Section) -> bool {
    let names = section.rows.iter().find(|row| !is_count(row));
    names.and_then(|row| row.fields.get(5)).is_some_and(|f| f.text.to_uppercase().starts_with("CAN"))
}

/// A line type's row: v1's 9 columns (`v1`) or v2's 10 or more (Diam, Mass/m, EA, BA/-zeta, EI,
/// Cd, Ca, CdAx, CaAx, optionally Cl).
fn line_type(row: &Row, v1: bool) -> Result<LineType, Located> {
    let name = field(row, 0, "line type name")?.text.to_string();
    let ea = field(row, 3, "EA")?;
    // A table of strain against tension is named by its file; a `|` adds viscoelastic terms.
    if ea.text.parse::<f64>().is_err() && (ea.text.contains('|') || ea.text.contains('.')) {
        return Err(Located {
            line: ea.line,
            col: ea.col,
            message: format!(
                "line type \"{name}\": EA \"{}\" is a nonlinear or viscoelastic stiffness, which Tether does not model (refused)",
                ea.text
            ),
        });
    }
    let column = |index: usize, what: &str| field(row, index, what).and_then(|f| non_negative(f, what));
    let line_type = LineType {
        diameter: column(1, "Diam")?,
        mass_per_length: column(2, "Mass/m")?,
        axial_stiffness: number(ea, "EA")?,
        damping: field(row, 4, "BA/-zeta").and_then(|f| number(f, "BA/-zeta"))?,
        bending_stiffness: if v1 { 0.0 } else { column(5, "EI")? },
        drag_normal: column(if v1 { 7 } else { 6 }, "Cd")?,
        added_mass_normal: column(if v1 { 5 } else { 7 }, "Ca")?,
        drag_tangential: column(8, "CdAx")?,
        added_mass_tangential: column(if v1 { 6 } else { 9 }, "CaAx")?,
        name,
        line: row.line,
    };
    if row.fields.len() > 10 && !v1 && number(row.fields[10], "Cl").is_ok_and(|cl| cl != 0.0) {
        return Err(Located {
            line: row.line,
            col: row.fields[10].col,
            message: format!(
                "line type \"{}\": vortex-induced vibration (Cl ≠ 0) is not modelled by Tether (refused)",
                line_type.name
            ),
        });
    }
    Ok(line_type)
}

/// Splits `Body3` into (`BODY`, 3), `Fixed` into (`FIXED`, none).
fn word_and_number(text: &str) -> (String, Option<usize>) {
    let split = text.find(|c: char| c.is_ascii_digit()).unwrap_or(text.len());
    (text[..split].to_uppercase(), text[split..].parse().ok())
}

fn point(row: &Row, body_count: usize) -> Result<Point, Located> {
    let id = whole(field(row, 0, "point ID")?, "point ID")?;
    let kind = field(row, 1, "point type")?;
    let attachment = match word_and_number(kind.text) {
        (word, _) if ["FIXED", "FIX", "ANCHOR"].contains(&word.as_str()) => Attachment::Fixed,
        (word, _) if ["FREE", "CONNECT", "CON", "POINT"].contains(&word.as_str()) => Attachment::Free,
        (word, _) if ["COUPLED", "CPLD", "VESSEL", "VES", "FAIRLEAD"].contains(&word.as_str()) => Attachment::Coupled,
        (word, Some(n)) if word == "BODY" && (1..=body_count).contains(&n) => Attachment::Body(n),
        (word, n) if word == "BODY" => {
            return Err(Located {
                line: kind.line,
                col: kind.col,
                message: format!(
                    "point {id} is attached to body {} but the file has {body_count} bodies",
                    n.map_or_else(|| "(no number)".to_string(), |n| n.to_string())
                ),
            });
        }
        (word, Some(n)) if word == "TURBINE" => Attachment::Turbine(n),
        (_, _) => {
            return Err(Located {
                line: kind.line,
                col: kind.col,
                message: format!(
                    "point {id}: unknown type \"{}\" (Fixed, Free, Coupled, Body<n> or Turbine<n>)",
                    kind.text
                ),
            });
        }
    };
    let xyz = |index: usize, what: &str| field(row, index, what).and_then(|f| number(f, what));
    let position = [xyz(2, "X")?, xyz(3, "Y")?, xyz(4, "Z")?];
    // v1 rows (and v2 rows that give them) carry a constant force FX FY FZ before CdA and Ca.
    let with_force = row.fields.len() >= 12;
    if with_force {
        for index in 7..10 {
            if number(row.fields[index], "force")? != 0.0 {
                return Err(Located {
                    line: row.line,
                    col: row.fields[index].col,
                    message: format!("point {id}: a constant external force is not modelled by Tether (refused)"),
                });
            }
        }
    }
    let tail = if with_force { 10 } else { 7 };
    let column = |index: usize, what: &str| field(row, index, what).and_then(|f| non_negative(f, what));
    Ok(Point {
        id,
        attachment,
        position,
        mass: column(5, "point mass")?,
        volume: column(6, "point volume")?,
        drag_area: column(tail, "point CdA")?,
        added_mass: column(tail + 1, "point Ca")?,
        line: row.line,
    })
}

fn body(row: &Row, warnings: &mut Vec<Located>) -> Result<Body, Located> {
    let id = whole(field(row, 0, "body ID")?, "body ID")?;
    let kind_field = field(row, 1, "body type")?;
    let kind = match word_and_number(kind_field.text).0.as_str() {
        "FIXED" | "FIX" | "ANCHOR" => BodyKind::Fixed,
        "COUPLED" | "CPLD" | "VESSEL" | "VES" => BodyKind::Coupled,
        "FREE" | "BODY" => BodyKind::Free,
        "COUPLEDPINNED" | "CPLDPIN" | "VESSELPINNED" | "VESPIN" => {
            return Err(Located {
                line: kind_field.line,
                col: kind_field.col,
                message: format!(
                    "body {id}: a pinned coupled body (moved but free to turn) is not modelled by Tether (refused)"
                ),
            });
        }
        _ => {
            return Err(Located {
                line: kind_field.line,
                col: kind_field.col,
                message: format!("body {id}: unknown type \"{}\" (Fixed, Free or Coupled)", kind_field.text),
            });
        }
    };
    let value = |index: usize, what: &str| field(row, index, what).and_then(|f| number(f, what));
    let per_axis = |index: usize, what: &str, counts: &[usize]| -> Result<Vec<f64>, Located> {
        let at = field(row, index, what)?;
        let values = numbers(at, what)?;
        if !counts.contains(&values.len()) || values.iter().any(|v| *v < 0.0 && what != "CG") {
            return Err(Located {
                line: at.line,
                col: at.col,
                message: format!(
                    "body {id}: {what} must be {counts:?} numbers separated by | (≥ 0), found \"{}\"",
                    at.text
                ),
            });
        }
        Ok(values)
    };
    let cg = per_axis(9, "CG", &[1, 3])?;
    let inertia = per_axis(10, "I", &[1, 3])?;
    let cda = per_axis(12, "CdA", &[1, 2, 3, 6])?;
    let ca = per_axis(13, "Ca", &[1, 3])?;
    let body = Body {
        id,
        kind,
        position: [value(2, "X0")?, value(3, "Y0")?, value(4, "Z0")?],
        angles_deg: [value(5, "r0")?, value(6, "p0")?, value(7, "y0")?],
        mass: field(row, 8, "Mass").and_then(|f| non_negative(f, "body mass"))?,
        // One number is the CG's height, three its x|y|z (MoorDyn's readBody).
        center_of_gravity: if cg.len() == 1 { [0.0, 0.0, cg[0]] } else { [cg[0], cg[1], cg[2]] },
        inertia: if inertia.len() == 1 { [inertia[0]; 3] } else { [inertia[0], inertia[1], inertia[2]] },
        volume: field(row, 11, "Volume").and_then(|f| non_negative(f, "body volume"))?,
        drag_area: match cda.len() {
            1 => [cda[0]; 6],
            2 => [cda[0], cda[0], cda[0], cda[1], cda[1], cda[1]],
            3 => [cda[0], cda[1], cda[2], cda[0], cda[1], cda[2]],
            _ => [cda[0], cda[1], cda[2], cda[3], cda[4], cda[5]],
        },
        added_mass: if ca.len() == 1 { [ca[0]; 3] } else { [ca[0], ca[1], ca[2]] },
        line: row.line,
    };
    if body.kind == BodyKind::Free && body.drag_area[3..].iter().any(|a| *a > 0.0) {
        warnings.push(Located {
            line: row.line,
            col: row.fields[12].col,
            message: format!("body {id}: rotational drag areas ignored (Tether's body drag acts at its drag centre)"),
        });
    }
    Ok(body)
}

/// Where a `LINES` row keeps its ends, length and segments: v2's `ID Type A B Len Segs`, or
/// v1's `ID Type Len Segs NodeAnch NodeFair` (OpenFAST's `LINE PROPERTIES`, told by its
/// column names).
#[derive(Debug, Clone, Copy)]
struct LineColumns {
    ends: [usize; 2],
    length: usize,
    segments: usize,
}

impl LineColumns {
    fn of(section: &Section) -> Result<Self, Located> {
        let v2 = Self { ends: [2, 3], length: 4, segments: 5 };
        let names = section.rows.iter().find(|row| !is_count(row));
        let v1 = names.and_then(|row| row.fields.get(2)).is_some_and(|f| f.text.to_uppercase().contains("LEN"));
        Ok(if v1 { Self { ends: [4, 5], length: 2, segments: 3 } } else { v2 })
    }
}

fn line(row: &Row, columns: LineColumns, types: &[LineType], points: &[Point]) -> Result<Line, Located> {
    let id = whole(field(row, 0, "line ID")?, "line ID")?;
    let type_field = field(row, 1, "line type")?;
    let line_type = types.iter().position(|t| t.name == type_field.text).ok_or_else(|| Located {
        line: type_field.line,
        col: type_field.col,
        message: format!(
            "line {id}: no line type \"{}\" (the file's types: {})",
            type_field.text,
            types.iter().map(|t| t.name.as_str()).collect::<Vec<_>>().join(", ")
        ),
    })?;
    let end = |index: usize| -> Result<usize, Located> {
        let at = field(row, columns.ends[index], "line end")?;
        let (word, number) = word_and_number(at.text);
        let refuse = |message: String| Located { line: at.line, col: at.col, message };
        if word.starts_with('R') && !word.starts_with("RO") || word == "ROD" {
            return Err(refuse(format!(
                "line {id}: ends on a rod (\"{}\"), which Tether does not model (refused)",
                at.text
            )));
        }
        if !["", "C", "CON", "P", "POINT"].contains(&word.as_str()) {
            return Err(refuse(format!("line {id}: end \"{}\" is not a point number", at.text)));
        }
        let id_of_point =
            number.ok_or_else(|| refuse(format!("line {id}: end \"{}\" has no point number", at.text)))?;
        points
            .iter()
            .position(|p| p.id == id_of_point)
            .ok_or_else(|| refuse(format!("line {id}: no point {id_of_point} (the file has {} points)", points.len())))
    };
    let length_field = field(row, columns.length, "UnstrLen")?;
    let length = number(length_field, "UnstrLen")?;
    if length <= 0.0 {
        return Err(Located {
            line: length_field.line,
            col: length_field.col,
            message: format!("line {id}: the unstretched length must be > 0 m, found {length}"),
        });
    }
    let segments_field = field(row, columns.segments, "NumSegs")?;
    let segments = whole(segments_field, "NumSegs")?;
    let segments = u32::try_from(segments).map_err(|_| Located {
        line: segments_field.line,
        col: segments_field.col,
        message: format!("line {id}: {segments} segments is too many"),
    })?;
    Ok(Line { id, line_type, end_a: end(0)?, end_b: end(1)?, length, segments, line: row.line })
}

/// IDs are unique (MoorDyn numbers them 1, 2, … in order).
fn check_unique(ids: impl Iterator<Item = (usize, usize)>, what: &str) -> Result<(), Located> {
    let mut seen = std::collections::HashMap::new();
    for (id, line) in ids {
        if let Some(first) = seen.insert(id, line) {
            return Err(Located {
                line,
                col: 1,
                message: format!("{what} {id} is declared again (first at line {first})"),
            });
        }
    }
    Ok(())
}

/// The options (`value name [description]`): those Tether uses, those it ignores because they
/// only steer MoorDyn's own run, and those that would change the result (refused).
fn read_options(section: &Section, warnings: &mut Vec<Located>) -> Result<Options, Located> {
    let mut options = Options::default();
    let mut depth = None;
    for row in &section.rows {
        let (Some(value), Some(name)) = (row.fields.first().copied(), row.fields.get(1).copied()) else {
            continue;
        };
        let refuse = |what: &str| Located {
            line: value.line,
            col: value.col,
            message: format!("option {} {}: {what} are not modelled by Tether (refused)", value.text, name.text),
        };
        match name.text.to_uppercase().as_str() {
            "G" | "GRAVITY" => options.gravity = number(value, "g")?,
            "WTRDNSTY" | "RHOW" | "RHO" | "WATERDENSITY" => options.density = non_negative(value, "WtrDnsty")?,
            "WTRDPTH" | "DEPTH" | "WTRDEPTH" | "WATERDEPTH" => depth = Some(non_negative(value, "WtrDpth")?),
            "KBOT" | "KB" => options.seabed_stiffness = non_negative(value, "kBot")?,
            "CBOT" | "CB" => options.seabed_damping = non_negative(value, "cBot")?,
            "FRICTIONCOEFFICIENT" | "MU_KT" => options.friction = non_negative(value, "FrictionCoefficient")?,
            "FRICDAMP" | "CV" => options.friction_damping = non_negative(value, "FricDamp")?,
            "STATDYNFRICSCALE" | "MC" if number(value, "StatDynFricScale")? != 1.0 => warnings.push(Located {
                line: value.line,
                col: value.col,
                message: format!(
                    "option {} {}: Tether's seabed friction has one coefficient (no static to dynamic ratio): taken as 1",
                    value.text, name.text
                ),
            }),
            "WAVEKIN" | "WATERKIN" if value.text != "0" => return Err(refuse("wave kinematics (files or grids)")),
            "CURRENTS" if value.text != "0" => return Err(refuse("current kinematics (files or grids)")),
            "SEAFLOORFILE" | "SEAFLOOR" => return Err(refuse("a 3-D seafloor from a file")),
            "DTM" | "TSCHEME" | "CFL" | "DTOUT" | "DTIC" | "TMAXIC" | "CDSCALEIC" | "ICDFAC" | "THRESHIC"
            | "ICTHRESH" | "ICDT" | "ICTMAX" | "ICGENDYNAMIC" | "FILEIC" | "WRITELOG" | "DISABLEOUTPUT"
            | "DISABLEOUTTIME" | "ECHO" | "WAVEKIN" | "WATERKIN" | "CURRENTS" | "WRITEUNITS" | "OUTSWITCH"
            | "STATDYNFRICSCALE" | "MC" => {
                options.unused.push(format!("{} {}", name.text, value.text));
            }
            _ => warnings.push(Located {
                line: row.line,
                col: name.col,
                message: format!("option {} unknown to Tether: ignored", name.text),
            }),
        }
    }
    options.depth = depth.unwrap_or(0.0);
    Ok(options)
}
