//! A sweep on a real Slurm cluster of one node: munge, slurmctld and slurmd from the
//! distribution's packages (`slurm-wlm`, `munge`), a generated `slurm.conf` on 127.0.0.1 with
//! free ports and everything — munge's socket, state, spool, logs, pid files — in a temporary
//! directory. The sweep goes through `examples/slurm/submit.sh` as a job array of four tasks
//! and a merge job that waits for them (`--dependency=afterok`); the merged results must equal
//! a local `--jobs 1` run of the same spec, row for row. The daemons are stopped by their pid
//! files whatever happens (the cluster's `Drop` runs on a failed assertion too).
//!
//! It needs root and the two packages, so it is ignored by a plain `cargo test`; `.ci/run`
//! installs the packages and runs it: `cargo test --release -p tether --test slurm -- --ignored`.
//! With `TETHER_SLURM_PID_FILES` set to a file, each daemon's pid file is also listed there, so
//! that `.ci/run` can stop the daemons even if this test is killed before its `Drop` runs.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

/// How long the jobs may take before the test gives up.
const PATIENCE: Duration = Duration::from_secs(300);

/// A one-node Slurm cluster, stopped when dropped.
struct Cluster {
    dir: tempfile::TempDir,
    /// Pid files of the daemons started, in the order started.
    started: Vec<PathBuf>,
}

impl Cluster {
    /// Starts munged, slurmctld and slurmd and waits for the node to be idle.
    fn start() -> Self {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path().to_path_buf();
        // munged runs as the munge user: it must reach its folder through ours.
        set_mode(&root, 0o755);
        let munge = root.join("munge");
        for folder in [&munge, &root.join("state"), &root.join("spool")] {
            std::fs::create_dir(folder).unwrap();
        }
        set_mode(&munge, 0o755);
        assert!(
            Command::new("chown").args(["munge:munge"]).arg(&munge).status().unwrap().success(),
            "chown munge: is the munge package installed?"
        );
        let mut cluster = Self { dir, started: Vec::new() };
        let path = |name: &str| root.join(name).display().to_string();
        let munged = Command::new("runuser")
            .args(["-u", "munge", "--", "/usr/sbin/munged", "--force"])
            .arg(format!("--socket={}", path("munge/munge.socket")))
            .arg(format!("--pid-file={}", path("munge/munged.pid")))
            .arg(format!("--log-file={}", path("munge/munged.log")))
            .arg(format!("--seed-file={}", path("munge/munged.seed")))
            .output()
            .expect("munged (apt-get install munge)");
        assert!(munged.status.success(), "munged: {}", String::from_utf8_lossy(&munged.stderr));
        cluster.started(root.join("munge/munged.pid"));
        let (controller, node) = (free_port(), free_port());
        let cpus = std::thread::available_parallelism().map_or(1, |n| n.get());
        let conf = format!(
            "ClusterName=tether-ci\nSlurmctldHost=localhost(127.0.0.1)\nSlurmctldPort={controller}\nSlurmdPort={node}\n\
             SlurmUser=root\nSlurmdUser=root\nAuthType=auth/munge\nAuthInfo=socket={socket}\nCredType=cred/munge\n\
             StateSaveLocation={state}\nSlurmdSpoolDir={spool}\nSlurmctldPidFile={ctld_pid}\nSlurmdPidFile={d_pid}\n\
             SlurmctldLogFile={ctld_log}\nSlurmdLogFile={d_log}\nProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n\
             SelectType=select/cons_tres\nSelectTypeParameters=CR_Core\nReturnToService=2\nMpiDefault=none\n\
             AccountingStorageType=accounting_storage/none\nJobCompType=jobcomp/none\nJobAcctGatherType=jobacct_gather/none\n\
             NodeName=localhost NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN\n\
             PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP\n",
            socket = path("munge/munge.socket"),
            state = path("state"),
            spool = path("spool"),
            ctld_pid = path("slurmctld.pid"),
            d_pid = path("slurmd.pid"),
            ctld_log = path("slurmctld.log"),
            d_log = path("slurmd.log"),
        );
        std::fs::write(root.join("slurm.conf"), conf).unwrap();
        for (daemon, args, pid) in
            [("slurmctld", vec!["-i"], "slurmctld.pid"), ("slurmd", vec!["-N", "localhost"], "slurmd.pid")]
        {
            let out = cluster
                .command(&format!("/usr/sbin/{daemon}"))
                .args(args)
                .output()
                .unwrap_or_else(|e| panic!("{daemon} (apt-get install slurm-wlm): {e}"));
            assert!(out.status.success(), "{daemon}: {}\n{}", String::from_utf8_lossy(&out.stderr), cluster.logs());
            cluster.started(root.join(pid));
        }
        let start = Instant::now();
        while run(cluster.command("sinfo").args(["-h", "-o", "%T"])).trim() != "idle" {
            assert!(start.elapsed() < Duration::from_secs(30), "the node is not idle after 30 s\n{}", cluster.logs());
            std::thread::sleep(Duration::from_millis(200));
        }
        cluster
    }

