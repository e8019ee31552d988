//! Stage 5, `mesh`: the skeleton becomes triangles in flat arrays ready for the GPU.
//!
//! Each segment becomes an open tube of `sides` quads whose ring lies in the turtle's L–U plane.
//! Widths are diameters measured in *width units*. By default ([`WidthUnit::Relative`]) one unit
//! is 1/300 of the skeleton's bounding-box diagonal, like cpfg's widths in pixels of a window that
//! frames the plant: `#width 1` draws thin but visible branches at any size, and `!(10)` a trunk
//! ten times thicker.

pub mod curve;
mod lines;
mod monotone;
mod pack;
pub mod parts;
pub mod polygon;
pub mod sphere;
pub mod surfaces;
mod tube;

use crate::turtle::Skeleton;
use glam::DVec3;
pub use lines::{segment_colors, segment_ends, segment_lines, segment_modules, SegmentLines};
pub use pack::{normal_samples, pack_colors, pack_normals};
pub use parts::{ChainPart, MeshParts, Part};

/// The mesh as four flat arrays. **This is the one place the layout is defined**; the wasm
/// boundary and the TypeScript `MeshBuffers` type refer here.
///
/// - `positions`: `f32` × 3 per vertex (x, y, z), in model units, Y up.
/// - `normals`: `f32` × 3 per vertex, unit length, pointing out of the surface.
/// - `colors`: `f32` × 3 per vertex (r, g, b), linear, 0..=1.
/// - `indices`: `u32` × 3 per triangle, each `< positions.len() / 3`, counter-clockwise seen
///   from outside (the side the normals point to). Leaves and polygons are two-sided: each is
///   there twice, once per side, with opposite normals.
/// - `ranges`: provenance, `u32` × 2 per range: (first triangle, module), sorted by first
///   triangle; a range runs to the next range's first triangle. `module` is the index, in the string
///   the turtle read, of the module that drew those triangles (a segment's `F`, a polygon's `{`, …).
/// - `color_ranges`: the colour index of every triangle, `u32` × 2 per range: (first triangle,
///   colour index), sorted and running like `ranges`. A triangle's index is that of the segment,
///   polygon, surface or sphere that drew it (`Skeleton::color` gives the colour); its vertices
///   carry that colour too, except where a tube passes from one segment to the next of another
///   colour, whose ring has the next segment's colour (the preview blends them along the quad).
///   The file writers group triangles by this index, one material per colour index. Stays in the
///   core (not copied to JavaScript).
/// - `uvs`: `f32` × 2 per vertex, texture coordinates (see `docs/LANGUAGE.md`, "Texture
///   coordinates"). Tubes: u runs 0..1 around the circumference (each ring has `sides + 1`
///   vertices, the last a copy of the first at u = 1, so the texture does not wrap backwards over
///   the seam) and v along the axis, accumulated over the chain in units of the tube's
///   circumference (bark is not stretched: one texture tile is as long as the tube is round);
///   caps map the disk into 0..1. Leaves and petals: u across and v along the leaf's own outline
///   frame, both 0..1. Polygons: a planar projection in their plane, u across and v from the first
///   point towards the farthest one, 0..1. Spheres: longitude and latitude, 0..1.
/// - `material_ranges`: the material kind of every triangle, `u32` × 2 per range (first
///   triangle, kind), sorted and running like `ranges`: [`MATERIAL_BARK`] (tubes and their caps),
///   [`MATERIAL_LEAF`] (predefined surfaces and polygons, two-sided) or [`MATERIAL_PLAIN`]
///   (spheres). The view and the writers choose the texture by it.
/// - `lines`, `line_colors`: only when the model is too large to mesh (`MeshOptions::max_vertices`):
///   `f32` × 3 per line end (two per segment) and `f32` × 3 colour per end; the triangle arrays
///   are then empty. Line `i` is `Skeleton::segments[i]` (its colour index is that segment's).
/// - `width_unit`: model units per width unit (what `#width 1` measured across), for writers that
///   draw widths themselves (SVG).
///
/// Where each chain, polygon, leaf and sphere of the skeleton lies in these arrays (contiguous runs
/// of vertices and triangles, in that order) is recorded by [`build_mesh_with_parts`] as
/// [`MeshParts`], for re-meshing a part alone (dragging a branch).
///
/// Memory: a tube of `sides` sides costs `sides + 1` vertices per joint (44 bytes each: position,
/// normal, colour, uv) and `2·sides` triangles per segment (24 bytes each), plus two caps per axis;
/// with the default 6 sides, about 370 bytes per segment.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshBuffers {
    pub positions: Vec<f32>,
    pub normals: Vec<f32>,
    pub colors: Vec<f32>,
    pub indices: Vec<u32>,
    pub ranges: Vec<u32>,
    pub color_ranges: Vec<u32>,
    pub uvs: Vec<f32>,
    pub material_ranges: Vec<u32>,
    pub lines: Vec<f32>,
    pub line_colors: Vec<f32>,
    pub width_unit: f64,
}

/// Material kind of tubes (bark texture).
pub const MATERIAL_BARK: u32 = 0;
/// Material kind of leaves, petals and polygons (leaf texture, two-sided, alpha-masked).
pub const MATERIAL_LEAF: u32 = 1;
/// Material kind of spheres (no texture).
pub const MATERIAL_PLAIN: u32 = 2;

