//! The whole mesh of small skeletons: tubes, joints, chains, caps, uvs, flats, spheres, ranges.

use super::chains::chains;
use super::*;
use crate::maths;
use crate::turtle::Skeleton;
use crate::turtle::{Polygon, Segment, Sphere};
use glam::DVec3;

/// Vertices of a rounded tube end with 8 sides: 3 rings of 8 and the apex.
const DOME: usize = 3 * 8 + 1;

fn segment(start: DVec3, end: DVec3, previous: Option<u32>) -> Segment {
    Segment {
        start,
        end,
        left: DVec3::NEG_X,
        up: DVec3::Z,
        width: 1.0,
        color: 0,
        module: 0,
        previous,
        smooth: false,
        anchor: previous,
    }
}

fn absolute(unit: f64) -> MeshOptions {
    MeshOptions {
        sides: 8,
        width_unit: WidthUnit::Absolute(unit),
        ..MeshOptions::default()
    }
}

/// A polygon with no anchor.
fn polygon(points: Vec<DVec3>, color: u16, module: u32) -> Polygon {
    Polygon {
        points,
        color,
        module,
        anchor: None,
    }
}

/// A sphere of radius 1 at the origin, with no anchor.
fn unit_sphere(color: u16, module: u32) -> Sphere {
    Sphere {
        center: DVec3::ZERO,
        radius: 1.0,
        radius_width: None,
        color,
        module,
        anchor: None,
    }
}

/// The chains of `skeleton` as a list of lists, to compare.
fn chain_lists(skeleton: &Skeleton, unit: f64) -> Vec<Vec<u32>> {
    chains(skeleton, unit).iter().map(<[u32]>::to_vec).collect()
}

/// The mesh of `skeleton` with 8 sides and widths in units of 0.1, checked for consistency.
fn checked_mesh(skeleton: &Skeleton) -> MeshBuffers {
    let mesh = build_mesh(skeleton, &absolute(0.1));
    assert_eq!(mesh.check(), Ok(()));
    mesh
}

#[test]
fn a_segment_is_a_capped_tube() {
    let skeleton = Skeleton {
        segments: vec![segment(DVec3::ZERO, DVec3::Y, None)],
        ..Skeleton::default()
    };
    let mesh = build_mesh(&skeleton, &absolute(0.2));
    // Two rings of 8 + 1 (the seam's copy), and two caps of 8 + 1 vertices; 16 side
    // triangles and 8 per cap.
    assert_eq!(mesh.vertex_count(), 18 + 18);
    assert_eq!(mesh.triangle_count(), 16 + 16);
    assert_eq!(mesh.check(), Ok(()));
    let [min, max] = mesh.bounds();
    assert!((max[0] - 0.1).abs() < 1e-6 && min[1].abs() < 1e-6 && (max[1] - 1.0).abs() < 1e-6);
}

#[test]
fn an_axis_shares_its_joints() {
    // Three segments of one axis with turns: one tube of four rings, not three tubes.
    let a = DVec3::ZERO;
    let b = DVec3::Y;
    let c = DVec3::new(-0.3, 1.9, 0.0);
    let d = DVec3::new(-0.4, 2.9, 0.0);
    let skeleton = Skeleton {
        segments: vec![
            segment(a, b, None),
            segment(b, c, Some(0)),
            segment(c, d, Some(1)),
        ],
        ..Skeleton::default()
    };
    let mesh = checked_mesh(&skeleton);
    assert_eq!(mesh.vertex_count(), 4 * 9 + 2 * 9);
    // The joint ring at b is the bisector's: its vertices are all at distance 0.05 from b.
    let ring = (9..18).map(|v| {
        DVec3::new(
            mesh.positions[v * 3] as f64,
            mesh.positions[v * 3 + 1] as f64,
            mesh.positions[v * 3 + 2] as f64,
        )
    });
    for p in ring {
        assert!(((p - b).length() - 0.05).abs() < 1e-6);
    }
}

