//! The command-line tool, run as a user runs it.

use std::path::PathBuf;
use std::process::Command;

fn meristem(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(args)
        .output()
        .expect("run meristem");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn example(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../public/examples")
        .join(name)
        .display()
        .to_string()
}

fn temp_file(name: &str, bytes: &[u8]) -> String {
    let path = std::env::temp_dir().join(format!("meristem-cli-{}-{name}", std::process::id()));
    std::fs::write(&path, bytes).expect("write temp file");
    path.display().to_string()
}

#[test]
fn derive_prints_the_string_on_one_line() {
    let (code, out, err) = meristem(&["derive", &example("abop-1.24d.lsys"), "--iterations", "1"]);
    assert_eq!((code, err.as_str()), (0, ""));
    assert_eq!(out, "F[+X]F[-X]+X\n");
}

#[test]
fn derive_stats_is_one_json_object_with_the_counts_and_bounds() {
    let (code, out, _) = meristem(&["derive", &example("abop-1.24d.lsys"), "--stats"]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), 1);
    for key in [
        "\"modules\":13956",
        "\"segments\":",
        "\"vertices\":",
        "\"triangles\":",
        "\"bounds\":[[",
    ] {
        assert!(out.contains(key), "{key} missing from {out}");
    }
}

#[test]
fn check_reports_file_line_column_and_fails_on_errors() {
    let file = temp_file("broken.lsys", b"axiom: X\nX -> F[\n#nope\n");
    let (code, out, err) = meristem(&["check", &file]);
    assert_eq!(code, 1);
    assert_eq!(out, "");
    assert!(
        err.contains(&format!("{file}:2:7: error: '[' is never closed")),
        "{err}"
    );
    assert!(
        err.contains(&format!("{file}:3:1: error: unknown directive '#nope'")),
        "{err}"
    );
    let good = temp_file("good.lsys", b"axiom: F\n");
    assert_eq!(meristem(&["check", &good]).0, 0);
}

#[test]
fn bad_arguments_and_non_utf8_files_fail_politely() {
    assert_eq!(meristem(&["derive"]).0, 2);
    assert_eq!(meristem(&["frobnicate", &example("abop-1.24d.lsys")]).0, 2);
    assert_eq!(meristem(&["derive", "/nonexistent/x.lsys"]).0, 2);
    let latin1 = temp_file("latin1.lsys", b"axiom: F\xe9\n");
    let (code, _, err) = meristem(&["check", &latin1]);
    assert_eq!(code, 1);
    assert!(err.contains("not UTF-8"), "{err}");
}

#[test]
fn seed_overrides_the_grammar_seed_and_fixes_the_result() {
    let file = temp_file(
        "stochastic.lsys",
        b"#seed 5\naxiom: F\nF -> (0.33) F[+F]F[-F]F\nF -> (0.33) F[+F]F\nF -> (0.34) F[-F]F\n",
    );
    let run = |seed: &str| meristem(&["derive", &file, "--iterations", "4", "--seed", seed]).1;
    assert_eq!(run("1"), run("1"));
    assert_ne!(run("1"), run("2"));
    let (_, grammar_seed, _) = meristem(&["derive", &file, "--iterations", "4"]);
    assert_eq!(grammar_seed, run("5"));
}

#[test]
fn derive_time_prints_each_stage_on_stderr() {
    let (code, out, err) = meristem(&["derive", &example("abop-1.24d.lsys"), "--stats", "--time"]);
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), 1, "stdout keeps only the stats");
    let pattern = [
        "parse+resolve ",
        " ms, derive ",
        " ms, interpret ",
        " ms, mesh ",
        " ms\n",
    ];
    let mut rest = err.as_str();
    for (i, part) in pattern.iter().enumerate() {
        let at = rest
            .find(part)
            .unwrap_or_else(|| panic!("{part:?} missing in {err:?}"));
        if i > 0 {
            let number = &rest[..at];
            assert!(
                number.parse::<f64>().is_ok_and(|t| t >= 0.0),
                "{number:?} in {err:?}"
            );
        }
        rest = &rest[at + part.len()..];
    }
}

fn import_input(relative: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/import")
        .join(relative)
        .display()
        .to_string()
}

