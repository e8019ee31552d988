//! Productions and module strings: formal parameters bound to slots, expressions compiled,
//! arities checked, and each section indexed by predecessor.

use super::definitions::MAX_NAMES;
use super::scope::Slots;
use super::Resolver;
use crate::diagnostics::{Diagnostic, Severity};
use crate::model::{
    Alphabet, ModuleId, PatternItem, PatternModule, Production, Program, RuleSet, SuccessorModule,
};
use crate::syntax::{ExprSyntax, ModuleSyntax, ProductionSyntax, SourceFile, Span};
use crate::vocabulary::{module_named, Command};
use std::collections::HashMap;

/// For each module id, how many parameters it is written with, and where.
type Uses = HashMap<ModuleId, Vec<(usize, Span)>>;

impl Resolver {
    /// A module string of the axiom or a successor, its arguments compiled with `slots` bound.
    pub(super) fn successor(
        &mut self,
        modules: &[ModuleSyntax],
        slots: &Slots,
    ) -> Vec<SuccessorModule> {
        modules
            .iter()
            .map(|m| {
                let id = self.alphabet.intern(&m.name);
                let args = m
                    .params
                    .iter()
                    .filter_map(|e| self.compile(e, slots))
                    .collect();
                let group = m.group.as_ref().map(|members| {
                    members
                        .iter()
                        .map(|member| self.successor(member, slots))
                        .collect()
                });
                SuccessorModule {
                    id,
                    args,
                    group,
                    span: m.span.clone(),
                }
            })
            .collect()
    }

    /// A predecessor or context module: its parameters must be names, bound to new slots.
    fn pattern(&mut self, m: &ModuleSyntax, slots: &mut Slots) -> PatternModule {
        let first_slot = slots.len().min(MAX_NAMES) as u16;
        if slots.len() + m.params.len() > MAX_NAMES {
            self.diagnostics.push(Diagnostic::error(
                "E0515",
                m.span.clone(),
                format!("more than {MAX_NAMES} formal parameters in one production"),
            ));
        }
        for p in &m.params {
            match p {
                ExprSyntax::Name(name, span) => {
                    if slots.binds(name) {
                        self.diagnostics.push(Diagnostic::error(
                            "E0512",
                            span.clone(),
                            format!(
                                "the formal parameter '{name}' is bound twice in this production"
                            ),
                        ));
                    }
                    slots.bind(Some(name));
                }
                other => {
                    self.diagnostics.push(Diagnostic::error(
                        "E0510",
                        other.span(),
                        "a parameter of a predecessor or context must be a name (a formal parameter)",
                    ));
                    slots.bind(None);
                }
            }
        }
        PatternModule {
            id: self.alphabet.intern(&m.name),
            arity: m.params.len(),
            first_slot,
            span: m.span.clone(),
        }
    }

    /// One production; `None` when it has an error (reported).
    pub(super) fn production(&mut self, p: &ProductionSyntax) -> Option<Production> {
        let errors_before = self.diagnostics.len();
        let mut slots = Slots::default();
        let predecessor = self.pattern(&p.predecessor, &mut slots);
        let left: Vec<_> = p.left.iter().map(|m| self.pattern(m, &mut slots)).collect();
        let right = p
            .right
            .iter()
            .map(|m| match bracket(&m.name) {
                Some(Command::Push) => PatternItem::Open,
                Some(_) => PatternItem::Close,
                None => PatternItem::Module(self.pattern(m, &mut slots)),
            })
            .collect();
        let condition = p.condition.as_ref().and_then(|c| self.compile(c, &slots));
        let weight = p.weight.as_ref().and_then(|w| self.compile(w, &slots));
        if let Some(w) = weight.as_ref().and_then(Program::constant) {
            if w < 0.0 {
                self.diagnostics.push(Diagnostic::error(
                    "E0513",
                    p.weight.as_ref().map_or(0..0, |w| w.span()),
                    "a weight cannot be negative",
                ));
            }
        }
        let successor = self.successor(&p.successor, &slots);
        if self.diagnostics[errors_before..]
            .iter()
            .any(|d| d.severity == Severity::Error)
        {
            return None;
        }
        Some(Production {
            label: p.label.clone(),
            section: p.section,
            left,
            predecessor,
            right,
            condition,
            weight,
            successor,
            slots: slots.len(),
            span: p.span.clone(),
        })
    }

    /// Arities: where a module is written (axiom, successors), a module named by letters that has
    /// no meaning in the vocabulary must always have the same number of parameters (`E0514`); and
    /// a pattern must match how the module is written somewhere (`E0511`).
    pub(super) fn check_arities(&mut self, axiom: &[SuccessorModule], sets: [&RuleSet; 3]) {
        let mut written = Uses::new();
        collect_uses(axiom, &mut written);
        for set in sets {
            for p in &set.productions {
                collect_uses(&p.successor, &mut written);
            }
        }
        self.inconsistent_arities(&written);
        for set in sets {
            for p in &set.productions {
                self.pattern_arities(p, &written);
            }
        }
    }

