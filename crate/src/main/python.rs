//! Runs an L-Py or lpfg model with the machine's Python: `python3` on the PATH, or the program
//! `MERISTEM_PYTHON` names (CPython 3.11 or later). The package `meristem_lsystem` is embedded in
//! this binary (`build.rs`) and handed to Python on stdin with the model's files, as JSON; a small
//! driver imports the package from that JSON (nothing is written to disk), calls
//! `meristem_lsystem.run(files, main, options)` and prints its result on stdout (what the model
//! prints goes to stderr). The child is killed after 55 s (`MERISTEM_PYTHON_TIMEOUT`, in
//! seconds, changes it), so that an import with its translation stays within a minute; the
//! runtime's own time limit is set 10 s shorter, so that a model that runs too long stops with
//! its own message.

use meristem::import::{ObjectFile, PythonMain};
use std::io::{Read, Write};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

include!(concat!(env!("OUT_DIR"), "/python_package.rs"));

/// The driver Python runs: the package imported from the request's sources, then `run`.
const DRIVER: &str = r#"
import sys
if sys.version_info < (3, 11):
    sys.stderr.write("Python %d.%d is too old: meristem needs 3.11 or later\n" % sys.version_info[:2])
    sys.exit(3)
import importlib.abc, importlib.util, json
request = json.loads(sys.stdin.buffer.read().decode("utf-8"))
package = request["package"]

class Embedded(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    def find_spec(self, name, path=None, target=None):
        base = name.replace(".", "/")
        for key, is_package in ((base + "/__init__.py", True), (base + ".py", False)):
            if key in package:
                return importlib.util.spec_from_loader(name, self, origin=key, is_package=is_package)
        return None

    def create_module(self, spec):
        return None

    def exec_module(self, module):
        key = module.__spec__.origin
        exec(compile(package[key], "<meristem>/" + key, "exec"), module.__dict__)

sys.meta_path.insert(0, Embedded())
from meristem_lsystem import run
# What the model prints goes to stderr: stdout carries the result alone.
result_out, sys.stdout = sys.stdout, sys.stderr
result = run(request["files"], request["main"], request["options"])
result_out.write(json.dumps(result))
result_out.flush()
"#;

/// The seconds after which Python is stopped.
fn timeout() -> f64 {
    std::env::var("MERISTEM_PYTHON_TIMEOUT")
        .ok()
        .and_then(|t| t.trim().parse::<f64>().ok())
        .filter(|t| t.is_finite() && *t > 0.0)
        .unwrap_or(55.0)
}

/// Runs `main` of `files` with Python: the result's JSON, or why there is none (Python missing or
/// too old, the package not embedded, a timeout, a crash), in a sentence.
pub fn run(
    files: &[ObjectFile],
    main: &PythonMain,
    steps: Option<u32>,
    seed: u64,
) -> Result<String, String> {
    if PACKAGE.is_empty() {
        return Err("this meristem was built without the Python package meristem_lsystem".into());
    }
    let limit = timeout();
    let input = request(files, main, steps, seed, limit);
    let program = std::env::var("MERISTEM_PYTHON").unwrap_or_else(|_| "python3".into());
    let child = Command::new(&program)
        .arg("-c")
        .arg(DRIVER)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("Python ({program}) could not be started: {e}"))?;
    let (status, stdout, stderr) = communicate(child, input, limit);
    let Some(status) = status else {
        return Err(format!(
            "running the model with Python did not finish within {limit} s and was stopped"
        ));
    };
    if !status.success() {
        let last = stderr.lines().rev().find(|l| !l.trim().is_empty());
        return Err(format!(
            "running the model with Python ({program}) failed: {}",
            last.unwrap_or("no message").trim()
        ));
    }
    if stdout.len() > MAX_RESULT_BYTES {
        return Err(format!(
            "Python's result is larger than {} MiB, the most Meristem reads",
            MAX_RESULT_BYTES >> 20
        ));
    }
    String::from_utf8(stdout).map_err(|_| "Python's result is not UTF-8 text".to_string())
}

