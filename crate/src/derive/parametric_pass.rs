//! The parametric pass: the productions section of a parametric grammar without control modules,
//! unplanned, each module rewritten as its class says ([`super::parametric_classes`]): templates
//! written straight into the output, sized before the step when no class is general.

use super::parametric_classes::{write_affine, Arg, ParametricClasses, ParametricKind, Template};
use super::rewriter::{Pass, Rewriter};
use super::successors::{put, put_wide, PAD};
use super::{check_size, NOT_REWRITTEN};
use crate::diagnostics::Diagnostic;
use crate::model::LString;
use std::mem::MaybeUninit;

impl<R: rand::Rng> Rewriter<'_, R> {
    /// [`Rewriter::rewrite_range`] over the whole string, each module as its class says: the
    /// productions section of a parametric grammar without control modules, unplanned.
    pub(super) fn rewrite_parametric(
        &mut self,
        c: &mut ParametricClasses,
        pass: &Pass<'_>,
        dst: &mut LString,
    ) -> Result<bool, Diagnostic> {
        match c.width {
            4 => self.rewrite_parametric_as::<4>(c, pass, dst),
            8 => self.rewrite_parametric_as::<8>(c, pass, dst),
            PAD => self.rewrite_parametric_as::<PAD>(c, pass, dst),
            _ => self.rewrite_parametric_as::<0>(c, pass, dst),
        }
    }

    /// [`Rewriter::rewrite_parametric`], each template's ids copied as `W` ids ([`put_wide`]; 0:
    /// as many as it has).
    #[inline(never)]
    fn rewrite_parametric_as<const W: usize>(
        &mut self,
        c: &mut ParametricClasses,
        pass: &Pass<'_>,
        dst: &mut LString,
    ) -> Result<bool, Diagnostic> {
        let Pass { src, num_it, .. } = *pass;
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
                return self.rewrite_range(pass, 0..src.len(), dst);
            }
            reserve(&mut dst.ids, len + PAD);
            reserve(&mut dst.offsets, len + 1);
            // Two more: the sized path copies parameters two at a time.
            reserve(&mut dst.params, params + 2);
            sized = true;
            if self.tracker.is_none() {
                let (changed, next) =
                    self.rewrite_parametric_sized::<W>(c, (src, num_it), dst, (len, params))?;
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
                ParametricKind::Template if to - from == class.arity as usize => {
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
                ParametricKind::Copy => {
                    copy(src, i, dst);
                    NOT_REWRITTEN
                }
                ParametricKind::Template => {
                    copy(src, i, dst);
                    NOT_REWRITTEN
                }
                ParametricKind::General => {
                    let applied = self.rewrite_module(pass, i, dst)?;
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
    /// when the output is its input as it is: [`ParametricClasses::carries`]). It reads only the
    /// pass's string and step, so it takes them, not the [`Pass`]: taking the Pass, eq. 1.9
    /// (n = 16) derived about 5% slower in V8 (measured 2026-11-29).
    #[inline(never)]
    fn rewrite_parametric_sized<const W: usize>(
        &mut self,
        c: &ParametricClasses,
        (src, num_it): (&LString, u32),
        dst: &mut LString,
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
        c: &ParametricClasses,
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
