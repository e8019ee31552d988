//! Triangulation of large polygons in O(n log n): the polygon is split into y-monotone pieces by a
//! sweep from top to bottom (de Berg et al., *Computational Geometry*, chapter 3), and each piece
//! is triangulated in linear time with a stack. Unlike ear clipping, whose ears grow long on
//! outlines close to a circle (its cost then goes with the square of the points), nothing here
//! depends on the outline's shape; unlike a fan, it covers a concave outline exactly, leaving no
//! gap over a notch and no overlap.
//!
//! The sweep assumes a simple polygon (no edge crossing another). Points are ordered by y, then
//! x (a symbolic rotation), so collinear and horizontal runs need no special case. What it gives
//! is checked (every triangle counter-clockwise, their areas summing to the polygon's): for an
//! outline that crosses itself the caller gets `None` and uses another method.

use crate::maths;
use glam::DVec2;

/// `a` comes before `b` in the sweep: higher, or as high and further left.
#[inline]
fn above(a: DVec2, b: DVec2) -> bool {
    a.y > b.y || (a.y == b.y && a.x < b.x)
}

/// Twice the signed area of `a b c`: positive when it turns counter-clockwise.
#[inline]
fn orient(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    (b - a).perp_dot(c - a)
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Start,
    Split,
    End,
    Merge,
    Regular,
}

/// Triangles (indices into `points`) of the simple polygon `points`, counter-clockwise; `None`
/// when the outline is not one this method can cut (it crosses itself, or has fewer than three
/// points). `tolerance` is twice an area that counts as none.
pub fn triangulate(points: &[DVec2], tolerance: f64) -> Option<Vec<[u32; 3]>> {
    let n = points.len();
    if n < 3 {
        return None;
    }
    let twice_area: f64 = (0..n)
        .map(|i| points[i].perp_dot(points[(i + 1) % n]))
        .sum();
    if twice_area <= tolerance {
        return None; // clockwise, or no area: not what the caller gives
    }
    let diagonals = monotone_diagonals(points);
    let faces = faces(points, &diagonals)?;
    let mut triangles = Vec::with_capacity(n - 2);
    for face in &faces {
        triangulate_monotone(points, face, &mut triangles);
    }
    // The check: counter-clockwise triangles that add up to the polygon.
    let mut sum = 0.0;
    for t in &triangles {
        let a = orient(
            points[t[0] as usize],
            points[t[1] as usize],
            points[t[2] as usize],
        );
        if a < -tolerance {
            return None;
        }
        sum += a;
    }
    let scale = points
        .iter()
        .fold(0.0f64, |m, p| m.max((*p - points[0]).length_squared()));
    if !sum.is_finite() || (sum - twice_area).abs() > 1e-9 * scale * n as f64 + tolerance {
        return None;
    }
    Some(triangles)
}

