//! The files of a fit: `report.md` and `report.json`, a chart per signal (`plots/<column>.png`),
//! the recording of the fitted run with each measured series beside the model's
//! (`fitted.rrd`, not for an interrupted fit), and the scene written again with the fitted values in place.

use super::chart;
use super::parameter::Target;
use super::report;
use super::run::Outcome;
use super::setup::Setup;
use super::solver::Ending;
use super::write_back::{self, Edit, HEADER_MARK};
use std::path::{Path, PathBuf};
use tether_record::{FaceArrows, FrameSchedule, Recorder, comparison, layout, paths};

/// Frames per simulated second of the fitted run's recording.
pub const LOG_HZ: f64 = 60.0;

/// Writes the report, the charts and (but for an interrupted fit) the recording into `dir` (made
/// if absent); returns what it wrote, labelled.
///
/// # Errors
/// A file that cannot be written, with its path.
pub fn write_results(setup: &Setup, outcome: &Outcome, dir: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    let io = |path: &Path, e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let plots = dir.join("plots");
    std::fs::create_dir_all(&plots).map_err(|e| io(&plots, &e))?;
    let mut written = Vec::new();
    let scene = setup.model.scene_path.file_stem().map_or_else(|| "scene".into(), |s| s.to_string_lossy().into_owned());
    for (signal, fit) in setup.model.signals.iter().zip(&outcome.signals) {
        let path = plots.join(format!("{}.png", file_name(&signal.column)));
        chart::write(signal, fit, &scene, &path)?;
        written.push((format!("chart of {}", signal.column), path));
    }
    // An interrupted fit stops within a second (crate::interrupt): its best point's recording
    // would be one more run, so it is left out and the report says the fit is partial.
    if outcome.ending != Ending::Cancelled {
        let recording = dir.join("fitted.rrd");
        write_recording(setup, outcome, &recording)?;
        written.push(("recording of the fitted run".into(), recording));
    }
    let markdown = dir.join("report.md");
    std::fs::write(&markdown, report::text(&setup.model, outcome)).map_err(|e| io(&markdown, &e))?;
    written.push(("report".into(), markdown));
    Ok(written)
}

/// Writes `report.json` into `dir` listing `files` too; returns its path.
///
/// # Errors
/// The file cannot be written.
pub fn write_json(
    setup: &Setup,
    outcome: &Outcome,
    files: &[(String, PathBuf)],
    dir: &Path,
) -> Result<PathBuf, String> {
    let path = dir.join("report.json");
    let listed: Vec<(String, String)> = files.iter().map(|(w, p)| (w.clone(), p.display().to_string())).collect();
    let text =
        serde_json::to_string_pretty(&report::json(&setup.model, outcome, &listed)).map_err(|e| e.to_string())?;
    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

/// A column's name as a file name.
fn file_name(column: &str) -> String {
    column.chars().map(|c| if c.is_alphanumeric() || "-_.".contains(c) { c } else { '_' }).collect()
}

/// Records the fitted run at [`LOG_HZ`], with each signal's plot of the record (at the model's
/// time, `t + τ`) and the model.
fn write_recording(setup: &Setup, outcome: &Outcome, path: &Path) -> Result<(), String> {
    let model = &setup.model;
    let fail = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let mut world = model.scene(&outcome.values)?.world;
    let mut recorder = Recorder::to_file(path, &world, &FaceArrows::default()).map_err(|e| fail(&e))?;
    let columns: Vec<&str> = model.signals.iter().map(|s| s.column.as_str()).collect();
    layout::send_layout_with_fits(recorder.stream(), &world, &columns, &layout::Camera::framing(&world))
        .map_err(|e| fail(&e))?;
    let shift = model.shift(&outcome.values);
    for (s, signal) in model.signals.iter().enumerate() {
        let stream = recorder.stream();
        comparison::log_styles(stream, &signal.column).map_err(|e| fail(&e))?;
        let shifted: Vec<f64> = signal.times.iter().map(|t| t + shift).collect();
        comparison::send_series(stream, &signal.column, paths::FIT_RECORD, &shifted, &signal.measured)
            .map_err(|e| fail(&e))?;
        let series = outcome.trajectory.series(s);
        comparison::send_series(stream, &signal.column, paths::FIT_MODEL, &outcome.trajectory.times, &series)
            .map_err(|e| fail(&e))?;
    }
    let steps = (model.end_time / world.dt()).ceil() as u64;
    let frames = FrameSchedule::new(LOG_HZ, world.dt(), steps);
    recorder.log_frame(&world).map_err(|e| fail(&e))?;
    for step in 1..=steps {
        world.step().map_err(|e| fail(&e))?;
        if frames.is_due(step) {
            recorder.log_frame(&world).map_err(|e| fail(&e))?;
        }
    }
    recorder.finish().map_err(|e| fail(&e))?;
    Ok(())
}

/// The scene's text with the fitted values in place and a header saying what was fitted to what,
/// and when (`now` as `YYYY-MM-DD HH:MM UTC`).
///
/// # Errors
/// The text cannot be scanned, or a path cannot be placed in it.
pub fn fitted_scene(setup: &Setup, outcome: &Outcome, now: &str) -> Result<String, String> {
    let model = &setup.model;
    let columns: Vec<&str> = model.signals.iter().map(|s| s.column.as_str()).collect();
    let window = model
        .signals
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| (a.min(s.times[0]), b.max(s.times[s.times.len() - 1])));
    let mut header = format!(
        "{HEADER_MARK} ({}) on {now} to {} (columns {} over {}–{} s){}:\n",
        setup.spec_path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
        setup.record_path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned()),
        columns.join(", "),
        report::number(window.0),
        report::number(window.1),
        if outcome.partial() { ", PARTIAL: stopped before it converged" } else { "" }
    );
    let mut edits = Vec::new();
    for (parameter, fitted) in model.parameters.iter().zip(&outcome.parameters) {
        let interval = match fitted.interval {
            Some((lo, hi)) => format!("95 % {} … {}", report::number(lo), report::number(hi)),
            None => "not determined by the data".into(),
        };
        let was = parameter.scene_value.map_or_else(|| "default".into(), report::number);
        header += &format!("//   {} = {} ({interval}; was {was})\n", parameter.name, report::number(fitted.value));
        if let Target::Scene(paths) = &parameter.target {
            edits.extend(paths.iter().map(|path| Edit { path, value: fitted.value }));
        }
    }
    let file = model.scene_file(&outcome.values)?;
    let generated = tether_scene::to_ron(&file).map_err(|e| e.to_string())?;
    write_back::write(&model.scene_text, &edits, &header, &generated)
}

/// The current time as `YYYY-MM-DD HH:MM UTC`.
pub fn utc_now() -> String {
    let seconds = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rest) = ((seconds / 86_400) as i64, seconds % 86_400);
    let (year, month, day) = civil_from_days(days);
    format!("{year:04}-{month:02}-{day:02} {:02}:{:02} UTC", rest / 3600, rest % 3600 / 60)
}

/// The proleptic Gregorian date of `days` since 1970-01-01 (H. Hinnant's `civil_from_days`).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(month <= 2), month, day)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(20_784), (2026, 11, 27));
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        assert_eq!(file_name("plots/tension/spring"), "plots_tension_spring");
    }
}
