//! Stage 4, `turtle`: the derived string becomes a [`Skeleton`] in 3D: segments, polygons,
//! predefined surfaces and spheres, plus the values of query modules.
//!
//! Frame conventions (docs/LANGUAGE.md, "Turtle"): the turtle starts at the origin with heading
//! H = +Y, left L = −X and up U = +Z (H × L = U), so plants grow up the Y axis (three.js's up)
//! and a flat grammar lies in the XY plane facing +Z. `+`, `&` and `/` are right-handed rotations
//! by δ about U, L and H respectively; `-`, `^` and `\` rotate by −δ. So `+` turns towards L
//! (left, counter-clockwise seen from +Z) and `&` tips H away from U (down).
//!
//! What each module does comes from the model (its row of the vocabulary, with the defaults of its
//! parameters). With growth attributes the turtle also takes plain per-module
//! [`Adjustments`] (turns towards attractors, length and width factors) that growth computes.

mod budget;
mod interpreter;
mod skeleton;
mod sketch;
mod state;

pub use budget::{drawing_size, DrawingSize, MAX_SKELETON_BYTES, MAX_SKETCH_BYTES};
pub(crate) use skeleton::f32_box;
pub use skeleton::{
    EnvironmentQuery, Extent, Polygon, QueryValue, Segment, Skeleton, Sphere, Surface, SurfaceKind,
    MAX_COORDINATE,
};
pub use sketch::{SegmentLines, Sketch};

use crate::growth::{Adjustments, Heights};
use crate::model::{LString, Model};
use interpreter::{empty_skeleton, Interpreter};

/// Runs the turtle over `string`.
pub fn interpret(model: &Model, string: &LString) -> Skeleton {
    interpret_adjusted(model, string, None)
}

/// Runs the turtle over `string` with growth's adjustments (one per module of `string`; ignored
/// when the lengths differ).
pub fn interpret_adjusted(
    model: &Model,
    string: &LString,
    adjustments: Option<&Adjustments>,
) -> Skeleton {
    let canvas = empty_skeleton(&model.settings, adjustments.is_some());
    Interpreter::new(model, string, adjustments, None, canvas).run(string)
}

/// [`interpret_adjusted`], with room for `segments` segments (a sketch of the same string or
/// [`drawing_size`] counted them): the skeleton's array grows once, and never holds an old and a
/// new copy at once.
pub fn interpret_sized(
    model: &Model,
    string: &LString,
    adjustments: Option<&Adjustments>,
    segments: usize,
) -> Skeleton {
    let mut canvas = empty_skeleton(&model.settings, adjustments.is_some());
    canvas.segments.reserve_exact(segments);
    Interpreter::new(model, string, adjustments, None, canvas).run(string)
}

/// Runs the turtle over `string` drawing only its segments, as lines ([`Sketch`]): line `i` is
/// segment `i` of [`interpret`]'s skeleton.
pub fn sketch(model: &Model, string: &LString) -> Sketch {
    let segments = drawing_size(model, string, &[]).segments;
    sketch_counted(model, string, &[], segments)
}

/// [`sketch`], with how many times each module id occurs in `string` (indexed by id, as
/// [`crate::derive::Derivation::id_counts`]; empty: not known), which spares the turtle a pass
/// over the string to size its lines, and the segments [`drawing_size`] counted (room for every
/// line at once when the interpreter draws them: a doubling array would hold half as much again
/// while it grows).
pub fn sketch_counted(
    model: &Model,
    string: &LString,
    id_counts: &[u64],
    segments: usize,
) -> Sketch {
    let others = empty_skeleton(&model.settings, false);
    if let Some(sketch) = sketch::plain_sketch(model, string, id_counts, others.clone()) {
        return sketch;
    }
    Interpreter::new(model, string, None, None, Sketch::new(others, segments)).run(string)
}

/// The height (Y) of the turtle at every module of `string` (the middle of the move for
/// `F f G g`), and the lowest and highest Y it reaches, its start included: what the growth
/// attributes divide into thirds.
pub fn heights(model: &Model, string: &LString, adjustments: Option<&Adjustments>) -> Heights {
    let mut heights = Heights::default();
    let canvas = empty_skeleton(&model.settings, adjustments.is_some());
    Interpreter::new(model, string, adjustments, Some(&mut heights), canvas).run(string);
    heights
}

#[cfg(all(test, feature = "placing"))]
mod line_tests;
#[cfg(test)]
mod tests;
