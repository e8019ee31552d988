//! Hostile input (issue 19): every grammar of `tests/hostile/` (and the large ones its recipes
//! generate) builds without a panic, a stack overflow or an abort, and gives what its first line
//! says (`// expect: ok` or `// expect: E0xxx`); every plant built is written in every format
//! with finite numbers only. Then a seeded fuzzer mutates the gallery and the corpus and asserts
//! the same: no panic, finite output, and a derivation kept small by the limits the grammar text
//! itself sets (the time bound comes from the limits, not from a clock).
//!
//! The wasm build runs the same corpus in Node (`tests/core/hostile.test.ts`).

use meristem::diagnostics::Severity;
use meristem::export::{export, Format};
use meristem::pipeline::{build, Build, BuildOptions};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

#[path = "shared/seeded.rs"]
mod seeded;
use seeded::Seeded;

fn corpus_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/hostile")
}

/// A recipe's text: `head`, `unit` repeated `count` times, `tail`.
fn from_recipe(json: &str) -> String {
    let v: serde_json::Value = serde_json::from_str(json).expect("recipe JSON");
    let text = |k: &str| v[k].as_str().unwrap_or_default().to_string();
    let count = v["count"].as_u64().unwrap_or(0) as usize;
    format!(
        "{}{}{}",
        text("head"),
        text("unit").repeat(count),
        text("tail")
    )
}

/// Every corpus case: (name, grammar text).
fn corpus() -> Vec<(String, String)> {
    let mut cases = Vec::new();
    for entry in std::fs::read_dir(corpus_dir()).expect("tests/hostile") {
        let path = entry.expect("entry").path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let text = std::fs::read_to_string(&path).expect("read");
        if name.ends_with(".recipe.json") {
            cases.push((name, from_recipe(&text)));
        } else if name.ends_with(".lsys") {
            cases.push((name, text));
        }
    }
    cases.sort();
    assert!(cases.len() >= 30, "only {} hostile cases", cases.len());
    cases
}

/// `ok`, or the code the first line expects.
fn expectation(text: &str) -> &str {
    // The corpus holds a file with a byte order mark and one with lone `\r` line ends.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.split(['\n', '\r'])
        .next()
        .and_then(|l| l.strip_prefix("// expect: "))
        .map(str::trim)
        .expect("the first line says '// expect: ok' or '// expect: E0xxx'")
}

/// What is wrong with the files the plant of `built` is written as, if anything.
fn invalid_output(built: &Build) -> Option<String> {
    let mesh = &built.plant.mesh;
    let finite = |v: &[f32]| v.iter().all(|x| x.is_finite());
    if !(finite(&mesh.positions)
        && finite(&mesh.normals)
        && finite(&mesh.uvs)
        && finite(&mesh.lines))
    {
        return Some("the mesh holds a number that is not finite".into());
    }
    if let Err(e) = mesh.check() {
        return Some(format!("invalid mesh: {e}"));
    }
    // Writing and reading back every format of a large plant takes minutes in a debug build;
    // the writers see the same finite mesh either way.
    if mesh.vertex_count() > 20_000 {
        return None;
    }
    let stats = built.plant.stats.to_json();
    if stats.contains("null") {
        return Some(format!("stats with null: {stats}"));
    }
    for format in Format::ALL {
        for file in export(format, mesh, &built.plant.skeleton, "plant") {
            if format == Format::Glb {
                let json_length = u32::from_le_bytes(file.bytes[12..16].try_into().unwrap());
                let json = String::from_utf8_lossy(&file.bytes[20..20 + json_length as usize]);
                if json.contains("null") || json.contains("inf") || json.contains("NaN") {
                    return Some(format!("{}: {json}", file.name));
                }
            } else if let Ok(text) = std::str::from_utf8(&file.bytes) {
                let bad = text
                    .split(|c: char| !(c.is_ascii_alphanumeric() || c == '.' || c == '-'))
                    .find(|w| {
                        matches!(
                            w.to_ascii_lowercase().trim_start_matches('-'),
                            "nan" | "inf" | "infinity"
                        )
                    });
                if let Some(word) = bad {
                    return Some(format!("{} contains {word}", file.name));
                }
            }
        }
    }
    None
}

/// Builds `text`; a description of what went wrong, if anything, against `expected` (`None`:
/// anything but a panic or invalid output).
fn check(name: &str, text: &str, expected: Option<&str>) -> Option<String> {
    let outcome = catch_unwind(AssertUnwindSafe(|| {
        let built = build(text, &BuildOptions::default());
        let invalid = if built.ok() {
            invalid_output(&built)
        } else {
            None
        };
        (built, invalid)
    }));
    let Ok((built, invalid)) = outcome else {
        return Some(format!("{name}: building panicked"));
    };
    if let Some(problem) = invalid {
        return Some(format!("{name}: {problem}"));
    }
    let codes: Vec<(&str, Severity)> = built
        .diagnostics
        .iter()
        .map(|d| (d.code, d.severity))
        .collect();
    match expected {
        None => None,
        Some("ok") if built.ok() => None,
        Some("ok") => Some(format!("{name}: expected a plant, got {codes:?}")),
        Some(code) => {
            let found = built.diagnostics.iter().find(|d| d.code == code);
            match found {
                Some(d) if d.severity == Severity::Error && built.ok() => {
                    Some(format!("{name}: {code} but built"))
                }
                Some(_) => None,
                None => Some(format!("{name}: expected {code}, got {codes:?}")),
            }
        }
    }
}

