//! A sketch: what the turtle draws as lines only, written straight into the flat arrays the view
//! and the benchmark read (no [`Segment`](super::Segment) records, no mesh stage). The studio
//! shows a big plant's sketch while its tubes are meshed; a build asked for a sketch draws the
//! full skeleton only when something needs it (`pipeline::Build::ensure_skeleton`).
//!
//! The same interpreter draws a sketch and a skeleton ([`super::interpreter::Canvas`]), so line
//! `i` of a sketch is exactly segment `i` of the skeleton as [`crate::mesh::segment_lines`] writes
//! it, clamped as [`Skeleton::clamp_to_finite`] clamps it.

use super::interpreter::Canvas;
use super::skeleton::{
    clamp_direction, clamp_number, clamp_point, Extent, Polygon, QueryValue, Skeleton, Sphere,
    Surface,
};
use super::state::TurtleState;
use crate::growth::Adjustments;
use crate::maths;
use crate::model::{LString, Model};
use crate::vocabulary::Command;
use glam::DVec3;

/// The segments of a skeleton as lines, in `Skeleton::segments` order: line `i` is segment `i`
/// (a [`Sketch`]'s, and `crate::mesh::segment_lines`'s of a skeleton).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SegmentLines {
    /// `f32` × 3 per line end, two ends per segment (start, end).
    pub ends: Vec<f32>,
    /// Linear RGB, `f32` × 3 per line end: the segment's colour at both ends.
    pub colors: Vec<f32>,
    /// The module that drew each segment (one per line), as `Segment::module`: an index into the
    /// string the turtle read.
    pub modules: Vec<u32>,
}

/// The segments as lines, with what the sketch needs to say about the rest of the drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Sketch {
    /// Line `i` is the skeleton's segment `i`: its ends, colour and module.
    pub lines: SegmentLines,
    /// Polygons, surfaces and spheres (few; no segments): they count for flatness and clamping.
    others: Skeleton,
    /// The segments' ends (clamped).
    extent: Extent,
    /// The first module whose segment was clamped.
    clamped: Option<u32>,
    /// The colour index last drawn with, and its colour.
    color: Option<(u16, [f32; 3])>,
}

impl Sketch {
    /// An empty sketch in the palette of `others` (an empty skeleton), with room for `segments`.
    pub(super) fn new(others: Skeleton, segments: usize) -> Sketch {
        Sketch {
            lines: SegmentLines {
                ends: Vec::with_capacity(6 * segments),
                colors: Vec::with_capacity(6 * segments),
                modules: Vec::with_capacity(segments),
            },
            others,
            extent: Extent::EMPTY,
            clamped: None,
            color: None,
        }
    }

    /// Segments drawn.
    pub fn segments(&self) -> usize {
        self.lines.modules.len()
    }

    /// As [`Skeleton::is_flat`] of the skeleton the same string draws.
    pub fn is_flat(&self) -> bool {
        let mut extent = self.extent;
        self.others.for_each_point(&mut |p| {
            extent.add(p);
            true
        });
        extent.is_flat()
    }

    /// `[[min x, y, z], [max x, y, z]]` of the lines' ends as stored (`f32`), as
    /// [`crate::mesh::MeshBuffers::bounds`] finds them (all zeros without a line), without reading
    /// them again: rounding to `f32` keeps the order, so the box of the rounded ends is the rounded
    /// box.
    pub fn line_bounds(&self) -> [[f64; 3]; 2] {
        if self.lines.ends.is_empty() {
            return [[0.0; 3]; 2];
        }
        let round = |v: DVec3| [v.x as f32 as f64, v.y as f32 as f64, v.z as f32 as f64];
        [round(self.extent.min), round(self.extent.max)]
    }

