//! The answer pass's own memory (docs/LANGUAGE.md, "Environment", Limits): for every `?E` of a
//! pass, where the turtle found it ([`EnvironmentQuery`]), the [`Probe`] the programs read, who
//! asked (plant and module) and the replies. They grow with the number of `?E` in the strings,
//! not with the parts the plants draw, so they are counted before the pass allocates them and
//! checked against the environment's budget ([`MAX_ENVIRONMENT_BYTES`], shared with the
//! programs): a string of millions of `?E` stops with `E0408`, never a trap.

use crate::diagnostics::Diagnostic;
use crate::environment::{Probe, MAX_ENVIRONMENT_BYTES};
use crate::model::{LString, Model, ModuleId};
use crate::turtle::EnvironmentQuery;

/// Bytes one `?E` takes during an answer pass that replies `stride` values: the turtle's record
/// of it, its probe, who asked, and its reply (measured from the types, so it stays true).
pub(super) fn bytes_per_query(stride: usize) -> usize {
    size_of::<EnvironmentQuery>()
        + size_of::<Probe<'static>>()
        + size_of::<Asker>()
        + stride * size_of::<f64>()
}

/// Who asked one `?E`: the plant, and the module's index in that plant's derived string.
#[derive(Clone, Copy, Debug)]
pub(super) struct Asker {
    pub(super) plant: u32,
    pub(super) module: u32,
}

/// The buffers of the answer passes, kept from one pass to the next (a pass of the same size
/// allocates nothing new).
#[derive(Default)]
pub(super) struct Answers {
    pub(super) askers: Vec<Asker>,
    pub(super) replies: Vec<f64>,
}

impl Answers {
    /// Makes room for `n` `?E` answered with `stride` values each, after [`check`] allowed it.
    pub(super) fn reset(&mut self, n: usize, stride: usize) {
        self.askers.clear();
        self.askers.reserve_exact(n);
        self.replies.clear();
        self.replies.resize(n * stride, 0.0);
    }

    /// Bytes held now (what the programs' budget leaves out).
    pub(super) fn bytes(&self) -> usize {
        self.askers.capacity() * size_of::<Asker>() + self.replies.capacity() * size_of::<f64>()
    }
}

/// How many `?E` (`query`) the strings hold, counted before anything is interpreted; `E0408`
/// when answering them would pass the environment's budget.
pub(super) fn check<'s>(
    model: &Model,
    query: ModuleId,
    strings: impl Iterator<Item = &'s LString>,
    stride: usize,
    step: u32,
) -> Result<usize, Diagnostic> {
    let n: usize = strings
        .map(|s| s.ids.iter().filter(|&&id| id == query).count())
        .sum();
    let bytes = n.saturating_mul(bytes_per_query(stride));
    if bytes <= MAX_ENVIRONMENT_BYTES {
        return Ok(n);
    }
    let mb = |b: usize| b.div_ceil(1 << 20);
    let most = MAX_ENVIRONMENT_BYTES / bytes_per_query(stride);
    let name = model.alphabet.name(query);
    let when = if step == 0 {
        "the axiom".to_string()
    } else {
        format!("step {step}")
    };
    Err(Diagnostic::error(
        "E0408",
        super::observer::first_written(model, query).unwrap_or_else(|| model.axiom_span.clone()),
        format!(
            "after {when} the string holds {n} {name}, whose answers would take {} MB ({} bytes \
             each), above the environment's budget of {} MB (at most {most} {name} at once); \
             ask from fewer places (only at the apices, and let the old ones go: \
             '{name}(…) -> ε'), or use fewer iterations",
            mb(bytes),
            bytes_per_query(stride),
            mb(MAX_ENVIRONMENT_BYTES)
        ),
    ))
}
