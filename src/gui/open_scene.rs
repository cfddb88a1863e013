//! The scene being run and tuned, with no egui in it: what its file says, what is tuned, its
//! knobs (what they show and why a value was refused, [`Knobs`]); loading it, checking a tuned
//! value with the scene builder, reverting to the file and saving as RON; values set by their
//! value paths (a fit's). The panel draws it and sends the simulation what it accepts.

use super::knobs::{Group, Knobs};
use super::simulation::{Command, Run, Wake};
use super::watch::FileWatch;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
pub use tether_analysis::parameters::KnobId;
use tether_analysis::value_path::ValuePath;
use tether_physics::integrator::Timing;
use tether_scene::air::AirDef;
use tether_scene::build::{self, Bodies};
use tether_scene::file::{CouplingDef, SeabedDef};
use tether_scene::water::{HydroDef, WaterDef};
use tether_scene::{self as scene, SceneError, SceneFile};

/// Why the scene builder refused a tuned value, as it words it (the same message as loading).
pub type Refusal = String;

/// The couplings' parameters, a knob per coupling, built against the scene's bodies. (Indexing
/// by `index` holds in each group: its knobs are read from a scene of the same shape as the one
/// written, the tuned scene being the file with values changed.)
static COUPLINGS: Group<CouplingDef, Refusal> = Group {
    values: |file| file.couplings.clone(),
    put: |file, index, def| file.couplings[index] = def,
    build: |candidate, index, bodies| {
        let coupling = build::coupling(candidate, index, bodies).map_err(|p| p.message)?;
        Ok(Command::SetCoupling { index, coupling, sent: Instant::now() })
    },
};

/// The water's waves, current and density: one knob, none without water.
static WATER: Group<WaterDef, Refusal> = Group {
    values: |file| file.water.iter().cloned().collect(),
    put: |file, _, water| file.water = Some(water),
    build: |candidate, _, _| Ok(Command::SetWater(build::water_spec(candidate).map_err(|p| p.message)?)),
};

/// Each body's drag and added-mass coefficients and, with potential flow, its drift model
/// (`None`: the body declares none), a knob per body.
static HYDRO: Group<Option<HydroDef>, Refusal> = Group {
    values: |file| file.bodies.iter().map(|body| body.hydro.clone()).collect(),
    put: |file, index, hydro| file.bodies[index].hydro = hydro,
    build: |candidate, body, bodies| {
        let spec = build::hydro_spec(candidate, body, bodies).map_err(|p| p.message)?;
        let hydro = candidate.bodies[body].hydro.as_ref();
        let drift = hydro.and_then(|h| h.potential.as_ref()).map(|potential| potential.drift);
        Ok(Command::SetHydro { body, spec, drift })
    },
};

/// The seabed's line friction `C_B` (its elevation is the water's bottom or the file's; its
/// contacts are couplings): one knob, none without a seabed.
static SEABED: Group<SeabedDef, Refusal> = Group {
    values: |file| file.seabed.iter().cloned().collect(),
    put: |file, _, seabed| file.seabed = Some(seabed),
    build: |candidate, _, _| Ok(Command::SetSeabed(build::seabed(candidate).map_err(|p| p.message)?)),
};

/// The air's wind, gusts and density: one knob, none without air.
static AIR: Group<AirDef, Refusal> = Group {
    values: |file| file.air.iter().cloned().collect(),
    put: |file, _, air| file.air = Some(air),
    build: |candidate, _, _| {
        let (spec, loads) = build::air_spec(candidate).map_err(|p| p.message)?;
        Ok(Command::SetAir { spec, loads })
    },
};