    /// Notes a daemon started, by its pid file (and in `TETHER_SLURM_PID_FILES`, if set).
    fn started(&mut self, pid_file: PathBuf) {
        if let Some(list) = std::env::var_os("TETHER_SLURM_PID_FILES") {
            use std::io::Write as _;
            let mut file = std::fs::OpenOptions::new().append(true).create(true).open(list).unwrap();
            writeln!(file, "{}", pid_file.display()).unwrap();
        }
        self.started.push(pid_file);
    }

    /// A Slurm command (or daemon) of this cluster.
    fn command(&self, program: &str) -> Command {
        let mut command = Command::new(program);
        command.env("SLURM_CONF", self.dir.path().join("slurm.conf"));
        command
    }

    /// Waits until no job is queued or running.
    fn wait_for_jobs(&self) {
        let start = Instant::now();
        while !run(self.command("squeue").arg("-h")).trim().is_empty() {
            assert!(
                start.elapsed() < PATIENCE,
                "jobs still queued after {PATIENCE:?}:\n{}\n{}",
                run(&mut self.command("squeue")),
                self.logs()
            );
            std::thread::sleep(Duration::from_millis(500));
        }
    }

    /// The daemons' logs, for a failure's message.
    fn logs(&self) -> String {
        ["munge/munged.log", "slurmctld.log", "slurmd.log"]
            .iter()
            .map(|name| {
                format!("--- {name}\n{}", std::fs::read_to_string(self.dir.path().join(name)).unwrap_or_default())
            })
            .collect::<Vec<_>>()
            .join("\n")
    }
}

impl Drop for Cluster {
    /// Stops the daemons started, last first, by the pids in their pid files: SIGTERM, then
    /// SIGKILL after 10 s.
    fn drop(&mut self) {
        for pid_file in self.started.iter().rev() {
            let Some(pid) = std::fs::read_to_string(pid_file).ok().and_then(|t| t.trim().parse::<libc::pid_t>().ok())
            else {
                continue;
            };
            // SAFETY: signalling a pid read from the daemon's own pid file.
            unsafe { libc::kill(pid, libc::SIGTERM) };
            let start = Instant::now();
            while Path::new(&format!("/proc/{pid}")).exists() && start.elapsed() < Duration::from_secs(10) {
                std::thread::sleep(Duration::from_millis(50));
            }
            if Path::new(&format!("/proc/{pid}")).exists() {
                // SAFETY: as above.
                unsafe { libc::kill(pid, libc::SIGKILL) };
            }
        }
    }
}

fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt as _;
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// A TCP port free on 127.0.0.1 now.
fn free_port() -> u16 {
    std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port()
}

