//! The turtle's output: plain geometry (segments, polygons, predefined surfaces, spheres) and the
//! values query modules read.

use glam::DVec3;

/// One drawn segment, from `start` to `end`, with the turtle's frame at the time.
#[derive(Clone, Debug, PartialEq)]
pub struct Segment {
    pub start: DVec3,
    pub end: DVec3,
    /// The turtle's left and up vectors while drawing (unit, orthogonal to the segment).
    pub left: DVec3,
    pub up: DVec3,
    pub width: f64,
    pub color: u16,
    /// Index in the interpreted string of the module that drew this segment.
    pub module: u32,
    /// The segment this one continues on the same axis (it starts where that one ended, with no
    /// branch, move or jump between): the mesh shares their joint.
    pub previous: Option<u32>,
    /// Drawn between `@Gc` and `@Ge`: part of a smooth generalized cylinder.
    pub smooth: bool,
    /// The segment this one grows from: the last segment drawn before it on the turtle's path
    /// from the start of the string (a closed `[…]` branch does not count, `f` keeps it, `@M`
    /// clears it). Equal to `previous` when the segment continues an axis; otherwise the segment
    /// at whose end joint a branch leaves. `None` for a segment that starts a new root. See
    /// [`crate::branches`].
    pub anchor: Option<u32>,
}

/// A filled polygon (`{ … }`), vertices in drawing order.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    pub points: Vec<DVec3>,
    pub color: u16,
    /// Index of the `{` module.
    pub module: u32,
    /// The segment the turtle's state at `{` grew from (as [`Segment::anchor`]).
    pub anchor: Option<u32>,
}

/// Which predefined surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceKind {
    /// Meristem's own flat leaf (`~l` undeclared).
    Leaf,
    /// Meristem's own flat petal (`~p` undeclared).
    Petal,
    /// The declared surface [`Skeleton::shapes`]`[k]` (`#surface`, `#patch`).
    Declared(u16),
}

/// A predefined surface (`~l`, `~p`, a declared `~X`) placed at the turtle.
#[derive(Clone, Debug, PartialEq)]
pub struct Surface {
    pub kind: SurfaceKind,
    pub origin: DVec3,
    pub heading: DVec3,
    pub left: DVec3,
    pub up: DVec3,
    /// The scale along L, H and U (`~X(s)`: s along each; `~X(sx, sy, sz)`).
    pub scale: DVec3,
    pub color: u16,
    pub module: u32,
    /// The segment the turtle's state here grew from (as [`Segment::anchor`]).
    pub anchor: Option<u32>,
}

impl Surface {
    /// A point of the surface's own frame (x along L, y along H, z along U, at scale 1) where
    /// the surface puts it.
    pub fn place(&self, p: DVec3) -> DVec3 {
        self.origin
            + self.left * (p.x * self.scale.x)
            + self.heading * (p.y * self.scale.y)
            + self.up * (p.z * self.scale.z)
    }
}

/// A sphere (`@O`). Its radius is in model units (`@O(r)`), or half the width in width units
/// when `@O` has no parameter (`radius_width`).
#[derive(Clone, Debug, PartialEq)]
pub struct Sphere {
    pub center: DVec3,
    pub radius: f64,
    pub radius_width: Option<f64>,
    pub color: u16,
    pub module: u32,
    /// The segment the turtle's state here grew from (as [`Segment::anchor`]).
    pub anchor: Option<u32>,
}

/// The value a query module (`?P`, `?H`, `?U`, `?L`) reads at its place in the string.
#[derive(Clone, Debug, PartialEq)]
pub struct QueryValue {
    pub module: u32,
    pub value: [f64; 3],
}

/// Where a communication module `?E` stands: the turtle's position and frame at it, which the
/// environment's programs answer (docs/LANGUAGE.md, "Environment").
#[derive(Clone, Debug, PartialEq)]
pub struct EnvironmentQuery {
    pub module: u32,
    pub position: [f64; 3],
    pub heading: [f64; 3],
    pub up: [f64; 3],
}

