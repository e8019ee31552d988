//! Per-module production classes: the general path's table for strings without parameters.
//!
//! For each module id, what its productions need at run time, decided once per derivation:
//! - [`ModuleKind::Fixed`]: the first production always applies (no context, condition or
//!   weight), or there is none (the module is copied): a table copy, as on the D0L path;
//! - [`ModuleKind::Choice`]: weighted productions with constant weights and nothing else to
//!   match: one draw, the same draw and the same arithmetic as [`super::rewriter`]'s weighted
//!   choice;
//! - [`ModuleKind::Neighbours`]: productions whose contexts are one module each side (or none): the
//!   pass compares the module's neighbours (the previous module on the path to the root, the next
//!   one on its branch, as [`super::context`] finds them) with the productions' contexts;
//! - [`ModuleKind::General`]: anything else (conditions, longer or branching contexts, weights
//!   mixed with contexts, control modules), matched by the general path module by module.
//!
//! So a stochastic or context-sensitive grammar still rewrites its plain modules (`F -> FF`) by
//! table, and a grammar mixing every feature pays for them only where they are.

use super::context::NONE;
use super::successors::{put, width, PAD};
use super::NOT_REWRITTEN;
use crate::model::{
    LString, Model, ModuleId, PatternItem, PatternModule, Production, RuleSet, SuccessorModule,
};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum ModuleKind {
    Fixed,
    Choice,
    Neighbours,
    General,
}

/// What a module is to context matching: a bracket, skipped, or a context.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Role {
    Context,
    Open,
    Close,
    Ignored,
}

/// One module id's class.
#[derive(Clone, Copy, Debug)]
pub(super) struct ModuleClass {
    pub kind: ModuleKind,
    pub role: Role,
    /// Fixed: the production applied ([`NOT_REWRITTEN`] for a copy).
    pub production: u32,
    /// Fixed: the successor in [`ModuleClasses::successors`]; Choice and Neighbours: the
    /// alternatives in [`ModuleClasses::alternatives`].
    pub start: u32,
    pub len: u32,
    /// Choice: the sum of the weights, in source order.
    pub total: f64,
    /// The module id alone in [`ModuleClasses::successors`] (what a copy writes).
    pub own: u32,
    /// How many modules the class writes, whatever the draw or the neighbours ([`VARIES`] when
    /// that depends on them, or the class is general).
    pub out: u32,
}

/// In [`ModuleClass::out`]: the length written depends on the module's draw or neighbours.
pub(super) const VARIES: u32 = u32::MAX;

/// One production of a Choice or Neighbours class.
#[derive(Clone, Copy, Debug)]
pub(super) struct Alternative {
    pub production: u32,
    pub weight: f64,
    /// The left and right context ids ([`NONE`]: no context).
    pub left: u32,
    pub right: u32,
    pub start: u32,
    pub len: u32,
}

/// The classes of the productions section of a grammar without parameters.
pub(super) struct ModuleClasses {
    pub classes: Vec<ModuleClass>,
    pub alternatives: Vec<Alternative>,
    /// Every successor's ids, back to back, then [`PAD`] ids of padding.
    pub successors: Vec<ModuleId>,
    /// True when some class compares neighbours: the pass finds each module's neighbours.
    pub neighbours: bool,
    /// True when some general class has contexts: the pass pairs the brackets for them.
    pub general_contexts: bool,
    /// True when every class writes a known number of modules ([`ModuleClass::out`]): the length of
    /// the next string is then known before the step.
    pub sized: bool,
    /// The copy width for these successors ([`width`]).
    pub width: usize,
    /// True when every class writes one module.
    pub unit: bool,
    /// For each module id, whether it is hot: a production may rewrite it whatever its
    /// neighbours, or it is the context of some neighbours class. A module that is not, between
    /// two that are not, is copied as it is.
    pub hot: Vec<bool>,
    /// The hot ids when there are at most four (repeated to fill four): a run of modules that
    /// are not hot is then found by comparing 16 ids at a time with them, like `memchr`.
    pub hot_ids: Option<[u32; 4]>,
    /// True when no string of the derivation can hold a bracket or an ignored module (none is in
    /// the axiom or a successor of the productions or of decomposition): each module's neighbours
    /// are then the modules next to it, without a pass over the string to find out.
    pub flat: bool,
    /// For each module id, its successor in [`ModuleClasses::successors`] (start, length) when its
    /// class is Fixed; the length is [`SPECIAL`] for a class of another kind, and has
    /// [`REWRITES`] set when a production applies. One small entry a module for the hot loop.
    pub entry: Vec<(u32, u32)>,
    /// For each module id, [`ModuleClass::out`]: what the sizing pass reads.
    pub outs: Vec<u32>,
}

