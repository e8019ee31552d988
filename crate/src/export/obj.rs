//! Wavefront OBJ (`.obj`) with its material library (`.mtl`): every vertex once (`v`, `vn`), then
//! the faces of each colour index after `usemtl color_N` (`f a//a b//b c//c`, counter-clockwise).
//! The MTL file has one material per colour index (`Kd` in sRGB, as OBJ readers take it). The OBJ
//! names the MTL file in `mtllib`, so the two travel together: the command-line tool writes
//! `OUT.obj` and `OUT.mtl` side by side; the studio downloads both in one zip. A model too large
//! to mesh is written as lines (`l a b`).

use super::scene::{decimals_for, extent, number, srgb, Primitive, Scene};
use std::fmt::Write;

/// The OBJ text of `scene`, naming `mtl_file` (e.g. `plant.mtl`) as its material library.
pub fn write_obj(scene: &Scene, mtl_file: &str) -> String {
    let decimals = decimals_for(extent(scene.bounds()));
    let groups = scene.groups();
    let primitive = scene.primitive();
    let points = scene.points();
    let mut out = String::with_capacity(64 + points.len() * 24);
    writeln!(
        out,
        "# Made with Meristem {}: {} vertices, {} {}",
        env!("CARGO_PKG_VERSION"),
        points.len() / 3,
        groups.iter().map(|g| g.items.len()).sum::<usize>(),
        match primitive {
            Primitive::Triangles => "triangles",
            Primitive::Lines => "lines (too large to mesh)",
        }
    )
    .ok();
    writeln!(out, "mtllib {mtl_file}\no plant").ok();
    triples(&mut out, "v", points, decimals);
    if primitive == Primitive::Triangles {
        triples(&mut out, "vn", &scene.mesh.normals, 4);
    }
    for group in &groups {
        writeln!(out, "usemtl color_{}", group.index).ok();
        for &item in &group.items {
            // OBJ counts vertices from 1.
            let [a, b, c] = scene.corners(item).map(|i| i + 1);
            match primitive {
                Primitive::Triangles => writeln!(out, "f {a}//{a} {b}//{b} {c}//{c}"),
                Primitive::Lines => writeln!(out, "l {a} {b}"),
            }
            .ok();
        }
    }
    out
}

/// The MTL text: one material per colour index that `scene` uses.
pub fn write_mtl(scene: &Scene) -> String {
    let mut out = String::new();
    writeln!(
        out,
        "# Made with Meristem {}: one material per colour index",
        env!("CARGO_PKG_VERSION")
    )
    .ok();
    for group in scene.groups() {
        writeln!(out, "\nnewmtl color_{}", group.index).ok();
        let [r, g, b] = srgb(group.color);
        out.push_str("Ka 0 0 0\nKd ");
        for (k, c) in [r, g, b].iter().enumerate() {
            if k > 0 {
                out.push(' ');
            }
            number(&mut out, *c as f64, 4);
        }
        out.push_str("\nKs 0 0 0\nd 1\nillum 1\n");
    }
    out
}

/// One `prefix x y z` line per point of a flat `f32` × 3 array.
fn triples(out: &mut String, prefix: &str, flat: &[f32], decimals: usize) {
    for p in flat.chunks_exact(3) {
        out.push_str(prefix);
        for c in p {
            out.push(' ');
            number(out, *c as f64, decimals);
        }
        out.push('\n');
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::export::tests::{small_scene, two_colour_plant};

    #[test]
    fn every_vertex_once_and_every_face_under_its_material() {
        let (mesh, skeleton) = two_colour_plant();
        let scene = Scene::new(&mesh, &skeleton);
        let obj = write_obj(&scene, "plant.mtl");
        let count = |prefix: &str| obj.lines().filter(|l| l.starts_with(prefix)).count();
        assert_eq!(count("v "), mesh.vertex_count());
        assert_eq!(count("vn "), mesh.vertex_count());
        assert_eq!(count("f "), mesh.triangle_count());
        assert_eq!(count("usemtl "), 2);
        assert!(obj.contains("mtllib plant.mtl\n"));
        let mtl = write_mtl(&scene);
        assert_eq!(mtl.matches("newmtl color_").count(), 2);
        for line in obj.lines().filter(|l| l.starts_with("usemtl ")) {
            assert!(mtl.contains(&format!("newmtl {}", &line[7..])));
        }
    }

    #[test]
    fn the_fallback_writes_lines() {
        let (mesh, skeleton) = small_scene(10);
        let obj = write_obj(&Scene::new(&mesh, &skeleton), "x.mtl");
        assert_eq!(
            obj.lines().filter(|l| l.starts_with("l ")).count(),
            mesh.lines.len() / 6
        );
        assert!(!obj.contains("\nf "));
    }
}
