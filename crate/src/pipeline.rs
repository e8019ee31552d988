//! The whole pipeline, parse -> resolve -> derive -> interpret -> mesh, as one call shared by the
//! command-line tool and the wasm boundary. Each stage's output is kept in the [`Build`], so callers
//! can show the derived string, the geometry and every diagnostic.
//!
//! The core reads no clock: a caller that has one passes it to [`build_with_clock`] (the wasm
//! boundary passes JavaScript's `performance.now`, the CLI `std::time::Instant`), and the time of
//! each stage lands in [`Build::timings`].

use crate::branches::{BranchEdit, BranchEditor, BranchTree, EditReport, MeshChange};
use crate::derive::{self, DeriveOptions};
use crate::diagnostics::{has_errors, Diagnostic, LineIndex, LocatedDiagnostic};
use crate::export::Stats;
use crate::growth::{Adjustments, GrowthRecord, GrowthTracker};
use crate::mesh::{self, MeshBuffers, MeshOptions};
use crate::model::{self, LString, Model};
use crate::syntax;
use crate::turtle::{self, Skeleton};
use serde::Serialize;

/// Options of one build; `None` fields take the grammar's own settings.
#[derive(Clone, Debug, Default)]
pub struct BuildOptions {
    /// Overrides `#iterations`.
    pub iterations: Option<u32>,
    /// Overrides `#seed`.
    pub seed: Option<u64>,
    pub mesh: MeshOptions,
}

/// Everything one build produced. When `diagnostics` has an error, the stages after the failing
/// one did not run and their fields are empty.
#[derive(Clone, Debug, Default)]
pub struct Build {
    pub diagnostics: Vec<Diagnostic>,
    pub model: Option<Model>,
    /// The derived string (the L-system's state after the last step).
    pub string: LString,
    /// The string the turtle read, when homomorphism rules made it differ from `string`.
    pub interpreted: Option<LString>,
    /// For each module of `string`, the production that made it in the last step
    /// (`derive::NOT_REWRITTEN` when copied).
    pub origin: Vec<u32>,
    pub skeleton: Skeleton,
    pub mesh: MeshBuffers,
    pub stats: Stats,
    /// Derivation steps run.
    pub iterations: u32,
    /// For each module of the string the turtle read, the module of `string` it came from (empty
    /// when they are the same string).
    pub turtle_origin: Vec<u32>,
    /// The string before the last step, and for each module of `string` the module of it that
    /// it came from (both empty after 0 steps): what [`Build::explain`] reads.
    pub previous: LString,
    pub parent: Vec<u32>,
    /// How long each stage took, when the caller passed a clock ([`build_with_clock`]).
    pub timings: Option<StageTimings>,
    /// With growth attributes (`#lifetime`, `#shape`, `#sun`, …): each module's growth state and
    /// what every step did (apices growing and stopped per third, rewritings).
    pub growth: Option<GrowthRecord>,
    /// The mesh options of the last (re)mesh.
    pub mesh_options: MeshOptions,
    /// Branch edits (issue 8): created by the first call that needs it ([`Build::branches`],
    /// [`Build::apply_edits`], [`Build::drag`]); `skeleton` and `mesh` are then the edited ones.
    pub editor: Option<Box<BranchEditor>>,
}

/// [`derive::Explanation`] in terms of the derived string: which of its modules production `p`
/// made in the last step, and which descend from the modules that served as its contexts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Explained {
    pub explanation: derive::Explanation,
    /// Modules of `string` the production wrote in the last step.
    pub produced: Vec<u32>,
    /// Modules of `string` that descend from a left / right context module of those rewritings.
    pub left: Vec<u32>,
    pub right: Vec<u32>,
}

/// Wall-clock time of each stage of one build, in the unit of the caller's clock (milliseconds
/// for the studio and the CLI). A stage that did not run (after an error) took 0.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct StageTimings {
    /// Parsing the text and resolving it into a model.
    pub parse_resolve: f64,
    /// Deriving the string (including the turtle runs that feed query modules).
    pub derive: f64,
    /// Interpreting the string with the turtle into a skeleton.
    pub interpret: f64,
    /// Building the mesh from the skeleton.
    pub mesh: f64,
}