/// The turtle's output: plain geometry, no mesh yet.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Skeleton {
    pub segments: Vec<Segment>,
    pub polygons: Vec<Polygon>,
    pub surfaces: Vec<Surface>,
    pub spheres: Vec<Sphere>,
    pub queries: Vec<QueryValue>,
    /// The communication modules `?E`, where they stand (only the environment reads them).
    #[cfg(feature = "environment")]
    pub environment_queries: Vec<EnvironmentQuery>,
    /// Where the turtle stood after the last module.
    pub end: DVec3,
    /// The colours of the colour indices (the grammar's palette); empty means
    /// [`crate::model::DEFAULT_PALETTE`].
    pub palette: Vec<[f32; 3]>,
    /// The grammar set widths (`#width`, `!`, or growth's width factors): the mesh draws them in its
    /// width unit as they are. When false, every segment has the default width and the mesh ties
    /// it to the internodes' length instead (see `mesh::WidthUnit`).
    pub widths_set: bool,
    /// `#width_unit`: model units per width unit, so that the mesh draws widths in the model's
    /// own units whatever the plant's size; `None`: the mesh options' unit (`mesh::WidthUnit`).
    pub width_unit: Option<f64>,
    /// The first module (index in the interpreted string) whose geometry went past
    /// [`MAX_COORDINATE`] or was not a finite number, and was clamped ([`Skeleton::clamp_to_finite`]).
    pub clamped: Option<u32>,
    /// How many elements the plant had after each step, 0 to N (the derivation's steps), as the
    /// derivation counted them (modules that draw, in the derived strings): what paces the
    /// plant's growth in time (`crate::mesh::growth_schedule`). Empty when not counted.
    pub step_counts: Vec<f64>,
    /// The surfaces the grammar declares, what [`SurfaceKind::Declared`] indexes.
    pub shapes: Vec<std::sync::Arc<crate::model::SurfaceShape>>,
}

/// The largest coordinate, width or radius the skeleton keeps: well inside `f32` (about 3.4e38),
/// which meshes and files store, with room for a tube's width around its axis.
pub const MAX_COORDINATE: f64 = 1e30;

/// The box around points and the largest |z| among them: whether a drawing is flat
/// ([`Skeleton::is_flat`]), gathered point by point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Extent {
    pub min: DVec3,
    pub max: DVec3,
    pub max_abs_z: f64,
}

impl Extent {
    /// No point yet.
    pub const EMPTY: Extent = Extent {
        min: DVec3::INFINITY,
        max: DVec3::NEG_INFINITY,
        max_abs_z: 0.0,
    };

    #[inline]
    pub fn add(&mut self, p: DVec3) {
        self.min = self.min.min(p);
        self.max = self.max.max(p);
        self.max_abs_z = self.max_abs_z.max(p.z.abs());
    }

    /// True when there is a point and every point lies in the plane z = 0 up to a millionth of
    /// the box's size.
    pub fn is_flat(&self) -> bool {
        if self.min.x > self.max.x {
            return false;
        }
        let size = (self.max - self.min).max_element();
        self.max_abs_z <= 1e-6 * size.max(1e-12)
    }

    /// The extent of points stored as x, y, z `f32`s (a sketch's line ends, in the order drawn):
    /// [`Extent::EMPTY`] without a point. By comparisons, a NaN skipped, a zero bound +0 (ties
    /// between -0 and +0 go either way with WebAssembly SIMD, so neither is kept).
    pub fn of_f32_points(points: &[f32]) -> Extent {
        if points.len() < 3 {
            return Extent::EMPTY;
        }
        let (min, max) = f32_box(points);
        // + 0.0 turns -0 into +0 and changes nothing else.
        let bound = |v: [f32; 3]| DVec3::from_array(v.map(|c| f64::from(c) + 0.0));
        let (min, max) = (bound(min), bound(max));
        Extent {
            min,
            max,
            // The largest |z| is the largest z or the smallest z negated.
            max_abs_z: if max.z > -min.z { max.z } else { -min.z + 0.0 },
        }
    }
}

/// The smallest and the largest of each coordinate of `points` (x, y, z `f32`s), a NaN skipped;
/// where a bound is zero, its sign may be another zero's than [`take_points`] gives.
#[cfg(not(all(target_arch = "wasm32", target_feature = "simd128")))]
pub(crate) fn f32_box(points: &[f32]) -> ([f32; 3], [f32; 3]) {
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    take_points(points, &mut min, &mut max);
    (min, max)
}

