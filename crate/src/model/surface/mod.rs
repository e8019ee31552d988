//! Declared surfaces (`#surface X …`, `#patch X …`): bicubic Bézier patches in the turtle's
//! frame, as cpfg reads them from a `.s` file (vlab `cpfg/patches.c`, `determine_transform` and
//! `get_patch`), and the organ library ([`organ_patches`]).
//!
//! A declared point p becomes q = (p − contact) · scale / size, then its coordinates in the
//! declared frame, (q · L′, q · H′, q · U′) with L′ = H′ × U (cpfg's `left`) and U′ = L′ × H′:
//! x along the turtle's L, y along H, z along U. `~X(s)` multiplies them by s
//! (`~X(sx, sy, sz)`: by sx along L, sy along H, sz along U) and adds the turtle's position.

#[cfg(feature = "surfaces")]
mod library;

#[cfg(feature = "surfaces")]
pub use library::organ_patches;

use crate::syntax::Span;
use crate::vocabulary::Organ;
use glam::DVec3;

/// One bicubic Bézier patch: 16 control points, row by row of its 4 × 4 grid (row `i`, column
/// `j` at `4 * i + j`).
pub type Patch = [DVec3; 16];

/// The most patches one surface may have.
pub const MAX_PATCHES: usize = 64;
/// The most quads along s or t of a patch (cpfg's is 10).
pub const MAX_PRECISION: u32 = 32;
#[cfg(feature = "surfaces")]
/// Quads along s and t when nothing says (cpfg's `S_COUNT / 2` when a `.s` file has no
/// `PRECISION` line).
pub const DEFAULT_PRECISION: u32 = 5;
#[cfg(feature = "surfaces")]
/// Quads along s and t of the library's shapes.
pub const LIBRARY_PRECISION: u32 = 8;

/// A control point as written in a `#patch` line: what an editor rewrites.
#[derive(Clone, Debug, PartialEq)]
pub struct WrittenPoint {
    /// Its patch (the `#patch` lines of the surface, in order) and its place in the 4 × 4 grid.
    pub patch: u32,
    pub index: u32,
    /// x y z as written (before the frame).
    pub value: [f64; 3],
    /// The text of its three numbers, from the first's start to the last's end.
    pub span: Span,
}

/// What `~X` draws.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceShape {
    /// The letter X.
    pub letter: char,
    /// The patches in the turtle's frame (x along L, y along H, z along U) at scale 1.
    pub patches: Vec<Patch>,
    /// Quads per patch along s (a patch's rows) and t (its columns).
    pub precision: [u32; 2],
    /// Where the turtle moves after drawing, in the same frame (`end`), if anywhere.
    pub end: Option<DVec3>,
    /// The library shape it is, if it is one.
    pub organ: Option<Organ>,
    /// The declared frame its points were placed by (what maps a written point to `patches`:
    /// the studio's surface editor maps a dragged point back through it).
    #[cfg(feature = "surfaces")]
    pub frame: Frame,
    /// The `#patch` points as written.
    pub written: Vec<WrittenPoint>,
    /// Each patch's colour indices, top (its front) then bottom (`#patch … color top
    /// [bottom]`), 0 for the turtle's colour; empty when no patch gives one.
    pub colors: Vec<[u16; 2]>,
}

impl SurfaceShape {
    /// The colour index patch `k` is drawn with on its front (`back` false) or back, when the
    /// turtle's is `turtle`: the patch's own when it gives one, as cpfg's `determine_vertex_shading`
    /// takes a `.s` patch's non-zero `TOP COLOR` / `BOTTOM COLOR` over the turtle's.
    pub fn patch_color(&self, k: usize, back: bool, turtle: u16) -> u16 {
        match self.colors.get(k).map(|c| c[usize::from(back)]) {
            Some(c) if c != 0 => c,
            _ => turtle,
        }
    }

    /// The largest distance of a control point from the contact point at scale 1 (a patch lies
    /// within its control points' hull).
    pub fn reach(&self) -> f64 {
        self.patches
            .iter()
            .flatten()
            .map(|p| p.length())
            .fold(0.0, f64::max)
    }
}

#[cfg(feature = "surfaces")]
/// The frame of a declaration: what a `.s` file's header and a view file's surface line give.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub contact: DVec3,
    pub heading: DVec3,
    pub up: DVec3,
    pub size: f64,
    pub scale: f64,
}

#[cfg(feature = "surfaces")]
impl Default for Frame {
    fn default() -> Self {
        Frame {
            contact: DVec3::ZERO,
            heading: DVec3::Y,
            up: DVec3::Z,
            size: 1.0,
            scale: 1.0,
        }
    }
}

#[cfg(feature = "surfaces")]
impl Frame {
    /// The frame's left, heading and up, orthonormal as cpfg makes them; `None` when the heading
    /// and up are parallel or zero.
    pub fn axes(&self) -> Option<[DVec3; 3]> {
        let heading = self.heading.try_normalize()?;
        let left = heading.cross(self.up.try_normalize()?).try_normalize()?;
        Some([left, heading, left.cross(heading)])
    }

    /// A declared point in the turtle's frame at scale 1.
    pub fn place(&self, p: DVec3, axes: &[DVec3; 3]) -> DVec3 {
        let q = (p - self.contact) * (self.scale / self.size);
        DVec3::new(q.dot(axes[0]), q.dot(axes[1]), q.dot(axes[2]))
    }
}

#[cfg(feature = "surfaces")]
#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_frame_keeps_points_and_a_cpfg_frame_moves_them() {
        let f = Frame::default();
        let axes = f.axes().unwrap();
        let p = DVec3::new(1.0, 2.0, 3.0);
        assert!((f.place(p, &axes) - p).length() < 1e-12);
        // cpfg's leaf.s: heading (0, .83, .55), up (0, .55, −.83): left = heading × up = −x.
        let f = Frame {
            contact: DVec3::new(0.21, -1.55, -37.04),
            heading: DVec3::new(0.0, 0.83, 0.55),
            up: DVec3::new(0.0, 0.55, -0.83),
            size: 122.04,
            scale: 2.0,
        };
        let axes = f.axes().unwrap();
        assert!((axes[0] - DVec3::NEG_X).length() < 1e-3);
        // The contact point lands at the turtle; a point along the heading lands along H.
        assert!(f.place(f.contact, &axes).length() < 1e-12);
        let ahead = f.place(f.contact + f.heading.normalize() * 61.02, &axes);
        assert!((ahead - DVec3::new(0.0, 1.0, 0.0)).length() < 1e-9);
        assert!(Frame { up: f.heading, ..f }.axes().is_none());
    }
}
