//! The importers under a seeded fuzzer (issue 50, 4-6): the files of `tests/import/` and the
//! audit's bombs (cpp macros that double or multiply themselves, an L-Py function that doubles
//! its argument nested 28 deep, a predecessor of 5,000 letters), mutated with the syntax the
//! translators expand. Every import must end without a panic, hold at most a bounded amount of
//! memory at once, write at most [`MAX_BYTES`] of text and notes, and give text that resolves
//! (or has nothing to derive). Memory is counted by the allocator, so this file holds one test.

use meristem::import::{self, Dialect};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};

#[path = "shared/counting.rs"]
mod counting;
#[path = "shared/seeded.rs"]
mod seeded;
use seeded::Seeded;

/// The most memory one import may hold at once. The translators derive a little to read flags
/// and measure (50,000 and 1,000,000 modules at most), and check their text a few times; a
/// bomb took gigabytes before its cap.
const MAX_PEAK: usize = 256 << 20;

/// The most text and notes one import may write (the output's cap is 4 MB; notes are capped at
/// 1,000, each quoting at most 300 bytes of a line).
const MAX_BYTES: usize = 6 << 20;

/// Pieces a mutation inserts: what the translators expand or nest, and line breaks of every kind.
const PIECES: &[&str] = &[
    "#define A A A A A A A A A A A\n",
    "#define X Y Y\n#define Y X X\n",
    "#define W(a) a a a a\n",
    "W(W(W(W(W(A)))))",
    "X",
    "A",
    "\\\n",
    "#include \"self.l\"\n",
    "/*",
    "*/",
    "\r",
    "\r\n",
    "def f(x):\n    return x+x\n",
    "f(f(f(f(f(f(f(f(",
    "))))))))",
    "array a[1000000];\n",
    "a[999999]",
    "{",
    "}",
    "(",
    ")",
    "[",
    "]",
    "-->",
    "->",
    ":",
    ";",
    "produce ",
    "nproduce ",
    "Axiom: ",
    "derivation length: 100000\n",
    "recursion 1000\n",
    "1e300",
    "-1e300",
    "global g\n",
    "if ",
    "else:\n",
    "for i in range(1000000):\n",
    "    ",
    "\t",
    "\n",
    ",",
    "@",
    "#",
];

/// `text` with one to four mutations: a piece inserted, a range deleted, a range doubled, or a
/// whole line repeated up to 300 times.
fn mutate(text: &str, rng: &mut Seeded) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    for _ in 0..1 + rng.below(4) {
        let at = rng.below(chars.len() + 1);
        match rng.below(5) {
            0 | 1 => {
                let piece = PIECES[rng.below(PIECES.len())];
                chars.splice(at..at, piece.chars());
            }
            2 if at < chars.len() => {
                let end = (at + 1 + rng.below(30)).min(chars.len());
                chars.drain(at..end);
            }
            3 if at < chars.len() => {
                let end = (at + 1 + rng.below(60)).min(chars.len());
                let copy: Vec<char> = chars[at..end].to_vec();
                chars.splice(end..end, copy);
            }
            _ => {
                let start = chars[..at]
                    .iter()
                    .rposition(|&c| c == '\n')
                    .map_or(0, |i| i + 1);
                let end = chars[at..]
                    .iter()
                    .position(|&c| c == '\n')
                    .map_or(chars.len(), |i| at + i + 1);
                let line: Vec<char> = chars[start..end].to_vec();
                let times = 1 + rng.below(300);
                let copies: Vec<char> = (0..times)
                    .flat_map(|_| line.iter().copied().chain(['\n']))
                    .collect();
                chars.splice(end..end, copies);
            }
        }
    }
    chars.into_iter().collect()
}

/// Every file of `tests/import/` with its dialect.
fn files() -> Vec<(String, String, Dialect)> {
    fn walk(dir: &Path, found: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).expect("tests/import").flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, found);
            } else if path.extension().is_some_and(|e| e != "md") {
                found.push(path);
            }
        }
    }
    let mut paths = Vec::new();
    walk(
        &Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/import"),
        &mut paths,
    );
    paths.sort();
    paths
        .iter()
        .filter_map(|path| {
            let text = std::fs::read_to_string(path).ok()?;
            let name = path.file_name()?.to_string_lossy().to_string();
            let dialect = import::detect(&text, &name)?;
            Some((name, text, dialect))
        })
        .collect()
}

