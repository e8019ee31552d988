//! Resolve: syntax tree -> [`Model`]. Checks directive arguments, interns module names, binds
//! formal parameters to slots, compiles every expression and indexes productions by predecessor.

use super::{
    Alphabet, Model, ModuleId, PatternItem, PatternModule, Production, Program, RandomVariable,
    RuleSet, Scope, Settings, SuccessorModule, DEFAULT_MAX_DEPTH, MAX_COLOR_INDEX,
};
use crate::diagnostics::Diagnostic;
use crate::syntax::{
    Directive, ExprSyntax, ModuleSyntax, ProductionSyntax, Section, SourceFile, Span,
};
use std::collections::HashMap;

/// Resolves a parsed file. Returns `None` for the model when there is nothing to derive (no
/// axiom); otherwise a model plus every diagnostic, even when some are errors.
pub fn resolve(file: &SourceFile) -> (Option<Model>, Vec<Diagnostic>) {
    let mut r = Resolver {
        diagnostics: Vec::new(),
        alphabet: Alphabet::default(),
        defines: HashMap::new(),
        random_names: Vec::new(),
    };
    let open = r.alphabet.intern("[");
    let close = r.alphabet.intern("]");
    let cut = [r.alphabet.intern("%"), r.alphabet.intern("@Prune")];
    let groups = super::GroupIds {
        switch: r.alphabet.intern("@Switch"),
        pendulum: r.alphabet.intern("@Pendulum"),
        repeat: r.alphabet.intern("@Repeat"),
        open: r.alphabet.intern("@<"),
        separator: r.alphabet.intern("@|"),
        close: r.alphabet.intern("@>"),
    };
    let mut settings = Settings::default();
    let mut homomorphism_depth = DEFAULT_MAX_DEPTH;
    let mut decomposition_depth = DEFAULT_MAX_DEPTH;
    let mut ignore: Vec<ModuleId> = Vec::new();
    let mut consider: Option<Vec<ModuleId>> = None;
    let mut random_syntax: Vec<&Directive> = Vec::new();
    let mut seen: Vec<&Directive> = Vec::new();
    let mut growth = crate::growth::Attributes::default();
    let mut apex: Vec<ModuleId> = Vec::new();

    // Definitions first: expressions anywhere may use them.
    for d in &file.directives {
        if let (Some((name, span)), Some(expr)) = (&d.target, &d.expr) {
            let taken = r.defines.contains_key(name) || r.random_names.iter().any(|n| n == name);
            if taken
                || name == "NumIt"
                || name == "MaxIt"
                || super::Function::lookup(name).is_some()
            {
                r.diagnostics.push(Diagnostic::error(
                    "E0205",
                    span.clone(),
                    format!("'{name}' is already defined"),
                ));
                continue;
            }
            if d.name == "define" {
                r.defines.insert(name.clone(), expr.clone());
            } else {
                r.random_names.push(name.clone());
                random_syntax.push(d);
            }
        }
    }

    for d in &file.directives {
        let repeatable = matches!(
            d.name.as_str(),
            "module" | "draw" | "define" | "random" | "ignore" | "color" | "colour" | "apex"
        );
        if let Some(previous) = seen.iter().find(|p| p.name == d.name && !repeatable) {
            r.diagnostics.push(Diagnostic::warning(
                "E0201",
                d.name_span.clone(),
                format!(
                    "#{} is set twice; this one replaces the value at byte {}",
                    d.name, previous.name_span.start
                ),
            ));
        }
        seen.push(d);
        match d.name.as_str() {
            "angle" => settings.angle = r.number(d).unwrap_or(settings.angle),
            "step" => settings.step = r.number(d).unwrap_or(settings.step),
            "width" => settings.width = r.number(d).unwrap_or(settings.width),
            "width_step" => settings.width_step = r.number(d).unwrap_or(settings.width_step),
            "tropism" => {
                if let Some(t) = r.tropism(d) {
                    settings.tropism = t;
                }
            }
            "color" | "colour" => r.color(d, &mut settings.palette),
            "iterations" => {
                if let Some(v) = r.whole(d, u32::MAX as u64) {
                    settings.iterations = v as u32;
                    settings.iterations_span = Some(d.name_span.start..d.args_span.end);
                }
            }
            "seed" => settings.seed = r.whole(d, u64::MAX).unwrap_or(settings.seed),
            "max_modules" => {
                settings.max_modules = r
                    .whole(d, u32::MAX as u64)
                    .map_or(settings.max_modules, |v| v.max(1) as usize)
            }
            "max_steps" => {
                settings.max_steps = r
                    .whole(d, u32::MAX as u64)
                    .map_or(settings.max_steps, |v| v as u32)
            }
            "homomorphism_depth" => {
                homomorphism_depth = r.whole(d, 10_000).map_or(homomorphism_depth, |v| v as u32)
            }
            "decomposition_depth" => {
                decomposition_depth = r.whole(d, 10_000).map_or(decomposition_depth, |v| v as u32)
            }
            "module" | "define" | "random" => {}
            "draw" => settings
                .draw
                .extend(d.modules.iter().map(|m| r.alphabet.intern(&m.name))),
            "ignore" => ignore.extend(d.modules.iter().map(|m| r.alphabet.intern(&m.name))),
            "apex" => apex.extend(d.modules.iter().map(|m| r.alphabet.intern(&m.name))),
            "lifetime" => growth.lifetime = r.lifetime(d),
            "speed" => growth.speed = r.speed(d),
            "shape" => growth.shape = r.shape(d),
            "shape_width" => growth.shape_width = r.shape_width(d),
            "sun" => growth.sun = r.sun(d),
            "gravity" => growth.gravity = r.bend(d, None),
            "wind" => growth.wind = r.bend(d, Some(())),
            "consider" => {
                consider = Some(
                    d.modules
                        .iter()
                        .map(|m| r.alphabet.intern(&m.name))
                        .collect(),
                )
            }
            name => r.diagnostics.push(Diagnostic::error(
                "E0200",
                d.name_span.clone(),
                format!("unknown directive '#{name}'"),
            )),
        }
    }
    if !ignore.is_empty() && consider.is_some() {
        let last = file
            .directives
            .iter()
            .rev()
            .find(|d| d.name == "ignore" || d.name == "consider");
        r.diagnostics.push(Diagnostic::error(
            "E0206",
            last.map_or(0..0, |d| d.name_span.clone()),
            "#ignore and #consider cannot both be used: one says what to skip, the other what to keep",
        ));
    }

    let mut random_variables = Vec::new();
    for d in random_syntax {
        let (Some((name, _)), Some(expr)) = (&d.target, &d.expr) else {
            continue;
        };
        if let Some(distribution) = r.compile(expr, &Slots::default()) {
            random_variables.push(RandomVariable {
                name: name.clone(),
                distribution,
            });
        }
    }

    let Some((axiom_syntax, axiom_span)) = &file.axiom else {
        r.diagnostics.push(Diagnostic::error(
            "E0300",
            0..0,
            "the grammar has no axiom: add a line 'axiom: …'",
        ));
        return (None, r.diagnostics);
    };
    let axiom = r.successor(axiom_syntax, &Slots::default());

    let mut sets = [RuleSet::default(), RuleSet::default(), RuleSet::default()];
    for p in &file.productions {
        if let Some(production) = r.production(p) {
            let set = &mut sets[section_index(p.section)];
            set.productions.push(production);
        }
    }
    let [mut productions, mut homomorphism, mut decomposition] = sets;
    productions.max_depth = 1;
    homomorphism.max_depth = homomorphism_depth;
    decomposition.max_depth = decomposition_depth;

    // Arities. Where a module is written (axiom, successors), a module named by letters that is not
    // a turtle command must always have the same number of parameters; and a pattern must match how
    // the module is written somewhere.
    let mut written: HashMap<ModuleId, Vec<(usize, Span)>> = HashMap::new();
    fn collect(modules: &[SuccessorModule], written: &mut HashMap<ModuleId, Vec<(usize, Span)>>) {
        for m in modules {
            if m.group.is_none() {
                written
                    .entry(m.id)
                    .or_default()
                    .push((m.args.len(), m.span.clone()));
            }
            for member in m.group.iter().flatten() {
                collect(member, written);
            }
        }
    }
    collect(&axiom, &mut written);
    for set in [&productions, &homomorphism, &decomposition] {
        for p in &set.productions {
            collect(&p.successor, &mut written);
        }
    }
    let mut inconsistent: Vec<(ModuleId, usize, usize, Span)> = Vec::new();
    for (&id, uses) in &written {
        let name = r.alphabet.name(id);
        let checked = name.starts_with(|c: char| c.is_alphabetic())
            && !crate::turtle::COMMANDS.iter().any(|c| c.name == name);
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
    inconsistent.sort_by_key(|(_, _, _, span)| span.start);
    for (id, arity, first, span) in inconsistent {
        r.diagnostics.push(Diagnostic::error(
            "E0514",
            span,
            format!(
                "'{}' is written with {arity} parameter{} here but with {first} before; a module keeps one number of parameters",
                r.alphabet.name(id),
                if arity == 1 { "" } else { "s" },
            ),
        ));
    }
    for set in [&productions, &homomorphism, &decomposition] {
        for p in &set.productions {
            let patterns = p.left.iter().chain(std::iter::once(&p.predecessor)).chain(
                p.right.iter().filter_map(|i| match i {
                    PatternItem::Module(m) => Some(m),
                    _ => None,
                }),
            );
            for m in patterns {
                if let Some(uses) = written.get(&m.id) {
                    if !uses.iter().any(|(arity, _)| *arity == m.arity) {
                        let (arity, _) = &uses[0];
                        r.diagnostics.push(Diagnostic::error(
                            "E0511",
                            m.span.clone(),
                            format!(
                                "'{}' is matched with {} parameter{} here, but it is written with {arity} everywhere else",
                                r.alphabet.name(m.id),
                                m.arity,
                                if m.arity == 1 { "" } else { "s" }
                            ),
                        ));
                    }
                }
            }
        }
    }

    let module_count = r.alphabet.len();
    for set in [&mut productions, &mut homomorphism, &mut decomposition] {
        set.by_predecessor = vec![Vec::new(); module_count];
        for (index, p) in set.productions.iter().enumerate() {
            set.by_predecessor[p.predecessor.id.index()].push(index as u32);
        }
        unreachable_warnings(set, &r.alphabet, &mut r.diagnostics);
    }

    let mut ignored = vec![false; module_count];
    if let Some(keep) = &consider {
        ignored.iter_mut().for_each(|x| *x = true);
        for id in keep {
            ignored[id.index()] = false;
        }
    }
    for id in &ignore {
        ignored[id.index()] = true;
    }
    ignored[open.index()] = false;
    ignored[close.index()] = false;

    for marker in [groups.open, groups.separator, groups.close] {
        ignored[marker.index()] = true;
    }

    fn any_module(modules: &[SuccessorModule], f: &dyn Fn(&SuccessorModule) -> bool) -> bool {
        modules
            .iter()
            .any(|m| f(m) || m.group.iter().flatten().any(|member| any_module(member, f)))
    }
    let everywhere = |f: &dyn Fn(&SuccessorModule) -> bool| {
        any_module(&axiom, f)
            || [&productions, &homomorphism, &decomposition]
                .iter()
                .any(|set| set.productions.iter().any(|p| any_module(&p.successor, f)))
    };
    let has_groups = everywhere(&|m| m.group.is_some());
    let parametric = has_groups || everywhere(&|m| !m.args.is_empty());
    (growth.apex, growth.segment) = growth_modules(
        &r.alphabet,
        &productions,
        &homomorphism,
        &settings.draw,
        &apex,
    );

    let model = Model {
        alphabet: r.alphabet,
        axiom,
        axiom_span: axiom_span.clone(),
        productions,
        homomorphism,
        decomposition,
        random_variables,
        ignored,
        open,
        close,
        cut,
        groups,
        has_groups,
        parametric,
        settings,
        growth,
    };
    (Some(model), r.diagnostics)
}

/// For each module id: is it an apex, and is it a segment (docs/LANGUAGE.md, "Growth")? Apices
/// are the modules `#apex` lists; without it, the modules that have a production and are not
/// turtle commands, or when there are none (edge rewriting), every module that has a production.
/// Segments are the modules the turtle draws (`F`, `G`, `#draw`) and those a homomorphism
/// rewrites.
fn growth_modules(
    alphabet: &Alphabet,
    productions: &RuleSet,
    homomorphism: &RuleSet,
    draw: &[ModuleId],
    listed: &[ModuleId],
) -> (Vec<bool>, Vec<bool>) {
    use crate::turtle::{command_named, Command};
    let n = alphabet.len();
    let ids = || (0..n).map(|i| ModuleId(i as u32));
    let has_production = |id: ModuleId| {
        productions
            .by_predecessor
            .get(id.index())
            .is_some_and(|p| !p.is_empty())
    };
    let is_command = |id: ModuleId| {
        let name = alphabet.name(id);
        command_named(name).is_some()
            || draw.contains(&id)
            || name.starts_with('@')
            || name == "["
            || name == "]"
            || name == "%"
    };
    let apex: Vec<bool> = if !listed.is_empty() {
        ids().map(|id| listed.contains(&id)).collect()
    } else {
        let nodes: Vec<bool> = ids()
            .map(|id| has_production(id) && !is_command(id))
            .collect();
        if nodes.iter().any(|&x| x) {
            nodes
        } else {
            ids().map(has_production).collect()
        }
    };
    let segment = ids()
        .map(|id| {
            let draws = command_named(alphabet.name(id))
                .is_some_and(|c| matches!(c.command, Command::Forward | Command::ForwardNoVertex));
            draws
                || draw.contains(&id)
                || homomorphism
                    .by_predecessor
                    .get(id.index())
                    .is_some_and(|p| !p.is_empty())
        })
        .collect();
    (apex, segment)
}

fn section_index(section: Section) -> usize {
    match section {
        Section::Productions => 0,
        Section::Homomorphism => 1,
        Section::Decomposition => 2,
    }
}

/// Warns about productions that an earlier, unconditional one always pre-empts.
fn unreachable_warnings(set: &RuleSet, alphabet: &Alphabet, diagnostics: &mut Vec<Diagnostic>) {
    for candidates in &set.by_predecessor {
        for (k, &q) in candidates.iter().enumerate() {
            let q = &set.productions[q as usize];
            let blocker = candidates[..k]
                .iter()
                .map(|&p| &set.productions[p as usize])
                .find(|p| {
                    p.predecessor.arity == q.predecessor.arity
                        && !p.has_context()
                        && p.condition.is_none()
                        && (p.weight.is_none() || q.weight.is_none())
                });
            if let Some(p) = blocker {
                diagnostics.push(Diagnostic::warning(
                    "E0301",
                    q.span.clone(),
                    format!(
                        "this production never applies: the production at byte {} always rewrites '{}' first",
                        p.span.start,
                        alphabet.name(q.predecessor.id)
                    ),
                ));
            }
        }
    }
}

/// The formal parameters of one production: name -> slot.
#[derive(Default)]
struct Slots {
    names: Vec<String>,
}

struct ScopeView<'a> {
    slots: &'a Slots,
    defines: &'a HashMap<String, ExprSyntax>,
    random_names: &'a [String],
}

