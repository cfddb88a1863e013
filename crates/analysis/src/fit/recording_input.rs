//! A Tether recording (an `.rrd` file written by `tether-record`, or any Rerun recording laid out
//! the same way) read back as measured series, so that a scene can be fitted to another run.
//!
//! What it reads, from the recording stores of the file (blueprints are skipped), on the
//! `sim_time` timeline (seconds; rows without it, and static rows, carry no sample):
//! - every `Scalars` plot: series `<entity path>/<series name>`, the names being the entity's
//!   `SeriesLines` names (logged statically by the recorder), e.g. `plots/tension/mooring1`,
//!   `plots/catenary/chain end2`, `plots/energy/moving/kinetic`, `plots/water/buoy/motion/heave`; a
//!   series without a name is `<entity path>/<index>` (0, 1, … in the row);
//! - every body's position, the translation of the `Transform3D` of `world/bodies/<name>` (the
//!   body's G): series `world/bodies/<name>/x`, `…/y`, `…/z`.
//!
//! Units are the recording's: SI, as Tether logs them (N for tensions and forces, J for
//! energies, m for lengths and positions, rad for angles). Positions are logged in single
//! precision (about 7 significant digits); plots in double precision.
//!
//! A recorder sends an entity's rows in many chunks (one per flush): the samples of a series are
//! gathered from all of them and sorted by time; of samples at the same time, the last in the
//! file is kept.

use super::series::Series;
use arrow_array::cast::AsArray as _;
use arrow_array::types::{Float32Type, Float64Type};
use arrow_array::{Array, ArrayRef, ListArray};
use re_chunk::Chunk;
use re_log_types::{EntityPath, LogMsg, StoreKind, TimeType};
use re_sdk_types::ComponentDescriptor;
use re_sdk_types::archetypes::{Scalars, SeriesLines, SeriesPoints, Transform3D};
use std::collections::{BTreeMap, HashMap};
use std::io::BufReader;
use std::path::Path;
use tether_record::{SIM_TIME, paths};

/// Samples `(time, value)` of one series, in file order.
type Samples = Vec<(f64, f64)>;

/// Reads the scalar plots and body positions of a Tether recording.
///
/// # Errors
/// A file that cannot be read or decoded, one line naming the file.
pub fn read(path: &Path) -> Result<Vec<Series>, String> {
    let fail = |what: &str, error: &dyn std::fmt::Display| format!("{}: {what}: {error}", path.display());
    let file = std::fs::File::open(path).map_err(|e| fail("cannot open the recording", &e))?;
    let mut recording = Recording::default();
    let mut messages = 0usize;
    for message in re_log_encoding::DecoderApp::decode_lazy(BufReader::new(file)) {
        let message = message.map_err(|e| fail("not a readable Rerun recording", &e))?;
        messages += 1;
        if let LogMsg::ArrowMsg(store, arrow) = message
            && store.kind() == StoreKind::Recording
        {
            let chunk = Chunk::from_arrow_msg(&arrow).map_err(|e| fail("a chunk cannot be decoded", &e))?;
            recording.add(&chunk).map_err(|e| fail("a chunk cannot be read", &e))?;
        }
    }
    if messages == 0 {
        return Err(fail("not a Rerun recording", &"no messages"));
    }
    Ok(recording.series())
}

/// What the chunks read so far hold.
#[derive(Default)]
struct Recording {
    /// Each plot entity's series, by index in its rows.
    plots: BTreeMap<String, Vec<Samples>>,
    /// Each plot entity's series names (static ones win over temporal ones).
    names: HashMap<String, (bool, Vec<String>)>,
    /// Each body's positions x, y, z.
    bodies: BTreeMap<String, [Samples; 3]>,
}

impl Recording {
    fn add(&mut self, chunk: &Chunk) -> Result<(), String> {
        let entity = path_of(chunk.entity_path());
        if let Some(names) = names_of(chunk)? {
            let is_static = chunk.is_static();
            let known = self.names.get(&entity).is_some_and(|(was_static, _)| *was_static && !is_static);
            if !known {
                self.names.insert(entity.clone(), (is_static, names));
            }
        }
        let Some(times) = sim_times(chunk) else { return Ok(()) };
        if let Some(scalars) = column(chunk, &Scalars::descriptor_scalars()) {
            let values = floats(scalars.values())
                .ok_or_else(|| format!("{entity}: scalars of type {}", scalars.value_type()))?;
            let plot = self.plots.entry(entity.clone()).or_default();
            for (row, &time) in times.iter().enumerate() {
                if scalars.is_null(row) {
                    continue;
                }
                let range = scalars.value_offsets()[row] as usize..scalars.value_offsets()[row + 1] as usize;
                for (index, value) in range.enumerate() {
                    if plot.len() <= index {
                        plot.resize_with(index + 1, Vec::new);
                    }
                    plot[index].push((time, values[value]));
                }
            }
        }
        if paths::body_of(&entity).is_some_and(|body| paths::body(body) == entity)
            && let Some(translations) = column(chunk, &Transform3D::descriptor_translation())
        {
            let vectors = translations.values().as_fixed_size_list_opt().filter(|v| v.value_length() == 3);
            let xyz = vectors
                .and_then(|v| floats(v.values()))
                .ok_or_else(|| format!("{entity}: translations of type {}", translations.value_type()))?;
            let body = self.bodies.entry(entity).or_default();
            for (row, &time) in times.iter().enumerate() {
                // A row holds one translation (a body has one pose); the last of several wins.
                let end = translations.value_offsets()[row + 1] as usize;
                if translations.is_null(row) || end == translations.value_offsets()[row] as usize {
                    continue;
                }
                for (axis, samples) in body.iter_mut().enumerate() {
                    samples.push((time, xyz[3 * (end - 1) + axis]));
                }
            }
        }
        Ok(())
    }

