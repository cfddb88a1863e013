//! `tether equilibrium SCENE [--write OUT.ron] [--json]`: the static equilibrium of every body that
//! responds to forces (PHYSICS.md §7): poses, tensions, grounded lengths and
//! touchdowns, each body's 6 × 6 stiffness; optionally the scene starting there.

use anyhow::Context as _;
use clap::Args;
use std::path::PathBuf;
use std::time::Instant;
use tether_analysis::statics::{data, report};
use tether_physics::statics::{Settings, equilibrium};
use tether_scene as scene;

#[derive(Debug, Args)]
pub struct EquilibriumArgs {
    /// Scene file (.ron), or a MoorDyn input file.
    scene: PathBuf,
    /// Write the scene with its bodies starting at equilibrium, at rest (RON; the original's
    /// comments are not kept).
    #[arg(long, value_name = "OUT.ron")]
    write: Option<PathBuf>,
    /// Print the equilibrium as JSON (the Python module's `equilibrium()` reads the same data):
    /// positions [m], quaternions [w, x, y, z], stiffness [SI], tensions [N].
    #[arg(long)]
    json: bool,
}

pub fn run(args: &EquilibriumArgs) -> anyhow::Result<()> {
    let loaded = super::load(&args.scene)?;
    let label = args.scene.display();
    let system = loaded.world.system();
    let start = system.initial_states();
    let clock = Instant::now();
    let solved = equilibrium::solve(system, start, &[], &Settings::default()).with_context(|| label.to_string())?;
    let elapsed = clock.elapsed();
    if args.json {
        let data = data::equilibrium(system, &solved, start);
        super::print(&(serde_json::to_string_pretty(&data)? + "\n"))?;
    } else {
        super::print(&format!("{label}: {}", report::equilibrium(system, &solved, start, elapsed)))?;
    }
    if let Some(out) = &args.write {
        let mut placed = scene::pose::with_poses(&loaded.file, loaded.bodies.bodies(), &solved.states);
        let folder = |p: &std::path::Path| {
            std::path::absolute(p.parent().unwrap_or(std::path::Path::new("."))).unwrap_or_default()
        };
        scene::relocate_meshes(&mut placed, &folder(&args.scene), &folder(out));
        let text =
            scene::to_ron(&placed).with_context(|| format!("{}: cannot write the scene as RON", out.display()))?;
        std::fs::write(out, text).with_context(|| format!("{}: cannot write", out.display()))?;
        super::print(&format!("\nwrote {} (the scene starting at equilibrium)\n", out.display()))?;
    }
    Ok(())
}