#[test]
fn tube_uvs_go_round_once_with_a_seam_and_grow_along_the_axis_in_circumferences() {
    let (a, b, c) = (DVec3::ZERO, DVec3::Y, DVec3::new(0.0, 2.0, 0.0));
    let skeleton = Skeleton {
        segments: vec![segment(a, b, None), segment(b, c, Some(0))],
        ..Skeleton::default()
    };
    let mesh = checked_mesh(&skeleton);
    let uv = |v: usize| (mesh.uvs[2 * v], mesh.uvs[2 * v + 1]);
    let circumference = std::f64::consts::PI * 0.1;
    for ring in 0..3 {
        // u from 0 to 1 in 8 steps; the seam's two vertices share a position.
        for j in 0..=8 {
            let (u, v) = uv(ring * 9 + j);
            assert!((u - j as f32 / 8.0).abs() < 1e-6);
            assert!((v as f64 - ring as f64 / circumference).abs() < 1e-3, "{v}");
        }
        let p = |v: usize| &mesh.positions[3 * v..3 * v + 3];
        assert_eq!(p(ring * 9), p(ring * 9 + 8));
    }
    // Continuous around the tube: no side triangle (after the start cap's 8) spans the seam
    // backwards.
    for t in mesh.indices[3 * 8..3 * (8 + 32)].chunks_exact(3) {
        let us: Vec<f32> = t.iter().map(|&i| uv(i as usize).0).collect();
        let spread = us.iter().cloned().fold(f32::MIN, f32::max)
            - us.iter().cloned().fold(f32::MAX, f32::min);
        assert!(spread <= 1.0 / 8.0 + 1e-6);
    }
    assert!(mesh
        .triangle_materials()
        .iter()
        .all(|&m| m as u32 == MATERIAL_BARK));
}

#[test]
fn leaves_polygons_and_spheres_have_uvs_in_the_unit_square_and_their_materials() {
    let skeleton = Skeleton {
        polygons: vec![polygon(
            vec![DVec3::ZERO, DVec3::X, DVec3::new(0.5, 2.0, 0.0)],
            0,
            0,
        )],
        surfaces: vec![crate::turtle::Surface {
            kind: crate::turtle::SurfaceKind::Leaf,
            origin: DVec3::ZERO,
            heading: DVec3::Y,
            left: DVec3::NEG_X,
            up: DVec3::Z,
            scale: DVec3::ONE,
            color: 0,
            module: 1,
            anchor: None,
        }],
        spheres: vec![unit_sphere(0, 2)],
        ..Skeleton::default()
    };
    let mesh = checked_mesh(&skeleton);
    assert!(mesh.uvs.iter().all(|x| (0.0..=1.0).contains(x)));
    let materials = mesh.triangle_materials();
    assert!(materials.contains(&(MATERIAL_LEAF as u8)));
    assert_eq!(*materials.last().unwrap(), MATERIAL_PLAIN as u8);
    // The polygon's tip (farthest from its first point) is at the top of the leaf image's opaque
    // band, its base at the bottom: the image cuts nothing off the polygon's own outline.
    let (v0, v1) = crate::mesh::build::POLYGON_V;
    assert_eq!(mesh.uvs[1], v0);
    assert_eq!(mesh.uvs[5], v1);
}

#[test]
fn without_tubes_only_leaves_polygons_and_spheres_are_meshed() {
    let mut skeleton = Skeleton {
        segments: vec![
            segment(DVec3::ZERO, DVec3::Y, None),
            segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0)),
        ],
        polygons: vec![polygon(
            vec![DVec3::ZERO, DVec3::X, DVec3::new(0.5, 2.0, 0.0)],
            0,
            5,
        )],
        spheres: vec![unit_sphere(0, 6)],
        ..Skeleton::default()
    };
    let no_tubes = MeshOptions {
        tubes: false,
        ..absolute(0.1)
    };
    let mesh = build_mesh(&skeleton, &no_tubes);
    mesh.check().expect("a valid mesh");
    assert!(!mesh.triangle_materials().contains(&(MATERIAL_BARK as u8)));
    // The very triangles of the polygon and the sphere of the whole mesh, without the tubes.
    let whole = build_mesh(&skeleton, &absolute(0.1));
    assert!(whole.triangle_materials().contains(&(MATERIAL_BARK as u8)));
    skeleton.segments.clear();
    assert_eq!(mesh, build_mesh(&skeleton, &absolute(0.1)));
}

