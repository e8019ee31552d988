//! Tubes: an axis of the skeleton (a chain of segments that continue each other) becomes a ring
//! of `sides + 1` vertices at each sample along it, quads between the rings, a flat cap at its
//! start (where it does not grow out of a joint) and at its end, rounded where branches leave it. A smooth axis is sampled along Bézier pieces through its joints; a straight one at
//! its joints, each ring across the bisector of the segments it joins.

use super::build::Builder;
use super::grow::{append, push};
use super::{curve, MATERIAL_BARK};
use crate::maths;
use crate::turtle::{Segment, Skeleton};
use glam::DVec3;

/// Rings of a tube's rounded end below its apex (the first is the tube's last ring, with the
/// dome's normals).
const DOME_STEPS: usize = 3;

/// The arrays a tube is built with, kept by the builder from tube to tube: a plant has tens of
/// thousands of axes, and allocating them for each cost a good part of the mesh stage in wasm.
#[derive(Default)]
pub(super) struct TubeScratch {
    points: Vec<DVec3>,
    widths: Vec<f64>,
    samples: Vec<AxisSample>,
    frame: Vec<(DVec3, DVec3)>,
    normals: Vec<DVec3>,
    /// One ring's directions from the axis, a side each and the seam's (side 0 again).
    radials: Vec<DVec3>,
    rings: Vec<u32>,
    /// With growth: the first vertex of the ring each quad ends at (a joint's ring is written
    /// twice, [`Builder::rings`]); empty otherwise (the quads end at `rings`).
    ends: Vec<u32>,
    offsets: Vec<DVec3>,
    outs: Vec<DVec3>,
}

/// The segments of a chain, in order (indices into the skeleton's, not a list of their own: a
/// plant has tens of thousands of chains).
#[derive(Clone, Copy)]
struct Chain<'a> {
    skeleton: &'a Skeleton,
    chain: &'a [u32],
}

impl<'a> Chain<'a> {
    fn nth(&self, k: usize) -> &'a Segment {
        &self.skeleton.segments[self.chain[k] as usize]
    }

    fn first(&self) -> &'a Segment {
        self.nth(0)
    }

    fn last(&self) -> &'a Segment {
        self.nth(self.chain.len() - 1)
    }

    fn iter(&self) -> impl Iterator<Item = &'a Segment> + 'a {
        let segments = &self.skeleton.segments;
        self.chain.iter().map(move |&i| &segments[i as usize])
    }
}

/// One ring of a tube, ready to write.
struct Ring<'a> {
    point: DVec3,
    /// Directions from the axis: a side each and the seam's (side 0 again).
    radials: &'a [DVec3],
    radius: f64,
    v: f32,
    color: [f32; 3],
}

impl Ring<'_> {
    /// Writes the ring's `sides + 1` vertices; returns the first. Each array grows once per ring
    /// (as `Builder::vertex` writes them, in the same arithmetic: a call per vertex and array
    /// costs more in wasm); u runs once around, the seam at u = 1.
    fn write(&self, mesh: &mut super::MeshBuffers, sides: usize) -> u32 {
        let first = mesh.vertex_count() as u32;
        let count = sides + 1;
        let (radials, radius, point) = (self.radials, self.radius, self.point);
        append(&mut mesh.positions, count, |j| {
            let p = point + radials[j] * radius;
            [p.x as f32, p.y as f32, p.z as f32]
        });
        append(&mut mesh.normals, count, |j| {
            let r = radials[j];
            [r.x as f32, r.y as f32, r.z as f32]
        });
        let (v, sides32) = (self.v, sides as f32);
        append(&mut mesh.uvs, count, |j| {
            [if j < sides { j as f32 / sides32 } else { 1.0 }, v]
        });
        let c = self.color;
        append(&mut mesh.colors, count, |_| c);
        first
    }
}

