//! A build at the boundary: `build`, which runs the pipeline, and [`PlantBuild`], what it made.

use super::inspector::PlantInspector;
use super::options::{
    BuildOptionsFields, BuildOptionsObject, SketchFirstFields, Tubes, ViewOptionsFields,
    ViewOptionsObject,
};
use crate::mesh::MeshOptions;
use crate::pipeline::{self, BuildOptions, Hooks, Progress, Stage};
use wasm_bindgen::prelude::*;

/// Runs the whole pipeline on `source`. `clock`, when given, is read between the stages
/// (JavaScript's `() => performance.now()`): their times come back in `timings()`.
/// `progress(stage, step, steps)`, when given, is told each stage as it starts (`parsing`,
/// `deriving`, `interpreting`, `meshing`; step and steps 0) and, while deriving, each step done
/// (`deriving`, k, n, from 0 of n). A progress callback that throws changes nothing.
///
/// With `sketchFirst` the one call makes a sketch and then the mesh: the pipeline up to the turtle
/// with segments as lines (drawn straight from the string, without the skeleton), the sketch
/// shown to `sketchFirst.show` when the plant is big, then the mesh as `remesh` makes it (the
/// very mesh a plain build makes, without the tubes when `sketchFirst.tubes` says so), timed with
/// the same clock (the skeleton's time adds to the interpret stage's, the tubes' to the mesh
/// stage's). A `show` that throws stops the build: the call throws what it threw.
#[wasm_bindgen]
pub fn build(
    source: &str,
    options: &BuildOptionsObject,
    clock: Option<js_sys::Function>,
    progress: Option<js_sys::Function>,
) -> Result<PlantBuild, JsValue> {
    build_after(source, options, None, clock, progress)
}

/// [`build`], continuing `from`'s derivation when it can ([`pipeline::build_on`]).
pub(super) fn build_after(
    source: &str,
    options: &BuildOptionsObject,
    from: Option<&pipeline::Build>,
    clock: Option<js_sys::Function>,
    progress: Option<js_sys::Function>,
) -> Result<PlantBuild, JsValue> {
    let fields = BuildOptionsFields::read(options)?;
    let (clock, progress) = (clock.as_ref(), progress.as_ref());
    let mut plant = build_reading(source, &fields.options(), from, clock, progress);
    if let Some(first) = &fields.sketch_first {
        plant.show_sketch(first, progress)?;
        let view = ViewOptionsFields {
            sides: fields.sides,
            smooth_all: fields.smooth_all,
            tubes: Some(plant.tubes_after_sketch(first)),
            growth: fields.growth,
        };
        plant.remesh_timed(&view.mesh(), clock);
    }
    Ok(plant)
}

/// The time `clock` (JavaScript's `() => performance.now()`) tells; 0 without one or when it
/// throws.
fn read_clock(clock: Option<&js_sys::Function>) -> f64 {
    clock
        .and_then(|c| c.call0(&JsValue::NULL).ok())
        .and_then(|t| t.as_f64())
        .unwrap_or(0.0)
}

/// Tells `progress(label, step, steps)`, when there is one; one that throws changes nothing.
fn tell(progress: Option<&js_sys::Function>, label: &str, step: u32, steps: u32) {
    if let Some(f) = progress {
        let _ = f.call3(
            &JsValue::NULL,
            &JsValue::from_str(label),
            &JsValue::from_f64(step.into()),
            &JsValue::from_f64(steps.into()),
        );
    }
}

/// Runs the pipeline with `options` (continuing `from`, when given and it can), reading `clock`
/// and telling `progress` as [`build`] says.
pub(super) fn build_reading(
    source: &str,
    options: &BuildOptions,
    from: Option<&pipeline::Build>,
    clock: Option<&js_sys::Function>,
    progress: Option<&js_sys::Function>,
) -> PlantBuild {
    let mut now = || read_clock(clock);
    let mut told = |p: Progress| match p {
        Progress::Started(stage) => tell(progress, stage.label(), 0, 0),
        Progress::Derived { step, steps } => tell(progress, Stage::Derive.label(), step, steps),
        #[cfg(feature = "environment")]
        Progress::Environment { step, steps } => tell(progress, p.label(), step, steps),
    };
    let mut hooks = Hooks {
        clock: clock.map(|_| &mut now as &mut dyn FnMut() -> f64),
        progress: progress.map(|_| &mut told as &mut dyn FnMut(Progress)),
    };
    let build = match from {
        Some(from) => pipeline::build_on(source, options, from, &mut hooks),
        None => pipeline::build_with(source, options, &mut hooks),
    };
    let diagnostics =
        serde_json::to_string(&build.located_diagnostics(source)).unwrap_or_else(|_| "[]".into());
    PlantBuild { build, diagnostics }
}

