//! The record of what the water did to one floating body at an evaluation (PHYSICS.md §6): its
//! own buffer beside the couplings', summed into the body's load by the water stage.

use crate::body::Load;

/// The water's forces on one floating body, about G, world axes [N, N·m].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WaterForces {
    /// Index of the body.
    pub body: usize,
    /// Hydrostatics and Froude–Krylov: the pressure integrated over the wet hull.
    pub pressure: Load,
    /// Morison drag, damping and rotational drag.
    pub drag: Load,
    /// The added mass's reaction, diffraction force included; with potential flow, `A∞`'s
    /// (PHYSICS.md §9).
    pub added_mass: Load,
    /// Potential flow's radiation force `F_r`, moved to G (PHYSICS.md §9).
    pub radiation: Load,
    /// Potential flow's wave excitation `F_exc`, ramped, moved to G.
    pub excitation: Load,
    /// Potential flow's second-order wave drift (PHYSICS.md §10), ramped, moved to G.
    pub drift: Load,
    /// `V_sub` \[m³]: `−∫_wet (z_w − z) n_z dA`.
    pub submerged_volume: f64,
    /// `w = V_sub / V`, within [0, 1].
    pub wetted_fraction: f64,
    /// `−∫_wet n_z dA` \[m²]: the waterplane area (exact for a flat cut).
    pub waterplane_area: f64,
    /// `F·v + M·ω` of all of the above \[W].
    pub power: f64,
}

impl WaterForces {
    /// Everything the water does to the body.
    pub fn total(&self) -> Load {
        Load {
            force: self.pressure.force
                + self.drag.force
                + self.added_mass.force
                + self.radiation.force
                + self.excitation.force
                + self.drift.force,
            moment: self.pressure.moment
                + self.drag.moment
                + self.added_mass.moment
                + self.radiation.moment
                + self.excitation.moment
                + self.drift.moment,
        }
    }
}
