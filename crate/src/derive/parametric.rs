//! Per-module classes for strings with parameters: the general path's table for parametric
//! grammars, decided once per derivation.
//!
//! For each module id:
//! - [`Kind::Copy`]: no production: the module is copied, parameters and all;
//! - [`Kind::Template`]: its first production has no context, condition or weight, and its
//!   successor no control module: when the module has the predecessor's arity, it always applies,
//!   and its successor is a template: the ids and the offsets are copied, each argument is written
//!   straight into the parameters, the simple ones ([`Simple`]: a constant, a parameter, one
//!   operator) without the interpreter, those of the form parameter `*` or `+` constant
//!   ([`Affine`], `#define` constants folded) without reading the slots;
//! - [`Kind::General`]: anything else, matched by the general path module by module.
//!
//! The output is sized before the step when no module is general, so the buffers never grow:
//! counted in a pass of its own on the first step, then carried (each step counts the size of the
//! next while writing) as long as nothing rewrites the string between steps (no decomposition,
//! no cut).

use super::classes::{put, put_wide, width, PAD};
use super::rewriter::Rewriter;
use super::{check_size, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::{LString, Model, ModuleId, Program, RuleSet, Simple};
use std::mem::MaybeUninit;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Copy,
    Template,
    General,
}

/// One module id's class.
#[derive(Clone, Copy, Debug)]
pub(super) struct Class {
    pub kind: Kind,
    /// Template: the predecessor's arity; the module matches when it has that many parameters.
    pub arity: u32,
    /// Template: its index in [`Classes::templates`].
    pub template: u32,
}

/// One argument of a template's successor.
#[derive(Clone, Debug)]
pub(super) enum Arg {
    /// Evaluated without the interpreter (when its value is finite).
    Simple(Simple, u32),
    /// Evaluated by the interpreter: the index of the program in [`Template::programs`].
    Program(u32),
}

/// A production's successor, ready to be written.
#[derive(Clone, Debug)]
pub(super) struct Template {
    pub production: u32,
    /// The first slot of the predecessor's parameters, and how many slots the production binds.
    pub first_slot: usize,
    pub slots: usize,
    pub ids: Vec<ModuleId>,
    /// The same ids in [`Classes::successors`], from `start`.
    pub start: u32,
    /// For each successor module, the parameters written up to and including it.
    pub ends: Vec<u32>,
    pub args: Vec<Arg>,
    pub programs: Vec<Program>,
    /// Every argument as an [`Affine`], when each is one and the predecessor has at most
    /// [`AFFINE_ARITY`] parameters: the successor is then written without the slots.
    pub affine: Option<Vec<Affine>>,
    /// What the successor adds to the size of the step after (modules, parameters): each of its
    /// modules as its own class will rewrite it ([`Classes::output_size`]).
    pub next_len: usize,
    pub next_params: usize,
}

/// The most parameters a predecessor may have for its successor's arguments to be [`Affine`].
const AFFINE_ARITY: usize = 3;

/// An argument `x[slot] * k + c`, where `x` holds the predecessor's parameters and then zeros
/// (`slot` [`AFFINE_ARITY`] is always zero). Equal bit for bit to [`Simple::eval`] for the shapes
/// it takes ([`Affine::new`]): `x * 1` and `x + (-0.0)` are `x`, `a - b` is `a + (-b)`, and
/// `0 * k + c` is `c` when `k` has `c`'s sign. No fused multiply-add: Rust never contracts.
#[derive(Clone, Copy, Debug)]
pub(super) struct Affine {
    slot: usize,
    k: f64,
    c: f64,
}