impl MeshBuffers {
    pub fn vertex_count(&self) -> usize {
        self.positions.len() / 3
    }

    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// Checks the invariants every mesh satisfies: array lengths agree, indices in range, finite
    /// floats, colours in 0..=1, unit normals, no degenerate triangle, and counter-clockwise
    /// winding (each face normal agrees with its vertex normals). Returns the first violation.
    pub fn check(&self) -> Result<(), String> {
        let vertices = self.vertex_count();
        if !self.positions.len().is_multiple_of(3) || self.normals.len() != self.positions.len() {
            return Err("positions and normals must hold 3 floats per vertex each".into());
        }
        if self.colors.len() != self.positions.len() || !self.indices.len().is_multiple_of(3) {
            return Err("colors must hold 3 floats per vertex and indices 3 per triangle".into());
        }
        self.check_ranges("ranges", &self.ranges)?;
        self.check_ranges("color_ranges", &self.color_ranges)?;
        if self.color_ranges.is_empty() != (self.triangle_count() == 0) {
            return Err("color_ranges must cover every triangle".into());
        }
        self.check_ranges("material_ranges", &self.material_ranges)?;
        if self.material_ranges.is_empty() != (self.triangle_count() == 0) {
            return Err("material_ranges must cover every triangle".into());
        }
        if self.uvs.len() != 2 * vertices {
            return Err("uvs must hold 2 floats per vertex".into());
        }
        if !self.uvs.iter().all(|v| v.is_finite()) {
            return Err("a texture coordinate is not finite".into());
        }
        if !self.lines.len().is_multiple_of(6) || self.line_colors.len() != self.lines.len() {
            return Err("lines must hold two 3-float ends per segment, each with a colour".into());
        }
        if let Some(i) = self.indices.iter().find(|&&i| i as usize >= vertices) {
            return Err(format!("index {i} out of range ({vertices} vertices)"));
        }
        if !self
            .positions
            .iter()
            .chain(&self.normals)
            .chain(&self.colors)
            .all(|v| v.is_finite())
        {
            return Err("a float is not finite".into());
        }
        if !self.colors.iter().all(|c| (0.0..=1.0).contains(c)) {
            return Err("a colour component is outside 0..=1".into());
        }
        let vector = |array: &[f32], i: u32| {
            let i = i as usize * 3;
            DVec3::new(array[i] as f64, array[i + 1] as f64, array[i + 2] as f64)
        };
        for v in 0..vertices as u32 {
            let length = vector(&self.normals, v).length();
            if (length - 1.0).abs() > 1e-5 {
                return Err(format!("normal of vertex {v} has length {length}"));
            }
        }
        for t in self.indices.chunks_exact(3) {
            let p = |i: u32| vector(&self.positions, i);
            let face = (p(t[1]) - p(t[0])).cross(p(t[2]) - p(t[0]));
            if face.length() == 0.0 {
                return Err(format!("degenerate triangle {t:?}"));
            }
            let normals = vector(&self.normals, t[0])
                + vector(&self.normals, t[1])
                + vector(&self.normals, t[2]);
            if face.dot(normals) <= 0.0 {
                return Err(format!("triangle {t:?} winds clockwise seen from outside"));
            }
        }
        Ok(())
    }

    /// (first triangle, value) pairs at increasing triangles inside the mesh, the first at 0.
    fn check_ranges(&self, name: &str, ranges: &[u32]) -> Result<(), String> {
        if !ranges.len().is_multiple_of(2) {
            return Err(format!("{name} must hold (first triangle, value) pairs"));
        }
        let firsts: Vec<u32> = ranges.iter().step_by(2).copied().collect();
        if firsts.windows(2).any(|w| w[0] >= w[1])
            || firsts
                .last()
                .is_some_and(|&f| f as usize >= self.triangle_count())
        {
            return Err(format!(
                "{name} must start at increasing triangles inside the mesh"
            ));
        }
        if !firsts.is_empty() && firsts[0] != 0 {
            return Err(format!("the first of {name} must start at triangle 0"));
        }
        Ok(())
    }

    /// The colour index of each triangle, expanded from `color_ranges`.
    pub fn triangle_color_indices(&self) -> Vec<u16> {
        self.per_triangle(&self.color_ranges, |value| {
            value.min(u16::MAX as u32) as u16
        })
    }

    /// The material kind of each triangle, expanded from `material_ranges`.
    pub fn triangle_materials(&self) -> Vec<u8> {
        self.per_triangle(&self.material_ranges, |value| value.min(255) as u8)
    }

    /// Expands `[first triangle, value, ...]` ranges to one `convert(value)` per triangle.
    fn per_triangle<T: Copy>(&self, ranges: &[u32], convert: impl Fn(u32) -> T) -> Vec<T> {
        let count = self.triangle_count();
        let mut out = Vec::with_capacity(count);
        let mut pairs = ranges.chunks_exact(2).peekable();
        while let Some(pair) = pairs.next() {
            let end = pairs.peek().map_or(count, |next| next[0] as usize);
            out.resize(end.max(out.len()), convert(pair[1]));
        }
        out
    }

    /// `[[min x, y, z], [max x, y, z]]` of the vertices (or of the lines, in the fallback); all
    /// zeros for an empty mesh.
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        let points = if self.positions.is_empty() {
            &self.lines
        } else {
            &self.positions
        };
        if points.is_empty() {
            return [[0.0; 3]; 2];
        }
        // In f32 by comparisons: converting every coordinate and `f64::min`'s NaN handling were
        // about a tenth of the whole mesh stage (the stats ask for these bounds after every
        // mesh). Exact: f32 to f64 is. Four points at a time with WebAssembly SIMD (`f32_box`:
        // 1.24d n = 10's mesh stage about 1.3 ms faster), whose lanes meet equal values in
        // another order. That matters for a bound of zero only: `take_points` keeps the first
        // of equal values, so its sign is the first zero's of that coordinate, looked up from the
        // start (a plant's base is often at 0, and its first vertex too: 1.24d's is).
        let (mut min, mut max) = crate::turtle::f32_box(points);
        for k in 0..3 {
            for bound in [&mut min[k], &mut max[k]] {
                if *bound == 0.0 {
                    let mut values = points.chunks_exact(3).map(|p| p[k]);
                    *bound = values.find(|&v| v == 0.0).unwrap_or(*bound);
                }
            }
        }
        [min.map(f64::from), max.map(f64::from)]
    }
}

/// How a width value becomes a diameter in model units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WidthUnit {
    /// One width unit is this fraction of the skeleton's bounding-box diagonal; but when the
    /// grammar sets no width (`Skeleton::widths_set`), at most [`DEFAULT_WIDTH_PER_LENGTH`] of its
    /// internodes' median length, so that a plant of many short internodes (ABOP 1.24a) is drawn
    /// thin, as in the book, not as beads as thick as they are long.
    Relative(f64),
    /// One width unit is this many model units.
    Absolute(f64),
}

/// The default width of an internode, where the grammar sets none, as a share of the internodes'
/// median length (see [`WidthUnit::Relative`]).
pub const DEFAULT_WIDTH_PER_LENGTH: f64 = 0.1;

