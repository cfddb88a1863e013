//! `tether rao SCENE --body NAME [--periods T,…] [--heading DEG] [--csv FILE]`: a floating
//! body's linear RAOs (PHYSICS.md §9, the frequency-domain solve
//! `ξ = [−ω² (M + A(ω)) + iω B(ω) + C]⁻¹ X(ω, β)`) from its potential-flow data, its mass about
//! the reference point and its mesh's linear hydrostatic stiffness
//! ([`tether_physics::rao`]): per dof the amplitude per metre of wave (m/m, deg/m) and the phase
//! \[deg] in WAMIT's convention (`q = Re{a ξ e^{iωt}}`, a positive phase leads the wave's crest
//! at the reference point).

use anyhow::{Context as _, bail};
use clap::Args;
use std::f64::consts::TAU;
use std::path::PathBuf;
use tether_physics::rao::{LinearModel, RaoRow};

#[derive(Debug, Args)]
pub struct RaoArgs {
    /// Scene file (.ron).
    scene: PathBuf,
    /// The body, floating under potential flow (`hydro: Hydro(potential: Wamit(...))`).
    #[arg(long)]
    body: String,
    /// Wave periods [s], comma-separated (default: the potential-flow file's frequencies).
    #[arg(long, value_delimiter = ',')]
    periods: Option<Vec<f64>>,
    /// Direction the waves travel toward [deg, counter-clockwise from +x] (default: the scene's
    /// sea; 0 in calm water); one of the file's headings.
    #[arg(long, allow_hyphen_values = true)]
    heading: Option<f64>,
    /// Also write the table as CSV.
    #[arg(long, value_name = "FILE")]
    csv: Option<PathBuf>,
}

/// The six dofs, with the unit of their amplitude per metre of wave.
const DOFS: [(&str, &str); 6] =
    [("surge", "m/m"), ("sway", "m/m"), ("heave", "m/m"), ("roll", "deg/m"), ("pitch", "deg/m"), ("yaw", "deg/m")];

pub fn run(args: &RaoArgs) -> anyhow::Result<()> {
    let loaded = super::load(&args.scene)?;
    let label = args.scene.display().to_string();
    let system = loaded.world.system();
    let model = LinearModel::new(system, &args.body).with_context(|| label.clone())?;
    let heading = match args.heading {
        Some(degrees) if degrees.is_finite() => degrees.to_radians(),
        Some(degrees) => bail!("--heading must be a number of degrees, got {degrees}"),
        None => sea_heading(system),
    };
    let index = model.heading_index(heading).with_context(|| label.clone())?;
    let omegas = match &args.periods {
        Some(periods) => periods
            .iter()
            .map(|&t| if t.is_finite() && t > 0.0 { Ok(TAU / t) } else { Err(t) })
            .collect::<Result<Vec<_>, _>>()
            .map_err(|t| anyhow::anyhow!("--periods must be positive numbers of seconds, got {t}"))?,
        None => model.coefficients().frequencies().to_vec(),
    };
    let rows = model.rao(&omegas, index);
    let header = format!(
        "{label}: RAOs of body \"{}\" in waves toward {:.1}°, per metre of wave amplitude; phase in WAMIT's convention (leads the crest at the reference point)\n\n",
        args.body,
        heading.to_degrees()
    );
    super::print(&(header + &text(&rows)))?;
    if let Some(path) = &args.csv {
        std::fs::write(path, csv(&rows)).with_context(|| format!("{}: cannot write", path.display()))?;
        super::print(&format!("\nwrote {}\n", path.display()))?;
    }
    Ok(())
}

/// The heading of the sea's first wave component \[rad], 0 in calm water.
fn sea_heading(system: &tether_physics::system::System) -> f64 {
    system.water().and_then(|stage| stage.water.sea().components().first().map(|c| c.heading)).unwrap_or(0.0)
}

/// Period \[s], ω \[rad/s], then amplitude and phase \[deg] per dof of `row` (rotations in deg/m);
/// `None` for a singular system.
fn values(row: &RaoRow) -> (f64, f64, Option<[(f64, f64); 6]>) {
    let columns = row.response.map(|xi| {
        std::array::from_fn(|dof| {
            let scale = if dof < 3 { 1.0 } else { 1.0_f64.to_degrees() };
            (xi[dof].norm() * scale, xi[dof].arg().to_degrees())
        })
    });
    (TAU / row.omega, row.omega, columns)
}

/// The table for people: one line per frequency.
fn text(rows: &[RaoRow]) -> String {
    let mut out = format!("{:>9} {:>9}", "T [s]", "ω [rad/s]");
    for (name, unit) in DOFS {
        out += &format!(" {:>15} {:>8}", format!("{name} [{unit}]"), "phase°");
    }
    out += "\n";
    for row in rows {
        let (period, omega, columns) = values(row);
        out += &format!("{period:>9.3} {omega:>9.4}");
        match columns {
            Some(columns) => {
                for (amplitude, phase) in columns {
                    out += &format!(" {amplitude:>15.5} {phase:>8.2}");
                }
            }
            None => out += "  singular (an undamped resonance)",
        }
        out += "\n";
    }
    out
}

/// The same table as CSV, one row per frequency (a singular one left empty).
fn csv(rows: &[RaoRow]) -> String {
    let mut out = "period_s,omega_rad_s".to_string();
    for (name, unit) in DOFS {
        let unit = unit.replace('/', "_per_");
        out += &format!(",{name}_{unit},{name}_phase_deg");
    }
    out += "\n";
    for row in rows {
        let (period, omega, columns) = values(row);
        out += &format!("{period},{omega}");
        match columns {
            Some(columns) => {
                for (amplitude, phase) in columns {
                    out += &format!(",{amplitude},{phase}");
                }
            }
            None => out += &",".repeat(12),
        }
        out += "\n";
    }
    out
}
