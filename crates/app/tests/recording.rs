//! A recording read back with Rerun's own reader: entities present, one row per logged frame.

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
    // Both spring-dampers (tyre, suspension) are strips of the one `world/springs` entity.
    for entity in ["/world/bodies/car", "/world/bodies/wheel", "/world/springs", "/plots/tension", "/plots/energy"] {
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
    // Only the arrows' static colour is there.
    assert!(rows.iter().filter(|(path, _)| path.starts_with("/world/contacts")).all(|(_, &n)| n == 0), "no face arrows by default: {rows:?}");
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
    let (_dir, out) = record("scenes/fender.ron", &["--duration", "4", "--log-hz", "10", "--face-arrows", "quay", "--face-arrows-from", "1.95"]);
    let rows = rows_per_entity(&out);
    assert_eq!(rows.get("/world/contacts/quay"), Some(&21), "{rows:?}");
    assert_eq!(rows.get("/world/contacts/hull"), Some(&0), "{rows:?}");
}