/// Model units per width unit for `skeleton` (see [`WidthUnit`]).
pub fn resolve_width_unit(skeleton: &Skeleton, unit: WidthUnit) -> f64 {
    match unit {
        WidthUnit::Absolute(u) => u,
        WidthUnit::Relative(fraction) => {
            let relative = fraction * skeleton_diagonal(skeleton);
            if skeleton.widths_set {
                return relative;
            }
            let mut lengths: Vec<f64> = skeleton
                .segments
                .iter()
                .map(|s| s.start.distance(s.end))
                .collect();
            if lengths.is_empty() {
                return relative;
            }
            let middle = lengths.len() / 2;
            // The element a sort would put in the middle, selected without sorting: sorting the
            // 116,050 lengths of ABOP 1.24d n = 10 was 7% of its mesh stage (issue 20).
            let median = crate::sort::select_nth_by(&mut lengths, middle, f64::total_cmp);
            if median > 0.0 && median.is_finite() {
                relative.min(DEFAULT_WIDTH_PER_LENGTH * median)
            } else {
                relative
            }
        }
    }
}

/// Fewest sides a tube may have in the view options (the studio's, links', the CLI's `--sides`).
pub const MIN_SIDES: u32 = 3;
/// Most sides a tube may have in the view options.
pub const MAX_SIDES: u32 = 64;

/// Options of the mesh stage.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshOptions {
    /// Sides of each tube (at least 3).
    pub sides: u32,
    pub width_unit: WidthUnit,
    /// Make every axis a smooth generalized cylinder, not only those between `@Gc` and `@Ge`.
    pub smooth_all: bool,
    /// Rings per segment along a smooth axis.
    pub smooth_samples: u32,
    /// Segments around (and half as many rings along) each sphere.
    pub sphere_segments: u32,
    /// Above this many vertices the mesh falls back to lines (`MeshBuffers::lines`).
    pub max_vertices: usize,
    /// Mesh the segments as tubes (true), or leave them out: the studio's Lines mode draws the
    /// segments as lines and needs the mesh only for leaves, polygons and spheres.
    pub tubes: bool,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            sides: 6,
            width_unit: WidthUnit::Relative(1.0 / 300.0),
            smooth_all: false,
            smooth_samples: 4,
            sphere_segments: 12,
            max_vertices: 4_000_000,
            tubes: true,
        }
    }
}

impl MeshOptions {
    /// The default options with the studio's view options: `sides` (clamped to
    /// [`MIN_SIDES`]..=[`MAX_SIDES`], default 6; the CLI refuses `--sides` out of that range
    /// before it gets here) and `smooth_all` (default false). The wasm boundary and the CLI's
    /// `--sides` and `--smooth-all` both build their meshes with these, so a download is the mesh
    /// on screen.
    pub fn view(sides: Option<u32>, smooth_all: Option<bool>) -> MeshOptions {
        let defaults = MeshOptions::default();
        MeshOptions {
            sides: sides.map_or(defaults.sides, |s| s.clamp(MIN_SIDES, MAX_SIDES)),
            smooth_all: smooth_all.unwrap_or(defaults.smooth_all),
            ..defaults
        }
    }
}

/// Consecutive segments whose directions differ by more than this start a new tube: a ring at
/// a sharper joint would pinch.
const MAX_JOINT_ANGLE_COS: f64 = -0.2;

/// Builds the mesh of a skeleton: a tube per axis (segments that continue each other share their
/// joint rings, ends are capped), smooth axes as generalized cylinders through their joints,
/// polygons and predefined surfaces two-sided, spheres. Above `max_vertices` it returns lines.
pub fn build_mesh(skeleton: &Skeleton, options: &MeshOptions) -> MeshBuffers {
    mesh_of(skeleton, options, false).0
}

/// [`build_mesh`], and where each element of the skeleton landed in the mesh ([`MeshParts`]):
/// what a partial re-mesh needs to rebuild or move one part alone.
pub fn build_mesh_with_parts(
    skeleton: &Skeleton,
    options: &MeshOptions,
) -> (MeshBuffers, MeshParts) {
    mesh_of(skeleton, options, true)
}

/// The mesh, and its parts when `with_parts` (else empty parts: the same mesh, without the
/// bookkeeping).
fn mesh_of(
    skeleton: &Skeleton,
    options: &MeshOptions,
    with_parts: bool,
) -> (MeshBuffers, MeshParts) {
    let unit = resolve_width_unit(skeleton, options.width_unit);
    let mut builder = Builder::new(options, unit);
    let mut parts = MeshParts {
        segment_chain: if with_parts {
            vec![parts::NO_CHAIN; skeleton.segments.len()]
        } else {
            Vec::new()
        },
        ..MeshParts::default()
    };
    let estimate = builder.estimate(skeleton);
    if estimate > options.max_vertices {
        builder.lines(skeleton);
        parts.lines = true;
        return (builder.mesh, parts);
    }
    // Grow each array once: reallocating arrays of millions of floats costs more than meshing.
    builder.mesh.positions.reserve(3 * estimate);
    builder.mesh.normals.reserve(3 * estimate);
    builder.mesh.colors.reserve(3 * estimate);
    builder.mesh.uvs.reserve(2 * estimate);
    builder.mesh.indices.reserve(6 * estimate);
    let tubes = if options.tubes {
        chains(skeleton, unit)
    } else {
        Chains::default()
    };
    let ends = parts::chain_ends(skeleton, tubes.iter());
    for (chain, (start_cap, end_dome)) in tubes.iter().zip(ends) {
        let before = builder.mark();
        builder.tube(skeleton, chain, start_cap, end_dome);
        if !with_parts {
            continue;
        }
        let part = builder.part_since(before);
        let ranges = builder.element_ranges_since(&before);
        for &s in chain {
            parts.segment_chain[s as usize] = parts.chains.len() as u32;
        }
        parts.chains.push(ChainPart {
            part,
            segments: chain.to_vec(),
            start_cap,
            end_dome,
            ranges,
        });
    }
    for i in 0..skeleton.polygons.len() {
        let before = builder.mark();
        builder.polygon(skeleton, i);
        parts.polygons.push(builder.part_since(before));
    }
    for i in 0..skeleton.surfaces.len() {
        let before = builder.mark();
        builder.surface(skeleton, i);
        parts.surfaces.push(builder.part_since(before));
    }
    for i in 0..skeleton.spheres.len() {
        let before = builder.mark();
        builder.sphere_of(skeleton, i);
        parts.spheres.push(builder.part_since(before));
    }
    (builder.mesh, parts)
}

