//! Stage 3, `derive`: parallel rewriting of the string, step by step.
//!
//! Every module of step k is rewritten from the string of step k (two buffers, swapped). Two
//! paths share the semantics:
//! - [`d0l`], for grammars without parameters, contexts, conditions or weights: a flat table from
//!   module id to successor, the next length computed before writing;
//! - [`rewriter`], the general path: productions tried in source order per module with
//!   bracket-aware contexts ([`context`]), compiled conditions, weighted (stochastic) choice and
//!   Green's random variables, control modules ([`groups`]) and planned steps ([`plan`]). Each
//!   [`rewriter::Pass`] (rules, string, step) of its productions section first sorts every
//!   module id into a class once per derivation, so that the common cases skip the general
//!   matching: [`module_classes`] and its passes ([`module_pass`], [`fixed_pass`]) for strings
//!   without parameters, [`parametric_classes`] and [`parametric_pass`] for strings with them;
//!   both copy successors with [`successors`].
//!
//! After each step, decomposition rules are applied until nothing changes and cut modules
//! ([`cut`]) remove the rest of their branch. Homomorphism rules make the string the turtle reads.
//!
//! Derive knows nothing of geometry or growth: what the later stages take part in while it
//! derives (the turtle answering query modules, growth following every module and planning each
//! step) comes in through an [`Observer`], which the pipeline implements.

pub mod context;
mod cut;
mod d0l;
mod explain;
mod fixed_pass;
mod generator;
mod groups;
mod limits;
mod module_classes;
mod module_pass;
mod parametric_classes;
mod parametric_pass;
mod plan;
mod resume;
mod rewriter;
mod stepper;
mod successors;
mod timed;

pub use explain::{
    explain, match_report, matching, ContextCheck, Explanation, LastStep, MatchReport,
};

use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model};
use d0l::D0lTable;
use rand::SeedableRng;
use rewriter::{Rewriter, Tracker};

pub use generator::Generator;
use limits::{check_size, memory_error, trace_error, work_error};
pub use limits::{work_budget, MAX_STRING_BYTES, MAX_TRACE_BYTES};
pub use resume::{resume, Resume};
pub use stepper::{Assembled, Shown, Stepper};

/// What one derivation does.
#[derive(Clone, Debug, Default)]
pub struct DeriveOptions {
    pub steps: u32,
    /// Overrides `#seed`.
    pub seed: Option<u64>,
    /// The growth time, in steps, when it is not `steps` (a fraction of a step): a timed
    /// grammar (`#terminal_age`) is derived to model time `time · #dt`; any other grammar
    /// derives `steps` steps.
    pub time: Option<f64>,
}

impl DeriveOptions {
    /// `steps` steps, with the grammar's seed.
    pub fn of_steps(steps: u32) -> Self {
        DeriveOptions {
            steps,
            ..Default::default()
        }
    }
}

/// The result of a derivation.
#[derive(Clone, Debug, Default)]
pub struct Derivation {
    /// The derived string after the last step (the L-system's state).
    pub string: LString,
    /// The string the turtle reads: `string` after homomorphism; `None` without homomorphism rules.
    pub interpreted: Option<LString>,
    /// Warnings met on the way (a homomorphism that hit its maximum depth).
    pub warnings: Vec<Diagnostic>,
    /// Provenance, recorded by [`derive_tracked`] only ([`Derivation::origin`],
    /// [`Derivation::parent`]).
    provenance: Provenance,
    /// Filled by [`derive_tracked`] when there is a homomorphism: for each module of the string
    /// the turtle reads, the index of the module of `string` it comes from.
    pub turtle_origin: Vec<u32>,
    /// Filled by [`derive_tracked`]: the string before the last step (empty after 0 steps).
    pub previous: LString,
    /// How many times each module id occurs in the string the turtle reads, indexed by id, when
    /// the derivation knows it without reading that string (the D0L path counts ids to size its
    /// steps); empty otherwise. The sketch turtle sizes its lines with it.
    pub id_counts: Vec<u64>,
    /// Kept by [`derive_tracked`] when the derivation can be continued exactly ([`resume()`]).
    pub resume: Option<Resume>,
}

/// In [`Derivation::origin`]: no production made this module in the last step.
pub const NOT_REWRITTEN: u32 = u32::MAX;

