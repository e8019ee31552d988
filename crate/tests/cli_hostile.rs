//! The command line given what a careless script or user gives it (issue 50, "Nothing breaks,
//! everywhere"): a vlab folder holding a named pipe or a link to `/dev/zero`, a file far larger
//! than any grammar, an output that is the command's own input, `--frames` to stdout, growth
//! animation settings out of range, a number that is not one. Each ends at once with a one-line
//! message and a non-zero exit, and nothing the user wrote is lost.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs the CLI in `dir`, killed after 30 s (a hang fails the test instead of stalling it): exit
/// code, stdout, stderr.
fn meristem_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run meristem");
    let start = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if start.elapsed() > Duration::from_secs(30) {
            child.kill().ok();
            child.wait().ok();
            panic!("meristem {args:?} still ran after 30 s");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().expect("output");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A fresh folder for one test.
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "meristem-cli-hostile-{}-{name}",
        std::process::id()
    ));
    std::fs::remove_dir_all(&dir).ok();
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

const GRAMMAR: &str = "#angle 25.7\n#iterations 2\naxiom: F\nF -> F[+F]F[-F]F\n";
const CPFG: &str = "Lsystem: 1\nderivation length: 2\nAxiom: F\nF --> F[+F]F\nendlsystem\n";

#[cfg(unix)]
#[test]
fn a_vlab_folder_is_read_for_its_regular_files_only_and_within_bounds() {
    let dir = temp_dir("folder");
    let object = dir.join("object");
    std::fs::create_dir_all(&object).expect("object");
    std::fs::write(object.join("plant.l"), CPFG).expect("plant.l");
    // A named pipe nobody writes (read, it waited forever) and a link to /dev/zero (read, it
    // filled the memory until the system killed the process).
    let made = Command::new("mkfifo").arg(object.join("pipe.v")).status();
    assert!(made.is_ok_and(|s| s.success()), "mkfifo");
    std::os::unix::fs::symlink("/dev/zero", object.join("zero.map")).expect("symlink");
    let (code, out, err) = meristem_in(&dir, &["import", "object"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("axiom: F"), "{out}");
    assert!(
        err.contains("pipe.v is not a regular file: not read"),
        "{err}"
    );
    assert!(
        err.contains("zero.map is not a regular file: not read"),
        "{err}"
    );
    // Past what a .zip may unpack to (a sparse file: no disk used), the folder is refused unread.
    let big = std::fs::File::create(object.join("huge.dat")).expect("huge");
    big.set_len(65 << 20).expect("sparse");
    let (code, _, err) = meristem_in(&dir, &["derive", "object"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("is not a vlab object: its files are more than 4096 or more than 64 MiB"),
        "{err}"
    );
}

#[test]
fn a_file_larger_than_any_grammar_is_refused_unread() {
    let dir = temp_dir("large");
    let big = std::fs::File::create(dir.join("big.lsys")).expect("big");
    big.set_len(1 << 30).expect("sparse");
    for verb in ["check", "derive"] {
        let (code, _, err) = meristem_in(&dir, &[verb, "big.lsys"]);
        assert_eq!(code, 2, "{verb}: {err}");
        assert_eq!(
            err.trim(),
            "meristem: big.lsys is larger than 64 MiB, the most Meristem reads of a file"
        );
    }
    let (code, _, err) = meristem_in(&dir, &["derive", "big.lsys", "--edits", "big.lsys"]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn an_output_is_never_written_over_the_commands_input() {
    let dir = temp_dir("over");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    std::fs::write(dir.join("plant.l"), CPFG).expect("cpfg");
    let edits = r#"{"version": 1, "edits": []}"#;
    std::fs::write(dir.join("edits.json"), edits).expect("edits");
    #[cfg(unix)]
    std::os::unix::fs::symlink("plant.lsys", dir.join("link.svg")).expect("link");
    let cases: &[&[&str]] = &[
        &[
            "export",
            "plant.lsys",
            "-o",
            "plant.lsys",
            "--format",
            "svg",
        ],
        &[
            "export",
            "plant.lsys",
            "-o",
            "./plant.lsys",
            "--format",
            "obj",
        ],
        &[
            "export",
            "plant.lsys",
            "--at",
            "1",
            "-o",
            "plant.lsys",
            "--format",
            "svg",
        ],
        &[
            "export",
            "plant.lsys",
            "-o",
            "edits.json",
            "--format",
            "wrl",
            "--edits",
            "edits.json",
        ],
        &["import", "plant.l", "-o", "plant.l"],
        #[cfg(unix)]
        &["export", "plant.lsys", "-o", "link.svg"],
    ];
    for args in cases {
        let (code, _, err) = meristem_in(&dir, args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains("this command reads"), "{args:?}: {err}");
        assert!(err.contains("give another output"), "{args:?}: {err}");
    }
    assert_eq!(
        std::fs::read_to_string(dir.join("plant.lsys")).expect("kept"),
        GRAMMAR
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("plant.l")).expect("kept"),
        CPFG
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("edits.json")).expect("kept"),
        edits
    );
    // A file of a vlab object's folder is an input too; a new file beside them is not.
    std::fs::create_dir_all(dir.join("object")).expect("object");
    std::fs::write(dir.join("object/plant.l"), CPFG).expect("object's .l");
    let (code, _, err) = meristem_in(&dir, &["import", "object", "-o", "object/plant.l"]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("a file of the object this command reads (object)"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.join("object/plant.l")).expect("kept"),
        CPFG
    );
    let (code, _, err) = meristem_in(&dir, &["import", "object", "-o", "object/plant.lsys"]);
    assert_eq!(code, 0, "{err}");
    // The OBJ's material library, named after the output, would be written over the OBJ itself.
    let (code, _, err) = meristem_in(
        &dir,
        &["export", "plant.lsys", "-o", "out.mtl", "--format", "obj"],
    );
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("out.mtl would be written over out.mtl, the obj file itself"),
        "{err}"
    );
    assert!(!dir.join("out.mtl").exists());
}

#[test]
fn frames_are_refused_a_stream_for_their_folder() {
    let dir = temp_dir("frames");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    for output in ["-", "/dev/stdout"] {
        let (code, out, err) = meristem_in(
            &dir,
            &["export", "plant.lsys", "--frames", "2", "-o", output],
        );
        assert_eq!(code, 2, "{output}: {err}");
        assert_eq!(out, "");
        assert!(
            err.contains("--frames writes its pictures into a folder"),
            "{err}"
        );
    }
    // It made a folder named `-` in the working directory.
    assert!(!dir.join("-").exists());
}

#[test]
fn growth_animation_settings_out_of_range_are_refused_not_replaced() {
    let dir = temp_dir("animation");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    let export = |flag: &str, value: &str| {
        let args = [
            "export",
            "plant.lsys",
            "-o",
            "a.glb",
            "--animate",
            flag,
            value,
        ];
        meristem_in(&dir, &args)
    };
    // 1e40 wrote infinite keyframe times ("max": [null], an invalid glTF); 0, -1 and NaN were
    // silently 1; 0 and 17 targets silently 1 and 16.
    for value in ["0", "-1", "NaN", "inf", "1e40", "0.0009", "3601"] {
        let (code, _, err) = export("--seconds-per-step", value);
        assert_eq!(code, 2, "{value}: {err}");
        assert!(
            err.contains("seconds per step must be from 0.001 to 3600"),
            "{err}"
        );
    }
    for value in ["0", "17", "4294967295"] {
        let (code, _, err) = export("--targets-per-step", value);
        assert_eq!(code, 2, "{value}: {err}");
        assert!(
            err.contains("targets per step must be from 1 to 16"),
            "{err}"
        );
    }
    for (flag, value) in [
        ("--seconds-per-step", "0.001"),
        ("--seconds-per-step", "3600"),
        ("--targets-per-step", "16"),
    ] {
        let (code, _, err) = export(flag, value);
        assert_eq!(code, 0, "{flag} {value}: {err}");
    }
}

#[test]
fn a_number_that_is_not_one_is_refused_naming_its_flag() {
    let dir = temp_dir("numbers");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    for (flag, value, what) in [
        ("--iterations", "-1", "a whole number from 0 to 4294967295"),
        ("--iterations", "1e9", "a whole number from 0 to 4294967295"),
        (
            "--seed",
            "abc",
            "a whole number from 0 to 18446744073709551615",
        ),
        ("--frames", "", "a whole number from 0 to 4294967295"),
        ("--line-width", "wide", "a number, e.g. 2.5"),
    ] {
        let (code, _, err) = meristem_in(&dir, &["derive", "plant.lsys", flag, value]);
        assert_eq!(code, 2, "{flag} {value}: {err}");
        let first = err.lines().next().unwrap_or_default();
        assert_eq!(first, format!("meristem: {flag} {value}: give {what}"));
    }
}

#[test]
fn a_flag_the_verb_has_no_use_for_is_refused_not_ignored() {
    let dir = temp_dir("flags");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    let cases: &[(&[&str], &str)] = &[
        // It printed the string on stdout with exit 0, and wrote no file.
        (
            &["derive", "plant.lsys", "-o", "out.txt"],
            "derive takes no -o (it prints on stdout: redirect it, > FILE)",
        ),
        (
            &["check", "plant.lsys", "--frames", "3"],
            "check takes no --frames",
        ),
        (
            &["lineage", "plant.lsys", "0", "--edits", "e.json"],
            "lineage takes no --edits",
        ),
        (
            &["import", "plant.lsys", "--format", "svg"],
            "import takes no --format",
        ),
        (
            &["export", "plant.lsys", "-o", "x.svg", "--stats"],
            "export takes no --stats",
        ),
        (
            &["derive", "plant.lsys", "--stats", "--growth"],
            "--stats and --growth: give one of them",
        ),
        (
            &["lineage", "plant.lsys", "0", "--at", "1", "-n", "2"],
            "--iterations and --at: give one of them",
        ),
        (
            &[
                "export",
                "plant.lsys",
                "-o",
                "a.glb",
                "--seconds-per-step",
                "2",
            ],
            "--seconds-per-step and --targets-per-step set the glTF animation: add --animate",
        ),
    ];
    for (args, says) in cases {
        let (code, out, err) = meristem_in(&dir, args);
        assert_eq!((code, out.as_str()), (2, ""), "{args:?}: {err}");
        assert_eq!(
            err.lines().next(),
            Some(format!("meristem: {says}").as_str()),
            "{args:?}"
        );
    }
    assert!(
        !dir.join("out.txt").exists() && !dir.join("x.svg").exists() && !dir.join("a.glb").exists()
    );
    // What each verb takes still runs.
    for args in [
        &[
            "derive",
            "plant.lsys",
            "--stats",
            "--sides",
            "8",
            "--seed",
            "3",
        ][..],
        &["check", "plant.lsys", "--iterations", "1", "--time"],
        &["lineage", "plant.lsys", "0", "--at", "1.5"],
    ] {
        let (code, _, err) = meristem_in(&dir, args);
        assert_eq!(code, 0, "{args:?}: {err}");
    }
}

/// Runs the CLI in `dir` with stdout on `stdout`: exit code and stderr.
fn meristem_to(dir: &Path, args: &[&str], stdout: Stdio) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(args)
        .current_dir(dir)
        .stdout(stdout)
        .output()
        .expect("run meristem");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn stdout_that_cannot_be_written_is_a_message_not_a_panic() {
    let dir = temp_dir("stdout");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    // A full disk: `print!` panicked ("failed printing to stdout", exit 101) in every verb.
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        for args in [
            &["derive", "plant.lsys"][..],
            &["derive", "plant.lsys", "--stats"],
            &["lineage", "plant.lsys", "0"],
            &["import", "plant.lsys", "--from", "green"],
            &["export", "plant.lsys", "-o", "out.svg"],
            &["help", "modules"],
            &["--help"],
            &["--version"],
        ] {
            let stdout = Stdio::from(full.try_clone().expect("clone"));
            let (code, err) = meristem_to(&dir, args, stdout);
            assert_eq!(code, 2, "{args:?}: {err}");
            assert!(!err.contains("panicked"), "{args:?}: {err}");
            assert!(
                err.contains("meristem: cannot write to stdout: "),
                "{args:?}: {err}"
            );
        }
    }
    // A reader gone (`meristem derive … | head`): the string of 5^8 F is more than a pipe holds.
    let mut child = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(["derive", "plant.lsys", "--iterations", "8"])
        .current_dir(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run meristem");
    drop(child.stdout.take());
    let out = child.wait_with_output().expect("ends");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.starts_with("meristem: cannot write to stdout: Broken pipe"),
        "{err}"
    );
}