    /// As [`Skeleton::clamped`] of the skeleton the same string draws.
    pub fn clamped(&self) -> Option<u32> {
        match (self.clamped, self.others.clamped) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    #[inline]
    fn color_of(&mut self, index: u16) -> [f32; 3] {
        match self.color {
            Some((i, c)) if i == index => c,
            _ => {
                let c = self.others.color(index);
                self.color = Some((index, c));
                c
            }
        }
    }
}

impl Canvas for Sketch {
    #[inline]
    fn segment(&mut self, start: DVec3, t: &TurtleState, index: u32) -> u32 {
        let (mut a, mut b) = (start, t.position);
        // What the skeleton clamps, so that the first clamped module is the same.
        let (mut width, mut left, mut up) = (t.width, t.left, t.up);
        let changed = clamp_point(&mut a)
            | clamp_point(&mut b)
            | clamp_number(&mut width)
            | clamp_direction(&mut left, DVec3::X)
            | clamp_direction(&mut up, DVec3::Z);
        if changed && self.clamped.is_none() {
            self.clamped = Some(index);
        }
        self.extent.add(a);
        self.extent.add(b);
        let c = self.color_of(t.color);
        let lines = &mut self.lines;
        lines.ends.extend_from_slice(&[
            a.x as f32, a.y as f32, a.z as f32, b.x as f32, b.y as f32, b.z as f32,
        ]);
        lines
            .colors
            .extend_from_slice(&[c[0], c[1], c[2], c[0], c[1], c[2]]);
        lines.modules.push(index);
        lines.modules.len() as u32 - 1
    }

    fn polygon(&mut self, polygon: Polygon) {
        self.others.polygons.push(polygon);
    }

    fn surface(&mut self, surface: Surface) {
        self.others.surfaces.push(surface);
    }

    fn sphere(&mut self, sphere: Sphere) {
        self.others.spheres.push(sphere);
    }

    fn wants_queries(&self) -> bool {
        false
    }

    fn query(&mut self, _query: QueryValue) {}

    #[cfg(feature = "environment")]
    fn environment_query(&mut self, _query: super::skeleton::EnvironmentQuery) {}

    fn widths_set(&mut self) {}

