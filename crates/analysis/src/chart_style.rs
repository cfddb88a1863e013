//! What the charts share: the font they are drawn with — DejaVu Sans, shipped in
//! `assets/fonts/` (Bitstream Vera license, beside it) and drawn through plotters' `ab_glyph`
//! backend, so no system font library is needed —, their colours, their axes and their legends.

use plotters::chart::{MeshStyle, SeriesLabelStyle};
use plotters::coord::CoordTranslate;
use plotters::coord::ranged1d::Ranged;
use plotters::prelude::{BLACK, DrawingBackend, WHITE};
use plotters::style::{Color, FontStyle, RGBColor, register_font};

static FONT: &[u8] = include_bytes!("../../../assets/fonts/DejaVuSans.ttf");

/// Colours of successive curves (matplotlib's "tab10").
pub const COLOURS: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

/// A chart that could not be drawn or written: the file and why.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{path}: {message}")]
pub struct ChartError {
    pub path: String,
    pub message: String,
}

/// Makes the bundled font plotters' "sans-serif".
///
/// # Errors
/// The bundled font is not a TrueType font (a broken build).
pub fn register_font_family() -> Result<(), String> {
    register_font("sans-serif", FontStyle::Normal, FONT)
        .map_err(|_| "the bundled font is not a valid TrueType font".to_string())
}

/// The charts' axes: tick labels at 18 px, axis titles at 20 px, a faint major grid and no minor
/// one. Chain the chart's own descriptions and formatters on what it returns.
pub fn axes<'m, 'a, 'b, X: Ranged, Y: Ranged, DB: DrawingBackend>(
    mesh: &'m mut MeshStyle<'a, 'b, X, Y, DB>,
) -> &'m mut MeshStyle<'a, 'b, X, Y, DB> {
    mesh.label_style(("sans-serif", 18))
        .axis_desc_style(("sans-serif", 20))
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.12))
}

/// The charts' legends: labels at `font_size` px in a nearly opaque white box with a faint
/// border. Chain the chart's own position and margin on what it returns, then draw it.
pub fn legend<'s, 'a, 'b, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    labels: &'s mut SeriesLabelStyle<'a, 'b, DB, CT>,
    font_size: u32,
) -> &'s mut SeriesLabelStyle<'a, 'b, DB, CT> {
    labels.label_font(("sans-serif", font_size)).background_style(WHITE.mix(0.9)).border_style(BLACK.mix(0.4))
}

/// The smallest and largest of `values` (`(∞, −∞)` when there are none).
pub fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// `lo..hi` widened on both sides by 5 % of its width, or of its size when the two are (nearly)
/// equal, so that a single value still gets an axis.
pub fn padded((lo, hi): (f64, f64)) -> std::ops::Range<f64> {
    let margin = 0.05 * (hi - lo).abs().max(hi.abs().max(lo.abs()) * 1e-3).max(1e-9);
    (lo - margin)..(hi + margin)
}