#[test]
fn a_branch_from_a_joint_has_no_start_cap() {
    // F[+F]: the branch starts at the end of the first segment, inside its tube.
    let mut branch = segment(DVec3::Y, DVec3::new(-0.7, 1.7, 0.0), None);
    branch.module = 3;
    let skeleton = Skeleton {
        segments: vec![segment(DVec3::ZERO, DVec3::Y, None), branch],
        ..Skeleton::default()
    };
    let mesh = checked_mesh(&skeleton);
    // The first tube's end, where the branch leaves it, is rounded (DOME: 3 rings of 8 and
    // the apex), not a flat stump; the branch's own tip is a flat cap.
    assert_eq!(mesh.vertex_count(), (18 + 9 + DOME) + (18 + 9));
}

#[test]
fn a_sharp_turn_or_a_zero_width_breaks_the_axis() {
    let skeleton = Skeleton {
        segments: vec![
            segment(DVec3::ZERO, DVec3::Y, None),
            segment(DVec3::Y, DVec3::ZERO, Some(0)),
        ],
        ..Skeleton::default()
    };
    assert_eq!(chain_lists(&skeleton, 0.1), vec![vec![0], vec![1]]);
    let mut thin = segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0));
    thin.width = 0.0;
    let skeleton = Skeleton {
        segments: vec![segment(DVec3::ZERO, DVec3::Y, None), thin],
        ..Skeleton::default()
    };
    assert_eq!(chain_lists(&skeleton, 0.1), vec![vec![0]]);
    assert_eq!(build_mesh(&skeleton, &absolute(0.1)).check(), Ok(()));
}

#[test]
fn a_wide_tube_at_a_bend_of_short_segments_breaks_instead_of_turning_inside_out() {
    // Width 40 at unit 0.1 is a radius of 2; a bend of 80° tilts the joint ring by 40°, so
    // it reaches 2 × sin 40° ≈ 1.29 along each segment: past the middle of a 0.3-long one.
    let turned = DVec3::new(
        -maths::sin(80f64.to_radians()),
        1.0 + maths::cos(80f64.to_radians()),
        0.0,
    );
    let mut segments = vec![
        segment(DVec3::ZERO, DVec3::Y, None),
        segment(DVec3::Y, DVec3::Y + (turned - DVec3::Y) * 0.3, Some(0)),
    ];
    segments.iter_mut().for_each(|s| s.width = 40.0);
    let skeleton = Skeleton {
        segments,
        ..Skeleton::default()
    };
    assert_eq!(chain_lists(&skeleton, 0.1), vec![vec![0], vec![1]]);
    assert_eq!(build_mesh(&skeleton, &absolute(0.1)).check(), Ok(()));
    // Thin enough, the same bend shares its joint.
    assert_eq!(chain_lists(&skeleton, 0.001), vec![vec![0, 1]]);
    assert_eq!(build_mesh(&skeleton, &absolute(0.001)).check(), Ok(()));
}

#[test]
fn smooth_axes_have_rings_between_the_joints() {
    let mut segments = vec![
        segment(DVec3::ZERO, DVec3::Y, None),
        segment(DVec3::Y, DVec3::new(0.5, 1.8, 0.0), Some(0)),
        segment(
            DVec3::new(0.5, 1.8, 0.0),
            DVec3::new(1.2, 2.3, 0.0),
            Some(1),
        ),
    ];
    for s in &mut segments {
        s.smooth = true;
    }
    let skeleton = Skeleton {
        segments,
        ..Skeleton::default()
    };
    let mesh = build_mesh(
        &skeleton,
        &MeshOptions {
            smooth_samples: 5,
            ..absolute(0.1)
        },
    );
    assert_eq!(mesh.vertex_count(), (3 * 5 + 1) * 9 + 2 * 9);
    assert_eq!(mesh.check(), Ok(()));
}

