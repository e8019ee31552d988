//! The drawing's budget in a build (docs/LANGUAGE.md, "Limits"): what the turtle would hold is
//! counted before it runs ([`turtle::drawing_size`]); a plant whose skeleton would pass
//! [`turtle::MAX_SKELETON_BYTES`] is drawn as lines only (`E0414`, a warning), and one whose
//! lines would pass [`turtle::MAX_SKETCH_BYTES`] too is not drawn (`E0413`).

use crate::diagnostics::Diagnostic;
use crate::model::Model;
use crate::turtle::{self, DrawingSize};

/// Where a drawing's size is blamed: `#iterations`, else the axiom.
pub(super) fn span(model: &Model) -> crate::syntax::Span {
    (model.settings.iterations_span.clone()).unwrap_or_else(|| model.axiom_span.clone())
}

/// `E0413`: the plant of `steps` steps cannot be drawn within the budget: even as lines, or at
/// all when `growth` (growth's adjustments need the skeleton).
pub(super) fn too_large(model: &Model, steps: u32, size: &DrawingSize, growth: bool) -> Diagnostic {
    let (bytes, what) = if growth {
        (
            size.skeleton,
            "as a skeleton (growth attributes need it: the plant cannot be drawn as lines only)",
        )
    } else {
        (size.sketch, "even as lines")
    };
    let message = over(steps, size, bytes, what, "use fewer iterations");
    Diagnostic::error("E0413", span(model), message)
}

/// `E0414`: the plant of `steps` steps is drawn as lines only, its skeleton being over budget.
pub(super) fn lines_only(model: &Model, steps: u32, size: &DrawingSize) -> Diagnostic {
    let message = over(
        steps,
        size,
        size.skeleton,
        "as a skeleton",
        "it is drawn as lines only (no tubes, branch editing or export); use fewer iterations \
         for those",
    );
    Diagnostic::warning("E0414", span(model), message)
}

/// The words of both: the plant's segments, what they would take `what`, the budget (the
/// skeleton's and the lines' are the same 512 MB), and what to do.
fn over(steps: u32, size: &DrawingSize, bytes: usize, what: &str, then: &str) -> String {
    const _: () = assert!(turtle::MAX_SKELETON_BYTES == turtle::MAX_SKETCH_BYTES);
    // Leaves, polygons and spheres too: a plant of 4 million leaves has no segment.
    let others = match size.others {
        0 => String::new(),
        n => format!(" and {n} polygons, polygon points, leaves, spheres or queries"),
    };
    format!(
        "after {steps} steps the plant has {} segments{others}, which would take {} MB {what}, \
         above the drawing's budget of {} MB; {then}",
        size.segments,
        bytes.div_ceil(1 << 20),
        turtle::MAX_SKELETON_BYTES >> 20
    )
}

/// `E0417`: the plant was too large to mesh and is drawn as lines, one per segment, which leave
/// out its polygons, surfaces and spheres (a plant of 65,536 spheres was drawn as nothing,
/// without a word); nothing when it was meshed or has none of them.
pub(super) fn shapes_left_out(model: &Model, plant: &super::Plant) -> Option<Diagnostic> {
    let (mesh, skeleton) = (&plant.mesh, &plant.skeleton);
    let shapes = skeleton.polygons.len() + skeleton.surfaces.len() + skeleton.spheres.len();
    if mesh.unmeshed_vertices == 0 || shapes == 0 {
        return None;
    }
    let message = format!(
        "the plant's mesh would have {} vertices, above the mesh's limit of {}: it is drawn as \
         lines, one per segment, and its {shapes} polygons, leaves and spheres are left out (of \
         the view and of exports); use fewer iterations",
        mesh.unmeshed_vertices, plant.mesh_options.max_vertices
    );
    Some(Diagnostic::warning("E0417", span(model), message))
}
