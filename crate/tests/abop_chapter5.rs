//! ABOP chapter 5 (models of plant organs): each gallery example of the chapter checked against
//! what its grammar implies and the book states: polygon and leaflet counts by hand count, a leaf's
//! symmetry about its midrib, the compound leaf's pairs of leaflets per step, a flower's whorls
//! (members and the angles 360/n between them), measured on the plant `pipeline::build` draws.

mod shared;

use glam::DVec3;
use meristem::maths;
use meristem::pipeline::{build, Build, BuildOptions};
use meristem::turtle::{Polygon, Surface, SurfaceKind};
use shared::example;

/// The example built at `n` steps (its own `#iterations` when `None`), without a diagnostic.
fn built(name: &str, n: Option<u32>) -> Build {
    let options = BuildOptions {
        iterations: n,
        ..BuildOptions::default()
    };
    let result = build(&example(name), &options);
    assert!(
        result.diagnostics.is_empty(),
        "{name}: {:?}",
        result.diagnostics
    );
    result
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance
}

/// Every polygon point of `polygons` has its mirror image about the plane x = 0 among the points
/// of `others`: a leaf symmetric about its midrib (the turtle's start heading, +Y).
fn assert_mirrored(name: &str, polygons: &[Polygon], others: &[Polygon]) {
    let theirs: Vec<DVec3> = others.iter().flat_map(|p| p.points.clone()).collect();
    for p in polygons.iter().flat_map(|p| &p.points) {
        let mirrored = DVec3::new(-p.x, p.y, p.z);
        assert!(
            theirs.iter().any(|q| (*q - mirrored).length() < 1e-9),
            "{name}: the point {p} has no mirror image on the other half"
        );
    }
}

/// The polygons whose points all lie on the side of x = 0 that `sign` gives (or on it).
fn half(polygons: &[Polygon], sign: f64) -> Vec<Polygon> {
    polygons
        .iter()
        .filter(|p| p.points.iter().all(|q| q.x * sign >= -1e-9))
        .cloned()
        .collect()
}

#[test]
fn fig_5_5_the_cordate_leaf_is_a_fan_of_n_polygons_a_half_mirrored_about_the_midrib() {
    let name = "abop-5.05-cordate-leaf.lsys";
    for n in [5u32, 12, 20] {
        let b = built(name, Some(n));
        // Each rewriting of A (or B) opens one polygon: n a half after n steps.
        assert_eq!(b.derived_text().matches('{').count(), 2 * n as usize);
        let polygons = &b.plant.skeleton.polygons;
        assert_eq!(polygons.len(), 2 * n as usize, "n = {n}");
        // Polygon k of a half joins the end of ray k+1 (its first point), the base (the top of the
        // petiole F(2)) and the end of ray k (its last point). Ray k turns k·δ from the midrib
        // (δ = 10°) and, its chain C written at step k+1 and one G longer at each later step, is
        // n − 1 − k long: the fan's rays shorten away from the midrib, and the blade is a heart.
        let base = DVec3::new(0.0, 2.0, 0.0);
        let ray = |k: f64| (n as f64 - 1.0 - k).max(0.0);
        let mut rays = [Vec::new(), Vec::new()];
        for p in polygons {
            let (first, last) = (p.points[0] - base, *p.points.last().unwrap() - base);
            if last.length() < 1e-9 {
                continue; // the young rays at the fan's edge have no length yet
            }
            let k = (last.angle_between(DVec3::Y).to_degrees() / 10.0).round();
            assert!(close(
                last.angle_between(DVec3::Y).to_degrees(),
                10.0 * k,
                1e-6
            ));
            assert!(close(last.length(), ray(k), 1e-9), "n = {n}: ray {k}");
            assert!(
                close(first.length(), ray(k + 1.0), 1e-9),
                "n = {n}: ray {}",
                k + 1.0
            );
            // The midrib's ray (k = 0) is on both halves: the side is where the polygon lies.
            rays[usize::from(first.x + last.x > 0.0)].push(k as u32);
        }
        for side in &mut rays {
            side.sort();
            assert_eq!(
                *side,
                (0..n - 1).collect::<Vec<_>>(),
                "n = {n}: rays 0 to n − 2"
            );
        }
        let left = half(polygons, -1.0);
        let right = half(polygons, 1.0);
        assert_mirrored(name, &left, &right);
        assert_mirrored(name, &right, &left);
        // The blade's tip is the midrib's ray, n − 1 above the base.
        let top = polygons
            .iter()
            .flat_map(|p| &p.points)
            .map(|p| p.y)
            .fold(0.0, f64::max);
        assert!(close(top, 2.0 + n as f64 - 1.0, 1e-9));
    }
}

