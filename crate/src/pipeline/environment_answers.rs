//! The answer pass's own memory (docs/LANGUAGE.md, "Environment", Limits): for every `?E` of a
//! pass, where the turtle found it ([`EnvironmentQuery`]), the [`Probe`] the programs read, who
//! asked (plant and module) and the replies. They grow with the number of `?E` in the strings,
//! not with the parts the plants draw, so they are counted before the pass allocates them and
//! checked against the pass's own budget ([`MAX_ANSWER_BYTES`], beside the programs'
//! [`crate::environment::MAX_ENVIRONMENT_BYTES`]): a string of millions of `?E` stops with
//! `E0408`, never a trap.

use crate::diagnostics::Diagnostic;
use crate::environment::Probe;
use crate::model::{LString, Model, ModuleId};
use crate::turtle::EnvironmentQuery;

/// Most bytes one answer pass may hold for its `?E` (`E0408`): what [`bytes_held`] counts, about
/// 150 bytes a `?E`, so some 900,000 at once (a stand of nine trees of 20,000 internodes, each
/// internode with its three lateral buds asking, has 560,000). Half of what one string may take
/// ([`crate::derive::MAX_STRING_BYTES`]): the `?E` are modules of the strings beside it.
pub const MAX_ANSWER_BYTES: usize = 128 << 20;

/// Bytes one `?E` holds for the whole pass when the programs reply `stride` values: its probe,
/// who asked, and its reply (measured from the types, so it stays true).
fn bytes_per_query(stride: usize) -> usize {
    size_of::<Probe<'static>>() + size_of::<Asker>() + stride * size_of::<f64>()
}

/// Bytes a pass holds at most for `n` `?E`, of which the largest plant has `largest`: every
/// `?E`'s probe, asker and reply, and the turtle's record of where each `?E` of one plant stands
/// (the plants are read one at a time, and each plant's records go before the next is read).
pub fn bytes_held(n: usize, largest: usize, stride: usize) -> usize {
    n.saturating_mul(bytes_per_query(stride))
        .saturating_add(largest.saturating_mul(size_of::<EnvironmentQuery>()))
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
}

/// How many `?E` (`query`) the strings hold, counted before anything is interpreted; `E0408`
/// when answering them would pass [`MAX_ANSWER_BYTES`].
pub(super) fn check<'s>(
    model: &Model,
    query: ModuleId,
    strings: impl Iterator<Item = &'s LString>,
    stride: usize,
    step: u32,
) -> Result<usize, Diagnostic> {
    let (mut n, mut largest) = (0, 0);
    for s in strings {
        let here = s.ids.iter().filter(|&&id| id == query).count();
        n += here;
        largest = largest.max(here);
    }
    let bytes = bytes_held(n, largest, stride);
    if bytes <= MAX_ANSWER_BYTES {
        return Ok(n);
    }
    let mb = |b: usize| b.div_ceil(1 << 20);
    let each = bytes.div_ceil(n.max(1));
    let most = MAX_ANSWER_BYTES / each;
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
            "after {when} the string holds {n} {name}, whose answers would take {} MB (about {each} \
             bytes each), above the budget of {} MB for one answer pass (at most {most} {name} at \
             once); ask from fewer places (only at the apices, and let the old ones go: \
             '{name}(…) -> ε'), or use fewer iterations",
            mb(bytes),
            mb(MAX_ANSWER_BYTES)
        ),
    ))
}