/// One step of a derivation as [`derive_traced`] records it: the derivation as a sequence, for the
/// studio's derivation view.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TracedStep {
    /// The string after the step (step 0: the axiom, decomposed).
    pub string: LString,
    /// For each module, the production that wrote it in this step ([`NOT_REWRITTEN`] when it was
    /// copied; all of them at step 0).
    pub origin: Vec<u32>,
    /// For each module, the module of the previous step's string it comes from (empty at step 0).
    pub parent: Vec<u32>,
    /// A timed derivation's growth time of this string, in steps (ABOP 6.1: each step is a round
    /// of replacements, at the moment it happened; after the last round, a step that only ages
    /// every module to the time asked, each module its own parent); `None` for other grammars.
    pub time: Option<f64>,
}

impl Derivation {
    /// The string the turtle reads.
    pub fn turtle_string(&self) -> &LString {
        self.interpreted.as_ref().unwrap_or(&self.string)
    }

    /// Filled by [`derive_tracked`] only: for each module of `string`, the index in
    /// `model.productions` of the production that made it in the last step ([`NOT_REWRITTEN`]
    /// when it was copied, or comes from the axiom).
    pub fn origin(&self) -> &[u32] {
        &self.provenance().0
    }

    /// Filled by [`derive_tracked`]: for each module of `string`, the index in `previous` of the
    /// module it was rewritten or copied from (empty after 0 steps).
    pub fn parent(&self) -> &[u32] {
        &self.provenance().1
    }

    /// (origin, parent), written out on the first call when the last step left them to be.
    fn provenance(&self) -> &(Vec<u32>, Vec<u32>) {
        let p = &self.provenance;
        p.written.get_or_init(|| match &p.pending {
            Some(successors) => successors.provenance(&self.previous, self.string.len()),
            None => Default::default(),
        })
    }
}

impl PartialEq for Derivation {
    /// Equal strings, warnings and provenance, whether the provenance is written out yet or not.
    fn eq(&self, other: &Self) -> bool {
        let Derivation {
            string,
            interpreted,
            warnings,
            provenance: _,
            turtle_origin,
            previous,
            id_counts,
            resume: _,
        } = self;
        *string == other.string
            && *interpreted == other.interpreted
            && *warnings == other.warnings
            && self.provenance() == other.provenance()
            && *turtle_origin == other.turtle_origin
            && *previous == other.previous
            && *id_counts == other.id_counts
    }
}

/// Where each module of the derived string comes from in the last step ([`Derivation::origin`]
/// and [`Derivation::parent`]). A step of the general path writes it as it rewrites. A D0L step
/// leaves it `pending`: it follows from the string the step read ([`Derivation::previous`]) and
/// each id's successor, and is written out when first asked for, so a build that never asks (a
/// sketch for the benchmark, the CLI) does not pay for it, and the studio pays the same once.
#[derive(Clone, Debug, Default)]
struct Provenance {
    written: std::cell::OnceCell<(Vec<u32>, Vec<u32>)>,
    pending: Option<d0l::Successors>,
}

/// What the stages after derive take part in while it derives. Every method has a default that
/// does nothing, so an observer implements only what it needs. Random numbers an observer draws
/// come from the derivation's generator (`rng`), so one seed still gives one plant.
/// What a pass wrote, module by module, as an [`Observer`] is told it.
#[derive(Clone, Copy, Debug)]
pub struct Written<'a> {
    /// The string the pass wrote.
    pub string: &'a LString,
    /// For each of its modules, the module of the previous string it comes from.
    pub parent: &'a [u32],
    /// For each of its modules, the production that wrote it ([`NOT_REWRITTEN`] for a copy).
    pub origin: &'a [u32],
    /// The step of a productions pass, `None` for decomposition (which finishes its parents' step).
    pub birth: Option<u32>,
}

pub trait Observer {
    /// True when the observer follows every module through every pass (and may plan steps):
    /// derivation then takes the general path and reports every pass to [`Observer::followed`].
    fn follows_modules(&self) -> bool {
        false
    }

    /// The axiom was written (before its decomposition).
    fn axiom(&mut self, _axiom: &LString, _rng: &mut dyn rand::Rng) {}

