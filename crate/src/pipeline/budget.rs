//! The drawing's budget in a build (docs/LANGUAGE.md, "Limits"): what the turtle would hold is
//! counted before it runs ([`turtle::drawing_size`]); a plant whose skeleton would pass
//! [`turtle::MAX_SKELETON_BYTES`] is drawn as lines only (`E0414`, a warning), and one whose
//! lines would pass [`turtle::MAX_SKETCH_BYTES`] too is not drawn (`E0413`).

use crate::diagnostics::Diagnostic;
use crate::model::Model;
use crate::turtle::{self, DrawingSize};

/// Where a drawing's size is blamed: `#iterations`, else the axiom.
fn span(model: &Model) -> crate::syntax::Span {
    (model.settings.iterations_span.clone()).unwrap_or_else(|| model.axiom_span.clone())
}

fn mb(bytes: usize) -> usize {
    bytes.div_ceil(1 << 20)
}

/// `E0413`: the plant of `steps` steps cannot be drawn within the budget: even as lines, or at
/// all when `growth` (growth's adjustments need the skeleton).
pub(super) fn too_large(model: &Model, steps: u32, size: &DrawingSize, growth: bool) -> Diagnostic {
    let segments = size.segments;
    let message = if growth {
        format!(
            "after {steps} steps the plant has {segments} segments, whose skeleton would take {} \
             MB, above its budget of {} MB (growth attributes need the skeleton: it cannot be \
             drawn as lines only); use fewer iterations",
            mb(size.skeleton),
            mb(turtle::MAX_SKELETON_BYTES)
        )
    } else {
        format!(
            "after {steps} steps the plant has {segments} segments, which would take {} MB even \
             as lines, above the drawing's budget of {} MB; use fewer iterations",
            mb(size.sketch),
            mb(turtle::MAX_SKETCH_BYTES)
        )
    };
    Diagnostic::error("E0413", span(model), message)
}

/// `E0414`: the plant of `steps` steps is drawn as lines only, its skeleton being over budget.
pub(super) fn lines_only(model: &Model, steps: u32, size: &DrawingSize) -> Diagnostic {
    Diagnostic::warning(
        "E0414",
        span(model),
        format!(
            "after {steps} steps the plant has {} segments, whose skeleton would take {} MB, \
             above its budget of {} MB: it is drawn as lines only (no tubes, branch editing or \
             SVG export); use fewer iterations for those",
            size.segments,
            mb(size.skeleton),
            mb(turtle::MAX_SKELETON_BYTES)
        ),
    )
}