#[test]
fn polygons_are_two_sided_and_spheres_closed() {
    let square = vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y];
    let skeleton = Skeleton {
        polygons: vec![polygon(square, 3, 7)],
        spheres: vec![unit_sphere(0, 9)],
        ..Skeleton::default()
    };
    let mesh = build_mesh(&skeleton, &MeshOptions::default());
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(
        &mesh.ranges[..4],
        &[0, 7, 4, 9],
        "the square's 2 + 2 triangles, then the sphere"
    );
    // The square's front faces +Z, its back −Z.
    assert_eq!(&mesh.normals[..3], &[0.0, 0.0, 1.0]);
    assert_eq!(&mesh.normals[12..15], &[0.0, 0.0, -1.0]);
}

#[test]
fn huge_models_fall_back_to_lines() {
    let skeleton = Skeleton {
        segments: (0..100)
            .map(|i| {
                segment(
                    DVec3::new(i as f64, 0.0, 0.0),
                    DVec3::new(i as f64, 1.0, 0.0),
                    None,
                )
            })
            .collect(),
        ..Skeleton::default()
    };
    let mesh = build_mesh(
        &skeleton,
        &MeshOptions {
            max_vertices: 500,
            ..MeshOptions::default()
        },
    );
    assert_eq!(mesh.triangle_count(), 0);
    assert_eq!(mesh.lines.len(), 100 * 6);
    assert_eq!(mesh.check(), Ok(()));
    assert_eq!(mesh.bounds(), [[0.0, 0.0, 0.0], [99.0, 1.0, 0.0]]);
}

#[test]
fn ranges_map_triangles_to_the_modules_that_drew_them() {
    let mut first = segment(DVec3::ZERO, DVec3::Y, None);
    first.module = 2;
    let mut second = segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0));
    second.module = 5;
    let skeleton = Skeleton {
        segments: vec![first, second],
        ..Skeleton::default()
    };
    let mesh = checked_mesh(&skeleton);
    // Start cap and first quads: module 2; second quads and end cap: module 5.
    assert_eq!(mesh.ranges, vec![0, 2, 8 + 16, 5]);
}

#[test]
fn color_ranges_give_every_triangle_the_colour_index_that_drew_it() {
    let mut second = segment(DVec3::Y, DVec3::new(0.0, 2.0, 0.0), Some(0));
    second.color = 2;
    let skeleton = Skeleton {
        segments: vec![segment(DVec3::ZERO, DVec3::Y, None), second],
        polygons: vec![polygon(
            vec![
                DVec3::X,
                DVec3::new(2.0, 0.0, 0.0),
                DVec3::new(2.0, 1.0, 0.0),
            ],
            5,
            9,
        )],
        ..Skeleton::default()
    };
    let mesh = checked_mesh(&skeleton);
    // Start cap and first quads: index 0; second quads and end cap: 2; the triangle: 5.
    assert_eq!(mesh.color_ranges, vec![0, 0, 8 + 16, 2, 8 + 16 + 16 + 8, 5]);
    let indices = mesh.triangle_color_indices();
    assert_eq!(indices.len(), mesh.triangle_count());
    // The first vertex of every triangle has its index's colour.
    for (t, &index) in indices.iter().enumerate() {
        let v = mesh.indices[3 * t] as usize;
        assert_eq!(
            &mesh.colors[3 * v..3 * v + 3],
            &skeleton.color(index),
            "triangle {t}"
        );
    }
    assert_eq!(mesh.width_unit, 0.1);
}
