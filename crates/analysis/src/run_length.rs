//! A run's length, checked before its first step: `duration ÷ dt × sub-steps` integrator steps
//! are known in advance, so a run that cannot end in a working day (a `dt` typed as 1e-12 s)
//! is refused in one line — how many steps, which value makes it long, and how long it would
//! take at the speed measured on a short start — instead of starting silently, as a sweep
//! refuses a plan past its `--max-cases` (docs/commands.md).

use std::time::{Duration, Instant};
use tether_physics::stability;
use tether_physics::world::World;

/// The most integrator steps a run may take unless told otherwise (`--max-steps`): 10⁸, past
/// every shipped scene's run by a factor of a hundred (the longest, `chain100`'s bench, takes
/// about 10⁶), and a few minutes even for the cheapest step of about 1 µs.
pub const DEFAULT_MAX_STEPS: u64 = 100_000_000;

/// Wall time spent measuring the speed of a refused run's first steps.
const PROBE: Duration = Duration::from_millis(200);

/// A run past the limit, with what it would cost.
#[derive(Debug, Clone, PartialEq)]
pub struct TooLong {
    /// Integrator steps the run needs.
    pub steps: f64,
    /// The limit it is past.
    pub max_steps: u64,
    /// Estimated wall time \[s] at the measured speed (`None`: the probe's world failed to step).
    pub wall_seconds: Option<f64>,
    /// The value that makes it long, with its figures.
    pub culprit: String,
}

impl std::fmt::Display for TooLong {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "the run needs {:.2e} integrator steps, past the limit of {:.0e}",
            self.steps, self.max_steps as f64
        )?;
        if let Some(wall) = self.wall_seconds {
            write!(f, " (about {} at the speed of its first steps)", readable_duration(wall))?;
        }
        write!(f, ": {}", self.culprit)
    }
}

impl std::error::Error for TooLong {}

/// Integrator steps for `duration` \[s] of `world`: `duration ÷ dt × sub-steps`.
pub fn integrator_steps(world: &World, duration: f64) -> f64 {
    (duration / world.dt()).round().max(1.0) * f64::from(world.substeps())
}

/// `Ok` if `duration` of `world` takes at most `max_steps` integrator steps; else why not, with
/// the wall time estimated from stepping a copy of the world for `PROBE`.
///
/// # Errors
/// [`TooLong`] past the limit.
pub fn check(world: &World, duration: f64, max_steps: u64) -> Result<(), TooLong> {
    let steps = integrator_steps(world, duration);
    if steps <= max_steps as f64 {
        return Ok(());
    }
    Err(TooLong {
        steps,
        max_steps,
        wall_seconds: probe_wall_seconds(world, duration),
        culprit: culprit(world, duration),
    })
}

/// Wall time \[s] of `duration` of `world` at the speed of a copy's first steps.
fn probe_wall_seconds(world: &World, duration: f64) -> Option<f64> {
    let mut probe = world.clone();
    let start = Instant::now();
    let mut steps = 0_u32;
    while start.elapsed() < PROBE {
        probe.step().ok()?;
        steps += 1;
    }
    let per_world_step = start.elapsed().as_secs_f64() / f64::from(steps);
    Some(per_world_step * (duration / world.dt()).round())
}

/// A step this many times below the stable one is the likely cause of a long run: a scene that
/// resolves its fastest motion finely runs at a tenth to a thousandth of the stable step (the
/// shipped `spring_mass` at 1/190), not at a ten-thousandth.
const FAR_BELOW_STABLE: f64 = 1e4;

/// The value that makes the run long: a step far below the stable one, many sub-steps, or
/// else the duration itself.
fn culprit(world: &World, duration: f64) -> String {
    let step = world.step_size();
    let binding = stability::binding(&world.limits());
    match binding.filter(|b| step < b.dt / FAR_BELOW_STABLE) {
        Some(b) => format!(
            "the time step dt = {:.3e} s is {:.1e} times below the stable step {:.3e} s ({}): raise dt",
            world.dt(),
            b.dt / step,
            b.dt,
            b.describe(world.system())
        ),
        None if world.substeps() > 1 => format!(
            "{} sub-steps per step of {:.3e} s over {duration} s: lower the sub-steps or the duration",
            world.substeps(),
            world.dt()
        ),
        None => format!("the duration {duration} s at dt = {:.3e} s: shorten the duration", world.dt()),
    }
}

/// `seconds` as a person reads a long wait: seconds, minutes, hours, days or years.
fn readable_duration(seconds: f64) -> String {
    const UNITS: [(f64, &str); 5] =
        [(365.25 * 86_400.0, "years"), (86_400.0, "days"), (3_600.0, "hours"), (60.0, "minutes"), (1.0, "s")];
    let (size, name) = UNITS.iter().copied().find(|&(size, _)| seconds >= size).unwrap_or((1.0, "s"));
    let value = seconds / size;
    match value {
        v if v < 0.1 => "under 0.1 s".to_string(),
        v if v >= 1e4 => format!("{v:.1e} {name}"),
        v if v >= 100.0 => format!("{v:.0} {name}"),
        v => format!("{v:.1} {name}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_wait_reads_in_its_largest_unit() {
        assert_eq!(readable_duration(0.002), "under 0.1 s");
        assert_eq!(readable_duration(0.3), "0.3 s");
        assert_eq!(readable_duration(42.0), "42.0 s");
        assert_eq!(readable_duration(90.0), "1.5 minutes");
        assert_eq!(readable_duration(7_200.0), "2.0 hours");
        assert_eq!(readable_duration(300.0 * 86_400.0), "300 days");
        // 10¹² s = 31,688.7 years.
        assert_eq!(readable_duration(1e12), "3.2e4 years");
    }
}
