//! Per-module classes for strings with parameters: the general path's table for parametric
//! grammars, decided once per derivation.
//!
//! For each module id:
//! - [`ParametricKind::Copy`]: no production: the module is copied, parameters and all;
//! - [`ParametricKind::Template`]: its first production has no context, condition or weight, and
//!   its successor no control module: when the module has the predecessor's arity, it always
//!   applies, and its successor is a template: the ids and the offsets are copied, each argument
//!   is written straight into the parameters, the simple ones ([`Simple`]: a constant, a
//!   parameter, one operator) without the interpreter, those of the form parameter `*` or `+`
//!   constant ([`Affine`], `#define` constants folded) without reading the slots;
//! - [`ParametricKind::General`]: anything else, matched by the general path module by module.
//!
//! The output is sized before the step when no module is general, so the buffers never grow:
//! counted in a pass of its own on the first step, then carried (each step counts the size of the
//! next while writing) as long as nothing rewrites the string between steps (no decomposition,
//! no cut).

use super::successors::{width, PAD};
use crate::model::{LString, Model, ModuleId, Program, RuleSet, Simple};
use std::mem::MaybeUninit;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ParametricKind {
    Copy,
    Template,
    General,
}

/// One module id's class.
#[derive(Clone, Copy, Debug)]
pub(super) struct ParametricClass {
    pub kind: ParametricKind,
    /// Template: the predecessor's arity; the module matches when it has that many parameters.
    pub arity: u32,
    /// Template: its index in [`ParametricClasses::templates`].
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
    /// The same ids in [`ParametricClasses::successors`], from `start`.
    pub start: u32,
    /// For each successor module, the parameters written up to and including it.
    pub ends: Vec<u32>,
    pub args: Vec<Arg>,
    pub programs: Vec<Program>,
    /// Every argument as an [`Affine`], when each is one and the predecessor has at most
    /// [`AFFINE_ARITY`] parameters: the successor is then written without the slots.
    pub affine: Option<Vec<Affine>>,
    /// What the successor adds to the size of the step after (modules, parameters): each of its
    /// modules as its own class will rewrite it ([`ParametricClasses::output_size`]).
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
pub(super) struct ParametricClasses {
    pub classes: Vec<ParametricClass>,
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
    pub carries: bool,
    /// After a sized step: the string it wrote (modules, parameters) and the size of the step
    /// after it.
    pub carried: Option<[usize; 4]>,
}

impl ParametricClasses {
    /// The classes of `model`'s productions, when its strings have parameters and no control
    /// module groups.
    pub fn new(model: &Model) -> Option<ParametricClasses> {
        if !model.parametric || model.has_groups {
            return None;
        }
        let rules = &model.productions;
        let mut classes = ParametricClasses {
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
            classes.general |= class.kind == ParametricKind::General;
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
                ParametricKind::Template => c.arity,
                _ => u32::MAX,
            })
            .collect();
        for k in 0..classes.templates.len() {
            let p = &rules.productions[classes.templates[k].production as usize];
            let (mut len, mut params) = (0, 0);
            for m in &p.successor {
                let class = &classes.classes[m.id.index()];
                if class.kind == ParametricKind::Template && class.arity as usize == m.args.len() {
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

    fn classify(&mut self, rules: &RuleSet, candidates: &[u32]) -> ParametricClass {
        let general = ParametricClass {
            kind: ParametricKind::General,
            arity: 0,
            template: 0,
        };
        let Some(&first) = candidates.first() else {
            return ParametricClass {
                kind: ParametricKind::Copy,
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
        ParametricClass {
            kind: ParametricKind::Template,
            arity: p.predecessor.arity as u32,
            template: (self.templates.len() - 1) as u32,
        }
    }

    /// The length and the parameter count of the string the step makes from `src`, when no
    /// module is general (every module then rewrites as its class says).
    pub fn output_size(&self, src: &LString) -> Option<(usize, usize)> {
        if self.general {
            return None;
        }
        let (mut len, mut params) = (0usize, 0usize);
        for (i, &id) in src.ids.iter().enumerate() {
            let class = &self.classes[id.index()];
            let own = (src.offsets[i + 1] - src.offsets[i]) as usize;
            if class.kind == ParametricKind::Template && own == class.arity as usize {
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

/// Writes the arguments `affine` of a template into `out`, the predecessor's parameters `own`
/// bound; false (with `out` partly written) when a value is not finite: the interpreter must
/// evaluate them and report it.
#[inline(always)]
pub(super) fn write_affine(affine: &[Affine], own: &[f64], out: &mut [MaybeUninit<f64>]) -> bool {
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
