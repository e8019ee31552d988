//! [`MeshBuffers`]: the mesh as flat arrays, and the definition of their layout.

use glam::DVec3;

/// The mesh as thirteen flat arrays. **This is the one place the layout is defined**; the wasm
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
///   point towards the farthest one, u 0..1 and v 0.15..0.85 (the band where the leaf image is
///   opaque across its width, so its cut-out never trims a polygon). Spheres: longitude and latitude, 0..1.
/// - `material_ranges`: the material kind of every triangle, `u32` × 2 per range (first
///   triangle, kind), sorted and running like `ranges`: [`MATERIAL_BARK`] (tubes and their caps),
///   [`MATERIAL_LEAF`] (predefined surfaces and polygons, two-sided) or [`MATERIAL_PLAIN`]
///   (spheres). The view and the writers choose the texture by it.
/// - `lines`, `line_colors`: only when the model is too large to mesh (`MeshOptions::max_vertices`):
///   `f32` × 3 per line end (two per segment) and `f32` × 3 colour per end; the triangle arrays
///   are then empty. Line `i` is `Skeleton::segments[i]` (its colour index is that segment's).
/// - `growth_origins`, `growth_times`: only when [`MeshOptions::growth`](super::MeshOptions) is
///   set (empty otherwise): the plant growing in time, growth time `t` counted in derivation
///   steps (the plant of step n is the plant at t = n). `growth_origins`: `f32` × 3 per vertex,
///   the point the vertex grows from, in the units and frame of `positions` (the start of the
///   segment that drew it, a polygon's first point, a leaf's origin, a sphere's centre).
///   `growth_times`: `f32` × 2 per vertex, `(t0, t1)` with `−1 ≤ t0 < t1 ≤ N` (N the steps
///   derived; elements the axiom's plant already has: `(−1, 0)`). At time `t` a vertex is drawn at
///   `origin + (position − origin) · g(clamp((t − t0) / (t1 − t0), 0, 1))`, `g(x) = x·x·(3 − 2x)`
///   (smoothstep; [`grown_position`](super::grown_position)), normals unchanged. A tube's rings
///   are not shared between segments then: each segment has its own start ring. In the lines
///   fallback the two arrays follow `lines`: one entry per line end. How `t0` and `t1` are chosen:
///   [`growth_schedule`](super::growth_schedule).
/// - `segment_growth_times`: with the growth arrays (empty otherwise), whatever the mesh holds:
///   `f32` × 2 per segment of the skeleton, in the order of `Skeleton::segments` (the order of the
///   segments as lines, `mesh::segment_ends`), `(t0, t1)` as above: the segment grows from its
///   start, its end at `start + (end − start) · g(…)`. What the studio's Lines mode, which draws
///   every segment as a line beside a mesh without tubes, grows its lines by.
/// - `width_unit`: model units per width unit (what `#width 1` measured across), for writers that
///   draw widths themselves (SVG).
/// - `unmeshed_vertices`: when the model was too large to mesh and is `lines`, the vertices its
///   mesh would have had (more than `MeshOptions::max_vertices`); 0 otherwise. The lines are the
///   segments only: a model's polygons, surfaces and spheres are then not drawn at all.
///
/// Where each chain, polygon, leaf and sphere of the skeleton lies in these arrays (contiguous runs
/// of vertices and triangles, in that order) is recorded by [`build_mesh_with_parts`](super::build_mesh_with_parts) as
/// [`MeshParts`](super::MeshParts), for re-meshing a part alone (dragging a branch).
///
/// Memory: a tube of `sides` sides costs `sides + 1` vertices per joint (44 bytes each: position,
/// normal, colour, uv) and `2·sides` triangles per segment (24 bytes each), plus two caps per axis;
/// with the default 6 sides, about 370 bytes per segment. The growth arrays add 20 bytes per vertex.
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
    pub growth_origins: Vec<f32>,
    pub growth_times: Vec<f32>,
    pub segment_growth_times: Vec<f32>,
    pub width_unit: f64,
    pub unmeshed_vertices: usize,
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
        self.check_growth()?;
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

    /// The growth arrays are empty, or hold an entry per vertex (per line end in the lines
    /// fallback), finite, with `−1 ≤ t0 < t1`; the segments' times are pairs, with `−1 ≤ t0 < t1`.
    fn check_growth(&self) -> Result<(), String> {
        let bad = |times: &[f32]| {
            times
                .chunks_exact(2)
                .position(|t| !(t[0] >= -1.0 && t[0] < t[1] && t[1].is_finite()))
        };
        if !self.segment_growth_times.len().is_multiple_of(2) {
            return Err("segment growth times must hold two times per segment".into());
        }
        if let Some(s) = bad(&self.segment_growth_times) {
            return Err(format!("growth times of segment {s} are not −1 ≤ t0 < t1"));
        }
        if self.growth_times.is_empty() && self.growth_origins.is_empty() {
            return Ok(());
        }
        let points = if self.positions.is_empty() {
            self.lines.len() / 3
        } else {
            self.vertex_count()
        };
        if self.growth_origins.len() != 3 * points || self.growth_times.len() != 2 * points {
            return Err("growth arrays must hold an origin and two times per vertex".into());
        }
        if !self.growth_origins.iter().all(|v| v.is_finite()) {
            return Err("a growth origin is not finite".into());
        }
        match bad(&self.growth_times) {
            Some(v) => Err(format!("growth times of vertex {v} are not −1 ≤ t0 < t1")),
            None => Ok(()),
        }
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