    /// Before step `step` rewrites `s`: how many times each module of `s` is rewritten in this
    /// step (0: not at all, 1: as usual, more: repeatedly); `None` when each is rewritten once.
    fn plan(
        &mut self,
        _step: u32,
        _s: &LString,
        _rng: &mut dyn rand::Rng,
    ) -> Result<Option<Vec<u32>>, Diagnostic> {
        Ok(None)
    }

    /// A pass wrote [`Written`]. Called only when [`Observer::follows_modules`].
    fn followed(&mut self, _written: &Written<'_>, _rng: &mut dyn rand::Rng) {}

    /// Cut removed modules: `kept` are the indices of the modules left, in the string before.
    fn cut(&mut self, _kept: &[u32]) {}

    /// Step `step` is complete (rewriting, decomposition and cut).
    fn stepped(&mut self, _step: u32) {}

    /// The value each query module of `s` reads (module index, [x, y, z]): asked on the axiom and
    /// after every step when the string has query modules (`?P ?H ?U ?L`).
    fn queries(&mut self, _s: &LString) -> Vec<(u32, [f64; 3])> {
        Vec::new()
    }
}

/// The observer of a derivation nobody watches.
pub struct Unobserved;

impl Observer for Unobserved {}

/// Derives with the generator seeded from `options.seed` or the grammar's `#seed`.
pub fn derive(model: &Model, options: &DeriveOptions) -> Result<Derivation, Diagnostic> {
    let mut rng = Generator::seed_from_u64(options.seed.unwrap_or(model.settings.seed));
    let when = (options.steps, options.time);
    run(model, when, &mut rng, false, &mut Unobserved)
}

/// Derives `steps` steps, drawing every random number from `rng`.
pub fn derive_with<R: rand::Rng>(
    model: &Model,
    steps: u32,
    rng: &mut R,
) -> Result<Derivation, Diagnostic> {
    run(model, (steps, None), rng, false, &mut Unobserved)
}

/// Like [`derive`], and also records provenance ([`Derivation::origin`],
/// [`Derivation::turtle_origin`], [`Derivation::previous`], [`Derivation::parent`]) for the
/// studio's highlighting, picking and explanations. Only the last step and what follows it are
/// tracked, so the cost is one pass's worth of bookkeeping. `observer` takes part as
/// [`Observer`] says.
pub fn derive_tracked(
    model: &Model,
    options: &DeriveOptions,
    observer: &mut dyn Observer,
) -> Result<Derivation, Diagnostic> {
    let mut rng = Generator::seed_from_u64(options.seed.unwrap_or(model.settings.seed));
    let when = (options.steps, options.time);
    let mut derivation = run(model, when, &mut rng, true, observer)?;
    // Only the studio core continues derivations (`buildOn`): the first plant's keeps no state.
    if cfg!(feature = "studio-extras") && !observer.follows_modules() {
        derivation.resume = Resume::after(model, options, &rng);
    }
    Ok(derivation)
}

/// Like [`derive_tracked`], and also records every step ([`TracedStep`]: the string, and where
/// each of its modules comes from). Meant for short derivations: it keeps every string.
pub fn derive_traced(
    model: &Model,
    options: &DeriveOptions,
    observer: &mut dyn Observer,
) -> Result<(Derivation, Vec<TracedStep>), Diagnostic> {
    let mut rng = Generator::seed_from_u64(options.seed.unwrap_or(model.settings.seed));
    let mut run = Run::start(model, options.steps, &mut rng, observer)?;
    run.trace = Some(vec![run.traced_axiom()]);
    let steps = match timed::Clock::new(model, options.steps, options.time) {
        Some(clock) => run.timed(clock, true)?,
        None => {
            for step in 1..=options.steps {
                run.step(step, true)?;
            }
            options.steps
        }
    };
    let trace = run.trace.take().unwrap_or_default();
    Ok((run.finish(steps, true)?, trace))
}

/// Sets each query module's three parameters to the value the observer reads there.
fn apply_queries(model: &Model, s: &mut LString, observer: &mut dyn Observer) {
    let is_query = |id| {
        model
            .command(id)
            .is_some_and(crate::vocabulary::Command::is_query)
    };
    if !model.has_queries() || !s.is_parametric() || !s.ids.iter().any(|&id| is_query(id)) {
        return;
    }
    for (module, value) in observer.queries(s) {
        let i = module as usize;
        if i < s.len() && s.params_of(i).len() == 3 {
            let at = s.offsets[i] as usize;
            s.params[at..at + 3].copy_from_slice(&value);
        }
    }
}

/// Derives `when.0` steps, or a timed grammar to the time `when.1` (in steps; `when.0` when not
/// given).
fn run<R: rand::Rng>(
    model: &Model,
    when: (u32, Option<f64>),
    rng: &mut R,
    track: bool,
    observer: &mut dyn Observer,
) -> Result<Derivation, Diagnostic> {
    let (steps, time) = when;
    let mut run = Run::start(model, steps, rng, observer)?;
    if let Some(clock) = timed::Clock::new(model, steps, time) {
        let rounds = run.timed(clock, track)?;
        return run.finish(rounds, track);
    }
    for step in 1..=steps {
        run.step(step, track && step == steps)?;
    }
    run.finish(steps, track)
}

/// A derivation under way: the string, the general path's state, and the provenance of the
/// last tracked step.
struct Run<'m, 'o, R: rand::Rng> {
    rewriter: Rewriter<'m, R>,
    observer: &'o mut dyn Observer,
    /// The D0L table, when the grammar and the observer allow that path.
    d0l: Option<D0lTable>,
    has_cut: bool,
    current: LString,
    next: LString,
    origin: Vec<u32>,
    parent: Vec<u32>,
    /// A D0L last step's successors, when its provenance is left to be written when asked for.
    pending: Option<d0l::Successors>,
    previous: LString,
    /// Every step so far, when the derivation is traced.
    trace: Option<Vec<TracedStep>>,
    /// The plan of a timed derivation's round, which replaces the observer's.
    timed_plan: Option<Vec<u32>>,
    /// Modules written by the steps so far ([`work_budget`]).
    work: u64,
}

impl<'m, 'o, R: rand::Rng> Run<'m, 'o, R> {
    /// Writes and decomposes the axiom, and reads its queries.
    fn start(
        model: &'m Model,
        steps: u32,
        rng: &'m mut R,
        observer: &'o mut dyn Observer,
    ) -> Result<Self, Diagnostic> {
        let follows = observer.follows_modules();
        let mut rewriter = Rewriter::new(model, steps, rng);
        let mut current = rewriter.axiom()?;
        check_size(model, 0, current.len(), current.bytes())?;
        let mut next = LString::default();
        observer.axiom(&current, &mut *rewriter.rng);
        if !model.decomposition.is_empty() {
            if follows {
                rewriter.tracker = Some(Tracker::default());
            }
            rewriter.decompose(&mut current, &mut next, 0, observer)?;
            rewriter.tracker = None;
        }
        apply_queries(model, &mut current, observer);
        let d0l = if follows { None } else { D0lTable::new(model) };
        Ok(Run::at(rewriter, observer, current, next, d0l))
    }

