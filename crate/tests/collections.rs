//! The whole public collections (issue 49): every cpfg and lpfg object of vlab's course folders
//! and every L-Py model of L-Py's repository, unselected (`tests/collections/`, sources and
//! licences in its SOURCES.md). Each item is opened as a user of the CLI opens it (`meristem
//! import`, then `meristem derive --stats`), with a time limit; it "builds a plant" when both
//! succeed and the plant has at least one segment or triangle.
//!
//! The test fails if an item crashes or times out, if an item that built stops building (every
//! item not in `FAILURES.tsv` must build), or if an item listed there builds (the list must stay
//! true: take it out). An item in `PARTIAL.tsv` builds something, but not the plant its tool
//! draws (the list says what is missing): it must build, and it does not count as a plant in the
//! shares. The shares per dialect are printed and written, with every item's outcome, to
//! `$CARGO_TARGET_TMPDIR/collections.tsv`.
//! Native only: it runs the CLI binary (and, for the models that need it, the machine's python3).
#![cfg(not(target_arch = "wasm32"))]

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Longer than the CLI's own limit on a Python run (60 s), so that the CLI's message is seen.
const LIMIT: Duration = Duration::from_secs(90);

#[derive(Clone, Debug, PartialEq)]
enum Outcome {
    Plant(String),
    Nothing(String),
    Crash(String),
    Timeout,
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/collections")
}

/// Runs the CLI with a time limit: its standard output on success, the outcome otherwise.
fn cli(args: &[&Path]) -> Result<String, Outcome> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Outcome::Crash(e.to_string()))?;
    let start = Instant::now();
    loop {
        match child.try_wait() {
            Ok(Some(_)) => break,
            Ok(None) if start.elapsed() > LIMIT => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(Outcome::Timeout);
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(20)),
            Err(e) => return Err(Outcome::Crash(e.to_string())),
        }
    }
    let out = child
        .wait_with_output()
        .map_err(|e| Outcome::Crash(e.to_string()))?;
    let stderr = String::from_utf8_lossy(&out.stderr).trim().to_string();
    if stderr.contains("panicked") || out.status.code().is_none_or(|c| c == 101) {
        return Err(Outcome::Crash(stderr));
    }
    if !out.status.success() {
        let last = stderr.lines().last().unwrap_or("").to_string();
        return Err(Outcome::Nothing(last));
    }
    Ok(String::from_utf8_lossy(&out.stdout).to_string())
}

/// What the CLI said, without the machine's folders (the item's own path and the scratch file).
fn plain(outcome: Outcome, scratch: &Path) -> Outcome {
    let strip = |s: String| {
        s.replace(&format!("{}/", root().display()), "")
            .replace(&format!("{}/", scratch.display()), "")
    };
    match outcome {
        Outcome::Nothing(why) => Outcome::Nothing(strip(why)),
        Outcome::Crash(why) => Outcome::Crash(strip(why)),
        other => other,
    }
}

fn open(item: &Path, scratch: &Path) -> Outcome {
    let grammar = scratch.join("grammar.lsys");
    if let Err(outcome) = cli(&[Path::new("import"), item, Path::new("-o"), &grammar]) {
        return plain(outcome, scratch);
    }
    let stats = match cli(&[Path::new("derive"), &grammar, Path::new("--stats")]) {
        Ok(stdout) => stdout,
        Err(outcome) => return plain(outcome, scratch),
    };
    let stats: serde_json::Value =
        serde_json::from_str(stats.lines().last().unwrap_or("")).unwrap_or_default();
    let count = |key: &str| stats.get(key).and_then(|n| n.as_u64()).unwrap_or(0);
    let summary = format!(
        "{} modules, {} segments, {} triangles",
        count("modules"),
        count("segments"),
        count("triangles")
    );
    if count("segments") + count("triangles") > 0 {
        Outcome::Plant(summary)
    } else {
        Outcome::Nothing(format!("nothing drawn: {summary}"))
    }
}

/// `dialect \t item \t source` rows of ITEMS.tsv: (dialect, item).
fn items() -> Vec<(String, String)> {
    let text = std::fs::read_to_string(root().join("ITEMS.tsv")).expect("ITEMS.tsv");
    text.lines()
        .filter_map(|l| {
            let mut cells = l.split('\t');
            Some((cells.next()?.to_string(), cells.next()?.to_string()))
        })
        .collect()
}

