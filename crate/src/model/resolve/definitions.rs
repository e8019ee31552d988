//! `#define` and `#random`: their names collected first (expressions anywhere may use them), each
//! constant `#define` evaluated once, and the `#random` variables compiled with the order in which
//! a variable that reads others must be drawn.

use super::scope::Slots;
use super::Resolver;
use crate::diagnostics::Diagnostic;
use crate::model::{Curve, CurveKind, Program, RandomVariable};
use crate::syntax::{Directive, ExprSyntax, SourceFile, Span};
use crate::vocabulary::{function_named, value_named, DirectiveKind};
use std::collections::HashMap;
use std::sync::Arc;

/// Most `#random` variables one variable may depend on, directly or through others (`E0508`).
pub const MAX_RANDOM_DEPENDENCIES: usize = 256;

/// Most `#random` variables (and formal parameters of one production): their index is a `u16`.
pub const MAX_NAMES: usize = u16::MAX as usize;

impl Resolver {
    /// Collects `#define` and `#random` names first: expressions anywhere may use them. Returns
    /// the `#random` directives whose names were taken.
    pub(super) fn definitions<'f>(&mut self, file: &'f SourceFile) -> Vec<&'f Directive> {
        let mut randoms = Vec::new();
        for d in &file.directives {
            let Some((name, span)) = &d.target else {
                continue;
            };
            let taken = self.defines.contains_key(name)
                || self.random_names.contains_key(name)
                || self.curves.contains_key(name)
                || value_named(name).is_some_and(|v| !v.definable)
                || function_named(name).is_some();
            let curve = curve_kind(d.kind);
            if taken && (curve.is_some() || d.expr.is_some()) {
                // A curve's name too (issue 50, 11: `#curve sin …`, a second `#curve c`, a
                // `#define c` before `#curve c` were ignored without a word).
                let built_in = function_named(name).is_some()
                    || value_named(name).is_some_and(|v| !v.definable);
                let what = if built_in {
                    "is a built-in name"
                } else {
                    "is already defined"
                };
                self.diagnostics.push(Diagnostic::error(
                    "E0205",
                    span.clone(),
                    format!("'{name}' {what}"),
                ));
                continue;
            }
            if let Some(kind) = curve {
                self.curve(name, kind, d);
                continue;
            }
            let Some(expr) = &d.expr else {
                continue;
            };
            if d.kind == Some(DirectiveKind::Define) {
                self.defines.insert(name.clone(), expr.clone());
                self.define_order.push(name.clone());
            } else if self.random_names.len() >= MAX_NAMES {
                self.diagnostics.push(Diagnostic::error(
                    "E0515",
                    span.clone(),
                    format!("more than {MAX_NAMES} #random variables"),
                ));
            } else {
                let index = self.random_names.len() as u16;
                self.random_names.insert(name.clone(), index);
                randoms.push(d);
            }
        }
        self.define_values();
        randoms
    }

    /// A `#curve` or `#table` named `name`.
    fn curve(&mut self, name: &str, kind: CurveKind, d: &Directive) {
        match Curve::new(kind, &d.points) {
            Ok(curve) => {
                self.curves.insert(name.to_string(), Arc::new(curve));
            }
            Err(why) => self.diagnostics.push(Diagnostic::error(
                "E0210",
                d.args_span.clone(),
                format!("{} {name}: {why}", d.written),
            )),
        }
    }

    /// Evaluates every `#define` whose expression is a constant, once, each after the names it
    /// uses: a chain of defines that doubles at every link costs one evaluation per link, not
    /// 2^links. Defines that use formal parameters, `NumIt`, random functions or `#random`
    /// variables stay expressions, expanded where they are used.
    fn define_values(&mut self) {
        for name in defines_in_dependency_order(&self.define_order, &self.defines) {
            let Some(expr) = self.defines.get(&name) else {
                continue;
            };
            let value = self.compile_constant(expr).ok().and_then(|p| p.constant());
            if let Some(value) = value {
                self.define_values.insert(name, value);
            }
        }
    }

    /// The `#random` variables, compiled in the order of their names, each with the variables it
    /// depends on in the order to draw them. A cycle is `E0507`.
    pub(super) fn random_variables(&mut self, randoms: &[&Directive]) -> Vec<RandomVariable> {
        let mut variables: Vec<RandomVariable> = Vec::new();
        for d in randoms {
            let (Some((name, span)), Some(expr)) = (&d.target, &d.expr) else {
                continue;
            };
            // A variable that does not compile keeps its place (its index is its name's), as 0.
            let distribution = self
                .compile(expr, &Slots::default())
                .unwrap_or_else(|| Program::constant_at(0.0, span.clone()));
            variables.push(RandomVariable {
                name: name.clone(),
                distribution,
                depends_on: Vec::new(),
            });
        }
        let reads: Vec<Vec<(usize, Span)>> = variables
            .iter()
            .map(|v| {
                v.distribution
                    .variables()
                    .map(|(k, span)| (k as usize, span.clone()))
                    .collect()
            })
            .collect();
        let Some(rank) = self.random_order(&variables, &reads) else {
            return variables;
        };
        for (k, variable) in variables.iter_mut().enumerate() {
            match closure(k, &reads, &rank) {
                Some(depends_on) => variable.depends_on = depends_on,
                None => self.diagnostics.push(Diagnostic::error(
                    "E0508",
                    variable.distribution.span.clone(),
                    format!(
                        "#random {} depends on more than {MAX_RANDOM_DEPENDENCIES} other variables",
                        variable.name
                    ),
                )),
            }
        }
        variables
    }

    /// Each variable's place in an order where every variable comes after those it reads; `None`
    /// (and `E0507` at the reference that closes it) when the variables read each other in a
    /// cycle.
    fn random_order(
        &mut self,
        variables: &[RandomVariable],
        reads: &[Vec<(usize, Span)>],
    ) -> Option<Vec<usize>> {
        match post_order(reads.len(), |k| reads[k].iter().map(|(j, _)| *j).collect()) {
            (order, None) => {
                let mut rank = vec![0; reads.len()];
                for (place, &k) in order.iter().enumerate() {
                    rank[k] = place;
                }
                Some(rank)
            }
            (_, Some(cycle)) => {
                let (last, first) = (cycle[cycle.len() - 1], cycle[0]);
                let span = reads[last].iter().find(|(j, _)| *j == first).map_or_else(
                    || variables[last].distribution.span.clone(),
                    |r| r.1.clone(),
                );
                let mut names: Vec<&str> =
                    cycle.iter().map(|&k| variables[k].name.as_str()).collect();
                names.push(&variables[first].name);
                self.diagnostics.push(Diagnostic::error(
                    "E0507",
                    span,
                    format!(
                        "#random {} depends on itself: {}",
                        variables[first].name,
                        names.join(" -> ")
                    ),
                ));
                None
            }
        }
    }
}

