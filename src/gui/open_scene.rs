//! The scene being run and tuned, with no egui in it: what its file says, what is tuned, what
//! the knobs show and why a value was refused; loading it, checking a tuned value with the scene
//! builder, reverting to the file and saving as RON. The panel draws it and sends the
//! simulation what it accepts.

use super::simulation::Run;
use super::simulation::Wake;
use super::watch::FileWatch;
use std::path::{Path, PathBuf};
use std::time::Duration;
use tether_physics::coupling::Coupling;
use tether_physics::integrator::Timing;
use tether_physics::water::WaterSpec;
use tether_physics::water::morison::HydroSpec;
use tether_scene::build::{self, Bodies};
use tether_scene::file::CouplingDef;
use tether_scene::water::{HydroDef, WaterDef};
use tether_scene::{self as scene, SceneError, SceneFile};

/// The scene being run: what its file says, and what is tuned.
pub struct OpenScene {
    pub path: PathBuf,
    /// The file's text when it was loaded (a change on disk to the same text is no change).
    text: String,
    /// What the file says.
    pub file: SceneFile,
    /// What runs: the file with the accepted tuned values.
    pub tuned: SceneFile,
    /// What the knobs show, accepted or not.
    pub drafts: Vec<CouplingDef>,
    /// Why a draft was refused, per coupling.
    pub refusals: Vec<Option<String>>,
    /// What the water knobs show (the file's water, tuned), and why it was refused.
    pub water_draft: Option<WaterDef>,
    pub water_refusal: Option<String>,
    /// What each body's water coefficients' knobs show, and why they were refused.
    pub hydro_drafts: Vec<Option<HydroDef>>,
    pub hydro_refusals: Vec<Option<String>>,
    /// The scene's bodies as built: a tuned coupling is built against them.
    bodies: Bodies,
    watch: Option<FileWatch>,
}

/// A scene loaded from its file: the model, the run to send the simulation, and what to tell
/// the user.
pub struct Loaded {
    pub scene: OpenScene,
    pub run: Run,
    /// The loader's warnings, and a note when the file will not be watched.
    pub notes: Vec<String>,
}

/// What the file on disk is doing.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OnDisk {
    /// Nothing happened since it was loaded.
    Quiet,
    /// It changed and is still being written.
    Settling,
    /// It changed, settled, and says something else than what was loaded.
    Changed,
    /// It changed and settled back to the text that was loaded.
    Restored,
}

impl OpenScene {
    /// Loads the scene at `path`, watched on disk (`wake` repaints when it changes).
    ///
    /// # Errors
    /// The file cannot be read or built: `path:line:col: message`.
    pub fn load(path: &Path, wake: Wake) -> Result<Loaded, SceneError> {
        let loaded = scene::load(path)?;
        let mut notes: Vec<String> = loaded.warnings.iter().map(|w| format!("warning: {w}")).collect();
        let label = path.file_stem().map_or_else(|| path.display().to_string(), |s| s.to_string_lossy().into_owned());
        let watch = match FileWatch::new(path, wake) {
            Ok(watch) => Some(watch),
            Err(error) => {
                notes.push(format!("{} will not reload on change: {error}", path.display()));
                None
            }
        };
        let scene = Self {
            path: path.to_path_buf(),
            text: loaded.text,
            drafts: loaded.file.couplings.clone(),
            refusals: vec![None; loaded.file.couplings.len()],
            water_draft: loaded.file.water.clone(),
            water_refusal: None,
            hydro_drafts: loaded.file.bodies.iter().map(|b| b.hydro.clone()).collect(),
            hydro_refusals: vec![None; loaded.file.bodies.len()],
            tuned: loaded.file.clone(),
            file: loaded.file,
            bodies: loaded.bodies,
            watch,
        };
        Ok(Loaded { scene, run: Run { label, world: loaded.world }, notes })
    }

    /// Loads the scene at `path` as its file says it, and runs `variant` of it (a sweep's
    /// case: the same scene with some values changed), shown as tuned values: "revert to file"
    /// goes back to what the file says. `label` names the run.
    ///
    /// # Errors
    /// The file cannot be read or built, or the loader refuses the variant.
    pub fn load_variant(path: &Path, variant: SceneFile, label: String, wake: Wake) -> Result<Loaded, SceneError> {
        let Loaded { scene: base, mut notes, .. } = Self::load(path, wake)?;
        let case = scene::build_variant(&base.text, path, variant)?;
        notes.extend(case.warnings.iter().map(|w| format!("warning: {w}")));
        let scene = Self {
            drafts: case.file.couplings.clone(),
            refusals: vec![None; case.file.couplings.len()],
            tuned: case.file,
            bodies: case.bodies,
            ..base
        };
        Ok(Loaded { scene, run: Run { label, world: case.world }, notes })
    }

