//! Water: hydrostatics, waves, current and hydrodynamic loads (PHYSICS.md §6).
//!
//! Water is an environment stage of the force evaluation ([`crate::system`]): declared by the
//! scene ([`crate::system::System::with_water`]), skipped when it declares none. It acts on the
//! bodies that declare [`Hydro`] coefficients, each with a closed [`Hull`] (its boundary mesh),
//! and writes each one's [`WaterForces`] to its own buffer of the evaluation before they are
//! summed into the loads, so they can be plotted.
//!
//! For each floating body, at the time of the evaluation (the water stage, [`crate::water_stage`],
//! which runs these rooms and [`crate::potential`] together):
//! 1. *pressure*: the pressure `p = ρ g (z_w − z) + p_d` at each hull vertex, once per vertex
//!    ([`environment`], [`waves`]); each triangle clipped at `p = 0` and `p` integrated exactly
//!    over its wet part ([`pressure`]): hydrostatics and Froude–Krylov;
//! 2. *Morison*: drag, damping and rotational drag from the flow relative to the body at its
//!    drag centre, the drag scaled by the wetted fraction, the declared dampers in full
//!    ([`morison`]; current from [`current`]);
//! 3. *added mass*: the fluid's inertia (and the diffraction force `M_a u̇`) as a reaction that
//!    turns the total load into the one the rigid-body equations need, so that every
//!    integrator solves `(m E + M_a) γ = F + M_a u̇` without knowing of it ([`added_mass`]);
//! 4. *potential flow* (a body with a panel code's data, PHYSICS.md §9, [`crate::potential`]):
//!    step 1 without the incident wave's pressure and step 3 without Morison's added mass; the
//!    radiation force, the excitation and the reaction of `A∞` instead;
//! 5. *power*: `Σ F·v + M·ω` of the water's forces, booked as external work.
//!
//! [`hydrostatics`] gives the still-water properties a naval architect checks (displacement,
//! draft, centre of buoyancy, waterplane, metacentric heights, natural periods); [`spectrum`]
//! builds an irregular sea from a JONSWAP spectrum; [`dispersion`] solves `ω² = g k tanh(k h)`.
//!
//! | quantity | unit | quantity | unit |
//! |---|---|---|---|
//! | density ρ | kg/m³ | pressure p | Pa = N/m² |
//! | wave height H, amplitude a | m | period T | s |
//! | frequency ω | rad/s | wave number k | rad/m |
//! | drag coefficient C_d, added-mass coefficient C_a | – | rotational drag C_r | N·m·s² |
//! | linear damping | N·s/m | rotational damping | N·m·s |
//! | added inertia | kg·m² | headings | rad (degrees in scene files) |

pub mod added_mass;
pub mod current;
pub mod dispersion;
pub mod environment;
pub mod forces;
pub mod hull;
pub mod hydrostatics;
pub mod morison;
pub mod pressure;
pub mod spectrum;
pub mod waves;

pub use environment::{CurrentProfile, CurrentSpec, Water, WaterError, WaterField, WaterSpec, WaveSpec};
pub use forces::WaterForces;
pub use hull::Hull;
pub use morison::Hydro;
