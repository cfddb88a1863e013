//! Potential-flow hydrodynamics from a panel code (PHYSICS.md §9, its drift §10): a body's frequency-domain
//! coefficients, its radiation kernel `K(t)`, and the radiation force by direct convolution (the
//! reference) or by a state-space approximation fitted to the kernel.
//!
//! Stages, in the order a body's data go through them:
//! - [`coefficients`]: `A(ω)`, `B(ω)`, `A∞`, `A(0)`, `X(ω, β)` about the body's reference point,
//!   checked once by [`Coefficients::new`];
//! - [`kernel`]: `K(t) = (2/π) ∫ B(ω) cos(ωt) dω`, each linear piece of `B` integrated exactly,
//!   and its cross-check from `A(ω) − A∞`;
//! - [`convolution`]: `F_r = −∫ K(t − τ) q̇(τ) dτ` over a history of `q̇`, by the trapezoid rule;
//! - [`state_space`]: `ẋ = A_r x + B_r q̇`, `F_r = −C_r x`, fitted to `K(t)` per nonzero pair;
//! - [`response`]: the linear frequency-domain response `ξ(ω)` in regular waves (the RAO);
//! - in the time domain: [`body`] (`A∞` in the generalised mass about the reference point, the
//!   forces moved to G), [`radiation`] (the radiation memory carried through the integrators'
//!   evaluations and committed at accepted steps), [`excitation`] (per wave component) and
//!   [`hydrostatics`] (the mesh's, or linear from the panel code's `.hst`), and [`drift`]: the
//!   second-order mean and slow drift from the panel code's mean drift coefficients (§10).

pub mod body;
pub mod coefficients;
pub mod convolution;
pub mod drift;
pub mod excitation;
pub mod hydrostatics;
pub mod kernel;
pub mod radiation;
pub mod response;
pub mod state_space;
pub mod tables;

pub use body::{PotentialBody, PotentialError, PotentialSpec};
pub use coefficients::{
    Coefficients, CoefficientsData, CoefficientsError, ComplexVector6, Excitation, Matrix6, Vector6,
};
pub use convolution::Convolution;
pub use drift::{DriftModel, DriftSource, MeanDrift, WaveDrift};
pub use excitation::{HeadingMissing, WaveExcitation};
pub use hydrostatics::{HydrostaticsModel, LinearHydrostatics};
pub use kernel::SampledKernel;
pub use radiation::{Radiation, RadiationMethod, RadiationRun};
pub use state_space::{FitError, FitSettings, PairFit, RadiationStateSpace};
