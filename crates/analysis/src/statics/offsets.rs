//! A body's offset curve as a table: per offset, the load along the held direction, the
//! restoring force (its opposite) and what each line and spring carries; as text and as CSV.

use tether_physics::coupling::CouplingKind;
use tether_physics::statics::OffsetCurve;
use tether_physics::system::System;

/// Column names (with units) and one row per offset.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    pub columns: Vec<String>,
    pub rows: Vec<Vec<f64>>,
}

/// The table of `curve` for `system`: offset, load, restoring force, then for each catenary its
/// end tensions and grounded length, for each spring its tension.
pub fn table(system: &System, curve: &OffsetCurve) -> Table {
    let direction = curve.dof.direction;
    let mut columns = vec![
        format!("offset {} [{}]", direction, direction.unit()),
        format!("load [{}]", direction.load_unit()),
        format!("restoring [{}]", direction.load_unit()),
    ];
    for coupling in system.couplings() {
        match coupling.kind {
            CouplingKind::Catenary(_) => columns.extend([
                format!("{} T1 [N]", coupling.name),
                format!("{} T2 [N]", coupling.name),
                format!("{} L_B [m]", coupling.name),
            ]),
            CouplingKind::SpringDamper(_) => columns.push(format!("{} tension [N]", coupling.name)),
            CouplingKind::Contact(_) => columns.push(format!("{} normal [N]", coupling.name)),
        }
    }
    let rows = curve
        .points
        .iter()
        .map(|point| {
            let mut row = vec![point.offset, point.load, -point.load];
            for (index, (coupling, forces)) in system.couplings().iter().zip(point.evaluation.forces()).enumerate() {
                match coupling.kind {
                    CouplingKind::Catenary(_) => {
                        let line = point.evaluation.line_state(index);
                        let (t1, t2) = line.map_or((f64::NAN, f64::NAN), |l| l.end_tensions());
                        row.extend([t1, t2, line.map_or(f64::NAN, |l| l.grounded_length())]);
                    }
                    CouplingKind::SpringDamper(_) => row.push(forces.tension),
                    CouplingKind::Contact(_) => {
                        row.push(point.evaluation.contact_forces(index).map_or(f64::NAN, |f| f.normal))
                    }
                }
            }
            row
        })
        .collect();
    Table { columns, rows }
}

impl Table {
    /// Aligned columns for a terminal.
    pub fn text(&self) -> String {
        let width = self.columns.iter().map(|c| c.chars().count()).max().unwrap_or(0).max(13) + 2;
        let mut out: String = self.columns.iter().map(|c| format!("{c:>width$}")).collect();
        out.push('\n');
        for row in &self.rows {
            out.extend(row.iter().map(|x| format!("{:>width$.6e}", x + 0.0)));
            out.push('\n');
        }
        out
    }

    /// Comma-separated values with a header line, full precision.
    pub fn csv(&self) -> String {
        let quote = |c: &String| {
            if c.contains(',') || c.contains('"') { format!("\"{}\"", c.replace('"', "\"\"")) } else { c.clone() }
        };
        let mut out = self.columns.iter().map(quote).collect::<Vec<_>>().join(",");
        out.push('\n');
        for row in &self.rows {
            out.push_str(&row.iter().map(|x| format!("{x:e}")).collect::<Vec<_>>().join(","));
            out.push('\n');
        }
        out
    }
}
