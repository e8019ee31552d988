//! What the stages after derive do while it derives ([`derive::Observer`]): growth follows the
//! string and the turtle answers query modules, for a build ([`derive_stage`]) and for the traced
//! derivation ([`trace`]).

use super::Build;
use crate::derive::{self, Derivation, DeriveOptions, Written};
use crate::diagnostics::Diagnostic;
use crate::growth::{Adjustments, GrowthTracker};
use crate::model::{LString, Model};
use crate::turtle;

/// Derives (with growth following, when the grammar has growth attributes) into `result`,
/// telling `stepped` each step done; returns the turtle's adjustments, or `None` when derivation
/// failed. The derivation continues `from` when it can ([`derive::resume`]). `count`: also count
/// the elements of every step ([`Build::step_counts`]).
pub(super) fn derive_stage(
    model: &Model,
    options: DeriveOptions,
    from: Option<&Derivation>,
    count: bool,
    result: &mut Build,
    stepped: &mut dyn FnMut(u32),
) -> Option<Option<Adjustments>> {
    #[cfg(feature = "environment")]
    if let Some(warning) = unanswered(model) {
        result.diagnostics.push(warning);
    }
    let mut observer = StageObserver::new(model, options.steps, count, true);
    observer.stepped = Some(stepped);
    let resumed = from.and_then(|from| derive::resume(model, &options, from, &mut observer));
    let derived = resumed.unwrap_or_else(|| derive::derive_tracked(model, &options, &mut observer));
    match derived {
        Ok(derivation) => Some(observer.record(derivation, options, result)),
        Err(diagnostic) => {
            result.diagnostics.push(diagnostic);
            None
        }
    }
}

/// Derives again, recording every step (the derivation as a sequence), with growth following as in
/// a build.
pub(super) fn trace(
    model: &Model,
    options: &DeriveOptions,
) -> Result<Vec<derive::TracedStep>, Diagnostic> {
    #[cfg(feature = "environment")]
    if super::environment::runs(model) {
        return super::environment::trace(model, options);
    }
    let mut observer = StageObserver::new(model, options.steps, false, true);
    derive::derive_traced(model, options, &mut observer).map(|(_, steps)| steps)
}

/// What the stages after derive do while it derives: growth follows every module and plans each
/// step (asking the turtle for heights), and the turtle answers query modules. Both read the
/// derived string itself, not its homomorphism image. The progress callback, if any, is told each
/// step done.
pub(super) struct StageObserver<'m, 's> {
    model: &'m Model,
    growth: Option<GrowthTracker<'m>>,
    stepped: Option<&'s mut dyn FnMut(u32)>,
    /// When the build counts each step's elements (for growth in time).
    counter: Option<StepCounter>,
}

impl<'m> StageObserver<'m, '_> {
    /// The observer of a derivation of `steps` steps: `count`, count each step's elements;
    /// `growth`, follow the grammar's growth attributes, if it has any.
    pub(super) fn new(model: &'m Model, steps: u32, count: bool, growth: bool) -> Self {
        StageObserver {
            model,
            growth: growth.then(|| GrowthTracker::new(model, steps)).flatten(),
            stepped: None,
            // (Without the feature, none: the counter is left out of the build.)
            counter: (cfg!(feature = "growth") && count).then(|| StepCounter::new(model)),
        }
    }

    /// Puts `derivation` (derived with `options`, this observer watching) into `result` with the
    /// growth record and the step counts; returns the turtle's adjustments.
    pub(super) fn record(
        mut self,
        mut derivation: Derivation,
        options: DeriveOptions,
        result: &mut Build,
    ) -> Option<Adjustments> {
        if let Some(counts) = self.step_counts(&derivation.string) {
            result.step_counts = counts;
        }
        result.diagnostics.append(&mut derivation.warnings);
        let adjustments = self
            .growth
            .as_ref()
            .map(|g| g.adjustments(&derivation.turtle_origin));
        result.growth = self.growth.map(GrowthTracker::finish);
        result.derivation = derivation;
        result.derived_with = options;
        adjustments
    }

    /// Growth's adjustments of the string the turtle reads now, whose module i comes from module
    /// `origin[i]` of the derived string (empty: it is the derived string); `None` without growth
    /// attributes.
    #[cfg(feature = "environment")]
    pub(super) fn adjustments(&self, origin: &[u32]) -> Option<Adjustments> {
        self.growth.as_ref().map(|g| g.adjustments(origin))
    }

    /// The elements after each step, when counted, the last step's `last` string counted too.
    pub(super) fn step_counts(&mut self, last: &LString) -> Option<Vec<f64>> {
        let mut counter = self.counter.take()?;
        counter.count(last);
        Some(counter.counts)
    }
}

/// The elements of each step's plant, counted on the derived strings: the modules that draw
/// (a segment, a polygon, a leaf or petal, a sphere) and those a homomorphism rewrites (what it
/// makes of them is not known before the end; one each is close enough to pace growth).
struct StepCounter {
    /// For each module id: whether it counts.
    draws: Vec<bool>,
    /// The count after each step so far.
    counts: Vec<f64>,
}

impl StepCounter {
    fn new(model: &Model) -> StepCounter {
        use crate::vocabulary::Command;
        let mut draws: Vec<bool> = (0..model.alphabet.len())
            .map(|i| {
                matches!(
                    model.command(crate::model::ModuleId(i as u32)),
                    Some(
                        Command::Forward
                            | Command::ForwardNoVertex
                            | Command::StartPolygon
                            | Command::Leaf
                            | Command::Petal
                            | Command::Surface
                            | Command::Sphere
                    )
                )
            })
            .collect();
        for p in &model.homomorphism.productions {
            if let Some(d) = draws.get_mut(p.predecessor.id.index()) {
                *d = true;
            }
        }
        StepCounter {
            draws,
            counts: Vec::new(),
        }
    }

