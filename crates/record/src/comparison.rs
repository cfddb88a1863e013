//! A measured series beside the model's, in a plot of their own: `plots/fit/<column>` holds
//! `record` (the measured samples, grey points) and `model` (the model's signal, a line), on the
//! `sim_time` timeline. A fit's recording of its fitted run carries one such plot per measured
//! signal, and the window draws them while a fit runs (docs/calibration.md).

use crate::columns::{plot, send};
use crate::rerun;
use crate::{RecordError, paths};
use rerun::RecordingStream;
use rerun::log::TimeColumn;

/// The measured series' colour: grey, apart from every model colour.
pub const RECORD_COLOUR: rerun::Color = rerun::Color(rerun::datatypes::Rgba32::from_rgb(110, 110, 110));

/// The model series' colour.
pub const MODEL_COLOUR: rerun::Color = rerun::Color(rerun::datatypes::Rgba32::from_rgb(31, 119, 180));

/// Logs the series' styles of `column`'s plot, once (static).
///
/// # Errors
/// The stream fails.
pub fn log_styles(stream: &RecordingStream, column: &str) -> Result<(), RecordError> {
    stream.log_static(
        paths::fit_series(column, paths::FIT_RECORD),
        &rerun::SeriesPoints::new().with_names(["record"]).with_colors([RECORD_COLOUR]).with_marker_sizes([2.0]),
    )?;
    stream.log_static(
        paths::fit_series(column, paths::FIT_MODEL),
        &rerun::SeriesLines::new().with_names(["model"]).with_colors([MODEL_COLOUR]).with_widths([2.0]),
    )?;
    Ok(())
}

/// Sends `values` at `times` \[s] as `column`'s `series` ([`paths::FIT_RECORD`] or
/// [`paths::FIT_MODEL`]), one chunk; a model series sent again replaces the one before at the
/// same times (the viewer shows the latest row at each time).
///
/// # Errors
/// The stream fails, or `times` and `values` differ in length.
pub fn send_series(
    stream: &RecordingStream,
    column: &str,
    series: &str,
    times: &[f64],
    values: &[f64],
) -> Result<(), RecordError> {
    if times.is_empty() {
        return Ok(());
    }
    // On `sim_time` alone: the samples are not world steps.
    let timelines = [TimeColumn::new_duration_secs(crate::SIM_TIME, times.iter().copied())];
    send(stream, &paths::fit_series(column, series), timelines, vec![plot(values.to_vec(), 1)])
}