/// [`f32_box`] with WebAssembly SIMD: four points (twelve values, three vectors) at a time, each
/// lane its own bound of the coordinate it holds (the lanes' coordinates repeat every three
/// vectors), the lanes' bounds and the last points folded together at the end.
#[cfg(all(target_arch = "wasm32", target_feature = "simd128"))]
pub(crate) fn f32_box(points: &[f32]) -> ([f32; 3], [f32; 3]) {
    use core::arch::wasm32::{f32x4_pmax, f32x4_pmin, f32x4_splat, v128, v128_load, v128_store};
    let mut low = [f32x4_splat(f32::INFINITY); 3];
    let mut high = [f32x4_splat(f32::NEG_INFINITY); 3];
    let mut fours = points.chunks_exact(12);
    for four in &mut fours {
        for k in 0..3 {
            // SAFETY: `four` holds 12 values, so 4 from 4k (`v128_load` needs no alignment).
            let v = unsafe { v128_load(four.as_ptr().add(4 * k) as *const v128) };
            // pmin(a, b) is `b < a ? b : a` and pmax(a, b) `a < b ? b : a`: the comparisons of
            // `take_points`, a NaN skipped.
            low[k] = f32x4_pmin(low[k], v);
            high[k] = f32x4_pmax(high[k], v);
        }
    }
    let lanes = |v: [v128; 3]| {
        let mut out = [0f32; 12];
        for (k, v) in v.into_iter().enumerate() {
            // SAFETY: `out` has room for 4 values from 4k.
            unsafe { v128_store(out.as_mut_ptr().add(4 * k) as *mut v128, v) };
        }
        out
    };
    let mut min = [f32::INFINITY; 3];
    let mut max = [f32::NEG_INFINITY; 3];
    take_points(&lanes(low), &mut min, &mut [f32::NEG_INFINITY; 3]);
    take_points(&lanes(high), &mut [f32::INFINITY; 3], &mut max);
    take_points(fours.remainder(), &mut min, &mut max);
    (min, max)
}

/// Lowers `min` and raises `max` to the coordinates of `points` (x, y, z `f32`s): by
/// comparisons, so a NaN changes nothing (as `f64::min` skips it), the first of equal values kept.
/// What [`f32_box`] computes without SIMD, and the order the mesh's bounds keep
/// ([`crate::mesh::MeshBuffers::bounds`]).
fn take_points(points: &[f32], min: &mut [f32; 3], max: &mut [f32; 3]) {
    // In locals, one comparison each spelled out: the first plant's core (opt-level "s") neither
    // unrolls the loop over x, y, z nor keeps the arrays behind the references in registers.
    let ([mut x0, mut y0, mut z0], [mut x1, mut y1, mut z1]) = (*min, *max);
    for p in points.chunks_exact(3) {
        let (x, y, z) = (p[0], p[1], p[2]);
        if x < x0 {
            x0 = x;
        }
        if x > x1 {
            x1 = x;
        }
        if y < y0 {
            y0 = y;
        }
        if y > y1 {
            y1 = y;
        }
        if z < z0 {
            z0 = z;
        }
        if z > z1 {
            z1 = z;
        }
    }
    (*min, *max) = ([x0, y0, z0], [x1, y1, z1]);
}

/// `v` within ±[`MAX_COORDINATE`] (0 for NaN), and whether it had to change.
pub(super) fn clamp_number(v: &mut f64) -> bool {
    let kept = if v.is_nan() {
        0.0
    } else {
        v.clamp(-MAX_COORDINATE, MAX_COORDINATE)
    };
    let changed = kept != *v;
    *v = kept;
    changed
}

/// Whether a segment from `start` drawn by the turtle `t` holds only what [`clamp_number`] and
/// [`clamp_direction`] keep as it is: its ends and width within ±[`MAX_COORDINATE`] (not NaN), its
/// frame finite.
#[inline]
pub(super) fn segment_within_bounds(start: DVec3, t: &super::state::TurtleState) -> bool {
    let limit = DVec3::splat(MAX_COORDINATE);
    start.abs().cmple(limit).all()
        & t.position.abs().cmple(limit).all()
        & (t.width.abs() <= MAX_COORDINATE)
        & t.left.is_finite()
        & t.up.is_finite()
}

/// Each component of `v` clamped ([`clamp_number`]).
pub(super) fn clamp_point(v: &mut DVec3) -> bool {
    let [mut x, mut y, mut z] = v.to_array();
    let changed = clamp_number(&mut x) | clamp_number(&mut y) | clamp_number(&mut z);
    *v = DVec3::new(x, y, z);
    changed
}

