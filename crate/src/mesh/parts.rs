//! Where each element of the skeleton lies in a mesh, and meshing one element alone: what a
//! partial re-mesh (dragging a branch, issue 8) uses to rebuild a few tubes and move the others
//! instead of meshing the whole plant again.
//!
//! [`build_mesh`](super::build_mesh) writes the tubes of the chains in order, then the polygons,
//! the leaves and petals, and the spheres, each into one contiguous run of vertices and of
//! triangles (a [`Part`]). Meshing an element alone ([`chain_mesh`] …) writes exactly what
//! `build_mesh` writes for it, from vertex 0: when its counts are those of its part, it can be
//! copied over the part (indices shifted by the part's first vertex), and the provenance and
//! colour ranges stay true as long as each triangle comes from the same segment as before
//! ([`ChainPart::ranges`]).

use super::build::Builder;
use super::{MeshBuffers, MeshOptions};
use crate::turtle::Skeleton;

/// Not in a chain (a segment of zero width), or not a segment (in element ranges).
pub const NO_CHAIN: u32 = u32::MAX;

/// A contiguous run of vertices and of triangles in a mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Part {
    pub first_vertex: u32,
    pub vertices: u32,
    pub first_triangle: u32,
    pub triangles: u32,
}

/// The tube of one chain.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ChainPart {
    pub part: Part,
    /// Its segments in order.
    pub segments: Vec<u32>,
    /// Whether its start is capped (it does not start at another segment's end).
    pub start_cap: bool,
    /// Whether its end is rounded (another segment starts there: a branch leaves it).
    pub end_dome: bool,
    /// (first triangle counted from the part's first, segment) pairs: the segment that drew
    /// each of its triangles (which gives their module and colour index).
    pub ranges: Vec<u32>,
}

/// The layout of a mesh by skeleton element.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshParts {
    pub chains: Vec<ChainPart>,
    /// For each segment, its chain (`NO_CHAIN` when it has no tube).
    pub segment_chain: Vec<u32>,
    /// One part per polygon, per surface and per sphere of the skeleton (empty parts for those
    /// that drew nothing).
    pub polygons: Vec<Part>,
    pub surfaces: Vec<Part>,
    pub spheres: Vec<Part>,
    /// The mesh is the lines fallback: there are no parts.
    pub lines: bool,
}

/// A set of points as exact keys ([`super::joint_key`]): an open-addressing hash table with
/// linear probing, at least twice as long as its points, each slot one word: 32 bits of the key's
/// hash and the index of a point with that key (the keys themselves stay in `keys`, written in
/// order). It replaced sorting the keys of every segment and searching them (issue 20): the two
/// sorts of 116,050 three-word keys through `crate::sort` were about a quarter of the mesh stage
/// of ABOP 1.24d n = 10 natively. The table's size matters more than its probing: a table of
/// whole keys (24 bytes a slot) spent its time in cache misses, and so the mesh stage holds the
/// few points it asks about in one ([`chain_ends`]) rather than every segment's. The standard
/// library's hash set was measured slower (its hasher).
///
/// Most points asked about are not in the set (a segment's end is seldom where a chain starts):
/// a bit per hash value's top bits, four for each slot (so at least eight for each point), answers
/// most of them from a table of 32 KB for 1.24d n = 10 instead of the slots' 512 KB, which the pass
/// over the segments keeps out of the cache (half of `index_of`'s time was that load).
#[derive(Clone, Debug, Default)]
struct PointSet {
    keys: Vec<[u64; 3]>,
    /// `hash << 32 | (index + 1)` (the hash's low half: its high bits pick the slot), 0 where a slot is free; a power of two long.
    slots: Vec<u64>,
    /// The bit numbered by the top bits of each key's hash (two more than pick its slot), four
    /// bits a slot: a clear bit means the key is not in the set.
    filter: Vec<u64>,
}