#[test]
fn fig_5_8_and_its_variant_the_developmental_leaves_have_two_polygons_a_step_and_a_symmetric_blade()
{
    // (LA, RA) of each example: the midrib is the sum of the main segments, the k-th of them
    // written at step k and grown by RA at every later step: LA·(RA^n − 1)/(RA − 1), or LA·n.
    for (name, la, ra) in [
        ("abop-5.08-rose-leaf.lsys", 5.0, 1.15f64),
        ("abop-sec-5.2-leaf-growth-rates.lsys", 5.0, 1.0),
    ] {
        for n in [6u32, 20] {
            let b = built(name, Some(n));
            let derived = b.derived_text();
            // The axiom opens two polygons; every rewriting of an apex opens one more.
            assert_eq!(derived.matches('{').count(), 2 + 2 * n as usize, "{name}");
            let polygons = &b.plant.skeleton.polygons;
            assert_eq!(polygons.len(), 2 + 2 * n as usize);
            let left = half(polygons, -1.0);
            let right = half(polygons, 1.0);
            assert_eq!(left.len(), right.len(), "{name}: both halves alike");
            assert_mirrored(name, &left, &right);
            assert_mirrored(name, &right, &left);
            let midrib = if ra == 1.0 {
                la * n as f64
            } else {
                la * (ra.powi(n as i32) - 1.0) / (ra - 1.0)
            };
            // The midrib's tip: the highest polygon point on it (a young tooth beside it, pointing
            // 60° from the midrib, may reach higher).
            let tip = polygons
                .iter()
                .flat_map(|p| &p.points)
                .filter(|p| p.x.abs() < 1e-9)
                .map(|p| p.y)
                .fold(0.0, f64::max);
            assert!(close(tip, 2.0 + midrib, 1e-6), "{name} n = {n}: {tip}");
        }
    }
    // The rose leaflet's teeth: up the left margin, each vein's end (a notch) is followed by its
    // tooth's tip (LC, growing at RC), farther from the midrib, then the next notch: the distance
    // from the midrib goes in and out at every vein. Without teeth (LC = 0) it widens, then narrows.
    let turns = |text: &str| {
        let b = build(text, &BuildOptions::default());
        let mut points: Vec<DVec3> = b
            .plant
            .skeleton
            .polygons
            .iter()
            .flat_map(|p| p.points.clone())
            .filter(|p| p.x < -1e-6)
            .collect();
        points.sort_by(|a, b| a.y.total_cmp(&b.y));
        points.dedup_by(|a, b| (*a - *b).length() < 1e-9);
        let steps: Vec<f64> = points
            .windows(2)
            .map(|w| w[0].x.abs() - w[1].x.abs())
            .collect();
        steps.windows(2).filter(|w| w[0] * w[1] < 0.0).count()
    };
    let rose = example("abop-5.08-rose-leaf.lsys");
    assert!(turns(&rose) >= 20, "serrated: {}", turns(&rose));
    let entire = rose.replace("#define LC 3 ", "#define LC 0 ");
    assert_ne!(entire, rose);
    assert!(turns(&entire) <= 2, "entire: {}", turns(&entire));
}

