//! The light program (`#environment light …`; issue 47): how much light a point receives from the
//! sky and the sun, shadowed by every plant's parts, on a voxel grid. Replies to a `?E` with
//! `exposure dx dy dz`.
//!
//! **The grid.** Voxels of edge `cell`, aligned on multiples of `cell` from the origin (so a voxel
//! stays put as the plant grows), covering the parts' box with a margin of `depth` voxels beside
//! and below it (as far as a shadow reaches) and one layer above. Rebuilt at every
//! [`Responder::update`], in the allocations of the one before. A segment counts as one part for
//! each cell of its length (at least one: a segment shorter than a cell is one part, as one
//! metamer is in Palubicki et al.), spread evenly along it; a flat organ counts as its area in
//! voxel faces (at least one part), at its centre. A part's radius is not used.
//!
//! **Diffuse light from the sky** (Palubicki et al. 2009): each part casts a pyramid of shadow
//! `shadow × spread^−q` on the voxels (i ± p, j − q, k ± p), p ≤ q ≤ `depth` (exactly, in one
//! pass: `shadow.rs`). A voxel with shadow s gets `max(C − s + shadow, 0) / C`, at most 1: the
//! "+ shadow" forgives the one part the point stands at (a bud at a segment's tip is not in its
//! own segment's shadow). C, the full light, is the shadow a voxel would get under a half-space
//! filled with one part a voxel: `C = shadow × Σ_{q=1..depth} (2q + 1)² spread^−q` (31.2 × shadow
//! with the defaults). So 0 is as dark as the inside of a crown of one part a voxel, and a point
//! under one closed layer of parts gets 0.89 with the defaults, under four 0.33.
//!
//! **Direct light from the sun**: a beam from `sun_direction`, Beer–Lambert: each part on the
//! way stops `absorb` of it, one part forgiven as for the sky: `(1 − absorb)^max(n − 1, 0)` for n
//! parts on the beam up to the point's voxel, swept plane by plane (`sun.rs`).
//!
//! **Exposure** = `(sky × diffuse + sun × direct) / (sky + sun)`, 0 to 1, read in the voxel that
//! holds the point. A point outside the grid gets all the sky's light (no shadow reaches it) and
//! the sun's light as it leaves the grid on the way to the point (1 when its beam misses the
//! grid: above the plants, full light).
//!
//! **Direction of most light**: the unit vector of the light arriving, up weighted by the sky's
//! part and the sun's direction by the sun's part, `(sky × diffuse × (0, 1, 0) + sun × direct ×
//! sun_direction) / (sky + sun)`, plus the gradient of the exposure over the 26 neighbouring
//! voxels (per voxel) times `depth`, so that going from dark to light across a shadow's reach
//! counts as much as full light. The sky's gradient counts across only (x and z, towards the
//! gaps): up and down the pyramids say little (they spread thinner deeper down, so a point
//! under a wide canopy would be told to grow down). It points away from shade; it is (0, 1, 0)
//! in the open under the default overhead sun, and when the sum is 0.
//!
//! Deterministic: no randomness, the same parts give the same replies.

mod grid;
mod probe;
mod settings;
mod shadow;
mod sun;

pub use settings::{LightSettings, BAD_SETTING, MOST_DEPTH};

use super::{Exceeded, Field, Part, Probe, Responder, Work};
use crate::diagnostics::Diagnostic;
use crate::environment::settings::shown;
use crate::maths;
use crate::model::ProgramSpec;
use grid::Extent;
use shadow::{Pyramid, ShadowPlanes};
use sun::SunPlanes;

/// The light program: its settings and its grid of the last update.
#[derive(Debug)]
pub struct Light {
    settings: LightSettings,
    /// The full light C (0 when parts cast no shadow).
    full: f64,
    /// ln(1 − absorb): the log of the sun's light one part lets through.
    kept: f64,
    /// The grid of the last update; no voxels before the first or when there were no parts.
    extent: Extent,
    /// Parts per voxel; after the sun's sweep, parts on the beam up to each voxel.
    beam: Vec<f32>,
    /// The sky's shadow of each voxel (when the sky counts).
    shadow: Vec<f32>,
    shadow_planes: ShadowPlanes,
    sun_planes: SunPlanes,
    /// The voxels its updates have swept and spread the parts over in this build.
    work: Work,
}

