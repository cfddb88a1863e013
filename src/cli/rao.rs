//! `tether rao SCENE --body NAME [--periods T,…] [--heading DEG] [--csv FILE] [--plot FILE.png]`: a floating
//! body's linear RAOs (PHYSICS.md §9, the frequency-domain solve
//! `ξ = [−ω² (M + A(ω)) + iω B(ω) + C]⁻¹ X(ω, β)`) from its potential-flow data, its mass about
//! the reference point and its mesh's linear hydrostatic stiffness
//! ([`tether_physics::rao`]): per dof the amplitude per metre of wave (m/m, deg/m) and the phase
//! \[deg] in WAMIT's convention (`q = Re{a ξ e^{iωt}}`, a positive phase leads the wave's crest
//! at the reference point).
//!
//! With `--natural-periods` it also prints the body's undamped natural periods and mode shapes at
//! the scene's static equilibrium, couplings included ([`tether_physics::natural_periods`]: with
//! `A(ω_n)` and with `A∞`).
//!
//! With `--time-domain` the same RAOs are also measured from regular-wave runs of the scene
//! ([`tether_physics::rao_time_domain`]), one per period on every core, and printed beside the
//! solve with their difference. The runs keep the scene's couplings, drag and other bodies; the
//! solve has none of them (a free-floating body), so a moored body's two columns differ by its
//! moorings.

use anyhow::{Context as _, bail};
use clap::Args;
use std::f64::consts::TAU;
use std::io::IsTerminal as _;
use std::path::PathBuf;
use tether_analysis::rao_chart::{self, DOFS, Responses, polar};
use tether_analysis::runner::Runner;
use tether_physics::potential::ComplexVector6;
use tether_physics::rao::{LinearModel, RaoRow};
use tether_physics::rao_time_domain::RegularWaveRun;
use tether_physics::world::World;

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
    /// Also draw the RAOs as a chart (PNG): amplitude and phase against the period per dof, the
    /// frequency-domain solve as lines and the --time-domain runs as circles.
    #[arg(long, value_name = "FILE.png")]
    plot: Option<PathBuf>,
    /// Also measure the RAOs from a run of the scene in regular waves at each period (its sea
    /// replaced; its couplings kept), printed beside the frequency-domain solve.
    #[arg(long)]
    time_domain: bool,
    /// With --time-domain: the waves' amplitude [m] (default 0.05).
    #[arg(long, allow_hyphen_values = true)]
    amplitude: Option<f64>,
    /// With --time-domain: the time the waves are ramped in over [s] (default 60).
    #[arg(long, allow_hyphen_values = true)]
    ramp: Option<f64>,
    /// With --time-domain: each run's length [s] (default: max(300 s, ramp + 2 × max(3 T, 40 s));
    /// the motion is fitted over its last max(3 T, 40 s)).
    #[arg(long, allow_hyphen_values = true)]
    duration: Option<f64>,
    /// Also print the body's undamped natural periods and mode shapes at the static equilibrium
    /// (couplings included), with A(ω_n) and with A∞.
    #[arg(long)]
    natural_periods: bool,
}

/// The waves' amplitude \[m] and ramp \[s] of `--time-domain` unless told.
const AMPLITUDE: f64 = 0.05;
const RAMP: f64 = 60.0;

/// A response whose frequency-domain amplitude is below this fraction of its period's largest
/// or of its dof's largest over the periods gets no difference: a percentage of numerical noise
/// (sway and roll in head seas, heave far above its resonance) says nothing. The chart leaves out
/// a dof by the same fraction.
const NEGLIGIBLE: f64 = rao_chart::NEGLIGIBLE;

/// The force left on a body at its initial pose, as a fraction of its weight, above which the
/// body is not at rest.
const UNBALANCED: f64 = 1e-3;

