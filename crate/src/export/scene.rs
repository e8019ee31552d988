//! What every file writer needs from the mesh and the skeleton: triangles (or, in the fallback,
//! lines) grouped by colour index, the camera that frames the plant, and numbers printed the same
//! way on every machine.

use crate::maths;
use crate::mesh::MeshBuffers;
use crate::turtle::Skeleton;
use glam::{DMat3, DQuat, DVec3};
use std::collections::BTreeMap;
use std::fmt::Write;

/// The triangles (or fallback lines) of one colour index.
#[derive(Clone, Debug, PartialEq)]
pub struct ColorGroup {
    /// The colour index (`'`, `;`), which names the material: `color_3`.
    pub index: u16,
    /// The palette's colour of that index, linear RGB.
    pub color: [f32; 3],
    /// Triangle numbers (into `MeshBuffers::indices / 3`), or in the fallback line numbers (into
    /// `MeshBuffers::lines / 6`), in mesh order.
    pub items: Vec<u32>,
}

/// What a writer draws: triangles, or the lines of a model too large to mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    Triangles,
    Lines,
}

/// The model a writer reads: the mesh, and the skeleton for the palette and the segments.
#[derive(Clone, Copy, Debug)]
pub struct Scene<'a> {
    pub mesh: &'a MeshBuffers,
    pub skeleton: &'a Skeleton,
}

impl<'a> Scene<'a> {
    pub fn new(mesh: &'a MeshBuffers, skeleton: &'a Skeleton) -> Self {
        Scene { mesh, skeleton }
    }

    /// Triangles when the model was meshed, lines when it fell back to lines.
    pub fn primitive(&self) -> Primitive {
        if self.mesh.indices.is_empty() && !self.mesh.lines.is_empty() {
            Primitive::Lines
        } else {
            Primitive::Triangles
        }
    }

    /// The points the primitives index: mesh vertices, or line ends (two per line).
    pub fn points(&self) -> &'a [f32] {
        match self.primitive() {
            Primitive::Triangles => &self.mesh.positions,
            Primitive::Lines => &self.mesh.lines,
        }
    }

    /// The triangles (or lines) grouped by colour index, in increasing index order; within a
    /// group in mesh order. Empty groups are left out.
    pub fn groups(&self) -> Vec<ColorGroup> {
        let mut by_index: BTreeMap<u16, Vec<u32>> = BTreeMap::new();
        match self.primitive() {
            Primitive::Triangles => {
                for (t, index) in self.mesh.triangle_color_indices().into_iter().enumerate() {
                    by_index.entry(index).or_default().push(t as u32);
                }
            }
            Primitive::Lines => {
                // Line i is segment i (`MeshBuffers::lines`).
                for line in 0..self.mesh.lines.len() / 6 {
                    let index = self.skeleton.segments.get(line).map_or(0, |s| s.color);
                    by_index.entry(index).or_default().push(line as u32);
                }
            }
        }
        by_index
            .into_iter()
            .map(|(index, items)| ColorGroup {
                index,
                color: self.skeleton.color(index),
                items,
            })
            .collect()
    }

    /// Points per primitive: 3 for triangles, 2 for lines.
    pub fn arity(&self) -> usize {
        match self.primitive() {
            Primitive::Triangles => 3,
            Primitive::Lines => 2,
        }
    }

    /// The point indices of triangle (or line) `item`; only the first [`Scene::arity`] count.
    pub fn corners(&self, item: u32) -> [u32; 3] {
        let i = item as usize;
        match self.primitive() {
            Primitive::Triangles => {
                let t = &self.mesh.indices[3 * i..3 * i + 3];
                [t[0], t[1], t[2]]
            }
            Primitive::Lines => [2 * item, 2 * item + 1, 2 * item + 1],
        }
    }

    /// `[[min x, y, z], [max x, y, z]]` of what is drawn.
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        self.mesh.bounds()
    }
}

/// The camera that frames the plant, in the model's coordinates (right-handed, Y up).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    pub eye: DVec3,
    pub target: DVec3,
    /// Field of view across the smaller side of the picture, in radians.
    pub fov: f64,
    /// Radius of the sphere around the plant.
    pub radius: f64,
    /// Distance from the eye to the target.
    pub distance: f64,
}

/// The field of view every writer's camera uses (across the smaller side of the picture).
pub const FIELD_OF_VIEW_DEGREES: f64 = 40.0;

