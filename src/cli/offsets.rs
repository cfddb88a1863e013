//! `tether offsets SCENE --body NAME --direction x|y|z|roll|pitch|yaw --to D [--steps N]`: the
//! body's restoring force as it is held at offsets from its static equilibrium (every other
//! direction settled at each), with what each line carries; prints the table and writes it as
//! CSV and as a chart (PNG).

use anyhow::{Context as _, bail};
use clap::Args;
use std::path::PathBuf;
use tether_analysis::statics::{chart, offsets as table};
use tether_physics::statics::{Direction, Dof, Dofs, Settings, equilibrium, offsets};

#[derive(Debug, Args)]
pub struct OffsetsArgs {
    /// Scene file (.ron).
    scene: PathBuf,
    /// The body held at the offsets.
    #[arg(long)]
    body: String,
    /// x, y, z [m] or roll, pitch, yaw [rad] (about the world axes through its centre of mass).
    #[arg(long, value_parser = parse_direction)]
    direction: Direction,
    /// The largest offset from equilibrium [m or rad]; negative to go the other way.
    #[arg(long, allow_hyphen_values = true)]
    to: f64,
    /// Offsets after the equilibrium itself.
    #[arg(long, default_value_t = 20)]
    steps: u32,
    /// Output files without extension: writes OUTPUT.csv and OUTPUT.png (default
    /// offsets-<scene>-<body>-<direction>).
    #[arg(short, long)]
    output: Option<PathBuf>,
}

fn parse_direction(text: &str) -> Result<Direction, String> {
    text.parse()
}

/// At most this many offsets: each is a static solve.
const MAX_STEPS: u32 = 10_000;

pub fn run(args: &OffsetsArgs) -> anyhow::Result<()> {
    if !(args.to.is_finite() && args.to != 0.0) {
        bail!("--to must be a non-zero number of {}, got {}", args.direction.unit(), args.to);
    }
    if !(1..=MAX_STEPS).contains(&args.steps) {
        bail!("--steps must be 1 to {MAX_STEPS}, got {}", args.steps);
    }
    let loaded = super::load(&args.scene)?;
    let label = args.scene.display().to_string();
    let system = loaded.world.system();
    let names: Vec<&str> = system.bodies().iter().map(|b| b.name.as_str()).collect();
    let Some(body) = names.iter().position(|n| *n == args.body) else {
        bail!("{label}: no body \"{}\" (bodies: {})", args.body, names.join(", "));
    };
    let dof = Dof { body, direction: args.direction };
    if !Dofs::of(system, &[]).free().contains(&dof) {
        bail!("{label}: body \"{}\" cannot move in {}: its support holds it there", args.body, args.direction);
    }
    let settings = Settings::default();
    let at_rest = equilibrium::solve(system, system.initial_states(), &[], &settings).with_context(|| label.clone())?;
    let curve = offsets::curve(system, &at_rest, dof, args.to, args.steps, &settings)
        .with_context(|| format!("{label}: offset curve of body \"{}\" in {}", args.body, args.direction))?;
    let rows = table::table(system, &curve);
    let stem = args.scene.file_stem().map_or_else(|| "scene".to_string(), |s| s.to_string_lossy().into_owned());
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("offsets-{stem}-{}-{}", args.body, args.direction)));
    let (csv, png) = (output.with_extension("csv"), output.with_extension("png"));
    let header = format!(
        "{label}: body \"{}\" held at offsets in {} from its equilibrium, the rest settled at each\n\n",
        args.body, args.direction
    );
    super::print(&(header + &rows.text()))?;
    std::fs::write(&csv, rows.csv()).with_context(|| format!("{}: cannot write", csv.display()))?;
    let title = format!("{stem}: offset curve of \"{}\" in {}", args.body, args.direction);
    chart::write(&rows, &title, &png)?;
    super::print(&format!("\nwrote {} and {}\n", csv.display(), png.display()))
}
