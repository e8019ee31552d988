//! ABOP chapter 4 (phyllotaxis) in the gallery, checked against the book: the divergence angle
//! measured between successive florets' positions, Vogel's r = c·√n, and the number of
//! parastichies counted from the florets' positions by their nearest neighbours, as the book's
//! reasoning does: an organ's nearest neighbours are the m-th and n-th organs before and after it,
//! and the eye joins them into m spirals one way and n the other.

mod shared;

use glam::DVec3;
use meristem::maths;
use meristem::pipeline::{build, Build, BuildOptions};
use meristem::turtle::Skeleton;
use shared::example;
use std::collections::HashMap;

/// The example's skeleton, built as the gallery builds it, without a diagnostic.
fn skeleton(name: &str) -> Skeleton {
    let result: Build = build(&example(name), &BuildOptions::default());
    assert!(result.diagnostics.is_empty(), "{:?}", result.diagnostics);
    result.plant.skeleton
}

/// The centres of the spheres (florets) the example draws, in the order the turtle drew them.
fn florets(name: &str) -> Vec<DVec3> {
    skeleton(name).spheres.iter().map(|s| s.center).collect()
}

/// The contact parastichies among `points[range]`: for each organ there, the index differences of
/// its four nearest neighbours (two in each family); the two most frequent, smaller first.
fn parastichies(points: &[DVec3], from: usize, to: usize) -> (usize, usize) {
    let mut seen: HashMap<usize, usize> = HashMap::new();
    for i in from..to {
        let mut near: Vec<(f64, usize)> = (0..points.len())
            .filter(|&j| j != i)
            .map(|j| (points[i].distance_squared(points[j]), i.abs_diff(j)))
            .collect();
        near.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut differences: Vec<usize> = near[..4].iter().map(|n| n.1).collect();
        differences.sort_unstable();
        differences.dedup();
        for d in differences {
            *seen.entry(d).or_default() += 1;
        }
    }
    let mut ranked: Vec<(usize, usize)> = seen.into_iter().collect();
    ranked.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let (m, n) = (ranked[0].0, ranked[1].0);
    (m.min(n), m.max(n))
}

/// The angle (degrees, 0 to 360) from `a` to `b` about the axis `axis` through the origin.
fn turn(a: DVec3, b: DVec3, axis: DVec3) -> f64 {
    let flat = |p: DVec3| p - axis * p.dot(axis);
    let (a, b) = (flat(a), flat(b));
    let angle = maths::atan2(a.cross(b).dot(axis), a.dot(b)).to_degrees();
    angle.rem_euclid(360.0)
}

#[test]
fn vogel_places_floret_n_at_n_times_the_divergence_angle_and_c_root_n() {
    for (name, angle) in [
        ("abop-4.02-vogel-planar.lsys", 137.5),
        ("abop-4.03a-vogel-137.3.lsys", 137.3),
        ("abop-4.03c-vogel-137.6.lsys", 137.6),
    ] {
        let p = florets(name);
        assert_eq!(p.len(), 600, "{name}: 600 florets");
        for n in 1..p.len() {
            // The head lies in the plane z = 0, c = 1.
            assert!(p[n].z.abs() < 1e-9 && (p[n].length() - (n as f64).sqrt()).abs() < 1e-6);
            if n > 1 {
                let divergence = turn(p[n - 1], p[n], DVec3::Z);
                assert!(
                    (divergence - angle).abs() < 1e-6,
                    "{name}: {divergence} at {n}"
                );
            }
        }
    }
}

#[test]
fn the_golden_angle_shows_34_and_55_parastichies_in_the_outer_part_of_the_head() {
    // Counted in the outer half of the head (florets 300 to 599); the angles 0.2° below and 0.1°
    // above it line the florets up in spokes of 21 and 34 instead, with gaps between (Fig. 4.3).
    let golden = florets("abop-4.02-vogel-planar.lsys");
    assert_eq!(parastichies(&golden, 300, 600), (34, 55));
    let below = florets("abop-4.03a-vogel-137.3.lsys");
    assert_eq!(parastichies(&below, 300, 600).0, 21);
    let above = florets("abop-4.03c-vogel-137.6.lsys");
    assert_eq!(parastichies(&above, 300, 600).0, 34);
    // The golden angle packs best: its florets' nearest neighbours are the farthest away.
    let nearest = |p: &[DVec3]| -> f64 {
        (300..600)
            .map(|i| {
                (0..p.len())
                    .filter(|&j| j != i)
                    .map(|j| p[i].distance(p[j]))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(f64::INFINITY, f64::min)
    };
    assert!(nearest(&golden) > nearest(&below) && nearest(&golden) > nearest(&above));
}

#[test]
fn the_sunflower_head_has_600_disk_florets_34_rays_and_34_55_parastichies() {
    let head = skeleton("abop-sec-4.1-sunflower-head.lsys");
    let disk: Vec<DVec3> = head.spheres.iter().map(|s| s.center).collect();
    assert_eq!(disk.len(), 600);
    assert_eq!(head.surfaces.len(), 34, "ray florets");
    assert_eq!(parastichies(&disk, 300, 600), (34, 55));
    // Every ray floret lies outside the disk.
    let rim = disk.iter().map(|p| p.length()).fold(0.0, f64::max);
    for ray in &head.surfaces {
        assert!(ray.origin.length() > rim - 1e-9);
    }
}

/// The organs of a cylindrical example, as seen from the axis Y: (angle, height) per organ.
fn about_the_axis(points: &[DVec3]) -> Vec<(f64, f64)> {
    points
        .iter()
        .map(|p| (maths::atan2(p.z, p.x).to_degrees(), p.y))
        .collect()
}

#[test]
fn the_cylindrical_model_turns_by_137_5_and_shows_its_parastichy_pairs() {
    // By hand, on the unrolled lattice (organ k at k·137.5° around and k·h up, radius r): the
    // nearest neighbours are the 3rd and 5th organs for h = 0.15 r, the 5th and 8th for h = 0.06 r
    // and the 8th and 13th for h = 0.03 r. Counted in the middle third, away from the ends.
    let cylinder = florets("abop-4.04-cylindrical.lsys");
    assert_eq!(cylinder.len(), 100);
    let polar = about_the_axis(&cylinder);
    for k in 1..polar.len() {
        let divergence = (polar[k - 1].0 - polar[k].0).rem_euclid(360.0);
        assert!((divergence - 137.5).abs() < 1e-6, "{divergence} at {k}");
        assert!((polar[k].1 - polar[k - 1].1 - 0.15).abs() < 1e-9);
    }
    assert_eq!(parastichies(&cylinder, 33, 67), (3, 5));
    let pineapple = florets("abop-sec-4.2-pineapple.lsys");
    assert_eq!(pineapple.len(), 110);
    assert_eq!(parastichies(&pineapple, 37, 74), (8, 13));
}

#[test]
fn the_pine_cone_shows_5_and_8_parastichies_where_it_is_widest() {
    // Each scale is placed by its base, the first point of its polygon, on the cone's surface.
    let cone = skeleton("abop-sec-4.2-pine-cone.lsys");
    let scales: Vec<DVec3> = cone.polygons.iter().map(|p| p.points[0]).collect();
    assert_eq!(scales.len(), 90);
    assert_eq!(parastichies(&scales, 30, 60), (5, 8));
}
