//! Live edits of a running world: a coupling replaced, the water or a body's coefficients in it
//! changed, the seabed changed, the bodies placed (at a static equilibrium), the time step
//! changed, a reset. All but the reset start the integrator again from the synchronised state at the current time (positions and
//! velocities do not move), keeping the energy ledger, so the motion goes on under what changed;
//! a refused edit leaves the world as it was.

use super::World;
use super::error::{EditError, StepError};
use crate::air::{AirSpec, WindLoadSpec};
use crate::body::BodyState;
use crate::coupling::Coupling;
use crate::energy::Work;
use crate::integrator::Timing;
use crate::potential::DriftModel;
use crate::seabed::Seabed;
use crate::stability;
use crate::system::SystemError;
use crate::water::WaterSpec;
use crate::water::morison::HydroSpec;

impl World {
    /// Restarts from t = 0 with the current parameters; on error the world is unchanged.
    pub fn reset(&mut self) -> Result<(), StepError> {
        *self = Self::new(self.system.clone(), self.timing)?;
        Ok(())
    }

    /// Replaces coupling `index` while running, without a restart (live tuning): the integrator
    /// starts again at the current time from the synchronised state, with the forces of the
    /// new coupling, so the motion goes on under them at the scheme's order across the change.
    /// Its energy does jump: the elastic energy of the new parameters at the same positions
    /// differs from the old one. That jump is booked as external work (PHYSICS.md §5), so
    /// `balance()` stays continuous across the swap and keeps checking the motion after it; the
    /// divergence message then quotes the stable time step of the new parameters.
    ///
    /// # Errors
    /// `index` out of range ([`EditError::NoSuchCoupling`]), a new coupling that refers to a
    /// body the world does not have or anchors below the seabed ([`EditError::System`]), or
    /// that cannot give its forces here ([`EditError::Forces`]); the world is then unchanged.
    pub fn replace_coupling(&mut self, index: usize, coupling: Coupling) -> Result<(), EditError> {
        let count = self.system.couplings().len();
        if index >= count {
            return Err(EditError::NoSuchCoupling { index, count });
        }
        let before = self.clone();
        self.states = self.synchronized_states();
        if let Err(error) = self.system.replace_coupling(index, coupling) {
            *self = before;
            return Err(error.into());
        }
        self.evaluation.forget(index, &self.system.couplings()[index]);
        self.restart_after_edit(before).map_err(Into::into)
    }

    /// Replaces the seabed while running (live tuning of its line friction `C_B`): as
    /// [`World::replace_coupling`], the integrator starts again at the current time from the
    /// synchronised state, and the jump of the lines' energy is booked as external work.
    ///
    /// # Errors
    /// A catenary anchor would lie below the new seabed, or the lines cannot give their forces
    /// on it; the world is then unchanged.
    pub fn set_seabed(&mut self, seabed: Seabed) -> Result<(), EditError> {
        let before = self.clone();
        self.states = self.synchronized_states();
        if let Err(error) = self.system.replace_seabed(seabed) {
            *self = before;
            return Err(error.into());
        }
        self.restart_after_edit(before).map_err(Into::into)
    }

    /// Puts the bodies at `states` at the current time, velocities included (the GUI's
    /// equilibrium button: the scene jumps to its static pose, at rest). The integrator starts
    /// again from them; the jump in energy is booked as external work, as for a tuned coupling.
    ///
    /// # Errors
    /// A state per body is needed, and the couplings must give their forces there; the world is
    /// then unchanged.
    pub fn place(&mut self, states: &[BodyState]) -> Result<(), EditError> {
        if states.len() != self.states.len() {
            let error = SystemError::StateCount { bodies: self.states.len(), states: states.len() };
            return Err(error.into());
        }
        let before = self.clone();
        self.states = states.to_vec();
        self.restart_after_edit(before).map_err(Into::into)
    }

    /// Replaces the water's spec while running (waves, current, density, level, depth, ramp):
    /// the integrator starts again at the current time from the synchronised state under the new
    /// water. The water stores no energy, but the lines weigh in it (`(λ0 − ρ A_d) g`) and lie
    /// on its bottom: the jump of their energy is booked as external work, as for a tuned
    /// coupling; the water's forces' work goes on being booked as external work.
    ///
    /// # Errors
    /// Water that cannot be, a world without water, or forces that cannot be evaluated; the
    /// world is then unchanged.
    pub fn replace_water(&mut self, spec: WaterSpec) -> Result<(), EditError> {
        self.edit_water(|system, _| system.replace_water(spec))
    }

    /// Replaces the coefficients of floating body `body` (drag, damping, added mass, drag
    /// centre) while running, as [`World::replace_water`] does the water.
    ///
    /// # Errors
    /// Bad coefficients, a body that does not float, or forces that cannot be evaluated; the
    /// world is then unchanged.
    pub fn replace_hydro(&mut self, body: usize, spec: HydroSpec) -> Result<(), EditError> {
        self.edit_water(|system, _| system.replace_hydro(body, spec))
    }