/// In [`ModuleClasses::entry`]'s length: the class is not Fixed (look at
/// [`ModuleClasses::classes`]).
pub(super) const SPECIAL: u32 = 1 << 31;
/// In [`ModuleClasses::entry`]'s length: a production rewrites the module (Fixed with a
/// production, or Choice).
pub(super) const REWRITES: u32 = 1 << 30;

impl ModuleClasses {
    /// The classes of `model`'s productions, when its strings have no parameters and no control
    /// module groups (whose members the general path rewrites on its own).
    pub fn new(model: &Model) -> Option<ModuleClasses> {
        if model.parametric || model.has_groups {
            return None;
        }
        let rules = &model.productions;
        let mut classes = ModuleClasses {
            classes: Vec::with_capacity(model.alphabet.len()),
            alternatives: Vec::new(),
            successors: Vec::new(),
            neighbours: false,
            general_contexts: false,
            sized: true,
            width: 0,
            unit: true,
            hot: Vec::new(),
            hot_ids: None,
            flat: flat(model),
            entry: Vec::new(),
            outs: Vec::new(),
        };
        for index in 0..model.alphabet.len() {
            let id = ModuleId(index as u32);
            let candidates = rules
                .by_predecessor
                .get(index)
                .map_or(&[][..], Vec::as_slice);
            let mut class = classes.classify(rules, id, candidates);
            class.role = role(model, id);
            (class.own, _) = classes.successor(std::iter::once(id));
            class.out = classes.out(&class);
            classes.sized &= class.out != VARIES;
            classes.classes.push(class);
        }
        let longest = classes.classes.iter().map(|c| c.len).max().unwrap_or(1);
        let longest = classes
            .alternatives
            .iter()
            .map(|a| a.len)
            .fold(longest.max(1), u32::max);
        classes.width = width(longest as usize);
        classes.unit = classes.classes.iter().all(|c| c.out == 1);
        classes.hot = classes
            .classes
            .iter()
            .map(|class| !classes.cold(class))
            .collect();
        for a in &classes.alternatives {
            for context in [a.left, a.right] {
                if let Some(h) = classes.hot.get_mut(context as usize) {
                    *h = true;
                }
            }
        }
        classes.loop_tables();
        classes
            .successors
            .extend(std::iter::repeat_n(ModuleId(0), PAD));
        Some(classes)
    }

    /// The tables the hot loops read: the hot ids for the 16-at-a-time search, each class's
    /// 8-byte entry and length written.
    fn loop_tables(&mut self) {
        let hot: Vec<u32> = (0..self.hot.len() as u32)
            .filter(|&id| self.hot[id as usize])
            .collect();
        self.hot_ids = match hot.as_slice() {
            [] => Some([NONE; 4]),
            [a, rest @ ..] if rest.len() < 4 => {
                let mut ids = [*a; 4];
                ids[1..=rest.len()].copy_from_slice(rest);
                Some(ids)
            }
            _ => None,
        };
        self.outs = self.classes.iter().map(|c| c.out).collect();
        self.entry = self
            .classes
            .iter()
            .map(|class| match class.kind {
                ModuleKind::Fixed if class.production == NOT_REWRITTEN => (class.start, class.len),
                ModuleKind::Fixed => (class.start, class.len | REWRITES),
                ModuleKind::Choice => (class.start, SPECIAL | REWRITES),
                ModuleKind::Neighbours | ModuleKind::General => (class.start, SPECIAL),
            })
            .collect();
    }

