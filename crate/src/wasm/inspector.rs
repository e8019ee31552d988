//! Questions about a build's derivation ([`PlantInspector`]) and the explanations it gives.

use crate::pipeline;
use wasm_bindgen::prelude::*;

/// Questions about a build's derivation, kept alive without its geometry.
#[wasm_bindgen]
pub struct PlantInspector {
    build: pipeline::Build,
}

impl PlantInspector {
    /// Questions about `build`'s derivation (`PlantBuild.intoInspector`).
    pub(super) fn new(build: pipeline::Build) -> Self {
        PlantInspector { build }
    }

    /// The build it keeps (its derivation, without the geometry).
    #[cfg(feature = "studio-extras")]
    pub(super) fn build(&self) -> &pipeline::Build {
        &self.build
    }

    /// The module texts `texts` picks, as a JSON array (empty without an inspector).
    fn texts_json(&self, texts: impl FnOnce(&pipeline::Inspector) -> Vec<String>) -> String {
        let texts = self
            .build
            .inspector()
            .map(|i| texts(&i))
            .unwrap_or_default();
        serde_json::to_string(&texts).unwrap_or_else(|_| "[]".into())
    }
}

#[wasm_bindgen]
impl PlantInspector {
    #[cfg(feature = "studio-extras")]
    /// Explains production `production` on the last step; `undefined` before the first step, for
    /// an unknown index, or on a runtime error.
    pub fn explain(&self, production: u32) -> Option<Explanation> {
        let explained = self.build.inspector()?.explain(production)?.ok()?;
        Some(Explanation { inner: explained })
    }

    #[cfg(feature = "studio-extras")]
    /// Explains how module `module` of the derived string was made (the production that wrote it,
    /// the contexts of that rewriting); `undefined` when it was copied or before the first step.
    #[wasm_bindgen(js_name = explainModule)]
    pub fn explain_module(&self, module: usize) -> Option<Explanation> {
        let explained = self.build.inspector()?.explain_module(module)?.ok()?;
        Some(Explanation { inner: explained })
    }

    /// The text of modules `start .. start + count` of the derived string, as a JSON array of
    /// strings (one per module).
    #[wasm_bindgen(js_name = moduleTexts)]
    pub fn module_texts(&self, start: usize, count: usize) -> String {
        self.texts_json(|i| i.module_texts(start, count))
    }

    #[cfg(feature = "studio-extras")]
    /// Why production `production` did or did not rewrite the module that module `module` of the
    /// derived string comes from, as JSON (`MatchReport`: `{production, module, moduleText,
    /// predecessor, left, right, condition, rewrittenBy}`, contexts as `{matched, modules,
    /// expected, found, foundText}`; module indices name the string the last step read);
    /// `undefined` before the first step.
    #[wasm_bindgen(js_name = matchReport)]
    pub fn match_report(&self, production: u32, module: usize) -> Option<String> {
        let report = self
            .build
            .inspector()?
            .match_report(production, module)?
            .ok()?;
        serde_json::to_string(&report).ok()
    }

