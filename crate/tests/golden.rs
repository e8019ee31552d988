//! Golden files: each `tests/golden/NAME.lsys` has a `NAME.golden` holding what every stage made
//! of it (syntax tree, diagnostics, derived string, turtle segments, stats). Run with
//! `UPDATE_GOLDEN=1 cargo test --test golden` to rewrite them after an intended change, then read
//! the diff before committing.

use meristem::pipeline::{build, BuildOptions};
use meristem::syntax;
use std::fmt::Write;
use std::path::Path;

fn render(source: &str) -> String {
    let mut out = String::new();
    let (file, _) = syntax::parse(source);
    out.push_str("== parse\n");
    for d in &file.directives {
        writeln!(out, "directive #{} {:?} @{:?}", d.name, d.args, d.name_span).ok();
    }
    if let Some((axiom, span)) = &file.axiom {
        let names: Vec<_> = axiom.iter().map(|m| m.name.as_str()).collect();
        writeln!(out, "axiom {names:?} @{span:?}").ok();
    }
    for p in &file.productions {
        let successor: Vec<_> = p.successor.iter().map(|m| m.name.as_str()).collect();
        writeln!(
            out,
            "production {:?} {} -> {successor:?} @{:?}",
            p.label, p.predecessor.name, p.span
        )
        .ok();
    }

    let result = build(source, &BuildOptions::default());
    out.push_str("== diagnostics\n");
    for d in result.located_diagnostics(source) {
        writeln!(
            out,
            "{}:{}: {:?} {}: {}",
            d.line, d.column, d.severity, d.code, d.message
        )
        .ok();
    }
    out.push_str("== derive\n");
    let text = result.derived_text();
    let shown: String = text.chars().take(2000).collect();
    writeln!(
        out,
        "{shown}{}",
        if shown.len() < text.len() { "…" } else { "" }
    )
    .ok();
    out.push_str("== turtle\n");
    for s in result.skeleton.segments.iter().take(40) {
        writeln!(
            out,
            "#{} ({:.6}, {:.6}, {:.6}) -> ({:.6}, {:.6}, {:.6}) w{} c{}",
            s.module, s.start.x, s.start.y, s.start.z, s.end.x, s.end.y, s.end.z, s.width, s.color
        )
        .ok();
    }
    writeln!(
        out,
        "end ({:.6}, {:.6}, {:.6})",
        result.skeleton.end.x, result.skeleton.end.y, result.skeleton.end.z
    )
    .ok();
    out.push_str("== stats\n");
    writeln!(out, "{}", result.stats.to_json()).ok();
    // Negative zero prints as "-0.000000"; fold it so goldens do not depend on rounding direction.
    out.replace("-0.000000", "0.000000")
}

#[test]
fn golden_files_match() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let update = std::env::var_os("UPDATE_GOLDEN").is_some();
    let mut inputs: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/golden exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "lsys"))
        .collect();
    inputs.sort();
    assert!(
        inputs.len() >= 4,
        "expected golden inputs in {}",
        dir.display()
    );
    let mut failures = Vec::new();
    for input in inputs {
        let source = std::fs::read_to_string(&input).expect("golden input is UTF-8");
        let actual = render(&source);
        let golden = input.with_extension("golden");
        if update {
            std::fs::write(&golden, &actual).expect("write golden");
            continue;
        }
        let expected = std::fs::read_to_string(&golden).unwrap_or_default();
        if expected != actual {
            let line = expected
                .lines()
                .zip(actual.lines())
                .position(|(a, b)| a != b)
                .unwrap_or(0);
            failures.push(format!(
                "{}: differs from its golden at line {} (UPDATE_GOLDEN=1 to rewrite)\n  expected: {:?}\n  actual:   {:?}",
                input.display(),
                line + 1,
                expected.lines().nth(line).unwrap_or("<end>"),
                actual.lines().nth(line).unwrap_or("<end>"),
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
