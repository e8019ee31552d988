//! L-Py globals used as flags: a global that a production sets to a constant (`global m` then
//! `m = 1` before `produce *`) and other productions test (`if m == 1:`). Meristem has no
//! variables, but such a flag changes only once: from the step after the production first
//! applies, it holds the new value. The importer finds that step by deriving the model itself
//! (a probe, with a marker module where the flag is set, under two seeds); when both agree, the
//! flag becomes `#define m (NumIt > K ? 1 : 0)`, else the production is skipped as before.

use super::super::{is_identifier, Line};
use crate::derive::{derive, DeriveOptions};
use crate::model::Model;
use std::collections::HashMap;

/// A global of the file that may be a flag: its name, its value at the top level, the one other
/// value productions set it to.
#[derive(Clone, Debug, PartialEq)]
pub(in crate::import::abop) struct Flag {
    pub name: String,
    pub initial: String,
    pub set: String,
}

/// The most steps and modules a probe derivation may take: beyond, the flag is not translated.
const PROBE_STEPS: u32 = 1_000;
const PROBE_MODULES: usize = 50_000;

/// The start of a marker module's name: the flag's index follows.
const MARKER: &str = "ProbeMark";

/// The marker module of the flag with index `k` in a probe.
pub(in crate::import::abop) fn marker(k: usize) -> String {
    format!("{MARKER}{k}")
}

/// The plain numbers an assignment `name = value` sets, or `None`.
fn number_assignment(code: &str) -> Option<(&str, &str)> {
    let (name, value) = code.split_once('=')?;
    let (name, value) = (name.trim(), value.trim());
    (is_identifier(name) && value.parse::<f64>().is_ok_and(f64::is_finite)).then_some((name, value))
}

/// The globals of an L-Py file that may be flags: set to a number at the top level, named by a
/// `global` statement, assigned nowhere but to numbers, and to only one number other than the
/// top-level one; augmented assignments (`m += 1`) rule a global out.
pub(in crate::import::abop) fn candidates(all: &[Line]) -> Vec<Flag> {
    let mut named: Vec<String> = Vec::new();
    for line in all {
        if let Some(rest) = line.code.strip_prefix("global ") {
            named.extend(rest.split(',').map(|g| g.trim().to_string()));
        }
    }
    let mut out = Vec::new();
    for line in all.iter().filter(|l| l.indent == 0) {
        let Some((name, initial)) = number_assignment(&line.code) else {
            continue;
        };
        if !named.iter().any(|g| g == name) || out.iter().any(|f: &Flag| f.name == name) {
            continue;
        }
        let mut set: Option<&str> = None;
        let mut ok = true;
        for other in all.iter().filter(|l| l.indent > 0) {
            let code = other.code.as_str();
            let Some((target, _)) = code.split_once('=') else {
                continue;
            };
            let target = target.trim().trim_end_matches(['+', '-', '*', '/']).trim();
            if target != name || code[target.len()..].trim_start().starts_with("==") {
                continue;
            }
            match number_assignment(code) {
                Some((_, v)) if v == initial => {}
                Some((_, v)) if set.is_none_or(|s| s == v) => set = Some(v),
                _ => ok = false,
            }
        }
        if let (true, Some(set)) = (ok, set) {
            out.push(Flag {
                name: name.to_string(),
                initial: initial.to_string(),
                set: set.to_string(),
            });
        }
    }
    out
}

/// For each flag index of `flags`, the first step in which its marker ([`marker`]) appears in a
/// derivation of `probe` (the probe's marker counts the steps after it was written): `Some(None)`
/// when it never does, `None` when the probe cannot be derived within its limits or two seeds
/// disagree. The probe is derived once per seed for all the flags: a file with many flags costs
/// two derivations, not two per flag.
pub(in crate::import::abop) fn first_steps(
    probe: &str,
    flags: &[usize],
) -> Vec<Option<Option<u32>>> {
    let derived = probe_model(probe).and_then(|(model, steps)| {
        let first = latest_marks(&model, steps, 1)?;
        let second = latest_marks(&model, steps, 2)?;
        Some((first, second, steps))
    });
    let Some((first, second, steps)) = derived else {
        return vec![None; flags.len()];
    };
    // The marker with the most steps after it was written is the first one written.
    let step = |marks: &HashMap<usize, f64>, k: usize| {
        marks.get(&k).map(|&most| steps.saturating_sub(most as u32))
    };
    flags
        .iter()
        .map(|&k| {
            let (a, b) = (step(&first, k), step(&second, k));
            (a == b).then_some(a)
        })
        .collect()
}

#[cfg(test)]
thread_local! {
    /// How many times this thread derived a probe (the tests count them).
    pub(in crate::import::abop) static PROBE_DERIVATIONS: std::cell::Cell<usize> =
        const { std::cell::Cell::new(0) };
}

/// The probe's model, its module limit lowered to the probe's, and its steps; `None` when it has
/// errors or more steps than a probe may take.
fn probe_model(probe: &str) -> Option<(Model, u32)> {
    let (file, _) = crate::syntax::parse(probe);
    let (model, diagnostics) = crate::model::resolve(&file);
    let mut model = model?;
    if crate::diagnostics::has_errors(&diagnostics) {
        return None;
    }
    let steps = model.settings.iterations;
    if steps > PROBE_STEPS {
        return None;
    }
    model.settings.max_modules = model.settings.max_modules.min(PROBE_MODULES);
    Some((model, steps))
}

/// The probe derived `steps` steps with `seed`: for each flag index whose marker it holds, the
/// largest count a marker of that flag holds. `None` when the derivation fails (a limit).
fn latest_marks(model: &Model, steps: u32, seed: u64) -> Option<HashMap<usize, f64>> {
    #[cfg(test)]
    PROBE_DERIVATIONS.with(|n| n.set(n.get() + 1));
    let options = DeriveOptions {
        steps,
        seed: Some(seed),
        ..Default::default()
    };
    let text = derive(model, &options)
        .ok()?
        .string
        .to_text(&model.alphabet);
    let mut most: HashMap<usize, f64> = HashMap::new();
    for (i, _) in text.match_indices(MARKER) {
        let rest = &text[i + MARKER.len()..];
        let digits = rest.len() - rest.trim_start_matches(|c: char| c.is_ascii_digit()).len();
        let (Ok(k), Some(args)) = (
            rest[..digits].parse::<usize>(),
            rest[digits..].strip_prefix('('),
        ) else {
            continue;
        };
        let Some(count) = args
            .find(')')
            .and_then(|end| args[..end].parse::<f64>().ok())
        else {
            continue;
        };
        most.entry(k)
            .and_modify(|m| *m = m.max(count))
            .or_insert(count);
    }
    Some(most)
}