#[test]
fn fig_5_6f_the_simple_leaf_is_one_polygon_of_2n_plus_1_vertices_up_its_midrib() {
    // By hand: the axiom's dot and two vein ends a step give 1 + 2n vertices of one polygon (after
    // the base, which `{` records too: Meristem's polygon starts where it is opened); the
    // midrib's k-th segment, made at step k, has grown to LA·RA^(n−k): the youngest veins' dots,
    // at the apex, stand 1 (the petiole F) + LA·(RA^n − 1)/(RA − 1) high, on the midrib.
    for n in [1u32, 5, 20] {
        let b = built("abop-5.06f-simple-leaf.lsys", Some(n));
        let polygons = &b.plant.skeleton.polygons;
        assert_eq!(polygons.len(), 1, "n = {n}");
        assert_eq!(polygons[0].points.len(), 2 + 2 * n as usize, "n = {n}");
        assert_eq!(
            polygons[0].points[0], polygons[0].points[1],
            "the base twice"
        );
        let midrib = 5.0 * (1.1f64.powi(n as i32) - 1.0) / 0.1;
        let top = polygons[0].points.iter().map(|p| p.y).fold(0.0, f64::max);
        assert!(close(top, 1.0 + midrib, 1e-6), "n = {n}: {top}");
        // Symmetric: the outline goes up the left veins' ends and down the right ones, mirrored.
        let points = &polygons[0].points[1..];
        for k in 1..=n as usize {
            let (left, right) = (points[k], points[points.len() - k]);
            assert!(
                close(left.x, -right.x, 1e-9) && close(left.y, right.y, 1e-9),
                "n = {n}, k = {k}"
            );
        }
    }
}

/// The number of apices after n steps from A(0) with the apical delay `d`, when every apex of age 0
/// makes `laterals` lateral apices a step (2: opposite, Fig 5.11; 1: alternate, Fig 5.12) and goes
/// on: a lateral made at step s waits d steps and grows like the whole from step s + d + 1, so
/// f(n) = f(n − 1) + laterals · f(n − 1 − d), f = 1 up to step 0. With d = 1 and two laterals: the
/// Jacobsthal numbers (2^(n+2) − (−1)^n)/3.
fn apices(n: u32, d: u32, laterals: usize) -> usize {
    let mut f = vec![1usize; (d + 1) as usize]; // f(−d) … f(0)
    for _ in 0..n {
        let next = f[f.len() - 1] + laterals * f[f.len() - 1 - d as usize];
        f.push(next);
    }
    f[f.len() - 1]
}

/// Branches `[` at the top level of `derived`: the laterals on the main axis.
fn top_level_branches(derived: &str) -> usize {
    let mut depth = 0;
    let mut count = 0;
    for c in derived.chars() {
        match c {
            '[' => {
                count += usize::from(depth == 0);
                depth += 1;
            }
            ']' => depth -= 1,
            _ => {}
        }
    }
    count
}

/// Figs 5.11 a–e and 5.12 a–c: (file, D, R, laterals a step on the rachis).
const COMPOUND: [(&str, u32, f64, usize); 8] = [
    ("abop-5.11a-compound-leaf.lsys", 0, 2.0, 2),
    ("abop-5.11b-compound-leaf.lsys", 1, 1.5, 2),
    ("abop-5.11c-compound-leaf.lsys", 2, 1.36, 2),
    ("abop-5.11d-compound-leaf.lsys", 4, 1.23, 2),
    ("abop-5.11e-compound-leaf.lsys", 7, 1.17, 2),
    ("abop-5.12a-compound-leaf-alternate.lsys", 1, 1.36, 1),
    ("abop-5.12b-compound-leaf-alternate.lsys", 4, 1.18, 1),
    ("abop-5.12c-compound-leaf-alternate.lsys", 7, 1.13, 1),
];