/// A point as a hash key (exact: joints are the same computed value, not merely close; the two
/// zeros are one): where a chain starts hidden at another segment's end.
pub fn joint_key(p: DVec3) -> [u64; 3] {
    key(p)
}

fn key(p: DVec3) -> [u64; 3] {
    let p = p + DVec3::ZERO;
    [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()]
}

/// Whether segment `i` joins segment `p` (the one it continues) in one tube: both have a width,
/// the same smoothness, the joint between them is not sharper than `MAX_JOINT_ANGLE_COS`, and the
/// joint's ring does not reach past the middle of either segment (a tube much wider than a short
/// segment at a bend: its rings would cross and the tube turn inside out). `unit` is the width unit.
pub(crate) fn joins(skeleton: &Skeleton, p: usize, i: usize, unit: f64) -> bool {
    let (before, after) = (&skeleton.segments[p], &skeleton.segments[i]);
    if !(after.width > 0.0 && before.width > 0.0 && before.smooth == after.smooth) {
        return false;
    }
    let (along_before, along_after) = (before.end - before.start, after.end - after.start);
    let cos = along_before.normalize().dot(along_after.normalize());
    // A zero-length segment has no direction (NaN): it joins nothing.
    if cos.is_nan() || cos <= MAX_JOINT_ANGLE_COS {
        return false;
    }
    // The joint ring lies across the bisector, tilted by half the bend from each segment's
    // cross-section: it reaches radius × sin(bend / 2) along each of them.
    let reach = 0.5 * after.width * unit * ((1.0 - cos.clamp(-1.0, 1.0)) * 0.5).sqrt();
    let overruns = reach >= 0.5 * along_before.length().min(along_after.length());
    !overruns
}

/// The axes of a skeleton ([`chains`]): lists of segment indices, each continuing the one before,
/// stored end to end (a plant has tens of thousands of them: one list each cost an allocation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chains {
    /// Every chain's segments, chain after chain.
    segments: Vec<u32>,
    /// Where each chain ends in `segments`.
    ends: Vec<u32>,
}

impl Chains {
    /// How many chains.
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    /// No chain at all (no tubes).
    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    /// Each chain's segments, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &[u32]> + Clone + '_ {
        (0..self.ends.len()).map(move |k| {
            let from = if k == 0 { 0 } else { self.ends[k - 1] };
            &self.segments[from as usize..self.ends[k] as usize]
        })
    }
}

/// The axes of the skeleton, each a list of segment indices continuing the one before, in the
/// order of their first segments. A chain breaks where widths are zero, at sharp joints, where
/// smoothness changes, and where the joint's ring would reach past the middle of a segment it
/// joins (see [`joins`]). `unit` is the width unit.
pub(crate) fn chains(skeleton: &Skeleton, unit: f64) -> Chains {
    const NONE: u32 = u32::MAX;
    let segments = &skeleton.segments;
    // The segment that continues each one (NONE: none), and the segments that start a chain,
    // found in one pass (the starts in order: a second pass reading every segment's width again
    // was a sixth of this function's time in 1.24d n = 10).
    let mut next = vec![NONE; segments.len()];
    let mut starts = Vec::new();
    for (i, s) in segments.iter().enumerate() {
        if s.width <= 0.0 {
            continue;
        }
        match s.previous.map(|p| p as usize) {
            Some(p) if next[p] == NONE && joins(skeleton, p, i, unit) => next[p] = i as u32,
            _ => starts.push(i as u32),
        }
    }
    let mut chains = Chains {
        segments: Vec::with_capacity(segments.len()),
        ends: Vec::with_capacity(starts.len()),
    };
    for start in starts {
        let mut at = start;
        while at != NONE {
            chains.segments.push(at);
            at = next[at as usize];
        }
        chains.ends.push(chains.segments.len() as u32);
    }
    chains
}

pub(crate) struct Builder<'a> {
    mesh: MeshBuffers,
    options: &'a MeshOptions,
    unit: f64,
    sides: usize,
    /// (sin, cos) of each side's angle around a ring.
    ring: Vec<(f64, f64)>,
    /// (first triangle, segment) pairs, as `ranges` but naming the segment that drew each
    /// triangle of a tube (`parts::NO_CHAIN` for other elements): what [`MeshParts`] records.
    element_ranges: Vec<u32>,
    /// The segment the next `range` call stands for.
    element: u32,
    /// The material kind the next `range` call stands for.
    material: u32,
    scratch: tube::TubeScratch,
}