impl PointSet {
    fn with_points(points: impl ExactSizeIterator<Item = glam::DVec3>) -> PointSet {
        let capacity = (2 * points.len()).max(16).next_power_of_two();
        let mut set = PointSet {
            keys: points.map(super::chains::key).collect(),
            slots: vec![0; capacity],
            // Four times the slots: 64 bits a word.
            filter: vec![0; capacity / 16],
        };
        let mask = capacity - 1;
        for index in 0..set.keys.len() {
            let key = &set.keys[index];
            let h = hash(key);
            let (bit, word) = set.filter_bit(h);
            set.filter[word] |= bit;
            let (mut i, tag) = set.slot(h);
            loop {
                let slot = set.slots[i];
                if slot == 0 {
                    set.slots[i] = tag | (index as u64 + 1);
                    break;
                }
                if slot >> 32 == tag >> 32 && set.keys[(slot as u32 - 1) as usize] == *key {
                    break;
                }
                i = (i + 1) & mask;
            }
        }
        set
    }

    /// The first slot to probe for a key of hash `h`, and the hash's high half as a slot's tag.
    fn slot(&self, h: u64) -> (usize, u64) {
        let bits = self.slots.len().trailing_zeros();
        ((h >> (64 - bits)) as usize, h << 32)
    }

    /// The filter's bit for the hash `h`, and the word it is in.
    fn filter_bit(&self, h: u64) -> (u64, usize) {
        let bits = (64 * self.filter.len()).trailing_zeros();
        let at = (h >> (64 - bits)) as usize;
        (1 << (at % 64), at / 64)
    }

    /// Whether the point with this exact key is in the set.
    #[cfg(test)]
    fn contains(&self, key: &[u64; 3]) -> bool {
        self.index_of(key).is_some()
    }

    /// The index of the first point with this exact key, if any.
    fn index_of(&self, key: &[u64; 3]) -> Option<usize> {
        if self.slots.is_empty() {
            return None;
        }
        let h = hash(key);
        let (bit, word) = self.filter_bit(h);
        if self.filter[word] & bit == 0 {
            return None;
        }
        let mask = self.slots.len() - 1;
        let (mut i, tag) = self.slot(h);
        loop {
            let slot = self.slots[i];
            if slot == 0 {
                return None;
            }
            let index = (slot as u32 - 1) as usize;
            if slot >> 32 == tag >> 32 && self.keys[index] == *key {
                return Some(index);
            }
            i = (i + 1) & mask;
        }
    }
}

/// A point key's hash: Fibonacci hashing, the product's top bits mixing all of the key's bits.
#[inline]
fn hash(key: &[u64; 3]) -> u64 {
    const K: u64 = 0x9E37_79B9_7F4A_7C15;
    ((key[0].wrapping_mul(K) ^ key[1]).wrapping_mul(K) ^ key[2]).wrapping_mul(K)
}

/// Whether each chain's tube (its segments, in order) gets a start cap (it does not start where a
/// segment ends: a branch growing out of a joint starts inside its parent's tube) and a rounded
/// end (a segment starts at its end: branches leave there, and grow out of a round joint, not a
/// stump), as `(start_cap, end_dome)`: what `build_mesh` asks of every chain, and the branch
/// editor of the chains it keeps.
///
/// The chains' starts and ends are put in two sets and every segment's end and start looked up
/// in them, in one pass. Sets of the points asked stay in the cache, where sets of all the
/// segments' ends and starts, asked about each chain, spent about a sixth of the mesh stage of
/// ABOP 1.24d n = 10 (19,683 chains, 116,050 segments) in cache misses.
pub fn chain_ends<'c>(
    skeleton: &Skeleton,
    chains: impl ExactSizeIterator<Item = &'c [u32]> + Clone,
) -> Vec<(bool, bool)> {
    if chains.len() == 0 {
        return Vec::new(); // no tubes (the Lines mode): no pass over the segments
    }
    let segments = &skeleton.segments;
    let mut joints = Asked::new(chains.clone().map(|c| segments[c[0] as usize].start));
    let mut branchings = Asked::new(chains.map(|c| end_of(skeleton, c)));
    // One pass over the segments (136 bytes each) for both questions.
    for s in segments {
        joints.look_for(s.end);
        branchings.look_for(s.start);
    }
    let answers = joints.answers().zip(branchings.answers());
    answers
        .map(|(joint, branching)| (!joint, branching))
        .collect()
}

/// The end point of a chain.
fn end_of(skeleton: &Skeleton, chain: &[u32]) -> glam::DVec3 {
    skeleton.segments[chain[chain.len() - 1] as usize].end
}