    /// Appends a successor's ids; returns (start, len).
    fn successor(&mut self, ids: impl Iterator<Item = ModuleId>) -> (u32, u32) {
        let start = self.successors.len();
        self.successors.extend(ids);
        (start as u32, (self.successors.len() - start) as u32)
    }

    fn classify(&mut self, rules: &RuleSet, id: ModuleId, candidates: &[u32]) -> ModuleClass {
        let mut class = ModuleClass {
            kind: ModuleKind::Fixed,
            role: Role::Context,
            production: NOT_REWRITTEN,
            start: 0,
            len: 0,
            total: 0.0,
            own: 0,
            out: VARIES,
        };
        let Some(&first) = candidates.first() else {
            (class.start, class.len) = self.successor(std::iter::once(id));
            return class;
        };
        let plain = |p: &Production| {
            p.predecessor.arity == 0
                && p.condition.is_none()
                && p.successor
                    .iter()
                    .all(|s| s.group.is_none() && s.args.is_empty())
        };
        if !candidates
            .iter()
            .all(|&k| plain(&rules.productions[k as usize]))
        {
            self.general_contexts |= candidates
                .iter()
                .any(|&k| rules.productions[k as usize].has_context());
            class.kind = ModuleKind::General;
            return class;
        }
        let p = &rules.productions[first as usize];
        let kind = match (p.has_context(), p.weight.is_some()) {
            (false, false) => {
                class.production = first;
                (class.start, class.len) = self.successor(p.successor.iter().map(|s| s.id));
                return class;
            }
            (false, true) => self.choice(rules, candidates, &mut class),
            (true, _) => self.neighbours(rules, candidates, &mut class),
        };
        if kind == ModuleKind::General {
            self.general_contexts |= candidates
                .iter()
                .any(|&k| rules.productions[k as usize].has_context());
        }
        self.neighbours |= kind == ModuleKind::Neighbours;
        class.kind = kind;
        class
    }

    /// The weighted productions among `candidates` (the first of which is weighted and always
    /// matches), when none has a context and every weight is a constant at least 0.
    fn choice(
        &mut self,
        rules: &RuleSet,
        candidates: &[u32],
        class: &mut ModuleClass,
    ) -> ModuleKind {
        let weighted = candidates
            .iter()
            .filter(|&&k| rules.productions[k as usize].weight.is_some());
        let read = |p: &Production| {
            let weight = p.weight.as_ref()?.constant().filter(|w| *w >= 0.0)?;
            (!p.has_context()).then_some((weight, (NONE, NONE)))
        };
        self.read_alternatives(rules, weighted, class, read, ModuleKind::Choice)
    }

    /// The productions among `candidates` up to the first without a context, when each has no
    /// weight and at most one module of context each side.
    fn neighbours(
        &mut self,
        rules: &RuleSet,
        candidates: &[u32],
        class: &mut ModuleClass,
    ) -> ModuleKind {
        // The first production without a context always applies: the ones after it never do.
        let applying = candidates
            .iter()
            .position(|&k| !rules.productions[k as usize].has_context())
            .map_or(candidates, |last| &candidates[..=last]);
        let read = |p: &Production| {
            let single = |m: &PatternModule| (m.arity == 0).then_some(m.id.0);
            let left = match p.left.as_slice() {
                [] => NONE,
                [m] => single(m)?,
                _ => return None,
            };
            let right = match p.right.as_slice() {
                [] => NONE,
                [PatternItem::Module(m)] => single(m)?,
                _ => return None,
            };
            p.weight.is_none().then_some((0.0, (left, right)))
        };
        self.read_alternatives(rules, applying.iter(), class, read, ModuleKind::Neighbours)
    }

