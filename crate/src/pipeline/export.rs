//! Exporting: a grammar built, its branch edits applied, and its model written as files. The
//! command line and the studio's export worker both call [`export`], so a download is byte for
//! byte the CLI's file.

use super::{build_with, Build, BuildOptions, Hooks, PlantEditor, Stage, StageTimings};
use crate::branches::{BranchEdit, EditReport};
use crate::diagnostics::Diagnostic;
use crate::export::animation::Animation;
use crate::export::{self, ExportedFile, Format};

/// What to export.
#[derive(Clone, Debug)]
pub struct ExportOptions {
    pub build: BuildOptions,
    pub format: Format,
    /// The files' stem (`plant` gives `plant.glb`; OBJ's `plant.obj` names `plant.mtl`).
    pub stem: String,
    /// Branch edits to apply first (`None`: the plant as it grew).
    pub edits: Option<Vec<BranchEdit>>,
    /// An SVG's picture settings (the default for the other formats).
    pub look: export::svg::Look,
    /// glTF only: the plant's growth in time as an animation (docs/LANGUAGE.md, "Growth in
    /// time").
    pub animation: Option<Animation>,
}

/// An export's files and what happened on the way.
#[derive(Clone, Debug)]
pub struct Exported {
    /// The model's files: the format's file first, then any others (OBJ's MTL, POV-Ray's
    /// texture images).
    pub files: Vec<ExportedFile>,
    /// The build's warnings.
    pub diagnostics: Vec<Diagnostic>,
    /// Which edits applied and which did not (with edits only).
    pub edits: Option<EditReport>,
    /// How long the build's stages took, when the caller lent a clock.
    pub timings: Option<StageTimings>,
}

/// Why nothing was exported.
#[derive(Debug)]
pub enum ExportError {
    /// The grammar has errors: there is no plant to write. The build is returned for its
    /// diagnostics.
    Grammar(Box<Build>),
    /// The export was refused, the message says why: the growth animation would pass its limit
    /// ([`export::animation::MAX_TARGET_BYTES`]) or was asked of another format than glTF, or
    /// the plant is drawn as lines only (its skeleton over budget: `E0414`).
    Refused(String),
}

/// Builds `source`, applies the edits, and writes the model; `hooks.progress` is told each stage
/// as it starts (`ApplyEdits` only with edits).
pub fn export(
    source: &str,
    options: &ExportOptions,
    hooks: &mut Hooks,
) -> Result<Exported, ExportError> {
    let animation = match options.animation {
        Some(_) if options.format != Format::Glb => {
            return Err(ExportError::Refused(format!(
                "the growth animation is written in glTF only, not in {}",
                options.format.extension()
            )))
        }
        a => a,
    };
    let mut build_options = options.build.clone();
    build_options.mesh.growth |= animation.is_some();
    let build = build_with(source, &build_options, hooks);
    if !build.ok() {
        return Err(ExportError::Grammar(Box::new(build)));
    }
    if build.plant.is_lines_only() {
        return Err(ExportError::Refused(format!(
            "the plant is too large to export: {} segments, drawn as lines only (its skeleton \
             would pass the budget of {} MB); export it with fewer iterations",
            build.plant.stats.segments,
            crate::turtle::MAX_SKELETON_BYTES >> 20
        )));
    }
    let steps = build.derived_with.steps;
    let (diagnostics, timings) = (build.diagnostics, build.timings);
    let (plant, edits) = match &options.edits {
        Some(edits) => {
            hooks.start(Stage::ApplyEdits);
            // (With the animation, the editor's mesh carries the growth arrays: an edited plant
            // grows when the unedited one does, from where the edits put each element.)
            let mut editor = PlantEditor::new(build.plant);
            let report = editor.apply_edits(edits);
            (editor.into_plant(), Some(report))
        }
        None => (build.plant, None),
    };
    let keyframes = animation
        .map(|a| a.keyframes(&plant.mesh, steps))
        .transpose()
        .map_err(ExportError::Refused)?;
    hooks.start(Stage::Write);
    let files = match keyframes {
        Some(keyframes) => {
            let scene = export::scene::Scene::new(&plant.mesh, &plant.skeleton);
            vec![ExportedFile {
                name: format!("{}.glb", export::safe_stem(&options.stem)),
                bytes: export::gltf::write_animated(&scene, Some(&keyframes)),
                mime: "model/gltf-binary",
            }]
        }
        None => export::export_with(
            options.format,
            &plant.mesh,
            &plant.skeleton,
            &options.stem,
            &options.look,
        ),
    };
    Ok(Exported {
        files,
        diagnostics,
        edits,
        timings,
    })
}
