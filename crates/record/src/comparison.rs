//! A measured series beside the model's, in a plot of their own: `plots/fit/<column>` holds
//! `record` (the measured samples, grey points) and `model` (the model's signal, a line), on the
//! `sim_time` timeline. A fit's recording of its fitted run carries one such plot per measured
//! signal, and the window draws them while a fit runs (docs/calibration.md), each new model
//! curve in place of the last ([`send_model_draft`]).

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
/// [`paths::FIT_MODEL`]), one chunk. A series sent again at the same times does not replace the
/// one before: the viewer's time series keep every row and draw the rows at one time as their
/// min–max (two curves become a band between them; a `Clear` does not remove them either,
/// checked in the 0.36.3 viewer): a curve that changes is sent with [`send_model_draft`].
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

/// Sends `column`'s model curve number `draft` of a fit in progress (0, 1, 2… within one
/// recording) as `plots/fit/<column>/model/<draft>`, with the model's style, and hides curve
/// `draft − 1`, so that the plot shows the record and the latest curve only.
///
/// Hiding is a static NaN logged on the earlier curve's entity: static data shadows an entity's
/// temporal data in every query, the viewer's time series included, and a NaN draws nothing
/// (the legend keeps one "model"). Checked in the 0.36.3 viewer; neither a second series at the
/// same times nor a `Clear` takes the first one away ([`send_series`]).
///
/// # Errors
/// The stream fails, or `times` and `values` differ in length.
pub fn send_model_draft(
    stream: &RecordingStream,
    column: &str,
    draft: u32,
    times: &[f64],
    values: &[f64],
) -> Result<(), RecordError> {
    let series = format!("{}/{draft}", paths::FIT_MODEL);
    stream.log_static(
        paths::fit_series(column, &series),
        &rerun::SeriesLines::new().with_names(["model"]).with_colors([MODEL_COLOUR]).with_widths([2.0]),
    )?;
    send_series(stream, column, &series, times, values)?;
    if let Some(before) = draft.checked_sub(1) {
        let hidden = format!("{}/{before}", paths::FIT_MODEL);
        stream.log_static(paths::fit_series(column, &hidden), &rerun::Scalars::new([f64::NAN]))?;
    }
    Ok(())
}
