//! The debugger's breakpoints (issue 48), as L-Py's debugger has them: where a derivation played
//! step by step pauses. A breakpoint on a production pauses at the first step where it fires; a
//! watch (`A(x) : x > 3`, a predecessor with its contexts and a condition, as a production's left
//! side is written) pauses at the first step whose string has a module it holds for. Both derive
//! again with every step recorded, as the lineage does ([`super::lineage()`]).

use super::observer;
use crate::derive::{self, DeriveOptions, NOT_REWRITTEN};
use crate::diagnostics::{Diagnostic, Severity};
use crate::model::{self, Model};
use crate::syntax;

/// Where a breakpoint pauses: the step, how many times its production fired there (or for how
/// many modules the watch held), and the first of those modules of that step's string.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Pause {
    pub step: u32,
    pub count: u32,
    pub module: u32,
}

/// The first step (1 or later) where production `production` fires: how many modules it rewrote
/// there. `None` when it never fires in the steps derived with `options`.
pub fn first_firing(
    model: &Model,
    options: &DeriveOptions,
    production: u32,
) -> Result<Option<Pause>, Diagnostic> {
    let steps = observer::trace(model, options)?;
    for (k, s) in steps.iter().enumerate().skip(1) {
        // One rewriting writes a run of modules with one parent: count the runs.
        let mut count = 0;
        let mut first = None;
        let mut last_parent = None;
        for (i, (&o, &p)) in s.origin.iter().zip(&s.parent).enumerate() {
            if o != production || o == NOT_REWRITTEN {
                continue;
            }
            if last_parent != Some(p) {
                count += 1;
                last_parent = Some(p);
            }
            first.get_or_insert(i as u32);
        }
        if let Some(module) = first {
            let step = k as u32;
            return Ok(Some(Pause {
                step,
                count,
                module,
            }));
        }
    }
    Ok(None)
}

/// The first step (0: the axiom) whose string has a module that `watch` holds for (`A(x) : x > 3`,
/// `B < A`, a production's left side with the grammar's constants): how many. `None` when none
/// does; `E0412` with the parser's or resolver's message when `watch` is not such a pattern.
pub fn first_watched(
    source: &str,
    model: &Model,
    options: &DeriveOptions,
    watch: &str,
) -> Result<Option<Pause>, Diagnostic> {
    let (watcher, production) = watching_model(source, model, watch)?;
    let steps = observer::trace(model, options)?;
    for (k, s) in steps.iter().enumerate() {
        let found = derive::matching(&watcher, &s.string, production, k as u32)?;
        if let Some(&module) = found.first() {
            let (step, count) = (k as u32, found.len() as u32);
            return Ok(Some(Pause {
                step,
                count,
                module,
            }));
        }
    }
    Ok(None)
}

/// The grammar with `watch` added as a production after its last one (or after the axiom), and
/// that production's index: its modules keep their ids, so it reads the grammar's strings.
fn watching_model(source: &str, model: &Model, watch: &str) -> Result<(Model, u32), Diagnostic> {
    let bad = |message: String| Diagnostic::error("E0412", 0..0, message);
    let watch = watch.trim();
    if watch.is_empty() || watch.contains(['\n', '\r']) || watch.contains("->") {
        return Err(bad(format!(
            "a watch is one line, a predecessor with its contexts and condition, as a production's \
             left side (`A(x) : x > 3`), without an arrow: '{watch}'"
        )));
    }
    let at = model
        .productions
        .productions
        .iter()
        .map(|p| p.span.end)
        .max()
        .unwrap_or(model.axiom_span.end)
        .min(source.len());
    let line = format!("\n{watch} ->\n");
    let text = format!("{}{line}{}", &source[..at], &source[at..]);
    let (file, mut diagnostics) = syntax::parse(&text);
    let (watcher, resolved) = model::resolve(&file);
    diagnostics.extend(resolved);
    let inserted = at..at + line.len();
    if let Some(d) = diagnostics
        .iter()
        .find(|d| d.severity == Severity::Error && inserted.contains(&d.span.start))
    {
        return Err(bad(format!("the watch '{watch}': {}", d.message)));
    }
    let watcher = watcher.ok_or_else(|| bad(format!("the watch '{watch}' cannot be read")))?;
    let production = watcher
        .productions
        .productions
        .iter()
        .position(|p| inserted.contains(&p.span.start))
        .ok_or_else(|| {
            bad(format!(
                "the watch '{watch}' is not a production's left side"
            ))
        })?;
    let same_ids = (0..model.alphabet.len() as u32).all(|k| {
        let id = model::ModuleId(k);
        watcher.alphabet.get(model.alphabet.name(id)) == Some(id)
    });
    if !same_ids {
        return Err(bad(format!(
            "the watch '{watch}' cannot be matched in this grammar (its modules are numbered \
             otherwise with it)"
        )));
    }
    Ok((watcher, production as u32))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::{build, BuildOptions};

    const GRAMMAR: &str = "#define T 3\naxiom: A(0)\nA(x) : x < T -> A(x + 1)\nA(x) : x >= T -> B A(x + 1)\nB -> B F\n";

    fn built(n: u32) -> crate::pipeline::Build {
        build(GRAMMAR, &BuildOptions::with_iterations(n))
    }

    #[test]
    fn a_production_breakpoint_pauses_at_its_first_firing_with_the_count() {
        let b = built(6);
        let model = b.model.as_ref().unwrap();
        // A(0) A(1) A(2) A(3): the second production first fires at step 4 (on A(3)), once.
        let pause = first_firing(model, &b.derived_with, 1).unwrap();
        assert_eq!(
            pause,
            Some(Pause {
                step: 4,
                count: 1,
                module: 0
            })
        );
        // B -> B F fires at step 5 on the one B; A(x) < T at step 1.
        let pause = first_firing(model, &b.derived_with, 2).unwrap().unwrap();
        assert_eq!((pause.step, pause.count), (5, 1));
        assert_eq!(
            first_firing(model, &b.derived_with, 0)
                .unwrap()
                .unwrap()
                .step,
            1
        );
        let b = built(3);
        let model = b.model.as_ref().unwrap();
        assert_eq!(first_firing(model, &b.derived_with, 1).unwrap(), None);
    }

    #[test]
    fn a_watch_pauses_where_its_condition_first_holds_for_a_module() {
        let b = built(6);
        let model = b.model.as_ref().unwrap();
        let at = |watch: &str| first_watched(GRAMMAR, model, &b.derived_with, watch);
        assert_eq!(
            at("A(x) : x > 1").unwrap(),
            Some(Pause {
                step: 2,
                count: 1,
                module: 0
            })
        );
        assert_eq!(at("A(x) : x >= T").unwrap().unwrap().step, 3);
        // B -> B F first writes an F at step 5.
        assert_eq!(at("F").unwrap().unwrap().step, 5);
        assert_eq!(at("B > A(y)").unwrap().unwrap().step, 4);
        assert!(at("B > A").unwrap_err().message.contains("written with 1"));
        assert_eq!(at("A(x) : x > 100").unwrap(), None);
        let e = at("A(x) : x >").unwrap_err();
        assert_eq!(e.code, "E0412");
        assert!(
            e.message.starts_with("the watch 'A(x) : x >': "),
            "{}",
            e.message
        );
        assert_eq!(at("A -> B").unwrap_err().code, "E0412");
    }
}
