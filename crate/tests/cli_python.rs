//! The command line's Python route: an L-Py or lpfg model whose hand translation falls short is
//! run by the machine's Python (`python3`, `MERISTEM_PYTHON`) with the embedded package, and the
//! plant it derives is imported; without Python the translation is kept, with a note.

use std::path::PathBuf;
use std::process::Command;
use std::time::Instant;

fn meristem(args: &[&str], env: &[(&str, &str)]) -> (i32, String, String) {
    let mut command = Command::new(env!("CARGO_BIN_EXE_meristem"));
    command.args(args);
    for (k, v) in env {
        command.env(k, v);
    }
    let out = command.output().expect("run meristem");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("meristem-py-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("make temp dir");
    dir
}

fn write(dir: &std::path::Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path.display().to_string()
}

fn segments(stats_json: &str) -> u64 {
    let line = stats_json.lines().last().unwrap_or("");
    let v: serde_json::Value = serde_json::from_str(line).expect("stats JSON");
    v["segments"].as_u64().expect("segments")
}

/// A global Python list read in a body: the hand translation drops it; Python does not.
const LIST_MODEL: &str = "lengths = [1.0, 0.8, 0.6]\n\
Axiom: A(0)\n\
derivation length: 3\n\
production:\n\
A(i):\n  produce F(lengths[i])[+(30)A(i+1)]\n\
endlsystem\n";

/// A Python interpreter is on this machine (the tests of the route need one).
fn python_present() -> bool {
    Command::new("python3")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

#[test]
fn an_lpy_whose_translation_falls_short_is_run_by_python_and_builds_its_plant() {
    assert!(python_present(), "these tests need python3 (3.11 or later)");
    let dir = temp_dir("list");
    let file = write(&dir, "list.lpy", LIST_MODEL);
    let out = dir.join("list.lsys").display().to_string();
    let (code, _, err) = meristem(&["import", &file, "-o", &out], &[]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&out).expect("output");
    assert!(
        text.starts_with("// Derived by Python from list.lpy in 3 steps, with seed 0"),
        "{text}\n{err}"
    );
    // By hand: F(1)[+F(0.8)[+F(0.6)[+A(3)]]], three segments.
    assert!(
        text.contains("F(1)[+(30)F(0.8)[+(30)F(0.6)[+(30)A(3)]]]"),
        "{text}"
    );
    let (code, stats, err) = meristem(&["derive", &out, "--stats"], &[]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(segments(&stats), 3);
    // derive reads the .lpy itself the same way.
    let (code, stats, err) = meristem(&["derive", &file, "--stats"], &[]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(segments(&stats), 3);
    // --iterations is passed on as the run's steps.
    let (code, text, _) = meristem(&["import", &file, "--iterations", "1"], &[]);
    assert_eq!(code, 0);
    assert!(
        text.contains("in 1 step,") && text.contains("F(1)[+(30)A(1)]"),
        "{text}"
    );
}

#[test]
fn without_python_the_translation_is_kept_with_a_note_saying_why() {
    let dir = temp_dir("missing");
    let file = write(&dir, "list.lpy", LIST_MODEL);
    let env = [("MERISTEM_PYTHON", "/nonexistent/python3")];
    let (code, text, err) = meristem(&["import", &file], &env);
    assert_eq!(code, 0, "{err}");
    assert!(!text.contains("Derived by Python"), "{text}");
    assert!(text.contains("Imported from L-Py"), "{text}");
    assert!(
        err.contains("Python (/nonexistent/python3) could not be started")
            && err.contains("the hand translation is used"),
        "{err}"
    );
}

#[test]
fn a_model_that_never_stops_is_killed_at_the_timeout_not_waited_for() {
    assert!(python_present());
    let dir = temp_dir("forever");
    let file = write(
        &dir,
        "forever.lpy",
        "Axiom: A\nderivation length: 1\nproduction:\nA:\n  while True:\n    pass\n  produce F\nendlsystem\n",
    );
    let start = Instant::now();
    let env = [("MERISTEM_PYTHON_TIMEOUT", "3")];
    let (code, _, err) = meristem(&["import", &file], &env);
    let seconds = start.elapsed().as_secs_f64();
    assert!(seconds < 30.0, "took {seconds} s");
    assert!(
        err.contains("did not finish within 3 s and was stopped") || err.contains("time limit"),
        "{err}"
    );
    assert!(err.contains("the hand translation is used"), "{err}");
    // The translation of `while` gives no plant: nothing to derive is an exit 1, or an axiom `A`.
    assert!(code == 0 || code == 1, "{code}: {err}");
}

#[test]
fn an_lpfg_object_with_a_loop_is_run_by_python_with_its_view_file() {
    assert!(python_present());
    let dir = temp_dir("lpfg");
    write(&dir, "specifications", "lpfg lsystem.l view.v\n");
    write(&dir, "view.v", "line style: cylinder\n");
    write(
        &dir,
        "lsystem.l",
        "#include <lpfgall.h>\nderivation length: 1;\nmodule A(int);\nAxiom: A(3);\n\
         A(n):\n{\n  for (int i = 0; i < n; i++)\n    nproduce F(1) SB() Left(30) F(0.5) EB();\n  produce;\n}\n",
    );
    let folder = dir.display().to_string();
    let (code, text, err) = meristem(&["import", &folder], &[]);
    assert_eq!(code, 0, "{err}");
    assert!(
        text.starts_with("// Derived by Python from lsystem.l in 1 step"),
        "{text}\n{err}"
    );
    // Three F(1) and three F(0.5) in branches: six segments, by hand.
    let (code, stats, err) = meristem(&["derive", &folder, "--stats"], &[]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(segments(&stats), 6, "{err}");
}
