//! Stage 5, `mesh`: the skeleton becomes triangles in flat arrays ready for the GPU.
//!
//! Each segment becomes an open tube of `sides` quads whose ring lies in the turtle's L–U plane.
//! Widths are diameters measured in *width units*. By default ([`WidthUnit::Relative`]) one unit
//! is 1/300 of the skeleton's bounding-box diagonal, like cpfg's widths in pixels of a window that
//! frames the plant: `#width 1` draws thin but visible branches at any size, and `!(10)` a trunk
//! ten times thicker.
//!
//! The files: `buffers.rs` ([`MeshBuffers`], the one definition of the arrays' layout),
//! `options.rs` ([`MeshOptions`]), `width.rs` ([`WidthUnit`]: widths to model units), `chains.rs`
//! (the axes that become tubes), `build.rs` (the builder: [`build_mesh`]), `grow.rs` (how the
//! arrays grow), `growth.rs` (growth in time: when each element grows, the mesh at a time), `tube.rs` (axes as tubes), `curve.rs`, `polygon.rs` and `monotone.rs`
//! (triangulation), `surfaces.rs` (the built-in leaf and petal), `bezier.rs` (declared surfaces'
//! patches), `sphere.rs`, `lines.rs` (segments as lines), `pack.rs` (normals
//! and colours packed for the GPU), `parts.rs` (one element re-meshed alone).

pub mod bezier;
mod buffers;
mod build;
mod chains;
pub mod curve;
mod grow;
mod growth;
mod lines;
mod monotone;
mod options;
mod pack;
pub mod parts;
pub mod polygon;
pub mod sphere;
pub mod surfaces;
mod tube;
mod width;

pub use buffers::{MeshBuffers, MATERIAL_BARK, MATERIAL_LEAF, MATERIAL_PLAIN};
pub use build::{build_mesh, build_mesh_with_parts};
pub use chains::{joint_key, Chains};
pub use growth::{
    grown_position, growth_factor, growth_schedule, mesh_at, skeleton_at, Growth, GrowthSchedule,
};
pub use lines::{segment_colors, segment_ends, segment_lines, segment_modules, SegmentLines};
pub use options::{MeshOptions, MAX_SIDES, MIN_SIDES};
pub use pack::{normal_samples, pack_colors, pack_normals};
pub use parts::{ChainPart, MeshParts, Part};
pub(crate) use width::skeleton_diagonal;
pub use width::{resolve_width_unit, WidthUnit, DEFAULT_WIDTH_PER_LENGTH};

#[cfg(test)]
mod tests;
