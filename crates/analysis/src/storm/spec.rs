//! A storm as a sweep (docs/design-loads.md): one factor, `seed`, setting every random seed the
//! scene has — the JONSWAP sea's (`water.waves.seed`) and the gusts' (`air.wind.gusts.seed`) —
//! to the same value, the seeds `first, first + 1, …`; each case runs the warm-up and then the
//! storm's hours, and measures after the warm-up, per catenary, its largest and mean tension and,
//! per moving body, its largest excursion from the start.
//!
//! The spec is text the sweep's own reader checks ([`crate::sweep::Plan::from_text`]), so a storm
//! directory is a sweep directory: `tether sweep merge` joins its shards and the window's sweep
//! table lists its seeds.

use super::StormError;
use crate::sweep::Plan;
use std::path::Path;
use tether_scene::air::GustsDef;
use tether_scene::file::{CouplingDef, SceneFile};
use tether_scene::water::WavesDef;

/// What a storm is asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StormRequest {
    /// The storm's length after the warm-up \[h] > 0.
    pub hours: f64,
    /// The warm-up before the maxima are taken \[s] ≥ 0 (the ramps, and the slow drift's
    /// transient from the start pose).
    pub warmup: f64,
    /// Number of seeds ≥ 2 (a Gumbel fit needs two maxima).
    pub seeds: u32,
    /// The first seed.
    pub first_seed: u64,
}

/// A measured column's name: `<line>.storm_tension_max_N`.
pub fn tension_max(line: &str) -> String {
    format!("{line}.storm_tension_max_N")
}

/// `<line>.storm_tension_mean_N`.
pub fn tension_mean(line: &str) -> String {
    format!("{line}.storm_tension_mean_N")
}

/// `<body>.storm_offset_max_m`.
pub fn offset_max(body: &str) -> String {
    format!("{body}.storm_offset_max_m")
}

/// The scene file's seed paths: the JONSWAP sea's and the gusts', where it has them.
pub fn seed_paths(file: &SceneFile) -> Vec<&'static str> {
    let mut paths = Vec::new();
    if let Some(water) = &file.water {
        match water.waves {
            WavesDef::Jonswap { .. } => paths.push("water.waves.seed"),
            WavesDef::Calm | WavesDef::Regular { .. } => {}
        }
    }
    if let Some(air) = &file.air {
        match air.wind.gusts {
            GustsDef::Npd { .. } | GustsDef::Kaimal { .. } => paths.push("air.wind.gusts.seed"),
            GustsDef::Steady => {}
        }
    }
    paths
}

/// The storm's sweep of the scene at `scene` (its file `file`, the bodies that move `moving`).
///
/// # Errors
/// A request out of range, or a scene with nothing random to seed.
pub fn plan(scene: &Path, file: &SceneFile, moving: &[String], request: &StormRequest) -> Result<Plan, StormError> {
    let text = spec_text(scene, file, moving, request)?;
    Ok(Plan::from_text(Path::new("storm.ron"), text, None)?)
}

/// The sweep spec's text (module docs).
///
/// # Errors
/// As [`plan`].
pub fn spec_text(
    scene: &Path,
    file: &SceneFile,
    moving: &[String],
    request: &StormRequest,
) -> Result<String, StormError> {
    let refuse = |message: String| Err(StormError::Scene(message));
    if !(request.hours.is_finite() && request.hours > 0.0) {
        return refuse(format!("--hours must be > 0 h, got {}", request.hours));
    }
    if !(request.warmup.is_finite() && request.warmup >= 0.0) {
        return refuse(format!("--warmup must be ≥ 0 s, got {}", request.warmup));
    }
    if request.seeds < 2 {
        return refuse(format!("--seeds must be at least 2 (a Gumbel fit needs two maxima), got {}", request.seeds));
    }
    let paths = seed_paths(file);
    if paths.is_empty() {
        return refuse(format!(
            "{}: nothing in the scene is random (no JONSWAP sea, no gusts): every seed would be the same storm",
            scene.display()
        ));
    }
    let paths: Vec<String> = paths.iter().map(|p| format!("{p:?}")).collect();
    let seeds: Vec<String> = (0..u64::from(request.seeds)).map(|i| (request.first_seed + i).to_string()).collect();
    let after = request.warmup;
    let mut metrics = Vec::new();
    for coupling in &file.couplings {
        if let CouplingDef::Catenary { name, .. } = coupling {
            metrics.push(format!(
                "Metric(name: {:?}, of: Tension({name:?}), take: Max, after: {after:?})",
                tension_max(name)
            ));
            metrics.push(format!(
                "Metric(name: {:?}, of: Tension({name:?}), take: Mean, after: {after:?})",
                tension_mean(name)
            ));
        }
    }
    for body in moving {
        metrics.push(format!(
            "Metric(name: {:?}, of: Excursion({body:?}), take: Max, after: {after:?})",
            offset_max(body)
        ));
    }
    let scene = std::path::absolute(scene).map_err(|e| StormError::Scene(format!("{}: {e}", scene.display())))?;
    Ok(format!(
        "Sweep(name: \"storm\", scene: {:?}, duration: {:?}, design: Grid, standard_metrics: false,\n    \
         factors: [Factor(name: \"seed\", path: [{}], values: List([{}]))],\n    metrics: [\n        {}\n    ],\n)\n",
        scene.display().to_string(),
        request.warmup + 3600.0 * request.hours,
        paths.join(", "),
        seeds.join(", "),
        metrics.join(",\n        ")
    ))
}