#[test]
fn import_prints_the_translation_and_notes_as_file_line_note() {
    let file = import_input("lparser/abop-monopodial-tree.ls");
    let (code, out, err) = meristem(&["import", &file]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("// Imported from Lparser (positional format)"),
        "{out}"
    );
    assert!(
        out.contains("\naxiom: ;(12)F(1,0.15)F(1,0.15)A(1,0.15)L\n"),
        "{out}"
    );
    assert!(
        err.contains(&format!("{file}:23: note: '~' without a value")),
        "{err}"
    );
    assert_eq!(err.lines().count(), 3, "{err}");
    // The translation builds.
    let out_file = temp_file("monopodial.lsys", out.as_bytes());
    assert_eq!(
        meristem(&["check", &out_file]),
        (0, String::new(), String::new())
    );
}

#[test]
fn import_writes_the_output_file_and_takes_the_dialect_from_the_command_line() {
    let green = temp_file(
        "green.txt",
        b"SYSTEM\nAXIOM\n  A(1)\nRULES\n  A(x) --> A(x+1)B\nEND.\n",
    );
    let target = std::env::temp_dir().join(format!("meristem-cli-{}-out.lsys", std::process::id()));
    let target = target.display().to_string();
    let (code, out, err) = meristem(&["import", &green, "--from", "green", "-o", &target]);
    assert_eq!((code, out.as_str()), (0, ""), "{err}");
    assert!(err.contains(&format!(
        "{green}: note: Green's syntax does not say how many steps"
    )));
    let written = std::fs::read_to_string(&target).expect("written");
    assert!(written.contains("A(x) -> A(x+1)B"), "{written}");
    let (code, out, _) = meristem(&["derive", &target]);
    assert_eq!((code, out.as_str()), (0, "A(2)B\n"));
    // Detected from the content when no dialect is given.
    assert_eq!(meristem(&["import", &green]).0, 0);
}

#[test]
fn import_fails_politely() {
    let plain = temp_file("plain.txt", b"axiom: F\n");
    let (code, _, err) = meristem(&["import", &plain]);
    assert_eq!(code, 2);
    assert!(err.contains("--from green|lparser|cpfg|lpy"), "{err}");
    assert_eq!(meristem(&["import", &plain, "--from", "basic"]).0, 2);
    // Nothing to import: exit 1, with the reason.
    let empty = temp_file("empty.l", b"Lsystem: 1\nF --> FF\nendlsystem\n");
    let (code, out, err) = meristem(&["import", &empty]);
    assert_eq!(code, 1);
    assert!(out.contains("F -> FF"));
    assert!(err.contains("no Axiom: line"), "{err}");
    // Lparser files predate UTF-8: a Latin-1 comment is read, and said so.
    let latin1 = temp_file("latin1.ls", b"# Lapr\xe9\n2\n30\n10\nF\nF=FF\n@\n");
    let (code, out, err) = meristem(&["import", &latin1]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("not UTF-8"), "{err}");
    assert!(out.contains("F_r -> F_r"), "{out}");
}

#[test]
fn derive_growth_prints_what_each_step_did_as_json() {
    let (code, out, err) = meristem(&["derive", &example("jou-fig2-lifetime.lsys"), "--growth"]);
    assert_eq!((code, err.as_str()), (0, ""));
    let steps: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let steps = steps.as_array().expect("one report per step");
    assert_eq!(steps.len(), 3);
    let third = &steps[2];
    assert_eq!(third["step"], 3);
    let sum = |key: &str| -> u64 {
        third[key]
            .as_array()
            .expect("per third")
            .iter()
            .map(|v| v.as_u64().expect("count"))
            .sum()
    };
    assert_eq!(sum("apices"), 64);
    let nb = third["survivors"].as_u64().expect("NB");
    assert!((34..=66).contains(&nb));
    assert_eq!(sum("growing") + sum("stopped"), 64);
    // Without growth directives there is nothing to report.
    let (code, out, _) = meristem(&["derive", &example("abop-1.24d.lsys"), "--growth"]);
    assert_eq!((code, out.as_str()), (0, "[]\n"));
}

/// A fresh folder for one test's output files.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("meristem-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create temp dir");
    dir
}

