//! Stage 6, `export`: what leaves the core as files. The statistics object (`meristem derive
//! --stats` and the studio's status line), and the model formats, one writer per module, each a
//! plain function of the [`MeshBuffers`] and the [`Skeleton`] (palette, colour indices, segments)
//! that returns bytes: no IO, no browser, so the command-line tool and the studio write the same
//! bytes. Output is deterministic: groups in colour-index order, numbers printed by
//! [`scene::number`].
//!
//! | format | module | what it holds |
//! | --- | --- | --- |
//! | VRML 2.0 `.wrl` | [`vrml`] | a `Shape` per colour index over one shared `Coordinate`/`Normal`, a framing `Viewpoint` |
//! | glTF 2.0 binary `.glb` | [`gltf`] | a primitive and PBR material per colour index over shared accessors; the growth as morph targets and an animation ([`animation`]) |
//! | POV-Ray 3.7 `.pov` | [`pov`] | one `mesh2` with a `texture_list`, camera and lights |
//! | OBJ + MTL `.obj` | [`obj`] | `usemtl color_N` groups; the MTL beside it (a zip in the studio) |
//! | OpenInventor 2.1 `.iv` | [`inventor`] | shared `Coordinate3`/`Normal`, a `Material` + face set per colour index |
//! | SVG `.svg` | [`svg`] | the skeleton projected onto X–Y: stroked segments, filled polygons |

pub mod animation;
pub mod gltf;
pub mod inventor;
pub mod obj;
pub mod pov;
pub mod scene;
pub mod svg;
pub mod text;
pub mod textures;
pub mod vrml;
pub mod zip;

use crate::mesh::MeshBuffers;
use crate::turtle::Skeleton;
use scene::Scene;
use serde::Serialize;

/// A model file format the core writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Vrml,
    Glb,
    Pov,
    Obj,
    Inventor,
    Svg,
}

impl Format {
    /// Every format, in the order the studio lists them.
    pub const ALL: [Format; 6] = [
        Format::Vrml,
        Format::Glb,
        Format::Pov,
        Format::Obj,
        Format::Inventor,
        Format::Svg,
    ];

    /// The file extension, which is also the format's name on the command line and at the wasm
    /// boundary.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Vrml => "wrl",
            Format::Glb => "glb",
            Format::Pov => "pov",
            Format::Obj => "obj",
            Format::Inventor => "iv",
            Format::Svg => "svg",
        }
    }

    /// The format of an extension (`wrl`, `glb`, `pov`, `obj`, `iv`, `svg`; any case).
    pub fn from_extension(extension: &str) -> Option<Format> {
        Format::ALL
            .into_iter()
            .find(|f| f.extension().eq_ignore_ascii_case(extension))
    }

    /// The extensions, for messages: `wrl, glb, pov, obj, iv, svg`.
    pub fn names() -> String {
        Format::ALL.map(Format::extension).join(", ")
    }
}

/// One written file.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportedFile {
    /// File name: the stem given to [`export`] and the format's extension.
    pub name: String,
    pub bytes: Vec<u8>,
    /// Media type, for a download.
    pub mime: &'static str,
}

/// Longest file stem an export writes (characters): [`safe_stem`] cuts a longer name.
pub const MAX_STEM_CHARS: usize = 64;

/// A name made a safe file stem (issue 50, 14): the one function every name goes through before
/// it names a file or is written into one (zip entries, OBJ's `mtllib`, the glTF download's
/// name). Path separators, control characters (a line break would start a line of its own in an
/// OBJ), whitespace (`mtllib` takes a list of names) and the characters Windows refuses
/// (`:*?"<>|`) become `-`, runs of them one `-`; dots and dashes at either end go (so `../../x`
/// is `x`, and no stem is hidden or `..`); at most [`MAX_STEM_CHARS`] characters are kept; an
/// empty result is `plant`. A stem that is already safe (`plant`, `fern_2`, `fougère`) is kept.
pub fn safe_stem(name: &str) -> String {
    let unsafe_char = |c: char| c.is_control() || c.is_whitespace() || "/\\:*?\"<>|".contains(c);
    let mut stem = String::new();
    for c in name.chars() {
        let c = if unsafe_char(c) { '-' } else { c };
        if !(c == '-' && stem.ends_with('-')) {
            stem.push(c);
        }
    }
    let ends = |c: char| c == '-' || c == '.';
    let stem: String = stem
        .trim_matches(ends)
        .chars()
        .take(MAX_STEM_CHARS)
        .collect();
    let stem = stem.trim_end_matches(ends);
    if stem.is_empty() {
        "plant".to_string()
    } else {
        stem.to_string()
    }
}

