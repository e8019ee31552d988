//! Exporting: a grammar built, its branch edits applied, and its model written as files. The
//! command line and the studio's export worker both call [`export`], so a download is byte for
//! byte the CLI's file.

use super::{build_with, Build, BuildOptions, Hooks, PlantEditor, Stage, StageTimings};
use crate::branches::{BranchEdit, EditReport};
use crate::diagnostics::Diagnostic;
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
}

/// Builds `source`, applies the edits, and writes the model; `hooks.progress` is told each stage
/// as it starts (`ApplyEdits` only with edits).
pub fn export(
    source: &str,
    options: &ExportOptions,
    hooks: &mut Hooks,
) -> Result<Exported, ExportError> {
    let build = build_with(source, &options.build, hooks);
    if !build.ok() {
        return Err(ExportError::Grammar(Box::new(build)));
    }
    let (diagnostics, timings) = (build.diagnostics, build.timings);
    let (plant, edits) = match &options.edits {
        Some(edits) => {
            hooks.start(Stage::ApplyEdits);
            let mut editor = PlantEditor::new(build.plant);
            let report = editor.apply_edits(edits);
            (editor.into_plant(), Some(report))
        }
        None => (build.plant, None),
    };
    hooks.start(Stage::Write);
    let files = export::export_with(
        options.format,
        &plant.mesh,
        &plant.skeleton,
        &options.stem,
        &options.look,
    );
    Ok(Exported {
        files,
        diagnostics,
        edits,
        timings,
    })
}
