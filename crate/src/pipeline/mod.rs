//! The whole pipeline, parse -> resolve -> derive -> (growth) -> interpret -> mesh, as one call
//! shared by the command-line tool and the wasm boundary, and what a caller does with its result.
//!
//! - [`build`] runs every stage and returns a [`Build`]: the diagnostics, the model, the
//!   [`Derivation`], the growth record and the [`Plant`] (skeleton, mesh, stats);
//! - [`Build::inspector`] answers questions about the derivation ([`Inspector`]: why a production
//!   fired, the text of the derived string);
//! - [`PlantEditor`] edits the plant's branches by their Bézier handles;
//! - [`export`] builds and writes a model file, the same bytes for the CLI and the studio.
//!
//! The core reads no clock and knows nothing of progress bars: a caller lends [`Hooks`] (a clock
//! read around each stage, a callback told each stage as it starts and each derivation step as it
//! ends).

mod editor;
mod export;
mod inspector;
mod plant;

pub use editor::{BranchInfo, PlantEditor};
pub use export::{export, ExportError, ExportOptions, Exported};
pub use inspector::{Explained, Inspector};
pub use plant::Plant;

use crate::derive::{self, Derivation, DeriveOptions};
use crate::diagnostics::{has_errors, locate_all, Diagnostic, LocatedDiagnostic};
use crate::growth::{Adjustments, GrowthRecord, GrowthTracker};
use crate::mesh::MeshOptions;
use crate::model::{self, LString, Model};
use crate::syntax;
use crate::turtle;
use serde::Serialize;

/// Options of one build; `None` fields take the grammar's own settings.
#[derive(Clone, Debug, Default)]
pub struct BuildOptions {
    /// Overrides `#iterations`.
    pub iterations: Option<u32>,
    /// Overrides `#seed`.
    pub seed: Option<u64>,
    pub mesh: MeshOptions,
    /// Draw the segments as lines only (a sketch, [`turtle::Sketch`]): no skeleton and no mesh
    /// until [`Build::remesh`] (or [`Build::ensure_skeleton`]) asks for them. Grammars with growth
    /// attributes draw their skeleton at once and mesh it with `mesh` as usual.
    pub sketch: bool,
}

/// A stage of a build or an export, in order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Parse,
    Derive,
    Interpret,
    Mesh,
    /// Exports only, with branch edits.
    ApplyEdits,
    /// Exports only.
    Write,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Stage; 6] = [
        Stage::Parse,
        Stage::Derive,
        Stage::Interpret,
        Stage::Mesh,
        Stage::ApplyEdits,
        Stage::Write,
    ];

    /// What a progress line says while the stage runs: `parsing`, `deriving`, …
    pub fn label(self) -> &'static str {
        match self {
            Stage::Parse => "parsing",
            Stage::Derive => "deriving",
            Stage::Interpret => "interpreting",
            Stage::Mesh => "meshing",
            Stage::ApplyEdits => "applying edits",
            Stage::Write => "writing",
        }
    }
}

/// Where a build or an export is, as its progress callback is told.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// A stage starts.
    Started(Stage),
    /// `step` of the derivation's `steps` steps are done: told with 0 as derivation starts, then
    /// after each step, so a long derivation can say "step k of n".
    Derived { step: u32, steps: u32 },
}

/// What a caller lends a build. Both are optional; neither changes the result.
#[derive(Default)]
pub struct Hooks<'a> {
    /// Any monotonic clock (the studio's and the CLI's are in milliseconds), read before and after
    /// each stage to fill [`Build::timings`].
    pub clock: Option<&'a mut dyn FnMut() -> f64>,
    /// Told each stage as it starts and each derivation step as it ends.
    pub progress: Option<&'a mut dyn FnMut(Progress)>,
}

impl Hooks<'_> {
    /// Tells the progress callback that `stage` starts.
    pub fn start(&mut self, stage: Stage) {
        self.tell(Progress::Started(stage));
    }

    fn tell(&mut self, progress: Progress) {
        if let Some(callback) = self.progress.as_mut() {
            callback(progress);
        }
    }
}