/// A direction that is not finite replaced by `default`.
pub(super) fn clamp_direction(v: &mut DVec3, default: DVec3) -> bool {
    let changed = !v.is_finite();
    if changed {
        *v = default;
    }
    changed
}

impl Skeleton {
    /// Clamps every point, width and radius to ±[`MAX_COORDINATE`] (a number that is not finite
    /// becomes 0, a direction that is not finite a default one) and records the first module
    /// that needed it in [`Skeleton::clamped`]: every mesh and every file written from the
    /// skeleton then holds finite numbers. Positions past that are far beyond any real plant.
    pub fn clamp_to_finite(&mut self) {
        self.clamp(true);
    }

    /// [`Self::clamp_to_finite`], the segments only when `segments` (false: the caller knows that
    /// none needs it, see [`segment_within_bounds`]).
    pub(super) fn clamp(&mut self, segments: bool) {
        let mut first: Option<u32> = None;
        let mut note = |changed: bool, module: u32| {
            if changed {
                first = Some(first.map_or(module, |f| f.min(module)));
            }
        };
        let checked: &mut [Segment] = if segments {
            &mut self.segments
        } else {
            &mut []
        };
        for s in checked {
            let changed = clamp_point(&mut s.start)
                | clamp_point(&mut s.end)
                | clamp_number(&mut s.width)
                | clamp_direction(&mut s.left, DVec3::X)
                | clamp_direction(&mut s.up, DVec3::Z);
            note(changed, s.module);
        }
        for p in &mut self.polygons {
            let changed = p.points.iter_mut().fold(false, |c, q| clamp_point(q) | c);
            note(changed, p.module);
        }
        for s in &mut self.surfaces {
            let changed = clamp_point(&mut s.origin)
                | clamp_point(&mut s.scale)
                | clamp_direction(&mut s.heading, DVec3::Y)
                | clamp_direction(&mut s.left, DVec3::X)
                | clamp_direction(&mut s.up, DVec3::Z);
            note(changed, s.module);
        }
        for s in &mut self.spheres {
            let width = s.radius_width.as_mut().is_some_and(clamp_number);
            let changed = clamp_point(&mut s.center) | clamp_number(&mut s.radius) | width;
            note(changed, s.module);
        }
        clamp_point(&mut self.end);
        self.clamped = first;
    }

    /// The colour of a colour index: the palette entry, wrapping modulo the palette's length.
    pub fn color(&self, index: u16) -> [f32; 3] {
        let palette: &[[f32; 3]] = if self.palette.is_empty() {
            &crate::model::DEFAULT_PALETTE
        } else {
            &self.palette
        };
        palette[index as usize % palette.len()]
    }

    /// True when something was drawn and all of it lies in the plane z = 0 (the plane a grammar
    /// that only turns with `+` and `-` draws in), up to a millionth of the drawing's size: the
    /// studio then shows it face-on in an orthographic view. Widths do not count (tubes always
    /// have thickness); spheres count by their centres.
    pub fn is_flat(&self) -> bool {
        let mut extent = Extent::EMPTY;
        self.for_each_point(&mut |p| {
            extent.add(p);
            true
        });
        extent.is_flat()
    }

    /// How far a surface reaches from its origin at scale 1: 1 for the built-in leaf and petal
    /// (their length), the farthest control point for a declared one.
    pub fn surface_reach(&self, s: &Surface) -> f64 {
        match s.kind {
            SurfaceKind::Declared(k) => self.shapes.get(k as usize).map_or(0.0, |x| x.reach()),
            _ => 1.0,
        }
    }

    /// Calls `f` on every point that counts for [`Skeleton::is_flat`] until it returns false;
    /// returns whether it never did.
    pub(crate) fn for_each_point(&self, f: &mut dyn FnMut(DVec3) -> bool) -> bool {
        self.segments.iter().all(|s| f(s.start) && f(s.end))
            && self.polygons.iter().all(|p| p.points.iter().all(|&q| f(q)))
            // The built-in outlines span heading and left from the origin; a declared surface
            // lies within its control points.
            && self.surfaces.iter().all(|s| match s.kind {
                SurfaceKind::Declared(k) => self.shapes.get(k as usize).is_none_or(|shape| {
                    shape.patches.iter().flatten().all(|&p| f(s.place(p)))
                }),
                _ => {
                    f(s.origin)
                        && f(s.place(DVec3::Y))
                        && f(s.place(DVec3::X))
                }
            })
            && self.spheres.iter().all(|s| f(s.center))
    }
}