    /// Every series, plots by entity path then in row order, then the bodies by name.
    fn series(self) -> Vec<Series> {
        let mut all = Vec::new();
        for (entity, plot) in self.plots {
            let names = self.names.get(&entity).map(|(_, names)| names.as_slice()).unwrap_or_default();
            for (index, samples) in plot.into_iter().enumerate() {
                let name = names.get(index).cloned().unwrap_or_else(|| index.to_string());
                all.push(series(format!("{entity}/{name}"), samples));
            }
        }
        for (entity, xyz) in self.bodies {
            for (axis, samples) in ["x", "y", "z"].into_iter().zip(xyz) {
                all.push(series(format!("{entity}/{axis}"), samples));
            }
        }
        all
    }
}

/// A series from samples in file order: sorted by time, the last of equal times kept.
fn series(name: String, mut samples: Samples) -> Series {
    // Stable: samples at one time stay in file order.
    samples.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut times: Vec<f64> = Vec::with_capacity(samples.len());
    let mut values: Vec<f64> = Vec::with_capacity(samples.len());
    for (time, value) in samples {
        if times.last() == Some(&time) {
            *values.last_mut().expect("as many values as times") = value;
        } else {
            times.push(time);
            values.push(value);
        }
    }
    Series { name, times, values }
}

/// An entity path as the recorder wrote it: `plots/tension`, no leading `/`, parts unescaped.
fn path_of(entity: &EntityPath) -> String {
    entity.iter().map(|part| part.unescaped_str()).collect::<Vec<_>>().join("/")
}

/// The chunk's `sim_time` of each row \[s] (`None` for a static chunk or one without it).
fn sim_times(chunk: &Chunk) -> Option<Vec<f64>> {
    let column = chunk.timelines().get(&SIM_TIME.into())?;
    let scale = match column.timeline().typ() {
        TimeType::DurationNs | TimeType::TimestampNs => 1e-9,
        TimeType::Sequence => 1.0,
    };
    Some(column.times_raw().iter().map(|&t| t as f64 * scale).collect())
}

/// The chunk's column of component `descriptor`.
fn column<'a>(chunk: &'a Chunk, descriptor: &ComponentDescriptor) -> Option<&'a ListArray> {
    chunk.components().get_array(descriptor.component)
}

/// The values of a Float64 (or Float32) array.
fn floats(array: &ArrayRef) -> Option<Vec<f64>> {
    if let Some(values) = array.as_primitive_opt::<Float64Type>() {
        Some(values.values().to_vec())
    } else {
        array.as_primitive_opt::<Float32Type>().map(|values| values.values().iter().map(|&v| f64::from(v)).collect())
    }
}

