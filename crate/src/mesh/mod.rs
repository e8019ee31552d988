//! Stage 5, `mesh`: the skeleton becomes triangles in flat arrays ready for the GPU.
//!
//! Each segment becomes an open tube of `sides` quads whose ring lies in the turtle's L–U plane.
//! Widths are diameters measured in *width units*. By default ([`WidthUnit::Relative`]) one unit
//! is 1/300 of the skeleton's bounding-box diagonal, like cpfg's widths in pixels of a window that
//! frames the plant: `#width 1` draws thin but visible branches at any size, and `!(10)` a trunk
//! ten times thicker.

pub mod curve;
pub mod polygon;
pub mod sphere;
pub mod surfaces;

use crate::turtle::Skeleton;
use glam::DVec3;

/// The mesh as four flat arrays. **This is the one place the layout is defined**; the wasm
/// boundary and the TypeScript `MeshBuffers` type refer here.
///
/// - `positions`: `f32` × 3 per vertex (x, y, z), in model units, Y up.
/// - `normals`: `f32` × 3 per vertex, unit length, pointing out of the surface.
/// - `colors`: `f32` × 3 per vertex (r, g, b), linear, 0..=1.
/// - `indices`: `u32` × 3 per triangle, each `< positions.len() / 3`, counter-clockwise seen
///   from outside (the side the normals point to).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshBuffers {
    pub positions: Vec<f32>,
    pub normals: Vec<f32>,
    pub colors: Vec<f32>,
    pub indices: Vec<u32>,
}

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

    /// `[[min x, y, z], [max x, y, z]]` of the vertices; all zeros for an empty mesh.
    pub fn bounds(&self) -> [[f64; 3]; 2] {
        if self.positions.is_empty() {
            return [[0.0; 3]; 2];
        }
        let mut min = [f64::INFINITY; 3];
        let mut max = [f64::NEG_INFINITY; 3];
        for p in self.positions.chunks_exact(3) {
            for k in 0..3 {
                min[k] = min[k].min(p[k] as f64);
                max[k] = max[k].max(p[k] as f64);
            }
        }
        [min, max]
    }
}

/// How a width value becomes a diameter in model units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum WidthUnit {
    /// One width unit is this fraction of the skeleton's bounding-box diagonal.
    Relative(f64),
    /// One width unit is this many model units.
    Absolute(f64),
}

/// Options of the mesh stage.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshOptions {
    /// Sides of each tube (at least 3).
    pub sides: u32,
    pub width_unit: WidthUnit,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            sides: 6,
            width_unit: WidthUnit::Relative(1.0 / 300.0),
        }
    }
}

/// Colours for the colour index (`'` and `;` in later versions): index 0 is the stem colour.
pub const PALETTE: &[[f32; 3]] = &[
    [0.30, 0.50, 0.16], // stem green
    [0.20, 0.55, 0.12], // leaf green
    [0.12, 0.38, 0.10], // dark green
    [0.45, 0.30, 0.16], // bark brown
    [0.85, 0.30, 0.45], // petal pink
    [0.95, 0.80, 0.20], // yellow
    [0.90, 0.90, 0.85], // white
    [0.55, 0.20, 0.60], // purple
];

/// Builds the tube mesh of a skeleton. Segments of zero length or zero width draw nothing.
pub fn build_mesh(skeleton: &Skeleton, options: &MeshOptions) -> MeshBuffers {
    let sides = options.sides.max(3) as usize;
    let unit = match options.width_unit {
        WidthUnit::Absolute(u) => u,
        WidthUnit::Relative(fraction) => fraction * skeleton_diagonal(skeleton),
    };
    let ring: Vec<(f64, f64)> = (0..sides)
        .map(|k| (k as f64 / sides as f64 * std::f64::consts::TAU).sin_cos())
        .collect();

    let drawn = skeleton.segments.len();
    let mut mesh = MeshBuffers {
        positions: Vec::with_capacity(drawn * sides * 6),
        normals: Vec::with_capacity(drawn * sides * 6),
        colors: Vec::with_capacity(drawn * sides * 6),
        indices: Vec::with_capacity(drawn * sides * 6),
    };
    for segment in &skeleton.segments {
        let radius = 0.5 * segment.width * unit;
        let length = (segment.end - segment.start).length();
        if !(radius > 0.0 && radius.is_finite() && length > 1e-12 && length.is_finite()) {
            continue;
        }
        let base = mesh.vertex_count() as u32;
        let color = PALETTE[segment.color as usize % PALETTE.len()];
        for center in [segment.start, segment.end] {
            for &(sin, cos) in &ring {
                let normal: DVec3 = segment.left * cos + segment.up * sin;
                let p = center + normal * radius;
                mesh.positions.extend([p.x as f32, p.y as f32, p.z as f32]);
                mesh.normals
                    .extend([normal.x as f32, normal.y as f32, normal.z as f32]);
                mesh.colors.extend(color);
            }
        }
        let n = sides as u32;
        for k in 0..n {
            let next = (k + 1) % n;
            let (a, b, c, d) = (base + k, base + next, base + n + k, base + n + next);
            mesh.indices.extend([a, b, c, b, d, c]);
        }
    }
    mesh
}

/// Length of the diagonal of the box around every segment end point.
fn skeleton_diagonal(skeleton: &Skeleton) -> f64 {
    let mut min = DVec3::INFINITY;
    let mut max = DVec3::NEG_INFINITY;
    for s in &skeleton.segments {
        min = min.min(s.start).min(s.end);
        max = max.max(s.start).max(s.end);
    }
    if skeleton.segments.is_empty() {
        0.0
    } else {
        (max - min).length()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::turtle::Segment;

    fn segment(start: DVec3, end: DVec3) -> Segment {
        Segment {
            start,
            end,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            width: 1.0,
            color: 0,
            module: 0,
        }
    }

    #[test]
    fn a_segment_is_a_tube_of_sides_quads() {
        let skeleton = Skeleton {
            segments: vec![segment(DVec3::ZERO, DVec3::Y)],
            end: DVec3::Y,
        };
        let mesh = build_mesh(
            &skeleton,
            &MeshOptions {
                sides: 8,
                width_unit: WidthUnit::Absolute(0.2),
            },
        );
        assert_eq!(mesh.vertex_count(), 16);
        assert_eq!(mesh.triangle_count(), 16);
        assert_eq!(mesh.check(), Ok(()));
        let [min, max] = mesh.bounds();
        assert!(
            (max[0] - 0.1).abs() < 1e-6 && (min[1]).abs() < 1e-6 && (max[1] - 1.0).abs() < 1e-6
        );
    }

    #[test]
    fn zero_length_segments_make_no_triangles() {
        let skeleton = Skeleton {
            segments: vec![segment(DVec3::Y, DVec3::Y)],
            end: DVec3::Y,
        };
        let mesh = build_mesh(&skeleton, &MeshOptions::default());
        assert_eq!(mesh.triangle_count(), 0);
    }
}
