//! Derivations continued from a finished one: the studio's step forward, Play, and grammars of
//! many small time steps (`dt`) cost the new steps only, not a derivation from the axiom.
//!
//! A derivation of n steps that [`derive_tracked`](super::derive_tracked) made keeps a
//! [`Resume`]: the generator as the n-th step left it and the seed it started from. [`resume`]
//! then derives steps n + 1 … m from the derived string, and gives exactly the derivation of m
//! steps from the axiom (string, provenance of the last step, id counts, warnings), because
//! nothing else carries from one step to the next: the general path's caches (classes, id counts)
//! are checked against the string they read, and each module's `#random` deviates are drawn anew.
//!
//! What would make the continuation differ is refused ([`Resume::blocked`]), and the caller
//! derives from the axiom: expressions that read `MaxIt` (they saw n, not m), `@Repeat` groups
//! (their budget counts every step's rewritings), a homomorphism that draws random numbers (the
//! generator is saved after it), and an observer that follows every module (growth attributes,
//! whose state is not carried).

use super::d0l::D0lTable;
use super::rewriter::Rewriter;
use super::{Derivation, DeriveOptions, Generator, Observer, Run};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, Program, RuleSet, SuccessorModule};

/// What continuing a derivation needs besides its string: where it stopped and the generator.
#[derive(Clone, Debug)]
pub struct Resume {
    /// The steps derived.
    pub steps: u32,
    /// The seed the generator started from (the caller's, else `#seed`).
    pub seed: u64,
    /// The generator after the last step (and after the homomorphism, which draws nothing when
    /// a derivation keeps this).
    rng: Generator,
}

impl Resume {
    /// The state to keep after `options.steps` steps of `model` with generator `rng`, or `None`
    /// when the derivation could not be continued exactly ([`Resume::blocked`]).
    pub(super) fn after(model: &Model, options: &DeriveOptions, rng: &Generator) -> Option<Self> {
        if Self::blocked(model).is_some() {
            return None;
        }
        Some(Resume {
            steps: options.steps,
            seed: options.seed.unwrap_or(model.settings.seed),
            rng: rng.clone(),
        })
    }

    /// Why a derivation of `model` cannot be continued exactly, or `None` when it can (the
    /// observer aside: see [`resume`]).
    pub fn blocked(model: &Model) -> Option<&'static str> {
        let rules = [&model.productions, &model.decomposition];
        if rules.iter().any(|r| reads_max_it(r))
            || model
                .random_variables
                .iter()
                .any(|v| v.distribution.reads_max_it())
        {
            return Some("an expression reads MaxIt, the number of steps");
        }
        let repeat = model.groups.repeat;
        let has_repeat = |modules: &[SuccessorModule]| holds(modules, &|s| s.id == repeat);
        if model.has_groups
            && (has_repeat(&model.axiom)
                || model
                    .productions
                    .productions
                    .iter()
                    .chain(&model.decomposition.productions)
                    .any(|p| has_repeat(&p.successor)))
        {
            return Some("@Repeat groups count their rewritings over the whole derivation");
        }
        if draws(&model.homomorphism) {
            return Some("the homomorphism draws random numbers");
        }
        if !model.settings.terminal_ages.is_empty() {
            return Some("a timed derivation's clock is not carried from one build to the next");
        }
        None
    }
}

/// True when `modules` (or the members of their groups) hold a module for which `test` is true.
fn holds(modules: &[SuccessorModule], test: &dyn Fn(&SuccessorModule) -> bool) -> bool {
    modules
        .iter()
        .any(|s| test(s) || s.group.iter().flatten().any(|member| holds(member, test)))
}

/// Every program of `rules`: conditions, weights and successor arguments.
fn programs(rules: &RuleSet) -> impl Iterator<Item = &Program> {
    rules.productions.iter().flat_map(|p| {
        let mut all: Vec<&Program> = p.condition.iter().chain(&p.weight).collect();
        collect_args(&p.successor, &mut all);
        all
    })
}

/// The argument programs of `modules` and of their groups' members.
fn collect_args<'a>(modules: &'a [SuccessorModule], out: &mut Vec<&'a Program>) {
    for s in modules {
        out.extend(&s.args);
        for member in s.group.iter().flatten() {
            collect_args(member, out);
        }
    }
}

fn reads_max_it(rules: &RuleSet) -> bool {
    programs(rules).any(Program::reads_max_it)
}

/// True when applying `rules` may draw random numbers (a weighted choice or a random expression).
fn draws(rules: &RuleSet) -> bool {
    rules.productions.iter().any(|p| p.weight.is_some()) || programs(rules).any(|p| p.random)
}

/// Continues `from`, a derivation of `model` that kept its [`Resume`], to `options.steps` steps:
/// the derivation [`derive_tracked`](super::derive_tracked) makes from the axiom with the same
/// options, `observer` told the new steps only. `None` when it cannot be continued exactly: no
/// [`Resume`], another seed, no step to add, or an observer that follows every module.
pub fn resume(
    model: &Model,
    options: &DeriveOptions,
    from: &Derivation,
    observer: &mut dyn Observer,
) -> Option<Result<Derivation, Diagnostic>> {
    let saved = from.resume.as_ref()?;
    let seed = options.seed.unwrap_or(model.settings.seed);
    if saved.seed != seed || saved.steps >= options.steps || observer.follows_modules() {
        return None;
    }
    let mut rng = saved.rng.clone();
    let steps = options.steps;
    let rewriter = Rewriter::new(model, steps, &mut rng);
    let run = Run::at(
        rewriter,
        observer,
        from.string.clone(),
        LString::default(),
        D0lTable::new(model),
    );
    Some(continued(run, saved.steps, options).map(|mut derivation| {
        derivation.resume = Resume::after(model, options, &rng);
        derivation
    }))
}

/// Steps `from + 1 ..= options.steps` of `run`, the last one tracked, and the derivation.
fn continued(
    mut run: Run<'_, '_, Generator>,
    from: u32,
    options: &DeriveOptions,
) -> Result<Derivation, Diagnostic> {
    let steps = options.steps;
    for step in from + 1..=steps {
        run.step(step, step == steps)?;
    }
    run.finish(steps, true)
}