    #[cfg(feature = "studio-extras")]
    /// The whole derivation, step 0 to the last, as JSON `[{texts, parent, origin, time?}]` (each
    /// step's modules as written, and for each the module of the step before it comes from and
    /// the production that wrote it; a timed grammar's steps their growth time), when all the
    /// steps' strings hold `max_modules` modules or fewer together; `undefined` when they do not.
    pub fn sequence(&self, max_modules: usize) -> Option<String> {
        #[derive(serde::Serialize)]
        struct Step<'a> {
            texts: Vec<String>,
            parent: &'a [u32],
            origin: &'a [u32],
            #[serde(skip_serializing_if = "Option::is_none")]
            time: Option<f64>,
        }
        let inspector = self.build.inspector()?;
        let traced = inspector.sequence(max_modules)?.ok()?;
        let steps: Vec<Step> = traced
            .iter()
            .map(|s| Step {
                texts: inspector.texts_of(&s.string),
                parent: &s.parent,
                origin: &s.origin,
                time: s.time,
            })
            .collect();
        serde_json::to_string(&steps).ok()
    }

    #[cfg(feature = "studio-extras")]
    /// The lineage of module `module` of the derived string (`pipeline::lineage`), as JSON: `{rows:
    /// [{step, module, text, production?, time?}]}`, the last step first, back to the axiom, or
    /// `{error}` with the message (no such module, or the derivation step by step over its memory
    /// budget).
    pub fn lineage(&self, module: usize) -> String {
        #[derive(serde::Serialize)]
        #[serde(rename_all = "camelCase")]
        enum Answer {
            Rows(Vec<pipeline::LineageRow>),
            Error(String),
        }
        let answer = match self.build.inspector().map(|i| i.lineage(module)) {
            Some(Ok(rows)) => Answer::Rows(rows),
            Some(Err(e)) => Answer::Error(e.message),
            None => Answer::Error("the grammar did not build".to_string()),
        };
        serde_json::to_string(&answer).unwrap_or_else(|_| "{}".into())
    }

    #[cfg(feature = "studio-extras")]
    /// Where Play pauses for a breakpoint (`pipeline::first_firing`, `first_watched`): with `watch`
    /// empty, at the first firing of production `production`; else at the first step where the
    /// watch (`A(x) : x > 3`, read with the grammar `source`) holds for a module. JSON `{pause:
    /// {step, count, module}}`, `{}` when it never does, `{error}` with the message.
    pub fn breakpoint(&self, source: &str, production: u32, watch: &str) -> String {
        #[derive(serde::Serialize)]
        #[serde(rename_all = "camelCase")]
        enum Answer {
            Pause(pipeline::Pause),
            Never {},
            Error(String),
        }
        let Some(model) = self.build.model.as_ref() else {
            return r#"{"error":"the grammar did not build"}"#.into();
        };
        let options = &self.build.derived_with;
        let found = if watch.trim().is_empty() {
            pipeline::first_firing(model, options, production)
        } else {
            pipeline::first_watched(source, model, options, watch)
        };
        let answer = match found {
            Ok(Some(pause)) => Answer::Pause(pause),
            Ok(None) => Answer::Never {},
            Err(e) => Answer::Error(e.message),
        };
        serde_json::to_string(&answer).unwrap_or_else(|_| "{}".into())
    }

    /// The text of modules `start .. start + count` of the string the last step read (JSON array).
    #[wasm_bindgen(js_name = previousTexts)]
    pub fn previous_texts(&self, start: usize, count: usize) -> String {
        self.texts_json(|i| i.previous_texts(start, count))
    }

    /// Modules in the string the last step read (0 after 0 steps).
    #[wasm_bindgen(getter, js_name = previousCount)]
    pub fn previous_count(&self) -> usize {
        self.build.derivation.previous.len()
    }

    /// For each module of the derived string, the module of the string the last step read it
    /// comes from (empty after 0 steps).
    pub fn parents(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(self.build.derivation.parent())
    }

    /// A fingerprint of the derived string (16 hex digits): equal for equal derivations.
    #[wasm_bindgen(js_name = derivedHash)]
    pub fn derived_hash(&self) -> String {
        self.build
            .inspector()
            .map(|i| i.derived_hash())
            .unwrap_or_default()
    }
}

#[cfg(feature = "studio-extras")]
/// Why and where one production fired in the last step. Module indices name the derived string.
#[wasm_bindgen]
pub struct Explanation {
    inner: pipeline::Explained,
}

#[cfg(feature = "studio-extras")]
#[wasm_bindgen]
impl Explanation {
    /// The production explained (an index into `productions()`).
    #[wasm_bindgen(getter)]
    pub fn production(&self) -> u32 {
        self.inner.explanation.production
    }

    /// Modules the production rewrote in the last step (in the whole string, also when the
    /// explanation is of one module).
    #[wasm_bindgen(getter)]
    pub fn fired(&self) -> u32 {
        self.inner.explanation.fired
    }

    /// Modules whose predecessor and contexts matched it.
    #[wasm_bindgen(getter, js_name = contextMatched)]
    pub fn context_matched(&self) -> u32 {
        self.inner.explanation.context_matched
    }

    /// Of those, the modules whose condition was false.
    #[wasm_bindgen(getter, js_name = conditionFailed)]
    pub fn condition_failed(&self) -> u32 {
        self.inner.explanation.condition_failed
    }

    /// Modules of the derived string the production wrote.
    pub fn produced(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.produced[..])
    }

    /// Modules of the derived string descending from the modules that served as left context.
    #[wasm_bindgen(js_name = leftContext)]
    pub fn left_context(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.left[..])
    }

    /// Modules of the derived string descending from the modules that served as right context.
    #[wasm_bindgen(js_name = rightContext)]
    pub fn right_context(&self) -> js_sys::Uint32Array {
        js_sys::Uint32Array::from(&self.inner.right[..])
    }
}
