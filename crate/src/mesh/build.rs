//! The builder: [`build_mesh`] writes each element of a skeleton into [`MeshBuffers`] (tubes by
//! `tube.rs`, flats and spheres here), recording where each landed ([`MeshParts`]).

#[cfg(feature = "surfaces")]
use super::bezier;
use super::chains::{chains, Chains};
use super::grow::{append, push, push_range};
use super::{growth_origin, growth_schedule, GrowthSchedule};
use super::{parts, polygon, segment_lines, sphere, surfaces, tube};
use super::{resolve_width_unit, ChainPart, MeshBuffers, MeshOptions, MeshParts, Part};
use super::{MATERIAL_BARK, MATERIAL_LEAF, MATERIAL_PLAIN};
use crate::maths;
use crate::turtle::{Skeleton, Surface, SurfaceKind};
use glam::DVec3;

/// An upper bound of the vertices a surface's mesh has: both sides of every patch's grid for a
/// declared surface, 64 for the built-in outlines.
fn surface_vertices(skeleton: &Skeleton, s: &Surface) -> usize {
    match s.kind {
        SurfaceKind::Declared(k) if cfg!(feature = "surfaces") => {
            skeleton.shapes.get(k as usize).map_or(0, |shape| {
                let [a, b] = shape.precision.map(|n| n as usize + 1);
                2 * shape.patches.len() * a * b
            })
        }
        _ => 64,
    }
}

/// Builds the mesh of a skeleton: a tube per axis (segments that continue each other share their
/// joint rings, ends are capped), smooth axes as generalized cylinders through their joints,
/// polygons and predefined surfaces two-sided, spheres. Above `max_vertices` it returns lines.
pub fn build_mesh(skeleton: &Skeleton, options: &MeshOptions) -> MeshBuffers {
    let schedule = options.with_growth().then(|| growth_schedule(skeleton));
    mesh_of(skeleton, options, schedule.as_ref(), false).0
}

/// [`build_mesh`], and where each element of the skeleton landed in the mesh ([`MeshParts`]):
/// what a partial re-mesh needs to rebuild or move one part alone.
pub fn build_mesh_with_parts(
    skeleton: &Skeleton,
    options: &MeshOptions,
) -> (MeshBuffers, MeshParts) {
    build_mesh_with_schedule(skeleton, options, None)
}

/// [`build_mesh_with_parts`], the growth times (with [`MeshOptions::growth`]) taken from
/// `schedule` when given, else from the skeleton's own [`growth_schedule`]: an edited plant's
/// elements grow when the unedited plant's schedule says (`crate::branches`), from where the
/// edits put them ([`super::growth_origin`]).
pub fn build_mesh_with_schedule(
    skeleton: &Skeleton,
    options: &MeshOptions,
    schedule: Option<&GrowthSchedule>,
) -> (MeshBuffers, MeshParts) {
    let own = (options.with_growth() && schedule.is_none()).then(|| growth_schedule(skeleton));
    mesh_of(skeleton, options, schedule.or(own.as_ref()), true)
}

/// The mesh, and its parts when `with_parts` (else empty parts: the same mesh, without the
/// bookkeeping); its growth times from `schedule` with [`MeshOptions::growth`].
fn mesh_of(
    skeleton: &Skeleton,
    options: &MeshOptions,
    schedule: Option<&GrowthSchedule>,
    with_parts: bool,
) -> (MeshBuffers, MeshParts) {
    let unit = resolve_width_unit(skeleton, options.width_unit);
    let mut builder = Builder::new(options, unit);
    if let Some(schedule) = schedule.filter(|_| options.with_growth()) {
        builder.mesh.segment_growth_times = segment_growth_times(schedule, skeleton);
        builder.growth = Some(schedule);
    }
    let mut parts = MeshParts {
        segment_chain: if with_parts {
            vec![parts::NO_CHAIN; skeleton.segments.len()]
        } else {
            Vec::new()
        },
        ..MeshParts::default()
    };
    let estimate = builder.estimate(skeleton);
    if estimate > builder.vertex_budget() {
        builder.lines(skeleton);
        builder.mesh.unmeshed_vertices = estimate;
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
        builder.grow(skeleton, skeleton.segments.len() + i);
        parts.polygons.push(builder.part_since(before));
    }
    for i in 0..skeleton.surfaces.len() {
        let before = builder.mark();
        builder.surface(skeleton, i);
        builder.grow(
            skeleton,
            skeleton.segments.len() + skeleton.polygons.len() + i,
        );
        parts.surfaces.push(builder.part_since(before));
    }
    for i in 0..skeleton.spheres.len() {
        let before = builder.mark();
        builder.sphere_of(skeleton, i);
        let flats = skeleton.polygons.len() + skeleton.surfaces.len();
        builder.grow(skeleton, skeleton.segments.len() + flats + i);
        parts.spheres.push(builder.part_since(before));
    }
    (builder.mesh, parts)
}

