// Editing a plant's branches by their Bézier handles (issue 8): the facade over the core's branch
// editor (crate/src/branches). A branch is a run of segments along one axis between branching
// points; its path is its root's index, then child indices (docs/LANGUAGE.md, "Branches").
// The editor itself (`editPlant`) is in ./branch-editor.ts, loaded on the first edit; the check of
// an edits document from outside (`validateEdits`) in ./edits-check.ts, loaded with the first.
import type { MeshBuffers, PlantStats } from './types';

/**
 * A drag the core refused, changing nothing: its target is further from the handle's place than
 * an edits document can hold (1,000 branch lengths), or the branch has no length. A user's drag
 * past the reach, not a bug: the handle stays where it last was.
 */
export class DragRefused extends Error {
  override name = 'DragRefused';
}

/** A point or an offset: x, y, z. */
export type Vec3 = [number, number, number];

/** The draggable handles of a branch's curve: P1, P2 and the end P3 (P0 is where it attaches). */
export type Handle = 1 | 2 | 3;

/** The version of the edits document this core reads and writes. */
export const EDITS_VERSION = 1;

/**
 * An override of one branch's handles: the offsets of P1, P2, P3 from their fitted places, each as
 * (heading, left, up) components in the branch's start frame, in units of the branch's length.
 */
export interface BranchEdit {
  path: number[];
  handles: [Vec3, Vec3, Vec3];
}

/**
 * The edits document (docs/LANGUAGE.md, "Branch edits"): what share links, the undo history and
 * `meristem export --edits` carry.
 */
export interface EditsDocument {
  version: typeof EDITS_VERSION;
  edits: BranchEdit[];
}

/** One branch of the plant. `index` is what the editor's other methods take. */
export interface BranchInfo {
  readonly index: number;
  /** Its path (what an edits document names it by), made when read: read it for one branch. */
  readonly path: number[];
  /** Its parent's index; null for a root. */
  parent: number | null;
  /** Its children's indices, in the order they appear in the string. */
  children: number[];
}

/** What applying edits did: every edit is applied or listed with the reason it is not. */
export interface EditReport {
  applied: number[][];
  notApplied: { path: number[]; reason: string }[];
}

/**
 * What a change did to the mesh. When `full`, the mesh was rebuilt whole (its sizes may differ):
 * `mesh` holds every array. Otherwise only the vertices in `ranges` changed, and `positions` /
 * `normals` hold their new values, range after range (apply them with {@link applyMeshUpdate}).
 */
export interface MeshUpdate {
  full: boolean;
  /** Why the mesh was rebuilt whole (null when it was not). */
  reason: string | null;
  /** (first vertex, count) pairs, sorted and disjoint. */
  ranges: Uint32Array;
  positions: Float32Array;
  normals: Float32Array;
  /** Texture coordinates of the changed vertices (2 floats each). */
  uvs: Float32Array;
  /**
   * Growth origins of the changed vertices (3 floats each; empty when the mesh has no growth
   * arrays): a moved branch grows from where it is now. Growth times do not change (an edit moves
   * where a branch grows, not when).
   */
  growthOrigins: Float32Array;
  /** The whole new mesh, when `full`. */
  mesh: MeshBuffers | null;
  /** The plant's stats after the change (its bounds move with its branches). */
  stats: PlantStats;
}

/** A plant whose branches can be edited; it keeps the core's build alive until `free`. */
export interface PlantEditor {
  /** The branches, parents before children (the tree never changes for one build). */
  branches(): BranchInfo[];
  /** The index of the branch at `path`, or null when there is none. */
  findBranch(path: readonly number[]): number | null;
  /** Every branch's control points P0, P1, P2, P3 where they are now: 12 floats per branch. */
  controlPoints(): Float32Array;
  /** The joints of one branch where they are now (3 floats each). */
  joints(branch: number): Float32Array;
  /** The parameter of each joint of one branch on its curve (0 to 1, by length). */
  parameters(branch: number): Float32Array;
  /** The branch that drew triangle `triangle` of the current mesh, or null. */
  branchAt(triangle: number): number | null;
  /**
   * Moves handle `handle` of `branch` to `position` (world coordinates): the branch's edit
   * changes, it and its descendants move, and only what moved is re-meshed. Throws on a bad
   * branch, handle or position (a caller's bug, not a user's), and {@link DragRefused} for a
   * target whose edit an edits document could not hold (nothing changes): so `edits()` always
   * gives a document `applyEdits` and {@link validateEdits} accept.
   */
  drag(branch: number, handle: Handle, position: Vec3): MeshUpdate;
  /** Replaces every edit by `document`'s (rebuilding the whole mesh); throws when malformed. */
  applyEdits(document: EditsDocument): { report: EditReport; update: MeshUpdate };
  /** The edits in force (applied ones only). */
  edits(): EditsDocument;
  /** A copy of the whole current mesh. */
  mesh(): MeshBuffers;
  /** Releases the core's memory; the editor must not be used afterwards. */
  free(): void;
}

/** The empty edits document. */
export function noEdits(): EditsDocument {
  return { version: EDITS_VERSION, edits: [] };
}

/**
 * Writes a partial update into `mesh` (the page's own copy) and returns it; after a full update,
 * returns the update's new mesh instead.
 */
export function applyMeshUpdate(mesh: MeshBuffers, update: MeshUpdate): MeshBuffers {
  if (update.full && update.mesh) return update.mesh;
  let at = 0;
  let uv = 0;
  for (let k = 0; k < update.ranges.length; k += 2) {
    const from = 3 * update.ranges[k];
    const n = 3 * update.ranges[k + 1];
    mesh.positions.set(update.positions.subarray(at, at + n), from);
    mesh.normals.set(update.normals.subarray(at, at + n), from);
    at += n;
    const m = 2 * update.ranges[k + 1];
    if (update.uvs.length >= uv + m && mesh.uvs.length >= 2 * update.ranges[k] + m) mesh.uvs.set(update.uvs.subarray(uv, uv + m), 2 * update.ranges[k]);
    uv += m;
    if (update.growthOrigins.length >= at && mesh.growthOrigins && mesh.growthOrigins.length >= from + n) mesh.growthOrigins.set(update.growthOrigins.subarray(at - n, at), from);
  }
  return mesh;
}