/// The variables `k` reads, directly or through others, ordered by `rank` (those read first);
/// `None` beyond [`MAX_RANDOM_DEPENDENCIES`].
fn closure(k: usize, reads: &[Vec<(usize, Span)>], rank: &[usize]) -> Option<Vec<u16>> {
    let mut seen = vec![k];
    let mut todo = vec![k];
    while let Some(v) = todo.pop() {
        for &(j, _) in &reads[v] {
            if !seen.contains(&j) {
                if seen.len() > MAX_RANDOM_DEPENDENCIES {
                    return None;
                }
                seen.push(j);
                todo.push(j);
            }
        }
    }
    seen.remove(0);
    crate::sort::sort_by_key(&mut seen, |&j| rank[j]);
    Some(seen.into_iter().map(|j| j as u16).collect())
}

/// The nodes `0..n` in an order where each comes after every node `edges` leads to from it
/// (depth first, without recursion), and the first cycle met (its nodes in the order of its
/// edges), whose closing edge the order ignores.
pub(super) fn post_order(
    n: usize,
    edges: impl Fn(usize) -> Vec<usize>,
) -> (Vec<usize>, Option<Vec<usize>>) {
    #[derive(Clone, Copy, PartialEq)]
    enum Mark {
        New,
        Open,
        Done,
    }
    let mut mark = vec![Mark::New; n];
    let mut order = Vec::with_capacity(n);
    let mut cycle = None;
    for root in 0..n {
        if mark[root] != Mark::New {
            continue;
        }
        // (node, its edges, how many of them were followed)
        let mut stack = vec![(root, edges(root), 0usize)];
        mark[root] = Mark::Open;
        while let Some((node, next, followed)) = stack.last_mut() {
            let Some(&to) = next.get(*followed) else {
                mark[*node] = Mark::Done;
                order.push(*node);
                stack.pop();
                continue;
            };
            *followed += 1;
            match mark.get(to) {
                Some(Mark::New) => {
                    mark[to] = Mark::Open;
                    let out = edges(to);
                    stack.push((to, out, 0));
                }
                Some(Mark::Open) if cycle.is_none() => {
                    let from = stack.iter().position(|(v, _, _)| *v == to).unwrap_or(0);
                    cycle = Some(stack[from..].iter().map(|(v, _, _)| *v).collect());
                }
                _ => {}
            }
        }
    }
    (order, cycle)
}

/// The `#define` names in an order where each comes after the defines its expression names (a
/// cycle's names in any order: they do not compile, and their use reports `E0503`).
fn defines_in_dependency_order(
    order: &[String],
    defines: &HashMap<String, ExprSyntax>,
) -> Vec<String> {
    let index: HashMap<&str, usize> = order
        .iter()
        .enumerate()
        .map(|(i, n)| (n.as_str(), i))
        .collect();
    let uses = |k: usize| -> Vec<usize> {
        let mut names = Vec::new();
        if let Some(expr) = defines.get(&order[k]) {
            names_in(expr, &mut names);
        }
        names
            .iter()
            .filter_map(|n| index.get(n.as_str()).copied())
            .collect()
    };
    let (sorted, _) = post_order(order.len(), uses);
    sorted.into_iter().map(|k| order[k].clone()).collect()
}

/// Every name `expr` reads (the tree's depth is bounded by the parser, so this recursion is too).
fn names_in(expr: &ExprSyntax, names: &mut Vec<String>) {
    match expr {
        ExprSyntax::Number(..) => {}
        ExprSyntax::Name(name, _) => names.push(name.clone()),
        ExprSyntax::Unary(_, x, _) => names_in(x, names),
        ExprSyntax::Binary(_, a, b, _) => {
            names_in(a, names);
            names_in(b, names);
        }
        ExprSyntax::Chain(first, links) => {
            names_in(first, names);
            links.iter().for_each(|(_, x, _)| names_in(x, names));
        }
        ExprSyntax::Conditional(c, a, b, _) => {
            names_in(c, names);
            names_in(a, names);
            names_in(b, names);
        }
        ExprSyntax::Call(_, _, args, _) => args.iter().for_each(|x| names_in(x, names)),
    }
}

/// The function kind a `#curve` or `#table` directive defines.
fn curve_kind(kind: Option<DirectiveKind>) -> Option<CurveKind> {
    match kind? {
        DirectiveKind::Curve => Some(CurveKind::Spline),
        DirectiveKind::Table => Some(CurveKind::Table),
        _ => None,
    }
}
