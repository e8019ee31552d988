//! L-Py's globals written in production bodies: those nothing reads (but dropped text labels)
//! are dropped, those productions read are flags (see [`super::flags`]).

use super::super::{is_identifier, Importer, Line};
use super::bodies::python_local;
use super::flags::{self, Flag};
use crate::syntax::PARENTHESES;

/// The globals of an L-Py file (assigned at the top level or named by `global`) that nothing
/// reads: every use is a `global` statement, an assignment to it, or inside a text label `@L(…)`,
/// which is dropped.
pub(in crate::import::abop) fn write_only_globals(all: &[Line]) -> Vec<String> {
    let mut candidates: Vec<String> = Vec::new();
    for line in all {
        if let Some(rest) = line.code.strip_prefix("global ") {
            candidates.extend(rest.split(',').map(|g| g.trim().to_string()));
        }
    }
    candidates.retain(|g| is_identifier(g));
    candidates.sort();
    candidates.dedup();
    candidates.retain(|g| {
        all.iter().all(|line| {
            let code = line.code.as_str();
            if code.starts_with("global ") || global_write(code, std::slice::from_ref(g)).is_some()
            {
                return true;
            }
            !has_word(&without_labels(code), g)
        })
    });
    candidates
}

/// Whether `word` stands alone (not part of a longer name) anywhere in `text`.
pub(in crate::import::abop) fn has_word(text: &str, word: &str) -> bool {
    let b = text.as_bytes();
    text.match_indices(word).any(|(i, _)| {
        let end = i + word.len();
        (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
            && (end >= b.len() || !(b[end].is_ascii_alphanumeric() || b[end] == b'_'))
    })
}

/// `code` without its text labels `@L(…)`.
pub(in crate::import::abop) fn without_labels(code: &str) -> String {
    let mut out = code.to_string();
    while let Some(at) = out.find("@L(") {
        let chars: Vec<char> = out.chars().collect();
        let open = out[..at + 2].chars().count();
        let Some(close) = PARENTHESES.closing_char(&chars, open) else {
            break;
        };
        let end: usize = chars[..=close].iter().map(|c| c.len_utf8()).sum();
        out.replace_range(at..end, "");
    }
    out
}

/// The global of `globals` that `code` is about, when it is `global g` naming only such globals
/// or an assignment to one (`g = …`, `g += …`).
pub(in crate::import::abop) fn global_write(code: &str, globals: &[String]) -> Option<String> {
    if let Some(rest) = code.strip_prefix("global ") {
        let names: Vec<&str> = rest.split(',').map(str::trim).collect();
        return names
            .iter()
            .all(|g| globals.iter().any(|w| w == g))
            .then(|| names.join(", "));
    }
    let (name, _) = python_local(code)?;
    globals.contains(&name).then_some(name)
}

impl Importer {
    /// The lines of an L-Py body without its blank lines, without `global g` and assignments
    /// to g when nothing but a dropped label reads g (noted), and with a flag's setting taken out
    /// (see [`Importer::flag_lines`]).
    pub(in crate::import::abop) fn body_lines(&mut self, body: &[Line]) -> Vec<Line> {
        let mut lines: Vec<&Line> = body.iter().filter(|l| !l.code.is_empty()).collect();
        lines.retain(|line| {
            let dropped = global_write(&line.code, &self.lpy.write_only);
            if let Some(g) = &dropped {
                let code = line.code.clone();
                self.note(line.n, format!("the Python code '{code}' changes the global {g}, which nothing but text labels (@L, dropped) reads; dropped"));
            }
            dropped.is_none()
        });
        match self.flag_lines(&lines) {
            Some(owned) => owned,
            None => lines.into_iter().cloned().collect(),
        }
    }

    /// The lines of an L-Py body with the setting of a flag (`global m`, `m = 1`) taken out, and
    /// in the probe a marker put in the `produce` that follows it; `None` when the body sets no
    /// flag, or sets one this run cannot translate (the body is then read as it is).
    pub(in crate::import::abop) fn flag_lines(&mut self, lines: &[&Line]) -> Option<Vec<Line>> {
        let flags = self.lpy.flags.clone();
        let flag_of = |name: &str| flags.iter().position(|f| f.name == name);
        let mut out: Vec<Line> = Vec::new();
        let mut pending: Option<(usize, usize)> = None;
        let mut any = false;
        for line in lines {
            let code = line.code.as_str();
            if let Some(rest) = code.strip_prefix("global ") {
                if rest.split(',').all(|g| flag_of(g.trim()).is_some()) {
                    continue;
                }
            }
            if let Some((k, set)) = code.split_once('=').and_then(|(name, value)| {
                let k = flag_of(name.trim())?;
                (value.trim() == flags[k].set && !value.starts_with('=')).then_some((k, line))
            }) {
                if !self.lpy.probe && !self.lpy.flag_steps.iter().any(|(f, _)| *f == flags[k].name)
                {
                    return None;
                }
                pending = Some((k, set.indent));
                any = true;
                self.flag_note(k, set);
                continue;
            }
            let mut line = (*line).clone();
            if let Some((k, indent)) = pending.take() {
                let successor = line
                    .code
                    .strip_prefix("produce")
                    .filter(|_| line.indent == indent)?;
                if !self.in_productions {
                    return None;
                }
                if self.lpy.probe {
                    let m = flags::marker(k);
                    if !self.declared.contains(&m) {
                        self.declared.push(m.clone());
                    }
                    let successor = successor.trim();
                    let successor = if successor == "*" { "" } else { successor };
                    line.code = format!("produce {m}(0) {successor}");
                    self.lpy.flags_written.push(k);
                }
            }
            out.push(line);
        }
        (any && pending.is_none()).then_some(out)
    }

    /// The note for the setting of flag `k` at `line` (after the probe).
    pub(in crate::import::abop) fn flag_note(&mut self, k: usize, line: &Line) {
        let Flag { name, initial, set } = self.lpy.flags[k].clone();
        let Some((_, step)) = self
            .lpy
            .flag_steps
            .iter()
            .find(|(f, _)| *f == name)
            .cloned()
        else {
            return;
        };
        let code = &line.code;
        let when = match step {
            Some(s) => format!("deriving the model at import time (seeds 1 and 2 agree) shows that this branch first applies in step {s}, so {name} is {initial} up to that step and {set} after it; in that step itself, modules to the right of this one see {initial} here where L-Py gives them {set}"),
            None => format!("deriving the model at import time (seeds 1 and 2 agree) shows that this branch never applies within the derivation length, so {name} stays {initial}"),
        };
        self.note(
            line.n,
            format!("the Python code '{code}' sets the global {name}, which productions read; Meristem has no variables: {when}"),
        );
    }
}
