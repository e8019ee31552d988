//! [`build_on`]: a build of more steps that continues an earlier build's derivation instead of
//! deriving from the axiom again, so that stepping forward and Play cost the new steps (then the
//! turtle and the mesh, as every build).
//!
//! The result is the build [`build_with`](super::build_with) makes, byte for byte: the text is
//! parsed and resolved again (its diagnostics are the build's), and the derivation continues only
//! when the grammar resolves to the earlier build's very model and [`derive::resume`] can continue
//! it exactly; otherwise it derives from the axiom.

use super::build::run_stages;
use super::hooks::Watch;
use super::{Build, BuildOptions, Hooks};
use crate::derive::{self, Derivation, DeriveOptions};
use crate::model::Model;

/// Builds `source` with `options` as [`build_with`](super::build_with) does, continuing `from`'s
/// derivation when `from` built the same grammar, with the same seed, to fewer steps.
pub fn build_on(source: &str, options: &BuildOptions, from: &Build, hooks: &mut Hooks) -> Build {
    let mut watch = Watch::new(hooks);
    let mut result = run_stages(source, options, Some(from), &mut watch);
    result.timings = watch.timings();
    result
}

/// `from`'s derivation, when a build of `model` derived with `options` continues it: `from`
/// has no error, the same model (so the same grammar, spans included) without growth attributes,
/// and kept what continuing needs, with the same seed and fewer steps ([`derive::Resume`]).
pub(super) fn continuable<'b>(
    from: &'b Build,
    model: &Model,
    options: &DeriveOptions,
) -> Option<&'b Derivation> {
    let saved = from.derivation.resume.as_ref()?;
    let seed = options.seed.unwrap_or(model.settings.seed);
    let fits = from.ok()
        && !model.growth.is_active()
        && saved.steps < options.steps
        && saved.seed == seed
        && from.model.as_ref() == Some(model);
    fits.then_some(&from.derivation)
}

/// Whether builds of `from`'s grammar can be continued ([`build_on`]); `None` when they can,
/// else the reason (for tests and the benchmark: a build that cannot is simply built whole).
pub fn why_not_continued(from: &Build) -> Option<&'static str> {
    let model = from.model.as_ref()?;
    if model.growth.is_active() {
        return Some("growth attributes follow every module; their state is not carried");
    }
    #[cfg(feature = "environment")]
    if super::environment::runs(model) {
        return Some("the environment's replies are not carried: its cycle derives from the axiom");
    }
    derive::Resume::blocked(model)
}
