//! Numbers written for a person: significant digits (never a float's full expansion), an SI
//! prefix where the unit takes one (`1.2 ms`, `66 kN`, `6.9 MJ`), a power of ten written as
//! such (`2.1×10⁹ s`) where it does not, integers as integers, zero as `0`. The window's panel
//! uses it for every figure it shows; a number field shows [`editable`] text, which it also
//! parses back.
//!
//! Crates considered: `numfmt` and `human_format` format a number with a suffix but know nothing
//! of which units take which prefix (a time step in `Gs`, a mass in `kkg`) nor of a field whose
//! text must parse back; the rules fit in this module.

/// The SI prefixes from 10⁻⁹ to 10⁹, by exponent.
const PREFIXES: [(i32, &str); 7] = [(-9, "n"), (-6, "µ"), (-3, "m"), (0, ""), (3, "k"), (6, "M"), (9, "G")];

/// The exponents of the prefixes a unit takes, smallest and largest: the ones a person reads on
/// an engineer's drawing (`ms`, `mm`, `km`, `kN`, `MJ`, `kN/m`); none for the others (`kg`,
/// `°`, `rad`, `–`, `m²`, `N/m³`…).
fn prefix_range(unit: &str) -> (i32, i32) {
    match unit {
        "s" => (-9, 0),
        "m" => (-6, 3),
        "N" | "J" | "W" | "Pa" | "N/m" | "N·m" | "N·s/m" => (-3, 9),
        _ => (0, 0),
    }
}

/// Plain decimals are written between these magnitudes; a power of ten outside.
const PLAIN: std::ops::Range<f64> = 1e-3..1e6;

/// `x` rounded to `digits` significant digits, as a plain decimal with no trailing zeros, or
/// `None` outside [`PLAIN`] (after rounding).
fn plain(x: f64, digits: usize) -> Option<String> {
    let rounded = round_significant(x, digits);
    if !PLAIN.contains(&rounded.abs()) {
        return None;
    }
    let magnitude = rounded.abs().log10().floor() as i32;
    let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
    Some(trim_zeros(format!("{rounded:.decimals$}")))
}

/// `x` rounded to `digits` (≥ 1) significant digits.
fn round_significant(x: f64, digits: usize) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    // Through the decimal text Rust writes: exact, where scaling by a power of ten is not.
    format!("{:.*e}", digits.max(1) - 1, x).parse().unwrap_or(x)
}

/// `12.500` → `12.5`, `3.000` → `3`, `120` → `120`.
fn trim_zeros(text: String) -> String {
    if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.').to_string() } else { text }
}

/// `x` as `mantissa` and power of ten, the mantissa rounded to `digits` significant digits.
fn scientific(x: f64, digits: usize) -> (String, i32) {
    let text = format!("{:.*e}", digits.max(1) - 1, x);
    // Rust writes `1.25e-7`: a mantissa, `e`, an exponent.
    let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
    (trim_zeros(mantissa.to_string()), exponent.parse().unwrap_or(0))
}

/// `n` in superscript digits: `-7` → `⁻⁷`.
fn superscript(n: i32) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let digits = n.unsigned_abs().to_string().chars().map(|c| DIGITS[c as usize - '0' as usize]).collect::<String>();
    if n < 0 { format!("⁻{digits}") } else { digits }
}

/// A real number to read: `digits` significant digits, trailing zeros dropped, a plain decimal
/// between 10⁻³ and 10⁶ and `1.25×10⁻⁷` outside; `0` for zero, `-0` too.
pub fn number(x: f64, digits: usize) -> String {
    written(x, digits, |mantissa, exponent| format!("{mantissa}×10{}", superscript(exponent)))
}

/// `x` to `digits` significant digits: `0`, a non-finite value's name, a plain decimal between
/// 10⁻³ and 10⁶, or else the mantissa and power of ten as `power` writes them.
fn written(x: f64, digits: usize, power: impl Fn(&str, i32) -> String) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return non_finite(x);
    }
    plain(x, digits).unwrap_or_else(|| {
        let (mantissa, exponent) = scientific(x, digits);
        power(&mantissa, exponent)
    })
}

/// A quantity to read in `unit`: [`number`]'s digits with the SI prefix that brings the
/// mantissa between 1 and 1000 when the unit takes it (`1.2 ms`, `66.2 kN`, `230 m`); else the
/// unit itself, with a power of ten beyond 10⁶ and under 10⁻³ (`2.07×10⁹ s`).
pub fn quantity(x: f64, unit: &str, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{} {unit}", number(x, digits));
    }
    let (low, high) = prefix_range(unit);
    let magnitude = round_significant(x, digits).abs().log10().floor() as i32;
    let natural = magnitude.div_euclid(3) * 3;
    let exponent = if (low..=high).contains(&natural) { natural } else { 0 };
    let prefix = PREFIXES.iter().find(|(e, _)| *e == exponent).map_or("", |(_, p)| p);
    let mantissa = x / 10f64.powi(exponent);
    format!("{} {prefix}{unit}", number(mantissa, digits))
}

/// [`quantity`] with its sign always written (`+1.2 J`, `−3 J`, `0 J`), for a change.
pub fn change(x: f64, unit: &str, digits: usize) -> String {
    let text = quantity(x, unit, digits);
    if x > 0.0 { format!("+{text}") } else { text }
}

