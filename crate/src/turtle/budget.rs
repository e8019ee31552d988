//! The turtle's memory budget (docs/LANGUAGE.md, "Limits"): what drawing a string would hold,
//! counted from its modules before the turtle runs, so that a plant too large for the skeleton
//! is drawn as lines ([`super::Sketch`]) and one too large even for lines stops with a
//! diagnostic, never a failed allocation (in WebAssembly, a trap that loses the core).

use super::{EnvironmentQuery, Polygon, QueryValue, Segment, Sphere, Surface};
use crate::model::{LString, Model};
use crate::vocabulary::Command;
use glam::DVec3;

/// Most bytes a skeleton may hold (its segments, polygons, surfaces, spheres and query values):
/// about 3.9 million segments. Above it the plant is drawn as lines, as the mesh draws any plant
/// of more than `MeshOptions::max_vertices` vertices anyway.
pub const MAX_SKELETON_BYTES: usize = 512 << 20;

/// Most bytes a sketch's lines may hold (their ends, colours and modules, 52 bytes a segment):
/// about 10 million segments.
pub const MAX_SKETCH_BYTES: usize = 512 << 20;

/// What drawing a string would hold at most.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DrawingSize {
    /// Segments drawn (an upper bound: a zero-length move draws none).
    pub segments: usize,
    /// The other elements the skeleton records: polygons and their `.` points, leaves, spheres,
    /// query values (an upper bound, as `segments`).
    pub others: usize,
    /// Bytes of the skeleton ([`super::interpret`]).
    pub skeleton: usize,
    /// Bytes of the sketch's lines ([`super::sketch`]).
    pub sketch: usize,
}

impl DrawingSize {
    /// True when the skeleton fits [`MAX_SKELETON_BYTES`].
    pub fn skeleton_fits(&self) -> bool {
        self.skeleton <= MAX_SKELETON_BYTES
    }

    /// True when the sketch fits [`MAX_SKETCH_BYTES`].
    pub fn sketch_fits(&self) -> bool {
        self.sketch <= MAX_SKETCH_BYTES
    }
}

/// Bytes a sketch holds for one segment: two ends and two colours of three `f32`, and a module.
const SKETCH_SEGMENT_BYTES: usize = 12 * size_of::<f32>() + size_of::<u32>();

/// What one module of `command` adds to a skeleton at most, and the segments it draws.
fn skeleton_cost(command: Command) -> (usize, usize) {
    let segment = size_of::<Segment>();
    match command {
        // A move inside `{ … }` adds a point instead, which is smaller.
        Command::Forward | Command::ForwardNoVertex => (segment, 1),
        Command::Move | Command::MoveNoVertex | Command::PolygonVertex => (size_of::<DVec3>(), 0),
        Command::LineTo | Command::LineRel | Command::OrientedLineTo | Command::OrientedLineRel => {
            (segment, 1)
        }
        // Its three axes.
        Command::Frame => (3 * segment, 3),
        Command::StartPolygon => (size_of::<Polygon>() + size_of::<DVec3>(), 0),
        Command::Leaf | Command::Petal | Command::Surface => (size_of::<Surface>(), 0),
        Command::Sphere => (size_of::<Sphere>(), 0),
        Command::QueryPosition | Command::QueryHeading | Command::QueryUp | Command::QueryLeft => {
            (size_of::<QueryValue>(), 0)
        }
        Command::QueryEnvironment => (size_of::<EnvironmentQuery>(), 0),
        _ => (0, 0),
    }
}

