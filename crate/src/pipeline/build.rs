//! [`build`]: every stage run on a grammar's text, into a [`Build`] (the diagnostics, the model,
//! the derivation, the growth record, the plant), and what a caller asks of a build afterwards.

use super::hooks::Watch;
use super::observer::derive_stage;
use super::step_on;
use super::{Hooks, Inspector, Plant, Progress, Stage, StageTimings};
use crate::derive::{Derivation, DeriveOptions};
use crate::diagnostics::{has_errors, locate_all, Diagnostic, LocatedDiagnostic};
use crate::growth::{Adjustments, GrowthRecord};
use crate::mesh::MeshOptions;
use crate::model::{self, Model};
use crate::syntax;
use crate::turtle;

/// Options of one build; `None` fields take the grammar's own settings.
#[derive(Clone, Debug, Default)]
pub struct BuildOptions {
    /// Overrides `#iterations`.
    pub iterations: Option<u32>,
    /// Overrides `#seed`.
    pub seed: Option<u64>,
    /// The growth time in steps, overriding `iterations` (docs/LANGUAGE.md, "Timed modules"): a
    /// timed grammar is derived to time `time · #dt`, between steps when it is a fraction; any
    /// other grammar derives its whole steps, `floor(time)`. Below 0 or not finite counts as 0.
    pub time: Option<f64>,
    pub mesh: MeshOptions,
    /// Draw the segments as lines only (a sketch, [`turtle::Sketch`]): no skeleton and no mesh
    /// until [`Build::remesh`] (or [`Build::ensure_skeleton`]) asks for them. Grammars with growth
    /// attributes draw their skeleton at once and mesh it with `mesh` as usual.
    pub sketch: bool,
}

#[cfg(test)]
impl BuildOptions {
    /// The default options with `n` iterations (the tests' usual build).
    pub(crate) fn with_iterations(n: u32) -> Self {
        BuildOptions {
            iterations: Some(n),
            ..BuildOptions::default()
        }
    }
}

/// Everything one build produced. When `diagnostics` has an error, the stages after the failing
/// one did not run and what they make is empty.
#[derive(Debug, Default)]
pub struct Build {
    pub diagnostics: Vec<Diagnostic>,
    pub model: Option<Model>,
    /// The derived string and where its modules come from.
    pub derivation: Derivation,
    /// The steps run and the seed that overrode `#seed`, if any.
    pub derived_with: DeriveOptions,
    /// With growth attributes (`#lifetime`, `#shape`, `#sun`, …): each module's growth state and
    /// what every step did (apices growing and stopped per third, rewritings).
    pub growth: Option<GrowthRecord>,
    pub plant: Plant,
    /// How many elements the plant had after each step, 0 to N, when the mesh options asked for
    /// growth in time (`Skeleton::step_counts`); empty otherwise.
    pub step_counts: Vec<f64>,
    /// How long each stage took, when the caller lent a clock.
    pub timings: Option<StageTimings>,
    /// The step the derivation went on from when it continued an earlier build's
    /// ([`super::build_on`]); `None` when it derived from the axiom.
    pub continued_from: Option<u32>,
    /// Where each plant of a stand stands (`#stand`, `#plant`; docs/LANGUAGE.md, "Stands"), in
    /// the order of the derived string, which holds each plant inside `[ @M(x, y, z) … ]`; empty
    /// for a single plant.
    #[cfg(feature = "environment")]
    pub plant_offsets: Vec<[f64; 3]>,
    /// What the views draw of the environment after the last step (the light grid, obstacles,
    /// attraction points); `None` for a grammar that declares none or was not derived with it.
    #[cfg(feature = "environment")]
    pub environment: Option<super::EnvironmentView>,
}

/// [`crate::turtle::MAX_COORDINATE`] as `{:e}` writes it, for the clamping warning: a constant
/// text, so that the first plant's core carries no float-to-exponent formatting (issue 22; a test
/// checks it against the number).
pub(super) const MAX_COORDINATE_TEXT: &str = "1e30";

impl Build {
    /// True when no diagnostic is an error (the geometry is complete).
    pub fn ok(&self) -> bool {
        !has_errors(&self.diagnostics)
    }

    /// The derived string in canonical text form.
    pub fn derived_text(&self) -> String {
        self.model
            .as_ref()
            .map(|m| self.derivation.string.to_text(&m.alphabet))
            .unwrap_or_default()
    }

