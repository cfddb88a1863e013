//! Pure rigid-body physics for Tether: no GUI, no viewer, no file format (`docs/PHYSICS.md`).
//!
//! The crate is a constant [`system::System`] (gravity, bodies, couplings) and a
//! [`world::World`] that runs it in time with one of five [`integrator`]s.
//!
//! - [`math`]: the shared numeric types;
//! - [`mass_properties`]: mass, centre of mass and principal inertia from master + slave nodes (§1);
//! - [`body`]: a rigid body's constant properties; its state, load, support and kinematics (§1);
//! - [`dynamics`]: accelerations from loads, Euler's equations (§1);
//! - [`table`]: piecewise-linear tables with exact integrals, for curve-defined laws;
//! - [`parameter`]: the range each parameter must lie in, checked once by the constructor of
//!   its type, and the error naming the field;
//! - [`mesh`]: boundary meshes of bodies for contact, and their distance queries (§4);
//! - [`coupling`]: the forces between bodies and the world (§2–4, lines on the seabed §7);
//! - [`seabed`]: the flat bottom lines lie on and bodies touch (§7);
//! - [`surroundings`]: gravity, fluid and seabed as the couplings see them;
//! - [`evaluation`]: what a force evaluation leaves behind (kinematics, loads, coupling records
//!   and caches);
//! - [`potential`]: potential flow from a panel code: frequency-domain data, radiation kernel,
//!   convolution and state-space radiation (§9);
//! - [`water`]: hydrostatics, waves, current, Morison loads and added mass (§6), an
//!   environment stage of the force evaluation;
//! - [`system`]: bodies, couplings, gravity and water, and the named stages of a force
//!   evaluation;
//! - [`integrator`]: how states advance in time (§1, time integration), on a narrow interface;
//! - [`energy`]: the energy balance that checks it all (§5);
//! - [`stability`]: the stable time step of each coupling and spinning body;
//! - [`rao`]: a floating body's RAOs from its potential data, its mass about the reference point
//!   and its mesh's linear hydrostatic stiffness (§9);
//! - [`natural_periods`]: its undamped natural periods and mode shapes at the static equilibrium,
//!   with `A∞` or `A(ω_n)` (§9);
//! - [`statics`]: the system at rest — tangent stiffness, static equilibrium, offset curves;
//! - [`simd`]: which vector instructions the hot stages are built for;
//! - [`world`]: a system running in time: clock, ledger, health check, live edits.
//!
//! Units are SI throughout:
//!
//! | quantity            | unit      | quantity              | unit        |
//! |---------------------|-----------|-----------------------|-------------|
//! | length, position    | m         | force                 | N = kg·m/s² |
//! | mass                | kg        | moment                | N·m         |
//! | time                | s         | stiffness (spring)    | N/m         |
//! | velocity            | m/s       | damping (spring)      | N·s/m       |
//! | angular velocity    | rad/s     | inertia               | kg·m²       |
//! | energy, work        | J = N·m   | gravity               | m/s²        |
//!
//! The world frame is right-handed with z up.

pub mod air;
pub mod body;
pub mod coupling;
pub mod dynamics;
pub mod energy;
pub mod evaluation;
pub mod integrator;
pub mod mass_properties;
pub mod math;
pub mod mesh;
pub mod natural_periods;
pub mod parameter;
pub mod potential;
pub mod rao;
pub mod rao_time_domain;
pub mod seabed;
pub mod simd;
pub mod stability;
pub mod statics;
pub mod surroundings;
pub mod system;
pub mod table;
pub mod water;
pub mod water_stage;
pub mod world;