#[test]
fn figs_5_11_and_5_12_compound_leaves_have_their_panels_delays_leaflets_and_rachis() {
    // Hand counts of the recurrence: D = 1 with pairs gives the Jacobsthal numbers, D = 0 powers
    // of 3 (every apex makes two more at once), alternate D = 1 the Fibonacci numbers.
    assert_eq!(
        (0..8).map(|n| apices(n, 1, 2)).collect::<Vec<_>>(),
        [1, 3, 5, 11, 21, 43, 85, 171]
    );
    assert_eq!(
        (0..5).map(|n| apices(n, 0, 2)).collect::<Vec<_>>(),
        [1, 3, 9, 27, 81]
    );
    assert_eq!(
        (0..8).map(|n| apices(n, 1, 1)).collect::<Vec<_>>(),
        [1, 2, 3, 5, 8, 13, 21, 34]
    );
    for (name, d, r, laterals) in COMPOUND {
        let text = example(name);
        assert!(text.contains(&format!("#define D {d} ")), "{name}: D");
        assert!(text.contains(&format!("#define R {r} ")), "{name}: R");
        for n in 0..=9 {
            let b = built(name, Some(n));
            let derived = b.derived_text();
            let apices_drawn = derived.matches('A').count() + derived.matches('B').count();
            assert_eq!(apices_drawn, apices(n, d, laterals), "{name} n = {n}");
            // One leaflet (a polygon of the homomorphism) per apex.
            assert_eq!(b.plant.skeleton.polygons.len(), apices(n, d, laterals));
            // The rachis carries `laterals` laterals a step.
            assert_eq!(
                top_level_branches(&derived),
                laterals * n as usize,
                "{name} n = {n}"
            );
            // Its two internodes a step elongate by R a step: 2·(1 + R + … + R^(n−1)).
            let rachis: f64 = b
                .plant
                .skeleton
                .segments
                .iter()
                .filter(|s| s.start.x.abs() < 1e-9 && s.end.x.abs() < 1e-9)
                .map(|s| (s.end - s.start).length())
                .sum();
            let expected = 2.0 * (0..n).map(|k| r.powi(k as i32)).sum::<f64>();
            assert!(close(rachis, expected, 1e-6), "{name} n = {n}: {rachis}");
        }
    }
    // Opposite: the two laterals of a node leave from one point of the rachis; alternate: never.
    let bases = |name: &str| {
        let b = built(name, Some(5));
        let mut points: Vec<(i64, i64)> = b
            .plant
            .skeleton
            .segments
            .iter()
            .filter(|s| s.start.x.abs() < 1e-9 && s.end.x.abs() > 1e-9)
            .map(|s| {
                (
                    (s.start.x * 1e6).round() as i64,
                    (s.start.y * 1e6).round() as i64,
                )
            })
            .collect();
        let all = points.len();
        points.sort();
        points.dedup();
        (all, points.len())
    };
    // A lateral written at step k waits a step (D = 1) and draws at step k + 2: at n = 5 the
    // laterals of steps 1 to 3 have drawn: 3 pairs on the opposite leaf, 3 single ones on the
    // alternate leaf.
    assert_eq!(bases("abop-5.11b-compound-leaf.lsys"), (6, 3));
    assert_eq!(bases("abop-5.12a-compound-leaf-alternate.lsys"), (3, 3));
}

/// A polygon's midline: the unit vector from its first point (the base of a leaf or petal drawn from
/// its base) to the point farthest from it (the tip).
fn midline(p: &Polygon) -> DVec3 {
    let base = p.points[0];
    let far = |q: &&DVec3| (**q - base).length();
    let tip = p
        .points
        .iter()
        .max_by(|a, b| far(a).total_cmp(&far(b)))
        .unwrap();
    (*tip - base).normalize()
}