/// Points asked about: whether each is exactly one of the points looked for.
struct Asked {
    set: PointSet,
    /// Per key's first point (where the set's slot points).
    met: Vec<bool>,
}

impl Asked {
    fn new(asked: impl ExactSizeIterator<Item = glam::DVec3>) -> Asked {
        let set = PointSet::with_points(asked);
        let met = vec![false; set.keys.len()];
        Asked { set, met }
    }

    fn look_for(&mut self, p: glam::DVec3) {
        if let Some(i) = self.set.index_of(&super::chains::key(p)) {
            self.met[i] = true;
        }
    }

    /// For each point asked, in order, whether it was met.
    fn answers(&self) -> impl Iterator<Item = bool> + '_ {
        let set = &self.set;
        set.keys
            .iter()
            .map(|k| set.index_of(k).is_some_and(|i| self.met[i]))
    }
}

/// The chains (axes cut where widths are zero, joints sharp, smoothness changes or a wide ring
/// would overrun a short segment), as
/// [`super::build_mesh`] cuts them.
pub fn chains(skeleton: &Skeleton, unit: f64) -> super::Chains {
    super::chains::chains(skeleton, unit)
}

/// Whether segment `i` continues segment `p` in one tube (given that it continues it on the
/// axis and is the first to).
pub fn joins(skeleton: &Skeleton, p: u32, i: u32, unit: f64) -> bool {
    super::chains::joins(skeleton, p as usize, i as usize, unit)
}

/// The tube of one chain alone, as `build_mesh` writes it, and its element ranges.
pub fn chain_mesh(
    skeleton: &Skeleton,
    options: &MeshOptions,
    unit: f64,
    chain: &[u32],
    start_cap: bool,
    end_dome: bool,
) -> (MeshBuffers, Vec<u32>) {
    let mut builder = Builder::new(options, unit);
    builder.tube(skeleton, chain, start_cap, end_dome);
    let ranges = builder.element_ranges_since(&[0, 0, 0]);
    (builder.mesh, ranges)
}

/// One polygon alone.
pub fn polygon_mesh(
    skeleton: &Skeleton,
    options: &MeshOptions,
    unit: f64,
    i: usize,
) -> MeshBuffers {
    alone(options, unit, |builder| builder.polygon(skeleton, i))
}

/// One leaf or petal alone.
pub fn surface_mesh(
    skeleton: &Skeleton,
    options: &MeshOptions,
    unit: f64,
    i: usize,
) -> MeshBuffers {
    alone(options, unit, |builder| builder.surface(skeleton, i))
}

/// One sphere alone.
pub fn sphere_mesh(skeleton: &Skeleton, options: &MeshOptions, unit: f64, i: usize) -> MeshBuffers {
    alone(options, unit, |builder| builder.sphere_of(skeleton, i))
}

/// The mesh `draw` writes into a new builder: one element meshed alone.
fn alone(options: &MeshOptions, unit: f64, draw: impl FnOnce(&mut Builder)) -> MeshBuffers {
    let mut builder = Builder::new(options, unit);
    draw(&mut builder);
    builder.mesh
}