/// The request on Python's stdin: the package's sources, the model's files, `main`, the options.
fn request(
    files: &[ObjectFile],
    main: &PythonMain,
    steps: Option<u32>,
    seed: u64,
    limit: f64,
) -> Vec<u8> {
    let request = serde_json::json!({
        "package": PACKAGE.iter().copied().collect::<std::collections::BTreeMap<_, _>>(),
        // Text files only (an object's icon and the like are left out).
        "files": files
            .iter()
            .filter_map(|f| Some((f.name.clone(), std::str::from_utf8(&f.bytes).ok()?)))
            .collect::<std::collections::BTreeMap<_, _>>(),
        "main": main.main,
        "options": {
            "steps": steps,
            "seed": seed,
            "dialect": main.dialect,
            "time_limit": (limit - 10.0).max(limit * 0.8),
        },
    });
    request.to_string().into_bytes()
}

/// The most bytes of Python's result (its stdout) read: past it the result is refused.
const MAX_RESULT_BYTES: usize = 512 << 20;

/// The bytes of what the model prints (Python's stderr) kept, its last: the error's line is read
/// from them. A model that prints in a loop filled the memory (6 GB in 4 s) before the timeout.
const MAX_MESSAGE_BYTES: usize = 64 << 10;

/// Which bytes of a stream [`drain`] keeps.
#[derive(Clone, Copy)]
enum Keep {
    First(usize),
    Last(usize),
}

/// Reads `stream` to its end (so the child is never blocked on a full pipe), keeping at most
/// the first or the last bytes `keep` says.
fn drain(mut stream: Box<dyn Read + Send>, keep: Keep) -> Vec<u8> {
    let mut kept = Vec::new();
    let mut chunk = vec![0u8; 64 << 10];
    loop {
        let n = match stream.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(_) => break,
        };
        match keep {
            Keep::First(most) => {
                let room = most.saturating_sub(kept.len()).min(n);
                kept.extend_from_slice(&chunk[..room]);
            }
            Keep::Last(most) => {
                kept.extend_from_slice(&chunk[..n]);
                if kept.len() > 2 * most {
                    kept.drain(..kept.len() - most);
                }
            }
        }
    }
    if let Keep::Last(most) = keep {
        kept.drain(..kept.len().saturating_sub(most));
    }
    kept
}

/// Writes `input` to the child, reads its output, waits at most `limit` seconds (then kills it):
/// its status (`None` when killed), stdout and stderr.
fn communicate(
    mut child: std::process::Child,
    input: Vec<u8>,
    limit: f64,
) -> (Option<std::process::ExitStatus>, Vec<u8>, String) {
    let mut stdin = child.stdin.take();
    let writer = std::thread::spawn(move || {
        if let Some(stdin) = stdin.as_mut() {
            let _ = stdin.write_all(&input);
        }
    });
    let reader = |stream: Option<Box<dyn Read + Send>>, keep: Keep| {
        std::thread::spawn(move || stream.map(|s| drain(s, keep)).unwrap_or_default())
    };
    let out = reader(
        child
            .stdout
            .take()
            .map(|s| Box::new(s) as Box<dyn Read + Send>),
        Keep::First(MAX_RESULT_BYTES + 1),
    );
    let err = reader(
        child
            .stderr
            .take()
            .map(|s| Box::new(s) as Box<dyn Read + Send>),
        Keep::Last(MAX_MESSAGE_BYTES),
    );
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed().as_secs_f64() < limit => {
                std::thread::sleep(Duration::from_millis(20))
            }
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
        }
    };
    let _ = writer.join();
    let stdout = out.join().unwrap_or_default();
    let stderr = String::from_utf8_lossy(&err.join().unwrap_or_default()).into_owned();
    (status, stdout, stderr)
}
