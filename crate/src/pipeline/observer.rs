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
    let mut observer = StageObserver {
        model,
        growth: GrowthTracker::new(model, options.steps),
        stepped: Some(stepped),
        // (Without the feature, none: the counter is left out of the build.)
        counter: (cfg!(feature = "growth") && count).then(|| StepCounter::new(model)),
    };
    let resumed = from.and_then(|from| derive::resume(model, &options, from, &mut observer));
    let derived = resumed.unwrap_or_else(|| derive::derive_tracked(model, &options, &mut observer));
    match derived {
        Ok(mut derivation) => {
            if let Some(mut counter) = observer.counter.take() {
                counter.count(&derivation.string);
                result.step_counts = counter.counts;
            }
            result.diagnostics.append(&mut derivation.warnings);
            let adjustments = observer
                .growth
                .as_ref()
                .map(|g| g.adjustments(&derivation.turtle_origin));
            result.growth = observer.growth.map(GrowthTracker::finish);
            result.derivation = derivation;
            result.derived_with = options;
            Some(adjustments)
        }
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
    let mut observer = StageObserver {
        model,
        growth: GrowthTracker::new(model, options.steps),
        stepped: None,
        counter: None,
    };
    derive::derive_traced(model, options, &mut observer).map(|(_, steps)| steps)
}

/// What the stages after derive do while it derives: growth follows every module and plans each
/// step (asking the turtle for heights), and the turtle answers query modules. Both read the
/// derived string itself, not its homomorphism image. The progress callback, if any, is told each
/// step done.
struct StageObserver<'m, 's> {
    model: &'m Model,
    growth: Option<GrowthTracker<'m>>,
    stepped: Option<&'s mut dyn FnMut(u32)>,
    /// When the build counts each step's elements (for growth in time).
    counter: Option<StepCounter>,
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
