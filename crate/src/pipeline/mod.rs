//! The whole pipeline, parse -> resolve -> derive -> (growth) -> interpret -> mesh, as one call
//! shared by the command-line tool and the wasm boundary, and what a caller does with its result.
//!
//! - [`build()`] runs every stage and returns a [`Build`]: the diagnostics, the model, the
//!   [`Derivation`](crate::derive::Derivation), the growth record and the [`Plant`] (skeleton,
//!   mesh, stats);
//! - [`Build::inspector`] answers questions about the derivation ([`Inspector`]: why a production
//!   fired, the text of the derived string);
//! - [`PlantEditor`] edits the plant's branches by their Bézier handles;
//! - [`export()`] builds and writes a model file, the same bytes for the CLI and the studio.
//!
//! The core reads no clock and knows nothing of progress bars: a caller lends [`Hooks`] (a clock
//! read around each stage, a callback told each stage as it starts and each derivation step as it
//! ends).
//!
//! The files: `breakpoints.rs` (where a derivation played step by step pauses: a production's
//! first firing, a watch's first true module), `build.rs` ([`build()`], [`Build`], [`BuildOptions`]), `hooks.rs` ([`Hooks`],
//! [`Stage`], [`Progress`], [`StageTimings`]), `observer.rs` (growth and the turtle following a
//! derivation), `step_on.rs` ([`build_on`]: a build that continues an earlier one's derivation),
//! `plant.rs`, `inspector.rs`, `lineage.rs` ([`lineage()`]: a module's
//! ancestors step by step back to the axiom, and the productions that made them), `editor.rs`, `export.rs`, `surface_preview.rs` ([`surface_preview`]: one
//! declared surface as the studio's surface editor shows it: meshed, its control points with the
//! text of each, its frame, and a library shape's text written out as `#patch` lines).

mod breakpoints;
mod budget;
mod build;
mod editor;
#[cfg(feature = "environment")]
mod environment;
#[cfg(feature = "environment")]
mod environment_answers;
#[cfg(feature = "environment")]
mod environment_reading;
#[cfg(feature = "environment")]
mod environment_view;
mod export;
mod hooks;
mod inspector;
mod lineage;
mod observer;
mod plant;
#[cfg(feature = "environment")]
mod stand;
mod step_on;
#[cfg(feature = "surfaces")]
mod surface_preview;

pub use breakpoints::{first_firing, first_watched, Pause};
pub use build::{build, build_with, Build, BuildOptions};
pub use editor::{BranchInfo, PlantEditor};
#[cfg(feature = "environment")]
pub use environment_reading::MAX_READING_BYTES;
#[cfg(feature = "environment")]
pub use environment_view::{EnvironmentView, FieldView, MAX_VIEW_POINTS, MAX_VIEW_VOXELS};
pub use export::{export, ExportError, ExportOptions, Exported};
pub use hooks::{Hooks, Progress, Stage, StageTimings};
pub use inspector::{Explained, Inspector};
pub use lineage::{lineage, lineage_text, production_place, LineageRow};
pub use plant::Plant;
pub use step_on::{build_on, why_not_continued};
#[cfg(feature = "surfaces")]
pub use surface_preview::{surface_preview, SurfacePreview};

#[cfg(test)]
mod tests;