impl StageTimings {
    /// One JSON object, e.g. `{"parseResolve":0.1,"derive":0.4,"interpret":0.9,"mesh":2.5}`.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|_| "{}".into())
    }
}

/// Reads a caller's clock between stages; without a clock it measures nothing.
struct Stopwatch<'a> {
    clock: Option<&'a mut dyn FnMut() -> f64>,
    last: f64,
    timings: StageTimings,
}

impl<'a> Stopwatch<'a> {
    fn new(mut clock: Option<&'a mut dyn FnMut() -> f64>) -> Self {
        let last = clock.as_mut().map_or(0.0, |now| now());
        Stopwatch {
            clock,
            last,
            timings: StageTimings::default(),
        }
    }

    /// The time since the previous lap (or the start).
    fn lap(&mut self) -> f64 {
        let Some(now) = self.clock.as_mut() else {
            return 0.0;
        };
        let time = now();
        let elapsed = (time - self.last).max(0.0);
        self.last = time;
        elapsed
    }

    fn finish(self, build: &mut Build) {
        if self.clock.is_some() {
            build.timings = Some(self.timings);
        }
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
            .map(|m| self.string.to_text(&m.alphabet))
            .unwrap_or_default()
    }

    /// Runs the mesh stage again on the kept skeleton, with other mesh options (a view option
    /// such as the number of sides or smooth axes needs no new derivation), and updates the stats.
    pub fn remesh(&mut self, options: &MeshOptions) {
        self.mesh_options = options.clone();
        self.mesh = match &mut self.editor {
            Some(editor) => editor.remesh(&self.skeleton, options),
            None => mesh::build_mesh(&self.skeleton, options),
        };
        self.remeshed();
    }

    /// After a whole new mesh: provenance in terms of the derived string, and the stats.
    fn remeshed(&mut self) {
        // Provenance ranges name modules of the derived string, not of the homomorphism's output.
        if !self.turtle_origin.is_empty() {
            for pair in self.mesh.ranges.chunks_exact_mut(2) {
                pair[1] = self
                    .turtle_origin
                    .get(pair[1] as usize)
                    .copied()
                    .unwrap_or(pair[1]);
            }
        }
        self.stats = Stats::new(
            self.string.len(),
            self.skeleton.segments.len(),
            self.iterations,
            &self.mesh,
        );
    }

    /// Explains production `production` (an index into the model's productions) on the last step:
    /// `None` before any step or without a model.
    pub fn explain(&self, production: u32) -> Option<Result<Explained, Diagnostic>> {
        self.explain_where(production, None)
    }

    /// Explains how module `module` of the derived string was made: the production that wrote it
    /// and the contexts of that one rewriting (`produced` is then every module that rewriting
    /// wrote). `None` when it was copied, before any step, or without a model.
    pub fn explain_module(&self, module: usize) -> Option<Result<Explained, Diagnostic>> {
        let production = *self.origin.get(module)?;
        if production == derive::NOT_REWRITTEN {
            return None;
        }
        let source = *self.parent.get(module)? as usize;
        let mut explained = self.explain_where(production, Some(source))?;
        if let Ok(e) = &mut explained {
            e.produced
                .retain(|&j| self.parent[j as usize] as usize == source);
        }
        Some(explained)
    }

    fn explain_where(
        &self,
        production: u32,
        only: Option<usize>,
    ) -> Option<Result<Explained, Diagnostic>> {
        let model = self.model.as_ref()?;
        if self.parent.is_empty() {
            return None;
        }
        Some(
            derive::explain(
                model,
                &self.previous,
                &self.origin,
                &self.parent,
                self.iterations,
                production,
                only,
            )
            .map(|explanation| {
                let mut is_left = vec![false; self.previous.len()];
                let mut is_right = vec![false; self.previous.len()];
                explanation
                    .left
                    .iter()
                    .for_each(|&i| is_left[i as usize] = true);
                explanation
                    .right
                    .iter()
                    .for_each(|&i| is_right[i as usize] = true);
                let mut explained = Explained::default();
                for (j, (&o, &p)) in self.origin.iter().zip(&self.parent).enumerate() {
                    if o == production {
                        explained.produced.push(j as u32);
                    }
                    if is_left[p as usize] {
                        explained.left.push(j as u32);
                    }
                    if is_right[p as usize] {
                        explained.right.push(j as u32);
                    }
                }
                explained.explanation = explanation;
                explained
            }),
        )
    }