    /// `E0514` for every module written with two numbers of parameters, in source order.
    fn inconsistent_arities(&mut self, written: &Uses) {
        let mut inconsistent: Vec<(ModuleId, usize, usize, Span)> = Vec::new();
        for (&id, uses) in written {
            let name = self.alphabet.name(id);
            let checked =
                name.starts_with(|c: char| c.is_alphabetic()) && module_named(name).is_none();
            if !checked {
                continue;
            }
            let first = uses
                .iter()
                .min_by_key(|(_, span)| span.start)
                .map(|(a, _)| *a)
                .unwrap_or(0);
            if let Some((arity, span)) = uses
                .iter()
                .filter(|(a, _)| *a != first)
                .min_by_key(|(_, span)| span.start)
            {
                inconsistent.push((id, *arity, first, span.clone()));
            }
        }
        crate::sort::sort_by_key(&mut inconsistent, |(_, _, _, span)| span.start);
        for (id, arity, first, span) in inconsistent {
            self.diagnostics.push(Diagnostic::error(
                "E0514",
                span,
                format!(
                    "'{}' is written with {arity} parameter{} here but with {first} before; a module keeps one number of parameters",
                    self.alphabet.name(id),
                    plural(arity),
                ),
            ));
        }
    }

    /// `E0511` for each module of `p`'s patterns matched with a number of parameters it is never
    /// written with.
    fn pattern_arities(&mut self, p: &Production, written: &Uses) {
        let patterns =
            p.left
                .iter()
                .chain(std::iter::once(&p.predecessor))
                .chain(p.right.iter().filter_map(|i| match i {
                    PatternItem::Module(m) => Some(m),
                    _ => None,
                }));
        for m in patterns {
            let Some(uses) = written.get(&m.id) else {
                continue;
            };
            if !uses.iter().any(|(arity, _)| *arity == m.arity) {
                let (arity, _) = &uses[0];
                self.diagnostics.push(Diagnostic::error(
                    "E0511",
                    m.span.clone(),
                    format!(
                        "'{}' is matched with {} parameter{} here, but it is written with {arity} everywhere else",
                        self.alphabet.name(m.id),
                        m.arity,
                        plural(m.arity),
                    ),
                ));
            }
        }
    }

    /// Indexes `set` by predecessor and warns about productions that never apply.
    pub(super) fn index(&mut self, set: &mut RuleSet, file: &SourceFile) {
        set.by_predecessor = vec![Vec::new(); self.alphabet.len()];
        for (index, p) in set.productions.iter().enumerate() {
            set.by_predecessor[p.predecessor.id.index()].push(index as u32);
        }
        unreachable_warnings(set, &self.alphabet, file, &mut self.diagnostics);
    }
}

/// `Push` for `[`, `Pop` for `]` in a right context.
fn bracket(name: &str) -> Option<Command> {
    module_named(name)
        .and_then(|m| m.command())
        .filter(|c| matches!(c, Command::Push | Command::Pop))
}

fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}

fn collect_uses(modules: &[SuccessorModule], written: &mut Uses) {
    for m in modules {
        if m.group.is_none() {
            written
                .entry(m.id)
                .or_default()
                .push((m.args.len(), m.span.clone()));
        }
        for member in m.group.iter().flatten() {
            collect_uses(member, written);
        }
    }
}

/// Warns about productions that an earlier, unconditional one always pre-empts. One pass per
/// predecessor: for each arity, the first unconditional production without a weight (it blocks
/// every later one) and the first with a weight (it blocks later ones without).
fn unreachable_warnings(
    set: &RuleSet,
    alphabet: &Alphabet,
    file: &SourceFile,
    diagnostics: &mut Vec<Diagnostic>,
) {
    for candidates in &set.by_predecessor {
        // arity -> (first unweighted blocker, first weighted blocker)
        let mut blockers: HashMap<usize, (Option<&Production>, Option<&Production>)> =
            HashMap::new();
        for &q in candidates {
            let q = &set.productions[q as usize];
            let arity = q.predecessor.arity;
            let (unweighted, weighted) = blockers.get(&arity).copied().unwrap_or_default();
            let weighted = weighted.filter(|_| q.weight.is_none());
            let blocker = match (unweighted, weighted) {
                (Some(a), Some(b)) => Some(if a.span.start <= b.span.start { a } else { b }),
                (a, b) => a.or(b),
            };
            if !q.has_context() && q.condition.is_none() {
                let entry = blockers.entry(arity).or_default();
                let slot = if q.weight.is_none() {
                    &mut entry.0
                } else {
                    &mut entry.1
                };
                slot.get_or_insert(q);
            }
            if let Some(p) = blocker {
                diagnostics.push(Diagnostic::warning(
                    "E0301",
                    q.span.clone(),
                    format!(
                        "this production never applies: the production on line {} always rewrites '{}' first",
                        file.line(p.span.start),
                        alphabet.name(q.predecessor.id)
                    ),
                ));
            }
        }
    }
}