#[test]
fn a_flag_given_twice_is_refused_not_overridden() {
    let dir = temp_dir("twice");
    std::fs::write(dir.join("plant.lsys"), GRAMMAR).expect("grammar");
    // The last one was taken without a word.
    for (args, flag) in [
        (
            &["derive", "plant.lsys", "-n", "1", "--iterations", "2"][..],
            "--iterations",
        ),
        (
            &["export", "plant.lsys", "-o", "a.svg", "--out", "b.svg"],
            "-o",
        ),
        (
            &[
                "export",
                "plant.lsys",
                "-o",
                "a.svg",
                "--format",
                "svg",
                "-f",
                "wrl",
            ],
            "--format",
        ),
        (
            &["derive", "plant.lsys", "--seed", "1", "-s", "1"],
            "--seed",
        ),
    ] {
        let (code, _, err) = meristem_in(&dir, args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert_eq!(
            err.lines().next(),
            Some(format!("meristem: {flag} is given twice: give it once").as_str())
        );
    }
    assert!(!dir.join("a.svg").exists() && !dir.join("b.svg").exists());
    // A switch twice changes nothing and is let be.
    let (code, _, err) = meristem_in(&dir, &["derive", "plant.lsys", "--stats", "--stats"]);
    assert_eq!(code, 0, "{err}");
}

#[cfg(unix)]
#[test]
fn a_model_that_prints_without_end_is_read_within_bounds() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir("prints");
    // A list in a body: the hand translation falls short, so Python runs the model.
    let model = "lengths = [1.0, 0.8]\nAxiom: A(0)\nderivation length: 2\nproduction:\n\
                 A(i):\n  produce F(lengths[i])[+(30)A(i+1)]\nendlsystem\n";
    std::fs::write(dir.join("model.lpy"), model).expect("model");
    // A "Python" whose model prints 1.5 GB (each print of a model goes to stderr), then fails.
    let python = dir.join("python.sh");
    let script = "#!/bin/sh\ncat > /dev/null\nyes 'the model prints' | head -c 1500000000 >&2\n\
                  printf '\\nValueError: boom\\n' >&2\nexit 1\n";
    std::fs::write(&python, script).expect("script");
    std::fs::set_permissions(&python, std::fs::Permissions::from_mode(0o755)).expect("chmod");
    // Under 1 GB of address space: all of stderr was kept (and copied again as text), so the
    // allocation failed and the process aborted.
    let command = format!(
        "ulimit -v 1000000; MERISTEM_PYTHON={} exec {} import model.lpy",
        python.display(),
        env!("CARGO_BIN_EXE_meristem")
    );
    let out = Command::new("sh")
        .args(["-c", &command])
        .current_dir(&dir)
        .output()
        .expect("run");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(
        err.contains("failed: ValueError: boom; the hand translation is used"),
        "{err}"
    );
}
