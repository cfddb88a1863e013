//! A sweep's output directory:
//!
//! ```text
//! DIR/sweep.json              what sweep this is: the spec's and the base scene's text, the columns
//! DIR/runs/all.csv            the rows of a run of the whole sweep, one per case as it finishes
//! DIR/runs/shard-2-of-4.csv   the rows of shard 2 of 4
//! DIR/recordings/case-17.rrd  with --record: case 17's recording
//! DIR/results.csv, results.parquet, summary.md, plots/   once every case has a row
//! ```
//!
//! A row is appended to its run file with one `write` as its case finishes (results stream to
//! disk: a sweep holds no row in memory), so a killed run loses at most the cases in flight; a
//! torn last line (a machine that went down mid-write) is cut off when the file is opened again.
//! Several shards write into one directory at once, each to its own file; the manifest is
//! written by whichever comes first, atomically (a temporary file renamed), and the others
//! check that it describes their sweep. Nothing of another sweep is ever overwritten.

use super::error::SweepError;
use super::table::{Columns, Row};
use serde::{Deserialize, Serialize};
use std::fs::{self, File, OpenOptions};
use std::io::{Read as _, Seek as _, SeekFrom, Write as _};
use std::path::{Path, PathBuf};

/// The manifest's file name.
pub const MANIFEST: &str = "sweep.json";
/// The folder of run files.
pub const RUNS: &str = "runs";
/// The folder of recordings.
pub const RECORDINGS: &str = "recordings";
/// The run file of a run of the whole sweep.
pub const ALL: &str = "all.csv";

/// Version of the directory's layout.
const FORMAT: u32 = 1;

/// What sweep a directory holds.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Manifest {
    pub format: u32,
    pub name: String,
    /// Where the spec and the base scene were read from (absolute), and what they said.
    pub spec_path: PathBuf,
    pub spec_text: String,
    pub scene_path: PathBuf,
    pub scene_text: String,
    pub cases: usize,
    pub columns: Columns,
}

impl Manifest {
    /// The manifest of a sweep of `cases` cases from these files and texts.
    pub fn new(name: &str, spec: (&Path, &str), scene: (&Path, &str), cases: usize, columns: Columns) -> Self {
        let absolute = |p: &Path| std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf());
        Self {
            format: FORMAT,
            name: name.to_string(),
            spec_path: absolute(spec.0),
            spec_text: spec.1.to_string(),
            scene_path: absolute(scene.0),
            scene_text: scene.1.to_string(),
            cases,
            columns,
        }
    }

    /// Why `self` (in a directory) is not the sweep `other`, if it is not.
    fn differs_from(&self, other: &Self) -> Option<&'static str> {
        if self.format != other.format {
            Some("it was written by another version of tether")
        } else if self.spec_text != other.spec_text {
            Some("its spec is not this one")
        } else if self.scene_text != other.scene_text {
            Some("its base scene said something else")
        } else if self.columns != other.columns || self.cases != other.cases {
            Some("its cases or columns differ")
        } else {
            None
        }
    }
}

/// A sweep's output directory.
#[derive(Debug, Clone)]
pub struct Store {
    dir: PathBuf,
}