pub fn run(args: &RaoArgs) -> anyhow::Result<()> {
    let measuring = regular_wave_run(args)?;
    let loaded = super::load(&args.scene)?;
    let label = args.scene.display().to_string();
    let system = loaded.world.system();
    let model = LinearModel::new(system, &args.body).with_context(|| label.clone())?;
    warn_if_not_at_rest(system, &model, &label, &args.body);
    let heading = match args.heading {
        Some(degrees) if degrees.is_finite() => degrees.to_radians(),
        Some(degrees) => bail!("--heading must be a number of degrees, got {degrees}"),
        None => sea_heading(system),
    };
    let index = model.heading_index(heading).with_context(|| label.clone())?;
    let omegas = match &args.periods {
        Some(periods) => periods
            .iter()
            .map(|&t| super::flags::positive("--periods", t, "s").map(|t| TAU / t))
            .collect::<anyhow::Result<Vec<_>>>()?,
        None => model.coefficients().frequencies().to_vec(),
    };
    let rows = model.rao(&omegas, index);
    let measured = match &measuring {
        Some(run) => {
            for omega in &omegas {
                run.check(TAU / omega).context("--time-domain")?;
            }
            Some(measure(&loaded.world, &model, run, &omegas, heading).with_context(|| label.clone())?)
        }
        None => None,
    };
    let mut header = format!(
        "{label}: RAOs of body \"{}\" in waves toward {:.1}°, per metre of wave amplitude; phase in WAMIT's convention (leads the crest at the reference point)\n",
        args.body,
        heading.to_degrees()
    );
    let table = match (&measuring, &measured) {
        (Some(run), Some(measured)) => {
            header += &format!(
                "frequency domain: the panel data with the body's mass and its mesh's hydrostatic stiffness (free floating: no couplings, no drag)\n\
                 time domain: the scene run in regular waves of {} m ramped over {} s, its couplings, drag and other bodies kept; \
                 fitted over the last max(3 T, 40 s) of each run ({})\n",
                run.amplitude(),
                run.ramp(),
                durations(run, &omegas)
            );
            comparison(&rows, measured)
        }
        _ => text(&rows),
    };
    super::print(&(header + "\n" + &table))?;
    if args.natural_periods {
        super::print(&natural_periods(system, &args.body).with_context(|| label.clone())?)?;
    }
    if let Some(path) = &args.csv {
        std::fs::write(path, csv(&rows, measured.as_deref()))
            .with_context(|| format!("{}: cannot write", path.display()))?;
        super::print(&format!("\nwrote {}\n", path.display()))?;
    }
    if let Some(path) = &args.plot {
        let responses = Responses::new(&rows, measured.as_deref());
        let title = format!("RAOs of \"{}\" in waves toward {:.1}° ({label})", args.body, heading.to_degrees());
        rao_chart::write(&responses, &title, path)?;
        let omitted: Vec<&str> = responses.omitted.iter().map(|&dof| DOFS[dof].0).collect();
        let left_out = if omitted.is_empty() {
            String::new()
        } else {
            format!(" ({} left out: below {NEGLIGIBLE:e} of their kind's largest)", omitted.join(", "))
        };
        super::print(&format!("\nwrote {}{left_out}\n", path.display()))?;
    }
    Ok(())
}

/// Warns when the body's initial pose leaves more than [`UNBALANCED`] of its weight on it.
fn warn_if_not_at_rest(system: &tether_physics::system::System, model: &LinearModel, label: &str, name: &str) {
    let weight = system.bodies()[model.body()].mass() * system.gravity().norm();
    let left = model.unbalanced().force.norm();
    if left > UNBALANCED * weight {
        eprintln!(
            "warning: {label}: body \"{name}\" is not at rest at t = 0: its weight, the water and the couplings leave {left:.0} N on it ({:.2} % of its weight); the solve linearises about this pose and a time-domain run settles about another (start the scene at rest: tether equilibrium --write)",
            100.0 * left / weight
        );
    }
}

/// The regular-wave runs `--time-domain` asks for; `--amplitude`, `--ramp` or `--duration`
/// without it refused.
fn regular_wave_run(args: &RaoArgs) -> anyhow::Result<Option<RegularWaveRun>> {
    if !args.time_domain {
        let given = [("--amplitude", args.amplitude), ("--ramp", args.ramp), ("--duration", args.duration)];
        if let Some((flag, _)) = given.iter().find(|(_, value)| value.is_some()) {
            bail!("{flag} sets the regular-wave runs: it needs --time-domain");
        }
        return Ok(None);
    }
    let run = RegularWaveRun::new(args.amplitude.unwrap_or(AMPLITUDE), args.ramp.unwrap_or(RAMP), args.duration)
        .context("--time-domain")?;
    Ok(Some(run))
}

