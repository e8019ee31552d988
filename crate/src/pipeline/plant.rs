//! The plant a build made: the turtle's skeleton and its mesh, with the counts the studio shows.

use crate::derive::Derivation;
use crate::export::Stats;
use crate::mesh::{self, MeshBuffers, MeshOptions};
use crate::turtle::{Skeleton, Sketch};
use std::borrow::Cow;

/// The geometry of one build.
#[derive(Clone, Debug, Default)]
pub struct Plant {
    pub skeleton: Skeleton,
    pub mesh: MeshBuffers,
    /// The options the mesh was last built with.
    pub mesh_options: MeshOptions,
    pub stats: Stats,
    /// Modules in the derived string, and derivation steps run (for the stats).
    modules: usize,
    steps: u32,
    /// For each module of the string the turtle read, the module of the derived string it came
    /// from (empty when they are the same string): the mesh's provenance names derived modules.
    turtle_origin: Vec<u32>,
    /// A sketch's plant ([`Plant::sketched`]): the skeleton is not drawn yet, the mesh holds the
    /// segments as lines; these are the lines' modules and whether the drawing is flat.
    sketch: Option<(Vec<u32>, bool)>,
    /// The skeleton would pass [`crate::turtle::MAX_SKELETON_BYTES`]: the plant stays a sketch's
    /// lines (`E0414`), and nothing draws its skeleton.
    lines_only: bool,
}

impl Plant {
    /// Meshes `skeleton`, which the turtle drew from `derivation`'s string after `steps` steps.
    pub fn new(
        skeleton: Skeleton,
        options: &MeshOptions,
        derivation: &Derivation,
        steps: u32,
    ) -> Plant {
        let mut plant = Plant {
            skeleton,
            modules: derivation.string.len(),
            steps,
            turtle_origin: derivation.turtle_origin.clone(),
            ..Plant::default()
        };
        plant.remesh(options);
        plant
    }

    /// The plant of a sketch (`BuildOptions::sketch`): its segments as lines in the mesh's line
    /// arrays, as the lines fallback has them, and no skeleton until
    /// [`crate::pipeline::Build::ensure_skeleton`] draws it.
    pub fn sketched(
        sketch: Sketch,
        options: &MeshOptions,
        derivation: &Derivation,
        steps: u32,
    ) -> Plant {
        let flat = sketch.is_flat();
        let segments = sketch.segments();
        let bounds = sketch.line_bounds();
        let lines = sketch.lines;
        let mesh = MeshBuffers {
            lines: lines.ends,
            line_colors: lines.colors,
            ..MeshBuffers::default()
        };
        let modules = derivation.string.len();
        Plant {
            stats: Stats {
                modules,
                segments,
                vertices: 0,
                triangles: 0,
                lines: segments,
                iterations: steps,
                bounds,
            },
            skeleton: Skeleton::default(),
            mesh,
            mesh_options: options.clone(),
            modules,
            steps,
            turtle_origin: derivation.turtle_origin.clone(),
            sketch: Some((lines.modules, flat)),
            lines_only: false,
        }
    }

    /// True for the plant of a sketch whose skeleton is not drawn yet.
    pub fn is_sketch(&self) -> bool {
        self.sketch.is_some()
    }

    /// True for a sketch's plant whose skeleton would pass its budget: lines only, for good.
    pub fn is_lines_only(&self) -> bool {
        self.lines_only
    }

    /// Marks a sketch's plant as one whose skeleton is never drawn ([`Plant::is_lines_only`]).
    pub(super) fn keep_lines_only(&mut self) {
        self.lines_only = self.sketch.is_some();
    }

    /// The skeleton of a sketch's plant, drawn now: the plant is a plain one from here on (its
    /// mesh is still the sketch's lines until [`Plant::remesh`]).
    pub(super) fn set_skeleton(&mut self, skeleton: Skeleton) {
        self.skeleton = skeleton;
        self.sketch = None;
    }

