//! The environment's reading of the plants (docs/LANGUAGE.md, "Environment", Limits): before each
//! answer pass every plant's string is drawn by the turtle, one plant at a time, and its
//! segments, polygons, surfaces and spheres become the [`Part`]s the programs take in. The
//! drawing is counted before the turtle runs ([`turtle::drawing_size`]) and the parts before
//! they are added, against one budget ([`MAX_READING_BYTES`]): a plant of millions of segments
//! stops with `E0416`, never a trap. (The build's own drawing, after the last step, has the
//! drawing's budget and its fallback to lines; the environment cannot read lines: it needs each
//! segment's width.)

use crate::diagnostics::Diagnostic;
use crate::environment::Part;
use crate::model::{LString, Model};
use crate::turtle::{self, DrawingSize, Skeleton};

/// Most bytes one reading may hold at once: the parts of the plants read so far and the skeleton
/// of the one being read. About 2.5 million segments in one plant (a skeleton takes about 128
/// bytes a segment, its parts 72), or 7 million over a stand of small plants. The same as the
/// drawing's budget ([`turtle::MAX_SKELETON_BYTES`]).
pub const MAX_READING_BYTES: usize = 512 << 20;

/// Bytes of `n` parts.
fn parts_bytes(n: usize) -> usize {
    n.saturating_mul(size_of::<Part>())
}

/// Before the turtle draws one plant's `string` after step `step`, with `parts` parts of the
/// plants read before it held: what its drawing will hold at most (the turtle sizes its skeleton
/// by it, so that a growing array never holds an old and a new copy beyond the count), or `E0416`
/// when that and the parts would pass [`MAX_READING_BYTES`].
pub(super) fn before_drawing(
    model: &Model,
    string: &LString,
    parts: usize,
    step: u32,
) -> Result<DrawingSize, Diagnostic> {
    let size = turtle::drawing_size(model, string, &[]);
    let held = parts_bytes(parts).saturating_add(size.skeleton);
    if held > MAX_READING_BYTES {
        return Err(over_budget(model, step, parts, size.segments, held));
    }
    Ok(size)
}

/// Before the parts of `skeleton` (which holds at most `skeleton_bytes`) are added to `parts`:
/// makes room for exactly them, or `E0416` when they, the parts before and the skeleton would
/// pass [`MAX_READING_BYTES`].
pub(super) fn before_parts(
    model: &Model,
    skeleton: &Skeleton,
    skeleton_bytes: usize,
    parts: &mut Vec<Part>,
    step: u32,
) -> Result<(), Diagnostic> {
    let new = skeleton.segments.len()
        + skeleton.polygons.len()
        + skeleton.surfaces.len()
        + skeleton.spheres.len();
    let total = parts.len().saturating_add(new);
    let held = parts_bytes(total).saturating_add(skeleton_bytes);
    if held > MAX_READING_BYTES {
        let before = parts.len();
        return Err(over_budget(
            model,
            step,
            before,
            skeleton.segments.len(),
            held,
        ));
    }
    parts.reserve_exact(new);
    Ok(())
}

/// `E0416`: reading the plants after step `step` would hold `held` bytes: `before` parts of the
/// plants already read and a plant of `segments` segments.
fn over_budget(
    model: &Model,
    step: u32,
    before: usize,
    segments: usize,
    held: usize,
) -> Diagnostic {
    let others = if before > 0 {
        format!(" beside the {before} parts of the plants read before it")
    } else {
        String::new()
    };
    Diagnostic::error(
        "E0416",
        super::budget::span(model),
        format!(
            "after step {step} the environment would read a plant of {segments} segments{others}, \
             which would take {} MB, above the environment's reading budget of {} MB; use fewer \
             iterations or a smaller plant",
            held.div_ceil(1 << 20),
            MAX_READING_BYTES >> 20
        ),
    )
}