/// Copies `alone` (one element meshed alone) over `part` of `mesh`: positions, normals and uvs, and
/// the indices when `indices` (their pattern may differ, e.g. a polygon triangulated anew).
/// Returns false, changing nothing, when the counts differ.
pub fn write_part(mesh: &mut MeshBuffers, part: &Part, alone: &MeshBuffers, indices: bool) -> bool {
    if alone.vertex_count() != part.vertices as usize
        || alone.triangle_count() != part.triangles as usize
    {
        return false;
    }
    let v = 3 * part.first_vertex as usize;
    let n = alone.positions.len();
    mesh.positions[v..v + n].copy_from_slice(&alone.positions);
    mesh.normals[v..v + n].copy_from_slice(&alone.normals);
    let u = 2 * part.first_vertex as usize;
    mesh.uvs[u..u + alone.uvs.len()].copy_from_slice(&alone.uvs);
    if indices {
        let t = 3 * part.first_triangle as usize;
        for (to, from) in mesh.indices[t..t + alone.indices.len()]
            .iter_mut()
            .zip(&alone.indices)
        {
            *to = from + part.first_vertex;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pipeline::{build, BuildOptions};

    #[test]
    fn parts_cover_the_mesh_and_each_element_meshes_alone_to_its_part() {
        let source =
            "#angle 30\n#surface a disk\naxiom: X\nX -> F[+X~l][-X{.f.f.}~a(0.5)]F@O(0.1)X\nF -> FF";
        let result = build(source, &BuildOptions::with_iterations(3));
        let options = MeshOptions::default();
        let (mesh, parts) = super::super::build_mesh_with_parts(&result.plant.skeleton, &options);
        assert_eq!(mesh, result.plant.mesh);
        let unit = mesh.width_unit;
        let all: Vec<Part> = parts
            .chains
            .iter()
            .map(|c| c.part)
            .chain(parts.polygons.iter().copied())
            .chain(parts.surfaces.iter().copied())
            .chain(parts.spheres.iter().copied())
            .collect();
        let (mut v, mut t) = (0, 0);
        for p in &all {
            assert_eq!((p.first_vertex, p.first_triangle), (v, t));
            v += p.vertices;
            t += p.triangles;
        }
        assert_eq!(
            (v as usize, t as usize),
            (mesh.vertex_count(), mesh.triangle_count())
        );
        assert!(
            !parts.surfaces.is_empty() && !parts.polygons.is_empty() && !parts.spheres.is_empty()
        );

        // Rewriting every part from its element meshed alone gives the same mesh.
        let mut copy = mesh.clone();
        copy.positions.iter_mut().for_each(|x| *x = 0.0);
        for c in &parts.chains {
            let (alone, ranges) = chain_mesh(
                &result.plant.skeleton,
                &options,
                unit,
                &c.segments,
                c.start_cap,
                c.end_dome,
            );
            assert_eq!(ranges, c.ranges);
            assert!(write_part(&mut copy, &c.part, &alone, true));
        }
        for (i, p) in parts.polygons.iter().enumerate() {
            assert!(write_part(
                &mut copy,
                p,
                &polygon_mesh(&result.plant.skeleton, &options, unit, i),
                true
            ));
        }
        for (i, p) in parts.surfaces.iter().enumerate() {
            assert!(write_part(
                &mut copy,
                p,
                &surface_mesh(&result.plant.skeleton, &options, unit, i),
                true
            ));
        }
        for (i, p) in parts.spheres.iter().enumerate() {
            assert!(write_part(
                &mut copy,
                p,
                &sphere_mesh(&result.plant.skeleton, &options, unit, i),
                true
            ));
        }
        assert_eq!(copy, mesh);
        // A part of another size is refused.
        let (alone, _) = chain_mesh(
            &result.plant.skeleton,
            &options,
            unit,
            &parts.chains[0].segments,
            true,
            false,
        );
        let small = Part {
            vertices: 3,
            ..parts.chains[0].part
        };
        assert!(!write_part(&mut copy, &small, &alone, false));
    }

    #[test]
    fn point_sets_hold_exactly_their_points() {
        use glam::DVec3;
        // Many points (probing past collisions in a table of 2^k slots), repeated ones, and the
        // two zeros as one point.
        let points: Vec<DVec3> = (0..5000)
            .map(|i| DVec3::new((i % 70) as f64 * 0.1, (i / 70) as f64 * 0.3, 0.0))
            .chain([DVec3::new(-0.0, 0.0, 0.0), DVec3::new(0.1, 0.0, 0.0)])
            .collect();
        let set = PointSet::with_points(points.iter().copied());
        for p in &points {
            assert!(set.contains(&super::super::chains::key(*p)), "{p}");
        }
        for p in [
            DVec3::new(0.05, 0.0, 0.0),
            DVec3::new(0.1, 0.0, 1e-300),
            DVec3::new(0.1 + f64::EPSILON, 0.0, 0.0),
            DVec3::new(7.0, 0.0, 0.0),
        ] {
            assert!(!set.contains(&super::super::chains::key(p)), "{p}");
        }
        assert!(set.contains(&super::super::chains::key(DVec3::new(0.0, -0.0, -0.0))));
        assert!(!PointSet::default().contains(&super::super::chains::key(DVec3::ZERO)));
    }
}