    /// A derivation under way whose string is `current` (`next`: a scratch string to reuse).
    fn at(
        rewriter: Rewriter<'m, R>,
        observer: &'o mut dyn Observer,
        current: LString,
        next: LString,
        d0l: Option<D0lTable>,
    ) -> Self {
        Run {
            d0l,
            has_cut: cut::contains_cut(rewriter.model),
            rewriter,
            observer,
            current,
            next,
            origin: Vec::new(),
            parent: Vec::new(),
            pending: None,
            previous: LString::default(),
            trace: None,
            timed_plan: None,
            work: 0,
        }
    }

    /// Step 0 as a traced step: the axiom, no module rewritten.
    fn traced_axiom(&self) -> TracedStep {
        TracedStep {
            string: self.current.clone(),
            origin: vec![NOT_REWRITTEN; self.current.len()],
            parent: Vec::new(),
            time: None,
        }
    }

    /// One step: the productions pass, decomposition, cut, queries. `tracked`: record where each
    /// module comes from.
    fn step(&mut self, step: u32, tracked: bool) -> Result<(), Diagnostic> {
        let model = self.rewriter.model;
        let follows = self.observer.follows_modules();
        if tracked || follows {
            self.rewriter.tracker = Some(Tracker::default());
        }
        self.rewriter.plan = match self.timed_plan.take() {
            Some(plan) => Some(plan),
            None => self
                .observer
                .plan(step, &self.current, &mut *self.rewriter.rng)?,
        };
        self.rewrite(step, tracked)?;
        std::mem::swap(&mut self.current, &mut self.next);
        self.work = self.work.saturating_add(self.current.len() as u64);
        if self.work > work_budget(model) {
            return Err(work_error(model, step, self.work));
        }
        if tracked {
            // The string before the step, kept instead of copied (decomposition takes a new
            // scratch string).
            self.previous = std::mem::take(&mut self.next);
        }
        if !model.decomposition.is_empty() {
            self.decompose(step, tracked)?;
        }
        if self.has_cut {
            self.cut(tracked);
        }
        self.observer.stepped(step);
        apply_queries(model, &mut self.current, self.observer);
        if self.trace.is_some() {
            let traced = TracedStep {
                string: self.current.clone(),
                origin: self.origin.clone(),
                parent: self.parent.clone(),
                time: None,
            };
            self.record(step, traced)?;
        }
        Ok(())
    }

