//! The GUI's simulation thread on `scenes/bench/chain100.ron` against the headless physics,
//! measured A/B in one run: the same world (the chain resting on the ground after 6 s, contact
//! on every sphere) stepped by a bare loop, and run by the GUI's simulation thread "as fast as
//! possible" and at ×1 with its recording fed, through the stream the window uses, into a
//! viewer's store (`EntityDb::add_log_msg` on a thread of its own, what the embedded viewer does
//! with each message before it draws).
//!
//! `cargo bench -p tether --bench live` prints, per round: headless steps/s; the GUI thread's
//! steps/s as fast as possible and its share of the headless speed; at ×1 the CPU the process
//! and the viewer's ingestion take per wall second, and how often the viewer's latest frame
//! moved on (its longest wait between two).

use rerun::external::re_entity_db::EntityDb;
use rerun::log::LogMsg;
use rerun::sink::{CallbackSink, LogSink};
use std::collections::HashMap;
use std::sync::mpsc;
use std::time::{Duration, Instant};
use tether::gui::simulation::{Command, Report, Run, Simulation, Speed};
use tether::gui::stream::Sinks;
use tether_analysis::runner::{process_cpu_seconds, thread_cpu_seconds};
use tether_physics::world::World;

/// Wall time of each measurement.
const SPAN: Duration = Duration::from_secs(4);

/// Rounds of the A/B comparison (the machine is shared: its speed drifts).
const ROUNDS: usize = 3;

fn main() {
    let path = std::path::PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR when it runs a test"),
    )
    .join("scenes/bench/chain100.ron");
    let scene = tether_scene::load(&path).expect("the shipped bench scene");
    let duration = scene.file.duration;
    let mut world = scene.world;
    // 6 s: the chain has fallen and its middle rests on the ground, every step pays for contact.
    for _ in 0..3000 {
        world.step().expect("the shipped scene is stable");
    }
    println!("chain100 from t = 6 s, {} s per measurement", SPAN.as_secs());
    for round in 1..=ROUNDS {
        let headless = headless(world.clone());
        let fastest = live(world.clone(), duration, Speed::Max);
        let real_time = live(world.clone(), duration, Speed::Factor(1.0));
        println!(
            "round {round}: headless {headless:.0} steps/s; GUI as fast as possible {:.0} steps/s ({:.0}% of headless), viewer ingestion {:.2} CPU s/s",
            fastest.steps_per_second,
            100.0 * fastest.steps_per_second / headless,
            fastest.ingest_cpu
        );
        println!(
            "         GUI at ×1: {:.2} sim s/s, process {:.2} CPU s/s (viewer ingestion {:.2}), the viewer's latest frame moved on {:.0} times/s, longest wait {:.0} ms",
            real_time.rate,
            real_time.process_cpu,
            real_time.ingest_cpu,
            real_time.updates_per_second,
            real_time.longest_wait.as_secs_f64() * 1e3
        );
    }
}

/// Bare world steps per second for [`SPAN`].
fn headless(mut world: World) -> f64 {
    let start = Instant::now();
    let mut steps = 0_u64;
    while start.elapsed() < SPAN {
        for _ in 0..100 {
            world.step().expect("the shipped scene is stable");
        }
        steps += 100;
    }
    steps as f64 / start.elapsed().as_secs_f64()
}

/// What a live run measured.
struct Live {
    steps_per_second: f64,
    /// Simulated seconds per wall second.
    rate: f64,
    /// CPU seconds per wall second: the whole process, the viewer's ingestion.
    process_cpu: f64,
    ingest_cpu: f64,
    /// How often the latest `sim_time` in the viewer's store moved on, and the longest wall
    /// time between two moves.
    updates_per_second: f64,
    longest_wait: Duration,
}

/// Runs `world` on the GUI's simulation thread at `speed` for [`SPAN`], its recording ingested
/// as the embedded viewer ingests it.
fn live(world: World, duration: f64, speed: Speed) -> Live {
    let (messages, inbox) = mpsc::channel::<Vec<LogMsg>>();
    let sink: Box<dyn LogSink> = Box::new(CallbackSink::new(move |batch: &[LogMsg]| {
        messages.send(batch.to_vec()).ok();
    }));
    let viewer = std::thread::spawn(move || ingest(&inbox));
    let mut simulation =
        Simulation::spawn(Sinks::new(vec![sink]), std::sync::Arc::new(|| {})).expect("the simulation thread");
    simulation.send(Command::Load(Box::new(Run { label: "chain100".into(), world, duration })));
    simulation.send(Command::SetSpeed(speed));
    simulation.send(Command::Play);
    let (cpu_start, start) = (process_cpu_seconds(), Instant::now());
    let mut first: Option<(Instant, u64, f64)> = None;
    let mut last = first;
    while start.elapsed() < SPAN {
        std::thread::sleep(Duration::from_millis(50));
        for report in simulation.drain() {
            match report {
                Report::Status(status) if status.running => {
                    let now = (Instant::now(), status.steps, status.time);
                    first.get_or_insert(now);
                    last = Some(now);
                }
                Report::Error(message) => panic!("the simulation failed: {message}"),
                _ => {}
            }
        }
    }
    let process_cpu = (process_cpu_seconds() - cpu_start) / start.elapsed().as_secs_f64();
    simulation.stop();
    drop(simulation);
    let ingested = viewer.join().expect("the ingestion thread");
    let ((t0, steps0, sim0), (t1, steps1, sim1)) = (first.expect("a status"), last.expect("a status"));
    let wall = (t1 - t0).as_secs_f64().max(f64::MIN_POSITIVE);
    Live {
        steps_per_second: (steps1 - steps0) as f64 / wall,
        rate: (sim1 - sim0) / wall,
        process_cpu,
        ingest_cpu: ingested.cpu / ingested.span.as_secs_f64().max(f64::MIN_POSITIVE),
        updates_per_second: ingested.updates as f64 / ingested.span.as_secs_f64().max(f64::MIN_POSITIVE),
        longest_wait: ingested.longest_wait,
    }
}

/// What the viewer's side did.
struct Ingested {
    cpu: f64,
    /// Wall time from the first frame to the last.
    span: Duration,
    updates: u64,
    longest_wait: Duration,
}

/// Adds every message to its store, as the viewer does, until the stream closes; times the
/// moves of the recording's latest `sim_time`.
fn ingest(inbox: &mpsc::Receiver<Vec<LogMsg>>) -> Ingested {
    let cpu_start = thread_cpu_seconds();
    let mut stores: HashMap<rerun::StoreId, EntityDb> = HashMap::new();
    let (mut latest, mut moved, mut first) = (None, None::<Instant>, None::<Instant>);
    let (mut updates, mut longest_wait) = (0, Duration::ZERO);
    for batch in inbox {
        for message in &batch {
            let db =
                stores.entry(message.store_id().clone()).or_insert_with(|| EntityDb::new(message.store_id().clone()));
            db.add_log_msg(message).expect("a message the viewer takes");
            let newest = db.time_range_for(&"sim_time".into()).map(|range| range.max());
            if newest.is_some() && newest > latest {
                let now = Instant::now();
                if let Some(before) = moved {
                    longest_wait = longest_wait.max(now - before);
                }
                (latest, moved) = (newest, Some(now));
                first.get_or_insert(now);
                updates += 1;
            }
        }
    }
    let span = match (first, moved) {
        (Some(first), Some(last)) => last - first,
        _ => Duration::ZERO,
    };
    Ingested { cpu: thread_cpu_seconds() - cpu_start, span, updates, longest_wait }
}
