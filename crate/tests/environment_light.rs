//! The light program (crate/src/environment/light/) driven directly with parts and probes, as the
//! environment's cycle drives it between derivation steps: a wall's shadow, a canopy's layers,
//! a bud at its segment's tip, the grid's budget, and its settings' errors.

use meristem::environment::light::Light;
use meristem::environment::{Part, Probe, Responder, MAX_ENVIRONMENT_BYTES};
use meristem::model::{ProgramSpec, SettingValue};
use meristem::vocabulary::EnvironmentProgram;

/// An `#environment light …` line as the resolver gives it: each setting at its own span.
fn spec(settings: &[(&'static str, &[f64])]) -> ProgramSpec {
    ProgramSpec {
        program: EnvironmentProgram::Light,
        shape: None,
        settings: settings
            .iter()
            .enumerate()
            .map(|(i, (name, values))| SettingValue {
                name,
                values: values.to_vec(),
                span: 100 + 10 * i..105 + 10 * i,
            })
            .collect(),
        span: 0..200,
    }
}

fn light(settings: &[(&'static str, &[f64])]) -> Light {
    Light::new(&spec(settings), 1.0).expect("the settings are good")
}

fn segment(from: [f64; 3], to: [f64; 3]) -> Part {
    Part {
        from,
        to,
        radius: 0.05,
        area: 0.0,
        plant: 0,
    }
}

/// Each probe's reply: exposure, dx, dy, dz.
fn replies(light: &mut Light, points: &[[f64; 3]]) -> Vec<[f64; 4]> {
    let probes: Vec<Probe<'_>> = points
        .iter()
        .map(|&position| Probe {
            position,
            heading: [0.0, 1.0, 0.0],
            up: [0.0, 0.0, 1.0],
            args: &[],
            plant: 0,
        })
        .collect();
    // Stride 6, offset 1: as the cycle writes replies among other programs'.
    let mut out = vec![f64::NAN; 6 * points.len()];
    light.answer(&probes, &mut out, 6, 1);
    out.chunks(6).map(|c| [c[1], c[2], c[3], c[4]]).collect()
}

/// A wall of vertical segments in the plane x = 0.5 (so in the voxels x = 0..1), 2 a voxel, from
/// y = 0 to 10 and z = −6 to 6.
fn wall() -> Vec<Part> {
    let mut parts = Vec::new();
    for y in 0..10 {
        for z in -12..12 {
            let z = f64::from(z) * 0.5 + 0.25;
            parts.push(segment(
                [0.5, f64::from(y), z],
                [0.5, f64::from(y) + 1.0, z],
            ));
        }
    }
    parts
}

/// The replies at `points` of a light with the sun low along `toward` (its beam stopped 90% by
/// each part) over `parts`.
fn low_sun(toward: [f64; 3], parts: &[Part], points: &[[f64; 3]]) -> Vec<[f64; 4]> {
    let mut light = light(&[
        ("sun", &[1.0]),
        ("sun_direction", &toward),
        ("absorb", &[0.9]),
    ]);
    light.update(parts, MAX_ENVIRONMENT_BYTES).unwrap();
    replies(&mut light, points)
}

#[test]
fn a_probe_behind_a_wall_from_a_low_sun_reads_less_and_its_light_points_away() {
    let r = low_sun(
        [1.0, 0.4, 0.0],
        &wall(),
        &[[3.5, 4.5, 0.25], [-2.5, 4.5, 0.25]],
    );
    let [lit, shaded] = [r[0], r[1]];
    // The same distance from the wall (3 voxels), so the same sky; the sun's beam crosses the
    // wall's two parts a voxel (one forgiven) on the far side: direct light 0.1 there, 1 here.
    assert!(lit[0] - shaded[0] > 0.4, "lit {lit:?}, shaded {shaded:?}");
    assert!(lit[0] > 0.9 && lit[0] <= 1.0, "{lit:?}");
    assert!(
        lit[1] > 0.3,
        "the lit side's light comes from +x, away from the wall: {lit:?}"
    );
    assert!(
        shaded[1] < -0.05,
        "the far side's light comes from −x, away from the wall: {shaded:?}"
    );
    for r in [lit, shaded] {
        let length = (r[1] * r[1] + r[2] * r[2] + r[3] * r[3]).sqrt();
        assert!((length - 1.0).abs() < 1e-9 && r[2] > 0.0, "{r:?}");
    }
}

#[test]
fn the_wall_casts_the_same_shadow_whichever_axis_the_sun_comes_along() {
    // The wall turned a quarter about y (in the plane z = 0.5) with the sun from +z, and mirrored
    // (the sun from −x): the same numbers as from +x, by the same sweep along another axis.
    let moved = |f: fn([f64; 3]) -> [f64; 3]| -> Vec<Part> {
        wall().iter().map(|p| segment(f(p.from), f(p.to))).collect()
    };
    let points = [[3.5, 4.5, 0.25], [-2.5, 4.5, 0.25]];
    let x = low_sun([1.0, 0.4, 0.0], &wall(), &points);
    let z = low_sun([0.0, 0.4, 1.0], &moved(swap_xz), &points.map(swap_xz));
    let m = low_sun([-1.0, 0.4, 0.0], &moved(mirror_x), &points.map(mirror_x));
    for i in 0..2 {
        assert!(
            (x[i][0] - z[i][0]).abs() < 1e-6 && (x[i][1] - z[i][3]).abs() < 1e-6,
            "{x:?} {z:?}"
        );
        assert!(
            (x[i][0] - m[i][0]).abs() < 1e-6 && (x[i][1] + m[i][1]).abs() < 1e-6,
            "{x:?} {m:?}"
        );
    }
}

fn swap_xz([x, y, z]: [f64; 3]) -> [f64; 3] {
    [z, y, x]
}

/// Mirrored about x = 0.5 (the wall's plane), so that voxels map onto voxels.
fn mirror_x([x, y, z]: [f64; 3]) -> [f64; 3] {
    [1.0 - x, y, z]
}

/// A closed canopy: `layers` layers of 31 × 31 leaves, one a voxel, the lowest at y = 10.
fn canopy(layers: usize) -> Vec<Part> {
    let mut parts = Vec::new();
    for layer in 0..layers {
        for x in -15..=15 {
            for z in -15..=15 {
                let at = [f64::from(x) + 0.5, 10.5 + layer as f64, f64::from(z) + 0.5];
                parts.push(Part {
                    from: at,
                    to: at,
                    radius: 0.0,
                    area: 0.5,
                    plant: 0,
                });
            }
        }
    }
    parts
}

#[test]
fn under_a_canopy_each_more_layer_is_darker_and_beside_it_the_sky_is_open() {
    let under = [0.5, 9.5, 0.5];
    let beside = [40.5, 9.5, 0.5];
    let mut previous = 1.0;
    for layers in 1..=6 {
        let mut light = light(&[]);
        light
            .update(&canopy(layers), MAX_ENVIRONMENT_BYTES)
            .unwrap();
        let r = replies(&mut light, &[under, beside, [0.5, 30.0, 0.5]]);
        assert!(
            r[0][0] < previous - 0.05,
            "{layers} layers: {} after {previous}",
            r[0][0]
        );
        previous = r[0][0];
        assert_eq!(r[1][0], 1.0, "beside the canopy");
        assert_eq!(r[2][0], 1.0, "above it");
        assert_eq!(
            r[2][1..],
            [0.0, 1.0, 0.0],
            "above it the light comes from straight up"
        );
        // Under the middle of a wide canopy the light is darkest straight up: it points up, little aside.
        assert!(r[0][2] > 0.9, "{:?}", r[0]);
    }
    // Under its edge (x = 15) the light comes from the open side.
    let mut three = light(&[]);
    three.update(&canopy(3), MAX_ENVIRONMENT_BYTES).unwrap();
    let edge = replies(&mut three, &[[14.5, 9.5, 0.5], [0.5, 9.5, 0.5]]);
    assert!(
        edge[0][0] > edge[1][0] + 0.05 && edge[0][1] > 0.5,
        "{edge:?}"
    );
    // The module doc's numbers: under one closed layer, (C − 9 × 1/2 + 1) / C with C = 31.2.
    let mut one = light(&[]);
    one.update(&canopy(1), MAX_ENVIRONMENT_BYTES).unwrap();
    let full: f64 = (1..=8)
        .map(|q| f64::from(2 * q + 1).powi(2) / 2f64.powi(q))
        .sum();
    let r = replies(&mut one, &[under]);
    assert!(
        (r[0][0] - (full - 4.5 + 1.0) / full).abs() < 1e-6,
        "{}",
        r[0][0]
    );
    // Six layers and the sun overhead: its beam crosses six parts, one forgiven.
    let mut sunny = light(&[("sky", &[0.0]), ("sun", &[1.0])]);
    sunny.update(&canopy(6), MAX_ENVIRONMENT_BYTES).unwrap();
    let r = replies(&mut sunny, &[under, [0.5, -30.0, 0.5]]);
    assert!((r[0][0] - 0.5f64.powi(5)).abs() < 1e-6, "{r:?}");
    assert!(
        (r[1][0] - 0.5f64.powi(5)).abs() < 1e-6,
        "far below, outside the grid: {r:?}"
    );
}

#[test]
fn a_bud_at_its_segments_tip_is_not_in_its_own_shadow() {
    let sun = &[("sun", &[1.0][..]), ("sun_direction", &[0.3, 1.0, 0.2][..])];
    for (from, to) in [
        ([0.3, 0.2, 0.4], [0.3, 1.2, 0.4]), // up, into the voxel above
        ([0.5, 1.8, 0.5], [0.5, 0.8, 0.5]), // hanging down into the voxel below
        ([0.1, 0.5, 0.5], [0.9, 0.5, 0.5]), // across, in one voxel
        ([0.5, 1.5, 0.5], [1.3, 0.7, 1.2]), // down and aside, into the voxel below and beside
        ([1.5, 1.5, 0.5], [0.7, 0.7, 0.5]), // down and towards −x, away from the sun
    ] {
        let mut light = light(sun);
        light
            .update(&[segment(from, to)], MAX_ENVIRONMENT_BYTES)
            .unwrap();
        let r = replies(&mut light, &[to]);
        assert_eq!(
            r[0][0], 1.0,
            "a segment {from:?} → {to:?} shades its tip: {r:?}"
        );
    }
    // But the tip of a chain of ten segments hanging under the sun is in the nine others' shadow.
    let chain: Vec<Part> = (0..10)
        .map(|y| {
            segment(
                [0.5, 10.5 - f64::from(y), 0.5],
                [0.5, 9.5 - f64::from(y), 0.5],
            )
        })
        .collect();
    let mut light = light(&[("sun", &[1.0])]);
    light.update(&chain, MAX_ENVIRONMENT_BYTES).unwrap();
    assert!(replies(&mut light, &[[0.5, 0.5, 0.5]])[0][0] < 0.7);
}

#[test]
fn a_grid_over_the_budget_is_refused_before_it_is_allocated() {
    // Cells of 1/1024 (a binary fraction: whole numbers of cells exactly).
    let mut light = Light::new(&spec(&[("cell", &[1.0 / 1024.0])]), 1.0).unwrap();
    let tree = [
        segment([0.0, 0.0, 0.0], [0.0, 10.0, 0.0]),
        segment([0.0, 10.0, 0.0], [5.0, 12.0, 3.0]),
    ];
    let exceeded = light.update(&tree, MAX_ENVIRONMENT_BYTES).unwrap_err();
    assert!(
        exceeded
            .what
            .starts_with("a light grid of 5137 × 12298 × 3089 voxels"),
        "{}",
        exceeded.what
    );
    assert!(exceeded.bytes > MAX_ENVIRONMENT_BYTES);
    assert_eq!(light.bytes(), 0, "nothing allocated");
    assert_eq!(light.dims(), [0, 0, 0]);
    // The same plant in cells of 1 fits, and a later update over the budget leaves no stale grid.
    let mut light = light_with_cell(1.0);
    light.update(&tree, MAX_ENVIRONMENT_BYTES).unwrap();
    assert!(light.bytes() > 0 && light.bytes() < 1 << 20);
    assert!(light.update(&tree, 1000).is_err());
    assert!(light.field().is_none());
    assert_eq!(replies(&mut light, &[[0.0, 5.0, 0.0]])[0][0], 1.0);
}

fn light_with_cell(cell: f64) -> Light {
    Light::new(&spec(&[("cell", &[cell])]), 1.0).unwrap()
}

#[test]
fn replies_are_the_same_for_the_same_parts_whatever_came_before() {
    let mut light = light(&[("sun", &[2.0]), ("sun_direction", &[0.5, 1.0, -0.3])]);
    let points = [[0.5, 9.5, 0.5], [3.2, 11.0, -4.0], [20.0, 0.0, 0.0]];
    light.update(&canopy(2), MAX_ENVIRONMENT_BYTES).unwrap();
    let first = replies(&mut light, &points);
    let field = light.field().unwrap();
    light.update(&wall(), MAX_ENVIRONMENT_BYTES).unwrap();
    assert_ne!(replies(&mut light, &points), first);
    light.update(&canopy(2), MAX_ENVIRONMENT_BYTES).unwrap();
    assert_eq!(replies(&mut light, &points), first);
    assert_eq!(light.field().unwrap(), field);
}

#[test]
fn the_field_is_the_exposure_a_probe_reads_in_each_voxel() {
    let mut light = light(&[("sun", &[1.0]), ("sun_direction", &[0.2, 1.0, 0.1])]);
    light.update(&canopy(3), MAX_ENVIRONMENT_BYTES).unwrap();
    let field = light.field().unwrap();
    // 31 leaves and 8 voxels of margin each side; 8 layers below the canopy's 3 and one above.
    assert_eq!(field.dims, [47, 12, 47]);
    assert_eq!(field.origin, [-23.0, 2.0, -23.0]);
    assert_eq!(field.values.len(), 47 * 12 * 47);
    for (i, j, k) in [(23, 7, 23), (5, 0, 40), (30, 11, 23), (23, 8, 23)] {
        let centre = [i, j, k].map(|c| c as f64 + 0.5);
        let p = [0, 1, 2].map(|a| field.origin[a] + centre[a] * field.cell);
        let value = field.values[i + 47 * (j + 12 * k)];
        assert_eq!(
            value,
            replies(&mut light, &[p])[0][0] as f32,
            "voxel ({i}, {j}, {k})"
        );
    }
}

#[test]
fn settings_out_of_range_are_errors_at_the_setting() {
    let cases: &[(&str, &[f64], &str)] = &[
        ("cell", &[0.0], "above 0"),
        ("depth", &[0.0], "from 1 to 64"),
        ("depth", &[65.0], "from 1 to 64"),
        ("depth", &[2.5], "whole"),
        ("spread", &[0.5], "from 1 up"),
        ("shadow", &[-1.0], "from 0 up"),
        ("absorb", &[1.5], "from 0 to 1"),
        ("sky", &[f64::INFINITY], "from 0 up"),
        ("sun_direction", &[0.0, 0.0, 0.0], "not all 0"),
    ];
    for &(name, values, says) in cases {
        let error = Light::new(&spec(&[("sky", &[1.0]), (name, values)]), 1.0).unwrap_err();
        assert_eq!(error.span, 110..115, "{name}: {error:?}");
        assert!(error.message.contains(says), "{name}: {}", error.message);
    }
    let dark = Light::new(&spec(&[("sky", &[0.0])]), 1.0).unwrap_err();
    assert!(dark.message.contains("both 0"), "{}", dark.message);
    let no_step = Light::new(&spec(&[]), 0.0).unwrap_err();
    assert!(
        no_step.message.contains("not written"),
        "{}",
        no_step.message
    );
    assert!(Light::new(
        &spec(&[("depth", &[64.0]), ("absorb", &[1.0]), ("spread", &[1.0])]),
        1.0
    )
    .is_ok());
}

#[test]
fn no_parts_odd_numbers_and_far_points_give_replies_never_a_panic() {
    let mut light = light(&[("sun", &[1.0]), ("sun_direction", &[0.3, 1.0, 0.2])]);
    let nan = [f64::NAN, 0.0, 0.0];
    let far = [1e300, -1e300, 0.0];
    for parts in [
        vec![],
        vec![segment(nan, [0.0; 3])],
        vec![segment(far, far)],
    ] {
        light.update(&parts, MAX_ENVIRONMENT_BYTES).unwrap();
        for r in replies(&mut light, &[[0.0; 3], nan, far, [f64::INFINITY; 3]]) {
            assert!(r.iter().all(|x| x.is_finite()), "{parts:?}: {r:?}");
            assert!((0.0..=1.0).contains(&r[0]), "{r:?}");
        }
    }
    assert!(light
        .update(&[segment(far, far)], MAX_ENVIRONMENT_BYTES)
        .is_ok());
    // A part far out and one at the origin: a grid the budget refuses, measured without overflow.
    let apart = [segment([0.0; 3], [0.0, 1.0, 0.0]), segment(far, far)];
    let exceeded = light.update(&apart, MAX_ENVIRONMENT_BYTES).unwrap_err();
    assert!(exceeded.bytes > MAX_ENVIRONMENT_BYTES, "{exceeded:?}");
    // A grid of one voxel's parts, and probes around it.
    light
        .update(
            &[segment([0.2, 0.2, 0.2], [0.3, 0.3, 0.3])],
            MAX_ENVIRONMENT_BYTES,
        )
        .unwrap();
    assert_eq!(light.dims(), [17, 10, 17]);
    let r = replies(
        &mut light,
        &[[0.5, -0.5, 0.5], [0.5, -8.5, 0.5], [0.5, -9.5, 0.5]],
    );
    assert!(
        r.iter().all(|r| r[0] == 1.0),
        "one part shades no one: {r:?}"
    );
}
