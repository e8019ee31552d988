//! Architecture tests: they read the core's own source and fail when its structure drifts.
//!
//! - **Dependency direction**: each module of `src/` may name (`crate::…`) only modules of an
//!   earlier stage: vocabulary, diagnostics → syntax → model → derive → growth → turtle → environment, mesh →
//!   branches → export → import → pipeline → the wasm boundary. An arrow back up (say `mesh` using
//!   `crate::pipeline`) fails the test with the file and line; so does any cycle.
//! - **Short functions**: no function body is longer than [`MAX_FUNCTION_LINES`] lines unless the
//!   comment above it says why (`Long because …`).
//! - **Short files**: no file is longer than [`MAX_FILE_LINES`] lines unless its opening comment
//!   says why (`Long because …`): a longer file is a sign it holds more than one concept.
//! - **One vocabulary**: outside `src/vocabulary/`, no string literal is exactly a name of the
//!   language (a `#directive`, an `@`, `?` or `~` module, a keyword as written), unless its line
//!   says it is another dialect's word (`// dialect: …`, in the importers); and every directive or
//!   module name that a literal mentions exists in the vocabulary.
//!
//! - **No IO, no clock, no browser**: only `main.rs` (the CLI) and `wasm/` (the boundary) may
//!   touch files, the environment, clocks, OS randomness or JavaScript; one exception, `number.rs`,
//!   which under wasm32 lets JavaScript's `parseFloat` convert the digits of a number (the first
//!   plant's core then leaves Rust's decimal-to-float code out: issue 22) and uses nothing else.
//!
//! Test code (`#[cfg(test)]` items, `tests.rs` files) is not checked: tests spell names on purpose.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// The stages in dependency order: a module may use only modules of a lower rank.
const RANKS: &[(&str, u32)] = &[
    // `sort`: one small sort for every stage (src/sort.rs, for the first load's size), below them all.
    ("sort", 0),
    // `number`: reading a number's text (src/number.rs), for the syntax and the model.
    ("number", 0),
    // `maths`: sin, exp, ln, pow… from the `libm` crate on every target (src/maths.rs), so the
    // native CLI and the wasm studio grow the same plant.
    ("maths", 0),
    ("vocabulary", 1),
    ("diagnostics", 1),
    ("syntax", 2),
    ("model", 3),
    ("derive", 4),
    ("growth", 5),
    ("turtle", 6),
    // `environment` reads the turtle's parts; `mesh` and it do not use each other.
    ("environment", 7),
    ("mesh", 7),
    ("branches", 8),
    ("export", 9),
    ("import", 10),
    ("pipeline", 11),
    ("wasm", 12),
    ("main", 13),
];

/// The longest a function body may be without a written reason.
const MAX_FUNCTION_LINES: usize = 80;

/// The longest a source file may be without a written reason.
const MAX_FILE_LINES: usize = 800;

fn rank(module: &str) -> Option<u32> {
    RANKS.iter().find(|(m, _)| *m == module).map(|&(_, r)| r)
}

/// One source file of the core, its test code removed and split into code and string literals.
struct Source {
    path: PathBuf,
    /// The stage it belongs to (`syntax` for `src/syntax/parse.rs`, `pipeline` for `src/pipeline.rs`).
    module: String,
    /// Each line without comments and with string literals blanked.
    code: Vec<String>,
    /// Each line's comments (to find written reasons).
    comments: Vec<String>,
    /// String literals with their 1-based line.
    literals: Vec<(usize, String)>,
}