impl Store {
    pub fn new(dir: &Path) -> Self {
        Self { dir: dir.to_path_buf() }
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The path of `name` in the directory.
    pub fn path(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }

    /// The directory's manifest, if it has one.
    ///
    /// # Errors
    /// A manifest that cannot be read or is not one.
    pub fn manifest(&self) -> Result<Option<Manifest>, SweepError> {
        let path = self.path(MANIFEST);
        match fs::read_to_string(&path) {
            Ok(text) => serde_json::from_str(&text)
                .map(Some)
                .map_err(|e| SweepError::Directory(format!("{}: not a sweep manifest: {e}", path.display()))),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(io(&path, "cannot read", &e)),
        }
    }

    /// Checks, touching nothing, that this directory can take the sweep `manifest`: it is
    /// absent or empty, or it holds the same sweep. Returns which cases have a row already.
    ///
    /// Another shard may be creating the directory meanwhile, and [`Store::create`] writes the
    /// manifest before anything else: a directory found not empty without a manifest is looked
    /// at once more, since the manifest may have appeared between the two looks.
    ///
    /// # Errors
    /// A directory that holds another sweep, or files that are not a sweep's.
    pub fn check(&self, manifest: &Manifest) -> Result<Vec<bool>, SweepError> {
        let dir = self.dir.display();
        let found = match self.manifest()? {
            Some(found) => found,
            None if !self.dir.exists() || self.is_empty()? => return Ok(vec![false; manifest.cases]),
            None => self.manifest()?.ok_or_else(|| {
                SweepError::Directory(format!("{dir} is not empty and holds no sweep: choose a new or empty directory"))
            })?,
        };
        if let Some(why) = found.differs_from(manifest) {
            return Err(SweepError::Directory(format!(
                "{dir} holds another sweep's results ({why}; spec {}): choose another directory",
                found.spec_path.display()
            )));
        }
        self.done_cases(manifest)
    }

    /// Whether the directory has nothing in it but another run's temporary manifest.
    fn is_empty(&self) -> Result<bool, SweepError> {
        let entries = fs::read_dir(&self.dir).map_err(|e| io(&self.dir, "cannot list", &e))?;
        Ok(entries.filter_map(Result::ok).all(|e| e.file_name().to_string_lossy().starts_with(".sweep.json.")))
    }

    /// Creates the directory, its manifest (unless it has one: another shard's), then its runs
    /// folder — in that order, because shards start at the same time: another shard's
    /// [`Store::check`] must find the directory empty (but for a temporary manifest) or holding
    /// the manifest, never holding a runs folder without one.
    ///
    /// # Errors
    /// A directory or file that cannot be written.
    pub fn create(&self, manifest: &Manifest) -> Result<(), SweepError> {
        fs::create_dir_all(&self.dir).map_err(|e| io(&self.dir, "cannot create", &e))?;
        if self.manifest()?.is_none() {
            let text = serde_json::to_string_pretty(manifest).map_err(|e| SweepError::Directory(e.to_string()))?;
            write_atomically(&self.path(MANIFEST), text.as_bytes())?;
        }
        let runs = self.path(RUNS);
        fs::create_dir_all(&runs).map_err(|e| io(&runs, "cannot create", &e))
    }

    /// The run files, sorted.
    ///
    /// # Errors
    /// The folder cannot be listed.
    pub fn run_files(&self) -> Result<Vec<PathBuf>, SweepError> {
        let folder = self.path(RUNS);
        let entries = match fs::read_dir(&folder) {
            Ok(entries) => entries,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
            Err(e) => return Err(io(&folder, "cannot list", &e)),
        };
        let mut files: Vec<PathBuf> = entries
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "csv"))
            .collect();
        files.sort();
        Ok(files)
    }

    /// Which cases have a row in any run file.
    ///
    /// # Errors
    /// A run file that cannot be read, or a row of it that is not one of this sweep's.
    pub fn done_cases(&self, manifest: &Manifest) -> Result<Vec<bool>, SweepError> {
        let mut done = vec![false; manifest.cases];
        for path in self.run_files()? {
            for_each_row(&path, &manifest.columns, |row, _| {
                match done.get_mut(row.case) {
                    Some(slot) => *slot = true,
                    None => return Err(format!("case {} is beyond the sweep's {} cases", row.case, manifest.cases)),
                }
                Ok(())
            })?;
        }
        Ok(done)
    }

    /// Opens run file `name` to append rows to (writing its header if it is new).
    ///
    /// # Errors
    /// The file cannot be opened or written.
    pub fn open_run(&self, name: &str, columns: &Columns) -> Result<RunFile, SweepError> {
        let path = self.path(RUNS).join(name);
        let mut file = OpenOptions::new()
            .read(true)
            .append(true)
            .create(true)
            .open(&path)
            .map_err(|e| io(&path, "cannot open", &e))?;
        let length = file.metadata().map_err(|e| io(&path, "cannot read", &e))?.len();
        if length == 0 {
            file.write_all(&csv_line(&columns.header())).map_err(|e| io(&path, "cannot write", &e))?;
        } else {
            let complete = complete_length(&mut file).map_err(|e| io(&path, "cannot read", &e))?;
            if complete < length {
                file.set_len(complete).map_err(|e| io(&path, "cannot cut the torn last line of", &e))?;
            }
        }
        Ok(RunFile { file, path, columns: columns.clone() })
    }
}