/// A built plant: what one run of the pipeline produced. Free it with `.free()`, or turn it into
/// an inspector or an editor, once its arrays are copied out.
#[wasm_bindgen]
pub struct PlantBuild {
    build: pipeline::Build,
    diagnostics: String,
}

plant_mesh_getters!(PlantBuild);

impl PlantBuild {
    /// The plant whose mesh the getters copy.
    fn plant(&self) -> &pipeline::Plant {
        &self.build.plant
    }

    /// What the build keeps of its environment for the views, if it has one.
    #[cfg(feature = "environment")]
    pub(super) fn environment_view(&self) -> Option<&pipeline::EnvironmentView> {
        self.build.environment.as_ref()
    }

    /// Meshes the plant again with `mesh`, timed with `clock` as [`Self::remesh`] says.
    fn remesh_timed(&mut self, mesh: &MeshOptions, clock: Option<&js_sys::Function>) {
        let mut now = || read_clock(clock);
        let mut hooks = Hooks {
            clock: clock.map(|_| &mut now as &mut dyn FnMut() -> f64),
            progress: None,
        };
        self.build.remesh_with(mesh, &mut hooks);
    }

    /// A sketch build's sketch shown to `first.show` when the plant has no errors and at least
    /// `first.minSegments` segments, then `progress` told the mesh stage starts (plants without
    /// errors only). `show` is given views of the sketch's arrays in the core's memory.
    fn show_sketch(
        &self,
        first: &SketchFirstFields,
        progress: Option<&js_sys::Function>,
    ) -> Result<(), JsValue> {
        if !self.build.ok() {
            return Ok(());
        }
        let plant = &self.build.plant;
        let segments = plant.stats.segments;
        if segments >= first.min_segments as usize {
            // SAFETY: the views are of memory nothing changes until `show` returns, and `show`
            // only copies them (the facade, web/src/core/build.ts): it must not call into the
            // core, whose memory could then grow and move under them.
            let (lines, colors) = unsafe {
                (
                    js_sys::Float32Array::view(&plant.mesh.lines),
                    js_sys::Float32Array::view(&plant.mesh.line_colors),
                )
            };
            first.show.call4(
                &JsValue::NULL,
                &lines,
                &colors,
                &JsValue::from_bool(plant.is_flat()),
                &JsValue::from_f64(segments as f64),
            )?;
        }
        tell(progress, Stage::Mesh.label(), 0, 0);
        Ok(())
    }

    /// Whether the mesh after the sketch has the segments' tubes (`first.tubes`).
    fn tubes_after_sketch(&self, first: &SketchFirstFields) -> bool {
        match first.tubes.unwrap_or_default() {
            Tubes::Always => true,
            Tubes::Never => false,
            Tubes::UnlessFlat => !self.build.plant.is_flat(),
        }
    }
}

#[wasm_bindgen]
impl PlantBuild {
    /// True when there is no error diagnostic (the geometry is present).
    #[wasm_bindgen(getter)]
    pub fn ok(&self) -> bool {
        self.build.ok()
    }

    /// JSON array of `{severity, code, message, from, to, line, column}`; `from`/`to` are UTF-8
    /// byte offsets, `line`/`column` 1-based, columns in Unicode scalar values.
    pub fn diagnostics(&self) -> String {
        self.diagnostics.clone()
    }

    /// JSON `{parseResolve, derive, interpret, mesh}` in the clock's unit, or `null` without one.
    pub fn timings(&self) -> String {
        self.build
            .timings
            .map_or_else(|| "null".into(), |t| t.to_json())
    }

    /// The grammar's own `#iterations` (0 when it has none or could not be resolved).
    #[wasm_bindgen(getter, js_name = grammarIterations)]
    pub fn grammar_iterations(&self) -> u32 {
        self.build
            .model
            .as_ref()
            .map_or(0, |m| m.settings.iterations)
    }

    /// The seed the derivation used: the `seed` option, or the grammar's `#seed` (0 when the
    /// grammar could not be resolved).
    #[wasm_bindgen(getter)]
    pub fn seed(&self) -> f64 {
        let grammar = self.build.model.as_ref().map_or(0, |m| m.settings.seed);
        self.build.derived_with.seed.unwrap_or(grammar) as f64
    }

    /// True when the grammar has timed modules (`#terminal_age`, ABOP 6.1): its plant at a growth
    /// time is derived at that time (the build option `time`), not grown from the whole plant's.
    #[wasm_bindgen(getter)]
    pub fn timed(&self) -> bool {
        self.build
            .model
            .as_ref()
            .is_some_and(|m| m.settings.timed())
    }

    /// True when the grammar declares surfaces (`#surface`, `#patch`), which only the studio
    /// core (crate/pkg, the feature `surfaces`) draws: the build worker builds such a grammar with
    /// it, as it does a timed one.
    #[wasm_bindgen(getter, js_name = declaresSurfaces)]
    pub fn declares_surfaces(&self) -> bool {
        self.build
            .model
            .as_ref()
            .is_some_and(|m| m.settings.surfaces_declared)
    }