impl Affine {
    /// The affine form of `e`, whose slots are the predecessor's, from `first`; `None` for a
    /// division or two parameters.
    fn new(e: Simple, first: u16, arity: usize) -> Option<Affine> {
        use crate::syntax::BinaryOp::{Add, Mul, Sub};
        let at = |s: u16| {
            let k = s.checked_sub(first)? as usize;
            (k < arity).then_some(k)
        };
        Some(match e {
            Simple::Const(c) => Affine {
                slot: AFFINE_ARITY,
                k: 0.0f64.copysign(c),
                c,
            },
            Simple::Slot(s) => Affine {
                slot: at(s)?,
                k: 1.0,
                c: -0.0,
            },
            Simple::SlotConst(Mul, s, c) | Simple::ConstSlot(Mul, c, s) => Affine {
                slot: at(s)?,
                k: c,
                c: -0.0,
            },
            Simple::SlotConst(Add, s, c) | Simple::ConstSlot(Add, c, s) => Affine {
                slot: at(s)?,
                k: 1.0,
                c,
            },
            Simple::SlotConst(Sub, s, c) => Affine {
                slot: at(s)?,
                k: 1.0,
                c: -c,
            },
            Simple::ConstSlot(Sub, c, s) => Affine {
                slot: at(s)?,
                k: -1.0,
                c,
            },
            _ => return None,
        })
    }

    #[inline(always)]
    fn eval(self, x: &[f64; AFFINE_ARITY + 1]) -> f64 {
        x[self.slot & AFFINE_ARITY] * self.k + self.c
    }
}

/// The classes of the productions section of a parametric grammar.
pub(super) struct Classes {
    pub classes: Vec<Class>,
    pub templates: Vec<Template>,
    /// Every template's ids, back to back, then [`PAD`] ids of padding for [`put`].
    pub successors: Vec<ModuleId>,
    /// True when some class is general: the output's size is not known before the step.
    pub general: bool,
    /// The copy width for the templates' ids ([`width`]).
    pub width: usize,
    /// The most arguments a template's successor has.
    pub most_args: usize,
    /// For each module id, the arity a module must have to be rewritten by its template
    /// (`u32::MAX` for a class that is not a template: no module has that many).
    pub matches: Vec<u32>,
    /// True when the string a step writes is the next step's input as it is (no decomposition,
    /// no cut): the size of the next step can be carried.
    carries: bool,
    /// After a sized step: the string it wrote (modules, parameters) and the size of the step
    /// after it.
    carried: Option<[usize; 4]>,
}

impl Classes {
    /// The classes of `model`'s productions, when its strings have parameters and no control
    /// module groups.
    pub fn new(model: &Model) -> Option<Classes> {
        if !model.parametric || model.has_groups {
            return None;
        }
        let rules = &model.productions;
        let mut classes = Classes {
            classes: Vec::with_capacity(model.alphabet.len()),
            templates: Vec::new(),
            successors: Vec::new(),
            general: false,
            width: 0,
            most_args: 0,
            matches: Vec::new(),
            carries: model.decomposition.is_empty() && !super::cut::contains_cut(model),
            carried: None,
        };
        for index in 0..model.alphabet.len() {
            let candidates = rules
                .by_predecessor
                .get(index)
                .map_or(&[][..], Vec::as_slice);
            let class = classes.classify(rules, candidates);
            classes.general |= class.kind == Kind::General;
            classes.classes.push(class);
        }
        let longest = classes.templates.iter().map(|t| t.ids.len()).max();
        classes.width = width(longest.unwrap_or(0));
        classes.most_args = classes
            .templates
            .iter()
            .map(|t| t.args.len())
            .max()
            .unwrap_or(0);
        classes
            .successors
            .extend(std::iter::repeat_n(ModuleId(0), PAD));
        classes.matches = classes
            .classes
            .iter()
            .map(|c| match c.kind {
                Kind::Template => c.arity,
                _ => u32::MAX,
            })
            .collect();
        for k in 0..classes.templates.len() {
            let p = &rules.productions[classes.templates[k].production as usize];
            let (mut len, mut params) = (0, 0);
            for m in &p.successor {
                let class = &classes.classes[m.id.index()];
                if class.kind == Kind::Template && class.arity as usize == m.args.len() {
                    let t = &classes.templates[class.template as usize];
                    len += t.ids.len();
                    params += t.args.len();
                } else {
                    len += 1;
                    params += m.args.len();
                }
            }
            let t = &mut classes.templates[k];
            (t.next_len, t.next_params) = (len, params);
        }
        Some(classes)
    }