/// The series names of a chunk's last row that has some (`SeriesLines`, else `SeriesPoints`).
fn names_of(chunk: &Chunk) -> Result<Option<Vec<String>>, String> {
    let lines = column(chunk, &SeriesLines::descriptor_names());
    let Some(names) = lines.or_else(|| column(chunk, &SeriesPoints::descriptor_names())) else {
        return Ok(None);
    };
    let Some(row) = (0..names.len()).rev().find(|&row| !names.is_null(row)) else { return Ok(None) };
    let strings = names.value(row);
    let strings = strings
        .as_string_opt::<i32>()
        .ok_or_else(|| format!("{}: series names of type {}", path_of(chunk.entity_path()), names.value_type()))?;
    Ok(Some(strings.iter().map(|name| name.unwrap_or_default().to_string()).collect()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use tether_record::{FrameSchedule, Recorder};

    const BODY: &str = "mass";
    const COUPLING: &str = "spring";

    /// What the test kept of each logged frame: time, body position, coupling tension.
    #[derive(Default)]
    struct Kept {
        times: Vec<f64>,
        x: Vec<f64>,
        z: Vec<f64>,
        tensions: Vec<f64>,
    }

    fn find<'a>(all: &'a [Series], name: &str) -> &'a Series {
        let names: Vec<&str> = all.iter().map(|s| s.name.as_str()).collect();
        all.iter().find(|s| s.name == name).unwrap_or_else(|| panic!("no series {name} among {names:?}"))
    }

    fn assert_matches(series: &Series, times: &[f64], values: &[f64]) {
        assert_eq!(series.times.len(), times.len(), "{}: samples", series.name);
        assert_eq!(series.values.len(), values.len(), "{}: values", series.name);
        for (i, ((&t, &v), (&t_kept, &v_kept))) in
            series.times.iter().zip(&series.values).zip(times.iter().zip(values)).enumerate()
        {
            // The timeline holds whole nanoseconds.
            assert!((t - t_kept).abs() <= 1e-9, "{}[{i}]: time {t} for {t_kept}", series.name);
            assert!((v - v_kept).abs() <= 1e-9 * v_kept.abs(), "{}[{i}]: {v} for {v_kept} at t = {t}", series.name);
        }
    }

    #[test]
    fn a_recorded_run_reads_back_as_its_positions_and_tensions() {
        let scene = tether_test_support::repo("scenes/spring_mass.ron");
        let mut world = tether_scene::load(&scene).expect("the scene loads").world;
        let body = world.bodies().iter().position(|b| b.name == BODY).expect("the body");
        let coupling = world.couplings().iter().position(|c| c.name == COUPLING).expect("the coupling");
        let dir = tempfile::tempdir().expect("a temporary directory");
        let file = dir.path().join("run.rrd");
        let mut recorder = Recorder::to_file(&file, &world, &Default::default()).expect("a recorder");
        let steps = (2.0 / world.dt()).round() as u64;
        let schedule = FrameSchedule::new(100.0, world.dt(), steps);
        let mut kept = Kept::default();
        let mut log = |world: &tether_physics::world::World, recorder: &mut Recorder| {
            recorder.log_frame(world).expect("a frame");
            // The recorder logs positions in single precision, tensions in double.
            let position = world.state(body).position;
            kept.times.push(world.time());
            kept.x.push(f64::from(position.x as f32));
            kept.z.push(f64::from(position.z as f32));
            kept.tensions.push(world.coupling_forces()[coupling].tension);
            // Many chunks per entity, as a long run sends.
            if kept.times.len() % 37 == 0 {
                recorder.flush().expect("a flush");
            }
        };
        log(&world, &mut recorder);
        for step in 1..=steps {
            world.step().expect("a step");
            if schedule.is_due(step) {
                log(&world, &mut recorder);
            }
        }
        recorder.finish().expect("the recording closes");
        assert_eq!(kept.times.len(), 201);
        assert!(kept.x.iter().any(|&x| (x - kept.x[0]).abs() > 1e-3), "the mass moves");

        let all = read(&file).expect("the recording reads");
        let names: Vec<&str> = all.iter().map(|s| s.name.as_str()).collect();
        assert_matches(find(&all, &format!("world/bodies/{BODY}/z")), &kept.times, &kept.z);
        assert_matches(find(&all, &format!("world/bodies/{BODY}/x")), &kept.times, &kept.x);
        assert_matches(find(&all, &format!("plots/tension/{COUPLING}")), &kept.times, &kept.tensions);
        assert!(names.contains(&"plots/energy/moving/kinetic"), "{names:?}");
        for series in &all {
            assert_eq!(series.times.len(), kept.times.len(), "{}", series.name);
            assert!(series.times.windows(2).all(|w| w[0] < w[1]), "{}: times increase", series.name);
        }
    }

    #[test]
    fn samples_are_sorted_and_the_last_of_equal_times_kept() {
        let s = series("s".into(), vec![(2.0, 20.0), (1.0, 10.0), (2.0, 21.0), (0.5, 5.0), (1.0, 11.0)]);
        assert_eq!(s.times, [0.5, 1.0, 2.0]);
        assert_eq!(s.values, [5.0, 11.0, 21.0]);
    }

    #[test]
    fn a_file_that_is_not_a_recording_is_an_error_naming_it() {
        let dir = tempfile::tempdir().expect("a temporary directory");
        for (name, text) in [("notes.rrd", &b"not a recording, only some text\n"[..]), ("empty.rrd", b"")] {
            let path = dir.path().join(name);
            std::fs::write(&path, text).expect("written");
            let error = read(&path).expect_err("not a recording");
            assert!(error.contains(&path.display().to_string()), "{error}");
            assert!(!error.contains('\n'), "{error}");
        }
        let missing = dir.path().join("missing.rrd");
        let error = read(&missing).expect_err("no file");
        assert!(error.contains(&missing.display().to_string()), "{error}");
    }
}