/// [`number`] with its sign always written (`+1.2×10⁻⁹`, `-3`, `0`), for a change.
pub fn signed(x: f64, digits: usize) -> String {
    let text = number(x, digits);
    if x > 0.0 { format!("+{text}") } else { text }
}

/// A count: `20`, `1500`.
pub fn count(n: impl Into<u64>) -> String {
    n.into().to_string()
}

/// A number field's text, which [`parse`] reads back: `digits` significant digits, no trailing
/// zeros, integers with no decimals, `2.5e10` (Rust's notation) beyond 10⁶ and under 10⁻³.
pub fn editable(x: f64, digits: usize) -> String {
    written(x, digits, |mantissa, exponent| format!("{mantissa}e{exponent}"))
}

/// A number as a person types it: spaces ignored, `−` (U+2212) as `-`, `×10` for `e`
/// (`2.5×10^6` and `2.5×10⁶` too), `,` as the decimal point when there is no `.`; `None` when
/// it is not a number.
pub fn parse(text: &str) -> Option<f64> {
    let mut plain: String =
        text.chars().filter(|c| !c.is_whitespace()).map(|c| if c == '−' { '-' } else { c }).collect();
    if !plain.contains('.') {
        plain = plain.replace(',', ".");
    }
    let plain = plain.replace("×10^", "e").replace("*10^", "e");
    let plain = match plain.split_once("×10") {
        Some((mantissa, power)) => format!("{mantissa}e{}", from_superscript(power)?),
        None => plain,
    };
    plain.parse::<f64>().ok().filter(|x| x.is_finite())
}

/// `⁻⁷` → `-7`.
fn from_superscript(text: &str) -> Option<String> {
    text.chars()
        .map(|c| match c {
            '⁻' => Some('-'),
            '⁰' => Some('0'),
            '¹' => Some('1'),
            '²' => Some('2'),
            '³' => Some('3'),
            '⁴'..='⁹' => char::from_digit(c as u32 - '⁴' as u32 + 4, 10),
            _ => None,
        })
        .collect()
}

fn non_finite(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x > 0.0 {
        "∞".into()
    } else {
        "−∞".into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cases issue 35 quotes, as a person reads them.
    #[test]
    fn the_window_s_figures_read_as_a_person_writes_them() {
        assert_eq!(quantity(29.132499999977455, "s", 5), "29.132 s");
        assert_eq!(change(0.0, "J", 4), "0 J");
        assert_eq!(change(1.678e-15, "J", 4), "+1.678×10⁻¹⁵ J");
        assert_eq!(change(-6.9e6, "J", 4), "-6.9 MJ");
        assert_eq!(quantity(5.659, "s", 4), "5.659 s");
        assert_eq!(quantity(2.074e9, "s", 4), "2.074×10⁹ s");
        assert_eq!(quantity(5e-2, "s", 4), "50 ms");
        assert_eq!(quantity(1.25e-4, "s", 4), "125 µs");
        assert_eq!(quantity(0.0, "°", 4), "0 °");
        assert_eq!(signed(4.32e17, 3), "+4.32×10¹⁷");
        assert_eq!(signed(-0.25, 3), "-0.25");
        assert_eq!(count(20u32), "20");
        assert_eq!(quantity(66_180.0, "N", 4), "66.18 kN");
        assert_eq!(quantity(241.37, "m", 4), "241.4 m");
        assert_eq!(quantity(1700.0, "m", 4), "1.7 km");
        assert_eq!(quantity(0.0052, "m", 3), "5.2 mm");
        assert_eq!(quantity(200_000.0, "N/m", 4), "200 kN/m");
        assert_eq!(quantity(1025.0, "kg/m³", 4), "1025 kg/m³", "no prefix on a compound of kg");
        assert_eq!(quantity(3.0e7, "N/m³", 4), "3×10⁷ N/m³");
    }

    #[test]
    fn rounding_carries_into_the_next_prefix_and_digit() {
        assert_eq!(quantity(999.96, "N", 4), "1 kN");
        assert_eq!(quantity(0.99996, "s", 4), "1 s");
        assert_eq!(number(9.99996e5, 4), "1×10⁶");
        assert_eq!(number(0.1 + 0.2, 6), "0.3");
        assert_eq!(number(-2.5e-7, 3), "-2.5×10⁻⁷");
    }

    #[test]
    fn a_field_s_text_reads_back_to_its_value() {
        for (x, text) in [
            (0.0, "0"),
            (20.0, "20"),
            (200_000.0, "200000"),
            (2.5e10, "2.5e10"),
            (1.2e-7, "1.2e-7"),
            (0.001, "0.001"),
            (-5.0, "-5"),
            (1.60334, "1.60334"),
        ] {
            assert_eq!(editable(x, 6), text);
            assert_eq!(parse(text), Some(x), "{text}");
        }
        assert_eq!(editable(1.0 / 3.0, 6), "0.333333");
    }

    #[test]
    fn numbers_are_read_as_people_type_them_and_text_is_not_a_number() {
        assert_eq!(parse(" 1 234.5 "), Some(1234.5));
        assert_eq!(parse("−3"), Some(-3.0));
        assert_eq!(parse("2,5"), Some(2.5));
        assert_eq!(parse("2.5×10⁻³"), Some(2.5e-3));
        assert_eq!(parse("4×10^6"), Some(4e6));
        assert_eq!(parse("abc"), None);
        assert_eq!(parse(""), None);
        assert_eq!(parse("1e999"), None, "not a finite number");
        assert_eq!(parse("NaN"), None);
    }
}
