//! A recording read back with Rerun's own reader: entities present, one row per logged frame, and
//! the values logged equal to the world's.

mod common;

use std::collections::BTreeMap;
use std::process::Command;

fn tether() -> Command {
    Command::new(env!("CARGO_BIN_EXE_tether"))
}

/// Temporal rows per entity path in an `.rrd` file.
fn rows_per_entity(path: &std::path::Path) -> BTreeMap<String, usize> {
    let mut file = std::fs::File::open(path).unwrap();
    let stores = rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
    // One recording, and the window's layout (a blueprint).
    let kinds: Vec<bool> = stores.keys().map(rerun::StoreId::is_recording).collect();
    assert_eq!(kinds.iter().filter(|&&recording| recording).count(), 1, "one recording: {kinds:?}");
    assert_eq!(kinds.len(), 2, "and one blueprint: {kinds:?}");
    let mut rows = BTreeMap::new();
    for store in stores.values().filter(|store| store.id().is_recording()) {
        for chunk in store.iter_physical_chunks() {
            let entry = rows.entry(chunk.entity_path().to_string()).or_insert(0);
            if !chunk.is_static() {
                *entry += chunk.num_rows();
            }
        }
    }
    rows
}

/// Records `scene` (under the repository) into a temporary directory with extra `flags`.
fn record(scene: &str, flags: &[&str]) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out.rrd");
    let status = tether()
        .args(["record", common::repo(scene).to_str().unwrap(), "-o", out.to_str().unwrap()])
        .args(flags)
        .status()
        .unwrap();
    assert!(status.success());
    (dir, out)
}

#[test]
fn record_writes_every_entity_once_per_frame() {
    let (_dir, out) = record("scenes/suspension.ron", &["--duration", "1", "--log-hz", "50"]);
    let rows = rows_per_entity(&out);
    // dt = 0.5 ms, 50 Hz → a frame every 40 steps, 2000 steps: frames at steps 0, 40, …, 2000.
    let frames = 51;
    // Both spring-dampers (tyre, suspension) are strips of the one `world/springs` entity.
    for entity in [
        "/world/bodies/car",
        "/world/bodies/wheel",
        "/world/springs",
        "/plots/tension",
        "/plots/energy/stored",
        "/plots/energy/moving",
    ] {
        assert_eq!(rows.get(entity), Some(&frames), "{entity}: {rows:?}");
    }
    for entity in ["/world", "/world/bodies/car/shape", "/world/bodies/wheel/shape"] {
        assert_eq!(rows.get(entity), Some(&0), "static only: {entity}: {rows:?}");
    }
}

/// `rerun rrd verify` (from the `rerun-sdk` Python package, which README and CI install)
/// accepts the file: it is complete, footer included.
#[test]
fn recording_passes_rerun_rrd_verify() {
    let (_dir, out) = record("scenes/t_handle.ron", &["--duration", "2"]);
    let verify = Command::new("rerun")
        .args(["rrd", "verify", out.to_str().unwrap()])
        .output()
        .expect("the `rerun` CLI must be on PATH: pip install rerun-sdk==0.36.3 (see README)");
    assert!(
        verify.status.success(),
        "rerun rrd verify failed:\n{}\n{}",
        String::from_utf8_lossy(&verify.stdout),
        String::from_utf8_lossy(&verify.stderr)
    );
}

/// A catenary is drawn along its shape (32 segments in 8 coloured bands) and its end tensions
/// plotted.
#[test]
fn catenary_shape_and_end_tensions_are_recorded() {
    let (_dir, out) = record("scenes/crane.ron", &["--duration", "0.5", "--log-hz", "20"]);
    let rows = rows_per_entity(&out);
    // dt = 1 ms, 20 Hz: frames at steps 0, 50, …, 500.
    for entity in ["/world/couplings/rope", "/plots/catenary", "/plots/tension", "/world/bodies/load"] {
        assert_eq!(rows.get(entity), Some(&11), "{entity}: {rows:?}");
    }
}

