//! Generated and mutated scene text fed to the loader, the builder and the stepper: nothing
//! panics, every error is one `path:line:col: message` line, and no accepted world produces a
//! non-finite state without reporting it (PHYSICS.md §5 "Health check"). Bounded: a fixed number of cases per run.
//! Inputs that once broke something are kept in `tests/regressions/`.

use tether_test_support as common;

use proptest::prelude::*;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

const TOKENS: &[&str] = &[
    "NaN",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "-1",
    "0",
    "0.0",
    "1e-320",
    "1e400",
    "(",
    ")",
    "[",
    "]",
    ",",
    ":",
    "\"",
    "\n",
    "//",
    "/*",
    "*/",
    "é",
    "\u{0}",
    "Body(",
    "name: \"x\"",
    "World((0, 0, 0))",
    "Body(body: \"ghost\")",
    "Linear(stiffness: -5, rest_length: 0)",
    "Catenary(name: \"c\", end1: World((0,0,0)), end2: World((0,0,0)), mass_per_length: 1, length: 1, stiffness: 1),",
    "Fixed(translation: (true, true, true), rotation: true)",
    "Kinematic(velocity: Table([(0.0, (0, 0, 0))]))",
    "Sphere(radius: 0)",
    "slaves: [Node(position: (0, 0, 0), mass: 0)],",
    "ForceCurve(points: [(1, 1)])",
    "mass: -3",
    "dt: 1e-300,",
];

#[derive(Debug, Clone)]
enum Mutation {
    Delete { at: usize, len: usize },
    Insert { at: usize, token: usize },
    Number { nth: usize, token: usize },
    DuplicateLine { nth: usize },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), 1usize..40).prop_map(|(at, len)| Mutation::Delete { at, len }),
        (any::<usize>(), 0..TOKENS.len()).prop_map(|(at, token)| Mutation::Insert { at, token }),
        (any::<usize>(), 0..16usize).prop_map(|(nth, token)| Mutation::Number { nth, token }),
        any::<usize>().prop_map(|nth| Mutation::DuplicateLine { nth }),
    ]
}

fn apply(text: &str, m: &Mutation) -> String {
    let chars: Vec<char> = text.chars().collect();
    match *m {
        Mutation::Delete { at, len } => {
            let at = at % (chars.len() + 1);
            chars[..at].iter().chain(chars[(at + len).min(chars.len())..].iter()).collect()
        }
        Mutation::Insert { at, token } => {
            let at = at % (chars.len() + 1);
            chars[..at].iter().collect::<String>() + TOKENS[token] + &chars[at..].iter().collect::<String>()
        }
        Mutation::Number { nth, token } => {
            // Replace the nth number-looking run of characters.
            let starts: Vec<usize> = (0..chars.len())
                .filter(|&i| {
                    chars[i].is_ascii_digit()
                        && (i == 0 || !chars[i - 1].is_ascii_alphanumeric() && chars[i - 1] != '.')
                })
                .collect();
            if starts.is_empty() {
                return text.to_string();
            }
            let start = starts[nth % starts.len()];
            let end = (start..chars.len())
                .find(|&i| !(chars[i].is_ascii_digit() || chars[i] == '.' || chars[i] == 'e' || chars[i] == '-'))
                .unwrap_or(chars.len());
            chars[..start].iter().collect::<String>() + TOKENS[token % 12] + &chars[end..].iter().collect::<String>()
        }
        Mutation::DuplicateLine { nth } => {
            let lines: Vec<&str> = text.lines().collect();
            let n = nth % lines.len().max(1);
            let mut out: Vec<&str> = lines.clone();
            if let Some(line) = lines.get(n) {
                out.insert(n, line);
            }
            out.join("\n")
        }
    }
}

/// The most integrator steps one case takes (see [`exercise`]).
const MAX_INTEGRATOR_STEPS: u64 = 20_000;

/// Loads `text`; on success steps it, checking that every step is either healthy (all states
/// finite) or an error. Returns a description of what went wrong, if anything.
pub fn exercise(text: &str) -> Result<(), String> {
    let outcome = catch_unwind(AssertUnwindSafe(|| -> Result<(), String> {
        match tether_scene::parse(text, Path::new("fuzz.ron")) {
            Err(error) => {
                let message = error.to_string();
                let well_formed = message.lines().count() == 1
                    && message.strip_prefix("fuzz.ron:").and_then(|rest| {
                        let mut parts = rest.splitn(3, ':');
                        Some(
                            parts.next()?.parse::<usize>().is_ok()
                                && parts.next()?.parse::<usize>().is_ok()
                                && parts.next()?.starts_with(' '),
                        )
                    }) == Some(true);
                if well_formed { Ok(()) } else { Err(format!("malformed error: {message:?}")) }
            }
            Ok(mut scene) => {
                // 200 steps, or fewer once 20,000 integrator steps are done: a mutation that
                // makes the stable step tiny under `substeps: Auto` gets 10,000 sub-steps per
                // step, and 200 of those steps took minutes (once 6 min in one suite run).
                for _ in 0..200 {
                    if scene.world.integrator_steps() >= MAX_INTEGRATOR_STEPS {
                        break;
                    }
                    if scene.world.step().is_err() {
                        return Ok(());
                    }
                    for i in 0..scene.world.bodies().len() {
                        let s = scene.world.state(i);
                        if !s
                            .position
                            .iter()
                            .chain(s.velocity.iter())
                            .chain(s.orientation.coords.iter())
                            .all(|x| x.is_finite())
                        {
                            return Err(format!("non-finite state of body {i} after a step reported healthy"));
                        }
                    }
                }
                Ok(())
            }
        }
    }));
    outcome.unwrap_or_else(|panic| {
        Err(format!(
            "panic: {:?}",
            panic.downcast_ref::<String>().map(String::as_str).or(panic.downcast_ref::<&str>().copied())
        ))
    })
}

fn sources() -> Vec<String> {
    let mut files = common::scene_files();
    files.retain(|f| !f.ends_with("chain100_air.ron"));
    files.push(common::here!("fixtures/unstable_chain.ron"));
    files.iter().map(|f| std::fs::read_to_string(f).unwrap()).collect()
}

/// Cases per property: 3000 in CI; set `TETHER_FUZZ_CASES` for a longer campaign.
fn cases() -> u32 {
    std::env::var("TETHER_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(3000)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn mutated_scenes_never_panic(source in 0usize..64, mutations in prop::collection::vec(mutation(), 1..5)) {
        let sources = sources();
        let mut text = sources[source % sources.len()].clone();
        for m in &mutations {
            text = apply(&text, m);
        }
        if let Err(problem) = exercise(&text) {
            prop_assert!(false, "{problem}\n--- input ---\n{text}");
        }
    }

    #[test]
    fn random_text_never_panics(text in "\\PC{0,200}") {
        prop_assert!(exercise(&text).is_ok(), "{text:?}");
    }
}

/// Inputs that once broke the loader or the stepper, each still handled.
#[test]
fn regression_corpus() {
    let dir = common::here!("regressions");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        exercise(&text).unwrap_or_else(|problem| panic!("{}: {problem}", path.display()));
        count += 1;
    }
    assert!(count > 0);
}
