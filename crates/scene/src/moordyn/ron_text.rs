//! The imported scene as readable RON: the source file named in the opening comment with the
//! units, the file's line types as named comments, the options used and ignored, the warnings,
//! and above each body and line a comment saying what it was in the file (and its line there).

use super::Located;
use super::input::Input;
use super::mapping::{Mapped, Origin};

/// RON text and, for each of its lines, the line of the MoorDyn file it comes from (0: none),
/// so that a problem the scene's build finds is reported at the file's line.
pub struct Written {
    pub text: String,
    pub origin_of_line: Vec<usize>,
}

/// Writes `mapped` (read from `input`, the file `source`) as commented RON.
///
/// # Errors
/// The scene cannot be written as RON (it always can: its numbers are finite).
pub fn write(input: &Input, mapped: &Mapped, source: &str) -> Result<Written, ron::Error> {
    let body = crate::to_ron(&mapped.file)?;
    let mut lines: Vec<String> = header(input, &mapped.warnings, source);
    let mut origin_of_line = vec![0; lines.len()];
    let mut current = 0;
    let body_lines: Vec<&str> = body.lines().collect();
    for (index, line) in body_lines.iter().enumerate() {
        // An item opens on the line before its `name: "…"`: its comment goes above it.
        let named =
            body_lines.get(index + 1).and_then(|next| item_name(next)).and_then(|name| mapped.origins.get(name));
        if let Some(Origin { line: from, comment }) = named {
            let indent: String = line.chars().take_while(|c| c.is_whitespace()).collect();
            lines.push(format!("{indent}// {comment} (file line {from})"));
            origin_of_line.push(*from);
            current = *from;
        }
        if line.trim_start().starts_with("],") || line.trim() == "]" {
            current = 0;
        }
        lines.push((*line).to_string());
        origin_of_line.push(current);
    }
    Ok(Written { text: lines.join("\n") + "\n", origin_of_line })
}

/// The name in a `name: "…",` line.
fn item_name(line: &str) -> Option<&str> {
    line.trim().strip_prefix("name: \"")?.strip_suffix("\",")
}

fn header(input: &Input, warnings: &[Located], source: &str) -> Vec<String> {
    let mut lines = vec![
        format!("// Imported by `tether import` from the MoorDyn input file {source}."),
        "// Units: SI — m, kg, s, N; a line's `stiffness` is EA/L [N/m] (EA = stiffness × length),".to_string(),
        "// `displaced_area` π d²/4 [m²], damping Ratio(ζ) (MoorDyn's negative BA) or Coefficient(BA N·s).".to_string(),
        "// Every line is Dynamic with the file's segments and coefficients (switch it in the window).".to_string(),
        "// Coupled points and bodies are kinematic bodies at rest: give them a motion (`support:".to_string(),
        "// Kinematic(velocity: Harmonic(amplitude: (2.0, 0.0, 0.0), period: 10.0))`).".to_string(),
        "// Line types of the file (MoorDyn's columns):".to_string(),
    ];
    for t in &input.line_types {
        lines.push(format!(
            "//   {}: Diam {} m, Mass/m {} kg/m, EA {} N, BA/-zeta {}, EI {} N·m², Cd {}, Ca {}, CdAx {}, CaAx {} (file line {})",
            t.name,
            t.diameter,
            t.mass_per_length,
            t.axial_stiffness,
            t.damping,
            t.bending_stiffness,
            t.drag_normal,
            t.added_mass_normal,
            t.drag_tangential,
            t.added_mass_tangential,
            t.line
        ));
    }
    let options = &input.options;
    lines.push(format!(
        "// Options used: g {} m/s², WtrDnsty {} kg/m³, WtrDpth {} m, kBot {} Pa/m, cBot {} Pa·s/m, FrictionCoefficient {}, FricDamp {} N·s/m (each line's friction_speed).",
        options.gravity,
        options.density,
        options.depth,
        options.seabed_stiffness,
        options.seabed_damping,
        options.friction,
        options.friction_damping
    ));
    if !options.unused.is_empty() {
        lines.push(format!(
            "// Options for MoorDyn's own run, not used (Tether starts from the static equilibrium): {}.",
            options.unused.join(", ")
        ));
    }
    for warning in warnings {
        lines.push(format!("// Warning (file line {}): {}", warning.line, warning.message));
    }
    lines
}

/// For a scene that imports to `written`, the origin map as a lookup: RON line (1-based) → file
/// line, the item's or else line 1.
pub fn file_line(written: &Written, ron_line: usize) -> usize {
    written.origin_of_line.get(ron_line.saturating_sub(1)).copied().filter(|l| *l > 0).unwrap_or(1)
}