/// The diagonals that split the polygon into y-monotone pieces (pairs of point indices).
/// Long because it is the sweep itself: the five kinds of vertex (start, end, split, merge,
/// regular) share its status of edges and helpers, each a short arm of one match.
fn monotone_diagonals(p: &[DVec2]) -> Vec<(u32, u32)> {
    let n = p.len();
    let prev = |i: usize| if i == 0 { n - 1 } else { i - 1 };
    let next = |i: usize| if i + 1 == n { 0 } else { i + 1 };
    let kind = |i: usize| {
        let (a, v, b) = (p[prev(i)], p[i], p[next(i)]);
        let convex = orient(a, v, b) > 0.0;
        match (above(v, a), above(v, b)) {
            (true, true) if convex => Kind::Start,
            (true, true) => Kind::Split,
            (false, false) if convex => Kind::End,
            (false, false) => Kind::Merge,
            _ => Kind::Regular,
        }
    };
    let kinds: Vec<Kind> = (0..n).map(kind).collect();
    let mut order: Vec<u32> = (0..n as u32).collect();
    crate::sort::sort_by(&mut order, |&a, &b| {
        let (a, b) = (p[a as usize], p[b as usize]);
        b.y.total_cmp(&a.y).then(a.x.total_cmp(&b.x))
    });
    // The edges the sweep line crosses that have the interior on their right (edge e runs from
    // point e to point e + 1), left to right, each with its helper.
    let mut status: Vec<u32> = Vec::new();
    let mut helper: Vec<u32> = vec![u32::MAX; n];
    let mut diagonals = Vec::new();
    // Where edge `e` crosses the horizontal line through `v` (at `v` itself for a horizontal edge).
    let x_at = |e: usize, v: DVec2| -> f64 {
        let (a, b) = (p[e], p[next(e)]);
        let (upper, lower) = if above(a, b) { (a, b) } else { (b, a) };
        if upper.y == lower.y {
            return crate::maths::clamp(v.x, upper.x, lower.x);
        }
        if v.y >= upper.y {
            return upper.x;
        }
        if v.y <= lower.y {
            return lower.x;
        }
        upper.x + (lower.x - upper.x) * (upper.y - v.y) / (upper.y - lower.y)
    };
    let position =
        |status: &[u32], v: DVec2| status.partition_point(|&e| x_at(e as usize, v) < v.x);
    let remove = |status: &mut Vec<u32>, e: usize, v: DVec2| {
        let at = position(status, v);
        let found = (at.saturating_sub(2)..(at + 2).min(status.len()))
            .find(|&k| status[k] as usize == e)
            .or_else(|| status.iter().position(|&s| s as usize == e));
        if let Some(k) = found {
            status.remove(k);
        }
    };
    let left_of = |status: &[u32], v: DVec2| {
        position(status, v)
            .checked_sub(1)
            .map(|k| status[k] as usize)
    };
    let is_merge = |h: u32| h != u32::MAX && kinds[h as usize] == Kind::Merge;
    // Edge `e` ends at vertex `i`: a merge vertex helping it gets a diagonal to `i`, and `e`
    // leaves the status.
    let end_edge = |status: &mut Vec<u32>,
                    helper: &[u32],
                    diagonals: &mut Vec<(u32, u32)>,
                    e: usize,
                    i: usize| {
        if is_merge(helper[e]) {
            diagonals.push((i as u32, helper[e]));
        }
        remove(status, e, p[i]);
    };
    // The edge leaving vertex `i` enters the status, helped by `i`.
    let start_edge = |status: &mut Vec<u32>, helper: &mut [u32], i: usize| {
        let at = position(status, p[i]);
        status.insert(at, i as u32);
        helper[i] = i as u32;
    };
    // Vertex `i` becomes the helper of the edge to its left, after a diagonal to the merge vertex
    // that helped it.
    let help_left =
        |status: &[u32], helper: &mut [u32], diagonals: &mut Vec<(u32, u32)>, i: usize| {
            if let Some(j) = left_of(status, p[i]) {
                if is_merge(helper[j]) {
                    diagonals.push((i as u32, helper[j]));
                }
                helper[j] = i as u32;
            }
        };
    for &i in &order {
        let i = i as usize;
        let v = p[i];
        let e_prev = prev(i);
        match kinds[i] {
            Kind::Start => start_edge(&mut status, &mut helper, i),
            Kind::End => end_edge(&mut status, &helper, &mut diagonals, e_prev, i),
            Kind::Split => {
                if let Some(j) = left_of(&status, v) {
                    diagonals.push((i as u32, helper[j]));
                    helper[j] = i as u32;
                }
                start_edge(&mut status, &mut helper, i);
            }
            Kind::Merge => {
                end_edge(&mut status, &helper, &mut diagonals, e_prev, i);
                help_left(&status, &mut helper, &mut diagonals, i);
            }
            Kind::Regular => {
                // The interior is on the right when the outline comes down to this point.
                if above(p[e_prev], v) {
                    end_edge(&mut status, &helper, &mut diagonals, e_prev, i);
                    start_edge(&mut status, &mut helper, i);
                } else {
                    help_left(&status, &mut helper, &mut diagonals, i);
                }
            }
        }
    }
    diagonals.retain(|&(a, b)| a != b && a != u32::MAX && b != u32::MAX);
    diagonals
}

/// The pieces the diagonals cut the polygon into, each a loop of point indices counter-clockwise;
/// `None` when the diagonals do not make faces (a self-crossing outline).
fn faces(p: &[DVec2], diagonals: &[(u32, u32)]) -> Option<Vec<Vec<u32>>> {
    let n = p.len();
    // Each point's neighbours (the outline's two and its diagonals'), counter-clockwise by angle;
    // `used` marks the half-edges (point → neighbour) already walked.
    let mut around: Vec<Vec<(u32, bool)>> = (0..n)
        .map(|i| {
            vec![
                (((i + n - 1) % n) as u32, true),
                (((i + 1) % n) as u32, false),
            ]
        })
        .collect();
    for &(a, b) in diagonals {
        around[a as usize].push((b, false));
        around[b as usize].push((a, false));
    }
    for (i, list) in around.iter_mut().enumerate() {
        if list.len() > 2 {
            let c = p[i];
            crate::sort::sort_by(list, |x, y| {
                let (dx, dy) = (p[x.0 as usize] - c, p[y.0 as usize] - c);
                maths::atan2(dx.y, dx.x).total_cmp(&maths::atan2(dy.y, dy.x))
            });
        }
    }
    let mut faces = Vec::with_capacity(diagonals.len() + 1);
    let half_edges = n + 2 * diagonals.len();
    let mut walked = 0;
    for start in 0..n {
        for k in 0..around[start].len() {
            if around[start][k].1 {
                continue;
            }
            // Walk the face on the left of start → neighbour, back to start.
            let mut face = Vec::new();
            let (mut from, mut to) = (start, around[start][k].0 as usize);
            around[start][k].1 = true;
            loop {
                face.push(from as u32);
                walked += 1;
                if walked > half_edges {
                    return None;
                }
                if to == start {
                    break;
                }
                // At `to`, the next edge is the first clockwise from the one back to `from`.
                let list = &around[to];
                let back = list.iter().position(|&(w, _)| w as usize == from)?;
                let k = (back + list.len() - 1) % list.len();
                let (w, used) = list[k];
                if used {
                    return None;
                }
                around[to][k].1 = true;
                from = to;
                to = w as usize;
            }
            if face.len() < 3 {
                return None;
            }
            faces.push(face);
        }
    }
    Some(faces)
}

