//! "Save as": a scene written back as RON loads to the same scene, wherever it is written.

use tether_test_support as common;

use common::{repo, scene_files};
use std::path::Path;
use tether_physics::coupling::CouplingKind;
use tether_scene as scene;

/// Every scene written back as RON ("save as") loads to the same scene data and world.
#[test]
fn every_scene_round_trips_through_ron() {
    for path in scene_files() {
        let loaded = scene::load(&path).unwrap();
        let text = scene::to_ron(&loaded.file).unwrap();
        // Beside the original, where its mesh files are.
        let again = scene::parse(&text, &path.with_file_name("saved.ron"))
            .unwrap_or_else(|e| panic!("{}: {e}\n{text}", path.display()));
        assert_eq!(again.file, loaded.file, "{}", path.display());
        assert_eq!(again.world.couplings(), loaded.world.couplings(), "{}", path.display());
    }
}

/// A scene with a mesh saved into another folder still finds its mesh.
#[test]
fn a_scene_saved_elsewhere_still_finds_its_mesh() {
    let original = repo("scenes/fender.ron");
    let mut loaded = scene::load(&original).unwrap();
    let elsewhere = tempfile::tempdir().unwrap();
    scene::relocate_meshes(&mut loaded.file, original.parent().unwrap(), elsewhere.path());
    let saved = elsewhere.path().join("fender.ron");
    std::fs::write(&saved, scene::to_ron(&loaded.file).unwrap()).unwrap();
    let again = scene::load(&saved).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(again.world.bodies().len(), loaded.world.bodies().len());
}

/// A tuned catenary written out and read back keeps its tuned values.
#[test]
fn a_tuned_catenary_is_saved_with_its_tuned_values() {
    let mut loaded = scene::load(&repo("scenes/moored_buoy.ron")).unwrap();
    if let scene::file::CouplingDef::Catenary { length, .. } = &mut loaded.file.couplings[0] {
        *length = 97.5;
    }
    let again = scene::parse(&scene::to_ron(&loaded.file).unwrap(), Path::new("saved.ron")).unwrap();
    match &again.world.couplings()[0].kind {
        CouplingKind::Catenary(line) => assert_eq!(line.length(), 97.5),
        other => panic!("not a catenary: {other:?}"),
    }
}

/// A dynamic line whose every value differs from the others and from its default is written
/// and read back to the same file model and the same physics model, field by field (the file
/// form of `scene::line_model` writes each field under its own name).
#[test]
fn a_dynamic_line_round_trips_each_of_its_values() {
    use scene::line_model::LineModelDef;
    use tether_physics::coupling::{InternalDamping, LineModel, LumpedMass, LumpedMassSpec};
    let mut loaded = scene::load(&repo("scenes/moored_buoy.ron")).unwrap();
    let tuned = LumpedMassSpec {
        segments: 37,
        damping: InternalDamping::Coefficient(1234.5),
        drag_normal: 2.1,
        drag_tangential: 0.3,
        added_mass_normal: 0.9,
        added_mass_tangential: 0.2,
        seabed_stiffness: 4.0e6,
        seabed_damping: 2.5e5,
        friction_speed: 0.02,
    };
    if let scene::file::CouplingDef::Catenary { model, .. } = &mut loaded.file.couplings[0] {
        *model = LineModelDef::Dynamic(tuned);
    }
    let text = scene::to_ron(&loaded.file).unwrap();
    assert!(text.contains("model: Dynamic(\n"), "written with one pair of parentheses:\n{text}");
    let again = scene::parse(&text, Path::new("saved.ron")).unwrap_or_else(|e| panic!("{e}\n{text}"));
    match &again.file.couplings[0] {
        scene::file::CouplingDef::Catenary { model, .. } => assert_eq!(*model, LineModelDef::Dynamic(tuned)),
        other => panic!("not a catenary: {other:?}"),
    }
    let built = LumpedMass::new(tuned);
    match &again.world.couplings()[0].kind {
        CouplingKind::Catenary(line) => assert_eq!(Ok(line.model()), built.map(LineModel::Dynamic)),
        other => panic!("not a catenary: {other:?}"),
    }
}
