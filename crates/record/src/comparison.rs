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

/// The measured samples' marker size and the model line's width [UI points]: small points on a
/// wider line, so that a record sampled densely still shows the model under it (points of 2 on a
/// line of 2 hid it entirely, checked in the 0.36.3 viewer).
pub const RECORD_MARKER: f32 = 1.0;
pub const MODEL_WIDTH: f32 = 3.0;

/// An earlier iteration's model curve: the model's colour, faded.
pub const EARLIER_COLOUR: rerun::Color =
    rerun::Color(rerun::datatypes::Rgba32::from_unmultiplied_rgba(31, 119, 180, 110));

/// Logs the series' styles of `column`'s plot, once (static).
///
/// # Errors
/// The stream fails.
pub fn log_styles(stream: &RecordingStream, column: &str) -> Result<(), RecordError> {
    stream.log_static(
        paths::fit_series(column, paths::FIT_RECORD),
        &rerun::SeriesPoints::new()
            .with_names(["record"])
            .with_colors([RECORD_COLOUR])
            .with_marker_sizes([RECORD_MARKER]),
    )?;
    stream.log_static(
        paths::fit_series(column, paths::FIT_MODEL),
        // Visible, said every time: a second fit in the same recording draws its drafts at the
        // paths of the first fit's, which were hidden as earlier iterations.
        &rerun::SeriesLines::new()
            .with_names(["model"])
            .with_colors([MODEL_COLOUR])
            .with_widths([MODEL_WIDTH])
            .with_visible_series([true]),
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
/// `draft − 1`, so that the plot shows the record and the latest curve.
///
/// The earlier curve is hidden by its style, logged again (static, the latest wins) as a faded
/// series named "earlier iterations" that is not visible: the legend keeps one hollow entry of
/// that name, which shows every earlier curve when clicked. Checked in the 0.36.3 viewer, where
/// neither a second series at the same times nor a `Clear` takes the first one away
/// ([`send_series`]), and a static NaN over it hides it but is reported as an error (a time
/// series cannot plot static data). Curves under one name share their legend entry: hidden
/// under "model", the latest would be hidden too.
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
        // Visible, said every time: a second fit in the same recording draws its drafts at the
        // paths of the first fit's, which were hidden as earlier iterations.
        &rerun::SeriesLines::new()
            .with_names(["model"])
            .with_colors([MODEL_COLOUR])
            .with_widths([MODEL_WIDTH])
            .with_visible_series([true]),
    )?;
    send_series(stream, column, &series, times, values)?;
    if let Some(before) = draft.checked_sub(1) {
        let earlier = format!("{}/{before}", paths::FIT_MODEL);
        stream.log_static(
            paths::fit_series(column, &earlier),
            &rerun::SeriesLines::new()
                .with_names(["earlier iterations"])
                .with_colors([EARLIER_COLOUR])
                .with_widths([1.0])
                .with_visible_series([false]),
        )?;
    }
    Ok(())
}
