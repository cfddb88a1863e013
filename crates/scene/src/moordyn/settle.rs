//! The imported system starts at rest where MoorDyn's starts after its initial-condition
//! relaxation: its free points and free bodies at static equilibrium (PHYSICS.md §7's Newton
//! solve, `tether equilibrium`), the file's positions being, as in MoorDyn, a first guess.
//! Tether's lines then start in their own discrete static equilibrium (PHYSICS.md §8).

use super::Located;
use crate::file::{SceneFile, SupportDef};
use std::path::Path;
use tether_physics::statics::{Settings, equilibrium};

/// `file` with its free bodies moved to static equilibrium; unchanged, with a warning, when the
/// solve finds none (a system that drifts away, a body with nothing holding it).
pub fn settle(file: SceneFile, warnings: &mut Vec<Located>) -> SceneFile {
    if !file.bodies.iter().any(|b| !matches!(b.support, SupportDef::Kinematic { .. })) {
        return file;
    }
    // The mapping writes only shapes without files, so the folder is never read.
    let Ok(built) = crate::build::build(&file, Path::new(".")) else {
        return file;
    };
    let system = built.world.system();
    match equilibrium::solve(system, system.initial_states(), &[], &Settings::default()) {
        Ok(solved) => crate::pose::with_poses(&file, built.bodies.bodies(), &solved.states),
        Err(error) => {
            warnings.push(Located {
                line: 1,
                col: 1,
                message: format!(
                    "free points and bodies start at the file's positions: no static equilibrium found ({error})"
                ),
            });
            file
        }
    }
}