/// The hooks of one run, with the time of the last lap.
struct Watch<'h, 'a> {
    hooks: &'h mut Hooks<'a>,
    last: Option<f64>,
    timings: StageTimings,
}

impl<'h, 'a> Watch<'h, 'a> {
    fn new(hooks: &'h mut Hooks<'a>) -> Self {
        let last = hooks.clock.as_mut().map(|now| now());
        Watch {
            hooks,
            last,
            timings: StageTimings::default(),
        }
    }

    fn start(&mut self, stage: Stage) {
        self.hooks.start(stage);
    }

    /// The time since the previous lap (0 without a clock).
    fn lap(&mut self) -> f64 {
        let (Some(now), Some(last)) = (self.hooks.clock.as_mut(), self.last) else {
            return 0.0;
        };
        let time = now();
        self.last = Some(time);
        (time - last).max(0.0)
    }

    /// The timings, when there is a clock.
    fn timings(&self) -> Option<StageTimings> {
        self.last.map(|_| self.timings)
    }
}

/// Everything one build produced. When `diagnostics` has an error, the stages after the failing
/// one did not run and what they make is empty.
#[derive(Clone, Debug, Default)]
pub struct Build {
    pub diagnostics: Vec<Diagnostic>,
    pub model: Option<Model>,
    /// The derived string and where its modules come from.
    pub derivation: Derivation,
    /// Derivation steps run.
    pub steps: u32,
    /// The seed that overrode `#seed`, if any.
    pub seed: Option<u64>,
    /// With growth attributes (`#lifetime`, `#shape`, `#sun`, …): each module's growth state and
    /// what every step did (apices growing and stopped per third, rewritings).
    pub growth: Option<GrowthRecord>,
    pub plant: Plant,
    /// How long each stage took, when the caller lent a clock.
    pub timings: Option<StageTimings>,
}

/// [`crate::turtle::MAX_COORDINATE`] as `{:e}` writes it, for the clamping warning: a constant
/// text, so that the first plant's core carries no float-to-exponent formatting (issue 22; a test
/// checks it against the number).
const MAX_COORDINATE_TEXT: &str = "1e30";

/// Wall-clock time of each stage of one build, in the unit of the caller's clock (milliseconds
/// for the studio and the CLI). A stage that did not run (after an error) took 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct StageTimings {
    /// Parsing the text and resolving it into a model.
    pub parse_resolve: f64,
    /// Deriving the string (including the turtle runs that feed query modules and growth).
    pub derive: f64,
    /// Interpreting the string with the turtle into a skeleton.
    pub interpret: f64,
    /// Building the mesh from the skeleton.
    pub mesh: f64,
}

