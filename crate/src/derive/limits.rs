//! The derivation's limits (docs/LANGUAGE.md, "Limits"): the module limit (`E0400`), one
//! string's memory (`E0401`), a trace's memory (`E0410`) and the work of all steps together
//! (`E0415`), each with its diagnostic.

use crate::diagnostics::Diagnostic;
use crate::model::Model;

/// Most bytes one derived string may take (`E0401`): a module's id, its parameters' offset when
/// the grammar has parameters, and 8 bytes per parameter ([`LString::bytes`]). A derivation holds
/// two strings (three when the last step is tracked) and their buffers may double, so this keeps
/// the derivation well inside wasm32's 4 GiB, and the CLI gives the same answer as the studio.
pub const MAX_STRING_BYTES: usize = 256 << 20;

/// Bytes an observer that follows every module (the growth attributes) holds for a module written:
/// its state (`growth::ModuleGrowth`, 64 bytes) for the string before the pass and for the one
/// written, both held while it follows.
pub const FOLLOWED_BYTES_PER_MODULE: usize = 128;

/// Most bytes the states of the modules followed may take (`E0401`): 1 GB, 8 million modules, so
/// the default `#max_modules` never meets it, and a raised one stops before wasm32's 4 GiB (a
/// string of 40 million modules with `#lifetime` held 2.2 GB when the module limit stopped it).
pub const MAX_FOLLOWED_BYTES: usize = 1 << 30;

/// `E0401` when the states of `len` modules written at `step` would pass [`MAX_FOLLOWED_BYTES`].
pub(super) fn check_followed(model: &Model, step: u32, len: usize) -> Result<(), Diagnostic> {
    let bytes = len.saturating_mul(FOLLOWED_BYTES_PER_MODULE);
    if bytes <= MAX_FOLLOWED_BYTES {
        return Ok(());
    }
    Err(Diagnostic::error(
        "E0401",
        size_span(model),
        format!(
            "{} {len} modules, whose growth states (64 bytes a module, before the step and \
             after) would take {} MB, above their budget of {} MB; use fewer iterations",
            size_when(step),
            bytes.div_ceil(1 << 20),
            MAX_FOLLOWED_BYTES >> 20
        ),
    ))
}

/// Most bytes a traced derivation ([`derive_traced`]: every step's string and provenance, for the
/// derivation view and a module's lineage) may hold (`E0410`).
pub const MAX_TRACE_BYTES: usize = 128 << 20;

/// `E0410`: the trace would hold `bytes` at `step`, above [`MAX_TRACE_BYTES`].
#[cold]
pub(super) fn trace_error(model: &Model, step: u32, bytes: usize) -> Diagnostic {
    Diagnostic::error(
        "E0410",
        size_span(model),
        format!(
            "the derivation step by step (every string kept, for the derivation view or a \
             module's lineage) would take {} MB by step {step}, above its budget of {} MB; \
             ask with fewer iterations",
            bytes.div_ceil(1 << 20),
            MAX_TRACE_BYTES >> 20
        ),
    )
}

/// Most modules one derivation may write over all its steps (`E0415`): 20 times
/// `#max_modules` (100 million by default: a few seconds of work), so that a string held below the
/// module limit for thousands of steps ends with a diagnostic instead of minutes of work where no
/// Stop button is at hand (the command line, an embedded plant).
pub fn work_budget(model: &Model) -> u64 {
    (model.settings.max_modules as u64).saturating_mul(20)
}

/// `E0415`: the steps up to `step` wrote `work` modules, past [`work_budget`].
#[cold]
pub(super) fn work_error(model: &Model, step: u32, work: u64) -> Diagnostic {
    Diagnostic::error(
        "E0415",
        size_span(model),
        format!(
            "by step {step} the derivation has written {work} modules, above its work budget of \
             {} (20 times the module limit); use fewer iterations, or raise the limit with \
             '#max_modules N'",
            work_budget(model)
        ),
    )
}

/// `E0400` when a string of `len` modules passes `#max_modules`, `E0401` when its `bytes` pass
/// [`MAX_STRING_BYTES`], at `step` (0: the axiom).
#[inline]
pub(super) fn check_size(
    model: &Model,
    step: u32,
    len: usize,
    bytes: usize,
) -> Result<(), Diagnostic> {
    if len > model.settings.max_modules {
        return Err(limit_error(model, step, len));
    }
    if bytes > MAX_STRING_BYTES {
        return Err(memory_error(model, step, len, bytes));
    }
    Ok(())
}

/// `E0401`: the string at `step` would take more than [`MAX_STRING_BYTES`].
#[cold]
pub(super) fn memory_error(model: &Model, step: u32, len: usize, bytes: usize) -> Diagnostic {
    let mb = |b: usize| b.div_ceil(1 << 20);
    let when = size_when(step);
    Diagnostic::error(
        "E0401",
        size_span(model),
        format!(
            "{when} {len} modules or more taking {} MB, above the memory budget of {} MB for \
             one string (4 bytes a module, 4 more with parameters, 8 a parameter); use fewer \
             iterations or fewer parameters per module",
            mb(bytes),
            mb(MAX_STRING_BYTES)
        ),
    )
}

/// How a size error at `step` begins: what the axiom has (step 0), or what the step would make.
fn size_when(step: u32) -> String {
    if step == 0 {
        "the axiom has".to_string()
    } else {
        format!("step {step} would make a string of")
    }
}

/// Where a size error points: `#iterations`, else the axiom.
fn size_span(model: &Model) -> crate::syntax::Span {
    model
        .settings
        .iterations_span
        .clone()
        .unwrap_or_else(|| model.axiom_span.clone())
}

/// `E0400`: the string would grow past `#max_modules` at `step` (0: the axiom).
#[cold]
fn limit_error(model: &Model, step: u32, len: usize) -> Diagnostic {
    let max = model.settings.max_modules;
    let span = size_span(model);
    let when = size_when(step);
    Diagnostic::error(
        "E0400",
        span,
        format!(
            "{when} {len} modules or more, above the limit of {max}; \
             use fewer iterations or raise the limit with '#max_modules N'"
        ),
    )
}