/// The stdout of `command`, which must succeed.
fn run(command: &mut Command) -> String {
    let out: Output = command.output().unwrap_or_else(|e| panic!("{command:?}: {e}"));
    assert!(out.status.success(), "{command:?}: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The rows of a results table without the `cpu_s` column (a measurement).
fn without_cpu(path: &Path) -> Vec<Vec<String>> {
    let mut reader = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    let cpu = header.iter().position(|h| h == "cpu_s").unwrap();
    let rows = reader.records().map(|r| r.unwrap().iter().map(String::from).collect::<Vec<_>>());
    std::iter::once(header)
        .chain(rows)
        .map(|mut row| {
            row.remove(cpu);
            row
        })
        .collect()
}

#[test]
#[ignore = "needs root and the slurm-wlm and munge packages: .ci/run installs them and runs it"]
fn a_job_array_and_its_merge_give_the_rows_of_a_local_run() {
    let begin = Instant::now();
    let cluster = Cluster::start();
    let started = begin.elapsed();
    let work = cluster.dir.path().join("work");
    std::fs::create_dir(&work).unwrap();
    std::fs::write(work.join("spring.ron"), common::spring_scene_text("m")).unwrap();
    let spec = r#"Sweep(scene: "spring.ron", duration: 2.0, design: Grid, factors: [
        Factor(path: "couplings.spring.law.stiffness", values: Log(from: 50.0, to: 5000.0, count: 5)),
        Factor(path: "integrator", values: List(["leapfrog", "rk4"])),
    ])"#;
    std::fs::write(work.join("sweep.ron"), spec).unwrap();
    let submitted = run(cluster
        .command(&common::repo("examples/slurm/submit.sh").display().to_string())
        .args(["sweep.ron", "cluster-out", "4", "--cpus-per-task=1"])
        .env("TETHER", env!("CARGO_BIN_EXE_tether"))
        .current_dir(&work));
    assert!(submitted.starts_with("array job ") && submitted.contains("(4 tasks), merge job "), "{submitted}");
    cluster.wait_for_jobs();
    let jobs = begin.elapsed() - started;
    let outputs: String = std::fs::read_dir(&work)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "out"))
        .map(|p| format!("--- {}\n{}", p.display(), std::fs::read_to_string(&p).unwrap_or_default()))
        .collect();
    let merged = work.join("cluster-out/results.csv");
    assert!(merged.is_file(), "no merged results:\n{outputs}\n{}", cluster.logs());
    for shard in 0..4 {
        assert!(
            work.join(format!("cluster-out/runs/shard-{shard}-of-4.csv")).is_file(),
            "shard {shard}'s rows:\n{outputs}"
        );
    }
    let local = Command::new(env!("CARGO_BIN_EXE_tether"))
        .args(["sweep", "sweep.ron", "-o", "local", "--jobs", "1"])
        .current_dir(&work)
        .output()
        .unwrap();
    assert!(local.status.success(), "{}", String::from_utf8_lossy(&local.stderr));
    let rows = without_cpu(&merged);
    assert_eq!(rows.len(), 11, "header and ten cases");
    assert_eq!(rows, without_cpu(&work.join("local/results.csv")), "the cluster's rows are the local run's");
    let storm_began = Instant::now();
    a_storms_array_and_report_give_the_local_storm(&cluster, &work);
    eprintln!(
        "slurm: cluster up in {:.1} s, the sweep's array and merge done in {:.1} s, the storm's in {:.1} s, {:.1} s in all",
        started.as_secs_f64(),
        jobs.as_secs_f64(),
        storm_began.elapsed().as_secs_f64(),
        begin.elapsed().as_secs_f64()
    );
}

/// A storm (docs/design-loads.md) through `examples/slurm/submit-storm.sh`: three seeds as a job
/// array of three tasks and its report job; its `storm.csv` equals a local `--jobs 1` storm's,
/// byte for byte (the seeds' rows are the same bit for bit, and so are their fits).
fn a_storms_array_and_report_give_the_local_storm(cluster: &Cluster, work: &Path) {
    let scene = common::repo("scenes/buoy_in_a_storm.ron").display().to_string();
    let storm_args = "--hours 0.005 --seeds 3 --warmup 10";
    let submitted = run(cluster
        .command(&common::repo("examples/slurm/submit-storm.sh").display().to_string())
        .args([scene.as_str(), "storm-cluster", "3", "--cpus-per-task=1"])
        .env("TETHER", env!("CARGO_BIN_EXE_tether"))
        .env("STORM_ARGS", storm_args)
        .current_dir(work));
    assert!(submitted.starts_with("array job ") && submitted.contains("(3 tasks), report job "), "{submitted}");
    cluster.wait_for_jobs();
    let report = work.join("storm-cluster/storm.csv");
    assert!(report.is_file(), "no storm report:\n{}", cluster.logs());
    let mut local_args = vec!["storm", scene.as_str(), "-o", "storm-local", "--jobs", "1"];
    local_args.extend(storm_args.split(' '));
    let local = Command::new(env!("CARGO_BIN_EXE_tether")).args(&local_args).current_dir(work).output().unwrap();
    assert!(local.status.success(), "{}", String::from_utf8_lossy(&local.stderr));
    let read = |path: PathBuf| std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(read(report), read(work.join("storm-local/storm.csv")), "the cluster's storm is the local one's");
}