    /// Makes the productions `ks` the alternatives of `class`, each with the weight and contexts
    /// (left, right) `read` finds in it; gives up (the class is General) at the first production
    /// `read` refuses.
    fn read_alternatives<'k>(
        &mut self,
        rules: &RuleSet,
        ks: impl Iterator<Item = &'k u32>,
        class: &mut ModuleClass,
        read: impl Fn(&Production) -> Option<(f64, (u32, u32))>,
        kind: ModuleKind,
    ) -> ModuleKind {
        let first = self.alternatives.len();
        for &k in ks {
            let p = &rules.productions[k as usize];
            let Some((weight, (left, right))) = read(p) else {
                self.alternatives.truncate(first);
                return ModuleKind::General;
            };
            class.total += weight;
            let (start, len) = self.successor(p.successor.iter().map(|m| m.id));
            self.alternatives.push(Alternative {
                production: k,
                weight,
                left,
                right,
                start,
                len,
            });
        }
        class.start = first as u32;
        class.len = (self.alternatives.len() - first) as u32;
        kind
    }

    /// True when `class` copies its module unless a neighbour is the context of one of its
    /// productions: no production, or every one has a context.
    fn cold(&self, class: &ModuleClass) -> bool {
        match class.kind {
            ModuleKind::Fixed => class.production == NOT_REWRITTEN,
            ModuleKind::Neighbours => self.alternatives[class.start as usize..]
                [..class.len as usize]
                .iter()
                .all(|a| a.left != NONE || a.right != NONE),
            ModuleKind::Choice | ModuleKind::General => false,
        }
    }

    /// How many modules `class` writes whatever happens, or [`VARIES`].
    fn out(&self, class: &ModuleClass) -> u32 {
        let alternatives = || &self.alternatives[class.start as usize..][..class.len as usize];
        match class.kind {
            ModuleKind::Fixed => class.len,
            ModuleKind::General => VARIES,
            ModuleKind::Choice => match alternatives() {
                [first, rest @ ..] if rest.iter().all(|a| a.len == first.len) => first.len,
                _ => VARIES,
            },
            // Matching nothing copies the module: one.
            ModuleKind::Neighbours => {
                if alternatives().iter().all(|a| a.len == 1) {
                    1
                } else {
                    VARIES
                }
            }
        }
    }

    /// Appends the successor of `len` ids at `start` in [`ModuleClasses::successors`] to `out`
    /// ([`put`]).
    #[inline(always)]
    pub fn put(&self, out: &mut Vec<ModuleId>, start: u32, len: u32) {
        put(out, &self.successors, start as usize, len as usize);
    }

    /// The alternative of a Choice class that the uniform draw `u` (in [0, 1)) picks: the weighted
    /// choice of the general path, with the same arithmetic.
    #[inline]
    pub fn choose(&self, class: &ModuleClass, u: f64) -> &Alternative {
        &self.alternatives[class.start as usize + self.choose_index(class, u)]
    }

    /// The index among its class's alternatives of the one [`ModuleClasses::choose`] picks.
    /// Without a branch on the draw (which goes either way at random): every alternative is looked at,
    /// and `r` stops changing at the first whose weight it is below, so the arithmetic up to it
    /// is the general path's.
    #[inline]
    pub fn choose_index(&self, class: &ModuleClass, u: f64) -> usize {
        let alternatives = &self.alternatives[class.start as usize..][..class.len as usize];
        let mut r = u * class.total;
        if let [first, _] = alternatives {
            // Two alternatives, the usual stochastic production: what the loop below picks (the
            // second unless `r` is below the first's weight, NaN included) without its chain of
            // dependent selects.
            return match r.partial_cmp(&first.weight) {
                Some(std::cmp::Ordering::Less) => 0,
                _ => 1,
            };
        }
        let mut pick = alternatives.len().saturating_sub(1);
        let mut found = false;
        for (k, a) in alternatives.iter().enumerate() {
            let hit = !found & (r < a.weight);
            pick = if hit { k } else { pick };
            found |= hit;
            r = if found { r } else { r - a.weight };
        }
        pick
    }

    /// The first alternative of a Neighbours class whose contexts are `left` and `right`.
    #[inline]
    pub fn neighbours_match(
        &self,
        class: &ModuleClass,
        left: u32,
        right: u32,
    ) -> Option<&Alternative> {
        self.alternatives[class.start as usize..][..class.len as usize]
            .iter()
            .find(|a| (a.left == NONE || a.left == left) && (a.right == NONE || a.right == right))
    }

    /// The index of the first hot module of `ids` from `from` (`ids.len()` when there is none).
    #[inline]
    pub fn next_hot(&self, ids: &[ModuleId], from: usize) -> usize {
        const CHUNK: usize = 16;
        let mut i = from;
        if let Some(h) = self.hot_ids {
            while let Some(chunk) = ids.get(i..i + CHUNK) {
                // No branch inside the chunk: the compares vectorise (4 ids to a SIMD compare).
                let mut any = 0u32;
                for id in chunk {
                    let v = id.0;
                    any |= ((v == h[0]) | (v == h[1]) | (v == h[2]) | (v == h[3])) as u32;
                }
                if any != 0 {
                    break;
                }
                i += CHUNK;
            }
        }
        while i < ids.len() && !self.hot[ids[i].index()] {
            i += 1;
        }
        i
    }
}