/// A run file open for appending.
pub struct RunFile {
    file: File,
    path: PathBuf,
    columns: Columns,
}

impl RunFile {
    /// Appends `row` in one write.
    ///
    /// # Errors
    /// The write failed (a full disk): the row is not in the file.
    pub fn append(&mut self, row: &Row) -> Result<(), SweepError> {
        self.file.write_all(&csv_line(&self.columns.record(row))).map_err(|e| io(&self.path, "cannot write", &e))
    }
}

/// `fields` as one CSV line.
fn csv_line(fields: &[String]) -> Vec<u8> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    // Writing to memory cannot fail.
    writer.write_record(fields).ok();
    writer.into_inner().unwrap_or_default()
}

/// Length of `file` up to its last newline: what whole lines it holds.
fn complete_length(file: &mut File) -> std::io::Result<u64> {
    let length = file.seek(SeekFrom::End(0))?;
    let mut tail = Vec::new();
    let mut from = length;
    // Back through the file in blocks until a newline turns up.
    while from > 0 {
        let start = from.saturating_sub(4096);
        file.seek(SeekFrom::Start(start))?;
        tail.resize((from - start) as usize, 0);
        file.read_exact(&mut tail)?;
        if let Some(at) = tail.iter().rposition(|&b| b == b'\n') {
            return Ok(start + at as u64 + 1);
        }
        from = start;
    }
    Ok(0)
}

/// Calls `each(row, position)` for every whole row of the run file at `path`, checking its
/// header; a torn last line is left out, and a file without a whole line (its header being
/// written) has no rows.
///
/// # Errors
/// A file that cannot be read, a header of other columns, a row that does not read.
pub fn for_each_row(
    path: &Path,
    columns: &Columns,
    mut each: impl FnMut(Row, csv::Position) -> Result<(), String>,
) -> Result<(), SweepError> {
    let fail = |line: u64, message: String| SweepError::Directory(format!("{}:{line}: {message}", path.display()));
    let mut file = File::open(path).map_err(|e| io(path, "cannot open", &e))?;
    let complete = complete_length(&mut file).map_err(|e| io(path, "cannot read", &e))?;
    if complete == 0 {
        // Not even its header yet: a file another shard has just created.
        return Ok(());
    }
    file.seek(SeekFrom::Start(0)).map_err(|e| io(path, "cannot read", &e))?;
    let mut reader = csv::Reader::from_reader(file.take(complete));
    let header = reader.headers().map_err(|e| fail(1, e.to_string()))?.clone();
    if header.iter().ne(columns.header().iter().map(String::as_str)) {
        return Err(fail(1, "its columns are not this sweep's".into()));
    }
    let mut record = csv::StringRecord::new();
    loop {
        let position = reader.position().clone();
        match reader.read_record(&mut record) {
            Ok(false) => return Ok(()),
            Ok(true) => {
                let row = columns.parse(&record).map_err(|m| fail(position.line(), m))?;
                each(row, position.clone()).map_err(|m| fail(position.line(), m))?;
            }
            Err(e) => return Err(fail(position.line(), e.to_string())),
        }
    }
}

/// Writes `bytes` to `path` through a temporary file in the same folder, renamed over it: a
/// reader sees the old file or the new, never part of one.
///
/// # Errors
/// The file cannot be written.
pub fn write_atomically(path: &Path, bytes: &[u8]) -> Result<(), SweepError> {
    let name = path.file_name().map_or_else(|| "file".into(), |n| n.to_string_lossy().into_owned());
    let temporary = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    fs::write(&temporary, bytes).map_err(|e| io(&temporary, "cannot write", &e))?;
    fs::rename(&temporary, path).map_err(|e| io(path, "cannot write", &e))
}

/// An I/O error on `path`.
pub fn io(path: &Path, doing: &str, error: &std::io::Error) -> SweepError {
    SweepError::Io { path: path.display().to_string(), message: format!("{doing} it: {error}") }
}
