//! L-Py globals used as flags: a global that a production sets to a constant (`global m` then
//! `m = 1` before `produce *`) and other productions test (`if m == 1:`). Meristem has no
//! variables, but such a flag changes only once: from the step after the production first
//! applies, it holds the new value. The importer finds that step by deriving the model itself
//! (a probe, with a marker module where the flag is set, under two seeds); when both agree, the
//! flag becomes `#define m (NumIt > K ? 1 : 0)`, else the production is skipped as before.

use super::super::{is_identifier, Line};
use crate::derive::{derive, DeriveOptions};

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

/// The marker module of the flag with index `k` in a probe.
pub(in crate::import::abop) fn marker(k: usize) -> String {
    format!("ProbeMark{k}")
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

/// The first step in which the marker `marker` appears in a derivation of `probe` (the probe's
/// marker counts the steps after it was written): `Some(None)` when it never does, `None` when
/// the probe cannot be derived within its limits or two seeds disagree.
pub(in crate::import::abop) fn first_step(probe: &str, marker: &str) -> Option<Option<u32>> {
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
    let mut found = Vec::new();
    for seed in [1, 2] {
        let d = derive(
            &model,
            &DeriveOptions {
                steps,
                seed: Some(seed),
                ..Default::default()
            },
        )
        .ok()?;
        let text = d.string.to_text(&model.alphabet);
        let open = format!("{marker}(");
        let most = text
            .match_indices(&open)
            .filter_map(|(i, _)| {
                let rest = &text[i + open.len()..];
                rest[..rest.find(')')?].parse::<f64>().ok()
            })
            .fold(None, |m: Option<f64>, c| Some(m.map_or(c, |m| m.max(c))));
        found.push(most.map(|c| steps.saturating_sub(c as u32)));
    }
    (found[0] == found[1]).then(|| found[0])
}
