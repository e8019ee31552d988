//! [`MeshOptions`]: the mesh stage's options, and the range of the view's tube sides.

use super::WidthUnit;

/// Fewest sides a tube may have in the view options (the studio's, links', the CLI's `--sides`).
pub const MIN_SIDES: u32 = 3;
/// Most sides a tube may have in the view options.
pub const MAX_SIDES: u32 = 64;

/// Options of the mesh stage.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshOptions {
    /// Sides of each tube (at least 3).
    pub sides: u32,
    pub width_unit: WidthUnit,
    /// Make every axis a smooth generalized cylinder, not only those between `@Gc` and `@Ge`.
    pub smooth_all: bool,
    /// Rings per segment along a smooth axis.
    pub smooth_samples: u32,
    /// Segments around (and half as many rings along) each sphere.
    pub sphere_segments: u32,
    /// Above this many vertices the mesh falls back to lines (`MeshBuffers::lines`).
    pub max_vertices: usize,
    /// Mesh the segments as tubes (true), or leave them out: the studio's Lines mode draws the
    /// segments as lines and needs the mesh only for leaves, polygons and spheres.
    pub tubes: bool,
    /// Also write each vertex's growth in time (`MeshBuffers::growth_origins`, `growth_times`;
    /// docs/LANGUAGE.md, "Growth in time"): 20 bytes more per vertex, counted against
    /// `max_vertices`.
    pub growth: bool,
}

impl Default for MeshOptions {
    fn default() -> Self {
        MeshOptions {
            sides: 6,
            width_unit: WidthUnit::Relative(1.0 / 300.0),
            smooth_all: false,
            smooth_samples: 4,
            sphere_segments: 12,
            max_vertices: 4_000_000,
            tubes: true,
            growth: false,
        }
    }
}

impl MeshOptions {
    /// The default options with the studio's view options: `sides` (clamped to
    /// [`MIN_SIDES`]..=[`MAX_SIDES`], default 6; the CLI refuses `--sides` out of that range
    /// before it gets here) and `smooth_all` (default false). The wasm boundary and the CLI's
    /// `--sides` and `--smooth-all` both build their meshes with these, so a download is the mesh
    /// on screen.
    pub fn view(sides: Option<u32>, smooth_all: Option<bool>) -> MeshOptions {
        let defaults = MeshOptions::default();
        MeshOptions {
            sides: sides.map_or(defaults.sides, |s| s.clamp(MIN_SIDES, MAX_SIDES)),
            smooth_all: smooth_all.unwrap_or(defaults.smooth_all),
            ..defaults
        }
    }
}
