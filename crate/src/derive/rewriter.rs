//! The general path: productions tried in source order for each module, with bracket-aware
//! contexts, compiled conditions, weighted (stochastic) choice and Green's random variables.

use super::context::{self, Recorder};
use super::fixed_pass::Counts;
use super::module_classes::ModuleClasses;
use super::parametric_classes::ParametricClasses;
use super::{check_size, Observer, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{Env, LString, Model, Production, Program, RuleSet, SuccessorModule};
use crate::syntax::Span;
use rand::RngExt;
use std::mem::take;

/// Where each module written by a tracked pass comes from.
#[derive(Default)]
pub(super) struct Tracker {
    /// For each module written, the index of the source module it was rewritten from.
    pub parent: Vec<u32>,
    /// For each module written, the production applied ([`NOT_REWRITTEN`] for a copy).
    pub origin: Vec<u32>,
}

impl Tracker {
    /// Annotates every module written since the last call.
    pub fn fill(&mut self, len: usize, parent: usize, origin: u32) {
        while self.parent.len() < len {
            self.parent.push(parent as u32);
            self.origin.push(origin);
        }
    }
}

/// What one parallel rewriting reads: the rules it applies, the string it rewrites and the step
/// (`num_it`, the number the expressions see). The passes and their helpers take it by reference
/// beside the module index and the output they write.
#[derive(Clone, Copy)]
pub(super) struct Pass<'a> {
    pub rules: &'a RuleSet,
    pub src: &'a LString,
    pub num_it: u32,
}

/// The general path's working state, reused across modules and steps.
pub(super) struct Rewriter<'m, R: rand::Rng> {
    pub model: &'m Model,
    pub rng: &'m mut R,
    max_it: f64,
    /// The formal parameters bound while matching.
    pub slots: Vec<f64>,
    /// The deviates of the `#random` variables for the module being matched.
    pub vars: Vec<Option<f64>>,
    /// For each bracket of the string being rewritten, its partner (for contexts).
    pub partner: Vec<u32>,
    /// Matching weighted productions of the current module: (production, weight, bound slots).
    weighted: Vec<(u32, f64, Vec<f64>)>,
    /// Provenance of the pass being run, when tracking.
    pub tracker: Option<Tracker>,
    /// During a step's productions pass, when the observer planned it: how many times each module
    /// of the string is rewritten (0: not at all, 1: as usual, more: repeatedly).
    pub plan: Option<Vec<u32>>,
    /// How many control module groups the range being rewritten is inside.
    pub group_depth: usize,
    /// The `@Repeat` rewritings run so far in this derivation, against [`Rewriter::repeat_budget`].
    pub repeat_passes: u64,
    /// The productions' classes, for strings without parameters.
    classes: Option<ModuleClasses>,
    /// The productions' classes, for strings with parameters.
    parametric: Option<ParametricClasses>,
    /// Whether `classes` and `parametric` are built: on the first productions pass, so that a
    /// derivation the D0L path runs alone (`super::d0l`) never builds them.
    classes_built: bool,
    /// Scratch of a classes pass: each module's right neighbour, and a stack of neighbours.
    right: Vec<u32>,
    stack: Vec<u32>,
    /// The id counts of the string the last Fixed/Choice pass wrote ([`Counts`]).
    pub counts: Counts,
    /// True when nothing changes the string between steps (no decomposition, no cut), so the
    /// counts of one pass's output are those of the next pass's input.
    carried: bool,
}