/// A point on a tube's axis where a ring of vertices goes.
#[derive(Clone, Copy, Debug)]
struct AxisSample {
    point: DVec3,
    tangent: DVec3,
    /// The tube's width there, in width units.
    width: f64,
    /// The index in the chain of the segment that starts here (the last one at the end).
    segment: usize,
}

impl Builder<'_> {
    /// The tube of `chain` (segment indices, each continuing the one before), capped at its start
    /// when `start_cap`, and at its end by a dome when `end_dome` (branches leave there), else flat.
    pub(super) fn tube(
        &mut self,
        skeleton: &Skeleton,
        chain: &[u32],
        start_cap: bool,
        end_dome: bool,
    ) {
        let segments = Chain { skeleton, chain };
        let mut scratch = std::mem::take(&mut self.scratch);
        self.axis_samples(&segments, &mut scratch);
        if scratch.samples.len() >= 2 {
            self.rings(&segments, &mut scratch);
            self.tube_triangles(&segments, &mut scratch, [start_cap, end_dome]);
        }
        self.scratch = scratch;
    }

    /// Where the rings of the tube through `segments` go: along the curve through the joints when
    /// the axis is smooth, else at the joints. Samples that are not finite or repeat the one
    /// before are dropped.
    /// The samples go to `scratch.samples`.
    fn axis_samples(&self, segments: &Chain, scratch: &mut TubeScratch) {
        let points = &mut scratch.points;
        points.clear();
        points.push(segments.first().start);
        // The width at each joint: a segment's width at its start; the last keeps its own.
        let widths = &mut scratch.widths;
        widths.clear();
        for s in segments.iter() {
            points.push(s.end);
            widths.push(s.width);
        }
        widths.push(segments.last().width);
        let smooth = self.options.smooth_all || segments.first().smooth;
        let samples = &mut scratch.samples;
        if smooth && points.len() > 2 {
            *samples = self.curve_samples(points, widths);
        } else {
            joint_samples(points, widths, samples);
        }
        samples.retain(|s| s.point.is_finite() && s.tangent.is_finite());
        samples.dedup_by(|b, a| (b.point - a.point).length() < 1e-12);
    }

    /// `smooth_samples` samples per segment along the Bézier curve through the joints `points`,
    /// the width interpolated between the joints' `widths`.
    fn curve_samples(&self, points: &[DVec3], widths: &[f64]) -> Vec<AxisSample> {
        let last_segment = points.len() - 2;
        let pieces = curve::bezier_through(points);
        let per = self.options.smooth_samples.max(1);
        let mut samples = Vec::new();
        for (k, piece) in pieces.iter().enumerate() {
            let first = if k == 0 { 0 } else { 1 };
            for j in first..=per {
                let t = j as f64 / per as f64;
                let (point, tangent) = curve::evaluate(piece, t);
                samples.push(AxisSample {
                    point,
                    tangent,
                    width: widths[k] + (widths[k + 1] - widths[k]) * t,
                    segment: k.min(last_segment),
                });
            }
        }
        samples
    }

    /// The ring vertices of each sample, its colour that of the segment it starts; returns the
    /// first vertex of each ring. u runs once around each ring (its last vertex repeats the first
    /// at u = 1); v is the distance along the axis in circumferences of the tube (the mean of the
    /// two rings' circumferences over each step), so a texture tile is as long as the tube is round.
    /// The first vertices go to `scratch.rings`.
    fn rings(&mut self, segments: &Chain, scratch: &mut TubeScratch) {
        let samples = &scratch.samples;
        scratch.frame.clear();
        for s in samples {
            scratch.frame.push((s.point, s.tangent));
        }
        curve::rotation_minimizing_normals_into(
            &scratch.frame,
            segments.first().left,
            &mut scratch.normals,
        );
        let normals = &scratch.normals;
        let sides = self.sides;
        let rings = &mut scratch.rings;
        rings.clear();
        scratch.ends.clear();
        let (growth, chain) = (self.growing(), segments.chain);
        let unit = self.unit;
        let circumference = |w: f64| (std::f64::consts::PI * w * unit).max(1e-12);
        let mut v = 0.0f64;
        for (k, sample) in samples.iter().enumerate() {
            if k > 0 {
                let before = samples[k - 1];
                v += (sample.point - before.point).length()
                    / (0.5 * (circumference(before.width) + circumference(sample.width)));
            }
            let n = normals[k];
            let b = sample.tangent.cross(n);
            let radius = 0.5 * sample.width * self.unit;
            let c = segments.skeleton.color(segments.nth(sample.segment).color);
            let first = self.mesh.vertex_count() as u32;
            // One per side from the builder's sin/cos table, and the seam: side 0 again, at u = 1.
            let radials = &mut scratch.radials;
            radials.clear();
            for j in 0..=sides {
                let (sin, cos) = self.ring[if j < sides { j } else { 0 }];
                radials.push(n * cos + b * sin);
            }
            let ring = Ring {
                point: sample.point,
                radials,
                radius,
                v: v as f32,
                color: c,
            };
            // With growth, a joint's ring is written twice: as the end of the segment before it
            // (growing with it) and as the start of the next.
            let segment = chain[sample.segment] as usize;
            if growth && k > 0 && samples[k - 1].segment != sample.segment {
                scratch.ends.push(ring.write(&mut self.mesh, sides));
                self.grow(segments.skeleton, chain[samples[k - 1].segment] as usize);
            } else if growth {
                scratch.ends.push(first);
            }
            let first = ring.write(&mut self.mesh, sides);
            self.grow(segments.skeleton, segment);
            rings.push(first);
        }
    }

    /// The triangles of the tube: the start cap (when `start_cap`), a quad between each pair of
    /// consecutive `rings` (their ranges naming the segment each starts at) and the end cap.
    fn tube_triangles(
        &mut self,
        segments: &Chain,
        scratch: &mut TubeScratch,
        [start_cap, end_dome]: [bool; 2],
    ) {
        let Chain { skeleton, chain } = *segments;
        let TubeScratch {
            samples,
            rings,
            ends,
            offsets,
            outs,
            ..
        } = scratch;
        let n = self.sides as u32;
        // Start cap, facing back along the axis.
        self.element = chain[0];
        self.material = MATERIAL_BARK;
        let first = segments.first();
        self.range(first.module, first.color);
        if start_cap {
            self.cap(
                samples[0].point,
                -samples[0].tangent,
                rings[0],
                skeleton.color(first.color),
                true,
            );
            self.grow(skeleton, chain[0] as usize);
        }
        for k in 0..rings.len() - 1 {
            let segment = segments.nth(samples[k].segment);
            self.element = chain[samples[k].segment];
            self.range(segment.module, segment.color);
            let (a0, b0) = (rings[k], *ends.get(k + 1).unwrap_or(&rings[k + 1]));
            append(&mut self.mesh.indices, n as usize, |j| {
                let (j, next) = (j as u32, j as u32 + 1);
                let (a, b, c, d) = (a0 + j, a0 + next, b0 + j, b0 + next);
                [a, b, c, b, d, c]
            });
        }
        let last = samples.len() - 1;
        let end = segments.last();
        self.element = chain[chain.len() - 1];
        self.range(end.module, end.color);
        let c = skeleton.color(end.color);
        let (point, tangent) = (samples[last].point, samples[last].tangent);
        if end_dome {
            self.dome(point, tangent, rings[last], c, (offsets, outs));
        } else {
            self.cap(point, tangent, rings[last], c, false);
        }
        self.grow(skeleton, chain[chain.len() - 1] as usize);
    }

    /// A rounded end closing a tube: a quarter circle of rings from the last ring to a point on
    /// the axis half a width beyond it, facing `normal` (the axis's direction). Where branches
    /// leave the end of an axis, they grow out of this dome, not out of a flat, faceted stump; a
    /// tip is rounded as a line's end is.
    fn dome(
        &mut self,
        center: DVec3,
        normal: DVec3,
        ring: u32,
        c: [f32; 3],
        (offsets, outs): (&mut Vec<DVec3>, &mut Vec<DVec3>),
    ) {
        let n = self.sides as u32;
        let read = |array: &[f32], j: u32| {
            let i = (ring + j) as usize * 3;
            DVec3::new(array[i] as f64, array[i + 1] as f64, array[i + 2] as f64)
        };
        offsets.clear();
        // The ring's own normals point out of the tube (as the full mesh and a partial one agree).
        outs.clear();
        for j in 0..n {
            offsets.push(read(&self.mesh.positions, j) - center);
            outs.push(read(&self.mesh.normals, j));
        }
        let radius = offsets.iter().map(|o| o.length()).sum::<f64>() / n as f64;
        let mut rings = [0u32; DOME_STEPS];
        for (step, first_of_step) in rings.iter_mut().enumerate() {
            let angle = std::f64::consts::FRAC_PI_2 * step as f64 / DOME_STEPS as f64;
            let (sin, cos) = maths::sin_cos(angle);
            let first = self.mesh.vertex_count() as u32;
            for (j, (offset, out)) in offsets.iter().zip(outs.iter()).enumerate() {
                let (u, v) = (j as f32 / n as f32, 0.5 + 0.5 * sin as f32);
                let position = center + *offset * cos + normal * (radius * sin);
                self.vertex(position, (*out * cos + normal * sin).normalize(), c, [u, v]);
            }
            *first_of_step = first;
        }
        let apex = self.vertex(center + normal * radius, normal, c, [0.5, 1.0]);
        for pair in rings.windows(2) {
            let (a0, b0) = (pair[0], pair[1]);
            for j in 0..n {
                let next = (j + 1) % n;
                let (a, b, c, d) = (a0 + j, a0 + next, b0 + j, b0 + next);
                push(&mut self.mesh.indices, [a, b, c, b, d, c]);
            }
        }
        let top = rings[rings.len() - 1];
        for j in 0..n {
            push(&mut self.mesh.indices, [apex, top + j, top + (j + 1) % n]);
        }
    }

    /// A flat disk closing a tube: a fan around a centre vertex facing `normal`. The ring's order
    /// runs counter-clockwise around the axis, so the start cap reverses it.
    fn cap(&mut self, center: DVec3, normal: DVec3, ring: u32, c: [f32; 3], reverse: bool) {
        let n = self.sides as u32;
        let first = self.mesh.vertex_count() as u32;
        for j in 0..n {
            let i = (ring + j) as usize * 3;
            let p = DVec3::new(
                self.mesh.positions[i] as f64,
                self.mesh.positions[i + 1] as f64,
                self.mesh.positions[i + 2] as f64,
            );
            let (sin, cos) = self.ring[j as usize];
            let u = 0.5 + 0.5 * cos as f32;
            let v = 0.5 + if reverse { -0.5 } else { 0.5 } * sin as f32;
            self.vertex(p, normal, c, [u, v]);
        }
        let middle = self.vertex(center, normal, c, [0.5, 0.5]);
        for j in 0..n {
            let (a, b) = (first + j, first + (j + 1) % n);
            if reverse {
                push(&mut self.mesh.indices, [middle, b, a]);
            } else {
                push(&mut self.mesh.indices, [middle, a, b]);
            }
        }
    }
}

/// A sample at each joint `points`, its tangent along the segment it ends or starts (the
/// bisector of both inside the chain).
fn joint_samples(points: &[DVec3], widths: &[f64], samples: &mut Vec<AxisSample>) {
    let last_segment = points.len() - 2;
    let direction = |i: usize| (points[i + 1] - points[i]).normalize();
    samples.clear();
    for i in 0..points.len() {
        let tangent = if i == 0 {
            direction(0)
        } else if i == points.len() - 1 {
            direction(i - 1)
        } else {
            (direction(i - 1) + direction(i)).normalize()
        };
        samples.push(AxisSample {
            point: points[i],
            tangent,
            width: widths[i],
            segment: i.min(last_segment),
        });
    }
}
