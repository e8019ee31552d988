//! Resolve: syntax tree -> [`Model`]. Interns module names and gives each its meaning from the
//! vocabulary, reads directive arguments by the kinds the vocabulary declares
//! ([`directives`]), binds formal parameters to slots and compiles every expression
//! ([`rules`]), checks arities, and indexes productions by predecessor.

mod definitions;
mod directives;
#[cfg(feature = "environment")]
mod environment;
mod rules;
mod scope;
#[cfg(feature = "surfaces")]
mod surfaces;
mod timed;

use super::{Alphabet, Curve, GroupIds, Model, ModuleId, RuleSet, SuccessorModule, SurfaceShape};
use crate::diagnostics::Diagnostic;
use crate::syntax::{ExprSyntax, Section, SourceFile};
use crate::vocabulary::{module_named, name_of, Command, GroupKind, Meaning, ModuleInfo, MODULES};
use directives::DirectiveValues;
use scope::Slots;
use std::collections::HashMap;
use std::sync::Arc;

/// Resolves a parsed file. Returns `None` for the model when there is nothing to derive (no
/// axiom); otherwise a model plus every diagnostic, even when some are errors.
// (Without the feature `environment` the model keeps no environment: only its declared flag.)
#[cfg_attr(not(feature = "environment"), allow(unused_variables))]
pub fn resolve(file: &SourceFile) -> (Option<Model>, Vec<Diagnostic>) {
    let mut r = Resolver::new();
    let fixed = r.fixed_ids();
    r.dt = timed::written_dt(file).unwrap_or(r.dt);
    let randoms = r.definitions(file);
    let mut values = r.directives(file);
    r.surface_settings(file, &mut values.settings);
    let environment = r.environment_settings(file, &mut values.settings);
    let random_variables = r.random_variables(&randoms);

    let Some((axiom_syntax, axiom_span)) = &file.axiom else {
        r.diagnostics.push(Diagnostic::error(
            "E0300",
            0..0,
            "the grammar has no axiom: add a line 'axiom: …'",
        ));
        return (None, r.diagnostics);
    };
    let axiom = r.successor(axiom_syntax, &Slots::default());
    let [mut productions, mut homomorphism, mut decomposition] = r.rule_sets(file);
    productions.max_depth = 1;
    homomorphism.max_depth = values.homomorphism_depth;
    decomposition.max_depth = values.decomposition_depth;
    r.check_arities(&axiom, [&productions, &homomorphism, &decomposition]);
    r.check_timed(
        &values,
        &axiom,
        [&productions, &homomorphism, &decomposition],
    );
    for set in [&mut productions, &mut homomorphism, &mut decomposition] {
        r.index(set, file);
    }

    let sets = [&productions, &homomorphism, &decomposition];
    let meanings = r.meanings_and_surfaces(&values.settings, &axiom, sets);
    let ignored = ignored(&r.alphabet, &values, &fixed);
    let everywhere = |f: &dyn Fn(&SuccessorModule) -> bool| {
        any_module(&axiom, f)
            || [&productions, &homomorphism, &decomposition]
                .iter()
                .any(|set| set.productions.iter().any(|p| any_module(&p.successor, f)))
    };
    let has_groups = everywhere(&|m| m.group.is_some());
    let parametric = has_groups || everywhere(&|m| !m.args.is_empty());
    let mut growth = values.growth;
    (growth.apex, growth.segment) = growth_modules(
        &r.alphabet,
        &meanings,
        &productions,
        &homomorphism,
        &values.apex,
    );

    let mut in_axiom = vec![false; r.alphabet.len()];
    mark_modules(&axiom, &mut in_axiom);
    let model = Model {
        axiom_ids: axiom.iter().map(|m| m.id).collect(),
        in_axiom,
        alphabet: r.alphabet,
        axiom,
        axiom_span: axiom_span.clone(),
        productions,
        homomorphism,
        decomposition,
        random_variables,
        ignored,
        open: fixed.open,
        close: fixed.close,
        cut: fixed.cut,
        groups: fixed.groups,
        has_groups,
        parametric,
        settings: values.settings,
        meanings,
        growth,
        #[cfg(feature = "environment")]
        environment,
    };
    (Some(model), r.diagnostics)
}

/// The resolver's state while it walks the file.
struct Resolver {
    diagnostics: Vec<Diagnostic>,
    alphabet: Alphabet,
    /// `#define` names and their expressions (inlined where they are used).
    defines: HashMap<String, ExprSyntax>,
    /// The `#define` names in source order.
    define_order: Vec<String>,
    /// The value of each `#define` whose expression is a constant, computed once.
    define_values: HashMap<String, f64>,
    /// `#random` names and each variable's index (the order the directives give them).
    random_names: HashMap<String, u16>,
    /// `#curve` and `#table` functions by name.
    curves: HashMap<String, Arc<Curve>>,
    /// `#dt`, read before anything is compiled (expressions fold `dt` to it).
    dt: f64,
}