impl StageTimings {
    /// One JSON object, e.g. `{"parseResolve":0.1,"derive":0.4,"interpret":0.9,"mesh":2.5}`.
    /// Written by hand with `Display` (which the module texts need anyway), not serde_json: its
    /// float writer would be one more in the first plant's core (issue 22). The text is serde_json's
    /// for every time a clock gives (a whole number keeps its `.0`; only below 1e-5 or from 1e16
    /// up would serde_json write an exponent, the same number); a time that is not finite is
    /// `null`, as serde_json writes it.
    pub fn to_json(&self) -> String {
        let number = |v: f64| {
            if !v.is_finite() {
                "null".to_string()
            } else if v.fract() == 0.0 {
                format!("{v}.0")
            } else {
                format!("{v}")
            }
        };
        format!(
            "{{\"parseResolve\":{},\"derive\":{},\"interpret\":{},\"mesh\":{}}}",
            number(self.parse_resolve),
            number(self.derive),
            number(self.interpret),
            number(self.mesh)
        )
    }
}

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
        let options = DeriveOptions {
            steps: self.steps,
            seed: self.seed,
        };
        Some(Inspector::new(
            self.model.as_ref()?,
            &self.derivation,
            options,
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
        let interpret = watch.lap();
        self.plant.remesh(options);
        let mesh = watch.lap();
        if let Some(timings) = self.timings.as_mut() {
            timings.interpret += interpret;
            timings.mesh += mesh;
        }
    }

    /// Draws the skeleton of a sketch's plant ([`BuildOptions::sketch`]), once; nothing otherwise.
    pub fn ensure_skeleton(&mut self) {
        if !self.plant.is_sketch() {
            return;
        }
        let segments = self.plant.stats.segments;
        let skeleton = match &self.model {
            Some(model) => {
                turtle::interpret_sized(model, self.derivation.turtle_string(), segments)
            }
            None => Default::default(),
        };
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
    let mut result = run_stages(source, options, &mut watch);
    result.timings = watch.timings();
    result
}

/// The stages, each timed; a stage that fails leaves the later ones out.
fn run_stages(source: &str, options: &BuildOptions, watch: &mut Watch<'_, '_>) -> Build {
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
    let steps = options.iterations.unwrap_or(model.settings.iterations);
    if steps > model.settings.max_steps {
        result.diagnostics.push(Diagnostic::error(
            "E0202",
            model.settings.iterations_span.clone().unwrap_or(0..0),
            format!(
                "{steps} iterations are more than the step limit {}; raise it with '{} {steps}'",
                model.settings.max_steps,
                crate::vocabulary::DirectiveKind::MaxSteps.written(),
            ),
        ));
        result.model = Some(model);
        return result;
    }
    watch.start(Stage::Derive);
    watch.hooks.tell(Progress::Derived { step: 0, steps });
    let mut stepped = |step| watch.hooks.tell(Progress::Derived { step, steps });
    let derived = derive_stage(&model, steps, options.seed, &mut result, &mut stepped);
    watch.timings.derive = watch.lap();
    if let Some(None) = derived.as_ref().filter(|_| options.sketch) {
        watch.start(Stage::Interpret);
        let derivation = &result.derivation;
        let sketch =
            turtle::sketch_counted(&model, derivation.turtle_string(), &derivation.id_counts);
        watch.timings.interpret = watch.lap();
        if let Some(module) = sketch.clamped() {
            result
                .diagnostics
                .push(clamped_warning(&model, &result.derivation, module));
        }
        watch.start(Stage::Mesh);
        result.steps = steps;
        result.seed = options.seed;
        result.plant = Plant::sketched(sketch, &options.mesh, &result.derivation, steps);
        watch.timings.mesh = watch.lap();
    } else if let Some(adjustments) = derived {
        watch.start(Stage::Interpret);
        let skeleton = turtle::interpret_adjusted(
            &model,
            result.derivation.turtle_string(),
            adjustments.as_ref(),
        );
        watch.timings.interpret = watch.lap();
        if let Some(module) = skeleton.clamped {
            result
                .diagnostics
                .push(clamped_warning(&model, &result.derivation, module));
        }
        watch.start(Stage::Mesh);
        result.steps = steps;
        result.seed = options.seed;
        result.plant = Plant::new(skeleton, &options.mesh, &result.derivation, steps);
        watch.timings.mesh = watch.lap();
    }
    result.model = Some(model);
    result
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

/// Derives (with growth following, when the grammar has growth attributes) into `result`,
/// telling `stepped` each step done; returns the turtle's adjustments, or `None` when derivation
/// failed.
fn derive_stage(
    model: &Model,
    steps: u32,
    seed: Option<u64>,
    result: &mut Build,
    stepped: &mut dyn FnMut(u32),
) -> Option<Option<Adjustments>> {
    let mut observer = StageObserver {
        model,
        growth: GrowthTracker::new(model, steps),
        stepped: Some(stepped),
    };
    let options = DeriveOptions { steps, seed };
    match derive::derive_tracked(model, &options, &mut observer) {
        Ok(mut derivation) => {
            result.diagnostics.append(&mut derivation.warnings);
            let adjustments = observer
                .growth
                .as_ref()
                .map(|g| g.adjustments(&derivation.turtle_origin));
            result.growth = observer.growth.map(GrowthTracker::finish);
            result.derivation = derivation;
            Some(adjustments)
        }
        Err(diagnostic) => {
            result.diagnostics.push(diagnostic);
            None
        }
    }
}

/// Derives again, recording every step (the derivation as a sequence), with growth following as in
/// a build.
fn trace(model: &Model, options: &DeriveOptions) -> Result<Vec<derive::TracedStep>, Diagnostic> {
    let mut observer = StageObserver {
        model,
        growth: GrowthTracker::new(model, options.steps),
        stepped: None,
    };
    derive::derive_traced(model, options, &mut observer).map(|(_, steps)| steps)
}

/// What the stages after derive do while it derives: growth follows every module and plans each
/// step (asking the turtle for heights), and the turtle answers query modules. Both read the
/// derived string itself, not its homomorphism image. The progress callback, if any, is told each
/// step done.
struct StageObserver<'m, 's> {
    model: &'m Model,
    growth: Option<GrowthTracker<'m>>,
    stepped: Option<&'s mut dyn FnMut(u32)>,
}

impl derive::Observer for StageObserver<'_, '_> {
    fn follows_modules(&self) -> bool {
        self.growth.is_some()
    }

    fn axiom(&mut self, axiom: &LString, rng: &mut dyn rand::Rng) {
        if let Some(g) = &mut self.growth {
            g.axiom(axiom, rng);
        }
    }

    fn plan(
        &mut self,
        step: u32,
        s: &LString,
        rng: &mut dyn rand::Rng,
    ) -> Result<Option<Vec<u32>>, Diagnostic> {
        let Some(g) = &mut self.growth else {
            return Ok(None);
        };
        let model = self.model;
        let mut heights = |s: &LString, a: &Adjustments| turtle::heights(model, s, Some(a));
        g.plan(step, s, &mut heights, rng).map(Some)
    }

    fn followed(
        &mut self,
        written: &LString,
        parent: &[u32],
        origin: &[u32],
        birth: Option<u32>,
        rng: &mut dyn rand::Rng,
    ) {
        if let Some(g) = &mut self.growth {
            g.follow(written, parent, origin, birth, rng);
        }
    }

    fn cut(&mut self, kept: &[u32]) {
        if let Some(g) = &mut self.growth {
            g.cut(kept);
        }
    }

    fn stepped(&mut self, step: u32) {
        if let Some(g) = &mut self.growth {
            g.stepped(step);
        }
        if let Some(stepped) = self.stepped.as_mut() {
            stepped(step);
        }
    }

    fn queries(&mut self, s: &LString) -> Vec<(u32, [f64; 3])> {
        let adjustments = self.growth.as_ref().map(|g| g.adjustments(&[]));
        turtle::interpret_adjusted(self.model, s, adjustments.as_ref())
            .queries
            .into_iter()
            .map(|q| (q.module, q.value))
            .collect()
    }
}
#[cfg(test)]
mod tests {
    use super::*;

    /// Hooks with `clock` and no progress.
    fn timed<'a>(clock: &'a mut dyn FnMut() -> f64) -> Hooks<'a> {
        Hooks {
            clock: Some(clock),
            progress: None,
        }
    }

    /// A clock that advances by one unit each time it is read.
    fn ticking() -> impl FnMut() -> f64 {
        let mut t = 0.0;
        move || {
            t += 1.0;
            t
        }
    }

    #[test]
    fn without_a_clock_there_are_no_timings() {
        assert_eq!(build("axiom: F", &BuildOptions::default()).timings, None);
    }

    #[test]
    fn a_clock_is_read_once_around_each_stage() {
        let mut clock = ticking();
        let result = build_with(
            "axiom: F\nF -> FF",
            &BuildOptions::default(),
            &mut timed(&mut clock),
        );
        let timings = result.timings.expect("timings");
        assert_eq!(
            timings,
            StageTimings {
                parse_resolve: 1.0,
                derive: 1.0,
                interpret: 1.0,
                mesh: 1.0
            }
        );
        assert_eq!(
            timings.to_json(),
            r#"{"parseResolve":1.0,"derive":1.0,"interpret":1.0,"mesh":1.0}"#
        );
    }

    #[test]
    fn a_timed_remesh_of_a_sketch_adds_its_skeleton_to_interpret_and_its_tubes_to_mesh() {
        let mut clock = ticking();
        let options = BuildOptions {
            sketch: true,
            ..BuildOptions::default()
        };
        let mut result = build_with("axiom: F\nF -> FF", &options, &mut timed(&mut clock));
        result.remesh_with(&options.mesh, &mut timed(&mut clock));
        let timings = result.timings.expect("timings");
        assert_eq!((timings.interpret, timings.mesh), (2.0, 2.0));
        // Without a clock, or on a build made without one, nothing is timed.
        result.remesh(&options.mesh);
        assert_eq!(result.timings, Some(timings));
        let mut untimed = build("axiom: F", &options);
        untimed.remesh_with(&options.mesh, &mut timed(&mut clock));
        assert_eq!(untimed.timings, None);
    }

    #[test]
    fn timings_json_is_what_serde_json_writes() {
        for times in [
            [0.25, 12.5, 0.1 + 0.2, 1234.0],
            [-0.0, 3.0e-3, 99999.875, 1.0 / 3.0],
        ] {
            let timings = StageTimings {
                parse_resolve: times[0],
                derive: times[1],
                interpret: times[2],
                mesh: times[3],
            };
            let by_serde = serde_json::to_string(&timings).unwrap();
            assert_eq!(timings.to_json(), by_serde);
        }
        let broken = StageTimings {
            derive: f64::NAN,
            mesh: f64::INFINITY,
            ..StageTimings::default()
        };
        assert_eq!(
            broken.to_json(),
            r#"{"parseResolve":0.0,"derive":null,"interpret":0.0,"mesh":null}"#
        );
    }

    #[test]
    fn the_clamping_warning_writes_max_coordinate_as_its_exponent_form() {
        assert_eq!(
            MAX_COORDINATE_TEXT,
            format!("{:e}", crate::turtle::MAX_COORDINATE)
        );
    }

    #[test]
    fn stages_after_an_error_take_no_time() {
        let mut clock = ticking();
        let result = build_with(
            "axiom: F[",
            &BuildOptions::default(),
            &mut timed(&mut clock),
        );
        assert!(!result.ok());
        let timings = result.timings.expect("timings");
        assert_eq!(timings.parse_resolve, 1.0);
        assert_eq!(
            (timings.derive, timings.interpret, timings.mesh),
            (0.0, 0.0, 0.0)
        );
    }

    /// What `progress` is told while `source` builds with `iterations`.
    fn progress_of(source: &str, iterations: u32) -> Vec<Progress> {
        let mut told = Vec::new();
        let mut progress = |p| told.push(p);
        let mut hooks = Hooks {
            clock: None,
            progress: Some(&mut progress),
        };
        let options = BuildOptions {
            iterations: Some(iterations),
            ..BuildOptions::default()
        };
        build_with(source, &options, &mut hooks);
        told
    }

    #[test]
    fn progress_tells_each_stage_and_each_derivation_step() {
        use Progress::{Derived, Started};
        let derived = |step| Derived { step, steps: 3 };
        assert_eq!(
            progress_of("axiom: F\nF -> F[+F]F", 3),
            [
                Started(Stage::Parse),
                Started(Stage::Derive),
                derived(0),
                derived(1),
                derived(2),
                derived(3),
                Started(Stage::Interpret),
                Started(Stage::Mesh),
            ]
        );
        // With growth attributes the derivation takes the general path: the same steps.
        let growing = progress_of("#lifetime 60 40\naxiom: A\nA -> F[+A]A", 2);
        let steps: Vec<_> = growing
            .iter()
            .filter_map(|p| match p {
                Derived { step, steps } => Some((*step, *steps)),
                _ => None,
            })
            .collect();
        assert_eq!(steps, [(0, 2), (1, 2), (2, 2)]);
        // Errors stop the progress where the build stops.
        assert_eq!(progress_of("axiom: F[", 3), [Started(Stage::Parse)]);
    }

    #[test]
    fn a_clock_changes_nothing_else() {
        let source = "#angle 30\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
        let options = BuildOptions {
            iterations: Some(3),
            ..BuildOptions::default()
        };
        let plain = build(source, &options);
        let mut clock = ticking();
        let timed = build_with(source, &options, &mut timed(&mut clock));
        assert_eq!(plain.plant.stats, timed.plant.stats);
        assert_eq!(plain.plant.mesh.positions, timed.plant.mesh.positions);
    }

    #[test]
    fn a_sketch_draws_lines_and_its_remesh_is_the_plain_build() {
        let source = "#angle 25\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
        let options = BuildOptions {
            iterations: Some(4),
            ..BuildOptions::default()
        };
        let plain = build(source, &options);
        let mut sketch = build(
            source,
            &BuildOptions {
                sketch: true,
                ..options.clone()
            },
        );
        // Lines only: no skeleton, no triangles; the stats count the segments as lines.
        assert!(sketch.plant.is_sketch());
        assert!(sketch.plant.skeleton.segments.is_empty());
        assert_eq!(sketch.plant.mesh.triangle_count(), 0);
        let segments = plain.plant.skeleton.segments.len();
        assert_eq!(sketch.plant.stats.segments, segments);
        assert_eq!(sketch.plant.stats.lines, segments);
        assert_eq!(sketch.plant.is_flat(), plain.plant.is_flat());
        let lines = plain.plant.segment_lines();
        let sketched = sketch.plant.segment_lines();
        assert_eq!(sketched.modules, lines.modules);
        assert_eq!(sketched.colors, lines.colors);
        for (a, b) in sketched.ends.iter().zip(&lines.ends) {
            assert!((a - b).abs() < 1e-5, "{a} against {b}");
        }
        for k in 0..3 {
            for side in 0..2 {
                let (a, b) = (
                    sketch.plant.stats.bounds[side][k],
                    crate::mesh::MeshBuffers {
                        lines: sketched.ends.clone(),
                        ..Default::default()
                    }
                    .bounds()[side][k],
                );
                assert_eq!(a, b, "the sketch's bounds are its lines'");
            }
        }
        // The tubes on demand: the very mesh and stats of the plain build.
        sketch.remesh(&options.mesh);
        assert!(!sketch.plant.is_sketch());
        assert_eq!(sketch.plant.skeleton, plain.plant.skeleton);
        assert_eq!(sketch.plant.mesh, plain.plant.mesh);
        assert_eq!(sketch.plant.stats, plain.plant.stats);
    }

    #[test]
    fn a_sketch_with_growth_draws_its_skeleton_at_once() {
        let source = "#lifetime 60 40\naxiom: A\nA -> F[+A]A";
        let sketch = build(
            source,
            &BuildOptions {
                iterations: Some(3),
                sketch: true,
                ..BuildOptions::default()
            },
        );
        assert!(!sketch.plant.is_sketch());
        assert!(!sketch.plant.skeleton.segments.is_empty());
    }

    #[test]
    fn without_tubes_the_bounds_are_the_segments() {
        let source = "#angle 25\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
        let options = BuildOptions {
            iterations: Some(3),
            ..BuildOptions::default()
        };
        let mut result = build(source, &options);
        let with_tubes = result.plant.stats.clone();
        result.remesh(&MeshOptions {
            tubes: false,
            ..options.mesh.clone()
        });
        let stats = &result.plant.stats;
        assert_eq!((stats.vertices, stats.triangles), (0, 0));
        assert_eq!(stats.segments, with_tubes.segments);
        let lines = crate::mesh::MeshBuffers {
            lines: result.plant.segment_lines().ends,
            ..Default::default()
        };
        assert_eq!(stats.bounds, lines.bounds());
        assert_ne!(stats.bounds, [[0.0; 3]; 2]);
    }
}
