//! Stage 3, `derive`: parallel rewriting of the string, step by step.
//!
//! Every module of step k is rewritten from the string of step k (two buffers, swapped). Two
//! paths share the semantics:
//! - the D0L path, for grammars without parameters, contexts, conditions or weights: a flat table
//!   from module id to successor, the next length computed before writing, no allocation per module;
//! - the general path: productions tried in source order per module with bracket-aware contexts
//!   ([`context`]), compiled conditions, weighted (stochastic) choice and Green's random variables.
//!
//! After each step, decomposition rules are applied until nothing changes and cut modules (`%`,
//! `@Prune`) remove the rest of their branch. Homomorphism rules make the string the turtle reads.
//!
//! With growth attributes (`#lifetime`, `#speed`, `#shape`, `#sun`, …; [`crate::growth`]), every
//! step starts with the growth hook: the modules' thirds from an [`Observer`], the segments bend,
//! apices stop or get extra rewritings; the general path then rewrites, and every module's
//! [`GrowthState`] follows it through rewriting, decomposition and cut.

pub mod context;

use crate::diagnostics::Diagnostic;
use crate::growth::{self, GrowthRecord, GrowthState, Heights, StepValues, Third};
use crate::model::{Env, LString, Model, ModuleId, Production, Program, RuleSet, SuccessorModule};
use crate::syntax::Span;
use rand::{RngExt, SeedableRng};

/// The named generator behind every random choice: PCG-64 (MCG variant), seeded from `#seed`.
pub type Generator = rand_pcg::Pcg64Mcg;

/// What one derivation does.
#[derive(Clone, Debug)]
pub struct DeriveOptions {
    pub steps: u32,
    /// Overrides `#seed`.
    pub seed: Option<u64>,
}

/// The result of a derivation.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Derivation {
    /// The derived string after the last step (the L-system's state).
    pub string: LString,
    /// The string the turtle reads: `string` after homomorphism; `None` without homomorphism rules.
    pub interpreted: Option<LString>,
    /// Warnings met on the way (a homomorphism that hit its maximum depth).
    pub warnings: Vec<Diagnostic>,
    /// Provenance, filled by [`derive_tracked`] only: for each module of `string`, the index in
    /// `model.productions` of the production that made it in the last step ([`NOT_REWRITTEN`]
    /// when it was copied, or comes from the axiom).
    pub origin: Vec<u32>,
    /// Filled by [`derive_tracked`] when there is a homomorphism: for each module of the string
    /// the turtle reads, the index of the module of `string` it comes from.
    pub turtle_origin: Vec<u32>,
    /// Filled by [`derive_tracked`]: the string before the last step (empty after 0 steps).
    pub previous: LString,
    /// Filled by [`derive_tracked`]: for each module of `string`, the index in `previous` of the
    /// module it was rewritten or copied from (empty after 0 steps).
    pub parent: Vec<u32>,
    /// With growth attributes: each module's growth state and what each step did.
    pub growth: Option<GrowthRecord>,
}

/// In [`Derivation::origin`]: no production made this module in the last step.
pub const NOT_REWRITTEN: u32 = u32::MAX;

impl Derivation {
    /// The string the turtle reads.
    pub fn turtle_string(&self) -> &LString {
        self.interpreted.as_ref().unwrap_or(&self.string)
    }
}

/// Derives with the generator seeded from `options.seed` or the grammar's `#seed`.
pub fn derive(model: &Model, options: &DeriveOptions) -> Result<Derivation, Diagnostic> {
    let mut rng = Generator::seed_from_u64(options.seed.unwrap_or(model.settings.seed));
    derive_with(model, options.steps, &mut rng)
}

/// Derives `steps` steps, drawing every random number from `rng`.
pub fn derive_with<R: rand::Rng + ?Sized>(
    model: &Model,
    steps: u32,
    rng: &mut R,
) -> Result<Derivation, Diagnostic> {
    run(model, steps, rng, false, None)
}

/// Like [`derive`], and also records provenance ([`Derivation::origin`] and
/// [`Derivation::turtle_origin`]) for the studio's highlighting and picking. Only the last step
/// and what follows it are tracked, so the cost is one pass's worth of bookkeeping (with growth
/// attributes every pass is followed anyway, for the modules' growth states).
///
/// `observer` is the turtle, passed by the pipeline (derive itself knows nothing of geometry).
/// When the grammar has query modules (`?P ?H ?U ?L`), it is asked on the axiom and after every
/// step for the value each query module reads, and the values become the query modules'
/// parameters (environmental L-systems). With growth attributes that depend on position
/// (`#lifetime`, `#speed`, `#sun`), it is asked before every step for the height of every module.
/// Without an observer ([`derive`], [`derive_with`]) every module counts as in the middle third.
pub fn derive_tracked(
    model: &Model,
    options: &DeriveOptions,
    observer: Option<&mut dyn Observer>,
) -> Result<Derivation, Diagnostic> {
    let mut rng = Generator::seed_from_u64(options.seed.unwrap_or(model.settings.seed));
    run(model, options.steps, &mut rng, true, observer)
}