const F32: usize = std::mem::size_of::<f32>();

impl Light {
    /// The program of `spec` (settings checked, errors at the setting); `step_length` is the
    /// default cell.
    pub fn new(spec: &ProgramSpec, step_length: f64) -> Result<Light, Diagnostic> {
        let settings = LightSettings::read(spec, step_length)?;
        let full = (1..=settings.depth)
            .map(|q| {
                settings.shadow * ((2 * q + 1) as f64).powi(2) / settings.spread.powi(q as i32)
            })
            .sum();
        Ok(Light {
            kept: maths::ln(1.0 - settings.absorb),
            settings,
            full,
            extent: Extent::default(),
            beam: Vec::new(),
            shadow: Vec::new(),
            shadow_planes: ShadowPlanes::default(),
            sun_planes: SunPlanes::default(),
            work: Work::default(),
        })
    }

    pub fn settings(&self) -> &LightSettings {
        &self.settings
    }

    /// The grid's voxels along x, y and z (0 before the first update or without parts).
    pub fn dims(&self) -> [usize; 3] {
        self.extent.dims
    }

    fn sky_counts(&self) -> bool {
        self.settings.sky > 0.0 && self.full > 0.0
    }

    fn sun_counts(&self) -> bool {
        self.settings.sun > 0.0
    }

    /// The grid `parts` need, or what it would take when over `budget`; `None` without parts.
    fn plan(&self, parts: &[Part], budget: usize) -> Result<Option<Extent>, Exceeded> {
        let cell = self.settings.cell;
        let inv = 1.0 / cell;
        let Some((lo, hi)) = grid::parts_box(parts, inv) else {
            return Ok(None);
        };
        let depth = self.settings.depth as f64;
        let (lo, dims) = Extent::with_margins(lo, hi, depth, depth, 1.0);
        let voxels = dims[0] * dims[1] * dims[2];
        let (sky, sun) = (self.sky_counts(), self.sun_counts());
        let planes = f64::from(u8::from(sky)) * ShadowPlanes::bytes_for(dims, self.settings.depth)
            + f64::from(u8::from(sun)) * SunPlanes::bytes_for(dims);
        let grids = 1.0 + f64::from(u8::from(sky));
        let bytes = voxels * grids * F32 as f64 + planes;
        // NaN: a box too far out for floats to measure.
        if bytes.is_nan() || bytes > budget as f64 {
            let [x, y, z] = dims;
            return Err(Exceeded {
                what: format!(
                    "a light grid of {} × {} × {} voxels",
                    shown(x),
                    shown(y),
                    shown(z)
                ),
                bytes: bytes.min(usize::MAX as f64) as usize,
            });
        }
        Ok(Some(Extent {
            lo,
            dims: dims.map(|d| d as usize),
            cell,
            inv,
        }))
    }

    /// The voxels `parts` are spread over (a long segment one piece a voxel it crosses), as
    /// [`Light::deposit`] spreads them.
    fn pieces(&self, parts: &[Part]) -> f64 {
        let inv = self.extent.inv;
        let pieces = |part: &Part| {
            if part.area > 0.0 {
                1.0
            } else {
                length_in_voxels(part, inv).ceil().max(1.0)
            }
        };
        parts.iter().filter(|p| grid::finite(p)).map(pieces).sum()
    }