/// The ids every model has, interned first and always in this order.
struct FixedIds {
    open: ModuleId,
    close: ModuleId,
    cut: [ModuleId; 2],
    groups: GroupIds,
}

impl Resolver {
    fn new() -> Self {
        Resolver {
            diagnostics: Vec::new(),
            alphabet: Alphabet::default(),
            defines: HashMap::new(),
            define_order: Vec::new(),
            define_values: HashMap::new(),
            random_names: HashMap::new(),
            curves: HashMap::new(),
            dt: crate::model::settings::directive_default(crate::vocabulary::DirectiveKind::Dt, 0),
        }
    }

    /// Interns the branch brackets, the cut modules, the control modules and the group markers.
    fn fixed_ids(&mut self) -> FixedIds {
        let mut intern = |meaning| self.alphabet.intern(name_of(meaning));
        let open = intern(Meaning::Turtle(Command::Push));
        let close = intern(Meaning::Turtle(Command::Pop));
        let mut cuts = MODULES.iter().filter(|m| m.meaning == Meaning::Cut);
        let mut next_cut = || cuts.next().map_or("", |m| m.name);
        let cut = [next_cut(), next_cut()].map(|name| self.alphabet.intern(name));
        let mut group = |kind| self.alphabet.intern(name_of(Meaning::Group(kind)));
        let (switch, pendulum, repeat) = (
            group(GroupKind::Switch),
            group(GroupKind::Pendulum),
            group(GroupKind::Repeat),
        );
        let [open_marker, separator, close_marker] =
            GroupIds::MARKERS.map(|name| self.alphabet.intern(name));
        FixedIds {
            open,
            close,
            cut,
            groups: GroupIds {
                switch,
                pendulum,
                repeat,
                open: open_marker,
                separator,
                close: close_marker,
            },
        }
    }

    /// The productions of each section, resolved.
    fn rule_sets(&mut self, file: &SourceFile) -> [RuleSet; 3] {
        let mut sets = [RuleSet::default(), RuleSet::default(), RuleSet::default()];
        for p in &file.productions {
            if let Some(production) = self.production(p) {
                let index = match p.section {
                    Section::Productions => 0,
                    Section::Homomorphism => 1,
                    Section::Decomposition => 2,
                };
                sets[index].productions.push(production);
            }
        }
        sets
    }
}

impl Resolver {
    /// Whether the file declares surfaces, and (with the feature `surfaces`) what they are.
    fn surface_settings(&mut self, file: &SourceFile, settings: &mut super::Settings) {
        use crate::vocabulary::DirectiveKind::{Patch, Surface};
        settings.surfaces_declared = file
            .directives
            .iter()
            .any(|d| matches!(d.kind, Some(Surface | Patch)));
        #[cfg(feature = "surfaces")]
        {
            settings.surfaces = self.surfaces(file);
        }
    }

    /// Whether the file declares an environment, and (with the feature `environment`) what it is.
    fn environment_settings(
        &mut self,
        file: &SourceFile,
        settings: &mut super::Settings,
    ) -> super::EnvironmentSpec {
        use crate::vocabulary::DirectiveKind::{Environment, Plant, Stand};
        settings.environment_declared = file
            .directives
            .iter()
            .any(|d| matches!(d.kind, Some(Environment | Stand | Plant)));
        #[cfg(feature = "environment")]
        if settings.environment_declared {
            let environment = self.environment(file, settings.seed);
            if !environment.plants.is_empty() {
                // The module that places each plant of a stand in the string the views read.
                self.alphabet
                    .intern(name_of(Meaning::Turtle(Command::MoveTo)));
            }
            return environment;
        }
        super::EnvironmentSpec::default()
    }

    /// [`meanings`], warning of each `~X` drawn but not declared.
    fn meanings_and_surfaces(
        &mut self,
        settings: &super::Settings,
        axiom: &[SuccessorModule],
        sets: [&RuleSet; 3],
    ) -> Vec<Option<&'static ModuleInfo>> {
        let meanings = meanings(&self.alphabet, &settings.draw, &settings.surfaces);
        #[cfg(feature = "surfaces")]
        self.check_surfaces_drawn(&meanings, &settings.surfaces, axiom, sets);
        #[cfg(not(feature = "surfaces"))]
        let _ = (axiom, sets);
        meanings
    }
}