/// What derive asks of the turtle while it derives: the pipeline implements it by interpreting
/// the string.
pub trait Observer {
    /// The value each query module of `s` reads: (module index, [x, y, z]). `growth` is the
    /// string's growth state when the grammar has growth attributes.
    fn queries(&mut self, s: &LString, growth: Option<&GrowthState>) -> Vec<(u32, [f64; 3])>;
    /// The height of every module of `s` with its growth state, and the plant's extent.
    fn heights(&mut self, s: &LString, growth: &GrowthState) -> Heights;
}

/// Sets each query module's three parameters to the value the turtle reads there.
fn apply_queries<'o>(
    model: &Model,
    s: &mut LString,
    observer: &mut (dyn Observer + 'o),
    growth: Option<&GrowthState>,
) {
    let names = ["?P", "?H", "?U", "?L"];
    if !names
        .iter()
        .any(|n| model.alphabet.get(n).is_some_and(|id| s.ids.contains(&id)))
        || !s.is_parametric()
    {
        return;
    }
    for (module, value) in observer.queries(s, growth) {
        let i = module as usize;
        if i < s.len() && s.params_of(i).len() == 3 {
            let at = s.offsets[i] as usize;
            s.params[at..at + 3].copy_from_slice(&value);
        }
    }
}

/// Where each module written by a tracked pass comes from.
#[derive(Default)]
struct Tracker {
    /// For each module written, the index of the source module it was rewritten from.
    parent: Vec<u32>,
    /// For each module written, the production applied ([`NOT_REWRITTEN`] for a copy).
    origin: Vec<u32>,
}

impl Tracker {
    /// Annotates every module written since the last call.
    fn fill(&mut self, len: usize, parent: usize, origin: u32) {
        while self.parent.len() < len {
            self.parent.push(parent as u32);
            self.origin.push(origin);
        }
    }
}

fn run<R: rand::Rng + ?Sized>(
    model: &Model,
    steps: u32,
    rng: &mut R,
    track: bool,
    mut observer: Option<&mut dyn Observer>,
) -> Result<Derivation, Diagnostic> {
    let growing = model.growth.is_active();
    let mut rewriter = Rewriter::new(model, steps, rng);
    let mut current = rewriter.axiom()?;
    if current.len() > model.settings.max_modules {
        return Err(limit_error(model, 0, current.len()));
    }
    let mut next = LString::default();
    let has_cut = contains_cut(model);
    if growing {
        let modules = growth::born_all(&model.growth, &current, 0, &mut *rewriter.rng);
        rewriter.growth = Some(GrowthRecord {
            state: GrowthState { step: 0, modules },
            steps: Vec::new(),
        });
    }
    if !model.decomposition.is_empty() {
        if growing {
            rewriter.tracker = Some(Tracker::default());
        }
        rewriter.decompose(&mut current, &mut next, 0)?;
        rewriter.tracker = None;
    }
    if let Some(o) = observer.as_deref_mut() {
        apply_queries(model, &mut current, o, rewriter.growth_state());
    }
    // The growth hook works per module on the general path.
    let d0l = if growing { None } else { D0lTable::new(model) };
    let mut origin: Vec<u32> = Vec::new();
    let mut parent: Vec<u32> = Vec::new();
    let mut previous = LString::default();
    for step in 1..=steps {
        let tracked = track && step == steps;
        if tracked {
            previous = current.clone();
        }
        // Growth follows every module through the step, so it needs the tracker at every step.
        if tracked || growing {
            rewriter.tracker = Some(Tracker::default());
        }
        if growing {
            rewriter.prepare_growth(&current, step, observer.as_deref_mut())?;
        }
        match &d0l {
            Some(table) if tracked => {
                (origin, parent) = table.step_tracked(model, &current, &mut next, step)?
            }
            Some(table) => table.step(model, &current, &mut next, step)?,
            None => {
                rewriter.pass(&model.productions, &current, &mut next, step)?;
                rewriter.plan = None;
                rewriter.follow_growth(&next, Some(step));
                if let Some(t) = rewriter.tracker.take() {
                    if tracked {
                        origin = t.origin;
                        parent = t.parent;
                    }
                }
            }
        }
        std::mem::swap(&mut current, &mut next);
        if !model.decomposition.is_empty() {
            if tracked || growing {
                rewriter.tracker = Some(Tracker::default());
            }
            let parents = rewriter.decompose(&mut current, &mut next, step)?;
            if let (true, Some(parents)) = (tracked, parents) {
                origin = parents.iter().map(|&p| origin[p as usize]).collect();
                parent = parents.iter().map(|&p| parent[p as usize]).collect();
            }
            rewriter.tracker = None;
        }
        if has_cut {
            if let Some(kept) = cut(model, &mut current) {
                if tracked {
                    origin = kept.iter().map(|&k| origin[k as usize]).collect();
                    parent = kept.iter().map(|&k| parent[k as usize]).collect();
                }
                if let Some(g) = rewriter.growth.as_mut() {
                    let old = std::mem::take(&mut g.state.modules);
                    g.state.modules = kept.iter().map(|&k| old[k as usize]).collect();
                }
            }
        }
        if let Some(g) = rewriter.growth.as_mut() {
            g.state.step = step;
            debug_assert_eq!(g.state.modules.len(), current.len());
        }
        if let Some(o) = observer.as_deref_mut() {
            apply_queries(model, &mut current, o, rewriter.growth_state());
        }
    }
    if track && origin.len() != current.len() {
        origin = vec![NOT_REWRITTEN; current.len()];
    }
    if parent.len() != current.len() {
        parent.clear();
        previous = LString::default();
    }
    let mut derivation = Derivation {
        string: current,
        interpreted: None,
        warnings: Vec::new(),
        origin,
        turtle_origin: Vec::new(),
        previous,
        parent,
        growth: rewriter.growth.take(),
    };
    if !model.homomorphism.is_empty() {
        let mut shown = derivation.string.clone();
        let rules = &model.homomorphism;
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
    }
    Ok(derivation)
}