/// `ξ` measured at each of `omegas` \[rad/s] by a run of a copy of `world` on every core; a
/// progress line on stderr when it is a terminal.
fn measure(
    world: &World,
    model: &LinearModel,
    run: &RegularWaveRun,
    omegas: &[f64],
    heading: f64,
) -> anyhow::Result<Vec<ComplexVector6>> {
    let mut measured = vec![None; omegas.len()];
    let progress = std::io::stderr().is_terminal();
    let mut finished = 0;
    let outcome = Runner::on_all_cores().run(
        omegas.iter().copied().enumerate(),
        |&(_, omega), _| run.measure(world.clone(), model, TAU / omega, heading),
        |(position, omega), result| {
            let xi = result.with_context(|| format!("the run at T = {:.3} s", TAU / omega))?;
            measured[position] = Some(xi);
            finished += 1;
            if progress {
                eprint!("\rtime domain: {finished} of {} periods run", omegas.len());
            }
            anyhow::Ok(())
        },
    );
    if progress && finished > 0 {
        eprintln!();
    }
    outcome?;
    measured.into_iter().collect::<Option<Vec<_>>>().context("a period was not run")
}

/// Each run's length, or the range of them.
fn durations(run: &RegularWaveRun, omegas: &[f64]) -> String {
    let lengths = omegas.iter().map(|omega| run.duration(TAU / omega));
    let (least, most) = lengths.fold((f64::INFINITY, 0.0_f64), |(a, b), d| (a.min(d), b.max(d)));
    if least == most { format!("{least:.0} s") } else { format!("{least:.0} to {most:.0} s") }
}

/// The heading of the sea's first wave component \[rad], 0 in calm water.
fn sea_heading(system: &tether_physics::system::System) -> f64 {
    system.water().and_then(|stage| stage.water.sea().components().first().map(|c| c.heading)).unwrap_or(0.0)
}

/// The table for people: one line per frequency.
fn text(rows: &[RaoRow]) -> String {
    let mut out = format!("{:>9} {:>9}", "T [s]", "ω [rad/s]");
    for (name, unit) in DOFS {
        out += &format!(" {:>15} {:>8}", format!("{name} [{unit}]"), "phase°");
    }
    out += "\n";
    for row in rows {
        out += &format!("{:>9.3} {:>9.4}", TAU / row.omega, row.omega);
        match &row.response {
            Some(xi) => {
                for (amplitude, phase) in polar(xi) {
                    out += &format!(" {amplitude:>15.5} {phase:>8.2}");
                }
            }
            None => out += "  singular (an undamped resonance)",
        }
        out += "\n";
    }
    out
}

/// The time domain beside the frequency domain, one line per period and dof, and the largest
/// differences.
fn comparison(rows: &[RaoRow], measured: &[ComplexVector6]) -> String {
    let mut out = format!(
        "{:>9} {:>9}  {:<14} {:>20} {:>20} {:>18}\n",
        "T [s]", "ω [rad/s]", "dof", "frequency domain", "time domain", "time − frequency"
    );
    let cell = |(amplitude, phase): (f64, f64)| format!("{amplitude:.5} ∠{phase:>8.2}°");
    // (|%|, °, where) of the largest amplitude and phase differences.
    let mut worst: [(f64, String); 2] = Default::default();
    let dof_largest: [f64; 6] = std::array::from_fn(|dof| {
        rows.iter().filter_map(|row| row.response.map(|fd| fd[dof].norm())).fold(0.0, f64::max)
    });
    for (row, td) in rows.iter().zip(measured) {
        let period = TAU / row.omega;
        let largest = row.response.map_or(0.0, |fd| fd.iter().map(|x| x.norm()).fold(0.0, f64::max));
        let small = |fd: &ComplexVector6, dof: usize| fd[dof].norm() < NEGLIGIBLE * largest.max(dof_largest[dof]);
        for (dof, ((name, unit), td_polar)) in DOFS.iter().zip(polar(td)).enumerate() {
            let lead = if dof == 0 { format!("{period:>9.3} {:>9.4}", row.omega) } else { " ".repeat(19) };
            let fd_cell = row.response.map_or_else(|| "singular".to_string(), |fd| cell(polar(&fd)[dof]));
            let difference = row.response.filter(|fd| !small(fd, dof)).map(|fd| {
                let amplitude = 100.0 * (td[dof].norm() / fd[dof].norm() - 1.0);
                let phase = (td[dof] / fd[dof]).arg().to_degrees();
                let at = format!("{name} at T = {period:.3} s");
                for (slot, value) in worst.iter_mut().zip([amplitude, phase]) {
                    if value.abs() > slot.0.abs() {
                        *slot = (value, at.clone());
                    }
                }
                format!("{amplitude:>+8.2} % {phase:>+7.2}°")
            });
            out += &format!(
                "{lead}  {:<14} {fd_cell:>20} {:>20} {:>18}\n",
                format!("{name} [{unit}]"),
                cell(td_polar),
                difference.unwrap_or_else(|| "—".to_string())
            );
        }
    }
    let [(amplitude, amplitude_at), (phase, phase_at)] = worst;
    out += &format!(
        "\nlargest differences (of responses above {NEGLIGIBLE:e} of their period's largest and of their dof's): {amplitude:+.2} % ({amplitude_at}), {phase:+.2}° ({phase_at})\n"
    );
    out
}