/// For each module id: its vocabulary row (`F`'s for the modules `#draw` lists, `~X`'s for the
/// surfaces `#surface` and `#patch` declare, `~l` and `~p` too).
fn meanings(
    alphabet: &Alphabet,
    draw: &[ModuleId],
    surfaces: &[Arc<SurfaceShape>],
) -> Vec<Option<&'static ModuleInfo>> {
    let forward = module_named(name_of(Meaning::Turtle(Command::Forward)));
    let surface = module_named(name_of(Meaning::Turtle(Command::Surface)));
    (0..alphabet.len())
        .map(|i| {
            let id = ModuleId(i as u32);
            if draw.contains(&id) {
                forward
            } else if cfg!(feature = "surfaces")
                && surface_index(alphabet.name(id), surfaces).is_some()
            {
                surface
            } else {
                module_named(alphabet.name(id))
            }
        })
        .collect()
}

/// The index in `surfaces` of the surface a module named `name` draws (`~X` with X declared).
pub fn surface_index(name: &str, surfaces: &[Arc<SurfaceShape>]) -> Option<usize> {
    let letter = surface_letter(name)?;
    surfaces.iter().position(|s| s.letter == letter)
}

/// X, for a module name `~X` of one ASCII letter.
fn surface_letter(name: &str) -> Option<char> {
    let surface = name_of(Meaning::Turtle(Command::Surface));
    let prefix = surface.strip_suffix(|c: char| c.is_ascii_alphabetic())?;
    match *name.strip_prefix(prefix)?.as_bytes() {
        [c] if c.is_ascii_alphabetic() => Some(char::from(c)),
        _ => None,
    }
}

/// For each module id: skipped by context matching (`#ignore`, or left out by `#consider`). The
/// branch brackets never are; the group markers always are.
fn ignored(alphabet: &Alphabet, values: &DirectiveValues, fixed: &FixedIds) -> Vec<bool> {
    let mut ignored = vec![false; alphabet.len()];
    if let Some(keep) = &values.consider {
        ignored.iter_mut().for_each(|x| *x = true);
        for id in keep {
            ignored[id.index()] = false;
        }
    }
    for id in &values.ignore {
        ignored[id.index()] = true;
    }
    ignored[fixed.open.index()] = false;
    ignored[fixed.close.index()] = false;
    let g = &fixed.groups;
    for marker in [g.open, g.separator, g.close] {
        ignored[marker.index()] = true;
    }
    ignored
}

/// True when `f` holds for a module of `modules` or of a control module's members.
/// Sets `used[id]` for every module of `modules`, the members of control modules too.
fn mark_modules(modules: &[SuccessorModule], used: &mut [bool]) {
    for m in modules {
        used[m.id.index()] = true;
        for member in m.group.iter().flatten() {
            mark_modules(member, used);
        }
    }
}

fn any_module(modules: &[SuccessorModule], f: &dyn Fn(&SuccessorModule) -> bool) -> bool {
    modules
        .iter()
        .any(|m| f(m) || m.group.iter().flatten().any(|member| any_module(member, f)))
}

/// For each module id: is it an apex, and is it a segment (docs/LANGUAGE.md, "Growth")? Apices
/// are the modules `#apex` lists; without it, the modules that have a production and have no
/// meaning for the turtle or derivation (nor an `@` name), or when there are none (edge
/// rewriting), every module that has a production. Segments are the modules the turtle draws
/// (`F`, `G`, `#draw`) and those a homomorphism rewrites.
fn growth_modules(
    alphabet: &Alphabet,
    meanings: &[Option<&'static ModuleInfo>],
    productions: &RuleSet,
    homomorphism: &RuleSet,
    listed: &[ModuleId],
) -> (Vec<bool>, Vec<bool>) {
    let ids = || (0..alphabet.len()).map(|i| ModuleId(i as u32));
    let rewrites = |set: &RuleSet, id: ModuleId| {
        set.by_predecessor
            .get(id.index())
            .is_some_and(|p| !p.is_empty())
    };
    let has_meaning =
        |id: ModuleId| meanings[id.index()].is_some() || alphabet.name(id).starts_with('@');
    let apex: Vec<bool> = if !listed.is_empty() {
        ids().map(|id| listed.contains(&id)).collect()
    } else {
        let nodes: Vec<bool> = ids()
            .map(|id| rewrites(productions, id) && !has_meaning(id))
            .collect();
        if nodes.iter().any(|&x| x) {
            nodes
        } else {
            ids().map(|id| rewrites(productions, id)).collect()
        }
    };
    let segment = ids()
        .map(|id| {
            let draws = meanings[id.index()]
                .and_then(ModuleInfo::command)
                .is_some_and(Command::draws);
            draws || rewrites(homomorphism, id)
        })
        .collect();
    (apex, segment)
}

#[cfg(test)]
mod tests;