fn contains_cut(model: &Model) -> bool {
    let is_cut = |s: &SuccessorModule| model.cut.contains(&s.id);
    model.axiom.iter().any(is_cut)
        || [&model.productions, &model.decomposition]
            .iter()
            .any(|set| {
                set.productions
                    .iter()
                    .any(|p| p.successor.iter().any(is_cut))
            })
}

/// Removes each cut module and the rest of its branch (up to, not including, the `]` that closes
/// the branch, or to the end of the string on the main axis).
/// Returns the indices of the kept modules in the old string, when anything was cut.
fn cut(model: &Model, s: &mut LString) -> Option<Vec<u32>> {
    if !s.ids.iter().any(|id| model.cut.contains(id)) {
        return None;
    }
    let old = std::mem::take(s);
    s.clear(old.is_parametric());
    let mut kept = Vec::new();
    let mut i = 0;
    while i < old.len() {
        let id = old.ids[i];
        if model.cut.contains(&id) {
            let mut depth = 0usize;
            i += 1;
            while i < old.len() {
                let id = old.ids[i];
                if id == model.open {
                    depth += 1;
                } else if id == model.close || model.groups.is_marker(id) && id != model.groups.open
                {
                    if depth == 0 {
                        break;
                    }
                    depth -= 1;
                } else if id == model.groups.open {
                    depth += 1;
                }
                i += 1;
            }
            continue;
        }
        s.push(id, old.params_of(i));
        kept.push(i as u32);
        i += 1;
    }
    Some(kept)
}

fn limit_error(model: &Model, step: u32, len: usize) -> Diagnostic {
    let max = model.settings.max_modules;
    let span = model
        .settings
        .iterations_span
        .clone()
        .unwrap_or_else(|| model.axiom_span.clone());
    let when = if step == 0 {
        "the axiom has".to_string()
    } else {
        format!("step {step} would make a string of")
    };
    Diagnostic::error(
        "E0400",
        span,
        format!(
            "{when} {len} modules or more, above the limit of {max}; \
             use fewer iterations or raise the limit with '#max_modules N'"
        ),
    )
}

/// The D0L path: usable when no production has parameters, contexts, conditions or weights.
struct D0lTable {
    successors: Vec<ModuleId>,
    rule_of: Vec<Option<(u32, u32)>>,
    /// For each module id, the production that rewrites it ([`NOT_REWRITTEN`] if none).
    production_of: Vec<u32>,
}