    /// Diagnostics with line and column, in source order.
    pub fn located_diagnostics(&self, source: &str) -> Vec<LocatedDiagnostic> {
        let index = LineIndex::new(source);
        let mut located: Vec<_> = self.diagnostics.iter().map(|d| index.locate(d)).collect();
        located.sort_by_key(|d| (d.from, d.to));
        located
    }
}

/// What the stages after derive do while it derives: growth follows every module and plans each
/// step (asking the turtle for heights), and the turtle answers query modules. Both read the
/// derived string itself, not its homomorphism image.
struct StageObserver<'m> {
    model: &'m Model,
    growth: Option<GrowthTracker<'m>>,
}

impl derive::Observer for StageObserver<'_> {
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

/// Runs every stage on `source`.
pub fn build(source: &str, options: &BuildOptions) -> Build {
    build_with_clock_option(source, options, None)
}

/// Runs every stage on `source`, reading `clock` (any monotonic time, e.g. milliseconds) before
/// and after each stage to fill [`Build::timings`].
pub fn build_with_clock(
    source: &str,
    options: &BuildOptions,
    clock: &mut dyn FnMut() -> f64,
) -> Build {
    build_with_clock_option(source, options, Some(clock))
}

fn build_with_clock_option(
    source: &str,
    options: &BuildOptions,
    clock: Option<&mut dyn FnMut() -> f64>,
) -> Build {
    let mut watch = Stopwatch::new(clock);
    let mut result = run_stages(source, options, &mut watch);
    watch.finish(&mut result);
    result
}

fn run_stages(source: &str, options: &BuildOptions, watch: &mut Stopwatch) -> Build {
    let mut result = Build::default();
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
                "{steps} iterations are more than the step limit {}; raise it with '#max_steps {steps}'",
                model.settings.max_steps
            ),
        ));
        result.model = Some(model);
        return result;
    }
    let mut observer = StageObserver {
        model: &model,
        growth: GrowthTracker::new(&model, steps),
    };
    let derived = derive::derive_tracked(
        &model,
        &DeriveOptions {
            steps,
            seed: options.seed,
        },
        &mut observer,
    );
    let adjustments = match derived {
        Ok(derivation) => {
            result.diagnostics.extend(derivation.warnings);
            result.string = derivation.string;
            result.interpreted = derivation.interpreted;
            result.origin = derivation.origin;
            result.previous = derivation.previous;
            result.parent = derivation.parent;
            result.turtle_origin = derivation.turtle_origin;
            let adjustments = observer
                .growth
                .as_ref()
                .map(|g| g.adjustments(&result.turtle_origin));
            result.growth = observer.growth.map(GrowthTracker::finish);
            adjustments
        }
        Err(diagnostic) => {
            result.diagnostics.push(diagnostic);
            result.model = Some(model);
            watch.timings.derive = watch.lap();
            return result;
        }
    };
    watch.timings.derive = watch.lap();
    result.skeleton = turtle::interpret_adjusted(
        &model,
        result.interpreted.as_ref().unwrap_or(&result.string),
        adjustments.as_ref(),
    );
    watch.timings.interpret = watch.lap();
    result.iterations = steps;
    result.remesh(&options.mesh);
    watch.timings.mesh = watch.lap();
    result.model = Some(model);
    result
}

/// One branch as the studio shows it (see [`crate::branches`]).
#[derive(Clone, Debug, PartialEq)]
pub struct BranchInfo {
    pub path: Vec<u32>,
    pub parent: Option<u32>,
    pub children: Vec<u32>,
    /// Its segments, in order along the axis.
    pub segments: Vec<u32>,
    /// Its Bézier control points `P0 … P3` where they are now (edits and ancestors' edits
    /// included); `P0` is where it attaches.
    pub control: [glam::DVec3; 4],
    /// The parameter of each of its joints on the curve (by cumulative length, 0 to 1).
    pub params: Vec<f64>,
}