/// Every knob of the scene, read from one scene file: the file's when it is loaded, a sweep
/// case's when a case is (all groups at once: none can keep another scene's values). A new
/// group is a [`Group`] static, a field here and a [`KnobId`] variant.
pub struct SceneKnobs {
    pub couplings: Knobs<CouplingDef, Refusal>,
    pub water: Knobs<WaterDef, Refusal>,
    pub hydro: Knobs<Option<HydroDef>, Refusal>,
    pub seabed: Knobs<SeabedDef, Refusal>,
    pub air: Knobs<AirDef, Refusal>,
}

impl SceneKnobs {
    /// The knobs showing what `file` says.
    pub fn of(file: &SceneFile) -> Self {
        Self {
            couplings: Knobs::of(&COUPLINGS, file),
            water: Knobs::of(&WATER, file),
            hydro: Knobs::of(&HYDRO, file),
            seabed: Knobs::of(&SEABED, file),
            air: Knobs::of(&AIR, file),
        }
    }
}

/// The scene being run: what its file says, and what is tuned.
pub struct OpenScene {
    pub path: PathBuf,
    /// The file's text when it was loaded (a change on disk to the same text is no change).
    text: String,
    /// What the file says.
    pub file: SceneFile,
    /// What runs: the file with the accepted tuned values.
    pub tuned: SceneFile,
    /// What the knobs show, accepted or not, and why a value was refused.
    pub knobs: SceneKnobs,
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
            knobs: SceneKnobs::of(&loaded.file),
            tuned: loaded.file.clone(),
            file: loaded.file,
            bodies: loaded.bodies,
            watch,
        };
        let run = Run { label, world: loaded.world, duration: scene.tuned.duration };
        Ok(Loaded { scene, run, notes })
    }

    /// Loads the scene at `path` as its file says it, and runs `variant` of it (a sweep's
    /// case: the same scene with some values changed), shown as tuned values in every knob:
    /// "revert to file" goes back to what the file says. `label` names the run.
    ///
    /// # Errors
    /// The file cannot be read or built, or the loader refuses the variant.
    pub fn load_variant(path: &Path, variant: SceneFile, label: String, wake: Wake) -> Result<Loaded, SceneError> {
        let Loaded { scene: base, mut notes, .. } = Self::load(path, wake)?;
        let case = scene::build_variant(&base.text, path, variant)?;
        notes.extend(case.warnings.iter().map(|w| format!("warning: {w}")));
        let scene = Self { knobs: SceneKnobs::of(&case.file), tuned: case.file, bodies: case.bodies, ..base };
        let run = Run { label, world: case.world, duration: scene.tuned.duration };
        Ok(Loaded { scene, run, notes })
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

    /// Checks what knob `knob` shows with the scene builder (same checks and messages as
    /// loading): an accepted value goes into the tuned scene and comes back as the command that
    /// applies it; a refused one stays in its knob with the reason.
    pub fn tune(&mut self, knob: KnobId) -> Option<Command> {
        let (knobs, tuned, bodies) = (&mut self.knobs, &mut self.tuned, &mut self.bodies);
        match knob {
            KnobId::Coupling(index) => knobs.couplings.tune(index, tuned, bodies),
            KnobId::Water => knobs.water.tune(0, tuned, bodies),
            KnobId::Hydro(index) => knobs.hydro.tune(index, tuned, bodies),
            KnobId::Seabed => knobs.seabed.tune(0, tuned, bodies),
            KnobId::Air => knobs.air.tune(0, tuned, bodies),
        }
    }

    /// The values at value paths `values` (the sweep's paths, `couplings.spring.law.stiffness`),
    /// each in the knob named with it, set in the tuned scene and checked by the scene builder as
    /// edits of those knobs: the commands that apply what it accepts (a refused value stays in
    /// its knob with the reason).
    ///
    /// # Errors
    /// A path that leads nowhere in the tuned scene, or a value its data does not take; nothing
    /// is changed then.
    pub fn set_values(&mut self, values: &[(KnobId, &str, f64)]) -> Result<Vec<Command>, String> {
        let mut tree = serde_json::to_value(&self.tuned).map_err(|e| e.to_string())?;
        for (_, path, value) in values {
            ValuePath::find(&tree, path)?.set(&mut tree, Value::from(*value));
        }
        let candidate: SceneFile = serde_json::from_value(tree).map_err(|e| e.to_string())?;
        let mut knobs: Vec<KnobId> = Vec::new();
        for (knob, _, _) in values {
            if !knobs.contains(knob) {
                knobs.push(*knob);
            }
        }
        Ok(knobs.into_iter().filter_map(|knob| self.show_and_tune(knob, &candidate)).collect())
    }

    /// The values at value paths `paths` (each in the knob named with it) back to what the file
    /// says, the scene's other tuned values kept; a knob whose file value has no such path (a
    /// line switched to dynamic since) goes back to the file whole. Returns the commands that
    /// apply them.
    pub fn revert_values(&mut self, paths: &[(KnobId, &str)]) -> Vec<Command> {
        let file = serde_json::to_value(&self.file).unwrap_or(Value::Null);
        let number = |path: &str| ValuePath::find(&file, path).ok()?.get(&file)?.as_f64();
        let (mut values, mut whole) = (Vec::new(), Vec::new());
        for &(knob, path) in paths {
            match number(path) {
                Some(value) => values.push((knob, path, value)),
                None if !whole.contains(&knob) => whole.push(knob),
                None => {}
            }
        }
        let values: Vec<_> = values.into_iter().filter(|(knob, _, _)| !whole.contains(knob)).collect();
        // The file's own values: its paths lead to them, and its data takes them.
        let mut commands = self.set_values(&values).unwrap_or_default();
        let file = self.file.clone();
        commands.extend(whole.into_iter().filter_map(|knob| self.show_and_tune(knob, &file)));
        commands
    }

    /// Knob `knob` shows what `file` says, checked as an edit.
    fn show_and_tune(&mut self, knob: KnobId, file: &SceneFile) -> Option<Command> {
        match knob {
            KnobId::Coupling(index) => self.knobs.couplings.show(index, file),
            KnobId::Water => self.knobs.water.show(0, file),
            KnobId::Hydro(index) => self.knobs.hydro.show(index, file),
            KnobId::Seabed => self.knobs.seabed.show(0, file),
            KnobId::Air => self.knobs.air.show(0, file),
        }
        self.tune(knob)
    }

    /// The scene as it runs, for a fit: its path and text — the file's, or, once tuned, the tuned
    /// scene as RON labelled `<file> (as tuned)` in the file's folder (meshes are found there).
    ///
    /// # Errors
    /// The tuned scene cannot be written as RON.
    pub fn as_run(&self) -> Result<(PathBuf, String), String> {
        if self.tuned == self.file {
            return Ok((self.path.clone(), self.text.clone()));
        }
        let text = scene::to_ron(&self.tuned).map_err(|e| e.to_string())?;
        let name = self.path.file_name().map_or_else(|| "scene".into(), |n| n.to_string_lossy().into_owned());
        Ok((self.path.with_file_name(format!("{name} (as tuned)")), text))
    }

    /// Every knob back to what the file says; returns the knobs to [`tune`](Self::tune) again
    /// (those tuned, or refused).
    pub fn revert_to_file(&mut self) -> Vec<KnobId> {
        let (knobs, file, tuned) = (&mut self.knobs, &self.file, &self.tuned);
        let couplings = knobs.couplings.revert(file, tuned).into_iter().map(KnobId::Coupling);
        let water = knobs.water.revert(file, tuned).into_iter().map(|_| KnobId::Water);
        let hydro = knobs.hydro.revert(file, tuned).into_iter().map(KnobId::Hydro);
        let seabed = knobs.seabed.revert(file, tuned).into_iter().map(|_| KnobId::Seabed);
        let air = knobs.air.revert(file, tuned).into_iter().map(|_| KnobId::Air);
        couplings.chain(water).chain(hydro).chain(seabed).chain(air).collect()
    }

    /// The time step settings of `candidate` (the tuned scene with the timing knobs written in),
    /// checked by the scene builder; accepted into the tuned scene.
    pub fn retime(&mut self, candidate: SceneFile) -> Result<Timing, String> {
        let timing = build::timing(&candidate).map_err(|p| p.message)?;
        self.tuned = candidate;
        Ok(timing)
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

#[cfg(test)]
mod tests {
    use super::*;
    use tether_physics::water::WaveSpec;
    use tether_scene::water::WavesDef;

    /// A floating box in regular waves 1 m high and 6 s long, drag C_d z = 1, on a spring of
    /// k = 100 N/m to the world.
    const FLOAT: &str = r#"Scene(dt: 0.01, water: Water(depth: 30.0, waves: Regular(height: 1.0, period: 6.0)), bodies: [
        Body(name: "float", master: Node(position: (0.0, 0.0, 0.0), mass: 1025.0, inertia: Inertia(xx: 300.0, yy: 300.0, zz: 300.0)),
             shape: Box(size: (2.0, 2.0, 1.0)), hydro: Hydro(drag: (1.0, 1.0, 1.0)))],
        couplings: [SpringDamper(name: "spring", end1: World((0.0, 0.0, -5.0)), end2: Body(body: "float"),
            law: Linear(stiffness: 100.0, rest_length: 5.0), damping: 0.0)])"#;

    fn waves(water: &WaterDef) -> (f64, f64) {
        match water.waves {
            WavesDef::Regular { height, period, .. } => (height, period),
            ref other => panic!("{other:?}"),
        }
    }

    fn water_knob(open: &mut OpenScene) -> &mut WaterDef {
        &mut open.knobs.water.knobs_mut().first_mut().expect("the scene has water").draft
    }

    fn open(dir: &tempfile::TempDir, variant: impl FnOnce(&mut SceneFile)) -> OpenScene {
        let path = dir.path().join("float.ron");
        std::fs::write(&path, FLOAT).unwrap();
        let mut case = scene::parse(FLOAT, &path).unwrap().file;
        variant(&mut case);
        OpenScene::load_variant(&path, case, "case".into(), std::sync::Arc::new(|| {})).unwrap().scene
    }

    /// A sweep case's values are what every knob group shows (the wave height 2.5 m, the drag
    /// C_d z = 0.3, the stiffness 400 N/m), the file's kept to revert to; tuning the wave period
    /// applies the case's height with it; reverting lists the three groups to apply again and
    /// shows the file's values.
    #[test]
    fn a_variant_shows_in_every_knob_group_and_survives_an_edit_of_another_value() {
        let dir = tempfile::tempdir().unwrap();
        let mut open = open(&dir, |case| {
            if let Some(WaterDef { waves: WavesDef::Regular { height, .. }, .. }) = &mut case.water {
                *height = 2.5;
            }
            if let Some(hydro) = &mut case.bodies[0].hydro {
                hydro.drag[2] = 0.3;
            }
            if let CouplingDef::SpringDamper { law: tether_scene::file::LawDef::Linear { stiffness, .. }, .. } =
                &mut case.couplings[0]
            {
                *stiffness = 400.0;
            }
        });
        assert_eq!(waves(water_knob(&mut open)), (2.5, 6.0));
        assert_eq!(open.knobs.hydro.knobs()[0].draft.as_ref().map(|h| h.drag[2]), Some(0.3));
        assert_eq!(open.knobs.couplings.knobs()[0].draft, open.tuned.couplings[0]);
        assert_eq!(open.file.water.as_ref().map(waves), Some((1.0, 6.0)), "the file's, to revert to");

        if let WavesDef::Regular { period, .. } = &mut water_knob(&mut open).waves {
            *period = 7.0;
        }
        let Some(Command::SetWater(spec)) = open.tune(KnobId::Water) else { panic!("the water is applied") };
        let WaveSpec::Regular { height, period, .. } = spec.waves else { panic!("{:?}", spec.waves) };
        assert_eq!((height, period), (2.5, 7.0), "the case's height, the new period");
        assert_eq!(open.tuned.water.as_ref().map(waves), Some((2.5, 7.0)));

        assert_eq!(open.revert_to_file(), [KnobId::Coupling(0), KnobId::Water, KnobId::Hydro(0)]);
        assert_eq!(waves(water_knob(&mut open)), (1.0, 6.0));
        assert_eq!(open.knobs.hydro.knobs()[0].draft, open.file.bodies[0].hydro);
        assert_eq!(open.knobs.couplings.knobs()[0].draft, open.file.couplings[0]);
    }

    /// A refused value stays in its knob with the builder's reason, the tuned scene untouched;
    /// revert lists it (refused, though the tuned value is the file's) and tuning it again
    /// clears the reason and applies nothing (the draft is what runs).
    #[test]
    fn a_refused_value_keeps_its_reason_until_reverted_and_tuned_again() {
        let dir = tempfile::tempdir().unwrap();
        let mut open = open(&dir, |_| {});
        water_knob(&mut open).density = 0.0;
        assert!(open.tune(KnobId::Water).is_none());
        let knob = &open.knobs.water.knobs()[0];
        let refused: Vec<String> = knob.refusals.iter().map(ToString::to_string).collect();
        assert_eq!(refused, ["density = 0 not applied (the run keeps 1025): water: density must be > 0 kg/m³, got 0"]);
        assert_eq!(open.tuned, open.file, "a refused value is not tuned");

        assert_eq!(open.revert_to_file(), [KnobId::Water]);
        assert_eq!(water_knob(&mut open).density, 1025.0);
        assert!(open.tune(KnobId::Water).is_none(), "the draft is what runs: nothing to apply");
        assert!(open.knobs.water.knobs()[0].refusals.is_empty());
        assert!(open.revert_to_file().is_empty(), "nothing left to apply");
    }

    /// Issue 35: after a refused wave period, a corrected wave height applies (the period stays
    /// refused, with its reason, the run keeping 6 s); fixing the period applies it and clears
    /// the reason.
    #[test]
    fn a_fixed_field_applies_while_another_of_the_same_knob_stays_refused() {
        let dir = tempfile::tempdir().unwrap();
        let mut open = open(&dir, |_| {});
        let set = |open: &mut OpenScene, h: f64, t: f64| {
            if let WavesDef::Regular { height, period, .. } = &mut water_knob(open).waves {
                (*height, *period) = (h, t);
            }
        };
        set(&mut open, 1.0, 0.0);
        assert!(open.tune(KnobId::Water).is_none());
        set(&mut open, 3.0, 0.0);
        let Some(Command::SetWater(spec)) = open.tune(KnobId::Water) else { panic!("the height is applied") };
        let WaveSpec::Regular { height, period, .. } = spec.waves else { panic!("{:?}", spec.waves) };
        assert_eq!((height, period), (3.0, 6.0), "the new height, the running period");
        assert_eq!(open.tuned.water.as_ref().map(waves), Some((3.0, 6.0)));
        assert_eq!(waves(water_knob(&mut open)), (3.0, 0.0), "the knob still shows the refused draft");
        let refused: Vec<String> = open.knobs.water.knobs()[0].refusals.iter().map(ToString::to_string).collect();
        assert_eq!(refused.len(), 1, "{refused:?}");
        assert!(refused[0].starts_with("waves.period = 0 not applied (the run keeps 6): water: "), "{}", refused[0]);

        set(&mut open, 3.0, 8.0);
        assert!(open.tune(KnobId::Water).is_some());
        assert_eq!(open.tuned.water.as_ref().map(waves), Some((3.0, 8.0)));
        assert!(open.knobs.water.knobs()[0].refusals.is_empty());
    }
}