/// The mesh being written: its arrays, the options, and the bookkeeping of ranges and parts.
pub(crate) struct Builder<'a> {
    pub(super) mesh: MeshBuffers,
    pub(super) options: &'a MeshOptions,
    pub(super) unit: f64,
    pub(super) sides: usize,
    /// (sin, cos) of each side's angle around a ring.
    pub(super) ring: Vec<(f64, f64)>,
    /// (first triangle, segment) pairs, as `ranges` but naming the segment that drew each
    /// triangle of a tube (`parts::NO_CHAIN` for other elements): what [`MeshParts`] records.
    element_ranges: Vec<u32>,
    /// The segment the next `range` call stands for.
    pub(super) element: u32,
    /// The material kind the next `range` call stands for.
    pub(super) material: u32,
    pub(super) scratch: tube::TubeScratch,
    /// When the mesh carries its growth in time ([`MeshOptions::growth`]): each element's times
    /// (its origin is where the skeleton meshed puts it, [`super::growth_origin`]).
    pub(super) growth: Option<&'a GrowthSchedule>,
}

impl<'a> Builder<'a> {
    pub(super) fn new(options: &'a MeshOptions, unit: f64) -> Builder<'a> {
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
                .map(|k| maths::sin_cos(k as f64 / sides as f64 * std::f64::consts::TAU))
                .collect(),
            element_ranges: Vec::new(),
            element: parts::NO_CHAIN,
            material: MATERIAL_BARK,
            scratch: tube::TubeScratch::default(),
            growth: None,
        }
    }

    /// The vertices the mesh may have: `max_vertices`, or fewer with the growth arrays, whose
    /// 20 bytes per vertex count against it (a vertex has 44 bytes without them).
    fn vertex_budget(&self) -> usize {
        if self.growing() {
            self.options.max_vertices / 64 * 44
        } else {
            self.options.max_vertices
        }
    }

    /// Whether the mesh carries growth: never without the `growth` feature, which leaves the
    /// growth code out of the first plant's core.
    #[inline(always)]
    pub(super) fn growing(&self) -> bool {
        cfg!(feature = "growth") && self.growth.is_some()
    }