impl<'m, R: rand::Rng> Rewriter<'m, R> {
    pub fn new(model: &'m Model, steps: u32, rng: &'m mut R) -> Self {
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
            partner: Vec::new(),
            weighted: Vec::new(),
            tracker: None,
            plan: None,
            group_depth: 0,
            repeat_passes: 0,
            classes: None,
            parametric: None,
            classes_built: false,
            right: Vec::new(),
            stack: Vec::new(),
            counts: Counts::default(),
            carried: model.decomposition.is_empty() && !super::cut::contains_cut(model),
        }
    }

    pub fn eval(
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
            variables: &self.model.random_variables,
            rng: &mut *self.rng,
        };
        program
            .eval(&mut env)
            .map_err(|e| e.into_diagnostic(&format!(" (at step {num_it})")))
    }

    pub fn axiom(&mut self) -> Result<LString, Diagnostic> {
        let mut s = LString::default();
        let model = self.model;
        if !model.parametric {
            // No parameters, so no control modules: the axiom's ids are its string.
            s.ids = model.axiom_ids.clone();
            return Ok(s);
        }
        s.clear(true);
        self.emit(&model.axiom, 0, 0, &mut s)?;
        Ok(s)
    }

    /// Appends successor modules, evaluating their arguments with the first `slots` slots bound;
    /// a control module writes its header and its members between markers.
    pub fn emit(
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
                    if s.id == model.groups.repeat {
                        self.check_repeat_count(value, s)?;
                    }
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

    /// Applies decomposition rules to `s` until nothing changes. When tracking, returns for each
    /// module of the result the index of the module of the input it comes from.
    pub fn decompose(
        &mut self,
        s: &mut LString,
        scratch: &mut LString,
        step: u32,
        observer: &mut dyn Observer,
    ) -> Result<Option<Vec<u32>>, Diagnostic> {
        let model = self.model;
        let rules = &model.decomposition;
        let mut parents: Option<Vec<u32>> =
            self.tracker.as_ref().map(|_| (0..s.len() as u32).collect());
        for _ in 0..rules.max_depth {
            if !self.pass(rules, s, scratch, step)? {
                return Ok(parents);
            }
            self.followed(scratch, None, step, observer)?;
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

    /// Tells the observer, when it follows every module, what the pass just run wrote (`birth`:
    /// the step of a productions pass, `None` for decomposition, which finishes its parents' step).
    /// `E0401` when their states would pass [`super::limits::MAX_FOLLOWED_BYTES`], before the
    /// observer allocates them (`step`: the step the pass belongs to).
    pub fn followed(
        &mut self,
        written: &LString,
        birth: Option<u32>,
        step: u32,
        observer: &mut dyn Observer,
    ) -> Result<(), Diagnostic> {
        super::limits::check_followed(self.model, step, written.len())?;
        if let Some(t) = &self.tracker {
            let written = super::Written {
                string: written,
                parent: &t.parent,
                origin: &t.origin,
                birth,
            };
            observer.followed(&written, &mut *self.rng);
        }
        Ok(())
    }

    /// Tests production `p` on module `i` of `src`, binding its slots.
    #[inline]
    pub fn matches(
        &mut self,
        p: &Production,
        src: &LString,
        i: usize,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        let (contexts, condition) = self.matches_recording(p, src, i, num_it, &mut (), &mut ())?;
        Ok(contexts && condition)
    }

    /// [`Rewriter::matches`], recording the indices of the context modules it matched in `left`
    /// and `right`: returns whether the predecessor and contexts matched, and whether the
    /// condition then held (false when they did not match). Derivation records nothing (`()`).
    #[inline]
    pub(super) fn matches_recording<C: Recorder>(
        &mut self,
        p: &Production,
        src: &LString,
        i: usize,
        num_it: u32,
        left: &mut C,
        right: &mut C,
    ) -> Result<(bool, bool), Diagnostic> {
        let params = src.params_of(i);
        if params.len() != p.predecessor.arity {
            return Ok((false, false));
        }
        let first = p.predecessor.first_slot as usize;
        self.slots[first..first + params.len()].copy_from_slice(params);
        let model = self.model;
        if !p.left.is_empty()
            && !context::match_left(model, src, &self.partner, i, &p.left, &mut self.slots, left)
        {
            return Ok((false, false));
        }
        if !p.right.is_empty()
            && !context::match_right(
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
    pub fn pass(
        &mut self,
        rules: &RuleSet,
        src: &LString,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        let model = self.model;
        // Whatever this pass does, the counts describe its input only if the last pass wrote it.
        let counted = self.counts.len.take();
        self.counts.carried = self.carried && counted == Some(src.len());
        let by_class = self.plan.is_none() && std::ptr::eq(rules, &model.productions);
        if by_class && !self.classes_built {
            self.classes = ModuleClasses::new(model);
            self.parametric = ParametricClasses::new(model);
            self.classes_built = true;
        }
        let classes = if by_class { self.classes.take() } else { None };
        let parametric = if by_class {
            self.parametric.take()
        } else {
            None
        };
        let partners = match &classes {
            Some(c) => c.general_contexts,
            None => rules.has_contexts(),
        };
        if partners {
            context::bracket_partners(model, src, &mut self.partner);
        }
        dst.clear(model.parametric);
        if let Some(t) = &mut self.tracker {
            t.parent.clear();
            t.origin.clear();
        }
        let pass = &Pass { rules, src, num_it };
        match classes {
            Some(c) => {
                let (mut right, mut stack) = (take(&mut self.right), take(&mut self.stack));
                let scratch = (&mut right, &mut stack);
                let changed = self.rewrite_by_class(&c, pass, dst, scratch);
                (self.classes, self.right, self.stack) = (Some(c), right, stack);
                changed
            }
            None => match parametric {
                Some(mut c) => {
                    let changed = self.rewrite_parametric(&mut c, pass, dst);
                    self.parametric = Some(c);
                    changed
                }
                None => self.rewrite_range(pass, 0..src.len(), dst),
            },
        }
    }

    /// Rewrites modules `range` of `src` onto the end of `dst`. Control module groups act only in
    /// the productions section; elsewhere their members are rewritten like any module.
    pub fn rewrite_range(
        &mut self,
        pass: &Pass<'_>,
        range: std::ops::Range<usize>,
        dst: &mut LString,
    ) -> Result<bool, Diagnostic> {
        let Pass { rules, src, .. } = *pass;
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
                i = self.rewrite_group(pass, i, dst)?;
                self.note(dst.len(), i, NOT_REWRITTEN);
                changed = true;
                continue;
            }
            let applied = if planned {
                self.rewrite_planned(pass, i, dst)?
            } else {
                self.rewrite_module(pass, i, dst)?
            };
            self.note(dst.len(), i, applied.unwrap_or(NOT_REWRITTEN));
            changed |= applied.is_some();
            i += 1;
        }
        Ok(changed)
    }

    /// When tracking, annotates the modules written since the last note as coming from `parent`.
    pub fn note(&mut self, len: usize, parent: usize, origin: u32) {
        if let Some(t) = &mut self.tracker {
            t.fill(len, parent, origin);
        }
    }

    /// Rewrites module `i` of `src` onto `dst`; returns the production applied, if any.
    pub fn rewrite_module(
        &mut self,
        pass: &Pass<'_>,
        i: usize,
        dst: &mut LString,
    ) -> Result<Option<u32>, Diagnostic> {
        let Pass { rules, src, num_it } = *pass;
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
                Some(_) => self.choose_weighted(pass, &candidates[k..], i)?,
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
        check_size(model, num_it, dst.len(), dst.bytes())
            .map_err(|e| blame_section(model, rules, p, dst.len(), e))?;
        Ok(Some(index))
    }

    /// Draws among the matching weighted productions in `candidates` (the first of which matched
    /// already), in proportion to their weights; leaves the chosen one's slots bound.
    fn choose_weighted(
        &mut self,
        pass: &Pass<'_>,
        candidates: &[u32],
        i: usize,
    ) -> Result<u32, Diagnostic> {
        let Pass { rules, src, num_it } = *pass;
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
        format!(
            "a weight cannot be negative (it is {} here)",
            crate::number::Decimal(w)
        ),
    )
}

/// A size error (`E0400`, `E0401`) met while a homomorphism or decomposition production wrote:
/// blamed on that production, not on the axiom or `#iterations` (issue 50, 11: a homomorphism
/// of an axiom `F` said "the axiom has 1010 modules"). A productions pass's error is kept.
#[cold]
fn blame_section(
    model: &Model,
    rules: &RuleSet,
    p: &Production,
    len: usize,
    e: Diagnostic,
) -> Diagnostic {
    let section = if std::ptr::eq(rules, &model.homomorphism) {
        "homomorphism"
    } else if std::ptr::eq(rules, &model.decomposition) {
        "decomposition"
    } else {
        return e;
    };
    Diagnostic {
        span: p.span.clone(),
        message: format!(
            "this {section} production makes a string of {len} modules or more, above \
             #max_modules ({}) or the 256 MB one string may take: write fewer modules in its \
             successor (or raise #max_modules)",
            model.settings.max_modules
        ),
        ..e
    }
}