    /// Questions about the derivation, when there is a model.
    pub fn inspector(&self) -> Option<Inspector<'_>> {
        Some(Inspector::new(
            self.model.as_ref()?,
            &self.derivation,
            self.derived_with.clone(),
        ))
    }

    /// Meshes the plant again with other mesh options (a view option such as the number of sides
    /// or smooth axes needs no new derivation).
    pub fn remesh(&mut self, options: &MeshOptions) {
        self.remesh_with(options, &mut Hooks::default());
    }

    /// [`Build::remesh`], timed with the caller's clock when the build was: drawing a sketch's
    /// skeleton adds to [`StageTimings::interpret`], meshing to [`StageTimings::mesh`] (a
    /// sketched build's mesh stage is then the tubes', not only its lines').
    pub fn remesh_with(&mut self, options: &MeshOptions, hooks: &mut Hooks) {
        let mut watch = Watch::new(hooks);
        self.ensure_skeleton();
        if self.plant.is_lines_only() {
            return;
        }
        let interpret = watch.lap();
        self.plant.remesh(options);
        // Other sides or smooth axes may pass the mesh's limit, or come back within it.
        self.diagnostics.retain(|d| d.code != "E0417");
        if let Some(model) = &self.model {
            let warning = super::budget::shapes_left_out(model, &self.plant);
            self.diagnostics.extend(warning);
        }
        let mesh = watch.lap();
        if let Some(timings) = self.timings.as_mut() {
            timings.interpret += interpret;
            timings.mesh += mesh;
        }
    }

    /// Draws the skeleton of a sketch's plant ([`BuildOptions::sketch`]), once; nothing otherwise,
    /// nor for a plant whose skeleton would pass its budget ([`Plant::is_lines_only`]).
    pub fn ensure_skeleton(&mut self) {
        if !self.plant.is_sketch() || self.plant.is_lines_only() {
            return;
        }
        let segments = self.plant.stats.segments;
        let mut skeleton: turtle::Skeleton = match &self.model {
            Some(model) => {
                turtle::interpret_sized(model, self.derivation.turtle_string(), None, segments)
            }
            None => Default::default(),
        };
        skeleton.step_counts = self.step_counts.clone();
        self.plant.set_skeleton(skeleton);
    }

    /// Diagnostics with line and column, in source order.
    pub fn located_diagnostics(&self, source: &str) -> Vec<LocatedDiagnostic> {
        locate_all(source, &self.diagnostics)
    }
}

/// Runs every stage on `source`.
pub fn build(source: &str, options: &BuildOptions) -> Build {
    build_with(source, options, &mut Hooks::default())
}

/// Runs every stage on `source`, with the caller's clock and progress callback.
pub fn build_with(source: &str, options: &BuildOptions, hooks: &mut Hooks) -> Build {
    let mut watch = Watch::new(hooks);
    let mut result = run_stages(source, options, None, &mut watch);
    result.timings = watch.timings();
    result
}

/// The stages, each timed; a stage that fails leaves the later ones out. The derivation goes on
/// from `from`'s when it can ([`super::step_on`]).
pub(super) fn run_stages(
    source: &str,
    options: &BuildOptions,
    from: Option<&Build>,
    watch: &mut Watch<'_, '_>,
) -> Build {
    let mut result = Build::default();
    watch.start(Stage::Parse);
    let (file, diagnostics) = syntax::parse(source);
    result.diagnostics = diagnostics;
    let (model, diagnostics) = model::resolve(&file);
    result.diagnostics.extend(diagnostics);
    watch.timings.parse_resolve = watch.lap();
    let Some(model) = model else { return result };
    if !result.ok() {
        result.model = Some(model);
        return result;
    }
    let (steps, time) = steps_and_time(&model, options);
    if let Some(error) = step_limit_error(&model, steps) {
        result.diagnostics.push(error);
        result.model = Some(model);
        return result;
    }
    watch.start(Stage::Derive);
    let derive = DeriveOptions {
        steps,
        seed: options.seed,
        time,
    };
    // A continued derivation starts at the step its earlier build stopped at; growth times count
    // the elements of every step from the axiom, so a build that asks for them derives again.
    let count = options.mesh.with_growth();
    let from = from.filter(|_| !count);
    let from = from.and_then(|from| step_on::continuable(from, &model, &derive));
    result.continued_from = from.and_then(|f| f.resume.as_ref()).map(|r| r.steps);
    let first = result.continued_from.unwrap_or(0);
    watch.hooks.tell(Progress::Derived { step: first, steps });
    let derived = derive_told(&model, derive, from, count, &mut result, watch.hooks, steps);
    watch.timings.derive = watch.lap();
    if let Some(adjustments) = derived {
        interpret_and_mesh(&model, options, steps, adjustments, &mut result, watch);
    }
    result.model = Some(model);
    result
}

/// The derive stage ([`derive_stage`], or the environment's cycle when the grammar declares an
/// environment), telling `hooks` each of the `steps` steps done (and each answer pass).
fn derive_told(
    model: &Model,
    derive: DeriveOptions,
    from: Option<&Derivation>,
    count: bool,
    result: &mut Build,
    hooks: &mut Hooks,
    steps: u32,
) -> Option<Option<Adjustments>> {
    #[cfg(feature = "environment")]
    if super::environment::runs(model) {
        let mut told = |progress: Progress| hooks.tell(progress.within(steps));
        return super::environment::derive_stage(model, derive, count, result, &mut told);
    }
    // A timed grammar's rounds of replacements may outnumber its steps: progress stays within.
    let mut stepped = |step: u32| {
        hooks.tell(Progress::Derived {
            step: step.min(steps),
            steps,
        })
    };
    derive_stage(model, derive, from, count, result, &mut stepped)
}