    /// Meshes the skeleton again with other options (the stats follow). The skeleton of a
    /// sketch's plant must be drawn first ([`crate::pipeline::Build::remesh`] does).
    pub fn remesh(&mut self, options: &MeshOptions) {
        self.mesh_options = options.clone();
        let counts = &mut self.skeleton.step_counts;
        if options.with_growth() && counts.len() != self.steps as usize + 1 {
            // Not counted while deriving: the plant grows evenly over its steps.
            *counts = (0..=self.steps).map(f64::from).collect();
        }
        self.mesh = mesh::build_mesh(&self.skeleton, options);
        self.meshed();
    }

    /// After a whole new mesh (here or by an editor): provenance in terms of the derived string,
    /// and the stats.
    pub(super) fn meshed(&mut self) {
        if !self.turtle_origin.is_empty() {
            for pair in self.mesh.ranges.chunks_exact_mut(2) {
                pair[1] = self
                    .turtle_origin
                    .get(pair[1] as usize)
                    .copied()
                    .unwrap_or(pair[1]);
            }
        }
        self.stats = Stats::new(
            self.modules,
            self.skeleton.segments.len(),
            self.steps,
            &self.mesh,
        );
        if !self.mesh_options.tubes {
            self.stats.bounds = self.bounds_with_segments();
        }
    }

    /// The bounds of the mesh and of the segments as lines (as `f32`, as the lines are drawn):
    /// what a mesh without tubes shows, with the segments drawn as lines over it.
    fn bounds_with_segments(&self) -> [[f64; 3]; 2] {
        let mut min = [f64::INFINITY; 3];
        let mut max = [f64::NEG_INFINITY; 3];
        if !self.mesh.positions.is_empty() || !self.mesh.lines.is_empty() {
            [min, max] = self.stats.bounds;
        }
        for s in &self.skeleton.segments {
            for p in [s.start, s.end] {
                for (k, v) in p.to_array().into_iter().enumerate() {
                    let v = v as f32 as f64;
                    min[k] = min[k].min(v);
                    max[k] = max[k].max(v);
                }
            }
        }
        if min[0] > max[0] {
            return [[0.0; 3]; 2];
        }
        [min, max]
    }

    /// Every segment as a line (the studio's Lines mode), its module in terms of the derived
    /// string, as the mesh's provenance.
    pub fn segment_lines(&self) -> mesh::SegmentLines {
        mesh::SegmentLines {
            ends: self.segment_ends().into_owned(),
            colors: self.segment_colors().into_owned(),
            modules: self.segment_modules(),
        }
    }

    /// [`Plant::segment_lines`]'s ends alone (a sketch's are its lines already): each of the three
    /// is made on its own, so that asking for all three draws the segments once.
    pub fn segment_ends(&self) -> Cow<'_, [f32]> {
        match &self.sketch {
            Some(_) => Cow::Borrowed(&self.mesh.lines),
            None => Cow::Owned(mesh::segment_ends(&self.skeleton)),
        }
    }

    /// [`Plant::segment_lines`]'s colours alone.
    pub fn segment_colors(&self) -> Cow<'_, [f32]> {
        match &self.sketch {
            Some(_) => Cow::Borrowed(&self.mesh.line_colors),
            None => Cow::Owned(mesh::segment_colors(&self.skeleton)),
        }
    }

    /// [`Plant::segment_lines`]'s modules alone, in terms of the derived string.
    pub fn segment_modules(&self) -> Vec<u32> {
        let mut modules = match &self.sketch {
            Some((modules, _)) => modules.clone(),
            None => mesh::segment_modules(&self.skeleton),
        };
        if !self.turtle_origin.is_empty() {
            for module in &mut modules {
                *module = self
                    .turtle_origin
                    .get(*module as usize)
                    .copied()
                    .unwrap_or(*module);
            }
        }
        modules
    }

    /// True when everything drawn lies in the plane z = 0 ([`Skeleton::is_flat`]).
    pub fn is_flat(&self) -> bool {
        match &self.sketch {
            Some((_, flat)) => *flat,
            None => self.skeleton.is_flat(),
        }
    }
}