/// `work(k)` for k in 0..4, each on its own thread (with the test harness's stack size), and every
/// failure they found.
fn on_four_threads(work: impl Fn(usize) -> Vec<String> + Sync) -> Vec<String> {
    std::thread::scope(|scope| {
        let workers: Vec<_> = (0..4)
            .map(|k| {
                scope.spawn({
                    let work = &work;
                    move || work(k)
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().expect("a worker panicked"))
            .collect()
    })
}

#[test]
fn every_hostile_grammar_gives_its_result_or_its_diagnostic() {
    let cases = corpus();
    // Each thread takes every fourth case.
    let failures = on_four_threads(|k| {
        cases
            .iter()
            .skip(k)
            .step_by(4)
            .filter_map(|(name, text)| check(name, text, Some(expectation(text))))
            .collect()
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Pieces a mutation inserts: the syntax the audit found fragile, and extreme numbers.
const PIECES: &[&str] = &[
    "@Repeat(3, ",
    "@Switch(",
    "@Pendulum(",
    ")",
    "(",
    "[",
    "]",
    "{",
    "}",
    ".",
    "1e300",
    "-1e300",
    "1e-300",
    "0",
    "/0",
    "NaN",
    "inf",
    "#random r = uniform(0, r)\n",
    "#define D D+1\n",
    "#define E 1e200*1e200\n",
    "@O(1e300)",
    "F(1e300)",
    "!(1e200)",
    "+(1e300)",
    "x",
    "p",
    "?",
    ":",
    "->",
    "\n",
    "%",
    "@Prune",
    "~l",
    "~p",
    "&",
    "^",
    "\\",
    "/",
    "|",
    "$",
    "F",
    "A",
    ",",
    "#iterations 12\n",
    "#max_steps 3\n",
    "uniform(0, 1e308)",
    "sqrt(-1)",
    "1+1+1+1+1+1+1+1",
];

/// `text` with one to four random mutations: a piece inserted, a range deleted, a range
/// doubled, or a number replaced by an extreme one.
fn mutate(text: &str, rng: &mut Seeded) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(chars.len() + 1);
        match rng.below(4) {
            0 | 1 => {
                let piece = PIECES[rng.below(PIECES.len())];
                chars.splice(at..at, piece.chars());
            }
            2 if at < chars.len() => {
                let end = (at + 1 + rng.below(20)).min(chars.len());
                chars.drain(at..end);
            }
            _ if at < chars.len() => {
                let end = (at + 1 + rng.below(40)).min(chars.len());
                let copy: Vec<char> = chars[at..end].to_vec();
                chars.splice(end..end, copy);
            }
            _ => {}
        }
    }
    // The grammar's own last word on the limits keeps every case small (the later one wins).
    let mut out: String = chars.into_iter().collect();
    out.push_str("\n#max_modules 5000\n");
    out
}

/// The seed grammars: the gallery and the small corpus files.
fn seeds() -> Vec<(String, String)> {
    let gallery = Path::new(env!("CARGO_MANIFEST_DIR")).join("../public/examples");
    let mut seeds: Vec<(String, String)> = std::fs::read_dir(gallery)
        .expect("public/examples")
        .filter_map(|e| {
            let path = e.ok()?.path();
            let text = std::fs::read_to_string(&path).ok()?;
            Some((path.file_name()?.to_string_lossy().to_string(), text))
        })
        .filter(|(name, _)| name.ends_with(".lsys"))
        .collect();
    seeds.extend(corpus().into_iter().filter(|(_, text)| text.len() < 4000));
    seeds.sort();
    seeds
}

#[test]
fn mutated_grammars_never_panic_and_write_finite_files() {
    let seeds = seeds();
    // Four threads, each with its own seed, so a failing case is found again from its thread's
    // seed and its number.
    let failures = on_four_threads(|k| fuzz(&seeds, 19 + k as u64, 100));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// `cases` mutated grammars from `seeds`, drawn with `seed`; what went wrong with each.
fn fuzz(seeds: &[(String, String)], seed: u64, cases: usize) -> Vec<String> {
    let mut rng = Seeded(seed);
    let mut failures = Vec::new();
    for case in 0..cases {
        let (name, text) = &seeds[rng.below(seeds.len())];
        let mutated = mutate(text, &mut rng);
        let label = format!("seed {seed} case {case} from {name}");
        if let Some(problem) = check(&label, &mutated, None) {
            failures.push(format!("{problem}\n--- grammar:\n{mutated}\n---"));
        }
    }
    failures
}
