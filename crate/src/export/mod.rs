//! Stage 6, `export`: what leaves the core as text. This version writes the statistics object
//! (`meristem derive --stats` and the studio's status line); the model formats (VRML, glTF,
//! POV-Ray, OBJ, …) will live here, one writer per module, each reading only [`MeshBuffers`] and
//! the skeleton.

use crate::mesh::MeshBuffers;
use serde::Serialize;

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
