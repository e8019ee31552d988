//! Meristem's own predefined surfaces, drawn by `~l` (leaf) and `~p` (petal) when the grammar
//! declares no surface for them (`#surface`, `#patch`: `bezier.rs`): `~l(s)` at the turtle with
//! scale `s`, flat outlines in the turtle's H–L plane, base at the turtle, tip along H.
//!
//! Both outlines have [`OUTLINE_POINTS`] points: the base (index 0), ten points up the right
//! side (−L), the tip (index [`TIP`], at `scale` along H), and ten points back down the left side
//! (+L). They run counter-clockwise seen from U, so the triangulated front faces U (H × L = U).

use crate::maths;
use glam::DVec3;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SurfaceKind {
    Leaf,
    Petal,
}

pub const OUTLINE_POINTS: usize = 22;
pub const TIP: usize = 11;

/// Half width of the outline at `t` (0 at the base, 1 at the tip) for a surface of length 1.
fn half_width(kind: SurfaceKind, t: f64) -> f64 {
    let s = maths::sin(std::f64::consts::PI * t).max(0.0);
    match kind {
        // Lanceolate: widest below the middle, narrow tip.
        SurfaceKind::Leaf => 0.19 * s * (1.0 - 0.35 * t) * 1.25,
        // Obovate: widest beyond the middle, round end.
        SurfaceKind::Petal => 0.32 * maths::powf(s, 0.6) * (0.7 + 0.5 * t),
    }
}

/// The outline in surface coordinates: (distance along H, distance along L) for length 1.
pub fn outline(kind: SurfaceKind) -> Vec<(f64, f64)> {
    let side = TIP - 1;
    let mut points = Vec::with_capacity(OUTLINE_POINTS);
    points.push((0.0, 0.0));
    for k in 1..=side {
        let t = k as f64 / TIP as f64;
        points.push((t, -half_width(kind, t)));
    }
    points.push((1.0, 0.0));
    for k in (1..=side).rev() {
        let t = k as f64 / TIP as f64;
        points.push((t, half_width(kind, t)));
    }
    points
}

/// The outline of a built-in surface as the turtle placed it: its length along H scaled by the
/// surface's scale along H, its width by the scale along L.
pub fn outline_of(kind: SurfaceKind, s: &crate::turtle::Surface) -> Vec<DVec3> {
    place(
        kind,
        s.origin,
        s.heading * s.scale.y,
        s.left * s.scale.x,
        1.0,
    )
}

/// The outline placed at `origin` in the frame (`heading`, `left`), scaled by `scale`.
pub fn place(
    kind: SurfaceKind,
    origin: DVec3,
    heading: DVec3,
    left: DVec3,
    scale: f64,
) -> Vec<DVec3> {
    outline(kind)
        .into_iter()
        .map(|(h, l)| origin + (heading * h + left * l) * scale)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::polygon::triangulate;

    #[test]
    fn outlines_have_their_base_and_tip_where_documented() {
        for kind in [SurfaceKind::Leaf, SurfaceKind::Petal] {
            let points = place(kind, DVec3::new(1.0, 0.0, 0.0), DVec3::Y, DVec3::NEG_X, 2.0);
            assert_eq!(points.len(), OUTLINE_POINTS);
            assert_eq!(points[0], DVec3::new(1.0, 0.0, 0.0));
            assert!((points[TIP] - DVec3::new(1.0, 2.0, 0.0)).length() < 1e-12);
            // Front faces U = H × L.
            let t = triangulate(&points);
            assert!((t.normal - DVec3::Y.cross(DVec3::NEG_X)).length() < 1e-12);
            assert_eq!(t.triangles.len(), OUTLINE_POINTS - 2);
        }
    }

    #[test]
    fn a_petal_is_wider_than_a_leaf() {
        let widest = |kind| outline(kind).iter().fold(0.0f64, |m, p| m.max(p.1));
        assert!(widest(SurfaceKind::Petal) > widest(SurfaceKind::Leaf));
        assert!(widest(SurfaceKind::Leaf) > 0.1);
    }
}