    /// Gives the vertices written since the last call the growth of element `element` of
    /// `skeleton` (see [`GrowthSchedule::elements`]), when the mesh carries growth.
    #[inline]
    pub(super) fn grow(&mut self, skeleton: &Skeleton, element: usize) {
        if !self.growing() {
            return;
        }
        let Some(g) = self.growth.and_then(|s| s.elements.get(element)) else {
            return;
        };
        let mesh = &mut self.mesh;
        let new = mesh.vertex_count() - mesh.growth_times.len() / 2;
        let o = growth_origin(skeleton, element).as_vec3().to_array();
        append(&mut mesh.growth_origins, new, |_| o);
        append(&mut mesh.growth_times, new, |_| [g.t0, g.t1]);
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
    pub(super) fn element_ranges_since(&self, mark: &[u32; 3]) -> Vec<u32> {
        let mut ranges = self.element_ranges[mark[2] as usize..].to_vec();
        for pair in ranges.chunks_exact_mut(2) {
            pair[0] -= mark[1];
        }
        ranges
    }

    pub(super) fn polygon(&mut self, skeleton: &Skeleton, i: usize) {
        let p = &skeleton.polygons[i];
        self.element = parts::NO_CHAIN;
        self.flat(&p.points, None, skeleton, p.color, p.module);
    }

    pub(super) fn surface(&mut self, skeleton: &Skeleton, i: usize) {
        let s = &skeleton.surfaces[i];
        let kind = match s.kind {
            SurfaceKind::Leaf => surfaces::SurfaceKind::Leaf,
            SurfaceKind::Petal => surfaces::SurfaceKind::Petal,
            SurfaceKind::Declared(k) => {
                // Without the feature `surfaces` the model declares none.
                #[cfg(feature = "surfaces")]
                if let Some(shape) = skeleton.shapes.get(k as usize) {
                    self.element = parts::NO_CHAIN;
                    let grids = bezier::tessellate(s, shape);
                    self.patches(&grids, s, shape, skeleton);
                }
                let _ = k;
                return;
            }
        };
        let points = surfaces::outline_of(kind, s);
        self.element = parts::NO_CHAIN;
        // The leaf's own frame: across along `left`, along the heading.
        let uvs = unit_square(points.iter().map(|p| {
            let d = *p - s.origin;
            (d.dot(s.left), d.dot(s.heading))
        }));
        self.flat(&points, Some(uvs), skeleton, s.color, s.module);
    }

    pub(super) fn sphere_of(&mut self, skeleton: &Skeleton, i: usize) {
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
        // With growth, every segment has its own start ring.
        let own_rings = 2 + usize::from(self.growing());
        let tubes = if self.options.tubes {
            skeleton.segments.len() * (rings_per_segment + own_rings) * (self.sides + 1)
        } else {
            0
        };
        let flats: usize = skeleton
            .polygons
            .iter()
            .map(|p| 2 * p.points.len())
            .sum::<usize>()
            + skeleton
                .surfaces
                .iter()
                .map(|s| surface_vertices(skeleton, s))
                .sum::<usize>();
        let spheres = skeleton.spheres.len() * (self.options.sphere_segments as usize + 1).pow(2);
        tubes + flats + spheres
    }

    pub(super) fn vertex(&mut self, p: DVec3, n: DVec3, c: [f32; 3], uv: [f32; 2]) -> u32 {
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
    pub(super) fn range(&mut self, module: u32, color: u16) {
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

    #[cfg(feature = "surfaces")]
    /// A declared surface's patches, two-sided as [`Builder::flat`]: the front faces each
    /// patch's ∂P/∂s × ∂P/∂t, in the patch's top colour, the back in its bottom colour (the
    /// turtle's where the patch gives none: [`SurfaceShape::patch_color`]). Texture coordinates
    /// span the whole surface in its own frame, across along `left` and along the heading, as the
    /// built-in leaf's (cpfg's texels per surface).
    fn patches(
        &mut self,
        grids: &[bezier::Grid],
        s: &Surface,
        shape: &crate::model::SurfaceShape,
        skeleton: &Skeleton,
    ) {
        let triangles: Vec<Vec<[u32; 3]>> = grids.iter().map(bezier::Grid::triangles).collect();
        if triangles.iter().all(Vec::is_empty) {
            return;
        }
        self.material = MATERIAL_LEAF;
        let uvs = unit_square(grids.iter().flat_map(|g| &g.points).map(|p| {
            let d = *p - s.origin;
            (d.dot(s.left), d.dot(s.heading))
        }));
        for (sign, flip) in [(1.0, false), (-1.0, true)] {
            let mut uv = uvs.iter();
            for (k, (grid, tris)) in grids.iter().zip(&triangles).enumerate() {
                let color = shape.patch_color(k, flip, s.color);
                self.range(s.module, color);
                let c = skeleton.color(color);
                let first = self.mesh.vertex_count() as u32;
                for (p, n) in grid.points.iter().zip(&grid.normals) {
                    self.vertex(*p, *n * sign, c, uv.next().copied().unwrap_or_default());
                }
                for &[a, b, d] in tris {
                    let [a, b, d] = [a, b, d].map(|k| first + k);
                    if flip {
                        self.mesh.indices.extend([a, d, b]);
                    } else {
                        self.mesh.indices.extend([a, b, d]);
                    }
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
            let u = 0.5 + maths::atan2(n.z, n.x) / std::f64::consts::TAU;
            let v = maths::acos(n.y.clamp(-1.0, 1.0)) / std::f64::consts::PI;
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
        if let Some(schedule) = self.growth.filter(|_| cfg!(feature = "growth")) {
            let mesh = &mut self.mesh;
            let segments = skeleton.segments.len().min(schedule.elements.len());
            for (g, s) in schedule.elements[..segments].iter().zip(&skeleton.segments) {
                let o = s.start.as_vec3().to_array();
                append(&mut mesh.growth_origins, 2, |_| o);
                append(&mut mesh.growth_times, 2, |_| [g.t0, g.t1]);
            }
        }
    }
}

/// Each segment's growth times `(t0, t1)` by `schedule`: `MeshBuffers::segment_growth_times`.
fn segment_growth_times(schedule: &GrowthSchedule, skeleton: &Skeleton) -> Vec<f32> {
    let segments = skeleton.segments.len().min(schedule.elements.len());
    schedule.elements[..segments]
        .iter()
        .flat_map(|g| [g.t0, g.t1])
        .collect()
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

/// The band of v in which the leaf image (`public/textures/leaf.png`) is opaque across its whole
/// width: its outline rounds off only below 0.128 and above 0.872.
pub const POLYGON_V: (f32, f32) = (0.15, 0.85);

/// A polygon's texture coordinates: projected in its plane with v from the first point towards
/// the point farthest from it (a leaf drawn from its base runs along its length) and u across,
/// scaled into 0..1 across and into [`POLYGON_V`] along, where the leaf image has no transparent
/// surround: a polygon keeps exactly the outline the grammar traced (a leaf of many polygons, ABOP's
/// developmental surfaces, would otherwise lose each one's corners to the image's cut-out).
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
    let (v0, v1) = POLYGON_V;
    let mut uvs = unit_square(points.iter().map(|p| {
        let d = *p - origin;
        (d.dot(across), d.dot(along))
    }));
    for uv in &mut uvs {
        uv[1] = v0 + (v1 - v0) * uv[1];
    }
    uvs
}