/// The same table as CSV, one row per frequency (a singular one left empty), the time domain's
/// columns after the frequency domain's when measured.
fn csv(rows: &[RaoRow], measured: Option<&[ComplexVector6]>) -> String {
    let mut out = "period_s,omega_rad_s".to_string();
    let columns = |out: &mut String, tag: &str| {
        for (name, unit) in DOFS {
            let unit = unit.replace('/', "_per_");
            *out += &format!(",{name}{tag}_{unit},{name}{tag}_phase_deg");
        }
    };
    columns(&mut out, "");
    if measured.is_some() {
        columns(&mut out, "_td");
    }
    out += "\n";
    for (position, row) in rows.iter().enumerate() {
        out += &format!("{},{}", TAU / row.omega, row.omega);
        let cells = |out: &mut String, xi: Option<&ComplexVector6>| match xi {
            Some(xi) => {
                for (amplitude, phase) in polar(xi) {
                    *out += &format!(",{amplitude},{phase}");
                }
            }
            None => *out += &",".repeat(12),
        };
        cells(&mut out, row.response.as_ref());
        if let Some(measured) = measured {
            cells(&mut out, measured.get(position));
        }
        out += "\n";
    }
    out
}

/// The body's modes at the static equilibrium (`--natural-periods`), longest first: the period
/// with `A(ω_n)` and with `A∞`, the dominant dof and the shape (m and rad, the dominant one 1).
fn natural_periods(system: &tether_physics::system::System, name: &str) -> anyhow::Result<String> {
    use tether_physics::natural_periods::{AddedMassAt, at_equilibrium};
    use tether_physics::statics::{Settings, equilibrium};
    let solved = equilibrium::solve(system, system.initial_states(), &[], &Settings::default())
        .context("--natural-periods needs the static equilibrium")?;
    let index = system.bodies().iter().position(|b| b.name == name).context("no such body")?;
    let modes = |added| at_equilibrium(system, &solved, index, added).context("the body has no potential flow");
    let (resonant, infinite) = (modes(AddedMassAt::Resonance)?, modes(AddedMassAt::Infinite)?);
    let mut out = format!(
        "\nnatural periods of body \"{name}\" at the static equilibrium, undamped (couplings included; PHYSICS.md §9):\n{:<7} {:>12} {:>12}  shape (surge sway heave [m], roll pitch yaw [rad])\n",
        "mode", "A(ω_n) [s]", "A∞ [s]"
    );
    for mode in &resonant {
        // The same mode with A∞: the one dominated by the same dof nearest in period.
        let with_infinite = infinite
            .iter()
            .filter(|m| m.dominant == mode.dominant)
            .map(|m| m.period)
            .min_by(|a, b| (a - mode.period).abs().total_cmp(&(b - mode.period).abs()));
        let shape: Vec<String> = mode.shape.iter().map(|x| format!("{x:+.3}")).collect();
        out += &format!(
            "{:<7} {:>12.3} {:>12}  {}\n",
            DOFS[mode.dominant].0,
            mode.period,
            with_infinite.map_or_else(|| "—".to_owned(), |p| format!("{p:.3}")),
            shape.join(" ")
        );
    }
    Ok(out)
}