impl D0lTable {
    fn new(model: &Model) -> Option<Self> {
        let rules = &model.productions;
        let simple = !model.parametric
            && rules
                .productions
                .iter()
                .all(|p| !p.has_context() && p.condition.is_none() && p.weight.is_none());
        if !simple {
            return None;
        }
        let mut successors = Vec::new();
        let rule_of = rules
            .by_predecessor
            .iter()
            .map(|candidates| {
                candidates.first().map(|&p| {
                    let start = successors.len() as u32;
                    successors.extend(rules.productions[p as usize].successor.iter().map(|s| s.id));
                    (start, successors.len() as u32)
                })
            })
            .collect();
        let production_of = rules
            .by_predecessor
            .iter()
            .map(|c| c.first().copied().unwrap_or(NOT_REWRITTEN))
            .collect();
        Some(D0lTable {
            successors,
            rule_of,
            production_of,
        })
    }

    /// [`D0lTable::step`], returning for each written module the production that made it.
    fn step_tracked(
        &self,
        model: &Model,
        src: &LString,
        dst: &mut LString,
        step: u32,
    ) -> Result<(Vec<u32>, Vec<u32>), Diagnostic> {
        self.step(model, src, dst, step)?;
        let mut origin = Vec::with_capacity(dst.len());
        let mut parent = Vec::with_capacity(dst.len());
        for (i, &id) in src.ids.iter().enumerate() {
            match self.rule_of[id.index()] {
                Some((start, end)) => {
                    let production = self.production_of[id.index()];
                    origin.extend(std::iter::repeat_n(production, (end - start) as usize));
                    parent.extend(std::iter::repeat_n(i as u32, (end - start) as usize));
                }
                None => {
                    origin.push(NOT_REWRITTEN);
                    parent.push(i as u32);
                }
            }
        }
        Ok((origin, parent))
    }

    fn step(
        &self,
        model: &Model,
        src: &LString,
        dst: &mut LString,
        step: u32,
    ) -> Result<(), Diagnostic> {
        let len: usize = src
            .ids
            .iter()
            .map(|id| match self.rule_of[id.index()] {
                Some((start, end)) => (end - start) as usize,
                None => 1,
            })
            .sum();
        if len > model.settings.max_modules {
            return Err(limit_error(model, step, len));
        }
        dst.clear(false);
        dst.ids.reserve(len);
        for &id in &src.ids {
            match self.rule_of[id.index()] {
                Some((start, end)) => dst
                    .ids
                    .extend_from_slice(&self.successors[start as usize..end as usize]),
                None => dst.ids.push(id),
            }
        }
        Ok(())
    }
}

/// The general path's working state, reused across modules and steps.
struct Rewriter<'m, R: rand::Rng + ?Sized> {
    model: &'m Model,
    rng: &'m mut R,
    max_it: f64,
    slots: Vec<f64>,
    vars: Vec<Option<f64>>,
    var_programs: Vec<Program>,
    partner: Vec<u32>,
    /// Matching weighted productions of the current module: (production, weight, bound slots).
    weighted: Vec<(u32, f64, Vec<f64>)>,
    /// Provenance of the pass being run, when tracking.
    tracker: Option<Tracker>,
    /// The growth state of the current string and the steps' reports, with growth attributes.
    growth: Option<GrowthRecord>,
    /// During a step's productions pass with growth attributes: how many times each module of
    /// the string is rewritten (0: a stopped or resting apex, 1: as usual, more: `#speed`).
    plan: Option<Vec<u32>>,
}

impl<'m, R: rand::Rng + ?Sized> Rewriter<'m, R> {
    fn new(model: &'m Model, steps: u32, rng: &'m mut R) -> Self {
        let max_slots = [
            &model.productions,
            &model.homomorphism,
            &model.decomposition,
        ]
        .iter()
        .flat_map(|set| set.productions.iter().map(|p| p.slots))
        .max()
        .unwrap_or(0);
        Rewriter {
            model,
            rng,
            max_it: steps as f64,
            slots: vec![0.0; max_slots],
            vars: vec![None; model.random_variables.len()],
            var_programs: model
                .random_variables
                .iter()
                .map(|v| v.distribution.clone())
                .collect(),
            partner: Vec::new(),
            weighted: Vec::new(),
            tracker: None,
            growth: None,
            plan: None,
        }
    }

    fn growth_state(&self) -> Option<&GrowthState> {
        self.growth.as_ref().map(|g| &g.state)
    }