    /// Adds each part to the voxels it is in (`beam` holds the parts per voxel).
    fn deposit(&mut self, parts: &[Part]) {
        let inv = self.extent.inv;
        for part in parts.iter().filter(|p| grid::finite(p)) {
            let (from, to) = (part.from, part.to);
            let middle = [0, 1, 2].map(|a| 0.5 * (from[a] + to[a]));
            if part.area > 0.0 {
                let v = self.extent.index(self.extent.voxel_clamped(middle));
                self.beam[v] += (part.area * inv * inv).max(1.0) as f32;
                continue;
            }
            let cells = length_in_voxels(part, inv);
            if cells <= 1.0 {
                let v = self.extent.index(self.extent.voxel_clamped(middle));
                self.beam[v] += 1.0;
                continue;
            }
            let pieces = cells.ceil();
            let (step, weight) = (1.0 / pieces, (cells / pieces) as f32);
            for s in 0..pieces as usize {
                let t = (s as f64 + 0.5) * step;
                let p = [0, 1, 2].map(|a| from[a] + t * (to[a] - from[a]));
                let v = self.extent.index(self.extent.voxel_clamped(p));
                self.beam[v] += weight;
            }
        }
    }
}

/// The length of a segment in voxels (`inv`: one over a voxel's side).
fn length_in_voxels(part: &Part, inv: f64) -> f64 {
    let d = [0, 1, 2].map(|a| part.to[a] - part.from[a]);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() * inv
}

/// A vector resized to `len` in the allocation it has (given back when it is more than twice
/// what is needed); what it held before is left in it.
fn fit(v: &mut Vec<f32>, len: usize) {
    v.resize(len, 0.0);
    if v.capacity() > 2 * len {
        v.shrink_to(len);
    }
}

impl Responder for Light {
    fn reply_len(&self) -> usize {
        4
    }

    fn update(&mut self, parts: &[Part], budget: usize) -> Result<(), Exceeded> {
        self.extent = Extent::default();
        let Some(extent) = self.plan(parts, budget)? else {
            return Ok(());
        };
        self.extent = extent;
        // A voxel spread over costs a test's time (a write anywhere in the grid); the sweeps of
        // the propagation, row after row, a quarter of that each voxel.
        let work = self.pieces(parts) + extent.voxels() as f64 / 4.0;
        self.work.add(work.min(u64::MAX as f64) as u64);
        if self.work.over() {
            self.extent = Extent::default();
            return Ok(());
        }
        let dims = extent.dims;
        fit(&mut self.beam, extent.voxels());
        self.beam.fill(0.0);
        self.deposit(parts);
        if self.sky_counts() {
            // Every voxel written by the propagation: no need to clear it.
            fit(&mut self.shadow, extent.voxels());
            let pyramid = Pyramid {
                shadow: self.settings.shadow as f32,
                fade: (1.0 / self.settings.spread) as f32,
                depth: self.settings.depth,
            };
            shadow::propagate(
                &self.beam,
                dims,
                pyramid,
                &mut self.shadow,
                &mut self.shadow_planes,
            );
        }
        if self.sun_counts() {
            let toward = self.settings.sun_direction;
            sun::propagate(&mut self.beam, dims, toward, &mut self.sun_planes);
        }
        Ok(())
    }

    fn work(&mut self) -> Option<&mut Work> {
        Some(&mut self.work)
    }

    fn answer(&mut self, probes: &[Probe<'_>], replies: &mut [f64], stride: usize, offset: usize) {
        for (i, probe) in probes.iter().enumerate() {
            let at = i * stride + offset;
            if let Some(reply) = replies.get_mut(at..at + 4) {
                reply.copy_from_slice(&self.read(probe.position));
            }
        }
    }

    fn bytes(&self) -> usize {
        (self.beam.capacity() + self.shadow.capacity()) * F32
            + self.shadow_planes.bytes()
            + self.sun_planes.bytes()
    }

    fn field(&self) -> Option<Field> {
        if self.extent.voxels() == 0 {
            return None;
        }
        let values = (0..self.extent.voxels())
            .map(|v| self.exposure_of(v) as f32)
            .collect();
        Some(Field {
            origin: self.extent.origin(),
            cell: self.extent.cell,
            dims: self.extent.dims,
            values,
        })
    }
}