    fn classify(&mut self, rules: &RuleSet, candidates: &[u32]) -> Class {
        let general = Class {
            kind: Kind::General,
            arity: 0,
            template: 0,
        };
        let Some(&first) = candidates.first() else {
            return Class {
                kind: Kind::Copy,
                ..general
            };
        };
        let p = &rules.productions[first as usize];
        // With one production, a module of another arity matches none and is copied; with more,
        // a later one may match it: the general path tries them.
        if candidates.len() > 1
            || p.has_context()
            || p.condition.is_some()
            || p.weight.is_some()
            || p.successor.iter().any(|s| s.group.is_some())
        {
            return general;
        }
        let mut template = Template {
            production: first,
            first_slot: p.predecessor.first_slot as usize,
            slots: p.slots,
            ids: Vec::with_capacity(p.successor.len()),
            start: self.successors.len() as u32,
            ends: Vec::with_capacity(p.successor.len()),
            args: Vec::new(),
            programs: Vec::new(),
            affine: None,
            next_len: 0,
            next_params: 0,
        };
        for s in &p.successor {
            template.ids.push(s.id);
            for a in &s.args {
                let simple = a
                    .simple()
                    .filter(|e| e.max_slot().is_none_or(|k| (k as usize) < p.slots));
                let program = template.programs.len() as u32;
                template.programs.push(a.clone());
                template.args.push(match simple {
                    Some(e) => Arg::Simple(e, program),
                    None => Arg::Program(program),
                });
            }
            template.ends.push(template.args.len() as u32);
        }
        let arity = p.predecessor.arity;
        template.affine = template
            .args
            .iter()
            .map(|a| match a {
                Arg::Simple(e, _) if arity <= AFFINE_ARITY => {
                    Affine::new(*e, p.predecessor.first_slot, arity)
                }
                _ => None,
            })
            .collect();
        self.successors.extend_from_slice(&template.ids);
        self.templates.push(template);
        Class {
            kind: Kind::Template,
            arity: p.predecessor.arity as u32,
            template: (self.templates.len() - 1) as u32,
        }
    }

    /// The length and the parameter count of the string the step makes from `src`, when no
    /// module is general (every module then rewrites as its class says).
    fn output_size(&self, src: &LString) -> Option<(usize, usize)> {
        if self.general {
            return None;
        }
        let (mut len, mut params) = (0usize, 0usize);
        for (i, &id) in src.ids.iter().enumerate() {
            let class = &self.classes[id.index()];
            let own = (src.offsets[i + 1] - src.offsets[i]) as usize;
            if class.kind == Kind::Template && own == class.arity as usize {
                let t = &self.templates[class.template as usize];
                len += t.ids.len();
                params += t.args.len();
            } else {
                len += 1;
                params += own;
            }
        }
        Some((len, params))
    }
}