    /// True when the grammar places the turtle by coordinates or draws its frame (`@LineTo`,
    /// `@LineRel`, `@OLineTo`, `@OLineRel`, `@R`, `@Frame`), which only the studio core
    /// (crate/pkg, the feature `placing`) draws: the build worker builds it with that core.
    #[wasm_bindgen(getter, js_name = placesByCoordinates)]
    pub fn places_by_coordinates(&self) -> bool {
        self.build
            .model
            .as_ref()
            .is_some_and(|m| m.places_by_coordinates())
    }

    /// True when the grammar declares an environment (`#environment`, `#stand`, `#plant`), which
    /// only the studio core (crate/pkg, the feature `environment`) runs: the build worker builds
    /// such a grammar with it, as it does one that declares surfaces.
    #[wasm_bindgen(getter, js_name = declaresEnvironment)]
    pub fn declares_environment(&self) -> bool {
        self.build
            .model
            .as_ref()
            .is_some_and(|m| m.settings.environment_declared)
    }

    /// True when the grammar is stepwise ([`crate::model::Settings::stepwise`]: a `#dt` without
    /// timed modules): its plant at a growth time t is derived to step ⌊t⌋, not grown from the
    /// whole plant's mesh. In the studio core only (the timeline builds with it).
    #[cfg(feature = "growth")]
    #[wasm_bindgen(getter)]
    pub fn stepwise(&self) -> bool {
        self.build
            .model
            .as_ref()
            .is_some_and(|m| m.settings.stepwise())
    }

    /// The step the derivation went on from, when it continued an earlier build's (`buildOn`);
    /// `undefined` when it derived from the axiom.
    #[wasm_bindgen(getter, js_name = continuedFrom)]
    pub fn continued_from(&self) -> Option<u32> {
        self.build.continued_from
    }

    /// Modules in the derived string.
    #[wasm_bindgen(getter, js_name = moduleCount)]
    pub fn module_count(&self) -> usize {
        self.build.derivation.string.len()
    }

    /// The derived string, cut after `max_chars` characters with `…` appended when longer.
    pub fn derived(&self, max_chars: usize) -> String {
        self.build
            .inspector()
            .map(|i| i.derived_text(max_chars))
            .unwrap_or_default()
    }

    /// For each module of the derived string, the index of the production that made it in the
    /// last step, or 4294967295 (u32::MAX) when it was copied.
    pub fn origins(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(self.build.derivation.origin())
    }

    /// The productions of the productions section, as JSON `[{index, from, to, label, context,
    /// condition}]`: `from`/`to` are the UTF-8 byte range of the production in the source,
    /// `context` whether it has a left or right context, `condition` the byte range of its
    /// condition or null. The index is what `origins()` and `explain` use.
    pub fn productions(&self) -> String {
        #[derive(serde::Serialize)]
        struct Row<'a> {
            index: usize,
            from: usize,
            to: usize,
            label: Option<&'a str>,
            context: bool,
            condition: Option<[usize; 2]>,
        }
        let rows: Vec<Row> = self.build.model.as_ref().map_or_else(Vec::new, |m| {
            m.productions
                .productions
                .iter()
                .enumerate()
                .map(|(index, p)| Row {
                    index,
                    from: p.span.start,
                    to: p.span.end,
                    label: p.label.as_deref(),
                    context: p.has_context(),
                    condition: p.condition.as_ref().map(|c| [c.span.start, c.span.end]),
                })
                .collect()
        });
        serde_json::to_string(&rows).unwrap_or_else(|_| "[]".into())
    }

    /// Meshes the plant again with other view options (no new derivation); the arrays and stats
    /// change. `clock`, as `build`'s: when both were given, `timings()` adds the time this took
    /// (a sketch's skeleton to `interpret`, the mesh to `mesh`).
    pub fn remesh(
        &mut self,
        options: &ViewOptionsObject,
        clock: Option<js_sys::Function>,
    ) -> Result<(), JsError> {
        let view = ViewOptionsFields::read(options)?;
        self.remesh_timed(&view.mesh(), clock.as_ref());
        Ok(())
    }

    /// Keeps only what questions about the derivation need (the geometry is dropped).
    #[wasm_bindgen(js_name = intoInspector)]
    pub fn into_inspector(mut self) -> PlantInspector {
        self.build.plant = Default::default();
        PlantInspector::new(self.build)
    }

    /// Starts editing the plant's branches (the plant is meshed once more to record its layout).
    #[cfg(feature = "studio-extras")]
    #[wasm_bindgen(js_name = intoEditor)]
    pub fn into_editor(mut self) -> super::PlantEditor {
        self.build.ensure_skeleton();
        super::PlantEditor::new(self.build.plant)
    }
}
