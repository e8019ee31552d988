//! Explanations: why and where a production fired in the last step (the studio's
//! context-sensitivity view), from the provenance a tracked derivation recorded.

use super::rewriter::Rewriter;
use super::{context, Generator};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model};
use rand::SeedableRng;

/// Why and where one production of the productions section fired in the last step of a tracked
/// derivation: the studio's context-sensitivity view. Indices name modules of
/// [`Derivation::previous`] (the string the last step read).
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize)]
pub struct Explanation {
    /// The production's index in `model.productions`.
    pub production: u32,
    /// The modules this production rewrote.
    pub rewritten: Vec<u32>,
    /// The modules that served as left context of those rewritings (each once).
    pub left: Vec<u32>,
    /// The modules that served as right context (each once).
    pub right: Vec<u32>,
    /// Modules whose predecessor and contexts matched this production.
    pub context_matched: u32,
    /// Of those, the modules whose condition was false.
    pub condition_failed: u32,
}

/// Explains production `production` on the last step of a derivation from [`derive_tracked`] with
/// `steps` ≥ 1, given its [`Derivation::previous`], [`Derivation::origin`] and [`Derivation::parent`]. Which modules it rewrote comes from the recorded
/// provenance, so stochastic choices are the ones the derivation made; the contexts are matched
/// again on [`Derivation::previous`]. A condition that draws random numbers is evaluated again
/// with fresh numbers for the `condition_failed` count (documented in docs/LANGUAGE.md).
/// With `only`, the rewritten modules and contexts are those of that one module of `previous`
/// (the counts still cover the whole string).
pub fn explain(
    model: &Model,
    previous: &LString,
    origin: &[u32],
    parent: &[u32],
    steps: u32,
    production: u32,
    only: Option<usize>,
) -> Result<Explanation, Diagnostic> {
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
        if fired_here && only.is_none_or(|o| o == i) {
            explanation.rewritten.push(i as u32);
            explanation.left.extend(&left);
            explanation.right.extend(&right);
        }
    }
    for list in [&mut explanation.left, &mut explanation.right] {
        list.sort_unstable();
        list.dedup();
    }
    Ok(explanation)
}