/// The polygon's outline is symmetric about its midline ([`midline`]): every point has its mirror
/// image.
fn assert_symmetric(what: &str, p: &Polygon) {
    let base = p.points[0];
    let along = midline(p);
    // Newell's normal of the outline.
    let n = p.points.len();
    let normal = (0..n)
        .map(|i| p.points[i].cross(p.points[(i + 1) % n]))
        .sum::<DVec3>()
        .normalize();
    let across = normal.cross(along);
    let local = |q: &DVec3| ((*q - base).dot(along), (*q - base).dot(across));
    for q in &p.points {
        let (a, c) = local(q);
        assert!(
            p.points
                .iter()
                .map(local)
                .any(|(a2, c2)| close(a, a2, 1e-9) && close(c, -c2, 1e-9)),
            "{what}: the point ({a}, {c}) has no mirror image"
        );
    }
}

/// The azimuths (degrees, 0 to 360) of `directions` about `axis`, measured from the first one.
fn azimuths(axis: DVec3, directions: &[DVec3]) -> Vec<f64> {
    let flat: Vec<DVec3> = directions
        .iter()
        .map(|d| (*d - axis * d.dot(axis)).normalize())
        .collect();
    let x = flat[0];
    let y = axis.cross(x);
    flat.iter()
        .map(|d| {
            maths::atan2(d.dot(y), d.dot(x))
                .to_degrees()
                .rem_euclid(360.0)
        })
        .collect()
}

/// Each member stands 360/n after the one before it (either way round the axis).
fn assert_whorl(what: &str, angles: &[f64], n: usize) {
    assert_eq!(angles.len(), n, "{what}: members");
    let step = 360.0 / n as f64;
    let sense = if close(angles[1], step, 1e-6) {
        1.0
    } else {
        -1.0
    };
    for (k, a) in angles.iter().enumerate() {
        let expected = (sense * step * k as f64).rem_euclid(360.0);
        let d = (a - expected + 180.0).rem_euclid(360.0) - 180.0;
        assert!(
            d.abs() < 1e-6,
            "{what}: member {k} at {a}°, not {expected}°"
        );
    }
}

/// The plant's predefined surfaces of one kind (`~l` or `~p`), in the order drawn.
fn surfaces(b: &Build, kind: SurfaceKind) -> Vec<&Surface> {
    let all = b.plant.skeleton.surfaces.iter();
    all.filter(|s| s.kind == kind).collect()
}

/// The flower's axis: the heading of the segment drawn before its first organ of `kind`.
fn flower_axis(b: &Build, first_organ: DVec3) -> DVec3 {
    let s = b
        .plant
        .skeleton
        .segments
        .iter()
        .find(|s| (s.end - first_organ).length() < 1e-9)
        .expect("the flower sits at the end of a segment");
    (s.end - s.start).normalize()
}

#[test]
fn the_lily_has_three_sepals_and_three_petals_120_degrees_apart_petals_between_sepals() {
    let b = built("abop-sec-5.1-lily.lsys", None);
    let skeleton = &b.plant.skeleton;
    let tepals = surfaces(&b, SurfaceKind::Petal);
    assert_eq!(tepals.len(), 6, "3 sepals + 3 petals");
    assert_eq!(surfaces(&b, SurfaceKind::Leaf).len(), 7, "#define LEAVES 7");
    let axis = flower_axis(&b, tepals[0].origin);
    let headings: Vec<DVec3> = tepals.iter().map(|s| s.heading).collect();
    let angles = azimuths(axis, &headings);
    assert_whorl("sepals", &angles[..3], 3);
    let petals: Vec<f64> = angles[3..].iter().map(|a| a - angles[3]).collect();
    assert_whorl("petals", &petals, 3);
    // The petals stand between the sepals: 180/N = 60° from them.
    let offset = (angles[3] - angles[0]).rem_euclid(120.0);
    assert!(
        close(offset, 60.0, 1e-6),
        "petals {offset}° from the sepals"
    );
    // Every tepal opens OPEN (60°) or OPEN − 8 from the flower's axis.
    for (k, h) in headings.iter().enumerate() {
        let open = h.angle_between(axis).to_degrees();
        assert!(close(open, if k < 3 { 60.0 } else { 52.0 }, 1e-6), "{open}");
    }
    // Six stamens, each with an anther: the orange spheres (colour 9).
    assert_eq!(skeleton.spheres.iter().filter(|s| s.color == 9).count(), 6);
}