    /// Adds `traced` (step `step`) to the trace: `E0410` when the trace would pass
    /// [`MAX_TRACE_BYTES`].
    fn record(&mut self, step: u32, traced: TracedStep) -> Result<(), Diagnostic> {
        let Some(trace) = self.trace.as_mut() else {
            return Ok(());
        };
        // Only the studio core traces (the first plant's core leaves the budget's code out).
        if cfg!(feature = "studio-extras") {
            let bytes = |t: &TracedStep| t.string.bytes() + 4 * (t.origin.len() + t.parent.len());
            let total: usize = trace.iter().map(bytes).sum::<usize>() + bytes(&traced);
            if total > MAX_TRACE_BYTES {
                return Err(trace_error(self.rewriter.model, step, total));
            }
        }
        trace.push(traced);
        Ok(())
    }

    /// A timed derivation: rounds of replacements until the clock reaches its end ([`timed`]),
    /// each tracked when `tracked`. Returns the number of rounds; `E0407` past `#max_steps`.
    fn timed(&mut self, mut clock: timed::Clock, tracked: bool) -> Result<u32, Diagnostic> {
        let mut round = 0;
        self.stamp_trace(&clock);
        self.rounds(&mut clock, &mut round, tracked)?;
        Ok(round)
    }

    /// A traced timed derivation: the step just recorded is at the clock's time.
    fn stamp_trace(&mut self, clock: &timed::Clock) {
        if let Some(last) = self.trace.as_mut().and_then(|trace| trace.last_mut()) {
            last.time = Some(clock.growth_time());
        }
    }

    /// A traced timed derivation whose clock went on after its last round: the string at the end,
    /// every module aged, recorded as a step of its own (each module its own parent, none
    /// rewritten), so the trace ends with the derived string as it does for other grammars.
    fn trace_ageing(&mut self, clock: &timed::Clock, round: u32) -> Result<(), Diagnostic> {
        let Some(trace) = self.trace.as_ref() else {
            return Ok(());
        };
        let now = clock.growth_time();
        let at_now = |t: f64| (t - now).abs() <= 1e-9 * now.max(1.0);
        if trace.last().and_then(|last| last.time).is_some_and(at_now) {
            return Ok(());
        }
        let n = self.current.len();
        let aged = TracedStep {
            string: self.current.clone(),
            origin: vec![NOT_REWRITTEN; n],
            parent: (0..n as u32).collect(),
            time: Some(now),
        };
        self.record(round + 1, aged)
    }

    /// The productions pass, from `current` into `next`.
    fn rewrite(&mut self, step: u32, tracked: bool) -> Result<(), Diagnostic> {
        let model = self.rewriter.model;
        match &mut self.d0l {
            Some(table) if tracked => {
                table.step(model, &self.current, &mut self.next, step)?;
                // Its provenance follows from the string read and the successors: written when
                // asked for, unless decomposition or cut must carry it along now, or the
                // derivation is traced (every step recorded).
                let successors = table.successors();
                if model.decomposition.is_empty() && !self.has_cut && self.trace.is_none() {
                    self.pending = Some(successors);
                } else {
                    (self.origin, self.parent) =
                        successors.provenance(&self.current, self.next.len());
                }
            }
            Some(table) => table.step(model, &self.current, &mut self.next, step)?,
            None => {
                let r = &mut self.rewriter;
                r.pass(&model.productions, &self.current, &mut self.next, step)?;
                r.plan = None;
                if self.observer.follows_modules() {
                    r.followed(&self.next, Some(step), step, self.observer)?;
                }
                if let Some(t) = r.tracker.take() {
                    if tracked {
                        self.origin = t.origin;
                        self.parent = t.parent;
                    }
                }
            }
        }
        Ok(())
    }

