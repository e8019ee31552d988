//! Growth in time (docs/LANGUAGE.md, "Growth in time"): when each element of a skeleton grows
//! ([`growth_schedule`]), and where a vertex of the mesh is at a growth time ([`grown_position`],
//! [`mesh_at`]): the one formula the shader, the CLI's frames and the glTF animation share.
//!
//! The plant grows from its roots outwards along the turtle's path, as a front: at growth time t
//! the front has reached the path distance S(t) from the root (the summed lengths of the
//! elements each element stands on, [`crate::turtle::Segment::anchor`]), and every element grows
//! while the front passes over it. S is piecewise linear, and S(n) is the distance within which
//! the plant has as many elements as the derivation had after step n
//! ([`Skeleton::step_counts`]): the plant at t = n has the size of step n's plant, and between
//! two steps it grows smoothly. An element starts exactly when the one it stands on has finished.

use super::MeshBuffers;
use crate::turtle::Skeleton;
use glam::DVec3;

/// When and from where one element grows: its vertices scale about `origin` from nothing at
/// growth time `t0` to their place at `t1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Growth {
    pub origin: DVec3,
    pub t0: f32,
    pub t1: f32,
}

/// The growth of every element of a skeleton, in the order segments, polygons, surfaces,
/// spheres (element `i` of the polygons is `segments.len() + i`, and so on).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GrowthSchedule {
    pub elements: Vec<Growth>,
    /// N: the growth times run over `[−1, N]`, the plant whole at N.
    pub span: u32,
}

/// Where an element starts on the path from the root, how long it is there, and where it grows
/// from.
#[derive(Clone, Copy)]
struct Reach {
    start: f64,
    length: f64,
    origin: DVec3,
}

/// The growth of every element of `skeleton` (see the module's doc).
pub fn growth_schedule(skeleton: &Skeleton) -> GrowthSchedule {
    let reaches = reaches(skeleton);
    let counts = &skeleton.step_counts;
    let span = if counts.is_empty() {
        1
    } else {
        counts.len() as u32 - 1
    };
    let front = Front::new(&reaches, &skeleton.step_counts, span);
    let elements = reaches
        .iter()
        .map(|r| {
            let end = r.start + r.length;
            // The elements of step 0's plant are whole at 0 (the axiom's plant); any other
            // starts at 0 or later, after them.
            let (t0, t1) = if end <= front.distances[1] {
                (-1.0, 0.0)
            } else {
                (front.time(r.start).max(0.0), front.time(end))
            };
            let (t0, t1) = (t0 as f32, t1 as f32);
            Growth {
                origin: r.origin,
                t0,
                t1: if t1 > t0 { t1 } else { t0.next_up() },
            }
        })
        .collect();
    GrowthSchedule { elements, span }
}

/// Each element's reach along the path from its root (segments first, then polygons, surfaces
/// and spheres). An element with no length gets a tiny one, so that every element takes time.
fn reaches(skeleton: &Skeleton) -> Vec<Reach> {
    let total: f64 = skeleton
        .segments
        .iter()
        .map(|s| (s.end - s.start).length())
        .sum();
    let least = 1e-9 * total.max(1.0);
    let mut reaches: Vec<Reach> = Vec::with_capacity(
        skeleton.segments.len()
            + skeleton.polygons.len()
            + skeleton.surfaces.len()
            + skeleton.spheres.len(),
    );
    // Where the element standing on segment `anchor` starts, `at` its base.
    let after = |reaches: &[Reach], anchor: Option<u32>, at: DVec3| match anchor {
        Some(a) => {
            let a = a as usize;
            let r = reaches[a];
            r.start + r.length + (at - skeleton.segments[a].end).length()
        }
        None => 0.0,
    };
    for s in &skeleton.segments {
        let start = after(&reaches, s.anchor, s.start);
        let length = (s.end - s.start).length().max(least);
        reaches.push(Reach {
            start,
            length,
            origin: s.start,
        });
    }
    let mut flat = |anchor: Option<u32>, origin: DVec3, size: f64| {
        let start = after(&reaches, anchor, origin);
        let length = if size.is_finite() { size } else { 0.0 }.max(least);
        reaches.push(Reach {
            start,
            length,
            origin,
        });
    };
    for p in &skeleton.polygons {
        let origin = p.points.first().copied().unwrap_or(skeleton.end);
        let size = p
            .points
            .iter()
            .map(|q| (*q - origin).length())
            .fold(0.0, f64::max);
        flat(p.anchor, origin, size);
    }
    for s in &skeleton.surfaces {
        flat(
            s.anchor,
            s.origin,
            s.scale.abs().max_element() * skeleton.surface_reach(s),
        );
    }
    for s in &skeleton.spheres {
        flat(s.anchor, s.center, s.radius.abs());
    }
    reaches
}