/// The contact force plots are always there; the face arrows only for the contacts and times
/// asked for.
#[test]
fn a_contact_recording_has_its_force_plots_and_the_face_arrows_asked_for() {
    // dt = 2 ms, 10 Hz → frames at steps 0, 50, …, 2000: 41.
    let (_dir, out) = record("scenes/fender.ron", &["--duration", "4", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    for entity in ["/plots/contact", "/plots/tension", "/world/bodies/fender"] {
        assert_eq!(rows.get(entity), Some(&41), "{entity}: {rows:?}");
    }
    // Not even the arrows' colour: a contact never drawn costs the recording nothing.
    assert!(!rows.keys().any(|path| path.starts_with("/world/contacts")), "no face arrows by default: {rows:?}");
    assert!(!rows.contains_key("/world/couplings/quay"), "a contact is not drawn as a line: {rows:?}");
    // The fender mesh is logged once, statically.
    assert_eq!(rows.get("/world/bodies/fender/shape"), Some(&0));

    let (_dir, out) = record("scenes/fender.ron", &["--duration", "4", "--log-hz", "10", "--face-arrows", "all"]);
    let rows = rows_per_entity(&out);
    for entity in ["/world/contacts/quay", "/world/contacts/hull"] {
        assert_eq!(rows.get(entity), Some(&41), "{entity}: {rows:?}");
    }

    // The quay's from t = 1.95 s (between two frames, so that no rounding of t decides): frames
    // at 2.0, 2.1, …, 4.0 s, 21 of them; none of the hull's.
    let (_dir, out) = record(
        "scenes/fender.ron",
        &["--duration", "4", "--log-hz", "10", "--face-arrows", "quay", "--face-arrows-from", "1.95"],
    );
    let rows = rows_per_entity(&out);
    assert_eq!(rows.get("/world/contacts/quay"), Some(&21), "{rows:?}");
    assert_eq!(rows.get("/world/contacts/hull"), None, "{rows:?}");
}

/// What `rows` finds of `entity` in each store of the `.rrd` file `path`: values by `step`.
fn rows_by_step<T>(
    path: &std::path::Path,
    entity: &str,
    rows: impl Fn(&rerun::ChunkStore, &str) -> Vec<(i64, T)>,
) -> BTreeMap<i64, T> {
    let mut file = std::fs::File::open(path).unwrap();
    let stores = rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
    stores.values().flat_map(|store| rows(store, entity)).collect()
}

/// The translations logged to `entity`, by `step`.
fn translations_by_step(path: &std::path::Path, entity: &str) -> BTreeMap<i64, [f32; 3]> {
    let component = rerun::Transform3D::descriptor_translation().component;
    rows_by_step(path, entity, |store, entity| {
        let step = rerun::TimelineName::from_static_str("step");
        store
            .iter_physical_chunks()
            .filter(|chunk| chunk.entity_path().to_string() == entity)
            .flat_map(|chunk| {
                chunk
                    .iter_component_indices(step, component)
                    .zip(chunk.iter_slices::<[f32; 3]>(component))
                    .map(|((time, _), values)| (time.as_i64(), values[0]))
                    .collect::<Vec<_>>()
            })
            .collect()
    })
}

/// The scalars logged to `entity`, by `step`.
fn scalars_by_step(path: &std::path::Path, entity: &str) -> BTreeMap<i64, Vec<f64>> {
    let component = rerun::Scalars::descriptor_scalars().component;
    rows_by_step(path, entity, |store, entity| {
        let step = rerun::TimelineName::from_static_str("step");
        store
            .iter_physical_chunks()
            .filter(|chunk| chunk.entity_path().to_string() == entity)
            .flat_map(|chunk| {
                chunk
                    .iter_component_indices(step, component)
                    .zip(chunk.iter_slices::<f64>(component))
                    .map(|((time, _), values)| (time.as_i64(), values.to_vec()))
                    .collect::<Vec<_>>()
            })
            .collect()
    })
}

/// The strips drawn for `entity` (`LineStrips3D`), by `step`: each strip's points.
fn strips_by_step(path: &std::path::Path, entity: &str) -> BTreeMap<i64, Vec<Vec<[f32; 3]>>> {
    use rerun::external::arrow::array::{Array as _, AsArray as _};
    use rerun::external::arrow::datatypes::Float32Type;
    let component = rerun::LineStrips3D::descriptor_strips().component;
    rows_by_step(path, entity, |store, entity| {
        let step = rerun::TimelineName::from_static_str("step");
        let mut rows = Vec::new();
        for chunk in store.iter_physical_chunks().filter(|chunk| chunk.entity_path().to_string() == entity) {
            let Some(column) = chunk.components().get_array(component) else { continue };
            let times = chunk.iter_component_indices(step, component).map(|(time, _)| time.as_i64());
            for (time, row) in times.zip((0..column.len()).map(|row| column.value(row))) {
                let strips = row.as_list::<i32>();
                let points = |strip: usize| {
                    let points = strips.value(strip);
                    let points = points.as_fixed_size_list();
                    (0..points.len())
                        .map(|p| {
                            let xyz = points.value(p);
                            let xyz = xyz.as_primitive::<Float32Type>();
                            [xyz.value(0), xyz.value(1), xyz.value(2)]
                        })
                        .collect::<Vec<_>>()
                };
                rows.push((time, (0..strips.len()).map(points).collect()));
            }
        }
        rows
    })
}

/// The values in a recording are the world's: the crane's load position, rope tension and rope
/// shape, read back from the `.rrd` at steps 2000, 4000 and 6000 (t = 2, 4, 6 s: hanging,
/// swinging behind the moving trolley, overtaking it), equal those of the same scene stepped
/// here, to f32 precision (positions are logged as f32, scalars as f64). The rope is drawn as
/// 8 bands of 4 segments, each band starting where the one before ended, through the 33 points
/// of the world's solved line.
#[test]
fn recorded_values_are_the_worlds() {
    let (_dir, out) = record("scenes/crane.ron", &["--duration", "6", "--log-hz", "10"]);
    let positions = translations_by_step(&out, "/world/bodies/load");
    let tensions = scalars_by_step(&out, "/plots/tension");
    let strips = strips_by_step(&out, "/world/couplings/rope");
    // dt = 1 ms, 10 Hz: a frame every 100 steps, 0 to 6000.
    assert_eq!(positions.len(), 61, "{:?}", positions.keys().collect::<Vec<_>>());
    let scene = tether_scene::load(&common::repo("scenes/crane.ron")).unwrap();
    let mut world = scene.world;
    for step in [2000, 4000, 6000] {
        while world.steps() < step {
            world.step().unwrap();
        }
        let expected = world.state(1).position;
        let recorded = positions[&(step as i64)];
        for k in 0..3 {
            assert!(
                (f64::from(recorded[k]) - expected[k]).abs() <= f64::from(f32::EPSILON) * expected[k].abs().max(1.0),
                "step {step}, axis {k}: recorded {recorded:?}, world {expected:?}"
            );
        }
        let tension = world.coupling_forces()[0].tension;
        let logged = tensions[&(step as i64)][0];
        assert!(
            (logged - tension).abs() <= f64::from(f32::EPSILON) * tension.abs(),
            "step {step}: recorded tension {logged} N, world {tension} N"
        );
        let bands = &strips[&(step as i64)];
        assert_eq!(bands.len(), 8, "step {step}");
        assert!(bands.iter().all(|band| band.len() == 5), "step {step}: {bands:?}");
        assert!(bands.windows(2).all(|pair| pair[0][4] == pair[1][0]), "step {step}: the bands join");
        let drawn: Vec<[f32; 3]> =
            bands.iter().enumerate().flat_map(|(b, band)| band[usize::from(b > 0)..].to_vec()).collect();
        let shape = world.line_state(0).expect("the rope is solved").sample(32);
        assert_eq!(drawn.len(), shape.len());
        for (point, (expected, _)) in drawn.iter().zip(&shape) {
            for k in 0..3 {
                assert!(
                    (f64::from(point[k]) - expected[k]).abs()
                        <= 4.0 * f64::from(f32::EPSILON) * expected[k].abs().max(1.0),
                    "step {step}: drawn {point:?}, solved {expected:?}"
                );
            }
        }
    }
    // The load moved between the three times: the comparison is not of a body at rest.
    let xs: Vec<f32> = [2000, 4000, 6000].iter().map(|s| positions[s][0]).collect();
    assert!(xs[0] < xs[1] && xs[1] < xs[2], "{xs:?}");
}

/// The contact force plot holds the forces the step summed, the same as the faces evaluated
/// again one by one (what the recorder logged before it took the step's): the fender against
/// the quay and the hull, read back at steps 500, 1000 and 2000 (t = 1, 2, 4 s).
#[test]
fn recorded_contact_forces_are_the_faces_sums() {
    let (_dir, out) = record("scenes/fender.ron", &["--duration", "4", "--log-hz", "10"]);
    let forces = scalars_by_step(&out, "/plots/contact");
    let mut world = tether_scene::load(&common::repo("scenes/fender.ron")).unwrap().world;
    let contacts: Vec<usize> = world
        .couplings()
        .iter()
        .enumerate()
        .filter(|(_, c)| matches!(c.kind, tether_physics::coupling::CouplingKind::Contact(_)))
        .map(|(i, _)| i)
        .collect();
    let mut pressed = 0;
    for step in [500, 1000, 2000] {
        while world.steps() < step {
            world.step().unwrap();
        }
        let logged = &forces[&(step as i64)];
        assert_eq!(logged.len(), 2 * contacts.len(), "normal and friction of each contact");
        for (k, &index) in contacts.iter().enumerate() {
            let tether_physics::coupling::CouplingKind::Contact(contact) = &world.couplings()[index].kind else {
                unreachable!("filtered on contacts")
            };
            let again = contact.totals(world.frames());
            // The same faces summed in another order: round-off far below 1e-9 of the normal
            // force (the physics test holds it to 1e-12).
            let tolerance = 1e-9 * again.normal.max(1.0);
            assert!(
                (logged[2 * k] - again.normal).abs() <= tolerance,
                "step {step}, contact {k}: normal {} logged, {} again",
                logged[2 * k],
                again.normal
            );
            assert!(
                (logged[2 * k + 1] - again.friction).abs() <= tolerance,
                "step {step}, contact {k}: friction {} logged, {} again",
                logged[2 * k + 1],
                again.friction
            );
            pressed += usize::from(again.normal > 0.0);
        }
    }
    assert!(pressed >= 3, "the comparison is of contacts that press ({pressed} of 6)");
}

/// The water: the moving sea surface each frame (its triangles once), the seabed once, the
/// buoy's water force and motion plots each frame, the heave read back equal to the world's;
/// a calm sea's surface once.
#[test]
fn the_water_is_recorded() {
    // dt = 50 ms, 10 Hz: a frame every 2 steps, 0 to 40: 21.
    let (_dir, out) = record("scenes/moored_buoy.ron", &["--duration", "2", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    for entity in
        ["/world/water/surface", "/world/water/forces/buoy", "/plots/water/buoy/motion", "/plots/water/buoy/angles"]
    {
        assert_eq!(rows.get(entity), Some(&21), "{entity}: {rows:?}");
    }
    assert_eq!(rows.get("/world/water/seabed"), Some(&0), "static: {rows:?}");
    let motion = scalars_by_step(&out, "/plots/water/buoy/motion");
    let mut world = tether_scene::load(&common::repo("scenes/moored_buoy.ron")).unwrap().world;
    let start = world.state(0).position.z;
    assert_eq!(motion[&0][1], 0.0, "no heave at t = 0");
    while world.steps() < 40 {
        world.step().unwrap();
    }
    let heave = world.state(0).position.z - start;
    assert!(
        (motion[&40][1] - heave).abs() <= 1e-12 * start.abs().max(1.0),
        "heave {} logged, {heave} m in the world",
        motion[&40][1]
    );
    assert!(heave.abs() > 1e-3, "the buoy moved in the waves: {heave} m");
    let potential: Vec<&String> =
        rows.keys().filter(|k| k.ends_with("/radiation") || k.ends_with("/excitation")).collect();
    assert!(potential.is_empty(), "no potential flow, no potential-flow plots: {potential:?}");

    // dt = 10 ms, 10 Hz: 21 frames; the calm surface once.
    let (_dir, out) = record("scenes/floating_box.ron", &["--duration", "2", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    assert_eq!(rows.get("/world/water/surface"), Some(&1), "{rows:?}");
    assert_eq!(rows.get("/plots/water/box/motion"), Some(&21), "{rows:?}");
}

/// Potential flow (PHYSICS.md §9): the cylinder of `tests/fixtures/rao/cylinder.ron` in its
/// regular sea (0.1 m, 8 s) has its radiation force and wave excitation plotted every frame, six
/// series each, equal to the world's water forces (about G, world axes) at steps 250, 500 and
/// 1000 (t = 5, 10, 20 s) to 1e-12; the block beside it, without potential data, has no such
/// plots.
#[test]
fn a_potential_flow_body_has_its_radiation_and_excitation_plotted() {
    let scene = "tests/fixtures/rao/cylinder.ron";
    // dt = 20 ms, 10 Hz: a frame every 5 steps, 0 to 1000: 201.
    let (_dir, out) = record(scene, &["--duration", "20", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    for entity in ["/plots/water/cylinder/radiation", "/plots/water/cylinder/excitation"] {
        assert_eq!(rows.get(entity), Some(&201), "{entity}: {rows:?}");
        assert_eq!(
            common::x11::series_names(&out, entity),
            ["Fx [N]", "Fy [N]", "Fz [N]", "Mx [N·m]", "My [N·m]", "Mz [N·m]"]
        );
    }
    for entity in ["/plots/water/block/radiation", "/plots/water/block/excitation"] {
        assert_eq!(rows.get(entity), None, "{entity}: {rows:?}");
    }
    let radiation = scalars_by_step(&out, "/plots/water/cylinder/radiation");
    let excitation = scalars_by_step(&out, "/plots/water/cylinder/excitation");
    let mut world = tether_scene::load(&common::repo(scene)).unwrap().world;
    for step in [250, 500, 1000] {
        while world.steps() < step {
            world.step().unwrap();
        }
        let forces = world.water_forces().iter().find(|r| r.body == 0).expect("the cylinder floats");
        for (logged, load) in
            [(&radiation[&(step as i64)], forces.radiation), (&excitation[&(step as i64)], forces.excitation)]
        {
            let expected = [load.force.x, load.force.y, load.force.z, load.moment.x, load.moment.y, load.moment.z];
            let scale = expected.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            assert!(scale > 1.0, "step {step}: the waves load the cylinder: {expected:?}");
            for (k, (logged, expected)) in logged.iter().zip(expected).enumerate() {
                assert!(
                    (logged - expected).abs() <= 1e-12 * scale,
                    "step {step}, series {k}: {logged} logged, {expected} in the world"
                );
            }
        }
    }
}

/// The moored buoy's chains on the seabed: each line's grounded part and touchdown are drawn and
/// the grounded lengths plotted every frame (one series per line), and mooring1's plotted `L_B` is the world's at steps 40,
/// 80 and 120 (t = 2, 4, 6 s, the buoy swinging back from its push).
#[test]
fn grounded_lines_are_drawn_marked_and_their_grounded_length_plotted() {
    let (_dir, out) = record("scenes/moored_buoy.ron", &["--duration", "6", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    // dt = 50 ms, 10 Hz: a frame every 2 steps, 0 to 120.
    for line in ["mooring1", "mooring2", "mooring3"] {
        for entity in [format!("/world/seabed/grounded/{line}"), format!("/world/seabed/touchdowns/{line}")] {
            assert_eq!(rows.get(&entity), Some(&61), "{entity}: {rows:?}");
        }
    }
    assert_eq!(rows.get("/plots/seabed"), Some(&61), "{rows:?}");
    let grounded = scalars_by_step(&out, "/plots/seabed");
    let mut world = tether_scene::load(&common::repo("scenes/moored_buoy.ron")).unwrap().world;
    let mut lengths = Vec::new();
    for step in [40, 80, 120] {
        while world.steps() < step {
            world.step().unwrap();
        }
        let expected = world.line_state(0).expect("a solved line").grounded_length();
        assert_eq!(grounded[&(step as i64)].len(), 3, "a series per line");
        let logged = grounded[&(step as i64)][0];
        // Scalars are logged as f64: the same number.
        assert_eq!(logged, expected, "step {step}");
        lengths.push(logged);
    }
    assert!(lengths.windows(2).all(|w| w[0] != w[1]), "the grounded length changes as the buoy swings: {lengths:?}");
}

/// Issue 35: a dynamic line's grounded length is its nodes' (the segments on the seabed), not 0.
/// moored_buoy with mooring1 dynamic (40 segments of 6.25 m): at t = 0 its nodes are the static
/// shape, whose grounded length is the quasi-static catenary's within a segment; it stays on
/// the seabed over the 2 s recorded.
#[test]
fn a_dynamic_line_s_grounded_length_is_read_from_its_nodes() {
    let text = std::fs::read_to_string(common::repo("scenes/moored_buoy.ron")).unwrap();
    let dynamic = "Dynamic(segments: 40, damping: Ratio(0.8), drag_normal: 2.4, drag_tangential: 1.15, added_mass_normal: 1.0, added_mass_tangential: 0.5)";
    let text = text.replacen("model: QuasiStatic,", &format!("model: {dynamic},"), 1);
    assert!(text.contains(&format!("model: {dynamic},")), "mooring1 made dynamic");
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("moored_buoy.ron");
    std::fs::write(&scene, &text).unwrap();
    let out = dir.path().join("out.rrd");
    let status = tether()
        .args(["record", scene.to_str().unwrap(), "-o", out.to_str().unwrap(), "--duration", "2", "--log-hz", "10"])
        .status()
        .unwrap();
    assert!(status.success());
    let grounded = scalars_by_step(&out, "/plots/seabed");
    let quasi_static = tether_scene::load(&common::repo("scenes/moored_buoy.ron")).unwrap().world;
    let expected = quasi_static.line_state(0).expect("a solved line").grounded_length();
    let at_start = grounded[&0][0];
    println!("mooring1 grounded at t = 0: {at_start} m dynamic, {expected} m quasi-static");
    assert!(expected > 10.0, "the chain lies on the seabed: {expected} m");
    assert!((at_start - expected).abs() <= 6.25, "{at_start} m against {expected} m");
    for (step, lengths) in &grounded {
        assert!(lengths[0] > 0.0, "step {step}: {lengths:?}");
    }
}

/// The blueprint store of an `.rrd` file.
fn blueprint_in_file(path: &std::path::Path) -> rerun::ChunkStore {
    let mut file = std::fs::File::open(path).unwrap();
    let stores = rerun::ChunkStore::from_rrd_reader(&rerun::ChunkStoreConfig::COMPACTION_DISABLED, &mut file).unwrap();
    stores.into_values().find(|store| !store.id().is_recording()).expect("a blueprint in the file")
}

/// The position and look target of the eye in the blueprint of an `.rrd` file, and the entity
/// path they are under.
fn eye_in_file(path: &std::path::Path) -> (String, [f32; 3], [f32; 3]) {
    let blueprint = blueprint_in_file(path);
    let eye = rerun::external::re_sdk_types::blueprint::archetypes::EyeControls3D::descriptor_position().component;
    let target =
        rerun::external::re_sdk_types::blueprint::archetypes::EyeControls3D::descriptor_look_target().component;
    let chunk = blueprint
        .iter_physical_chunks()
        .find(|chunk| chunk.entity_path().to_string().ends_with("/EyeControls3D"))
        .expect("the 3D view's eye in the blueprint");
    let first = |component| chunk.iter_slices::<[f32; 3]>(component).next().expect("a value")[0];
    (chunk.entity_path().to_string(), first(eye), first(target))
}

/// `tether record` writes the window's layout into the file, the 3D view's eye where the
/// framing of the run puts it, so that the file opens framed in Rerun's own viewer as in the
/// window.
#[test]
fn a_recording_opens_with_its_eye_framing_the_run() {
    for scene in ["scenes/box_drop.ron", "scenes/oc3_hywind.ron"] {
        let (_dir, out) = record(scene, &["--duration", "0.5"]);
        let (path, eye, target) = eye_in_file(&out);
        let world = tether_scene::load(&common::repo(scene)).unwrap().world;
        let framing = tether_record::framing::Framing::of(&world);
        let close = |a: [f32; 3], b: &tether_physics::math::Vec3| (0..3).all(|i| (f64::from(a[i]) - b[i]).abs() < 1e-3);
        assert!(
            close(eye, &framing.eye) && close(target, &framing.target),
            "{scene}: {path} {eye:?} {target:?} {framing:?}"
        );
    }
}

/// The 3D view's line grid and background in the blueprint of an `.rrd` file: the grid shown
/// or not, and the background's colour if one is set.
fn grid_and_sky_in_file(path: &std::path::Path) -> (bool, Option<u32>) {
    use rerun::external::re_sdk_types::blueprint::archetypes::{Background, LineGrid3D};
    let blueprint = blueprint_in_file(path);
    let chunk_of = |property: &str| {
        blueprint.iter_physical_chunks().find(|chunk| chunk.entity_path().to_string().ends_with(property)).cloned()
    };
    let grid = chunk_of("/LineGrid3D").expect("the 3D view's grid in the blueprint");
    let visible =
        grid.iter_slices::<bool>(LineGrid3D::descriptor_visible().component).next().expect("a value").value(0);
    let sky = chunk_of("/Background")
        .map(|chunk| chunk.iter_slices::<u32>(Background::descriptor_color().component).next().expect("a colour")[0]);
    (visible, sky)
}

/// Issue 47: a scene at sea hides the viewer's grid (it cut through the sea surface) and draws a
/// sky to the sea's horizon; a dry scene keeps the grid and the viewer's own background.
#[test]
fn a_scene_at_sea_has_a_sky_and_no_grid_through_its_surface() {
    let (_dir, out) = record("scenes/box_drop.ron", &["--duration", "0.1"]);
    assert_eq!(grid_and_sky_in_file(&out), (true, None), "box_drop: the grid, the viewer's background");
    let (_dir, out) = record("scenes/moored_buoy.ron", &["--duration", "0.1"]);
    let (grid, sky) = grid_and_sky_in_file(&out);
    assert!(!grid, "moored_buoy: no grid at the water line");
    // Rerun's colour is 0xRRGGBBAA.
    assert_eq!(sky, Some(0x60_78_96_ff), "moored_buoy: the sky [96, 120, 150]");
}

/// `tether record` frames with its own run's steps (`framing::MotionSweep`) rather than a copy's run:
/// the same box whether the run outlasts the sweep (6 s of box_drop's crate, which falls and
/// hops, against a sweep of 5 s), stops inside it (0.3 s, finished on a copy) or has not
/// stepped at all.
#[test]
fn a_sweep_fed_by_the_run_frames_as_a_copy_of_it_does() {
    let world = tether_scene::load(&common::repo("scenes/box_drop.ron")).unwrap().world;
    let expected = tether_record::framing::swept_box(&world);
    // Dropped from G at 1.2 m (its lowest corner above 0.79 m), it reaches the ground and ends
    // 3.1 m from where it fell: the box spans more than the crate's 0.82 m diagonal.
    let (low, high) = expected;
    assert!(low.z < 0.1 && (high.x - low.x).max(high.y - low.y) > 2.5, "{expected:?}");
    for seconds in [0.0, 0.3, 6.0] {
        let mut run = world.clone();
        let mut sweep = tether_record::framing::MotionSweep::start(&run);
        for _ in 0..(seconds / run.dt()).round() as usize {
            run.step().unwrap();
            sweep.after_step(&run);
        }
        assert_eq!(sweep.finish(&run), expected, "{seconds} s");
    }
}

/// The framing sweeps what moves over its first seconds: a sphere (r = 0.1 m) falling freely
/// from z = 10 m for 5 s reaches z = 10 − g·5²/2 = −112.6 m; the spring anchor 1 m from where it
/// starts is framed with it, the one 3 km away is not.
#[test]
fn the_framing_holds_a_free_fall_over_its_first_seconds_and_the_anchors_near_it() {
    let text = |anchor: &str| {
        format!(
            "Scene(dt: 0.001, duration: 10.0, bodies: [
                Body(name: \"ball\", master: Node(position: (0.0, 0.0, 10.0), mass: 1.0,
                     inertia: Inertia(xx: 0.004, yy: 0.004, zz: 0.004)), shape: Sphere(radius: 0.1)),
                Body(name: \"post\", master: Node(position: {anchor}, mass: 1.0,
                     inertia: Inertia(xx: 1.0, yy: 1.0, zz: 1.0)),
                     support: Fixed(translation: (true, true, true), rotation: true), shape: Sphere(radius: 0.1)),
            ], couplings: [
                SpringDamper(name: \"tie\", end1: World({anchor}), end2: Body(body: \"post\"),
                    law: Linear(stiffness: 1.0, rest_length: 0.0)),
            ])"
        )
    };
    let g = 9.81;
    let fallen = 10.0 - g * 5.0 * 5.0 / 2.0;
    let (low, high) = tether_record::framing::swept_box(&tether_test_support::scene(&text("(1.0, 0.0, 10.0)")).world);
    // The leapfrog's positions in uniform gravity are exact up to g·dt·t = 4.9 cm at t = 5 s.
    assert!((low.z - (fallen - 0.1)).abs() < g * 0.001 * 5.0, "{low}");
    assert!((high.z - 10.1).abs() < 1e-9 && (high.x - 1.0).abs() < 1e-9, "{high}: the near anchor framed");
    let (low, high) =
        tether_record::framing::swept_box(&tether_test_support::scene(&text("(3000.0, 0.0, 10.0)")).world);
    assert!((high.x - 0.1).abs() < 1e-9 && (low.x + 0.1).abs() < 1e-9, "{low} {high}: the far anchor is not");
}

/// Issue 47: a line a prescribed motion drives is what its scene is about: `chain_forced_surge`
/// frames its whole chain, from the anchor at x = −237 m, z = −50 m (the seabed) to the surged
/// fairlead (x up to 2.5 m: the sphere of 0.5 m surged 2 m), where the sphere alone
/// (about 5 m across) was framed before; a moored buoy's free chains still are not.
#[test]
fn a_driven_line_is_framed_whole() {
    let world = tether_scene::load(&common::repo("scenes/chain_forced_surge.ron")).unwrap().world;
    let (low, high) = tether_record::framing::swept_box(&world);
    // The nodes on the seabed press into it by millimetres (its penalty, PHYSICS.md §8).
    assert!((low.x + 237.0).abs() < 1e-6 && (low.z + 50.0).abs() < 0.05, "the anchor framed: {low}");
    assert!(high.x > 2.0 && high.x < 2.6, "the fairlead's surge framed: {high}");
    let buoy = tether_scene::load(&common::repo("scenes/buoy_on_dynamic_chains.ron")).unwrap().world;
    let (low, high) = tether_record::framing::swept_box(&buoy);
    assert!((high - low).norm() < 30.0, "the buoy framed, its chains leave the frame: {low} {high}");
}

/// The viewer's plots for `scene`: each tab's name and its plots' titles.
fn tabs_of(scene: &str, columns: &[&str]) -> Vec<(String, Vec<String>)> {
    let scene = tether_scene::load(&common::repo(scene)).expect("a shipped scene loads");
    tether_record::layout::plot_tabs(&scene.world, columns)
        .into_iter()
        .map(|tab| (tab.name, tab.plots.into_iter().map(|plot| plot.title).collect()))
        .collect()
}

#[test]
fn the_first_plots_are_what_the_scene_is_about_and_every_tab_holds_few() {
    let moored = tabs_of("scenes/moored_buoy.ron", &[]);
    let names: Vec<&str> = moored.iter().map(|(name, _)| name.as_str()).collect();
    assert_eq!(names, ["mooring", "lines", "buoy", "energy"]);
    assert_eq!(moored[0].1, ["tension [N]", "buoy: elevation, heave [m]", "buoy: roll, pitch [deg]"]);
    assert_eq!(moored[1].1, ["tension [N]", "catenary end tensions [N]", "grounded length L_B [m]"]);
    let fender = tabs_of("scenes/fender.ron", &[]);
    assert_eq!(fender[0].0, "contacts", "{fender:?}");
    let fit = tabs_of("scenes/spring_mass.ron", &["x"]);
    assert_eq!(fit[0], ("fit".to_string(), vec!["fit: x".to_string()]));
    // Every shipped scene: at most four plots a tab, and the energy in its two plots, each
    // listing only its own series (two entities).
    for path in tether_test_support::scene_files() {
        let scene = tether_scene::load(&path).expect("a shipped scene loads");
        let tabs = tether_record::layout::plot_tabs(&scene.world, &[]);
        assert!(tabs.iter().all(|tab| (1..=4).contains(&tab.plots.len())), "{}: {tabs:?}", path.display());
        let energy = tabs.last().expect("the energy tab");
        let origins: Vec<&str> = energy.plots.iter().map(|plot| plot.origin.as_str()).collect();
        assert_eq!(origins, [tether_record::paths::ENERGY_STORED, tether_record::paths::ENERGY_MOVING]);
    }
}