/// Triangulates one y-monotone piece (`face`: point indices counter-clockwise) into `out`.
fn triangulate_monotone(p: &[DVec2], face: &[u32], out: &mut Vec<[u32; 3]>) {
    let m = face.len();
    if m == 3 {
        out.push([face[0], face[1], face[2]]);
        return;
    }
    let pt = |k: usize| p[face[k] as usize];
    let top = (0..m).fold(0, |t, k| if above(pt(k), pt(t)) { k } else { t });
    let bottom = (0..m).fold(0, |b, k| if above(pt(b), pt(k)) { k } else { b });
    // Counter-clockwise from the top down to the bottom is the left chain.
    let mut left = vec![false; m];
    let mut k = top;
    while k != bottom {
        left[k] = true;
        k = (k + 1) % m;
    }
    let mut order: Vec<usize> = (0..m).collect();
    crate::sort::sort_by(&mut order, |&a, &b| {
        let (a, b) = (pt(a), pt(b));
        b.y.total_cmp(&a.y).then(a.x.total_cmp(&b.x))
    });
    let mut push = |a: usize, b: usize, c: usize| {
        let (ia, ib, ic) = (face[a], face[b], face[c]);
        if orient(pt(a), pt(b), pt(c)) >= 0.0 {
            out.push([ia, ib, ic]);
        } else {
            out.push([ia, ic, ib]);
        }
    };
    let mut stack: Vec<usize> = vec![order[0], order[1]];
    for &u in &order[2..m - 1] {
        let top_of = *stack.last().unwrap_or(&order[0]);
        if left[u] != left[top_of] {
            // Across: a fan from u over the whole stack.
            for w in stack.windows(2) {
                push(u, w[0], w[1]);
            }
            stack = vec![top_of, u];
        } else {
            let mut last = stack.pop().unwrap_or(top_of);
            while let Some(&b) = stack.last() {
                let turn = orient(pt(b), pt(last), pt(u));
                // Going down the left chain is going counter-clockwise (the piece on the left).
                let inside = if left[u] { turn > 0.0 } else { turn < 0.0 };
                if !inside {
                    break;
                }
                push(u, last, b);
                last = b;
                stack.pop();
            }
            stack.push(last);
            stack.push(u);
        }
    }
    let u = order[m - 1];
    for w in stack.windows(2) {
        push(u, w[0], w[1]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(points: &[DVec2], triangles: &[[u32; 3]]) -> f64 {
        triangles
            .iter()
            .map(|t| {
                0.5 * orient(
                    points[t[0] as usize],
                    points[t[1] as usize],
                    points[t[2] as usize],
                )
            })
            .sum()
    }

    /// The points of an outline given as (x, y) pairs.
    fn outline(xy: &[(f64, f64)]) -> Vec<DVec2> {
        xy.iter().map(|&(x, y)| DVec2::new(x, y)).collect()
    }

    #[test]
    fn small_outlines_of_every_vertex_kind() {
        // A square, an arrow head (a merge point), a "W" (split and merge points), a comb.
        let shapes: Vec<Vec<DVec2>> = vec![
            outline(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]),
            outline(&[(0.0, 0.0), (2.0, 1.0), (0.0, 2.0), (0.5, 1.0)]),
            outline(&[
                (0.0, 0.0),
                (4.0, 0.0),
                (4.0, 3.0),
                (3.0, 1.0),
                (2.0, 3.0),
                (1.0, 1.0),
                (0.0, 3.0),
            ]),
            outline(&[
                (0.0, 3.0),
                (1.0, 1.0),
                (2.0, 3.0),
                (3.0, 1.0),
                (4.0, 3.0),
                (4.0, 0.0),
                (0.0, 0.0),
            ])
            .into_iter()
            .map(|p| DVec2::new(p.x, -p.y)) // listed clockwise: mirrored, counter-clockwise
            .collect(),
        ];
        for (k, shape) in shapes.iter().enumerate() {
            let n = shape.len();
            let twice: f64 = (0..n).map(|i| shape[i].perp_dot(shape[(i + 1) % n])).sum();
            let t = triangulate(shape, 1e-12).unwrap_or_else(|| panic!("shape {k}"));
            assert_eq!(t.len(), n - 2, "shape {k}");
            assert!((area(shape, &t) - 0.5 * twice).abs() < 1e-12, "shape {k}");
        }
    }

    #[test]
    fn a_self_crossing_outline_is_refused_not_a_hang() {
        let bow = outline(&[(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.1), (-1.0, 1.0)]);
        let _ = triangulate(&bow, 1e-12); // any answer, promptly
        let figure_eight: Vec<DVec2> = (0..200)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / 200.0;
                DVec2::new(maths::sin(t), maths::sin(2.0 * t) * 0.5 + 0.01 * t)
            })
            .collect();
        let _ = triangulate(&figure_eight, 1e-12);
    }
}
