//! Spheres (`@O`): a latitude–longitude mesh with one vertex at each pole, so no triangle is
//! degenerate.

use crate::maths;
use glam::DVec3;

#[derive(Clone, Debug, Default, PartialEq)]
pub struct SphereMesh {
    pub positions: Vec<DVec3>,
    pub normals: Vec<DVec3>,
    /// Counter-clockwise seen from outside.
    pub triangles: Vec<[u32; 3]>,
}

/// A sphere of `segments` meridians and `rings` bands (at least 3 and 2). Vertices:
/// `2 + (rings − 1)·segments`; triangles: `2·segments·(rings − 1)`. A radius that is not a positive
/// finite number gives an empty mesh, and so does a sphere too small for its distance from the
/// origin to be drawn in `f32`, the mesh's precision (a triangle would collapse to a line or turn
/// over there: a radius of 1 at 1e30). The poles are on the Y axis (the view's up).
pub fn sphere(center: DVec3, radius: f64, segments: u32, rings: u32) -> SphereMesh {
    let mut mesh = SphereMesh::default();
    if !(radius > 0.0 && radius.is_finite() && center.is_finite()) {
        return mesh;
    }
    let (segments, rings) = (segments.max(3), rings.max(2));
    let push = |n: DVec3, mesh: &mut SphereMesh| {
        mesh.positions.push(center + n * radius);
        mesh.normals.push(n);
    };
    push(DVec3::Y, &mut mesh);
    for r in 1..rings {
        let theta = r as f64 / rings as f64 * std::f64::consts::PI;
        let (sin_t, cos_t) = maths::sin_cos(theta);
        for s in 0..segments {
            let phi = s as f64 / segments as f64 * std::f64::consts::TAU;
            let (sin_p, cos_p) = maths::sin_cos(phi);
            push(DVec3::new(sin_t * cos_p, cos_t, -sin_t * sin_p), &mut mesh);
        }
    }
    push(DVec3::NEG_Y, &mut mesh);
    let bottom = mesh.positions.len() as u32 - 1;
    let at = |r: u32, s: u32| 1 + (r - 1) * segments + s % segments;
    for s in 0..segments {
        mesh.triangles.push([0, at(1, s), at(1, s + 1)]);
    }
    for r in 1..rings - 1 {
        for s in 0..segments {
            let (a, b, c, d) = (at(r, s), at(r, s + 1), at(r + 1, s), at(r + 1, s + 1));
            mesh.triangles.push([a, c, b]);
            mesh.triangles.push([b, c, d]);
        }
    }
    for s in 0..segments {
        mesh.triangles
            .push([bottom, at(rings - 1, s + 1), at(rings - 1, s)]);
    }
    if drawn_in_f32(&mesh) {
        mesh
    } else {
        SphereMesh::default()
    }
}

/// Whether every triangle keeps an area and its outward side once its corners are rounded to
/// `f32` (as `MeshBuffers::check` sees them).
fn drawn_in_f32(mesh: &SphereMesh) -> bool {
    let rounded = |p: DVec3| p.as_vec3().as_dvec3();
    mesh.triangles.iter().all(|t| {
        let [a, b, c] = t.map(|i| rounded(mesh.positions[i as usize]));
        let normals: DVec3 = t.iter().map(|&i| mesh.normals[i as usize]).sum();
        let face = (b - a).cross(c - a);
        face.length() > 0.0 && face.dot(normals) > 0.0
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_and_outward_winding() {
        let center = DVec3::new(1.0, 2.0, 3.0);
        let s = sphere(center, 2.0, 12, 6);
        assert_eq!(s.positions.len(), 2 + 5 * 12);
        assert_eq!(s.triangles.len(), 2 * 12 * 5);
        for p in &s.positions {
            assert!(((*p - center).length() - 2.0).abs() < 1e-12);
        }
        for &[a, b, c] in &s.triangles {
            let (pa, pb, pc) = (
                s.positions[a as usize],
                s.positions[b as usize],
                s.positions[c as usize],
            );
            let face = (pb - pa).cross(pc - pa);
            assert!(face.length() > 1e-9, "degenerate triangle");
            assert!(
                face.dot((pa + pb + pc) / 3.0 - center) > 0.0,
                "triangle faces inwards"
            );
        }
    }

    #[test]
    fn no_sphere_too_small_to_draw_where_it_is() {
        // Far out along two axes, the corners round onto one line (what clamped coordinates give).
        assert!(sphere(DVec3::new(1e30, 0.0, -1e30), 1.0, 8, 4)
            .positions
            .is_empty());
        assert!(sphere(DVec3::new(3e7, 2.0, 3e7), 0.5, 8, 4)
            .positions
            .is_empty());
        assert!(!sphere(DVec3::new(1e4, 0.0, 0.0), 0.01, 8, 4)
            .positions
            .is_empty());
        assert!(!sphere(DVec3::new(1e30, 0.0, 0.0), 1e26, 8, 4)
            .positions
            .is_empty());
    }

    #[test]
    fn no_sphere_without_a_radius() {
        assert!(sphere(DVec3::ZERO, 0.0, 8, 4).triangles.is_empty());
        assert!(sphere(DVec3::ZERO, f64::NAN, 8, 4).positions.is_empty());
        assert!(sphere(DVec3::ZERO, -1.0, 8, 4).positions.is_empty());
    }
}