    /// Counts the plant of the next step, `s`.
    fn count(&mut self, s: &LString) {
        let draws = &self.draws;
        let n = s
            .ids
            .iter()
            .filter(|id| draws.get(id.index()).copied().unwrap_or(false))
            .count();
        self.counts.push(n as f64);
    }
}

impl derive::Observer for StageObserver<'_, '_> {
    fn follows_modules(&self) -> bool {
        self.growth.is_some()
    }

    fn axiom(&mut self, axiom: &LString, rng: &mut dyn rand::Rng) {
        if let Some(g) = &mut self.growth {
            g.axiom(axiom, rng);
        }
    }

    fn plan(
        &mut self,
        step: u32,
        s: &LString,
        rng: &mut dyn rand::Rng,
    ) -> Result<Option<Vec<u32>>, Diagnostic> {
        // The string before step `step`: the plant of step `step` − 1.
        if let Some(counter) = &mut self.counter {
            counter.count(s);
        }
        let Some(g) = &mut self.growth else {
            return Ok(None);
        };
        let model = self.model;
        let mut heights = |s: &LString, a: &Adjustments| turtle::heights(model, s, Some(a));
        g.plan(step, s, &mut heights, rng).map(Some)
    }

    fn followed(&mut self, written: &Written<'_>, rng: &mut dyn rand::Rng) {
        if let Some(g) = &mut self.growth {
            g.follow(written, rng);
        }
    }

    fn cut(&mut self, kept: &[u32]) {
        if let Some(g) = &mut self.growth {
            g.cut(kept);
        }
    }

    fn stepped(&mut self, step: u32) {
        if let Some(g) = &mut self.growth {
            g.stepped(step);
        }
        if let Some(stepped) = self.stepped.as_mut() {
            stepped(step);
        }
    }

    fn queries(&mut self, s: &LString) -> Vec<(u32, [f64; 3])> {
        let adjustments = self.growth.as_ref().map(|g| g.adjustments(&[]));
        turtle::interpret_adjusted(self.model, s, adjustments.as_ref())
            .queries
            .into_iter()
            .map(|q| (q.module, q.value))
            .collect()
    }
}

/// A [`StageObserver`] lent to a derivation through a shared cell, so that its owner reads its
/// growth between steps while the derivation holds it (the environment's cycle reads each plant
/// as drawn, growth's adjustments included). The derivation and the owner take turns: never both
/// at once.
#[cfg(feature = "environment")]
pub(super) struct Lent<'c, 'm, 's>(pub(super) &'c std::cell::RefCell<StageObserver<'m, 's>>);

#[cfg(feature = "environment")]
impl derive::Observer for Lent<'_, '_, '_> {
    fn follows_modules(&self) -> bool {
        self.0.borrow().follows_modules()
    }

    fn axiom(&mut self, axiom: &LString, rng: &mut dyn rand::Rng) {
        self.0.borrow_mut().axiom(axiom, rng);
    }

    fn plan(
        &mut self,
        step: u32,
        s: &LString,
        rng: &mut dyn rand::Rng,
    ) -> Result<Option<Vec<u32>>, Diagnostic> {
        self.0.borrow_mut().plan(step, s, rng)
    }

    fn followed(&mut self, written: &Written<'_>, rng: &mut dyn rand::Rng) {
        self.0.borrow_mut().followed(written, rng);
    }

    fn cut(&mut self, kept: &[u32]) {
        self.0.borrow_mut().cut(kept);
    }

    fn stepped(&mut self, step: u32) {
        self.0.borrow_mut().stepped(step);
    }

    fn queries(&mut self, s: &LString) -> Vec<(u32, [f64; 3])> {
        self.0.borrow_mut().queries(s)
    }
}

/// `E0409` when the grammar writes `?E` and declares no program to answer it (its parameters
/// stay as written). Only the studio core says so: the first plant's has no room for it, and runs
/// no environment anyway.
#[cfg(feature = "environment")]
fn unanswered(model: &Model) -> Option<Diagnostic> {
    let query = model.environment_query()?;
    if !model.environment.programs.is_empty() {
        return None;
    }
    let name = model.alphabet.name(query);
    Some(Diagnostic::warning(
        "E0409",
        first_written(model, query).unwrap_or_else(|| model.axiom_span.clone()),
        format!(
            "no environment program answers {name}: its parameters stay as written; declare one \
             with '{} obstacle box min x y z max x y z' (or light, space, attractors)",
            crate::vocabulary::DirectiveKind::Environment.written()
        ),
    ))
}

/// Where module `id` is first written, in the axiom or a successor.
#[cfg(feature = "environment")]
pub(super) fn first_written(
    model: &Model,
    id: crate::model::ModuleId,
) -> Option<crate::syntax::Span> {
    fn find(
        modules: &[crate::model::SuccessorModule],
        id: crate::model::ModuleId,
    ) -> Option<crate::syntax::Span> {
        modules.iter().find_map(|m| {
            if m.id == id {
                return Some(m.span.clone());
            }
            m.group.iter().flatten().find_map(|member| find(member, id))
        })
    }
    let sets = [
        &model.productions,
        &model.decomposition,
        &model.homomorphism,
    ];
    find(&model.axiom, id).or_else(|| {
        sets.iter()
            .flat_map(|set| &set.productions)
            .find_map(|p| find(&p.successor, id))
    })
}
