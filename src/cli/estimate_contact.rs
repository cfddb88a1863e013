//! `tether estimate-contact`: contact parameters from the impact they must stop (PHYSICS.md §4).

use clap::Args;
use std::fmt::Write as _;
use tether_physics::coupling::contact::estimator::{self, Impact, STEPS_PER_STOPPING_TIME};

#[derive(Debug, Args)]
#[command(allow_negative_numbers = true)]
pub struct EstimateArgs {
    /// Mass of the body [kg].
    #[arg(long)]
    mass: f64,
    /// Mass of the other body [kg] (body–body contact; omit against the environment).
    #[arg(long)]
    mass2: Option<f64>,
    /// Expected contact area A [m²].
    #[arg(long)]
    area: f64,
    /// Normal impact speed v [m/s].
    #[arg(long)]
    speed: f64,
    /// Range d0 where the contact starts to push [m].
    #[arg(long)]
    d0: f64,
    /// Distance d_min at which the impact must be stopped [m] (< d0; negative = penetration).
    #[arg(long)]
    dmin: f64,
    /// Damping ratio ζ (≪ 1).
    #[arg(long, default_value_t = 0.1)]
    zeta: f64,
    /// A world time step [s]: also print the sub-steps it needs.
    #[arg(long)]
    dt: Option<f64>,
}

pub fn run(args: &EstimateArgs) -> anyhow::Result<()> {
    let impact = Impact {
        mass: args.mass,
        other_mass: args.mass2,
        area: args.area,
        speed: args.speed,
        range: args.d0,
        min_distance: args.dmin,
        damping_ratio: args.zeta,
    };
    let estimate = estimator::estimate(&impact)?;
    let mut out = String::new();
    let _ = writeln!(out, "effective mass   m_e = {:.6e} kg", estimate.effective_mass);
    let _ = writeln!(out, "stiffness        k1  = {:.6e} N/m³   (stiffness: in the scene)", estimate.stiffness);
    let _ = writeln!(out, "damping          k2  = {:.6e} N·s/m³ (damping: in the scene)", estimate.damping);
    let _ = writeln!(out, "stopping time    τ   = {:.6e} s", estimate.stopping_time);
    let _ = writeln!(out, "recommended dt   τ/{STEPS_PER_STOPPING_TIME} = {:.6e} s", estimate.recommended_dt);
    if let Some(dt) = args.dt {
        super::flags::positive("--dt", dt, "s")?;
        let substeps = estimator::substeps_for(dt, estimate.recommended_dt);
        let _ = writeln!(
            out,
            "at dt = {dt:e} s: substeps: Fixed({substeps}) (integrator step {:.6e} s)",
            dt / f64::from(substeps)
        );
    }
    super::print(&out)
}