    /// The growth hook at the start of step `step`: the thirds of the modules (from the observer,
    /// on the string's geometry so far), the segments' bending, and the lifetime and speed plan
    /// that the productions pass follows.
    fn prepare_growth<'o>(
        &mut self,
        current: &LString,
        step: u32,
        observer: Option<&mut (dyn Observer + 'o)>,
    ) -> Result<(), Diagnostic> {
        let model = self.model;
        let attributes = &model.growth;
        let mut values = StepValues::default();
        if let Some(l) = &attributes.lifetime {
            values.lifetime = Some((
                self.eval(&l.mean, 0, step, false)?,
                self.eval(&l.variance, 0, step, false)?,
            ));
        }
        if let Some(s) = &attributes.speed {
            values.speed = Some((
                self.eval(&s.mean, 0, step, false)?,
                self.eval(&s.variance, 0, step, false)?,
            ));
        }
        let Some(record) = self.growth.as_mut() else {
            return Ok(());
        };
        record.state.step = step - 1;
        // Every pass is followed, so the state matches the string; never index past it anyway.
        debug_assert_eq!(record.state.modules.len(), current.len());
        record
            .state
            .modules
            .resize(current.len(), growth::ModuleGrowth::default());
        let thirds = match observer.filter(|_| attributes.needs_heights()) {
            Some(o) => {
                let heights = o.heights(current, &record.state);
                if heights.modules.len() == current.len() {
                    heights.thirds()
                } else {
                    vec![Third::Middle; current.len()]
                }
            }
            None => vec![Third::Middle; current.len()],
        };
        growth::bend(attributes, &current.ids, &thirds, &mut record.state.modules);
        let (times, report) = growth::plan(
            attributes,
            step,
            &current.ids,
            &thirds,
            &mut record.state.modules,
            values,
            &mut *self.rng,
        );
        record.steps.push(report);
        self.plan = Some(times);
        Ok(())
    }

    /// After a pass with the tracker on: the growth state follows the string the pass wrote
    /// (`birth`: the step, or `None` for decomposition, which finishes its parents' step).
    fn follow_growth(&mut self, written: &LString, birth: Option<u32>) {
        let (Some(record), Some(t)) = (self.growth.as_mut(), self.tracker.as_ref()) else {
            return;
        };
        record.state.modules = growth::follow(
            &self.model.growth,
            &record.state.modules,
            written,
            &t.parent,
            |j| t.origin[j] != NOT_REWRITTEN,
            birth,
            &mut *self.rng,
        );
    }

    fn eval(
        &mut self,
        program: &Program,
        slots: usize,
        num_it: u32,
        fresh_vars: bool,
    ) -> Result<f64, Diagnostic> {
        let mut env = Env {
            slots: &self.slots[..slots],
            num_it: num_it as f64,
            max_it: self.max_it,
            vars: &mut self.vars,
            fresh_vars,
            var_programs: &self.var_programs,
            rng: &mut *self.rng,
        };
        program
            .eval(&mut env)
            .map_err(|e| e.into_diagnostic(&format!(" (at step {num_it})")))
    }

    fn axiom(&mut self) -> Result<LString, Diagnostic> {
        let mut s = LString::default();
        s.clear(self.model.parametric);
        let model = self.model;
        self.emit(&model.axiom, 0, 0, &mut s)?;
        Ok(s)
    }

    /// Appends successor modules, evaluating their arguments with the first `slots` slots bound;
    /// a control module writes its header and its members between markers.
    fn emit(
        &mut self,
        modules: &[SuccessorModule],
        slots: usize,
        num_it: u32,
        dst: &mut LString,
    ) -> Result<(), Diagnostic> {
        let model = self.model;
        for s in modules {
            dst.ids.push(s.id);
            if model.parametric {
                if let Some(_members) = &s.group {
                    // The header's one parameter: the Switch cursor, the Pendulum orientation
                    // (0: as written), or the Repeat count, evaluated once when the group is made.
                    let value = match s.args.first() {
                        Some(k) => self.eval(k, slots, num_it, true)?.round().max(0.0),
                        None => 0.0,
                    };
                    dst.params.push(value);
                } else {
                    for a in &s.args {
                        let v = self.eval(a, slots, num_it, true)?;
                        dst.params.push(v);
                    }
                }
                dst.offsets.push(dst.params.len() as u32);
            }
            if let Some(members) = &s.group {
                dst.push(model.groups.open, &[]);
                for (k, member) in members.iter().enumerate() {
                    if k > 0 {
                        dst.push(model.groups.separator, &[]);
                    }
                    self.emit(member, slots, num_it, dst)?;
                }
                dst.push(model.groups.close, &[]);
            }
        }
        Ok(())
    }