impl View {
    /// A camera that sees the whole box `bounds` in a square picture (so in any picture, when
    /// `fov` spans its smaller side), as the studio frames a plant: it looks across the box's
    /// thinner horizontal axis (a flat plant is seen face-on), a little from the side and from
    /// above, from as near as every corner allows. An empty box is a unit box at the origin.
    pub fn framing(bounds: [[f64; 3]; 2]) -> View {
        let (mut min, mut max) = (DVec3::from(bounds[0]), DVec3::from(bounds[1]));
        if !(min.is_finite() && max.is_finite() && (max - min).length() > 1e-9) {
            (min, max) = (DVec3::splat(-0.5), DVec3::splat(0.5));
        }
        let size = max - min;
        let target = (min + max) * 0.5;
        let radius = size.length() * 0.5;
        let fov = FIELD_OF_VIEW_DEGREES.to_radians();
        let across = if size.z <= size.x {
            DVec3::new(0.25, 0.18, 1.0)
        } else {
            DVec3::new(1.0, 0.18, -0.25)
        };
        let back = across.normalize();
        let right = DVec3::Y.cross(back).normalize();
        let up = back.cross(right);
        // Each corner needs the eye far enough that its offset across the view stays within
        // tan(fov / 2) of its depth; 3 % more leaves a margin.
        let tan = maths::tan(fov * 0.5);
        let mut distance: f64 = 0.0;
        for k in 0..8 {
            let corner = DVec3::new(
                if k & 1 == 0 { min.x } else { max.x },
                if k & 2 == 0 { min.y } else { max.y },
                if k & 4 == 0 { min.z } else { max.z },
            ) - target;
            let lateral = corner.dot(right).abs().max(corner.dot(up).abs());
            distance = distance.max(corner.dot(back) + lateral / tan);
        }
        let distance = distance * 1.03;
        View {
            eye: target + back * distance,
            target,
            fov,
            radius,
            distance,
        }
    }

    /// Unit vector from the eye to the target.
    pub fn direction(&self) -> DVec3 {
        (self.target - self.eye).normalize()
    }

    /// The rotation (axis, angle in radians) that turns a camera looking down −Z with +Y up
    /// (VRML's and Inventor's default) into this view, with the world's +Y as up.
    pub fn orientation(&self) -> (DVec3, f64) {
        let back = -self.direction();
        let right = DVec3::Y.cross(back).normalize();
        let up = back.cross(right);
        let rotation = DQuat::from_mat3(&DMat3::from_cols(right, up, back)).normalize();
        let (axis, angle) = rotation.to_axis_angle();
        if angle.abs() < 1e-12 || !axis.is_finite() {
            (DVec3::Z, 0.0)
        } else {
            (axis, angle)
        }
    }
}

/// Linear RGB (the palette, glTF, POV-Ray with `assumed_gamma 1`) to sRGB (what VRML, Inventor,
/// MTL and SVG viewers take as displayed colours; three.js's loaders convert them back).
pub fn srgb(linear: [f32; 3]) -> [f32; 3] {
    linear.map(|c| {
        let c = c.clamp(0.0, 1.0) as f64;
        let s = if c <= 0.003_130_8 {
            12.92 * c
        } else {
            1.055 * maths::powf(c, 1.0 / 2.4) - 0.055
        };
        s as f32
    })
}

/// The rows of an Inventor or VRML `coordIndex` for `items` (triangles or lines of `scene`):
/// each item's corners and `-1`, every number after a space and followed by `separator` (`,` in
/// Inventor, nothing in VRML).
pub fn coord_index(out: &mut String, scene: &Scene, items: &[u32], separator: &str) {
    let arity = scene.arity();
    for &item in items {
        out.push_str("     ");
        for corner in &scene.corners(item)[..arity] {
            write!(out, " {corner}{separator}").ok();
        }
        writeln!(out, " -1{separator}").ok();
    }
}