/// Issue 50's bombs, one that passed every cap of a line (2,000 lines each using a macro of
/// 10,000 modules: 45 KB of cpfg that was 20 MB of text and 1.2 GB of memory), and twenty L-Py
/// flags (their markers in one probe derivation).
fn bombs() -> Vec<(String, String, Dialect)> {
    let cpfg = |head: &str, body: &str| {
        format!(
            "{head}Lsystem: 1\nderivation length: 3\nAxiom: A\n{body}A --> F[+A]A\nendlsystem\n"
        )
    };
    let mut nested = "s".to_string();
    for _ in 0..28 {
        nested = format!("f({nested})");
    }
    let letters: String = (0..5000)
        .map(|k| if k % 2 == 0 { 'A' } else { 'B' })
        .collect();
    let tenfold = "#define B A A A A A A A A A A\n#define C B B B B B B B B B B\n\
                   #define D C C C C C C C C C C\n#define E D D D D D D D D D D\n";
    let uses: String = (0..2000)
        .map(|k| format!("A < A > A : {k} --> E\n"))
        .collect();
    // L-Py globals that productions set once (flags): the importer derives the model to find
    // when each is set, once per seed for all of them.
    let names: Vec<String> = (0..20).map(|k| format!("Pa{k}")).collect();
    let mut flags = format!("module {}\n", names.join(", "));
    flags += &(0..20).map(|k| format!("m{k} = 0\n")).collect::<String>();
    let axiom: String = names.iter().map(|n| format!("{n}(0)")).collect();
    flags += &format!("derivation length: 30\nAxiom: {axiom}X(0)\nproduction:\n");
    flags += "X(n) :\n    if n < 6: produce X(n+1)X(n+1)\n";
    for (k, name) in names.iter().enumerate() {
        flags += &format!("{name}(t) :\n    if t < {}: produce {name}(t+1)\n    else:\n        global m{k}\n        m{k} = 1\n        produce *\nX(n) :\n    if m{k} == 1: produce F\n", k + 2);
    }
    [
        ("macros-doubling", cpfg("#define A B B\n#define B A A\n", ""), Dialect::Cpfg),
        ("macro-tenfold", cpfg("#define A A A A A A A A A A A\n", ""), Dialect::Cpfg),
        ("macro-on-every-line", cpfg(tenfold, &uses), Dialect::Cpfg),
        (
            "inlining",
            format!("def f(x):\n    return x+x\n\nAxiom: A(1)\nderivation length: 2\nproduction:\nA(s) --> F({nested})A(s)\nendlsystem\n"),
            Dialect::Lpy,
        ),
        (
            "long-predecessor",
            format!("Lsystem: 1\nderivation length: 1\nAxiom: {}\n{letters} --> F\nendlsystem\n", "AB".repeat(500)),
            Dialect::Cpfg,
        ),
        ("many-flags", flags, Dialect::Lpy),
    ]
    .into_iter()
    .map(|(name, text, dialect)| (name.to_string(), text, dialect))
    .collect()
}

/// What is wrong with importing `text` as `dialect`, if anything.
fn check(text: &str, dialect: Dialect) -> Option<String> {
    let (result, peak) =
        counting::peak_of(|| catch_unwind(AssertUnwindSafe(|| import::import(text, dialect))));
    let Ok(imported) = result else {
        return Some("panicked".into());
    };
    if peak > MAX_PEAK {
        return Some(format!("held {peak} bytes at once"));
    }
    let notes: usize = imported.notes.iter().map(|n| n.message.len()).sum();
    if imported.text.len() + notes > MAX_BYTES {
        return Some(format!(
            "wrote {} bytes of text and {notes} of notes",
            imported.text.len()
        ));
    }
    if imported.is_empty() {
        return None;
    }
    let (file, mut diagnostics) = meristem::syntax::parse(&imported.text);
    diagnostics.extend(meristem::model::resolve(&file).1);
    let errors: Vec<String> = diagnostics
        .iter()
        .filter(|d| d.severity == meristem::diagnostics::Severity::Error)
        .map(|d| format!("{} {}", d.code, d.message))
        .collect();
    (!errors.is_empty()).then(|| format!("the translation does not resolve: {errors:?}"))
}

#[test]
fn mutated_models_and_bombs_import_within_bounds() {
    let mut failures = Vec::new();
    // The bombs as they are, then mutated files and bombs (one thread: the allocator's count is
    // the process's).
    for (name, text, dialect) in bombs() {
        if let Some(problem) = check(&text, dialect) {
            failures.push(format!("{name}: {problem}"));
        }
    }
    let mut seeds = files();
    seeds.extend(bombs());
    let mut rng = Seeded(50);
    for case in 0..300 {
        let (name, text, dialect) = &seeds[rng.below(seeds.len())];
        let mutated = mutate(text, &mut rng);
        if let Some(problem) = check(&mutated, *dialect) {
            let start: String = mutated.chars().take(2000).collect();
            failures.push(format!("case {case} from {name} ({dialect:?}): {problem}\n--- input (first 2,000 characters):\n{start}\n---"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