/// What drawing `string` would hold, from how many times each module id occurs in it
/// (`id_counts`, indexed by id as [`crate::derive::Derivation::id_counts`]; empty: counted here
/// in one pass over the string).
pub fn drawing_size(model: &Model, string: &LString, id_counts: &[u64]) -> DrawingSize {
    let counted;
    let counts = if id_counts.is_empty() {
        let mut counts = vec![0u64; model.meanings.len()];
        for id in &string.ids {
            if let Some(n) = counts.get_mut(id.index()) {
                *n += 1;
            }
        }
        counted = counts;
        &counted[..]
    } else {
        id_counts
    };
    let (mut segments, mut others, mut skeleton) = (0usize, 0usize, 0usize);
    for (index, &n) in counts.iter().enumerate() {
        let command = model.meanings.get(index).copied().flatten();
        let Some(command) = command.and_then(|info| info.command()) else {
            continue;
        };
        let n = usize::try_from(n).unwrap_or(usize::MAX);
        let (bytes, drawn) = skeleton_cost(command);
        segments = segments.saturating_add(n.saturating_mul(drawn));
        // (A move records a point only inside a polygon: it is counted in bytes, not here.)
        let move_ = matches!(command, Command::Move | Command::MoveNoVertex);
        if drawn == 0 && bytes > 0 && !move_ {
            others = others.saturating_add(n);
        }
        skeleton = skeleton.saturating_add(n.saturating_mul(bytes));
    }
    DrawingSize {
        segments,
        others,
        skeleton,
        sketch: segments.saturating_mul(SKETCH_SEGMENT_BYTES),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What `source` after `iterations` steps would hold, counted both ways, and the segments
    /// its skeleton has.
    fn size(source: &str, iterations: u32) -> (DrawingSize, usize) {
        let build = crate::pipeline::build(
            source,
            &crate::pipeline::BuildOptions::with_iterations(iterations),
        );
        let model = build.model.as_ref().expect("a model");
        let string = build.derivation.turtle_string();
        let counted = drawing_size(model, string, &build.derivation.id_counts);
        assert_eq!(
            counted,
            drawing_size(model, string, &[]),
            "counts or a pass"
        );
        (counted, build.plant.skeleton.segments.len())
    }

    #[test]
    fn counts_the_segments_the_turtle_draws_and_their_bytes() {
        // F -> F[+F]F[-F]F: 5^3 = 125 F at n = 3, every one drawn.
        let (s, drawn) = size("axiom: F\nF -> F[+F]F[-F]F", 3);
        assert_eq!((s.segments, drawn), (125, 125));
        assert_eq!(s.skeleton, 125 * size_of::<Segment>());
        assert_eq!(s.sketch, 125 * 52);
    }

    #[test]
    fn a_frame_draws_three_and_a_polygon_holds_its_points() {
        let (s, drawn) = size("axiom: @Frame(1) {.f.f.}", 0);
        assert_eq!((s.segments, drawn), (3, 3));
        let points = 3 * size_of::<DVec3>() + 2 * size_of::<DVec3>();
        let polygon = size_of::<Polygon>() + size_of::<DVec3>();
        assert_eq!(s.skeleton, 3 * size_of::<Segment>() + polygon + points);
    }

    #[test]
    fn sixteen_million_segments_fit_neither() {
        // F -> FF, 2^24 segments: 2 GB as a skeleton, 832 MB as lines; 2^23: 1 GB and 416 MB;
        // 2^22: 512 MB, the skeleton's budget exactly.
        let source = "#max_modules 40000000\naxiom: F\nF -> FF";
        let count = |n| {
            let (file, _) = crate::syntax::parse(source);
            let model = crate::model::resolve(&file).0.expect("a model");
            let options = crate::derive::DeriveOptions {
                steps: n,
                ..Default::default()
            };
            let derivation = crate::derive::derive(&model, &options).expect("derived");
            drawing_size(&model, &derivation.string, &derivation.id_counts)
        };
        let s = count(24);
        assert_eq!(s.segments, 1 << 24);
        assert!(!s.skeleton_fits() && !s.sketch_fits(), "{s:?}");
        let s = count(23);
        assert!(!s.skeleton_fits() && s.sketch_fits(), "{s:?}");
        assert!(count(22).skeleton_fits());
    }
}