/// The items of `file` (`FAILURES.tsv`: those that do not build a plant yet; `PARTIAL.tsv`: those
/// that build something else than their tool's plant), each with why (`item \t reason`; `#`
/// comments).
fn listed(file: &str) -> BTreeMap<String, String> {
    let text = std::fs::read_to_string(root().join(file)).expect(file);
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .filter_map(|l| {
            let (item, why) = l.split_once('\t')?;
            Some((item.to_string(), why.to_string()))
        })
        .collect()
}

/// The shares issue 49 asks for.
fn goal(dialect: &str) -> f64 {
    match dialect {
        "cpfg" => 0.95,
        "lpfg" => 0.80,
        _ => 0.85,
    }
}

#[test]
fn every_item_of_the_collections_opens_as_recorded() {
    let all = items();
    assert_eq!(all.len(), 310, "88 cpfg, 55 lpfg and 167 L-Py items");
    let queue = Arc::new(Mutex::new(all.clone()));
    let results = Arc::new(Mutex::new(BTreeMap::new()));
    let scratch = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("collections");
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get().min(4));
    let threads: Vec<_> = (0..workers)
        .map(|w| {
            let (queue, results) = (queue.clone(), results.clone());
            let scratch = scratch.join(w.to_string());
            std::thread::spawn(move || {
                std::fs::create_dir_all(&scratch).expect("scratch folder");
                loop {
                    let next = queue.lock().expect("queue").pop();
                    let Some((_, item)) = next else { break };
                    let outcome = open(&root().join(&item), &scratch);
                    results.lock().expect("results").insert(item, outcome);
                }
            })
        })
        .collect();
    for t in threads {
        t.join().expect("a worker");
    }
    let results = results.lock().expect("results").clone();
    let (failures, partial) = (listed("FAILURES.tsv"), listed("PARTIAL.tsv"));
    report(&all, &results, &partial);
    check(&all, &results, &failures, &partial);
}

fn report(
    all: &[(String, String)],
    results: &BTreeMap<String, Outcome>,
    partial: &BTreeMap<String, String>,
) {
    let mut table = String::new();
    let mut shares: BTreeMap<&str, (usize, usize)> = BTreeMap::new();
    for (dialect, item) in all {
        let outcome = &results[item];
        let share = shares.entry(dialect).or_default();
        share.1 += 1;
        if matches!(outcome, Outcome::Plant(_)) && !partial.contains_key(item) {
            share.0 += 1;
        }
        let part = if partial.contains_key(item) {
            "\tpartial"
        } else {
            ""
        };
        table.push_str(&format!("{dialect}\t{item}\t{outcome:?}{part}\n"));
    }
    let path = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("collections.tsv");
    std::fs::write(&path, table).expect("collections.tsv");
    for (dialect, (built, total)) in &shares {
        println!(
            "{dialect}: {built} of {total} build their tool's plant ({:.1} %; the issue asks {:.0} %)",
            100.0 * *built as f64 / *total as f64,
            100.0 * goal(dialect)
        );
    }
    let built: usize = shares.values().map(|s| s.0).sum();
    println!(
        "all: {built} of {} (each outcome: {})",
        all.len(),
        path.display()
    );
}

fn check(
    all: &[(String, String)],
    results: &BTreeMap<String, Outcome>,
    failures: &BTreeMap<String, String>,
    partial: &BTreeMap<String, String>,
) {
    let mut wrong = Vec::new();
    for (_, item) in all {
        if let (Outcome::Nothing(why), Some(_)) = (&results[item], partial.get(item)) {
            wrong.push(format!(
                "{item} is in PARTIAL.tsv but draws nothing now: {why}"
            ));
        }
        match (&results[item], failures.get(item)) {
            (Outcome::Crash(why), _) => wrong.push(format!("{item}: crashed: {why}")),
            (Outcome::Timeout, _) => wrong.push(format!("{item}: over {LIMIT:?}")),
            (Outcome::Plant(what), Some(_)) => wrong.push(format!(
                "{item} builds a plant now ({what}): take it out of FAILURES.tsv"
            )),
            (Outcome::Nothing(why), None) => {
                wrong.push(format!("{item} no longer builds a plant: {why}"))
            }
            _ => {}
        }
    }
    for (file, list) in [("FAILURES.tsv", failures), ("PARTIAL.tsv", partial)] {
        for item in list.keys() {
            if !results.contains_key(item) {
                wrong.push(format!("{file} names {item}, which is not an item"));
            }
        }
    }
    for item in partial.keys().filter(|i| failures.contains_key(*i)) {
        wrong.push(format!("{item} is in both FAILURES.tsv and PARTIAL.tsv"));
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
