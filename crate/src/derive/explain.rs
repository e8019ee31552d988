//! Explanations: why and where a production fired in the last step (the studio's
//! context-sensitivity view), from the provenance a tracked derivation recorded.

use super::rewriter::Rewriter;
use super::{context, Generator, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, PatternItem, Production};
use rand::SeedableRng;

/// Why and where one production of the productions section fired in the last step of a tracked
/// derivation: the studio's context-sensitivity view. Indices name modules of
/// [`Derivation::previous`] (the string the last step read).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Explanation {
    /// The production's index in `model.productions`.
    pub production: u32,
    /// The modules this production rewrote (with `only`: that module, when it did).
    pub rewritten: Vec<u32>,
    /// How many modules it rewrote in the whole string.
    pub fired: u32,
    /// The modules that served as left context of those rewritings (each once).
    pub left: Vec<u32>,
    /// The modules that served as right context (each once).
    pub right: Vec<u32>,
    /// Modules whose predecessor and contexts matched this production.
    pub context_matched: u32,
    /// Of those, the modules whose condition was false.
    pub condition_failed: u32,
}

/// The last step of a derivation from [`super::derive_tracked`] with `steps` ≥ 1: the string it
/// read ([`super::Derivation::previous`]) and the provenance of the string it wrote
/// ([`super::Derivation::origin`], [`super::Derivation::parent`]). What the explanations read.
#[derive(Clone, Copy, Debug)]
pub struct LastStep<'a> {
    pub model: &'a Model,
    pub previous: &'a LString,
    pub origin: &'a [u32],
    pub parent: &'a [u32],
    pub steps: u32,
}

/// Explains production `production` on the last step. Which modules it rewrote comes from the
/// recorded provenance, so stochastic choices are the ones the derivation made; the contexts are
/// matched again on the string the step read. A condition that draws random numbers is evaluated
/// again with fresh numbers for the `condition_failed` count (documented in docs/LANGUAGE.md).
/// With `only`, the rewritten modules and contexts are those of that one module of `previous`
/// (the counts still cover the whole string).
pub fn explain(
    last: LastStep,
    production: u32,
    only: Option<usize>,
) -> Result<Explanation, Diagnostic> {
    let LastStep {
        model,
        previous,
        origin,
        parent,
        steps,
    } = last;
    let mut explanation = Explanation {
        production,
        ..Explanation::default()
    };
    let rules = &model.productions;
    let Some(p) = rules.productions.get(production as usize) else {
        return Ok(explanation);
    };
    let src = previous;
    if parent.len() != origin.len() || src.is_empty() {
        return Ok(explanation);
    }
    let mut fired = vec![false; src.len()];
    for (&o, &from) in origin.iter().zip(parent) {
        if o == production {
            fired[from as usize] = true;
        }
    }
    let mut rng = Generator::seed_from_u64(model.settings.seed);
    let mut rewriter = Rewriter::new(model, steps, &mut rng);
    context::bracket_partners(model, src, &mut rewriter.partner);
    let candidates = rules
        .by_predecessor
        .get(p.predecessor.id.index())
        .map_or(&[][..], Vec::as_slice);
    let (mut left, mut right) = (Vec::new(), Vec::new());
    for (i, &fired_i) in fired.iter().enumerate() {
        if src.ids[i] != p.predecessor.id {
            continue;
        }
        left.clear();
        right.clear();
        rewriter.vars.iter_mut().for_each(|v| *v = None);
        let (contexts, condition) =
            rewriter.matches_recording(p, src, i, steps, &mut left, &mut right)?;
        if !contexts {
            continue;
        }
        explanation.context_matched += 1;
        if !condition {
            explanation.condition_failed += 1;
            continue;
        }
        // A production with an empty successor writes no module to trace: it fired when no
        // production before it in source order matched.
        let fired_here = if p.successor.is_empty() {
            let mut earlier = false;
            for &q in candidates.iter().take_while(|&&q| q != production) {
                earlier |= rewriter.matches(&rules.productions[q as usize], src, i, steps)?;
            }
            !earlier
        } else {
            fired_i
        };
        explanation.fired += fired_here as u32;
        if fired_here && only.is_none_or(|o| o == i) {
            explanation.rewritten.push(i as u32);
            explanation.left.extend(&left);
            explanation.right.extend(&right);
        }
    }
    for list in [&mut explanation.left, &mut explanation.right] {
        crate::sort::sort(list);
        list.dedup();
    }
    Ok(explanation)
}