    /// Decomposition after the step; the provenance follows it.
    fn decompose(&mut self, step: u32, tracked: bool) -> Result<(), Diagnostic> {
        if tracked || self.observer.follows_modules() {
            self.rewriter.tracker = Some(Tracker::default());
        }
        let parents =
            self.rewriter
                .decompose(&mut self.current, &mut self.next, step, self.observer)?;
        if let (true, Some(parents)) = (tracked, parents) {
            self.origin = parents.iter().map(|&p| self.origin[p as usize]).collect();
            self.parent = parents.iter().map(|&p| self.parent[p as usize]).collect();
        }
        self.rewriter.tracker = None;
        Ok(())
    }

    /// Cut after the step; the provenance and the observer follow it.
    fn cut(&mut self, tracked: bool) {
        let Some(kept) = cut::cut(self.rewriter.model, &mut self.current) else {
            return;
        };
        if tracked {
            self.origin = kept.iter().map(|&k| self.origin[k as usize]).collect();
            self.parent = kept.iter().map(|&k| self.parent[k as usize]).collect();
        }
        self.observer.cut(&kept);
    }

    /// The derivation, its provenance complete (or empty when the last step recorded none), and
    /// the string the turtle reads.
    fn finish(mut self, steps: u32, track: bool) -> Result<Derivation, Diagnostic> {
        let id_counts = self
            .d0l
            .as_mut()
            .and_then(|table| table.take_counts(self.current.len()))
            .unwrap_or_default();
        let Run {
            mut rewriter,
            current,
            mut origin,
            mut parent,
            pending,
            mut previous,
            ..
        } = self;
        let provenance = match pending {
            Some(successors) => Provenance {
                written: Default::default(),
                pending: Some(successors),
            },
            None => {
                if track && origin.len() != current.len() {
                    origin = vec![NOT_REWRITTEN; current.len()];
                }
                if parent.len() != current.len() {
                    parent.clear();
                    previous = LString::default();
                }
                Provenance {
                    written: (origin, parent).into(),
                    pending: None,
                }
            }
        };
        let mut derivation = Derivation {
            string: current,
            interpreted: None,
            warnings: Vec::new(),
            provenance,
            turtle_origin: Vec::new(),
            previous,
            id_counts,
            resume: None,
        };
        homomorphism(&mut rewriter, steps, &mut derivation, track)?;
        Ok(derivation)
    }
}

/// Applies the homomorphism rules to the derived string until nothing changes (or their maximum
/// depth, with a warning): the string the turtle reads.
fn homomorphism<R: rand::Rng>(
    rewriter: &mut Rewriter<'_, R>,
    steps: u32,
    derivation: &mut Derivation,
    track: bool,
) -> Result<(), Diagnostic> {
    let rules = &rewriter.model.homomorphism;
    if rules.is_empty() {
        return Ok(());
    }
    let mut shown = derivation.string.clone();
    let mut next = LString::default();
    let mut depth = 0;
    let mut turtle_origin: Vec<u32> = if track {
        (0..shown.len() as u32).collect()
    } else {
        Vec::new()
    };
    loop {
        if depth == rules.max_depth {
            let span = rules.productions.first().map_or(0..0, |p| p.span.clone());
            derivation.warnings.push(Diagnostic::warning(
                "E0403",
                span,
                format!(
                    "homomorphism stopped at its maximum depth {} with modules left to rewrite; \
                     raise it with 'maximum depth: N' after 'homomorphism:'",
                    rules.max_depth
                ),
            ));
            break;
        }
        if track {
            rewriter.tracker = Some(Tracker::default());
        }
        let changed = rewriter.pass(rules, &shown, &mut next, steps)?;
        let tracker = rewriter.tracker.take();
        if !changed {
            break;
        }
        if let Some(t) = tracker {
            turtle_origin = t
                .parent
                .iter()
                .map(|&p| turtle_origin[p as usize])
                .collect();
        }
        std::mem::swap(&mut shown, &mut next);
        depth += 1;
    }
    derivation.interpreted = Some(shown);
    derivation.turtle_origin = turtle_origin;
    // The turtle reads another string than the one counted.
    derivation.id_counts = Vec::new();
    Ok(())
}
