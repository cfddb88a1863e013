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
    assert_eq!(stores.len(), 1, "one recording");
    let mut rows = BTreeMap::new();
    for store in stores.values() {
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
    let status = tether().args(["record", common::repo(scene).to_str().unwrap(), "-o", out.to_str().unwrap()]).args(flags).status().unwrap();
    assert!(status.success());
    (dir, out)
}

#[test]
fn record_writes_every_entity_once_per_frame() {
    let (_dir, out) = record("scenes/suspension.ron", &["--duration", "1", "--log-hz", "50"]);
    let rows = rows_per_entity(&out);
    // dt = 0.5 ms, 50 Hz → a frame every 40 steps, 2000 steps: frames at steps 0, 40, …, 2000.
    let frames = 51;
    for entity in ["/world/bodies/car", "/world/bodies/wheel", "/world/couplings/tyre", "/world/couplings/suspension", "/plots/tension", "/plots/energy"] {
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
    assert!(verify.status.success(), "rerun rrd verify failed:\n{}\n{}", String::from_utf8_lossy(&verify.stdout), String::from_utf8_lossy(&verify.stderr));
}

/// A catenary is drawn along its shape (32 coloured segments) and its end tensions plotted.
#[test]
fn catenary_shape_and_end_tensions_are_recorded() {
    let (_dir, out) = record("scenes/crane.ron", &["--duration", "0.5", "--log-hz", "20"]);
    let rows = rows_per_entity(&out);
    // dt = 1 ms, 20 Hz: frames at steps 0, 50, …, 500.
    for entity in ["/world/couplings/rope", "/plots/catenary/rope", "/plots/tension", "/world/bodies/load"] {
        assert_eq!(rows.get(entity), Some(&11), "{entity}: {rows:?}");
    }
}

#[test]
fn a_contact_recording_has_its_face_arrows_and_force_plots() {
    let (_dir, out) = record("scenes/fender.ron", &["--duration", "4", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    // dt = 2 ms, 10 Hz → frames at steps 0, 50, …, 2000: 41.
    for entity in ["/world/contacts/quay", "/world/contacts/hull", "/plots/contact/quay", "/plots/contact/hull", "/world/bodies/fender"] {
        assert_eq!(rows.get(entity), Some(&41), "{entity}: {rows:?}");
    }
    assert!(!rows.contains_key("/world/couplings/quay"), "a contact is not drawn as a line: {rows:?}");
    // The fender mesh is logged once, statically.
    assert_eq!(rows.get("/world/bodies/fender/shape"), Some(&0));
}


/// What `rows` finds of `entity` in each store of the `.rrd` file `path`: values by `step`.
fn rows_by_step<T>(path: &std::path::Path, entity: &str, rows: impl Fn(&rerun::ChunkStore, &str) -> Vec<(i64, T)>) -> BTreeMap<i64, T> {
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
            .flat_map(|chunk| chunk.iter_component_indices(step, component).zip(chunk.iter_slices::<[f32; 3]>(component)).map(|((time, _), values)| (time.as_i64(), values[0])).collect::<Vec<_>>())
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
            .flat_map(|chunk| chunk.iter_component_indices(step, component).zip(chunk.iter_slices::<f64>(component)).map(|((time, _), values)| (time.as_i64(), values.to_vec())).collect::<Vec<_>>())
            .collect()
    })
}

/// The values in a recording are the world's: the crane's load position and rope tension, read
/// back from the `.rrd` at steps 2000, 4000 and 6000 (t = 2, 4, 6 s: hanging, swinging behind
/// the moving trolley, overtaking it), equal those of the same scene stepped here, to f32
/// precision (positions are logged as f32, scalars as f64).
#[test]
fn recorded_values_are_the_worlds() {
    let (_dir, out) = record("scenes/crane.ron", &["--duration", "6", "--log-hz", "10"]);
    let positions = translations_by_step(&out, "/world/bodies/load");
    let tensions = scalars_by_step(&out, "/plots/tension");
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
            assert!((f64::from(recorded[k]) - expected[k]).abs() <= f64::from(f32::EPSILON) * expected[k].abs().max(1.0), "step {step}, axis {k}: recorded {recorded:?}, world {expected:?}");
        }
        let tension = world.coupling_forces()[0].tension;
        let logged = tensions[&(step as i64)][0];
        assert!((logged - tension).abs() <= f64::from(f32::EPSILON) * tension.abs(), "step {step}: recorded tension {logged} N, world {tension} N");
    }
    // The load moved between the three times: the comparison is not of a body at rest.
    let xs: Vec<f32> = [2000, 4000, 6000].iter().map(|s| positions[s][0]).collect();
    assert!(xs[0] < xs[1] && xs[1] < xs[2], "{xs:?}");
}

/// The moored buoy's chains on the seabed: each line's grounded part and touchdown are drawn and
/// its grounded length plotted every frame, and the plotted `L_B` is the world's at steps 1000,
/// 2000 and 3000 (t = 2, 4, 6 s, the buoy swinging back from its push).
#[test]
fn grounded_lines_are_drawn_marked_and_their_grounded_length_plotted() {
    let (_dir, out) = record("scenes/moored_buoy.ron", &["--duration", "6", "--log-hz", "10"]);
    let rows = rows_per_entity(&out);
    // dt = 2 ms, 10 Hz: a frame every 50 steps, 0 to 3000.
    for line in ["mooring1", "mooring2", "mooring3"] {
        for entity in [format!("/world/seabed/grounded/{line}"), format!("/world/seabed/touchdowns/{line}"), format!("/plots/seabed/{line}")] {
            assert_eq!(rows.get(&entity), Some(&61), "{entity}: {rows:?}");
        }
    }
    let grounded = scalars_by_step(&out, "/plots/seabed/mooring1");
    let mut world = tether_scene::load(&common::repo("scenes/moored_buoy.ron")).unwrap().world;
    let mut lengths = Vec::new();
    for step in [1000, 2000, 3000] {
        while world.steps() < step {
            world.step().unwrap();
        }
        let expected = world.line_state(0).expect("a solved line").grounded_length();
        let logged = grounded[&(step as i64)][0];
        // Scalars are logged as f64: the same number.
        assert_eq!(logged, expected, "step {step}");
        lengths.push(logged);
    }
    assert!(lengths.windows(2).all(|w| w[0] != w[1]), "the grounded length changes as the buoy swings: {lengths:?}");
}