impl<'a> Builder<'a> {
    fn new(options: &'a MeshOptions, unit: f64) -> Builder<'a> {
        let sides = options.sides.max(3) as usize;
        Builder {
            mesh: MeshBuffers {
                width_unit: unit,
                ..MeshBuffers::default()
            },
            options,
            unit,
            sides,
            ring: (0..sides)
                .map(|k| (k as f64 / sides as f64 * std::f64::consts::TAU).sin_cos())
                .collect(),
            element_ranges: Vec::new(),
            element: parts::NO_CHAIN,
            material: MATERIAL_BARK,
            scratch: tube::TubeScratch::default(),
        }
    }

    /// The position of the next vertex, triangle and element range.
    fn mark(&self) -> [u32; 3] {
        [
            self.mesh.vertex_count() as u32,
            self.mesh.triangle_count() as u32,
            self.element_ranges.len() as u32,
        ]
    }

    /// The part written since `mark`.
    fn part_since(&self, mark: [u32; 3]) -> Part {
        Part {
            first_vertex: mark[0],
            vertices: self.mesh.vertex_count() as u32 - mark[0],
            first_triangle: mark[1],
            triangles: self.mesh.triangle_count() as u32 - mark[1],
        }
    }

    /// The element ranges written since `mark`, their first triangles counted from the mark's.
    fn element_ranges_since(&self, mark: &[u32; 3]) -> Vec<u32> {
        let mut ranges = self.element_ranges[mark[2] as usize..].to_vec();
        for pair in ranges.chunks_exact_mut(2) {
            pair[0] -= mark[1];
        }
        ranges
    }

    fn polygon(&mut self, skeleton: &Skeleton, i: usize) {
        let p = &skeleton.polygons[i];
        self.element = parts::NO_CHAIN;
        self.flat(&p.points, None, skeleton, p.color, p.module);
    }

    fn surface(&mut self, skeleton: &Skeleton, i: usize) {
        let s = &skeleton.surfaces[i];
        let kind = match s.kind {
            crate::turtle::SurfaceKind::Leaf => surfaces::SurfaceKind::Leaf,
            crate::turtle::SurfaceKind::Petal => surfaces::SurfaceKind::Petal,
        };
        let points = surfaces::place(kind, s.origin, s.heading, s.left, s.scale);
        self.element = parts::NO_CHAIN;
        // The leaf's own frame: across along `left`, along the heading.
        let uvs = unit_square(points.iter().map(|p| {
            let d = *p - s.origin;
            (d.dot(s.left), d.dot(s.heading))
        }));
        self.flat(&points, Some(uvs), skeleton, s.color, s.module);
    }

    fn sphere_of(&mut self, skeleton: &Skeleton, i: usize) {
        let s = &skeleton.spheres[i];
        let radius = s.radius_width.map_or(s.radius, |w| w * self.unit);
        self.element = parts::NO_CHAIN;
        self.sphere(s.center, radius, skeleton, s.color, s.module);
    }

    /// An upper bound of the vertices the full mesh needs.
    fn estimate(&self, skeleton: &Skeleton) -> usize {
        let rings_per_segment =
            if self.options.smooth_all || skeleton.segments.iter().any(|s| s.smooth) {
                self.options.smooth_samples.max(1) as usize
            } else {
                1
            };
        // Each segment's rings and two more (a start ring, a cap). Rounded ends (about 3 rings)
        // close only axes that branch at their end, a few of the segments: counting one for every
        // segment would send ABOP 1.24d at n = 7 (116,050 segments, 1.3 M vertices meshed) to the
        // lines fallback. The arrays grow past this when a plant needs it.
        let tubes = if self.options.tubes {
            skeleton.segments.len() * (rings_per_segment + 2) * (self.sides + 1)
        } else {
            0
        };
        let flats: usize = skeleton
            .polygons
            .iter()
            .map(|p| 2 * p.points.len())
            .sum::<usize>()
            + skeleton.surfaces.len() * 64;
        let spheres = skeleton.spheres.len() * (self.options.sphere_segments as usize + 1).pow(2);
        tubes + flats + spheres
    }

    fn vertex(&mut self, p: DVec3, n: DVec3, c: [f32; 3], uv: [f32; 2]) -> u32 {
        let index = self.mesh.vertex_count() as u32;
        let mesh = &mut self.mesh;
        push(&mut mesh.uvs, uv);
        push(&mut mesh.positions, [p.x as f32, p.y as f32, p.z as f32]);
        push(&mut mesh.normals, [n.x as f32, n.y as f32, n.z as f32]);
        push(&mut mesh.colors, c);
        index
    }

    /// Starts a provenance range and a colour range: the triangles from here on come from
    /// `module` and have colour index `color`.
    fn range(&mut self, module: u32, color: u16) {
        let first = self.mesh.triangle_count() as u32;
        push_range(&mut self.mesh.ranges, first, module);
        push_range(&mut self.mesh.color_ranges, first, color as u32);
        push_range(&mut self.mesh.material_ranges, first, self.material);
        push_range(&mut self.element_ranges, first, self.element);
    }

    /// A polygon or predefined surface, two-sided: the front faces its normal, the back the other way.
    /// `uvs` holds a texture coordinate per point, or `None` for a polygon's planar projection
    /// (both sides share them: the back shows the texture mirrored, as the back of a leaf does).
    fn flat(
        &mut self,
        points: &[DVec3],
        uvs: Option<Vec<[f32; 2]>>,
        skeleton: &Skeleton,
        color: u16,
        module: u32,
    ) {
        let t = polygon::triangulate(points);
        if t.triangles.is_empty() {
            return;
        }
        let uvs = uvs.unwrap_or_else(|| polygon_uvs(points, t.normal));
        self.material = MATERIAL_LEAF;
        self.range(module, color);
        let c = skeleton.color(color);
        for (normal, flip) in [(t.normal, false), (-t.normal, true)] {
            let first = self.mesh.vertex_count() as u32;
            for (p, uv) in points.iter().zip(&uvs) {
                self.vertex(*p, normal, c, *uv);
            }
            for tri in &t.triangles {
                let [a, b, d] = tri.map(|i| first + i);
                if flip {
                    self.mesh.indices.extend([a, d, b]);
                } else {
                    self.mesh.indices.extend([a, b, d]);
                }
            }
        }
    }

    fn sphere(&mut self, center: DVec3, radius: f64, skeleton: &Skeleton, color: u16, module: u32) {
        let segments = self.options.sphere_segments.max(3);
        let s = sphere::sphere(center, radius, segments, segments / 2);
        if s.triangles.is_empty() {
            return;
        }
        self.material = MATERIAL_PLAIN;
        self.range(module, color);
        let c = skeleton.color(color);
        let first = self.mesh.vertex_count() as u32;
        for (p, n) in s.positions.iter().zip(&s.normals) {
            // Longitude and latitude of the normal.
            let u = 0.5 + n.z.atan2(n.x) / std::f64::consts::TAU;
            let v = n.y.clamp(-1.0, 1.0).acos() / std::f64::consts::PI;
            self.vertex(*p, *n, c, [u as f32, v as f32]);
        }
        for tri in &s.triangles {
            self.mesh.indices.extend(tri.map(|i| first + i));
        }
    }

    /// The fallback for models too large to mesh: each segment as a coloured line.
    fn lines(&mut self, skeleton: &Skeleton) {
        let lines = segment_lines(skeleton);
        self.mesh.lines = lines.ends;
        self.mesh.line_colors = lines.colors;
    }
}

/// 2-D coordinates scaled into the unit square by their bounding box (a zero extent maps to 0).
fn unit_square(points: impl Iterator<Item = (f64, f64)> + Clone) -> Vec<[f32; 2]> {
    let (mut lo, mut hi) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    for (a, b) in points.clone() {
        lo = (lo.0.min(a), lo.1.min(b));
        hi = (hi.0.max(a), hi.1.max(b));
    }
    let scale = |x: f64, l: f64, h: f64| {
        let r = if h - l > 1e-12 {
            (x - l) / (h - l)
        } else {
            0.0
        };
        if r.is_finite() {
            r.clamp(0.0, 1.0) as f32
        } else {
            0.0
        }
    };
    points
        .map(|(a, b)| [scale(a, lo.0, hi.0), scale(b, lo.1, hi.1)])
        .collect()
}

/// A polygon's texture coordinates: projected in its plane with v from the first point towards
/// the point farthest from it (a leaf drawn from its base runs along its length) and u across,
/// scaled into 0..1.
fn polygon_uvs(points: &[DVec3], normal: DVec3) -> Vec<[f32; 2]> {
    let Some(&origin) = points.first() else {
        return Vec::new();
    };
    let far = points
        .iter()
        .map(|p| *p - origin)
        .max_by(|a, b| a.length_squared().total_cmp(&b.length_squared()))
        .unwrap_or(DVec3::Y);
    let along = far.try_normalize().unwrap_or(DVec3::Y);
    let across = normal
        .cross(along)
        .try_normalize()
        .unwrap_or_else(|| along.any_orthonormal_vector());
    unit_square(points.iter().map(|p| {
        let d = *p - origin;
        (d.dot(across), d.dot(along))
    }))
}

/// Appends (first, value) to a range list unless the last range has that value already; a range
/// that would stay empty is overwritten.
fn push_range(ranges: &mut Vec<u32>, first: u32, value: u32) {
    if let [.., last_first, last_value] = ranges[..] {
        if last_value == value {
            return;
        }
        if last_first == first {
            let n = ranges.len();
            ranges[n - 1] = value;
            return;
        }
    }
    push(ranges, [first, value]);
}

// The mesh's arrays grow through `append` and `push`, not `Vec::resize` and `Vec::extend`: the
// first plant's core (crate/pkg-core, which the studio builds with until its studio core has
// loaded) is built for size (opt-level "s", scripts/build-wasm.sh), which leaves those as calls
// that write one element at a time, and they took a third of the mesh stage (ABOP 1.24d n = 10,
// 1.09 M vertices: 69 ms against 47, and 41 at opt-level 3; measured in Node 2026-11-27). `append`
// writes each new element once: growing the arrays with zeros first and writing over them cost
// another tenth.

/// Appends `n` groups of `W` elements to `v`, group `k` being `group(k)`, the arrays grown once.
#[inline(always)]
fn append<T: Copy, const W: usize>(
    v: &mut Vec<T>,
    n: usize,
    mut group: impl FnMut(usize) -> [T; W],
) {
    let (at, len) = (v.len(), n * W);
    if v.capacity() - at < len {
        v.reserve(len);
    }
    for (k, slot) in v.spare_capacity_mut()[..len]
        .chunks_exact_mut(W)
        .enumerate()
    {
        let values = group(k);
        // SAFETY: `slot` is a checked slice of `W` elements and `values` is `W` of them (`Copy`):
        // a copy of a constant size.
        unsafe { std::ptr::copy_nonoverlapping(values.as_ptr(), slot.as_mut_ptr().cast(), W) };
    }
    // SAFETY: the capacity holds `len` more, and the loop wrote all of them (`len / W` groups of
    // exactly `W`; a panic in `group` leaves the length as it was).
    unsafe { v.set_len(at + len) };
}

/// Appends `values` to `v`.
#[inline(always)]
fn push<T: Copy, const N: usize>(v: &mut Vec<T>, values: [T; N]) {
    append(v, 1, |_| values);
}

/// Length of the diagonal of the box around every segment end point.
pub(crate) fn skeleton_diagonal(skeleton: &Skeleton) -> f64 {
    let mut min = DVec3::INFINITY;
    let mut max = DVec3::NEG_INFINITY;
    for s in &skeleton.segments {
        min = min.min(s.start).min(s.end);
        max = max.max(s.start).max(s.end);
    }
    for p in skeleton.polygons.iter().flat_map(|p| &p.points) {
        min = min.min(*p);
        max = max.max(*p);
    }
    if min.x > max.x {
        0.0
    } else {
        (max - min).length()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Vertices of a rounded tube end with 8 sides: 3 rings of 8 and the apex.
    const DOME: usize = 3 * 8 + 1;
    use crate::turtle::{Polygon, Segment, Sphere};

    fn segment(start: DVec3, end: DVec3, previous: Option<u32>) -> Segment {
        Segment {
            start,
            end,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            width: 1.0,
            color: 0,
            module: 0,
            previous,
            smooth: false,
            anchor: previous,
        }
    }

    fn absolute(unit: f64) -> MeshOptions {
        MeshOptions {
            sides: 8,
            width_unit: WidthUnit::Absolute(unit),
            ..MeshOptions::default()
        }
    }

    /// A polygon with no anchor.
    fn polygon(points: Vec<DVec3>, color: u16, module: u32) -> Polygon {
        Polygon {
            points,
            color,
            module,
            anchor: None,
        }
    }

    /// A sphere of radius 1 at the origin, with no anchor.
    fn unit_sphere(color: u16, module: u32) -> Sphere {
        Sphere {
            center: DVec3::ZERO,
            radius: 1.0,
            radius_width: None,
            color,
            module,
            anchor: None,
        }
    }

    /// The chains of `skeleton` as a list of lists, to compare.
    fn chain_lists(skeleton: &Skeleton, unit: f64) -> Vec<Vec<u32>> {
        chains(skeleton, unit).iter().map(<[u32]>::to_vec).collect()
    }

    /// The mesh of `skeleton` with 8 sides and widths in units of 0.1, checked for consistency.
    fn checked_mesh(skeleton: &Skeleton) -> MeshBuffers {
        let mesh = build_mesh(skeleton, &absolute(0.1));
        assert_eq!(mesh.check(), Ok(()));
        mesh
    }

    #[test]
    fn a_segment_is_a_capped_tube() {
        let skeleton = Skeleton {
            segments: vec![segment(DVec3::ZERO, DVec3::Y, None)],
            ..Skeleton::default()
        };
        let mesh = build_mesh(&skeleton, &absolute(0.2));
        // Two rings of 8 + 1 (the seam's copy), and two caps of 8 + 1 vertices; 16 side
        // triangles and 8 per cap.
        assert_eq!(mesh.vertex_count(), 18 + 18);
        assert_eq!(mesh.triangle_count(), 16 + 16);
        assert_eq!(mesh.check(), Ok(()));
        let [min, max] = mesh.bounds();
        assert!((max[0] - 0.1).abs() < 1e-6 && min[1].abs() < 1e-6 && (max[1] - 1.0).abs() < 1e-6);
    }

    #[test]
    fn an_axis_shares_its_joints() {
        // Three segments of one axis with turns: one tube of four rings, not three tubes.
        let a = DVec3::ZERO;
        let b = DVec3::Y;
        let c = DVec3::new(-0.3, 1.9, 0.0);
        let d = DVec3::new(-0.4, 2.9, 0.0);
        let skeleton = Skeleton {
            segments: vec![
                segment(a, b, None),
                segment(b, c, Some(0)),
                segment(c, d, Some(1)),
            ],
            ..Skeleton::default()
        };
        let mesh = checked_mesh(&skeleton);
        assert_eq!(mesh.vertex_count(), 4 * 9 + 2 * 9);
        // The joint ring at b is the bisector's: its vertices are all at distance 0.05 from b.
        let ring = (9..18).map(|v| {
            DVec3::new(
                mesh.positions[v * 3] as f64,
                mesh.positions[v * 3 + 1] as f64,
                mesh.positions[v * 3 + 2] as f64,
            )
        });
        for p in ring {
            assert!(((p - b).length() - 0.05).abs() < 1e-6);
        }
    }

    #[test]
    fn tube_uvs_go_round_once_with_a_seam_and_grow_along_the_axis_in_circumferences() {
        let (a, b, c) = (DVec3::ZERO, DVec3::Y, DVec3::new(0.0, 2.0, 0.0));
        let skeleton = Skeleton {
            segments: vec![segment(a, b, None), segment(b, c, Some(0))],
            ..Skeleton::default()
        };
        let mesh = checked_mesh(&skeleton);
        let uv = |v: usize| (mesh.uvs[2 * v], mesh.uvs[2 * v + 1]);
        let circumference = std::f64::consts::PI * 0.1;
        for ring in 0..3 {
            // u from 0 to 1 in 8 steps; the seam's two vertices share a position.
            for j in 0..=8 {
                let (u, v) = uv(ring * 9 + j);
                assert!((u - j as f32 / 8.0).abs() < 1e-6);
                assert!((v as f64 - ring as f64 / circumference).abs() < 1e-3, "{v}");
            }
            let p = |v: usize| &mesh.positions[3 * v..3 * v + 3];
            assert_eq!(p(ring * 9), p(ring * 9 + 8));
        }
        // Continuous around the tube: no side triangle (after the start cap's 8) spans the seam
        // backwards.
        for t in mesh.indices[3 * 8..3 * (8 + 32)].chunks_exact(3) {
            let us: Vec<f32> = t.iter().map(|&i| uv(i as usize).0).collect();
            let spread = us.iter().cloned().fold(f32::MIN, f32::max)
                - us.iter().cloned().fold(f32::MAX, f32::min);
            assert!(spread <= 1.0 / 8.0 + 1e-6);
        }
        assert!(mesh
            .triangle_materials()
            .iter()
            .all(|&m| m as u32 == MATERIAL_BARK));
    }

    #[test]
    fn leaves_polygons_and_spheres_have_uvs_in_the_unit_square_and_their_materials() {
        let skeleton = Skeleton {
            polygons: vec![polygon(
                vec![DVec3::ZERO, DVec3::X, DVec3::new(0.5, 2.0, 0.0)],
                0,
                0,
            )],
            surfaces: vec![crate::turtle::Surface {
                kind: crate::turtle::SurfaceKind::Leaf,
                origin: DVec3::ZERO,
                heading: DVec3::Y,
                left: DVec3::NEG_X,
                scale: 1.0,
                color: 0,
                module: 1,
                anchor: None,
            }],
            spheres: vec![unit_sphere(0, 2)],
            ..Skeleton::default()
        };
        let mesh = checked_mesh(&skeleton);
        assert!(mesh.uvs.iter().all(|x| (0.0..=1.0).contains(x)));
        let materials = mesh.triangle_materials();
        assert!(materials.contains(&(MATERIAL_LEAF as u8)));
        assert_eq!(*materials.last().unwrap(), MATERIAL_PLAIN as u8);
        // The polygon's tip (farthest from its first point) is at v = 1, its base at v = 0.
        assert_eq!(mesh.uvs[1], 0.0);
        assert_eq!(mesh.uvs[5], 1.0);
    }

    #[test]
    fn without_tubes_only_leaves_polygons_and_spheres_are_meshed() {
        let mut skeleton = Skeleton {
            segments: vec![
                segment(DVec3::ZERO, DVec3::Y, None),
                segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0)),
            ],
            polygons: vec![polygon(
                vec![DVec3::ZERO, DVec3::X, DVec3::new(0.5, 2.0, 0.0)],
                0,
                5,
            )],
            spheres: vec![unit_sphere(0, 6)],
            ..Skeleton::default()
        };
        let no_tubes = MeshOptions {
            tubes: false,
            ..absolute(0.1)
        };
        let mesh = build_mesh(&skeleton, &no_tubes);
        mesh.check().expect("a valid mesh");
        assert!(!mesh.triangle_materials().contains(&(MATERIAL_BARK as u8)));
        // The very triangles of the polygon and the sphere of the whole mesh, without the tubes.
        let whole = build_mesh(&skeleton, &absolute(0.1));
        assert!(whole.triangle_materials().contains(&(MATERIAL_BARK as u8)));
        skeleton.segments.clear();
        assert_eq!(mesh, build_mesh(&skeleton, &absolute(0.1)));
    }