impl<R: rand::Rng> Rewriter<'_, R> {
    /// [`Rewriter::rewrite_range`] over the whole string, each module as its class says: the
    /// productions section of a parametric grammar without control modules, unplanned.
    pub(super) fn rewrite_parametric(
        &mut self,
        c: &mut Classes,
        rules: &RuleSet,
        src: &LString,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        match c.width {
            4 => self.rewrite_parametric_as::<4>(c, rules, src, dst, num_it),
            8 => self.rewrite_parametric_as::<8>(c, rules, src, dst, num_it),
            PAD => self.rewrite_parametric_as::<PAD>(c, rules, src, dst, num_it),
            _ => self.rewrite_parametric_as::<0>(c, rules, src, dst, num_it),
        }
    }

    /// [`Rewriter::rewrite_parametric`], each template's ids copied as `W` ids ([`put_wide`]; 0:
    /// as many as it has).
    #[inline(never)]
    fn rewrite_parametric_as<const W: usize>(
        &mut self,
        c: &mut Classes,
        rules: &RuleSet,
        src: &LString,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<bool, Diagnostic> {
        let model = self.model;
        // Sized before the step: no module can pass a limit on the way.
        let mut sized = false;
        let carried = match c.carried.take() {
            Some([l, n, len, params]) if (l, n) == (src.len(), src.params.len()) => {
                Some((len, params))
            }
            _ => c.output_size(src),
        };
        if let Some((len, params)) = carried {
            // As LString::bytes counts them: an id and an offset a module, one offset more.
            let bytes = len * 8 + 4 + params * size_of::<f64>();
            if check_size(model, num_it, len, bytes).is_err() {
                // Past a limit: the general path says where, as it always has.
                return self.rewrite_range(rules, src, 0..src.len(), dst, num_it);
            }
            reserve(&mut dst.ids, len + PAD);
            reserve(&mut dst.offsets, len + 1);
            // Two more: the sized path copies parameters two at a time.
            reserve(&mut dst.params, params + 2);
            sized = true;
            if self.tracker.is_none() {
                let (changed, next) =
                    self.rewrite_parametric_sized::<W>(c, src, dst, num_it, (len, params))?;
                if c.carries {
                    c.carried = Some([len, params, next.0, next.1]);
                }
                return Ok(changed);
            }
        }
        let tracking = self.tracker.is_some();
        let random_vars = !self.vars.is_empty();
        let mut changed = false;
        for (i, &id) in src.ids.iter().enumerate() {
            let class = &c.classes[id.index()];
            let (from, to) = (src.offsets[i] as usize, src.offsets[i + 1] as usize);
            let production = match class.kind {
                Kind::Template if to - from == class.arity as usize => {
                    let t = &c.templates[class.template as usize];
                    if random_vars {
                        self.vars.iter_mut().for_each(|v| *v = None);
                    }
                    self.slots[t.first_slot..t.first_slot + (to - from)]
                        .copy_from_slice(&src.params[from..to]);
                    self.write_template::<W>(c, t, dst, num_it)?;
                    if !sized {
                        check_size(model, num_it, dst.len(), dst.bytes())?;
                    }
                    changed = true;
                    t.production
                }
                Kind::Copy => {
                    copy(src, i, dst);
                    NOT_REWRITTEN
                }
                Kind::Template => {
                    copy(src, i, dst);
                    NOT_REWRITTEN
                }
                Kind::General => {
                    let applied = self.rewrite_module(rules, src, i, dst, num_it)?;
                    changed |= applied.is_some();
                    applied.unwrap_or(NOT_REWRITTEN)
                }
            };
            if tracking {
                self.note(dst.len(), i, production);
            }
        }
        Ok(changed)
    }

    /// [`Rewriter::rewrite_parametric_as`] when the output's `size` (modules, parameters) is known
    /// and nothing is tracked: the output is laid out first, then every module written in place.
    /// Returns whether a module was rewritten, and the size of the step after this one (valid
    /// when the output is its input as it is: [`Classes::carries`]).
    #[inline(never)]
    fn rewrite_parametric_sized<const W: usize>(
        &mut self,
        c: &Classes,
        src: &LString,
        dst: &mut LString,
        num_it: u32,
        (len, params): (usize, usize),
    ) -> Result<(bool, (usize, usize)), Diagnostic> {
        // Written in place into the buffers' spare room (reserved by the caller, with room for
        // the over-copy of W ids past the last module), then the lengths set once all is written:
        // no zeroing first, no capacity check per module.
        debug_assert!(dst.ids.is_empty() && dst.offsets.len() == 1 && dst.params.is_empty());
        let mut buffer = vec![0.0; c.most_args];
        let ids = &mut dst.ids.spare_capacity_mut()[..len + PAD];
        // offsets[k]: the offset after module k (the first, 0, is already there).
        let offsets = &mut dst.offsets.spare_capacity_mut()[..len];
        let values = &mut dst.params.spare_capacity_mut()[..params + 2];
        let (mut o, mut p) = (0usize, 0usize);
        // The size of the step after: this one's, each applied template's successor counted as
        // it will be rewritten (wrapping: a successor may shrink).
        let (mut next_len, mut next_params) = (len, params);
        let mut changed = false;
        let mut from = src.offsets[0] as usize;
        for (&id, &to) in src.ids.iter().zip(&src.offsets[1..]) {
            let (from_own, to) = (from, to as usize);
            let own = &src.params[from..to];
            from = to;
            if c.matches[id.index()] != own.len() as u32 {
                // Copied (a template of another arity matches nothing), and copied again in the
                // step after (no class is general here): its size there is its size here.
                ids[o].write(id);
                copy_params(&src.params, from_own, own, values, p);
                p += own.len();
                offsets[o].write(p as u32);
                o += 1;
                continue;
            }
            let t = &c.templates[c.classes[id.index()].template as usize];
            let n = t.ids.len();
            let start = t.start as usize;
            let wide = if W == 0 { n } else { W };
            for (out, s) in ids[o..o + wide]
                .iter_mut()
                .zip(&c.successors[start..start + wide])
            {
                out.write(*s);
            }
            for (out, &end) in offsets[o..o + n].iter_mut().zip(&t.ends) {
                out.write(p as u32 + end);
            }
            let m = t.args.len();
            let out = &mut values[p..p + m];
            let written = match &t.affine {
                Some(affine) => write_affine(affine, own, out),
                None => false,
            };
            if !written {
                self.evaluate_template(t, own, &mut buffer[..m], num_it)?;
                for (out, v) in out.iter_mut().zip(&buffer[..m]) {
                    out.write(*v);
                }
            }
            o += n;
            p += m;
            // The step after: this successor's size there instead of its size here.
            next_len = next_len.wrapping_add(t.next_len.wrapping_sub(n));
            next_params = next_params.wrapping_add(t.next_params.wrapping_sub(m));
            changed = true;
        }
        assert_eq!((o, p), (len, params), "the step's size was computed before");
        // SAFETY: modules 0..len, offsets 1..=len and parameters 0..params were all written
        // above, in order (o and p count what was written); the capacities hold them.
        unsafe {
            dst.ids.set_len(len);
            dst.offsets.set_len(len + 1);
            dst.params.set_len(params);
        }
        Ok((changed, (next_len, next_params)))
    }

    /// Evaluates template `t`'s arguments into `evaluated`, the predecessor's parameters `own`
    /// bound: the simple ones without the interpreter, the others (and the simple ones that were
    /// not finite) with it. Out of line: the sized loop keeps its registers.
    #[inline(never)]
    fn evaluate_template(
        &mut self,
        t: &Template,
        own: &[f64],
        evaluated: &mut [f64],
        num_it: u32,
    ) -> Result<(), Diagnostic> {
        if !self.vars.is_empty() {
            self.vars.iter_mut().for_each(|v| *v = None);
        }
        self.slots[t.first_slot..t.first_slot + own.len()].copy_from_slice(own);
        let slots = &self.slots[..t.slots];
        let mut retry = false;
        for (out, arg) in evaluated.iter_mut().zip(&t.args) {
            match arg {
                Arg::Simple(e, _) => {
                    *out = e.eval(slots);
                    retry |= !out.is_finite();
                }
                Arg::Program(_) => retry = true,
            }
        }
        if retry {
            self.evaluate_again(t, evaluated, num_it)?;
        }
        Ok(())
    }

    /// Evaluates with the interpreter, in order, the arguments of template `t` that it must
    /// evaluate (the programs, and the simple ones that were not finite, which it reports):
    /// a random argument draws as it always has.
    fn evaluate_again(
        &mut self,
        t: &Template,
        written: &mut [f64],
        num_it: u32,
    ) -> Result<(), Diagnostic> {
        for (k, arg) in t.args.iter().enumerate() {
            let program = match arg {
                Arg::Simple(_, p) if !written[k].is_finite() => p,
                Arg::Simple(..) => continue,
                Arg::Program(p) => p,
            };
            written[k] = self.eval(&t.programs[*program as usize], t.slots, num_it, true)?;
        }
        Ok(())
    }

    /// Writes template `t`'s successor onto `dst`, the production's slots bound.
    #[inline]
    fn write_template<const W: usize>(
        &mut self,
        c: &Classes,
        t: &Template,
        dst: &mut LString,
        num_it: u32,
    ) -> Result<(), Diagnostic> {
        if W == 0 {
            put(&mut dst.ids, &c.successors, t.start as usize, t.ids.len());
        } else {
            put_wide::<W>(&mut dst.ids, &c.successors, t.start as usize, t.ids.len());
        }
        let base = dst.params.len() as u32;
        dst.offsets.extend(t.ends.iter().map(|&e| base + e));
        let at = dst.params.len();
        dst.params.resize(at + t.args.len(), 0.0);
        let slots = &self.slots[..t.slots];
        let mut retry = false;
        for (out, arg) in dst.params[at..].iter_mut().zip(&t.args) {
            match arg {
                Arg::Simple(e, _) => {
                    *out = e.eval(slots);
                    retry |= !out.is_finite();
                }
                Arg::Program(_) => retry = true,
            }
        }
        if retry {
            self.evaluate_again(t, &mut dst.params[at..], num_it)?;
        }
        Ok(())
    }
}