/// Writes `value` with at most `decimals` decimals, trailing zeros and a trailing point removed
/// and `-0` printed as `0`: `1.5`, `2`, `-0.25`. The same bytes on every machine: the value is
/// scaled and rounded (half away from zero) in IEEE arithmetic, then printed as integers, which is
/// also several times faster than `{:.6}` on the millions of numbers of a large model. Values too
/// large for that take Rust's own formatting (no locale either way).
pub fn number(out: &mut String, value: f64, decimals: usize) {
    const POWERS: [u64; 16] = {
        let mut p = [1u64; 16];
        let mut k = 1;
        while k < 16 {
            p[k] = p[k - 1] * 10;
            k += 1;
        }
        p
    };
    let value = if value.is_finite() { value } else { 0.0 };
    let scaled = if decimals < POWERS.len() {
        (value * POWERS[decimals] as f64).round()
    } else {
        f64::INFINITY
    };
    if scaled.abs() >= 9.0e15 {
        let start = out.len();
        write!(out, "{value:.decimals$}").ok();
        if out[start..].contains('.') {
            let trimmed = out[start..]
                .trim_end_matches('0')
                .trim_end_matches('.')
                .len();
            out.truncate(start + trimmed);
        }
        if &out[start..] == "-0" {
            out.truncate(start);
            out.push('0');
        }
        return;
    }
    let magnitude = scaled.abs() as u64;
    if magnitude == 0 {
        out.push('0');
        return;
    }
    if scaled < 0.0 {
        out.push('-');
    }
    let whole = magnitude / POWERS[decimals];
    let mut fraction = magnitude % POWERS[decimals];
    write!(out, "{whole}").ok();
    if fraction != 0 {
        let mut digits = decimals;
        while fraction.is_multiple_of(10) {
            fraction /= 10;
            digits -= 1;
        }
        write!(out, ".{fraction:0digits$}").ok();
    }
}

/// Decimals that resolve a millionth of `extent` (about f32's precision): 6 for a plant a unit
/// tall, 3 for one a thousand units tall.
pub fn decimals_for(extent: f64) -> usize {
    if !(extent.is_finite() && extent > 0.0) {
        return 6;
    }
    (6.0 - maths::log10(extent).floor()).clamp(0.0, 12.0) as usize
}

/// The largest side of the bounds.
pub fn extent(bounds: [[f64; 3]; 2]) -> f64 {
    (0..3)
        .map(|k| bounds[1][k] - bounds[0][k])
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(value: f64, decimals: usize) -> String {
        let mut s = String::new();
        number(&mut s, value, decimals);
        s
    }

    #[test]
    fn numbers_are_trimmed_and_never_negative_zero() {
        assert_eq!(text(1.5, 6), "1.5");
        assert_eq!(text(2.0, 6), "2");
        assert_eq!(text(-0.25, 6), "-0.25");
        assert_eq!(text(-0.0000001, 6), "0");
        assert_eq!(text(123.456789, 3), "123.457");
        assert_eq!(text(100.0, 0), "100");
        assert_eq!(text(f64::NAN, 3), "0");
        assert_eq!(text(0.05, 4), "0.05");
        assert_eq!(text(-3.000_04, 4), "-3");
        assert_eq!(text(0.000_123, 8), "0.000123");
        assert_eq!(text(2.5e20, 6), "250000000000000000000");
    }

    #[test]
    fn decimals_follow_the_size_of_the_plant() {
        assert_eq!(decimals_for(1.36), 6);
        assert_eq!(decimals_for(1124.0), 3);
        assert_eq!(decimals_for(0.05), 8);
        assert_eq!(decimals_for(0.0), 6);
    }

    #[test]
    fn srgb_brightens_the_midtones_and_keeps_the_ends() {
        assert_eq!(srgb([0.0, 1.0, 0.5])[..2], [0.0, 1.0]);
        assert!((srgb([0.0, 0.0, 0.2140])[2] - 0.5).abs() < 1e-3);
    }

    #[test]
    fn the_view_sees_the_whole_box_and_its_orientation_points_the_camera_at_it() {
        let bounds = [[-1.0, 0.0, -0.1], [1.0, 10.0, 0.1]];
        let view = View::framing(bounds);
        // Every corner is inside the square pyramid of half-angle fov/2 around the view.
        let (axis, angle) = view.orientation();
        let rotation = DQuat::from_axis_angle(axis, angle);
        let (right, up) = (rotation * DVec3::X, rotation * DVec3::Y);
        let tan = maths::tan(view.fov * 0.5);
        let mut widest: f64 = 0.0;
        for x in [-1.0, 1.0] {
            for y in [0.0, 10.0] {
                for z in [-0.1, 0.1] {
                    let to = DVec3::new(x, y, z) - view.eye;
                    let depth = to.dot(view.direction());
                    let lateral = to.dot(right).abs().max(to.dot(up).abs()) / depth;
                    assert!(lateral <= tan + 1e-9);
                    widest = widest.max(lateral);
                }
            }
        }
        assert!(widest > tan * 0.9, "the plant fills the view, not a speck");
        // A flat plant in the XY plane is seen from +Z, face-on.
        assert!(view.direction().z < -0.9);
        assert!((rotation * DVec3::NEG_Z - view.direction()).length() < 1e-9);
        assert!((rotation * DVec3::Y).y > 0.9, "up stays up");
    }
}
