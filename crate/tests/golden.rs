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
    for s in result.plant.skeleton.segments.iter().take(40) {
        writeln!(
            out,
            "#{} ({:.6}, {:.6}, {:.6}) -> ({:.6}, {:.6}, {:.6}) w{} c{}",
            s.module, s.start.x, s.start.y, s.start.z, s.end.x, s.end.y, s.end.z, s.width, s.color
        )
        .ok();
    }
    let v = |p: glam::DVec3| format!("({:.6}, {:.6}, {:.6})", p.x, p.y, p.z);
    for p in result.plant.skeleton.polygons.iter().take(10) {
        let points: Vec<String> = p.points.iter().map(|&q| v(q)).collect();
        writeln!(
            out,
            "polygon #{} c{} {}",
            p.module,
            p.color,
            points.join(" ")
        )
        .ok();
    }
    for s in result.plant.skeleton.surfaces.iter().take(10) {
        // One number when the scale is the same along L, H and U (`~l(s)`), else all three.
        let scale = if s.scale.min_element() == s.scale.max_element() {
            s.scale.x.to_string()
        } else {
            s.scale.to_string()
        };
        writeln!(
            out,
            "surface #{} {:?} at {} h {} l {} scale {} c{}",
            s.module,
            s.kind,
            v(s.origin),
            v(s.heading),
            v(s.left),
            scale,
            s.color
        )
        .ok();
    }
    for s in result.plant.skeleton.spheres.iter().take(10) {
        writeln!(
            out,
            "sphere #{} at {} r {} {:?} c{}",
            s.module,
            v(s.center),
            s.radius,
            s.radius_width,
            s.color
        )
        .ok();
    }
    for q in result.plant.skeleton.queries.iter().take(10) {
        writeln!(
            out,
            "query #{} ({:.6}, {:.6}, {:.6})",
            q.module, q.value[0], q.value[1], q.value[2]
        )
        .ok();
    }
    writeln!(
        out,
        "end ({:.6}, {:.6}, {:.6})",
        result.plant.skeleton.end.x, result.plant.skeleton.end.y, result.plant.skeleton.end.z
    )
    .ok();
    out.push_str("== stats\n");
    writeln!(out, "{}", result.plant.stats.to_json()).ok();
    // Negative zero prints as "-0.000000"; fold it so goldens do not depend on rounding direction.
    out.replace("-0.000000", "0.000000")
}

/// FNV-1a, 64 bits: a stable fingerprint of a whole derived string.
fn fnv1a(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ b as u64).wrapping_mul(0x0100_0000_01b3)
    })
}

/// A gallery example's golden: the derived string's length, fingerprint and first characters, and
/// the stats (so a change to any stage that alters a gallery plant shows up in review).
fn render_example(source: &str) -> String {
    let result = build(source, &BuildOptions::default());
    let text = result.derived_text();
    let head: String = text.chars().take(300).collect();
    format!(
        "diagnostics {}\nmodules {}\nfnv1a {:016x}\nhead {head}\nstats {}\n",
        result.diagnostics.len(),
        result.derivation.string.len(),
        fnv1a(&text),
        result.plant.stats.to_json()
    )
}

#[test]
fn golden_files_match() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    check_dir(
        &root.join("tests/golden"),
        &root.join("tests/golden"),
        render,
        4,
    );
}

#[test]
fn gallery_goldens_match() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    check_dir(
        &root.join("../public/examples"),
        &root.join("tests/golden/gallery"),
        render_example,
        1,
    );
}

/// Renders every `.lsys` in `inputs` and compares it with `NAME.golden` in `goldens`, or rewrites
/// the golden under `UPDATE_GOLDEN=1`.
fn check_dir(inputs: &Path, goldens: &Path, render: fn(&str) -> String, at_least: usize) {
    let update = std::env::var_os("UPDATE_GOLDEN").is_some();
    let mut files: Vec<_> = std::fs::read_dir(inputs)
        .expect("input folder exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "lsys"))
        .collect();
    files.sort();
    assert!(
        files.len() >= at_least,
        "expected at least {at_least} inputs in {}",
        inputs.display()
    );
    if update {
        std::fs::create_dir_all(goldens).expect("create the golden folder");
    }
    let mut failures = Vec::new();
    for input in files {
        let source = std::fs::read_to_string(&input).expect("golden input is UTF-8");
        let actual = render(&source);
        let golden = goldens
            .join(input.file_name().expect("a file name"))
            .with_extension("golden");
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