/// Writes the arguments `affine` of a template into `out`, the predecessor's parameters `own`
/// bound; false (with `out` partly written) when a value is not finite: the interpreter must
/// evaluate them and report it.
#[inline(always)]
fn write_affine(affine: &[Affine], own: &[f64], out: &mut [MaybeUninit<f64>]) -> bool {
    let x = match *own {
        [] => [0.0; AFFINE_ARITY + 1],
        [a] => [a, 0.0, 0.0, 0.0],
        [a, b] => [a, b, 0.0, 0.0],
        [a, b, c] => [a, b, c, 0.0],
        _ => return false,
    };
    let mut finite = true;
    for (out, a) in out.iter_mut().zip(affine) {
        let v = a.eval(&x);
        finite &= v.is_finite();
        out.write(v);
    }
    finite
}

/// Writes a copied module's parameters `own` (at `from` in `params`) to `values` at `p`. Most
/// modules have two parameters or fewer: two are copied, in one move, when there is room on both
/// sides (the second one is overwritten next).
#[inline(always)]
fn copy_params(
    params: &[f64],
    from: usize,
    own: &[f64],
    values: &mut [MaybeUninit<f64>],
    p: usize,
) {
    match (params.get(from..from + 2), values.get_mut(p..p + 2)) {
        (Some(&[a, b]), Some([x, y])) if own.len() <= 2 => {
            x.write(a);
            y.write(b);
        }
        _ => copy_rest(own, values, p),
    }
}