/// The growth front: the path distance it has reached at times −1, 0, 1, … N (`distances[k]` at
/// time k − 1), piecewise linear between.
struct Front {
    distances: Vec<f64>,
}

impl Front {
    /// The front for elements `reaches`, after step n as far as the `targets(n)` nearest
    /// element ends (by `counts`, else evenly over `span` steps).
    fn new(reaches: &[Reach], counts: &[f64], span: u32) -> Front {
        let mut ends: Vec<f64> = reaches.iter().map(|r| r.start + r.length).collect();
        ends.sort_by(f64::total_cmp);
        let elements = ends.len();
        let last = counts.last().copied().unwrap_or(0.0);
        let mut distances = vec![0.0];
        let mut reached = 0usize;
        for n in 0..=span {
            let target = if n == span {
                elements
            } else {
                let share = if counts.len() == span as usize + 1 && last > 0.0 {
                    counts[n as usize] / last
                } else {
                    f64::from(n) / f64::from(span)
                };
                ((share * elements as f64).round().max(0.0) as usize).min(elements)
            };
            reached = reached.max(target);
            let distance = if reached == 0 { 0.0 } else { ends[reached - 1] };
            let before = distances.last().copied().unwrap_or(0.0);
            distances.push(distance.max(before));
        }
        Front { distances }
    }

    /// The growth time at which the front reaches path distance `s`.
    fn time(&self, s: f64) -> f64 {
        let d = &self.distances;
        let k = d.partition_point(|&x| x < s);
        if k == 0 {
            return -1.0;
        }
        if k == d.len() {
            return (d.len() - 2) as f64;
        }
        // d[k − 1] < s ≤ d[k]: between times k − 2 and k − 1.
        k as f64 - 2.0 + (s - d[k - 1]) / (d[k] - d[k - 1])
    }
}

/// The growth function: smoothstep, 0 at 0, 1 at 1, flat at both ends.
#[inline]
pub fn growth_factor(x: f32) -> f32 {
    let x = x.clamp(0.0, 1.0);
    x * x * (3.0 - 2.0 * x)
}

/// Where a vertex at `position`, growing from `origin` over `[t0, t1]`, is at growth time `t`.
#[inline]
pub fn grown_position(
    position: [f32; 3],
    origin: [f32; 3],
    [t0, t1]: [f32; 2],
    t: f32,
) -> [f32; 3] {
    let g = growth_factor((t - t0) / (t1 - t0));
    if g >= 1.0 {
        // Exactly where it is (o + (p − o) may round).
        return position;
    }
    [0, 1, 2].map(|k| origin[k] + (position[k] - origin[k]) * g)
}

/// The skeleton at growth time `t` by `schedule` (its [`growth_schedule`]): each element scaled
/// about its base by the growth function, as the mesh's vertices are (an element not started has
/// no size; its place in the lists is kept). What the CLI's SVG frames draw.
pub fn skeleton_at(skeleton: &Skeleton, schedule: &GrowthSchedule, t: f32) -> Skeleton {
    let mut at = skeleton.clone();
    let mut factors = schedule
        .elements
        .iter()
        .map(|g| f64::from(growth_factor((t - g.t0) / (g.t1 - g.t0))));
    let mut next = || factors.next().unwrap_or(1.0);
    let grow = |p: &mut glam::DVec3, origin: glam::DVec3, g: f64| *p = origin + (*p - origin) * g;
    for s in &mut at.segments {
        let g = next();
        grow(&mut s.end, s.start, g);
        s.width *= g;
    }
    for p in &mut at.polygons {
        let g = next();
        let origin = p.points.first().copied().unwrap_or_default();
        p.points.iter_mut().for_each(|q| grow(q, origin, g));
    }
    for s in &mut at.surfaces {
        s.scale *= next();
    }
    for s in &mut at.spheres {
        let g = next();
        s.radius *= g;
        if let Some(w) = &mut s.radius_width {
            *w *= g;
        }
    }
    at
}

/// The mesh's points at growth time `t`: its vertices (its line ends in the lines fallback)
/// moved by [`grown_position`]; the points as they are when the mesh has no growth arrays.
pub fn mesh_at(mesh: &MeshBuffers, t: f32) -> Vec<f32> {
    let points = if mesh.positions.is_empty() {
        &mesh.lines
    } else {
        &mesh.positions
    };
    if mesh.growth_times.len() / 2 != points.len() / 3 || mesh.growth_origins.len() != points.len()
    {
        return points.clone();
    }
    let mut out = Vec::with_capacity(points.len());
    for ((p, o), times) in points
        .chunks_exact(3)
        .zip(mesh.growth_origins.chunks_exact(3))
        .zip(mesh.growth_times.chunks_exact(2))
    {
        let q = grown_position(
            [p[0], p[1], p[2]],
            [o[0], o[1], o[2]],
            [times[0], times[1]],
            t,
        );
        out.extend_from_slice(&q);
    }
    out
}