/// What the turtle drew: a sketch's lines, or the skeleton.
enum Drawn {
    Sketch(turtle::Sketch),
    Skeleton(turtle::Skeleton),
}

/// The turtle and the mesh stages: the segments as lines when the options ask for a sketch (and
/// growth does not adjust the turtle), else the skeleton, adjusted by growth, and its mesh.
fn interpret_and_mesh(
    model: &Model,
    options: &BuildOptions,
    steps: u32,
    adjustments: Option<Adjustments>,
    result: &mut Build,
    watch: &mut Watch<'_, '_>,
) {
    watch.start(Stage::Interpret);
    let derivation = &result.derivation;
    let turtle_string = derivation.turtle_string();
    let size = turtle::drawing_size(model, turtle_string, &derivation.id_counts);
    let lines_only = !size.skeleton_fits();
    if !size.sketch_fits() || (lines_only && adjustments.is_some()) {
        let error = super::budget::too_large(model, steps, &size, adjustments.is_some());
        result.diagnostics.push(error);
        return;
    }
    let drawn = match adjustments {
        None if options.sketch || lines_only => Drawn::Sketch(turtle::sketch_counted(
            model,
            turtle_string,
            &derivation.id_counts,
            size.segments,
        )),
        adjustments => {
            let mut skeleton =
                turtle::interpret_sized(model, turtle_string, adjustments.as_ref(), size.segments);
            skeleton.step_counts = result.step_counts.clone();
            Drawn::Skeleton(skeleton)
        }
    };
    watch.timings.interpret = watch.lap();
    let clamped = match &drawn {
        Drawn::Sketch(sketch) => sketch.clamped(),
        Drawn::Skeleton(skeleton) => skeleton.clamped,
    };
    if let Some(module) = clamped {
        let warning = clamped_warning(model, &result.derivation, module);
        result.diagnostics.push(warning);
    }
    watch.start(Stage::Mesh);
    let (mesh, derivation) = (&options.mesh, &result.derivation);
    result.plant = match drawn {
        Drawn::Sketch(sketch) => Plant::sketched(sketch, mesh, derivation, steps),
        Drawn::Skeleton(skeleton) => Plant::new(skeleton, mesh, derivation, steps),
    };
    let left_out = super::budget::shapes_left_out(model, &result.plant);
    result.diagnostics.extend(left_out);
    if lines_only {
        result.plant.keep_lines_only();
        let warning = super::budget::lines_only(model, steps, &size);
        result.diagnostics.push(warning);
    }
    watch.timings.mesh = watch.lap();
}

/// `E0202` when `steps` is more than `#max_steps`.
fn step_limit_error(model: &Model, steps: u32) -> Option<Diagnostic> {
    let max = model.settings.max_steps;
    (steps > max).then(|| {
        Diagnostic::error(
            "E0202",
            model.settings.iterations_span.clone().unwrap_or(0..0),
            format!(
                "{steps} iterations are more than the step limit {max}; raise it with '{} {steps}'",
                crate::vocabulary::DirectiveKind::MaxSteps.written(),
            ),
        )
    })
}

/// The steps to derive and the growth time ([`BuildOptions::time`]): a time overrides the
/// iterations; a timed grammar derives up to the step after it, any other its whole steps.
pub(super) fn steps_and_time(model: &Model, options: &BuildOptions) -> (u32, Option<f64>) {
    let time = options
        .time
        .map(|t| if t.is_finite() { t.max(0.0) } else { 0.0 });
    let whole = |t: f64| t.min(u32::MAX as f64) as u32;
    let steps = match time {
        Some(t) if !model.settings.timed() => whole(t.floor()),
        Some(t) => whole(t.ceil()),
        None => options.iterations.unwrap_or(model.settings.iterations),
    };
    (steps, time)
}

/// `E0406`: the module at `module` of the turtle's string drew past the skeleton's bounds; at
/// the production that wrote it in the last step (else the axiom).
fn clamped_warning(model: &Model, derivation: &Derivation, module: u32) -> Diagnostic {
    let turtle = derivation.turtle_string();
    let name = turtle
        .ids
        .get(module as usize)
        .map_or("?", |&id| model.alphabet.name(id));
    let in_string = derivation
        .turtle_origin
        .get(module as usize)
        .copied()
        .unwrap_or(module);
    let span = derivation
        .origin()
        .get(in_string as usize)
        .and_then(|&p| model.productions.productions.get(p as usize))
        .map_or_else(|| model.axiom_span.clone(), |p| p.span.clone());
    Diagnostic::warning(
        "E0406",
        span,
        format!(
            "'{name}' (module {} of the string) draws past ±{MAX_COORDINATE_TEXT} or with a \
             number that is not finite; its geometry is clamped so that the view and every file \
             stay valid",
            module as u64 + 1,
        ),
    )
}