/// True when no module of the axiom or of a successor of the productions or of decomposition is
/// a bracket or ignored: no string derived from them holds one.
fn flat(model: &Model) -> bool {
    let plain = |modules: &[SuccessorModule]| {
        modules
            .iter()
            .all(|m| m.group.is_none() && role(model, m.id) == Role::Context)
    };
    let axiom_plain = (0..model.alphabet.len()).all(|index| {
        let id = ModuleId(index as u32);
        !model.in_axiom[index] || role(model, id) == Role::Context
    });
    axiom_plain
        && [&model.productions, &model.decomposition]
            .iter()
            .all(|rules| rules.productions.iter().all(|p| plain(&p.successor)))
}

fn role(model: &Model, id: ModuleId) -> Role {
    if id == model.open {
        Role::Open
    } else if id == model.close {
        Role::Close
    } else if model.ignored.get(id.index()).copied().unwrap_or(false) {
        Role::Ignored
    } else {
        Role::Context
    }
}

/// For each module of `s`, the id of its right neighbour for context matching ([`NONE`] when it
/// has none): the next module on its branch, skipping ignored modules and whole branches; a `]`
/// or an unbalanced `[` ends the search ([`super::context::match_right`] for one module).
/// Returns false, leaving `right` empty, when `s` is flat (no brackets, nothing ignored): each
/// module's neighbours are then the modules next to it.
pub(super) fn right_neighbours(
    classes: &[ModuleClass],
    s: &LString,
    right: &mut Vec<u32>,
    stack: &mut Vec<u32>,
) -> bool {
    right.clear();
    if s.ids
        .iter()
        .all(|id| classes[id.index()].role == Role::Context)
    {
        return false;
    }
    right.resize(s.len(), NONE);
    stack.clear();
    // `next`: what a search starting at module i + 1 finds.
    let mut next = NONE;
    for (i, &id) in s.ids.iter().enumerate().rev() {
        right[i] = next;
        match classes[id.index()].role {
            Role::Close => {
                stack.push(next);
                next = NONE;
            }
            // The top of the stack is the search from past this bracket's partner; none when the
            // bracket is unbalanced.
            Role::Open => next = stack.pop().unwrap_or(NONE),
            Role::Ignored => {}
            Role::Context => next = id.0,
        }
    }
    true
}

/// After module `id`: the left neighbour of the next module, `last` being this module's (the
/// previous module on the path to the root, skipping ignored modules and whole branches;
/// [`super::context::match_left`] for one module).
#[inline(always)]
pub(super) fn step_left(role: Role, id: ModuleId, last: u32, stack: &mut Vec<u32>) -> u32 {
    match role {
        Role::Context => id.0,
        Role::Ignored => last,
        Role::Open => {
            stack.push(last);
            last
        }
        // An unbalanced `]` has no partner: nothing before it is on the path to the root.
        Role::Close => stack.pop().unwrap_or(NONE),
    }
}
