//! What the charts share: the font they are drawn with — DejaVu Sans, shipped in
//! `assets/fonts/` (Bitstream Vera license, beside it) and drawn through plotters' `ab_glyph`
//! backend, so no system font library is needed — and their colours.

use plotters::style::{FontStyle, RGBColor, register_font};

static FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");

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

/// Makes the bundled font plotters' "sans-serif".
///
/// # Errors
/// The bundled font is not a TrueType font (a broken build).
pub fn register_font_family() -> Result<(), String> {
    register_font("sans-serif", FontStyle::Normal, FONT).map_err(|_| "the bundled font is not a valid TrueType font".to_string())
}