/// Editing branches by their Bézier handles (issue 8): [`crate::branches`].
impl Build {
    /// The branch editor, created on first use from the unedited plant (meshing it once more to
    /// record the mesh's layout).
    pub fn editor(&mut self) -> &BranchEditor {
        if self.editor.is_none() {
            let (editor, mesh) =
                BranchEditor::new(&self.skeleton, &self.mesh_options, self.mesh.width_unit);
            self.editor = Some(Box::new(editor));
            self.mesh = mesh;
            self.remeshed();
        }
        self.editor.as_deref().expect("created above")
    }

    /// The branch tree of the plant (of its unedited skeleton: edits move branches, never make
    /// or remove one).
    pub fn branch_tree(&mut self) -> &BranchTree {
        self.editor().tree()
    }

    /// Every branch: path, parent, children, segments, and its control points where they are now.
    pub fn branches(&mut self) -> Vec<BranchInfo> {
        let editor = self.editor();
        let tree = editor.tree();
        (0..tree.len() as u32)
            .map(|b| {
                let branch = &tree.branches[b as usize];
                BranchInfo {
                    path: branch.path.clone(),
                    parent: branch.parent,
                    children: branch.children.clone(),
                    segments: branch.segments.clone(),
                    control: editor.control_points(b),
                    params: branch.fit.params.clone(),
                }
            })
            .collect()
    }

    /// The joints of branch `branch` where they are now (empty for no such branch).
    pub fn branch_joints(&mut self, branch: u32) -> Vec<glam::DVec3> {
        self.editor();
        match &self.editor {
            Some(e) if (branch as usize) < e.tree().len() => {
                e.tree().joints(&self.skeleton, branch)
            }
            _ => Vec::new(),
        }
    }

    /// Replaces all edits by `edits` (an empty list undoes every edit) and rebuilds the edited
    /// skeleton and the whole mesh. Edits whose path names no branch are reported, not errors.
    pub fn apply_edits(&mut self, edits: &[BranchEdit]) -> EditReport {
        self.editor();
        let editor = self.editor.as_deref_mut().expect("created by editor()");
        let report = editor.apply(edits, &mut self.skeleton, &mut self.mesh);
        self.remeshed();
        report
    }

    /// The edits in force (applied ones only), in branch order.
    pub fn edits(&self) -> Vec<BranchEdit> {
        self.editor.as_ref().map_or_else(Vec::new, |e| e.edits())
    }

    /// Drags handle `handle` (1, 2, 3 for P1, P2, P3) of branch `branch` (an index into
    /// [`Build::branches`]) to `position`: the branch's edit changes, it and its descendants
    /// move, and only the changed part of the mesh is rebuilt (see [`MeshChange`]). The stats'
    /// bounds follow. Errors name a bad branch, handle or position.
    pub fn drag(
        &mut self,
        branch: u32,
        handle: usize,
        position: glam::DVec3,
    ) -> Result<MeshChange, String> {
        self.editor();
        let editor = self.editor.as_deref_mut().expect("created by editor()");
        let change = editor
            .drag(branch, handle, position, &mut self.skeleton, &mut self.mesh)?
            .clone();
        if change.full {
            self.remeshed();
        } else {
            self.stats.bounds = change.bounds;
        }
        Ok(change)
    }

    /// The branch that drew each triangle, as (first triangle, branch) pairs (see
    /// [`BranchEditor::branch_ranges`]).
    pub fn branch_ranges(&mut self) -> Vec<u32> {
        self.editor().branch_ranges()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let result = build_with_clock("axiom: F\nF -> FF", &BuildOptions::default(), &mut clock);
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
    fn stages_after_an_error_take_no_time() {
        let mut clock = ticking();
        let result = build_with_clock("axiom: F[", &BuildOptions::default(), &mut clock);
        assert!(!result.ok());
        let timings = result.timings.expect("timings");
        assert_eq!(timings.parse_resolve, 1.0);
        assert_eq!(
            (timings.derive, timings.interpret, timings.mesh),
            (0.0, 0.0, 0.0)
        );
    }

    #[test]
    fn a_clock_changes_nothing_else() {
        let source = "#angle 30\naxiom: X\nX -> F[+X]F[-X]+X\nF -> FF";
        let options = BuildOptions {
            iterations: Some(3),
            ..BuildOptions::default()
        };
        let plain = build(source, &options);
        let timed = build_with_clock(source, &options, &mut ticking());
        assert_eq!(plain.stats, timed.stats);
        assert_eq!(plain.mesh.positions, timed.mesh.positions);
    }
}
