//! The command line's input and output paths that are not regular files (issue 50, 13): an
//! export on stdout (`-o -`, `-o /dev/stdout`) is the file alone, with nothing written beside it,
//! and a grammar read from a stream (`/dev/stdin`, `/dev/zero`) is read up to the studio's
//! largest grammar file, then refused with a message.

use std::io::Write;
use std::path::PathBuf;
use std::process::{Command, Stdio};

/// Runs the CLI with `stdin` on its standard input: exit code, stdout bytes, stderr text.
fn meristem(args: &[&str], stdin: &[u8]) -> (i32, Vec<u8>, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_meristem"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run meristem");
    let mut input = child.stdin.take().expect("stdin");
    let bytes = stdin.to_vec();
    // The CLI may refuse before it has read everything: a broken pipe is then expected.
    let writer = std::thread::spawn(move || input.write_all(&bytes).ok());
    let out = child.wait_with_output().expect("meristem ends");
    writer.join().ok();
    (
        out.status.code().unwrap_or(-1),
        out.stdout,
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

fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("meristem-cli-paths-{}-{name}", std::process::id()))
}

#[test]
fn an_export_on_stdout_is_the_file_alone() {
    let source = example("abop-1.24a.lsys");
    for format in ["glb", "obj", "wrl", "svg"] {
        let file = temp_path(&format!("plant.{format}"));
        let file = file.to_str().expect("UTF-8 path");
        let (code, _, _) = meristem(&["export", &source, "-o", file], b"");
        assert_eq!(code, 0, "{format}");
        let expected = std::fs::read(file).expect("written");
        for output in ["-", "/dev/stdout"] {
            let (code, stdout, err) =
                meristem(&["export", &source, "-o", output, "--format", format], b"");
            assert_eq!(code, 0, "{format} {output}: {err}");
            if format == "obj" {
                // The material library has no place beside a stream: the OBJ names plant.mtl.
                let text = String::from_utf8_lossy(&stdout).into_owned();
                let names_library = text.contains("\nmtllib plant.mtl\n");
                assert!(names_library, "{output}: {}", &text[..200.min(text.len())]);
                assert!(err.contains("plant.mtl is not written"), "{output}: {err}");
            } else {
                assert!(
                    stdout == expected,
                    "{format} {output}: stdout is not the file; {err}"
                );
            }
        }
        std::fs::remove_file(file).ok();
    }
    // One picture of the growth goes on stdout the same way.
    let (code, stdout, err) = meristem(
        &["export", &source, "--at", "1", "-o", "-", "--format", "svg"],
        b"",
    );
    assert_eq!(code, 0, "{err}");
    assert!(stdout.starts_with(b"<?xml"), "{err}");
    assert!(!PathBuf::from("-").exists(), "no file named '-'");
    assert!(!PathBuf::from("/dev/stdout.mtl").exists());
    assert!(!PathBuf::from("/dev/plant.mtl").exists());
}

#[test]
fn a_grammar_from_a_stream_is_read_up_to_the_studios_largest_file() {
    // A grammar of 1,200,000 bytes on stdin: more than the studio opens (1,000,000 bytes).
    let mut big = b"#iterations 1\naxiom: F\n".to_vec();
    big.resize(1_200_000, b' ');
    let (code, _, err) = meristem(&["check", "/dev/stdin"], &big);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("not a regular file"), "{err}");
    assert!(err.contains("1000000 bytes"), "{err}");
    // A small one is read.
    let (code, _, err) = meristem(&["check", "/dev/stdin"], b"axiom: F\nF -> FF\n");
    assert_eq!((code, err.as_str()), (0, ""));
    // A device that never ends is refused at once, not read until memory runs out.
    let started = std::time::Instant::now();
    let (code, _, err) = meristem(&["check", "/dev/zero"], b"");
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("/dev/zero is not a regular file"), "{err}");
    assert!(started.elapsed().as_secs() < 20);
    // The edits document is read the same way.
    let (code, _, err) = meristem(
        &[
            "derive",
            &example("abop-1.24a.lsys"),
            "--edits",
            "/dev/zero",
        ],
        b"",
    );
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("/dev/zero is not a regular file"), "{err}");
}