/// How one context of a production met the string around a module.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
#[serde(rename_all = "camelCase")]
pub struct ContextCheck {
    /// True when the whole context matched (and when the production has none).
    pub matched: bool,
    /// The string's modules that matched it, nearest the predecessor first on the left and in
    /// string order on the right (indices of the string the step read).
    pub modules: Vec<u32>,
    /// Where it did not match: the pattern's element that was not met (`C`, `[`, `]`).
    pub expected: Option<String>,
    /// … and the module found where it was expected, if any (an index of the string the step read).
    pub found: Option<u32>,
    /// That module as written (`D(2)`).
    pub found_text: Option<String>,
}

/// Why production `production` did or did not rewrite module `module` of the string the last step
/// read ([`super::Derivation::previous`]): each part of the production checked against it in turn.
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
#[serde(rename_all = "camelCase")]
pub struct MatchReport {
    pub production: u32,
    /// The module checked: an index of the string the last step read, and as written.
    pub module: u32,
    pub module_text: String,
    /// The module is the production's predecessor: its name, and its number of parameters.
    pub predecessor: bool,
    pub left: ContextCheck,
    pub right: ContextCheck,
    /// The condition's value, when there is one and the predecessor and contexts matched.
    pub condition: Option<bool>,
    /// The production that rewrote the module in the last step (`None`: it was copied).
    pub rewritten_by: Option<u32>,
}

/// Checks production `production` part by part against module `module` of the string the last
/// step read. Contexts are checked nearest the predecessor first, so the report says which element
/// failed and what stood there instead.
pub fn match_report(
    last: LastStep,
    production: u32,
    module: usize,
) -> Result<MatchReport, Diagnostic> {
    let LastStep {
        model,
        previous,
        steps,
        ..
    } = last;
    let mut report = MatchReport {
        production,
        module: module as u32,
        rewritten_by: rewritten_by(last.origin, last.parent, module),
        ..MatchReport::default()
    };
    let Some(p) = model.productions.productions.get(production as usize) else {
        return Ok(report);
    };
    if module >= previous.len() {
        return Ok(report);
    }
    report.module_text = previous.module_text(&model.alphabet, module);
    let mut rng = Generator::seed_from_u64(model.settings.seed);
    let mut rewriter = Rewriter::new(model, steps, &mut rng);
    context::bracket_partners(model, previous, &mut rewriter.partner);
    report.predecessor = previous.ids[module] == p.predecessor.id
        && previous.params_of(module).len() == p.predecessor.arity;
    if !report.predecessor {
        return Ok(report);
    }
    report.left = rewriter.check_left(p, previous, module);
    report.right = rewriter.check_right(p, previous, module);
    for check in [&mut report.left, &mut report.right] {
        check.found_text = check
            .found
            .map(|f| previous.module_text(&model.alphabet, f as usize));
    }
    if report.left.matched && report.right.matched {
        let (_, condition) =
            rewriter.matches_recording(p, previous, module, steps, &mut (), &mut ())?;
        report.condition = p.condition.as_ref().map(|_| condition);
    }
    Ok(report)
}