    /// Applies decomposition rules to `s` until nothing changes.
    /// Applies decomposition rules to `s` until nothing changes. When tracking, returns for each
    /// module of the result the index of the module of the input it comes from.
    fn decompose(
        &mut self,
        s: &mut LString,
        scratch: &mut LString,
        step: u32,
    ) -> Result<Option<Vec<u32>>, Diagnostic> {
        let model = self.model;
        let rules = &model.decomposition;
        let mut parents: Option<Vec<u32>> =
            self.tracker.as_ref().map(|_| (0..s.len() as u32).collect());
        for _ in 0..rules.max_depth {
            if !self.pass(rules, s, scratch, step)? {
                return Ok(parents);
            }
            self.follow_growth(scratch, None);
            if let (Some(parents), Some(t)) = (&mut parents, &self.tracker) {
                *parents = t.parent.iter().map(|&p| parents[p as usize]).collect();
            }
            std::mem::swap(s, scratch);
        }
        // One more pass tells whether anything is still left to decompose.
        if self.pass(rules, s, scratch, step)? {
            let span = rules.productions.first().map_or(0..0, |p| p.span.clone());
            return Err(Diagnostic::error(
                "E0402",
                span,
                format!(
                    "decomposition did not finish within its maximum depth {} at step {step}; \
                     raise it with 'maximum depth: N' after 'decomposition:'",
                    rules.max_depth
                ),
            ));
        }
        Ok(parents)
    }

    /// Tests production `p` on module `i` of `src`, binding its slots.
    fn matches(
        &mut self,
        p: &Production,
        src: &LString,
        i: usize,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        let params = src.params_of(i);
        if params.len() != p.predecessor.arity {
            return Ok(false);
        }
        let first = p.predecessor.first_slot as usize;
        self.slots[first..first + params.len()].copy_from_slice(params);
        if !p.left.is_empty()
            && !context::match_left(self.model, src, &self.partner, i, &p.left, &mut self.slots)
        {
            return Ok(false);
        }
        if !p.right.is_empty()
            && !context::match_right(
                self.model,
                src,
                &self.partner,
                i + 1,
                &p.right,
                &mut self.slots,
            )
        {
            return Ok(false);
        }
        match &p.condition {
            Some(c) => Ok(self.eval(c, p.slots, num_it, false)? != 0.0),
            None => Ok(true),
        }
    }

    /// Like [`Rewriter::matches`], recording the context modules: returns whether the predecessor
    /// and contexts matched, and whether the condition then held.
    fn matches_recording(
        &mut self,
        p: &Production,
        src: &LString,
        i: usize,
        num_it: u32,
        left: &mut Vec<u32>,
        right: &mut Vec<u32>,
    ) -> Result<(bool, bool), Diagnostic> {
        let params = src.params_of(i);
        if params.len() != p.predecessor.arity {
            return Ok((false, false));
        }
        let first = p.predecessor.first_slot as usize;
        self.slots[first..first + params.len()].copy_from_slice(params);
        let model = self.model;
        if !p.left.is_empty()
            && !context::match_left_recording(
                model,
                src,
                &self.partner,
                i,
                &p.left,
                &mut self.slots,
                left,
            )
        {
            return Ok((false, false));
        }
        if !p.right.is_empty()
            && !context::match_right_recording(
                model,
                src,
                &self.partner,
                i + 1,
                &p.right,
                &mut self.slots,
                right,
            )
        {
            return Ok((false, false));
        }
        let condition = match &p.condition {
            Some(c) => self.eval(c, p.slots, num_it, false)? != 0.0,
            None => true,
        };
        Ok((true, condition))
    }

    /// One parallel rewriting of `src` into `dst` with `rules`. Returns whether any production
    /// applied.
    fn pass(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        let model = self.model;
        if rules.has_contexts() {
            context::bracket_partners(model, src, &mut self.partner);
        }
        dst.clear(model.parametric);
        if let Some(t) = &mut self.tracker {
            t.parent.clear();
            t.origin.clear();
        }
        self.rewrite_range(rules, src, 0..src.len(), dst, num_it)
    }

    /// Rewrites modules `range` of `src` onto the end of `dst`. Control module groups act only in
    /// the productions section; elsewhere their members are rewritten like any module.
    fn rewrite_range(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        range: std::ops::Range<usize>,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        let model = self.model;
        let groups_act = model.has_groups && std::ptr::eq(rules, &model.productions);
        let planned = self.plan.is_some();
        let mut changed = false;
        let mut i = range.start;
        while i < range.end {
            let id = src.ids[i];
            if groups_act
                && model.groups.is_group(id)
                && src.ids.get(i + 1) == Some(&model.groups.open)
            {
                i = self.rewrite_group(rules, src, i, dst, num_it)?;
                self.note(dst.len(), i, NOT_REWRITTEN);
                changed = true;
                continue;
            }
            let applied = if planned {
                self.rewrite_planned(rules, src, i, dst, num_it)?
            } else {
                self.rewrite_module(rules, src, i, dst, num_it)?
            };
            self.note(dst.len(), i, applied.unwrap_or(NOT_REWRITTEN));
            changed |= applied.is_some();
            i += 1;
        }
        Ok(changed)
    }