/// Writes the model in `format` as files named after `stem` (`plant` gives `plant.wrl`; OBJ gives
/// `plant.obj`, which names `plant.mtl`, and `plant.mtl`).
pub fn export(
    format: Format,
    mesh: &MeshBuffers,
    skeleton: &Skeleton,
    stem: &str,
) -> Vec<ExportedFile> {
    export_with(format, mesh, skeleton, stem, &svg::Look::default())
}

/// [`export`], an SVG drawn in `look` (the other formats have no look).
pub fn export_with(
    format: Format,
    mesh: &MeshBuffers,
    skeleton: &Skeleton,
    stem: &str,
    look: &svg::Look,
) -> Vec<ExportedFile> {
    let scene = Scene::new(mesh, skeleton);
    let stem = safe_stem(stem);
    let file = |extension: &str, bytes: Vec<u8>, mime: &'static str| ExportedFile {
        name: format!("{stem}.{extension}"),
        bytes,
        mime,
    };
    match format {
        Format::Vrml => vec![file("wrl", vrml::write(&scene).into_bytes(), "model/vrml")],
        Format::Glb => vec![file("glb", gltf::write(&scene), "model/gltf-binary")],
        Format::Pov => {
            // The images the scene's textures name, beside it (only those some triangle uses).
            let kinds = mesh.triangle_materials();
            let mut files = vec![file("pov", pov::write(&scene).into_bytes(), "text/plain")];
            for (kind, name, png) in [
                (crate::mesh::MATERIAL_BARK, "bark.png", textures::BARK_PNG),
                (crate::mesh::MATERIAL_LEAF, "leaf.png", textures::LEAF_PNG),
            ] {
                if kinds.contains(&(kind as u8)) {
                    files.push(ExportedFile {
                        name: name.into(),
                        bytes: png.to_vec(),
                        mime: "image/png",
                    });
                }
            }
            files
        }
        Format::Obj => {
            let mtl = format!("{stem}.mtl");
            vec![
                file(
                    "obj",
                    obj::write_obj(&scene, &mtl).into_bytes(),
                    "model/obj",
                ),
                file("mtl", obj::write_mtl(&scene).into_bytes(), "model/mtl"),
            ]
        }
        Format::Inventor => vec![file(
            "iv",
            inventor::write(&scene).into_bytes(),
            "text/plain",
        )],
        Format::Svg => vec![file(
            "svg",
            svg::write_with(mesh, skeleton, look).into_bytes(),
            "image/svg+xml",
        )],
    }
}

/// What the studio downloads: the one file of an export, or a zip (`STEM.zip`, `stem` a
/// [`safe_stem`] and what the caller adds to it, as `fern-obj`) of its files
/// when it has several (OBJ and MTL; POV-Ray's scene and the texture images it names). `None`
/// only past 4 GiB.
pub fn bundle(mut files: Vec<ExportedFile>, stem: &str) -> Option<ExportedFile> {
    if files.len() == 1 {
        return files.pop();
    }
    let entries: Vec<(&str, &[u8])> = files
        .iter()
        .map(|f| (f.name.as_str(), f.bytes.as_slice()))
        .collect();
    Some(ExportedFile {
        name: format!("{stem}.zip"),
        bytes: zip::stored(&entries)?,
        mime: "application/zip",
    })
}