#[test]
fn export_writes_the_format_of_the_extension() {
    let dir = temp_dir("export");
    let source = example("abop-1.24a.lsys");
    for (extension, start) in [
        ("wrl", &b"#VRML V2.0 utf8\n"[..]),
        ("glb", b"glTF"),
        ("pov", b"#version 3.7;\n"),
        ("obj", b"# Made with Meristem"),
        ("iv", b"#Inventor V2.1 ascii\n"),
        ("svg", b"<?xml version=\"1.0\""),
    ] {
        let out = dir.join(format!("plant.{extension}"));
        let out = out.to_str().expect("UTF-8 path");
        let (code, stdout, err) = meristem(&["export", &source, "-o", out, "--iterations", "2"]);
        assert_eq!((code, err.as_str()), (0, ""), "{extension}");
        assert!(stdout.starts_with(&format!("wrote {out} (")), "{stdout}");
        let bytes = std::fs::read(out).expect("written");
        assert!(bytes.starts_with(start), "{extension}");
    }
    // OBJ names its material library, written beside it.
    let obj = std::fs::read_to_string(dir.join("plant.obj")).expect("obj");
    assert!(obj.contains("\nmtllib plant.mtl\n"));
    let mtl = std::fs::read_to_string(dir.join("plant.mtl")).expect("mtl");
    assert!(mtl.contains("newmtl color_0\n"));
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn export_takes_the_format_option_and_is_deterministic() {
    let dir = temp_dir("export-format");
    let source = example("abop-1.27-stochastic.lsys");
    let run = |name: &str, seed: &str| {
        let out = dir.join(name);
        let out = out.to_str().expect("UTF-8 path").to_string();
        let (code, _, err) = meristem(&[
            "export", &source, "-o", &out, "--format", "glb", "--seed", seed,
        ]);
        assert_eq!((code, err.as_str()), (0, ""));
        std::fs::read(&out).expect("written")
    };
    let first = run("a.bin", "3");
    assert!(first.starts_with(b"glTF"));
    assert_eq!(
        first,
        run("b.bin", "3"),
        "same grammar and seed, same bytes"
    );
    assert_ne!(first, run("c.bin", "4"), "another seed, another plant");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn export_takes_the_studio_view_options() {
    let dir = temp_dir("export-view");
    let source = example("abop-1.24a.lsys");
    let vertices = |extra: &[&str]| {
        let out = dir.join("plant.obj");
        let out = out.to_str().expect("UTF-8 path");
        let mut args = vec!["export", &source, "-o", out, "--iterations", "2"];
        args.extend_from_slice(extra);
        let (code, _, err) = meristem(&args);
        assert_eq!((code, err.as_str()), (0, ""));
        let obj = std::fs::read_to_string(out).expect("written");
        obj.lines().filter(|l| l.starts_with("v ")).count()
    };
    let six = vertices(&[]);
    assert_eq!(vertices(&["--sides", "6"]), six, "6 sides is the default");
    assert!(vertices(&["--sides", "12"]) > six);
    assert!(vertices(&["--smooth-all"]) > six);
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn sides_out_of_range_are_refused_not_clamped() {
    let dir = temp_dir("export-sides");
    let source = example("abop-1.24a.lsys");
    let out = dir.join("plant.obj");
    let out = out.to_str().expect("UTF-8 path");
    for sides in [
        "0",
        "1",
        "2",
        "65",
        "1000000",
        "99999999999",
        "-1",
        "six",
        "3.5",
        "",
    ] {
        let (code, stdout, err) = meristem(&["export", &source, "-o", out, "--sides", sides]);
        assert_eq!(code, 2, "--sides {sides}: {err}");
        assert!(
            err.starts_with(&format!(
                "meristem: --sides {sides} is out of range: a branch tube has 3 to 64 sides (a whole number)\n"
            )),
            "--sides {sides}: {err}"
        );
        assert_eq!(stdout, "");
        assert!(
            !std::path::Path::new(out).exists(),
            "nothing written for --sides {sides}"
        );
    }
    // The ends of the range are accepted (derive takes the option too).
    for sides in ["3", "64"] {
        let (code, _, err) = meristem(&["export", &source, "-o", out, "--sides", sides]);
        assert_eq!((code, err.as_str()), (0, ""), "--sides {sides}");
    }
    let (code, _, err) = meristem(&["derive", &source, "--sides", "0"]);
    assert_eq!(code, 2);
    assert!(err.contains("--sides 0 is out of range"), "{err}");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn export_refuses_unknown_formats_and_reports_grammar_errors() {
    let dir = temp_dir("export-errors");
    let source = example("abop-1.24a.lsys");
    let png = dir.join("plant.png");
    let (code, _, err) = meristem(&["export", &source, "-o", png.to_str().expect("path")]);
    assert_eq!(code, 2);
    assert!(
        err.contains("unknown extension '.png'; the formats are wrl, glb, pov, obj, iv, svg"),
        "{err}"
    );
    let (code, _, err) = meristem(&["export", &source]);
    assert_eq!(code, 2);
    assert!(err.contains("-o OUT.EXT"), "{err}");
    let (code, _, err) = meristem(&["export", &source, "-o", "x.glb", "--format", "stl"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown format 'stl'"), "{err}");

    let broken = temp_file("broken-export.lsys", b"axiom: X\nX -> F[\n");
    let out = dir.join("broken.wrl");
    let (code, stdout, err) = meristem(&["export", &broken, "-o", out.to_str().expect("path")]);
    assert_eq!((code, stdout.as_str()), (1, ""));
    assert!(
        err.contains(&format!("{broken}:2:7: error: '[' is never closed")),
        "{err}"
    );
    assert!(!out.exists(), "no file for a grammar with errors");
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn export_takes_an_svgs_look_and_refuses_it_for_other_formats() {
    let dir = temp_dir("export-look");
    let source = example("abop-1.24a.lsys");
    let out = dir.join("figure.svg");
    let out = out.to_str().expect("UTF-8 path");
    let (code, _, err) = meristem(&[
        "export",
        &source,
        "-o",
        out,
        "-n",
        "2",
        "--background",
        "white",
        "--line-width",
        "5",
        "--size",
        "1748x2480",
        "--dpi",
        "300",
    ]);
    assert_eq!((code, err.as_str()), (0, ""));
    let svg = std::fs::read_to_string(out).expect("written");
    assert!(
        svg.contains(" width=\"148mm\" height=\"209.97mm\""),
        "{svg}"
    );
    assert!(svg.contains(" fill=\"#ffffff\"/>"), "{svg}");
    // Out of range, malformed, or for a format that has no look: exit 2 with the reason.
    for (args, reason) in [
        (
            &["--line-width", "0"][..],
            "line width must be from 0.5 to 60",
        ),
        (&["--size", "100"], "--size takes WIDTHxHEIGHT"),
        (&["--size", "9000x100"], "from 16 to 8192 pixels"),
        (&["--dpi", "0"], "DPI must be from 10 to 2400"),
        (&["--background", "red"], "unknown background 'red'"),
    ] {
        let (code, _, err) = meristem(&[&["export", &source, "-o", out][..], args].concat());
        assert_eq!(code, 2, "{args:?}");
        assert!(err.contains(reason), "{args:?}: {err}");
    }
    let glb = dir.join("plant.glb");
    let (code, _, err) = meristem(&[
        "export",
        &source,
        "-o",
        glb.to_str().expect("UTF-8 path"),
        "--background",
        "white",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("an SVG's picture settings, not glb's"),
        "{err}"
    );
    assert!(!glb.exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn derive_at_a_time_shows_a_timed_grammar_between_steps() {
    let file = example("abop-6.1-timed-anabaena.lsys");
    let (code, out, err) = meristem(&["derive", &file, "--at", "2.5"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.trim(), "b_l(0.5)a_r(0.5)a_r(0.5)");
    let (code, out, _) = meristem(&["derive", &file, "--at", "3"]);
    assert_eq!(code, 0);
    assert_eq!(out.trim(), "a_l(0)a_l(0)b_r(0)a_l(0)b_r(0)");
    for bad in ["-1", "soon", "inf"] {
        let (code, _, err) = meristem(&["derive", &file, "--at", bad]);
        assert_eq!(code, 2, "--at {bad}");
        assert!(err.contains("growth time"), "{err}");
    }
}

/// A PNG the CLI wrote, decoded (8-bit RGBA, unfiltered rows, as it writes them): width, height
/// and the pixels.
fn decode_png(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let (mut at, mut size, mut data) = (8, (0, 0), Vec::new());
    while at + 8 <= bytes.len() {
        let n = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        let (kind, body) = (&bytes[at + 4..at + 8], &bytes[at + 8..at + 8 + n]);
        match kind {
            b"IHDR" => {
                let word = |k: usize| u32::from_be_bytes(body[k..k + 4].try_into().unwrap());
                size = (word(0), word(4));
                assert_eq!(&body[8..10], &[8, 6], "8 bits, RGBA");
            }
            b"IDAT" => data.extend_from_slice(body),
            _ => {}
        }
        at += 12 + n;
    }
    let raw = miniz_oxide::inflate::decompress_to_vec_zlib(&data).expect("a zlib stream");
    let row = 1 + 4 * size.0 as usize;
    assert_eq!(raw.len(), row * size.1 as usize);
    let pixels = raw.chunks_exact(row).flat_map(|r| {
        assert_eq!(r[0], 0, "rows unfiltered");
        r[1..].to_vec()
    });
    (size.0, size.1, pixels.collect())
}

#[test]
fn export_frames_writes_png_pictures_of_the_growth() {
    let dir = std::env::temp_dir().join(format!("meristem-cli-png-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let grammar = example("abop-6.1-timed-anabaena.lsys");
    let frames = dir.join("frames");
    let look = [
        "--size",
        "400x120",
        "--background",
        "white",
        "--line-width",
        "3",
    ];
    let args = [
        &["export", &grammar, "--frames", "7", "--format", "png", "-o"][..],
        &[frames.to_str().unwrap()],
        &look,
    ]
    .concat();
    let (code, _, err) = meristem(&args);
    assert_eq!((code, err.as_str()), (0, ""));
    // The filament at t = 0, 1, … 6: φ^(t + 1) long (the example's header), drawn from the left
    // on a white picture framed on the whole filament; its drawn pixels grow by about φ a step.
    let drawn: Vec<usize> = (0..7)
        .map(|k| {
            let (w, h, rgba) =
                decode_png(&std::fs::read(frames.join(format!("frame_{k:03}.png"))).unwrap());
            assert_eq!((w, h), (400, 120));
            rgba.chunks_exact(4)
                .filter(|p| p[..3] != [255, 255, 255])
                .count()
        })
        .collect();
    let phi = (1.0 + 5f64.sqrt()) / 2.0;
    for t in 3..7 {
        let ratio = drawn[t] as f64 / drawn[t - 1] as f64;
        assert!((ratio - phi).abs() < 0.08, "t = {t}: {drawn:?}");
    }
    // One picture at a time: the last frame is the filament at t = 6.
    let at = dir.join("at.png");
    let args = [
        &["export", &grammar, "--at", "6", "-o"][..],
        &[at.to_str().unwrap()],
        &look,
    ]
    .concat();
    assert_eq!(meristem(&args).0, 0);
    assert_eq!(
        std::fs::read(&at).unwrap(),
        std::fs::read(frames.join("frame_006.png")).unwrap()
    );
    // Transparent by default (the filament drawn, the rest clear); too big a picture is refused.
    let (code, _, _) = meristem(&["export", &grammar, "--at", "2", "-o", at.to_str().unwrap()]);
    assert_eq!(code, 0);
    let (_, _, rgba) = decode_png(&std::fs::read(&at).unwrap());
    assert!(rgba.chunks_exact(4).any(|p| p[3] == 0) && rgba.chunks_exact(4).any(|p| p[3] > 0));
    let (code, _, err) = meristem(&[
        "export",
        &grammar,
        "--at",
        "2",
        "--size",
        "5000x100",
        "-o",
        at.to_str().unwrap(),
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("the most is 4096 on a side"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn lineage_lists_a_module_back_to_the_axiom_with_the_production_of_each_step() {
    // 1.24d after 1 step: F [ + X ] F [ - X ] + X (0-11); step 2 writes F as F F (0, 1), copies
    // [ + (2, 3), and writes step 1's X at 3 as F [ + X ] …, from 4: its X is module 7.
    let file = example("abop-1.24d.lsys");
    let (code, out, err) = meristem(&["lineage", &file, "7", "--iterations", "2"]);
    assert_eq!((code, err.as_str()), (0, ""));
    assert_eq!(
        out,
        "step 2: X [7] <- 7:1 X -> F[+X]F[-X]+X\n\
         step 1: X [3] <- 7:1 X -> F[+X]F[-X]+X\n\
         step 0: X [0] <- axiom\n"
    );
    let (code, _, err) = meristem(&["lineage", &file, "9999", "--iterations", "2"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("no module 9999") && err.contains("[E0411]"),
        "{err}"
    );
    let (code, _, err) = meristem(&["lineage", &file]);
    assert_eq!(code, 2);
    assert!(err.contains("lineage needs a module index"), "{err}");
}