    /// Switches floating body `body`'s potential flow on or off while running (PHYSICS.md §9,
    /// the window's switch), as [`World::replace_water`] does the water: off, the body goes on as
    /// it would without potential data (the incident wave's pressure and Morison's added mass
    /// back, `A∞` out of its generalised mass and of its stable time step); on, it goes on under
    /// potential flow again, its excitation built for the sea as it is, its radiation memory
    /// started afresh (the body at rest before now). Switching to the state it is in changes
    /// nothing.
    ///
    /// # Errors
    /// A body that does not float or has no potential-flow data, a sea heading its file lacks,
    /// or forces that cannot be evaluated; the world is then unchanged.
    pub fn set_potential_flow(&mut self, body: usize, on: bool) -> Result<(), EditError> {
        let already = self
            .system
            .water()
            .and_then(|stage| stage.floating_body(body))
            .is_some_and(|floating| floating.has_potential_data() && floating.potential().is_some() == on);
        if already {
            return Ok(());
        }
        self.edit_water(|system, evaluation| {
            if let Some(index) = system.switch_potential_flow(body, on)? {
                evaluation.forget_radiation(index);
            }
            Ok(())
        })
    }

    /// Sets how the mean drift loads floating body `body` (PHYSICS.md §10: `Off`, `Mean`,
    /// `Newman`) while running, as [`World::replace_water`] does the water: the drift is built
    /// again for the sea as it is, on the body's potential flow whether on or switched off. The
    /// drift stores no energy; its work goes on being booked as external work.
    ///
    /// # Errors
    /// A body that does not float or has no potential-flow data, a drift model without the
    /// file's drift coefficients (`.8`/`.9`), or a sea heading they lack; the world is then
    /// unchanged.
    pub fn set_drift_model(&mut self, body: usize, drift: DriftModel) -> Result<(), EditError> {
        let already = self
            .system
            .water()
            .and_then(|stage| stage.floating_body(body))
            .and_then(|floating| floating.potential_model())
            .is_some_and(|model| model.drift_model() == drift);
        if already {
            return Ok(());
        }
        self.edit_water(|system, _| system.set_drift_model(body, drift))
    }

    /// Replaces the coefficients of floating body `body` and sets its drift model, in one edit
    /// ([`World::replace_hydro`], [`World::set_drift_model`]): both apply, or neither and the
    /// world is unchanged.
    ///
    /// # Errors
    /// As those two.
    pub fn replace_hydro_and_drift(
        &mut self,
        body: usize,
        spec: HydroSpec,
        drift: DriftModel,
    ) -> Result<(), EditError> {
        self.edit_water(|system, _| {
            system.replace_hydro(body, spec)?;
            system.set_drift_model(body, drift)
        })
    }

    /// Replaces the air (wind speed, height, heading, profile, gusts, density, ramp) and the
    /// loads on its bodies while running (PHYSICS.md §10), as [`World::replace_water`] does the
    /// water: the exposures from the poses at t = 0, as when built; a new gust seed is a new
    /// realisation from t = 0 on. The air stores no energy; its work is external work.
    ///
    /// # Errors
    /// Air that cannot be, a world without air, a body whose windage or rotor cannot be, or
    /// forces that cannot be evaluated; the world is then unchanged.
    pub fn replace_air(&mut self, spec: AirSpec, loads: Vec<(usize, WindLoadSpec)>) -> Result<(), EditError> {
        self.edit_water(|system, _| system.replace_air(spec, loads))
    }

    /// Applies `edit` to the system and the evaluation's buffers and restarts the integrator
    /// from the synchronised state; on any error, the world as it was.
    fn edit_water(
        &mut self,
        edit: impl FnOnce(&mut crate::system::System, &mut crate::evaluation::Evaluation) -> Result<(), SystemError>,
    ) -> Result<(), EditError> {
        let before = self.clone();
        self.states = self.synchronized_states();
        if let Err(error) = edit(&mut self.system, &mut self.evaluation) {
            *self = before;
            return Err(error.into());
        }
        self.restart_after_edit(before).map_err(Into::into)
    }

    /// Changes the time step, the integrator, the substeps and the adaptive tolerances (checked
    /// by [`Timing::new`]) at the current time, keeping the state: the new integrator starts
    /// from the synchronised positions and velocities, so the motion goes on where it was.
    /// `Substeps::Auto` is resolved from the stable time steps of the current state.
    ///
    /// # Errors
    /// Forces that cannot be evaluated; the world is then unchanged.
    pub fn set_timing(&mut self, timing: Timing) -> Result<(), EditError> {
        let before = self.clone();
        if let Err(error) = self.retime(timing) {
            *self = before;
            return Err(error.into());
        }
        Ok(())
    }

    /// [`World::set_timing`] once checked: the new integrator from the synchronised states, with
    /// `Substeps::Auto` resolved by the limits of the new scheme at one substep.
    fn retime(&mut self, timing: Timing) -> Result<(), StepError> {
        let synchronized = self.synchronized_states();
        self.states.clone_from(&synchronized);
        self.timing = timing;
        self.substeps = timing.first_substeps();
        self.start_integrator()?;
        self.plan_auto_substeps(synchronized)
    }

    /// Starts the integrator again after a live edit of the world that was `before`, with
    /// `Substeps::Auto` planned again for what the edit changed (a stiffer line, a shorter one
    /// pulled taut, heavier water need more substeps, a softer one fewer), books the jump in
    /// energy the edit made as external work (PHYSICS.md §5: the balance then still checks the
    /// integrator) and refreshes the stable-step limit; if the couplings cannot give their
    /// forces, the world goes back to `before`.
    fn restart_after_edit(&mut self, before: World) -> Result<(), StepError> {
        let edited = self.states.clone();
        if let Err(error) = self.start_integrator().and_then(|()| self.plan_auto_substeps(edited)) {
            *self = before;
            return Err(error);
        }
        let jump = self.energy().total() - before.energy().total();
        self.ledger.add(&Work::external(jump));
        self.health.limit = stability::binding(&self.limits());
        Ok(())
    }
}