    #[test]
    fn a_branch_from_a_joint_has_no_start_cap() {
        // F[+F]: the branch starts at the end of the first segment, inside its tube.
        let mut branch = segment(DVec3::Y, DVec3::new(-0.7, 1.7, 0.0), None);
        branch.module = 3;
        let skeleton = Skeleton {
            segments: vec![segment(DVec3::ZERO, DVec3::Y, None), branch],
            ..Skeleton::default()
        };
        let mesh = checked_mesh(&skeleton);
        // The first tube's end, where the branch leaves it, is rounded (DOME: 3 rings of 8 and
        // the apex), not a flat stump; the branch's own tip is a flat cap.
        assert_eq!(mesh.vertex_count(), (18 + 9 + DOME) + (18 + 9));
    }

    #[test]
    fn a_sharp_turn_or_a_zero_width_breaks_the_axis() {
        let skeleton = Skeleton {
            segments: vec![
                segment(DVec3::ZERO, DVec3::Y, None),
                segment(DVec3::Y, DVec3::ZERO, Some(0)),
            ],
            ..Skeleton::default()
        };
        assert_eq!(chain_lists(&skeleton, 0.1), vec![vec![0], vec![1]]);
        let mut thin = segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0));
        thin.width = 0.0;
        let skeleton = Skeleton {
            segments: vec![segment(DVec3::ZERO, DVec3::Y, None), thin],
            ..Skeleton::default()
        };
        assert_eq!(chain_lists(&skeleton, 0.1), vec![vec![0]]);
        assert_eq!(build_mesh(&skeleton, &absolute(0.1)).check(), Ok(()));
    }

    #[test]
    fn a_wide_tube_at_a_bend_of_short_segments_breaks_instead_of_turning_inside_out() {
        // Width 40 at unit 0.1 is a radius of 2; a bend of 80° tilts the joint ring by 40°, so
        // it reaches 2 × sin 40° ≈ 1.29 along each segment: past the middle of a 0.3-long one.
        let turned = DVec3::new(
            -(80f64.to_radians().sin()),
            1.0 + 80f64.to_radians().cos(),
            0.0,
        );
        let mut segments = vec![
            segment(DVec3::ZERO, DVec3::Y, None),
            segment(DVec3::Y, DVec3::Y + (turned - DVec3::Y) * 0.3, Some(0)),
        ];
        segments.iter_mut().for_each(|s| s.width = 40.0);
        let skeleton = Skeleton {
            segments,
            ..Skeleton::default()
        };
        assert_eq!(chain_lists(&skeleton, 0.1), vec![vec![0], vec![1]]);
        assert_eq!(build_mesh(&skeleton, &absolute(0.1)).check(), Ok(()));
        // Thin enough, the same bend shares its joint.
        assert_eq!(chain_lists(&skeleton, 0.001), vec![vec![0, 1]]);
        assert_eq!(build_mesh(&skeleton, &absolute(0.001)).check(), Ok(()));
    }

    #[test]
    fn smooth_axes_have_rings_between_the_joints() {
        let mut segments = vec![
            segment(DVec3::ZERO, DVec3::Y, None),
            segment(DVec3::Y, DVec3::new(0.5, 1.8, 0.0), Some(0)),
            segment(
                DVec3::new(0.5, 1.8, 0.0),
                DVec3::new(1.2, 2.3, 0.0),
                Some(1),
            ),
        ];
        for s in &mut segments {
            s.smooth = true;
        }
        let skeleton = Skeleton {
            segments,
            ..Skeleton::default()
        };
        let mesh = build_mesh(
            &skeleton,
            &MeshOptions {
                smooth_samples: 5,
                ..absolute(0.1)
            },
        );
        assert_eq!(mesh.vertex_count(), (3 * 5 + 1) * 9 + 2 * 9);
        assert_eq!(mesh.check(), Ok(()));
    }

    #[test]
    fn polygons_are_two_sided_and_spheres_closed() {
        let square = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
        let skeleton = Skeleton {
            polygons: vec![polygon(square, 3, 7)],
            spheres: vec![unit_sphere(0, 9)],
            ..Skeleton::default()
        };
        let mesh = build_mesh(&skeleton, &MeshOptions::default());
        assert_eq!(mesh.check(), Ok(()));
        assert_eq!(
            &mesh.ranges[..4],
            &[0, 7, 4, 9],
            "the square's 2 + 2 triangles, then the sphere"
        );
        // The square's front faces +Z, its back −Z.
        assert_eq!(&mesh.normals[..3], &[0.0, 0.0, 1.0]);
        assert_eq!(&mesh.normals[12..15], &[0.0, 0.0, -1.0]);
    }

    #[test]
    fn huge_models_fall_back_to_lines() {
        let skeleton = Skeleton {
            segments: (0..100)
                .map(|i| {
                    segment(
                        DVec3::new(i as f64, 0.0, 0.0),
                        DVec3::new(i as f64, 1.0, 0.0),
                        None,
                    )
                })
                .collect(),
            ..Skeleton::default()
        };
        let mesh = build_mesh(
            &skeleton,
            &MeshOptions {
                max_vertices: 500,
                ..MeshOptions::default()
            },
        );
        assert_eq!(mesh.triangle_count(), 0);
        assert_eq!(mesh.lines.len(), 100 * 6);
        assert_eq!(mesh.check(), Ok(()));
        assert_eq!(mesh.bounds(), [[0.0, 0.0, 0.0], [99.0, 1.0, 0.0]]);
    }

    #[test]
    fn ranges_map_triangles_to_the_modules_that_drew_them() {
        let mut first = segment(DVec3::ZERO, DVec3::Y, None);
        first.module = 2;
        let mut second = segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0));
        second.module = 5;
        let skeleton = Skeleton {
            segments: vec![first, second],
            ..Skeleton::default()
        };
        let mesh = checked_mesh(&skeleton);
        // Start cap and first quads: module 2; second quads and end cap: module 5.
        assert_eq!(mesh.ranges, vec![0, 2, 8 + 16, 5]);
    }

    #[test]
    fn color_ranges_give_every_triangle_the_colour_index_that_drew_it() {
        let mut second = segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0));
        second.color = 2;
        let skeleton = Skeleton {
            segments: vec![segment(DVec3::ZERO, DVec3::Y, None), second],
            polygons: vec![polygon(
                vec![
                    DVec3::X,
                    DVec3::new(2.0, 0.0, 0.0),
                    DVec3::new(2.0, 1.0, 0.0),
                ],
                5,
                9,
            )],
            ..Skeleton::default()
        };
        let mesh = checked_mesh(&skeleton);
        // Start cap and first quads: index 0; second quads and end cap: 2; the triangle: 5.
        assert_eq!(mesh.color_ranges, vec![0, 0, 8 + 16, 2, 8 + 16 + 16 + 8, 5]);
        let indices = mesh.triangle_color_indices();
        assert_eq!(indices.len(), mesh.triangle_count());
        // The first vertex of every triangle has its index's colour.
        for (t, &index) in indices.iter().enumerate() {
            let v = mesh.indices[3 * t] as usize;
            assert_eq!(
                &mesh.colors[3 * v..3 * v + 3],
                &skeleton.color(index),
                "triangle {t}"
            );
        }
        assert_eq!(mesh.width_unit, 0.1);
    }
}