/// The modules of `s` (a string of this grammar) where production `production`'s predecessor,
/// contexts and condition all hold, as they would if `s` were rewritten at step `steps` (the
/// debugger's watch: a pattern and condition true for some module). A condition that draws random
/// numbers draws them from a generator of its own.
pub fn matching(
    model: &Model,
    s: &LString,
    production: u32,
    steps: u32,
) -> Result<Vec<u32>, Diagnostic> {
    let Some(p) = model.productions.productions.get(production as usize) else {
        return Ok(Vec::new());
    };
    let mut rng = Generator::seed_from_u64(model.settings.seed);
    let mut rewriter = Rewriter::new(model, steps, &mut rng);
    context::bracket_partners(model, s, &mut rewriter.partner);
    let mut found = Vec::new();
    for i in 0..s.len() {
        if s.ids[i] != p.predecessor.id || s.params_of(i).len() != p.predecessor.arity {
            continue;
        }
        if !rewriter.check_left(p, s, i).matched || !rewriter.check_right(p, s, i).matched {
            continue;
        }
        let (_, condition) = rewriter.matches_recording(p, s, i, steps, &mut (), &mut ())?;
        if condition {
            found.push(i as u32);
        }
    }
    Ok(found)
}

/// The production that wrote the first module `module` became, if any.
fn rewritten_by(origin: &[u32], parent: &[u32], module: usize) -> Option<u32> {
    let child = parent.iter().position(|&p| p as usize == module)?;
    Some(origin[child]).filter(|&o| o != NOT_REWRITTEN)
}

/// The name a pattern element stands for, as written.
fn element_name(model: &Model, item: &PatternItem) -> String {
    match item {
        PatternItem::Module(m) => model.alphabet.name(m.id).to_string(),
        PatternItem::Open => model.alphabet.name(model.open).to_string(),
        PatternItem::Close => model.alphabet.name(model.close).to_string(),
    }
}

impl<R: rand::Rng> Rewriter<'_, R> {
    /// The left context of `p` against module `i`, one element at a time from the predecessor out.
    fn check_left(&mut self, p: &Production, src: &LString, i: usize) -> ContextCheck {
        let model = self.model;
        let (partner, slots) = (&self.partner, &mut self.slots);
        let n = p.left.len();
        check_context(
            n,
            i,
            |k, matched| {
                context::match_left(model, src, partner, i, &p.left[n - k..], slots, matched)
            },
            |k| model.alphabet.name(p.left[n - k].id).to_string(),
            |from| context::previous(model, src, partner, from).map(|f| f as u32),
        )
    }

    /// The right context of `p` against module `i`, one element at a time from the predecessor on.
    fn check_right(&mut self, p: &Production, src: &LString, i: usize) -> ContextCheck {
        let model = self.model;
        let (partner, slots) = (&self.partner, &mut self.slots);
        check_context(
            p.right.len(),
            i,
            |k, matched| {
                context::match_right(model, src, partner, i + 1, &p.right[..k], slots, matched)
            },
            |k| element_name(model, &p.right[k - 1]),
            |from| {
                (from + 1..src.len())
                    .find(|&j| !model.ignored[src.ids[j].index()])
                    .map(|j| j as u32)
            },
        )
    }
}

/// A context of `n` elements checked against module `i` one element at a time, nearest the
/// predecessor first: `matches(k, matched)` matches its `k` nearest elements, recording the modules
/// they met in `matched`; at the first that fails, `expected(k)` names the element not met and
/// `found(from)` is the module standing where it was expected, `from` being the last module met
/// (or `i`).
fn check_context(
    n: usize,
    i: usize,
    mut matches: impl FnMut(usize, &mut Vec<u32>) -> bool,
    expected: impl Fn(usize) -> String,
    found: impl Fn(usize) -> Option<u32>,
) -> ContextCheck {
    let mut check = ContextCheck {
        matched: true,
        ..ContextCheck::default()
    };
    for k in 1..=n {
        let mut matched = Vec::new();
        if matches(k, &mut matched) {
            check.modules = matched;
            continue;
        }
        let from = check.modules.last().map_or(i, |&m| m as usize);
        check.matched = false;
        check.expected = Some(expected(k));
        check.found = found(from);
        break;
    }
    check
}