    /// What the file on disk is doing, once it has been quiet for `settle`.
    pub fn on_disk(&self, settle: Duration) -> OnDisk {
        let Some(watch) = &self.watch else { return OnDisk::Quiet };
        match watch.settled(settle) {
            None => OnDisk::Quiet,
            Some(false) => OnDisk::Settling,
            Some(true) => {
                let same = std::fs::read_to_string(&self.path).is_ok_and(|text| text == self.text);
                if same { OnDisk::Restored } else { OnDisk::Changed }
            }
        }
    }

    /// Checks draft `index` with the scene builder (same checks and messages as loading): an
    /// accepted value goes into the tuned scene and comes back as the coupling to run; a
    /// refused one stays in its knob with the reason.
    pub fn tune(&mut self, index: usize) -> Option<Coupling> {
        let (Some(draft), Some(_)) = (self.drafts.get(index), self.refusals.get(index)) else { return None };
        let mut candidate = self.tuned.clone();
        candidate.couplings[index] = draft.clone();
        match build::coupling(&candidate, index, &mut self.bodies) {
            Ok(coupling) => {
                self.refusals[index] = None;
                self.tuned = candidate;
                Some(coupling)
            }
            Err(problem) => {
                self.refusals[index] = Some(problem.message);
                None
            }
        }
    }

    /// Checks the water draft with the scene builder: accepted into the tuned scene and returned
    /// as the spec to run; refused with the reason kept.
    pub fn tune_water(&mut self) -> Option<WaterSpec> {
        let mut candidate = self.tuned.clone();
        candidate.water.clone_from(&self.water_draft);
        match build::water_spec(&candidate) {
            Ok(spec) => {
                self.water_refusal = None;
                self.tuned = candidate;
                Some(spec)
            }
            Err(problem) => {
                self.water_refusal = Some(problem.message);
                None
            }
        }
    }

    /// Checks body `index`'s coefficients draft likewise.
    pub fn tune_hydro(&mut self, index: usize) -> Option<HydroSpec> {
        let Some(draft) = self.hydro_drafts.get(index) else { return None };
        let mut candidate = self.tuned.clone();
        candidate.bodies[index].hydro.clone_from(draft);
        match build::hydro_spec(&candidate, index, &self.bodies) {
            Ok(spec) => {
                self.hydro_refusals[index] = None;
                self.tuned = candidate;
                Some(spec)
            }
            Err(problem) => {
                self.hydro_refusals[index] = Some(problem.message);
                None
            }
        }
    }

    /// The water knobs back to what the file says; returns whether the water and which bodies'
    /// coefficients are to be applied again (those tuned, or refused).
    pub fn revert_water_to_file(&mut self) -> (bool, Vec<usize>) {
        self.water_draft.clone_from(&self.file.water);
        let water = self.tuned.water != self.file.water || self.water_refusal.is_some();
        self.hydro_drafts = self.file.bodies.iter().map(|b| b.hydro.clone()).collect();
        let bodies = (0..self.hydro_drafts.len())
            .filter(|&i| self.tuned.bodies[i].hydro != self.file.bodies[i].hydro || self.hydro_refusals[i].is_some())
            .collect();
        (water, bodies)
    }

    /// The time step settings of `candidate` (the tuned scene with the timing knobs written in),
    /// checked by the scene builder; accepted into the tuned scene.
    pub fn retime(&mut self, candidate: SceneFile) -> Result<Timing, String> {
        let timing = build::timing(&candidate).map_err(|p| p.message)?;
        self.tuned = candidate;
        Ok(timing)
    }

    /// Every knob back to what the file says; returns the couplings to apply again (those
    /// tuned, or refused).
    pub fn revert_to_file(&mut self) -> Vec<usize> {
        self.drafts.clone_from(&self.file.couplings);
        (0..self.drafts.len())
            .filter(|&i| self.tuned.couplings[i] != self.file.couplings[i] || self.refusals[i].is_some())
            .collect()
    }

    /// Writes the tuned scene to `path` as RON that loads back to the same scene (mesh files
    /// found from the new folder too).
    pub fn save_as(&self, path: &Path) -> Result<(), String> {
        let mut tuned = self.tuned.clone();
        let folder = |p: &Path| std::path::absolute(p.parent().unwrap_or(Path::new("."))).unwrap_or_default();
        scene::relocate_meshes(&mut tuned, &folder(&self.path), &folder(path));
        let text = scene::to_ron(&tuned).map_err(|e| e.to_string())?;
        std::fs::write(path, text).map_err(|e| e.to_string())
    }
}