#[test]
fn the_bellflower_has_five_sepals_and_five_polygon_petals_72_degrees_apart() {
    let b = built("abop-sec-5.1-campanula.lsys", None);
    let skeleton = &b.plant.skeleton;
    let sepals = surfaces(&b, SurfaceKind::Leaf);
    assert_eq!(sepals.len(), 5);
    let petals: Vec<_> = skeleton.polygons.iter().filter(|p| p.color == 13).collect();
    assert_eq!(petals.len(), 5);
    // The stem's leaves are ABOP's outline, in green (entry 4).
    let leaves: Vec<_> = skeleton.polygons.iter().filter(|p| p.color != 13).collect();
    assert_eq!(leaves.len(), 4);
    assert!(leaves.iter().all(|p| p.color == 4));
    let axis = flower_axis(&b, sepals[0].origin);
    // The pedicel bends down: the flower nods.
    assert!(axis.y < 0.0, "the bell hangs: axis {axis}");
    let sepal_angles = azimuths(axis, &sepals.iter().map(|s| s.heading).collect::<Vec<_>>());
    assert_whorl("sepals", &sepal_angles, 5);
    // A petal's direction: from its base to the lobe's tip.
    let petal_directions: Vec<DVec3> = petals.iter().map(|p| midline(p)).collect();
    let mut all = vec![sepals[0].heading];
    all.extend(&petal_directions);
    let angles = azimuths(axis, &all);
    let petals_only: Vec<f64> = angles[1..].iter().map(|a| a - angles[1]).collect();
    assert_whorl("petals", &petals_only, 5);
    // The petals stand between the sepals, 36° from them.
    assert!(
        close(angles[1].rem_euclid(72.0), 36.0, 1e-6),
        "{}",
        angles[1]
    );
    // Each petal is symmetric about its midline (base to tip): every point has its mirror image.
    for p in &petals {
        assert_symmetric("a petal", p);
    }
}

#[test]
fn polygon_leaves_traced_by_the_outline_or_by_dots_are_symmetric_and_green() {
    let b = built("abop-sec-5.1-polygon-leaves.lsys", None);
    let polygons = &b.plant.skeleton.polygons;
    // A node's two leaves are written at one step and drawn from the next: n − 1 nodes at n = 6.
    assert_eq!(polygons.len(), 2 * 5);
    for (k, p) in polygons.iter().enumerate() {
        // L, ABOP's outline: { and six f (the last back at the start); M: { . then eight dots.
        let (expected, what) = if k % 2 == 0 { (7, "L") } else { (9, "M") };
        assert_eq!(p.points.len(), expected, "{what}");
        assert_symmetric(what, p);
        // No colour on their path: leaf green.
        assert_eq!(p.color, 5, "{what}");
    }
    assert!(b.plant.skeleton.segments.iter().all(|s| s.color == 0));
}

#[test]
fn the_herb_grows_one_leaf_a_step_each_a_ray_wider_a_step() {
    let name = "abop-sec-5.2-herb-with-cordate-leaves.lsys";
    for n in [4u32, 10, 16] {
        let b = built(name, Some(n));
        // The leaf of step k opens its fan at step k + 2 and adds a polygon a half at every later
        // step: n − k − 1 a half, (n − 1)(n − 2) in all.
        let expected = ((n - 1) * (n - 2)) as usize;
        assert_eq!(b.derived_text().matches('{').count(), expected, "n = {n}");
        assert_eq!(b.plant.skeleton.polygons.len(), expected, "n = {n}");
        assert_eq!(
            b.plant.skeleton.segments.len(),
            n as usize + n as usize - 1,
            "n = {n}: internodes and petioles"
        );
    }
}