/// [`copy_values`] out of line: the sized loop's rare case (the last module, or more than two
/// parameters).
#[inline(never)]
#[cold]
fn copy_rest(own: &[f64], values: &mut [MaybeUninit<f64>], p: usize) {
    copy_values(own, values, p);
}

/// Writes the parameters `own` into `values` from `p`; returns where they end.
#[inline(always)]
fn copy_values(own: &[f64], values: &mut [MaybeUninit<f64>], p: usize) -> usize {
    // Most modules have a parameter or two: no call to a copy of any length for them.
    match own {
        [] => {}
        [a] => {
            values[p].write(*a);
        }
        [a, b] => {
            values[p].write(*a);
            values[p + 1].write(*b);
        }
        more => {
            for (out, v) in values[p..p + more.len()].iter_mut().zip(more) {
                out.write(*v);
            }
        }
    }
    p + own.len()
}

/// Copies module `i` of `src` onto `dst`, parameters and all.
#[inline(always)]
fn copy(src: &LString, i: usize, dst: &mut LString) {
    dst.ids.push(src.ids[i]);
    let (from, to) = (src.offsets[i] as usize, src.offsets[i + 1] as usize);
    // Most modules have a parameter or two: no call to a copy of any length for them.
    match &src.params[from..to] {
        [] => {}
        [a] => dst.params.push(*a),
        [a, b] => {
            dst.params.push(*a);
            dst.params.push(*b);
        }
        more => dst.params.extend_from_slice(more),
    }
    dst.offsets.push(dst.params.len() as u32);
}

/// Makes room for `len` items in the empty `v`: a new buffer when it lacks room (growing the old
/// one would copy what it held).
fn reserve<T>(v: &mut Vec<T>, len: usize) {
    if v.capacity() < len {
        let mut fresh = Vec::new();
        fresh.reserve_exact(len);
        // Keep what was written (the first offset of a cleared parametric string).
        fresh.append(v);
        *v = fresh;
    }
}