fn sources() -> Vec<Source> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    collect(&root, &mut files);
    files.sort();
    files
        .into_iter()
        .filter(|p| p.file_name().is_some_and(|n| n != "tests.rs"))
        .filter_map(|path| {
            let relative = path.strip_prefix(&root).ok()?;
            let first = relative.components().next()?.as_os_str().to_string_lossy();
            let module = first.trim_end_matches(".rs").to_string();
            if module == "lib" {
                return None;
            }
            let text = std::fs::read_to_string(&path).ok()?;
            Some(split(path, module, &without_tests(&text)))
        })
        .collect()
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src/ is readable").flatten() {
        let path = entry.path();
        if path.is_dir() {
            collect(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The text with every `#[cfg(test)]` item blanked (its lines kept empty, so line numbers hold).
fn without_tests(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out: Vec<String> = Vec::with_capacity(lines.len());
    let mut i = 0;
    while i < lines.len() {
        if lines[i].trim() != "#[cfg(test)]" {
            out.push(lines[i].to_string());
            i += 1;
            continue;
        }
        // Skip the attribute and the item after it, up to its closing brace or semicolon.
        let mut depth = 0i32;
        let mut opened = false;
        loop {
            out.push(String::new());
            let line = lines[i];
            depth += line.matches('{').count() as i32 - line.matches('}').count() as i32;
            opened |= line.contains('{');
            i += 1;
            let ended = (opened && depth <= 0) || (!opened && line.trim_end().ends_with(';'));
            if ended || i >= lines.len() {
                break;
            }
        }
    }
    out.join("\n")
}

/// Splits Rust source into code (comments removed, literals blanked), comments, and literals.
fn split(path: PathBuf, module: String, text: &str) -> Source {
    let chars: Vec<char> = text.chars().collect();
    let mut code = String::new();
    let mut comments = String::new();
    let mut literals = Vec::new();
    let mut line = 1;
    let mut i = 0;
    let push_newline = |c: char, code: &mut String, comments: &mut String, line: &mut usize| {
        if c == '\n' {
            code.push('\n');
            comments.push('\n');
            *line += 1;
        }
    };
    while i < chars.len() {
        let c = chars[i];
        let next = chars.get(i + 1).copied();
        if c == '/' && next == Some('/') {
            while i < chars.len() && chars[i] != '\n' {
                comments.push(chars[i]);
                i += 1;
            }
        } else if c == '/' && next == Some('*') {
            i += 2;
            while i < chars.len() && !(chars[i] == '*' && chars.get(i + 1) == Some(&'/')) {
                push_newline(chars[i], &mut code, &mut comments, &mut line);
                i += 1;
            }
            i += 2;
        } else if c == '"'
            || (c == 'r' && (next == Some('"') || next == Some('#')) && !prev_is_ident(&chars, i))
        {
            // A string literal, raw or not.
            let start_line = line;
            let mut hashes = 0;
            if c == 'r' {
                i += 1;
                while chars.get(i) == Some(&'#') {
                    hashes += 1;
                    i += 1;
                }
                if chars.get(i) != Some(&'"') {
                    code.push('r');
                    continue;
                }
            }
            i += 1;
            let mut literal = String::new();
            while i < chars.len() {
                let d = chars[i];
                if c != 'r' && d == '\\' {
                    literal.push(d);
                    if let Some(&e) = chars.get(i + 1) {
                        literal.push(e);
                        push_newline(e, &mut code, &mut comments, &mut line);
                    }
                    i += 2;
                    continue;
                }
                if d == '"' && (0..hashes).all(|k| chars.get(i + 1 + k) == Some(&'#')) {
                    i += 1 + hashes;
                    break;
                }
                literal.push(d);
                push_newline(d, &mut code, &mut comments, &mut line);
                i += 1;
            }
            code.push_str("\"\"");
            literals.push((start_line, literal));
        } else if let Some(length) = char_literal(&chars, i) {
            // A char literal ('x', '\n', '\''); lifetimes ('a) are code.
            code.push_str("' '");
            i += length;
        } else {
            code.push(c);
            if c == '\n' {
                comments.push('\n');
                line += 1;
            }
            i += 1;
        }
    }
    Source {
        path,
        module,
        code: code.lines().map(str::to_string).collect(),
        comments: comments.lines().map(str::to_string).collect(),
        literals,
    }
}

fn prev_is_ident(chars: &[char], i: usize) -> bool {
    i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_')
}

/// The length of the char literal at `i` (`'x'`, `'\n'`, `'\u{7f}'`), or `None` when the `'`
/// starts a lifetime or a label.
fn char_literal(chars: &[char], i: usize) -> Option<usize> {
    if chars.get(i) != Some(&'\'') {
        return None;
    }
    match (chars.get(i + 1), chars.get(i + 2)) {
        (Some('\\'), _) => {
            let close = chars[i + 2..].iter().position(|&d| d == '\'')?;
            Some(close + 3)
        }
        (Some(_), Some('\'')) => Some(3),
        _ => None,
    }
}

/// Every `crate::name` a line of code uses, with its 1-based line.
fn crate_uses(source: &Source) -> Vec<(usize, String)> {
    let mut uses = Vec::new();
    for (k, line) in source.code.iter().enumerate() {
        let mut rest = line.as_str();
        while let Some(at) = rest.find("crate::") {
            let after = &rest[at + "crate::".len()..];
            let name: String = after
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                uses.push((k + 1, name));
            } else if after.starts_with('{') {
                // `use crate::{a, b::c}`: each first segment.
                let inner = &after[1..after.find('}').unwrap_or(after.len())];
                for part in inner.split(',') {
                    let first: String = part
                        .trim()
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    if !first.is_empty() {
                        uses.push((k + 1, first));
                    }
                }
            }
            rest = &rest[at + "crate::".len()..];
        }
    }
    uses
}

/// The arrows of `source` that run back up (or sideways) the stages: (line, used module).
fn back_arrows(source: &Source) -> Vec<(usize, String)> {
    let Some(own) = rank(&source.module) else {
        return vec![(
            0,
            format!("{} is not a known stage: add it to RANKS", source.module),
        )];
    };
    crate_uses(source)
        .into_iter()
        .filter(|(_, used)| used != &source.module)
        .filter(|(_, used)| rank(used).is_none_or(|r| r >= own))
        .collect()
}

#[test]
fn dependencies_point_one_way() {
    let mut problems = Vec::new();
    for source in sources() {
        for (line, used) in back_arrows(&source) {
            problems.push(format!(
                "{}:{line}: {} uses crate::{used}, a stage at or after its own",
                source.path.display(),
                source.module
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "arrows back up the pipeline:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_dependency_check_finds_an_arrow_back_up() {
    let source = split(
        PathBuf::from("src/mesh/example.rs"),
        "mesh".into(),
        "use crate::turtle::Skeleton;\n// crate::pipeline in a comment\nfn f() { crate::pipeline::build(\"\", &Default::default()); }\n",
    );
    assert_eq!(back_arrows(&source), [(3, "pipeline".to_string())]);
}

/// Functions longer than the limit: (line, name, lines).
/// What stands before `fn` without its visibility: `pub`, `pub(crate)`, `pub(in crate::a::b)`.
fn without_visibility(head: &str) -> &str {
    let Some(rest) = head.strip_prefix("pub") else {
        return head;
    };
    match rest.strip_prefix('(') {
        Some(inner) => inner.find(')').map_or(head, |close| &inner[close + 1..]),
        None => rest,
    }
}

fn long_functions(source: &Source) -> Vec<(usize, String, usize)> {
    let mut found = Vec::new();
    let lines = &source.code;
    for (k, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let Some(at) = trimmed.find("fn ") else {
            continue;
        };
        let head = without_visibility(&trimmed[..at]);
        let is_item = head
            .split_whitespace()
            .all(|w| matches!(w, "const" | "unsafe" | "async" | "extern"));
        if !is_item {
            continue;
        }
        let name: String = trimmed[at + 3..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let Some((start, end)) = body_lines(lines, k) else {
            continue;
        };
        let length = end - start + 1;
        let reason = (0..k)
            .rev()
            .take_while(|&j| {
                source.comments[j].trim_start().starts_with("//")
                    || lines[j].trim().starts_with("#[")
            })
            .any(|j| source.comments[j].contains("Long because"));
        if length > MAX_FUNCTION_LINES && !reason {
            found.push((k + 1, name, length));
        }
    }
    found
}

/// The first and last line (0-based) of the body of the function whose `fn` is on line `k`, or
/// `None` when it has none (a trait method's `fn f(&self);`). The signature ends at the first `{`
/// or `;` outside brackets: the `;` of `[f32; 3]` and the `>` of `->` do not end it. The lines are
/// code as [`split`] leaves it: comments removed, string and char literals blanked.
fn body_lines(lines: &[String], k: usize) -> Option<(usize, usize)> {
    let mut brackets = 0i32; // depth in (), [] and <> while in the signature
    let mut braces = 0i32;
    let mut opened = None;
    for (j, l) in lines.iter().enumerate().skip(k) {
        let mut previous = ' ';
        for c in l.chars() {
            match c {
                '(' | '[' | '<' if opened.is_none() => brackets += 1,
                '>' if opened.is_none() && previous == '-' => {}
                ')' | ']' | '>' if opened.is_none() => brackets -= 1,
                ';' if opened.is_none() && brackets == 0 => return None,
                '{' if opened.is_some() || brackets == 0 => {
                    braces += 1;
                    opened.get_or_insert(j);
                }
                '}' if opened.is_some() => {
                    braces -= 1;
                    if braces == 0 {
                        return opened.map(|start| (start, j));
                    }
                }
                _ => {}
            }
            previous = c;
        }
    }
    None
}

#[test]
fn functions_are_short_or_say_why_not() {
    let mut problems = Vec::new();
    for source in sources() {
        for (line, name, length) in long_functions(&source) {
            problems.push(format!(
                "{}:{line}: fn {name} is {length} lines",
                source.path.display()
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "functions over {MAX_FUNCTION_LINES} lines without a 'Long because' comment:\n{}",
        problems.join("\n")
    );
}

/// The file's length in lines when it is over [`MAX_FILE_LINES`] and its opening comment (the
/// comment lines before its first line of code) does not say `Long because`.
fn too_long(source: &Source) -> Option<usize> {
    let reason = source
        .code
        .iter()
        .zip(&source.comments)
        .take_while(|(code, _)| code.trim().is_empty())
        .any(|(_, comment)| comment.contains("Long because"));
    let length = source.code.len();
    (length > MAX_FILE_LINES && !reason).then_some(length)
}

#[test]
fn files_are_short_or_say_why_not() {
    let problems: Vec<String> = sources()
        .iter()
        .filter_map(|source| {
            let length = too_long(source)?;
            Some(format!("{} is {length} lines", source.path.display()))
        })
        .collect();
    assert!(
        problems.is_empty(),
        "files over {MAX_FILE_LINES} lines without a 'Long because' in their opening comment:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_file_length_check_reads_the_opening_comment() {
    let body = "fn f() {}\n".repeat(MAX_FILE_LINES);
    let read = |text: &str| split(PathBuf::from("src/mesh/example.rs"), "mesh".into(), text);
    assert_eq!(too_long(&read(&body)), None);
    let long = format!("//! A module.\n{body}");
    assert_eq!(too_long(&read(&long)), Some(MAX_FILE_LINES + 1));
    let excused = format!("//! A module.\n//! Long because it is one table.\n\n{body}");
    assert_eq!(too_long(&read(&excused)), None);
    let late = format!("{body}// Long because it is too late to say so.\n");
    assert_eq!(too_long(&read(&late)), Some(MAX_FILE_LINES + 1));
}

#[test]
fn the_length_check_reads_signatures_with_arrays_and_arrows() {
    let body = "    let _ = 1;\n".repeat(MAX_FUNCTION_LINES);
    let text = format!(
        "trait T {{\n    fn declared(&self, p: [f32; 3]) -> [f32; 3];\n}}\n\
         pub fn long(p: [f32; 3], f: impl Fn(u8) -> Vec<u8>) -> [f32; 3] {{\n{body}    p\n}}\n\
         // Long because the test says so.\nfn excused(p: [f32; 3]) {{\n{body}}}\n\
         fn short(p: [f32; 3]) -> f32 {{\n    p[0]\n}}\n\
         pub(in crate::mesh) fn scoped() {{\n{body}}}\n"
    );
    let source = split(PathBuf::from("src/mesh/example.rs"), "mesh".into(), &text);
    let scoped_at = 1 + text.lines().position(|l| l.contains("fn scoped")).unwrap();
    assert_eq!(
        long_functions(&source),
        [
            (4, "long".to_string(), MAX_FUNCTION_LINES + 3),
            (scoped_at, "scoped".to_string(), MAX_FUNCTION_LINES + 2)
        ]
    );
}

/// The language's names as written, and which of them a literal may not spell exactly: the
/// directives, the modules of two or more characters and the keywords as a line writes them
/// (`axiom:`). One-character modules are also punctuation, and function names and bare keywords
/// are also words of JSON, POV-Ray and other dialects, so those do not count as spelled.
fn vocabulary() -> (BTreeSet<String>, BTreeSet<String>) {
    let all: BTreeSet<String> = meristem::vocabulary::written_names().into_iter().collect();
    let mut spelled: BTreeSet<String> = all
        .iter()
        .filter(|n| n.starts_with(['#', '@', '?', '~']) && n.chars().count() > 1)
        .cloned()
        .collect();
    for keyword in meristem::vocabulary::KEYWORDS {
        for spelling in keyword.spellings() {
            spelled.insert(format!(
                "{spelling}{}",
                if keyword.colon { ":" } else { "" }
            ));
        }
    }
    (all, spelled)
}

/// True when a comment on the line or the line above says that the literal is another dialect's
/// word (`// dialect: …`).
fn marked_as_dialect(source: &Source, line: usize) -> bool {
    [line.saturating_sub(2), line - 1].iter().any(|&k| {
        source
            .comments
            .get(k)
            .is_some_and(|c| c.contains("dialect:"))
    })
}

/// The names a literal mentions: `#word` directives and `@Word`, `?X`, `~x` modules.
fn mentioned_names(literal: &str) -> Vec<String> {
    let chars: Vec<char> = literal.chars().collect();
    let mut names = Vec::new();
    for (i, &c) in chars.iter().enumerate() {
        if i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_') {
            continue;
        }
        let word: String = chars[i + 1..]
            .iter()
            .take_while(|c| c.is_ascii_alphanumeric() || **c == '_')
            .collect();
        let name = match c {
            '#' if word.starts_with(|c: char| c.is_ascii_lowercase()) => format!("#{word}"),
            '@' if word.starts_with(|c: char| c.is_ascii_uppercase()) => format!("@{word}"),
            '?' if word.len() == 1 && word.starts_with(|c: char| c.is_ascii_uppercase()) => {
                format!("?{word}")
            }
            '~' if word.len() == 1 && word.starts_with(|c: char| c.is_ascii_lowercase()) => {
                format!("~{word}")
            }
            _ => continue,
        };
        names.push(name);
    }
    names
}

#[test]
fn names_of_the_language_are_spelled_only_in_the_vocabulary() {
    let (all, spelled) = vocabulary();
    let mut problems = Vec::new();
    for source in sources().iter().filter(|s| s.module != "vocabulary") {
        for (line, literal) in &source.literals {
            if spelled.contains(literal) && !marked_as_dialect(source, *line) {
                problems.push(format!(
                    "{}:{line}: \"{literal}\" spells a name of the language: read it from crate::vocabulary",
                    source.path.display()
                ));
            }
            // The importers read other dialects and the exporters write other formats, whose
            // words (`#declare`, `#include`) are not Meristem's.
            if source.module == "import" || source.module == "export" {
                continue;
            }
            for name in mentioned_names(literal) {
                if !all.contains(&name) {
                    problems.push(format!(
                        "{}:{line}: \"{literal}\" names {name}, which the vocabulary does not have",
                        source.path.display()
                    ));
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_name_checks_can_fail() {
    let (all, spelled) = vocabulary();
    assert!(spelled.contains("@Gc") && spelled.contains("#angle") && spelled.contains("axiom:"));
    assert!(!spelled.contains("F") && !spelled.contains("min"));
    assert_eq!(
        mentioned_names("raise it with '#max_modules N' or @Foo"),
        ["#max_modules", "@Foo"]
    );
    assert!(!all.contains("@Foo"));
}

/// What only the command line and the wasm boundary may use.
const OUTSIDE_WORLD: &[&str] = &[
    "std::fs",
    "std::io",
    "std::env",
    "std::time",
    "std::process",
    "std::net",
    "Instant",
    "SystemTime",
    "thread_rng",
    "rand::rng",
    "getrandom",
    "wasm_bindgen",
    "js_sys",
];

#[test]
fn the_core_does_no_io_and_knows_nothing_of_the_browser() {
    let mut problems = Vec::new();
    for source in sources() {
        if source.module == "main" || source.module == "wasm" {
            continue;
        }
        // number.rs: js_sys::parse_float under wasm32 (see the module's doc), nothing else.
        let allowed: &[&str] = if source.module == "number" {
            &["js_sys"]
        } else {
            &[]
        };
        for (k, line) in source.code.iter().enumerate() {
            for word in OUTSIDE_WORLD
                .iter()
                .filter(|w| line.contains(*w) && !allowed.contains(w))
            {
                problems.push(format!("{}:{}: uses {word}", source.path.display(), k + 1));
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_language_reference_lists_every_name() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/LANGUAGE.md");
    let reference = std::fs::read_to_string(path).expect("docs/LANGUAGE.md");
    let missing: Vec<String> = meristem::vocabulary::MODULES
        .iter()
        .map(|m| m.name.replace('|', "\\|"))
        .chain(
            meristem::vocabulary::DIRECTIVES
                .iter()
                .map(|d| format!("#{}", d.name)),
        )
        .filter(|name| {
            !reference.contains(&format!("`{name}")) && !reference.contains(&format!(" {name} "))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "docs/LANGUAGE.md does not mention {missing:?}"
    );
}