    fn finish(&mut self, end: DVec3, _widths: Option<(&Adjustments, f64, f64)>, _: bool) {
        // Widths are not drawn; the rest is clamped as the skeleton's is.
        self.others.end = end;
        self.others.clamp_to_finite();
    }
}

/// What the plain sketch loop does with a module id: one byte, so that the loop dispatches on a
/// small table (the ids of a grammar are few).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
enum Op {
    /// Nothing a sketch shows changes (`@Gc`, queries, letters without a command, …).
    Nothing,
    /// `F`, `G`: a move that draws, by a length.
    Draw,
    /// `f`, `g`: a move without drawing.
    Move,
    /// A rotation about U (`+ -`), L (`& ^`) or H (`/ \`) in the direction of [`Step::sign`].
    TurnUp,
    TurnLeft,
    TurnHeading,
    TurnAround,
    RollToVertical,
    Push,
    Pop,
    /// `!`: only whether the skeleton would clamp a width.
    Width,
    NextColor,
    SetColor,
    /// Something the plain loop leaves to the interpreter (polygons, surfaces, spheres, tropism,
    /// `@M`, lines to points, `@R`, frames).
    Other,
}

/// A module id's operation in the plain loop, with its parameter's default value (NaN: none) and,
/// for a rotation, its sign (−1 for `-`, `^`, `\`) and the sine and cosine of its default angle.
#[derive(Clone, Copy, Debug)]
struct Step {
    op: Op,
    default: f64,
    sign: f64,
    turn: (f64, f64),
}

fn op_of(command: Option<Command>) -> (Op, f64) {
    use Command as C;
    let Some(command) = command else {
        return (Op::Nothing, 1.0);
    };
    match command {
        C::Forward | C::ForwardNoVertex => (Op::Draw, 1.0),
        C::Move | C::MoveNoVertex => (Op::Move, 1.0),
        C::TurnLeft => (Op::TurnUp, 1.0),
        C::TurnRight => (Op::TurnUp, -1.0),
        C::PitchDown => (Op::TurnLeft, 1.0),
        C::PitchUp => (Op::TurnLeft, -1.0),
        C::RollRight => (Op::TurnHeading, 1.0),
        C::RollLeft => (Op::TurnHeading, -1.0),
        C::TurnAround => (Op::TurnAround, 1.0),
        C::RollToVertical => (Op::RollToVertical, 1.0),
        C::Push => (Op::Push, 1.0),
        C::Pop => (Op::Pop, 1.0),
        C::NextColor => (Op::NextColor, 1.0),
        C::SetColor => (Op::SetColor, 1.0),
        C::Width => (Op::Width, 1.0),
        C::StartSmooth
        | C::EndSmooth
        | C::QueryPosition
        | C::QueryHeading
        | C::QueryUp
        | C::QueryLeft
        | C::QueryEnvironment => (Op::Nothing, 1.0),
        C::StartPolygon
        | C::PolygonVertex
        | C::EndPolygon
        | C::Leaf
        | C::Petal
        | C::Surface
        | C::Sphere
        | C::MoveTo
        | C::LineTo
        | C::LineRel
        | C::OrientedLineTo
        | C::OrientedLineRel
        | C::SetHeading
        | C::Frame
        | C::TropismVector
        | C::TropismStrength => (Op::Other, 1.0),
    }
}

/// The plain turtle of a sketch: position and frame, width and colour index.
#[derive(Clone, Copy)]
struct Plain {
    p: DVec3,
    h: DVec3,
    l: DVec3,
    u: DVec3,
    width: f64,
    color: u16,
}

/// The sketch of `string` by the plain loop: one byte dispatch per module, frames rotated without
/// re-orthonormalising (the interpreter's skeleton does; the lines agree with its segments to
/// far below a pixel: about 1e-13 of the plant's size per rotation), ends written straight into
/// an array sized by `segments` (an upper bound), colours as runs of one colour index, spread
/// into the per-end array once at the end. `None` when the string has a module the plain loop
/// leaves to the interpreter, when the grammar bends by tropism, or when a position or width
/// would be clamped (the check is on every position and width, drawn or not: what the plain loop
/// refuses, the interpreter draws the same): [`super::sketch`] then draws with the interpreter.
pub(super) fn plain_sketch(
    model: &Model,
    string: &LString,
    id_counts: &[u64],
    others: Skeleton,
) -> Option<Sketch> {
    let settings = &model.settings;
    if settings.tropism.1 != 0.0 {
        return None;
    }
    let steps: Vec<Step> = (0..model.meanings.len())
        .map(|i| {
            let Some(info) = model.meanings[i] else {
                return Step {
                    op: Op::Nothing,
                    default: f64::NAN,
                    sign: 1.0,
                    turn: (0.0, 1.0),
                };
            };
            let (op, sign) = op_of(info.command());
            let default = info
                .params
                .first()
                .and_then(|p| p.default_value(|d| settings.value(d)))
                .unwrap_or(f64::NAN);
            let turn = match op {
                Op::TurnUp | Op::TurnLeft | Op::TurnHeading => turn_of(sign, default),
                _ => (0.0, 1.0),
            };
            Step {
                op,
                default,
                sign,
                turn,
            }
        })
        .collect();
    // Each id's kind: bit 0 draws, bit 1 is left to the interpreter.
    let kinds: Vec<u8> = steps
        .iter()
        .map(|s| match s.op {
            Op::Draw => 1,
            Op::Other => 2,
            _ => 0,
        })
        .collect();
    let (segments, other) = sizes(&kinds, string, id_counts)?;
    if other & 2 != 0 {
        return None;
    }
    if string.is_parametric() {
        plain_loop::<true>(settings, &steps, string, others, segments)
    } else {
        plain_loop::<false>(settings, &steps, string, others, segments)
    }
}

/// How many lines the string draws at most, and the kinds of its modules or-ed together (bit 0
/// draws, bit 1 is left to the interpreter), from `kinds` (one per id) and the counts of each id
/// when known (`id_counts`), else from a pass over the string.
fn sizes(kinds: &[u8], string: &LString, id_counts: &[u64]) -> Option<(usize, u8)> {
    let count = || {
        let (mut segments, mut other) = (0usize, 0u8);
        for id in &string.ids {
            let kind = kinds.get(id.index()).copied().unwrap_or(2);
            segments += (kind & 1) as usize;
            other |= kind;
        }
        (segments, other)
    };
    if id_counts.is_empty() {
        return Some(count());
    }
    // The same sums from the counts of each id, without reading the string.
    let (mut segments, mut other) = (0u64, 0u8);
    for (index, &n) in id_counts.iter().enumerate() {
        if n > 0 {
            let kind = kinds.get(index).copied().unwrap_or(2);
            segments += n * (kind & 1) as u64;
            other |= kind;
        }
    }
    let counted = (usize::try_from(segments).ok()?, other);
    debug_assert_eq!(counted, count(), "the id counts are the string's");
    Some(counted)
}

/// The loop of [`plain_sketch`], once for strings with parameters (`PARAMETRIC`: a first
/// parameter replaces the default length or angle, `F(l)`, `+(a)`) and once without (no
/// parameter is read).
///
/// Long because it is the loop itself, one arm per operation with the frame, the stack and the
/// output arrays in locals: split into functions, each would take the whole turtle by reference,
/// which is what this loop exists to avoid.
///
/// Out of line (`inline(never)`), so that it is a function of its own in WebAssembly: V8 first runs
/// every function in its baseline compiler and optimises one once it has run a while, in the
/// background, in time that grows with the function's size. Inlined into `sketch_counted` (with
/// the interpreter's fallback and both variants) it took TurboFan 112 ms to compile on the
/// project's machine (sketch builds of 1.24d n = 7 take 2-3 times as long while their functions
/// run the baseline code); alone, 4 ms, and `sketch_counted` 22 ms. Once optimised, the same speed
/// (Node, the two builds alternating).
#[inline(never)]
fn plain_loop<const PARAMETRIC: bool>(
    settings: &crate::model::Settings,
    steps: &[Step],
    string: &LString,
    others: Skeleton,
    segments: usize,
) -> Option<Sketch> {
    // The start as the interpreter's (`#heading` turns it).
    let start = TurtleState::start(settings);
    let mut t = Plain {
        p: start.position,
        h: start.heading,
        l: start.left,
        u: start.up,
        width: start.width,
        color: 0,
    };
    // What the skeleton would clamp (a coordinate or width past MAX_COORDINATE, or not a
    // number) is left to the interpreter. Comparisons, not min and max: those pay for NaN
    // semantics on every call, and no NaN gets past here.
    const LIMIT: f64 = super::MAX_COORDINATE;
    let inside = |p: DVec3| p.abs().cmple(DVec3::splat(LIMIT)).all();
    if !inside(t.p) || t.width.is_nan() || t.width > LIMIT {
        return None;
    }
    let mut stack: Vec<Plain> = Vec::new();
    let mut ends: Vec<[f32; 6]> = Vec::with_capacity(segments);
    let mut modules: Vec<u32> = Vec::with_capacity(segments);
    // Written through their spare room, the lengths set once after the loop: no length stored
    // per line (in WebAssembly a `Vec`'s length lives in memory, not in a local).
    let ends_out = &mut ends.spare_capacity_mut()[..segments];
    let modules_out = &mut modules.spare_capacity_mut()[..segments];
    let mut drawn = 0usize;
    // (first line, colour index) for each run of lines of one colour.
    let mut runs: Vec<(usize, u16)> = vec![(0, 0)];
    let mut color_index = 0u16;
    let first = |index: usize| -> Option<f64> {
        if PARAMETRIC {
            string
                .params_of(index)
                .first()
                .copied()
                .filter(|v| v.is_finite())
        } else {
            None
        }
    };
    for (index, id) in string.ids.iter().enumerate() {
        let step = &steps[id.index()];
        match step.op {
            Op::Nothing | Op::Other => {}
            Op::Draw | Op::Move => {
                let length = first(index).unwrap_or(step.default);
                let length = if length.is_nan() { 0.0 } else { length };
                let a = t.p;
                t.p += t.h * length;
                if length == 0.0 {
                    // Where the turtle is (up to the sign of a zero): nothing drawn.
                    continue;
                }
                let b = t.p;
                if !inside(b) {
                    return None;
                }
                if step.op == Op::Move {
                    continue;
                }
                if t.color != color_index {
                    color_index = t.color;
                    runs.push((drawn, color_index));
                }
                ends_out[drawn].write([
                    a.x as f32, a.y as f32, a.z as f32, b.x as f32, b.y as f32, b.z as f32,
                ]);
                modules_out[drawn].write(index as u32);
                drawn += 1;
            }
            Op::TurnUp | Op::TurnLeft | Op::TurnHeading => {
                let (s, c) = match first(index) {
                    Some(angle) => turn_of(step.sign, angle),
                    None => step.turn,
                };
                match step.op {
                    Op::TurnUp => yaw(&mut t, s, c),
                    Op::TurnLeft => {
                        let h = t.h * c - t.u * s;
                        t.u = t.h * s + t.u * c;
                        t.h = h;
                    }
                    _ => {
                        let l = t.l * c + t.u * s;
                        t.u = t.u * c - t.l * s;
                        t.l = l;
                    }
                }
            }
            Op::TurnAround => {
                let (s, c) = maths::sin_cos(std::f64::consts::PI);
                yaw(&mut t, s, c);
            }
            Op::RollToVertical => {
                let l = DVec3::Y.cross(t.h);
                if l.length() > 1e-9 {
                    t.l = l.normalize();
                    t.u = t.h.cross(t.l);
                }
            }
            Op::Push => stack.push(t),
            Op::Pop => {
                if let Some(saved) = stack.pop() {
                    t = saved;
                }
            }
            Op::Width => {
                t.width = match first(index) {
                    Some(w) => w.max(0.0),
                    None => (t.width - settings.width_step).max(0.0),
                };
                if t.width > LIMIT {
                    return None;
                }
            }
            Op::NextColor => {
                let value = first(index).unwrap_or(step.default);
                let step = if value.is_nan() {
                    1
                } else {
                    value.round().clamp(-1000.0, 1000.0) as i32
                };
                t.color = (t.color as i32 + step).clamp(0, u16::MAX as i32) as u16;
            }
            Op::SetColor => {
                t.color = match first(index) {
                    Some(c) => c.round().clamp(0.0, u16::MAX as f64) as u16,
                    None => t.color.saturating_add(1),
                }
            }
        }
    }
    // The colours, one run at a time, each run's first line's by copies of what is written
    // already, doubling (bulk copies, not a store per float).
    // SAFETY: the loop wrote the first `drawn` elements of both arrays (one per line drawn, at
    // most `segments`, the room they were given), and nothing else.
    unsafe {
        ends.set_len(drawn);
        modules.set_len(drawn);
    }
    let lines = drawn;
    let mut colors: Vec<f32> = Vec::with_capacity(6 * lines);
    for (k, &(from, index)) in runs.iter().enumerate() {
        let to = runs.get(k + 1).map_or(lines, |r| r.0);
        if to == from {
            continue;
        }
        let c = others.color(index);
        let start = colors.len();
        let end = start + 6 * (to - from);
        colors.extend_from_slice(&[c[0], c[1], c[2], c[0], c[1], c[2]]);
        while colors.len() < end {
            let more = (colors.len() - start).min(end - colors.len());
            colors.extend_from_within(start..start + more);
        }
    }
    let mut sketch = Sketch::new(others, 0);
    let ends = ends.into_flattened();
    // The box of the ends as stored, after the loop: kept in the loop, its bounds took registers
    // the turtle's frame needed (in WebAssembly, V8 then kept the position on the stack, a store
    // and a load in the chain from one line to the next): 1.24d n = 10 sketched about 20% faster
    // without (measured 2026-11-27). The box of the ends rounded to `f32` is the rounded box of
    // the ends, which is what `line_bounds` gives and `is_flat` needs to a millionth.
    sketch.extent = Extent::of_f32_points(&ends);
    sketch.lines = SegmentLines {
        ends,
        colors,
        modules,
    };
    sketch.others.end = t.p;
    Some(sketch)
}

/// The sine and cosine of a turn by `angle` degrees (none for NaN) in the direction `sign`, as
/// the interpreter computes them.
fn turn_of(sign: f64, angle: f64) -> (f64, f64) {
    let angle = if angle.is_nan() { 0.0 } else { angle };
    maths::sin_cos(sign * angle.to_radians())
}

/// Rotation about U: H turns towards L.
#[inline]
fn yaw(t: &mut Plain, s: f64, c: f64) {
    let h = t.h * c + t.l * s;
    t.l = t.l * c - t.h * s;
    t.h = h;
}