/// Counts and extent of one build.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Stats {
    /// Modules in the derived string.
    pub modules: usize,
    /// Segments drawn by the turtle.
    pub segments: usize,
    pub vertices: usize,
    pub triangles: usize,
    /// Segments drawn as lines because the model was too large to mesh (0 normally).
    pub lines: usize,
    /// Derivation steps run.
    pub iterations: u32,
    /// `[[minx, miny, minz], [maxx, maxy, maxz]]` of the mesh vertices.
    pub bounds: [[f64; 3]; 2],
}

impl Stats {
    pub fn new(modules: usize, segments: usize, iterations: u32, mesh: &MeshBuffers) -> Self {
        Stats {
            modules,
            segments,
            vertices: mesh.vertex_count(),
            triangles: mesh.triangle_count(),
            lines: mesh.lines.len() / 6,
            iterations,
            bounds: mesh.bounds(),
        }
    }

    /// One JSON object on one line.
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).unwrap_or_else(|_| "{}".into())
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::mesh::MeshOptions;
    use crate::pipeline::{build, BuildOptions};

    /// The mesh and skeleton of a grammar with the default options.
    pub fn built(source: &str) -> (MeshBuffers, Skeleton) {
        built_with(source, MeshOptions::default())
    }

    fn built_with(source: &str, mesh: MeshOptions) -> (MeshBuffers, Skeleton) {
        let result = build(
            source,
            &BuildOptions {
                mesh,
                ..BuildOptions::default()
            },
        );
        assert!(result.ok(), "{:?}", result.diagnostics);
        (result.plant.mesh, result.plant.skeleton)
    }

    /// A trunk of colour index 0 with a branch of colour index 1.
    pub fn two_colour_plant() -> (MeshBuffers, Skeleton) {
        built("#angle 30\naxiom: F[+;F]F\n")
    }

    /// The text a writer makes of [`two_colour_plant`], with the plant's mesh, once checked that
    /// it starts with the format's `header` and holds each pattern of `counts` that many times.
    pub fn written_two_colour_plant(
        write: fn(&Scene) -> String,
        header: &str,
        counts: &[(&str, usize)],
    ) -> (MeshBuffers, String) {
        let (mesh, skeleton) = two_colour_plant();
        let text = write(&Scene::new(&mesh, &skeleton));
        assert!(text.starts_with(header), "{text}");
        for &(pattern, count) in counts {
            assert_eq!(text.matches(pattern).count(), count, "{pattern}");
        }
        (mesh, text)
    }

    /// A plant of colour indices 0, 1 and 2 meshed with at most `max_vertices`: lines when small.
    pub fn small_scene(max_vertices: usize) -> (MeshBuffers, Skeleton) {
        let (mesh, skeleton) = built_with(
            "#angle 30\naxiom: F[+;F]F[-;;F]\n",
            MeshOptions {
                max_vertices,
                ..MeshOptions::default()
            },
        );
        assert!(mesh.indices.is_empty() && !mesh.lines.is_empty());
        (mesh, skeleton)
    }

    /// Panics unless the text a writer makes of [`small_scene`] (its fallback for a plant too
    /// large to mesh) holds every pattern of `present` and none of `absent`.
    pub fn assert_fallback_text(write: fn(&Scene) -> String, present: &[&str], absent: &[&str]) {
        let (mesh, skeleton) = small_scene(10);
        let text = write(&Scene::new(&mesh, &skeleton));
        for pattern in present {
            assert!(text.contains(pattern), "{pattern} missing in {text}");
        }
        for pattern in absent {
            assert!(!text.contains(pattern), "{pattern} in {text}");
        }
    }

    #[test]
    fn formats_are_named_by_their_extensions() {
        for format in Format::ALL {
            assert_eq!(Format::from_extension(format.extension()), Some(format));
        }
        assert_eq!(Format::from_extension("WRL"), Some(Format::Vrml));
        assert_eq!(Format::from_extension("png"), None);
        assert_eq!(Format::names(), "wrl, glb, pov, obj, iv, svg");
    }

    #[test]
    fn obj_is_two_files_and_its_download_a_zip_of_both() {
        let (mesh, skeleton) = two_colour_plant();
        let files = export(Format::Obj, &mesh, &skeleton, "tree");
        let names: Vec<&str> = files.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, ["tree.obj", "tree.mtl"]);
        let zip = bundle(files.clone(), "tree").expect("small");
        assert_eq!(zip.name, "tree.zip");
        assert_eq!(zip.mime, "application/zip");
        // Stored entries: each file's bytes appear whole in the archive.
        for f in &files {
            assert!(zip
                .bytes
                .windows(f.bytes.len())
                .any(|w| w == f.bytes.as_slice()));
        }
        let glb = bundle(export(Format::Glb, &mesh, &skeleton, "tree"), "tree").expect("small");
        assert_eq!(
            (glb.name.as_str(), glb.mime),
            ("tree.glb", "model/gltf-binary")
        );
    }

    #[test]
    fn a_name_becomes_a_safe_stem() {
        for (name, stem) in [
            ("plant", "plant"),
            ("fern_2", "fern_2"),
            ("fougère", "fougère"),
            ("../../x", "x"),
            ("..\\..\\x", "x"),
            ("/etc/passwd", "etc-passwd"),
            ("a\nv nan nan nan", "a-v-nan-nan-nan"),
            ("tree\r\0\t.", "tree"),
            ("C:fern?*", "C-fern"),
            ("..", "plant"),
            ("", "plant"),
            (" \n ", "plant"),
            (".hidden", "hidden"),
        ] {
            assert_eq!(safe_stem(name), stem, "{name:?}");
            assert_eq!(safe_stem(stem), stem, "a safe stem is kept");
        }
        let long = safe_stem(&"a".repeat(100_000));
        assert_eq!(long, "a".repeat(MAX_STEM_CHARS));
        // Cut to its length, a stem still does not end in a dash or a dot.
        let cut = safe_stem(&format!("{}.b", "a".repeat(MAX_STEM_CHARS - 1)));
        assert_eq!(cut, "a".repeat(MAX_STEM_CHARS - 1));
    }

    #[test]
    fn a_hostile_name_reaches_no_file_as_it_is() {
        let (mesh, skeleton) = two_colour_plant();
        let name = "../../x\nv nan nan nan";
        let files = export(Format::Obj, &mesh, &skeleton, name);
        let names: Vec<&str> = files.iter().map(|f| f.name.as_str()).collect();
        assert_eq!(names, ["x-v-nan-nan-nan.obj", "x-v-nan-nan-nan.mtl"]);
        let obj = std::str::from_utf8(&files[0].bytes).expect("text");
        assert!(obj.contains("\nmtllib x-v-nan-nan-nan.mtl\n"), "{obj}");
        assert!(!obj.lines().any(|l| l.starts_with("v nan")));
        // The entries' names are the files' own: none climbs out of the folder it is unpacked in.
        let zip = bundle(files, &safe_stem(name)).expect("small");
        assert_eq!(zip.name, "x-v-nan-nan-nan.zip");
        assert!(!zip.bytes.windows(3).any(|w| w == b"../"));
        let files = export(Format::Obj, &mesh, &skeleton, &"n".repeat(100_000));
        assert_eq!(files[0].name, format!("{}.obj", "n".repeat(MAX_STEM_CHARS)));
        assert!(
            bundle(files, "n").is_some(),
            "a long name is cut, not an archive past 4 GiB"
        );
    }

    #[test]
    fn every_writer_handles_a_plant_that_draws_nothing() {
        let (mesh, skeleton) = built("axiom: X\n");
        assert_eq!(mesh.triangle_count(), 0);
        for format in Format::ALL {
            let files = export(format, &mesh, &skeleton, "empty");
            assert!(files.iter().all(|f| !f.bytes.is_empty()), "{format:?}");
        }
    }
}