    /// When tracking, annotates the modules written since the last note as coming from `parent`.
    fn note(&mut self, len: usize, parent: usize, origin: u32) {
        if let Some(t) = &mut self.tracker {
            t.fill(len, parent, origin);
        }
    }

    /// Rewrites module `i` of `src` as the growth plan says: not at all (a stopped or resting
    /// apex), once, or several times (`#speed`).
    fn rewrite_planned(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        i: usize,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<Option<u32>, Diagnostic> {
        let times = self
            .plan
            .as_ref()
            .map_or(1, |plan| plan.get(i).copied().unwrap_or(1));
        match times {
            0 => {
                dst.push(src.ids[i], src.params_of(i));
                Ok(None)
            }
            1 => self.rewrite_module(rules, src, i, dst, num_it),
            _ => self.rewrite_repeatedly(rules, src, i, dst, num_it, times),
        }
    }

    /// `#speed`: rewrites module `i` of `src` `times` times within this step, like `@Repeat` on
    /// that one module. The first rewriting sees the whole string's contexts, the later ones
    /// only the module's own successor; nothing more happens when no production applies.
    fn rewrite_repeatedly(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        i: usize,
        dst: &mut LString,
        num_it: u32,
        times: u32,
    ) -> Result<Option<u32>, Diagnostic> {
        let model = self.model;
        let mut current = LString::default();
        current.clear(model.parametric);
        let applied = self.rewrite_module(rules, src, i, &mut current, num_it)?;
        if applied.is_some() && times > 1 {
            let plan = self.plan.take();
            let tracker = self.tracker.take();
            let saved = std::mem::take(&mut self.partner);
            let mut next = LString::default();
            for _ in 1..times {
                if rules.has_contexts() {
                    context::bracket_partners(model, &current, &mut self.partner);
                }
                next.clear(model.parametric);
                let len = current.len();
                self.rewrite_range(rules, &current, 0..len, &mut next, num_it)?;
                std::mem::swap(&mut current, &mut next);
                if dst.len() + current.len() > model.settings.max_modules {
                    return Err(limit_error(model, num_it, dst.len() + current.len()));
                }
            }
            self.partner = saved;
            self.tracker = tracker;
            self.plan = plan;
        }
        for j in 0..current.len() {
            dst.push(current.ids[j], current.params_of(j));
        }
        Ok(applied)
    }

    /// Rewrites module `i` of `src` onto `dst`; returns the production applied, if any.
    fn rewrite_module(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        i: usize,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<Option<u32>, Diagnostic> {
        let model = self.model;
        let id = src.ids[i];
        let candidates = rules
            .by_predecessor
            .get(id.index())
            .map_or(&[][..], Vec::as_slice);
        if candidates.is_empty() {
            dst.push(id, src.params_of(i));
            return Ok(None);
        }
        self.vars.iter_mut().for_each(|v| *v = None);
        let mut chosen = None;
        for (k, &index) in candidates.iter().enumerate() {
            let p = &rules.productions[index as usize];
            if !self.matches(p, src, i, num_it)? {
                continue;
            }
            chosen = Some(match &p.weight {
                None => index,
                Some(_) => self.choose_weighted(rules, &candidates[k..], src, i, num_it)?,
            });
            break;
        }
        let Some(index) = chosen else {
            dst.push(id, src.params_of(i));
            return Ok(None);
        };
        let p = &rules.productions[index as usize];
        if p.successor.iter().all(|s| s.group.is_none()) {
            // The hot path: no control modules in this successor.
            for s in &p.successor {
                dst.ids.push(s.id);
                if model.parametric {
                    for a in &s.args {
                        let v = self.eval(a, p.slots, num_it, true)?;
                        dst.params.push(v);
                    }
                    dst.offsets.push(dst.params.len() as u32);
                }
            }
        } else {
            self.emit(&p.successor, p.slots, num_it, dst)?;
        }
        if dst.len() > model.settings.max_modules {
            return Err(limit_error(model, num_it, dst.len()));
        }
        Ok(Some(index))
    }

    /// Derives the control module group whose header is at `i` (LANGUAGE.md section 7) and returns
    /// the index just after its closing marker.
    fn rewrite_group(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        i: usize,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<usize, Diagnostic> {
        let g = self.model.groups;
        // Members: the ranges between the group's own separators.
        let mut members = Vec::new();
        let mut depth = 0usize;
        let mut start = i + 2;
        let mut end = src.len();
        for k in i + 2..src.len() {
            let id = src.ids[k];
            if id == g.open {
                depth += 1;
            } else if id == g.close {
                if depth == 0 {
                    end = k;
                    break;
                }
                depth -= 1;
            } else if id == g.separator && depth == 0 {
                members.push(start..k);
                start = k + 1;
            }
        }
        members.push(start..end);
        let id = src.ids[i];
        let header = src.params_of(i).first().copied().unwrap_or(0.0);
        let n = members.len();
        let write_header = |dst: &mut LString, value: f64| dst.push(id, &[value]);
        if id == g.switch {
            let cursor = (header.max(0.0) as usize) % n;
            write_header(dst, ((cursor + 1) % n) as f64);
            dst.push(g.open, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
            for (k, member) in members.into_iter().enumerate() {
                if k > 0 {
                    dst.push(g.separator, &[]);
                    self.note(dst.len(), i, NOT_REWRITTEN);
                }
                if k == cursor {
                    self.rewrite_range(rules, src, member, dst, num_it)?;
                } else {
                    for j in member {
                        dst.push(src.ids[j], src.params_of(j));
                        self.note(dst.len(), j, NOT_REWRITTEN);
                    }
                }
            }
        } else if id == g.pendulum {
            // As written on odd steps, reversed on even ones.
            let reversed = if num_it.is_multiple_of(2) { 1.0 } else { 0.0 };
            if reversed != header {
                members.reverse();
            }
            write_header(dst, reversed);
            dst.push(g.open, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
            for (k, member) in members.into_iter().enumerate() {
                if k > 0 {
                    dst.push(g.separator, &[]);
                    self.note(dst.len(), i, NOT_REWRITTEN);
                }
                self.rewrite_range(rules, src, member, dst, num_it)?;
            }
        } else {
            // @Repeat(k): the enclosed string is derived k times within this step.
            let times = header.max(0.0) as u32;
            write_header(dst, header);
            dst.push(g.open, &[]);
            self.note(dst.len(), i, NOT_REWRITTEN);
            // The k inner derivations are not tracked: their modules count as the group's. The
            // growth plan names modules of the step's string, not of the group's.
            let tracker = self.tracker.take();
            let plan = self.plan.take();
            let member = members.swap_remove(0);
            let mut current = LString::default();
            current.clear(src.is_parametric());
            for j in member {
                current.push(src.ids[j], src.params_of(j));
            }
            let mut next = LString::default();
            let saved = std::mem::take(&mut self.partner);
            for _ in 0..times {
                if rules.has_contexts() {
                    context::bracket_partners(self.model, &current, &mut self.partner);
                }
                next.clear(current.is_parametric());
                let len = current.len();
                self.rewrite_range(rules, &current, 0..len, &mut next, num_it)?;
                std::mem::swap(&mut current, &mut next);
                if current.len() > self.model.settings.max_modules {
                    return Err(limit_error(self.model, num_it, current.len()));
                }
            }
            self.partner = saved;
            self.tracker = tracker;
            self.plan = plan;
            for j in 0..current.len() {
                dst.push(current.ids[j], current.params_of(j));
            }
            self.note(dst.len(), i, NOT_REWRITTEN);
        }
        dst.push(g.close, &[]);
        Ok((end + 1).min(src.len()))
    }

    /// Draws among the matching weighted productions in `candidates` (the first of which matched
    /// already), in proportion to their weights; leaves the chosen one's slots bound.
    fn choose_weighted(
        &mut self,
        rules: &RuleSet,
        candidates: &[u32],
        src: &LString,
        i: usize,
        num_it: u32,
    ) -> Result<u32, Diagnostic> {
        self.weighted.clear();
        let mut total = 0.0;
        for (k, &index) in candidates.iter().enumerate() {
            let p = &rules.productions[index as usize];
            let Some(weight) = &p.weight else { continue };
            if k > 0 && !self.matches(p, src, i, num_it)? {
                continue;
            }
            let w = self.eval(weight, p.slots, num_it, false)?;
            if w < 0.0 {
                return Err(negative_weight(weight.span.clone(), w));
            }
            total += w;
            self.weighted
                .push((index, w, self.slots[..p.slots].to_vec()));
        }
        let mut r = self.rng.random::<f64>() * total;
        let mut pick = self.weighted.len() - 1;
        for (k, (_, w, _)) in self.weighted.iter().enumerate() {
            if r < *w {
                pick = k;
                break;
            }
            r -= w;
        }
        let (index, _, slots) = &self.weighted[pick];
        self.slots[..slots.len()].copy_from_slice(slots);
        Ok(*index)
    }
}

fn negative_weight(span: Span, w: f64) -> Diagnostic {
    Diagnostic::error(
        "E0513",
        span,
        format!("a weight cannot be negative (it is {w} here)"),
    )
}

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