impl Scope for ScopeView<'_> {
    fn slot(&self, name: &str) -> Option<u16> {
        self.slots
            .names
            .iter()
            .position(|n| n == name)
            .map(|i| i as u16)
    }
    fn define(&self, name: &str) -> Option<&ExprSyntax> {
        self.defines.get(name)
    }
    fn random_var(&self, name: &str) -> Option<u16> {
        self.random_names
            .iter()
            .position(|n| n == name)
            .map(|i| i as u16)
    }
}

struct Resolver {
    diagnostics: Vec<Diagnostic>,
    alphabet: Alphabet,
    defines: HashMap<String, ExprSyntax>,
    random_names: Vec<String>,
}

impl Resolver {
    fn compile(&mut self, expr: &ExprSyntax, slots: &Slots) -> Option<Program> {
        let scope = ScopeView {
            slots,
            defines: &self.defines,
            random_names: &self.random_names,
        };
        match Program::compile(expr, &scope) {
            Ok(p) => Some(p),
            Err(d) => {
                self.diagnostics.push(d);
                None
            }
        }
    }

    fn successor(&mut self, modules: &[ModuleSyntax], slots: &Slots) -> Vec<SuccessorModule> {
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
        let first_slot = slots.names.len() as u16;
        for p in &m.params {
            match p {
                ExprSyntax::Name(name, span) => {
                    if slots.names.contains(name) {
                        self.diagnostics.push(Diagnostic::error(
                            "E0512",
                            span.clone(),
                            format!(
                                "the formal parameter '{name}' is bound twice in this production"
                            ),
                        ));
                    }
                    slots.names.push(name.clone());
                }
                other => {
                    self.diagnostics.push(Diagnostic::error(
                        "E0510",
                        other.span(),
                        "a parameter of a predecessor or context must be a name (a formal parameter)",
                    ));
                    slots.names.push(String::new());
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

    fn production(&mut self, p: &ProductionSyntax) -> Option<Production> {
        let errors_before = self.diagnostics.len();
        let mut slots = Slots::default();
        let predecessor = self.pattern(&p.predecessor, &mut slots);
        let left: Vec<_> = p.left.iter().map(|m| self.pattern(m, &mut slots)).collect();
        let right = p
            .right
            .iter()
            .map(|m| match m.name.as_str() {
                "[" => PatternItem::Open,
                "]" => PatternItem::Close,
                _ => PatternItem::Module(self.pattern(m, &mut slots)),
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
            .any(|d| d.severity == crate::diagnostics::Severity::Error)
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
            slots: slots.names.len(),
            span: p.span.clone(),
        })
    }

    /// The value of a directive's argument: a number or a constant expression (`#angle 360 / n`
    /// with `#define n 7`); `None` with the reason when it is not one.
    fn constant(&mut self, d: &Directive) -> Result<f64, String> {
        if d.args.is_empty() {
            return Err("nothing".into());
        }
        if let Ok(v) = d.args.parse::<f64>() {
            return if v.is_finite() {
                Ok(v)
            } else {
                Err(format!("'{}', which is too large", d.args))
            };
        }
        let quoted = |message: String| format!("'{}' ({message})", d.args);
        let expr = crate::syntax::parse_expression(&d.args, d.args_span.start)
            .map_err(|e| quoted(e.message))?;
        let scope = ScopeView {
            slots: &Slots::default(),
            defines: &self.defines,
            random_names: &[],
        };
        let program = Program::compile(&expr, &scope).map_err(|e| quoted(e.message))?;
        if program.random {
            return Err(format!("'{}', which draws random numbers", d.args));
        }
        let mut rng = rand_pcg::Pcg64Mcg::new(0);
        let mut env = super::Env {
            slots: &[],
            num_it: 0.0,
            max_it: 0.0,
            vars: &mut [],
            fresh_vars: true,
            var_programs: &[],
            rng: &mut rng,
        };
        program.eval(&mut env).map_err(|e| e.message)
    }

    /// The whitespace-separated numbers (or constant expressions without spaces) of a directive.
    fn numbers(&mut self, d: &Directive) -> Option<Vec<f64>> {
        let mut values = Vec::new();
        for word in d.args.split_whitespace() {
            let offset = word.as_ptr() as usize - d.args.as_ptr() as usize;
            let part = Directive {
                args: word.to_string(),
                args_span: d.args_span.start + offset..d.args_span.start + offset + word.len(),
                ..d.clone()
            };
            values.push(self.number(&part)?);
        }
        Some(values)
    }

    /// `#tropism x y z e`: four numbers.
    fn tropism(&mut self, d: &Directive) -> Option<(glam::DVec3, f64)> {
        let values = self.numbers(d)?;
        if values.len() != 4 {
            self.directive_error(
                "E0207",
                d,
                format!(
                    "#tropism needs four numbers: x y z e, found {}",
                    values.len()
                ),
            );
            return None;
        }
        Some((glam::DVec3::new(values[0], values[1], values[2]), values[3]))
    }

    /// `#color i r g b` sets one entry of the palette; `#color i j r g b r g b` sets entries
    /// i..=j to a linear ramp between two colours. Components are 0..=255, indices 0..=255.
    fn color(&mut self, d: &Directive, palette: &mut Vec<[f32; 3]>) {
        let Some(values) = self.numbers(d) else {
            return;
        };
        let usage = "#color needs 'index r g b' or 'first last r g b r g b' \
                     (indices 0 to 255, components 0 to 255)";
        let (first, last, from, to) = match values.as_slice() {
            [i, r, g, b] => (*i, *i, [*r, *g, *b], [*r, *g, *b]),
            [i, j, r0, g0, b0, r1, g1, b1] => (*i, *j, [*r0, *g0, *b0], [*r1, *g1, *b1]),
            _ => {
                self.directive_error(
                    "E0208",
                    d,
                    format!("{usage}, found {} numbers", values.len()),
                );
                return;
            }
        };
        let index_ok = |v: f64| v >= 0.0 && v.fract() == 0.0 && v <= MAX_COLOR_INDEX as f64;
        let component_ok = |v: &f64| (0.0..=255.0).contains(v);
        if !index_ok(first)
            || !index_ok(last)
            || last < first
            || !from.iter().all(component_ok)
            || !to.iter().all(component_ok)
        {
            self.directive_error("E0208", d, format!("{usage}, with first <= last"));
            return;
        }
        let (first, last) = (first as usize, last as usize);
        // Entries between the old end and `first` keep the colours they had by wrapping.
        let old = palette.len();
        while palette.len() <= last {
            let wrapped = palette[palette.len() % old];
            palette.push(wrapped);
        }
        for (offset, entry) in palette[first..=last].iter_mut().enumerate() {
            let t = if last == first {
                0.0
            } else {
                offset as f64 / (last - first) as f64
            };
            *entry = std::array::from_fn(|k| ((from[k] + (to[k] - from[k]) * t) / 255.0) as f32);
        }
    }

    /// The words of a directive's arguments, each as a directive of its own (for spans).
    fn words(d: &Directive) -> Vec<Directive> {
        d.args
            .split_whitespace()
            .map(|word| {
                let offset = word.as_ptr() as usize - d.args.as_ptr() as usize;
                Directive {
                    args: word.to_string(),
                    args_span: d.args_span.start + offset..d.args_span.start + offset + word.len(),
                    ..d.clone()
                }
            })
            .collect()
    }

    /// An argument that may change from step to step: an expression over `NumIt` (the step about
    /// to run), `MaxIt` and `#define`d names, drawing no random number.
    fn step_program(&mut self, word: &Directive) -> Option<Program> {
        let expr = match crate::syntax::parse_expression(&word.args, word.args_span.start) {
            Ok(e) => e,
            Err(e) => {
                self.diagnostics.push(e);
                return None;
            }
        };
        let program = self.compile(&expr, &Slots::default())?;
        if program.random {
            self.directive_error(
                "E0209",
                word,
                format!(
                    "{} cannot draw random numbers here: its own Rand() is drawn at every step",
                    word.written
                ),
            );
            return None;
        }
        Some(program)
    }

    /// Three numbers for the upper, middle and lower thirds.
    fn thirds(&mut self, words: &[Directive]) -> Option<[f64; 3]> {
        let mut v = [0.0; 3];
        for (k, w) in words.iter().enumerate() {
            v[k] = self.number(w)?;
        }
        Some(v)
    }

    /// `#lifetime MB VB [pu pm pl]`.
    fn lifetime(&mut self, d: &Directive) -> Option<crate::growth::Lifetime> {
        let words = Self::words(d);
        if words.len() != 2 && words.len() != 5 {
            self.directive_error(
                "E0209",
                d,
                format!(
                    "#lifetime needs 'MB VB' or 'MB VB pu pm pl' (the mean and variance of the \
                     surviving branches, then the shares of the upper, middle and lower thirds), \
                     found {} values",
                    words.len()
                ),
            );
            return None;
        }
        let mean = self.step_program(&words[0]);
        let variance = self.step_program(&words[1]);
        let probabilities = if words.len() == 5 {
            let p = self.thirds(&words[2..])?;
            if p.iter().any(|x| *x < 0.0) || p.iter().all(|x| *x == 0.0) {
                self.directive_error(
                    "E0209",
                    d,
                    "#lifetime's shares of the thirds must be 0 or more, and not all 0".into(),
                );
                return None;
            }
            p
        } else {
            crate::growth::DEFAULT_PROBABILITIES
        };
        Some(crate::growth::Lifetime {
            mean: mean?,
            variance: variance?,
            probabilities,
        })
    }

    /// `#speed SM VR [PFu PFm PFl]`.
    fn speed(&mut self, d: &Directive) -> Option<crate::growth::Speed> {
        let words = Self::words(d);
        if words.len() != 2 && words.len() != 5 {
            self.directive_error(
                "E0209",
                d,
                format!(
                    "#speed needs 'SM VR' or 'SM VR PFu PFm PFl' (the seasonal mean and variance \
                     of the rewritings, then the positional factors of the thirds), found {} values",
                    words.len()
                ),
            );
            return None;
        }
        let mean = self.step_program(&words[0]);
        let variance = self.step_program(&words[1]);
        let positional = if words.len() == 5 {
            self.thirds(&words[2..])?
        } else {
            crate::growth::DEFAULT_SPEED_POSITIONAL
        };
        Some(crate::growth::Speed {
            mean: mean?,
            variance: variance?,
            positional,
        })
    }

    /// `#shape GR m [VR]`.
    fn shape(&mut self, d: &Directive) -> Option<crate::growth::Shape> {
        let words = Self::words(d);
        let usage = "#shape needs 'GR m' or 'GR m VR': a growth rate above 0 other than 1, a \
                     maturity from 1 and the variance of the length";
        if words.len() != 2 && words.len() != 3 {
            self.directive_error("E0209", d, format!("{usage}, found {} values", words.len()));
            return None;
        }
        let rate = self.number(&words[0])?;
        let maturity = self.whole(&words[1], 1_000)?;
        let variance = match words.get(2) {
            Some(w) => self.number(w)?,
            None => 0.0,
        };
        if rate <= 0.0 || rate == 1.0 || maturity == 0 {
            self.directive_error("E0209", d, usage.into());
            return None;
        }
        Some(crate::growth::Shape {
            rate,
            maturity: maturity as u32,
            variance,
        })
    }

    /// `#shape_width [VR [PFu PFm PFl]]`.
    fn shape_width(&mut self, d: &Directive) -> Option<crate::growth::ShapeWidth> {
        let words = Self::words(d);
        if ![0, 1, 4].contains(&words.len()) {
            self.directive_error(
                "E0209",
                d,
                format!(
                    "#shape_width needs nothing, 'VR' or 'VR PFu PFm PFl' (the variance of the \
                     width, then the positional factors of the thirds), found {} values",
                    words.len()
                ),
            );
            return None;
        }
        let variance = match words.first() {
            Some(w) => self.number(w)?,
            None => 0.0,
        };
        let positional = if words.len() == 4 {
            self.thirds(&words[1..])?
        } else {
            crate::growth::DEFAULT_WIDTH_POSITIONAL
        };
        Some(crate::growth::ShapeWidth {
            variance,
            positional,
        })
    }

    /// `#sun latitude season angle`.
    fn sun(&mut self, d: &Directive) -> Option<crate::growth::Sun> {
        let words = Self::words(d);
        let usage = "#sun needs 'latitude season angle': a latitude from -90 to 90, a season \
                     (summer, winter, spring, autumn, fall or equinox) and the degrees per step";
        if words.len() != 3 {
            self.directive_error("E0209", d, format!("{usage}, found {} values", words.len()));
            return None;
        }
        let latitude = self.number(&words[0])?;
        let Some(season) = crate::growth::Season::named(&words[1].args) else {
            self.directive_error(
                "E0209",
                &words[1],
                format!("{usage}; '{}' is not a season", words[1].args),
            );
            return None;
        };
        let angle = self.number(&words[2])?;
        if !(-90.0..=90.0).contains(&latitude) {
            self.directive_error("E0209", &words[0], usage.into());
            return None;
        }
        Some(crate::growth::Sun {
            latitude,
            season,
            angle,
        })
    }

    /// `#gravity angle [variation]`, or with `wind`, `#wind x z angle [variation]`.
    fn bend(&mut self, d: &Directive, wind: Option<()>) -> Option<crate::growth::Bend> {
        let words = Self::words(d);
        let (skip, usage) = match wind {
            Some(()) => (
                2,
                "#wind needs 'x z angle' or 'x z angle variation': a horizontal direction other \
                 than 0 0, and the degrees per step",
            ),
            None => (
                0,
                "#gravity needs 'angle' or 'angle variation': the degrees per step",
            ),
        };
        if words.len() != skip + 1 && words.len() != skip + 2 {
            self.directive_error("E0209", d, format!("{usage}, found {} values", words.len()));
            return None;
        }
        let mut values = Vec::new();
        for w in &words {
            values.push(self.number(w)?);
        }
        let direction = if skip == 2 {
            let v = glam::DVec3::new(values[0], 0.0, values[1]);
            if v.length() == 0.0 {
                self.directive_error("E0209", d, usage.into());
                return None;
            }
            v.normalize()
        } else {
            glam::DVec3::NEG_Y
        };
        Some(crate::growth::Bend {
            direction,
            angle: values[skip],
            variance: values.get(skip + 1).copied().unwrap_or(0.0),
        })
    }

    fn directive_error(&mut self, code: &'static str, d: &Directive, message: String) {
        let span = if d.args.is_empty() {
            d.name_span.clone()
        } else {
            d.args_span.clone()
        };
        self.diagnostics
            .push(Diagnostic::error(code, span, message));
    }

    fn number(&mut self, d: &Directive) -> Option<f64> {
        match self.constant(d) {
            Ok(v) => Some(v),
            Err(found) => {
                self.directive_error(
                    "E0203",
                    d,
                    format!("{} needs a number, found {found}", d.written),
                );
                None
            }
        }
    }

    fn whole(&mut self, d: &Directive, max: u64) -> Option<u64> {
        match self.constant(d) {
            Ok(v) if v >= 0.0 && v.fract() == 0.0 && v <= max as f64 => Some(v as u64),
            result => {
                let found = result.map_or_else(|e| e, |v| format!("{v}"));
                self.directive_error(
                    "E0204",
                    d,
                    format!(
                        "{} needs a whole number from 0 to {max}, found {found}",
                        d.written
                    ),
                );
                None
            }
        }
    }
}
