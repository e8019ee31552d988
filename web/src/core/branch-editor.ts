// The branch editor over the core (`editPlant`, issue 8). Branch editing is in the whole
// boundary's module (crate/pkg, feature `studio-extras`), not in the first plant's (issue 22's
// first-load budget): the page loads this file and that module on its first edit
// (`loadBranchEditing`); in node, `initIo` with the module's bytes, then `editPlant`.
import { build as buildWithExtras, type PlantEditor as WasmPlantEditor } from '../../../crate/pkg/meristem.js';
import { DragRefused, type BranchInfo, type EditReport, type EditsDocument, type Handle, type MeshUpdate, type PlantEditor, type Vec3 } from './branches';
import { copyMesh, plainBuild, runBuildWith } from './build';
import { guarded, ownedArray } from './init';
import { assertIoReady, initIo } from './io';
import type { BuildOptions, MeshBuffers, PlantBuild, PlantStats } from './types';

/** Loads the module with branch editing once (the browser's hashed asset); then {@link editPlant} works. */
export function initBranchEditing(): Promise<void> {
  return initIo();
}

/**
 * Builds `source` like `buildPlant` and keeps the build alive behind a {@link PlantEditor}.
 * Starting to edit meshes the plant once more (to record where each part lies), so the first
 * editor call costs about one mesh stage. Requires `initIo` (the module with branch editing).
 */
export function editPlant(source: string, options: BuildOptions = {}): { build: PlantBuild; editor: PlantEditor } {
  assertIoReady();
  const result = runBuildWith(buildWithExtras, source, options);
  let plain: PlantBuild;
  try {
    plain = plainBuild(source, result);
  } catch (error) {
    result.free();
    throw error;
  }
  return { build: plain, editor: new LiveEditor(guarded(() => result.intoEditor())) };
}

/**
 * One branch of {@link LiveEditor.branches}: its path made when asked for, from its parents' ranks
 * (every path at once would be n²/2 numbers for a comb of n forks).
 */
class Branch implements BranchInfo {
  readonly children: number[] = [];

  constructor(
    readonly index: number,
    private readonly rank: number,
    readonly parent: number | null,
    private readonly tree: readonly Branch[],
  ) {}

  get path(): number[] {
    const path: number[] = [];
    for (let b: Branch | undefined = this; b; b = b.parent === null ? undefined : this.tree[b.parent]) path.push(b.rank);
    return path.reverse();
  }
}

/** A {@link PlantEditor} over the core's `PlantEditor` on this thread. */
class LiveEditor implements PlantEditor {
  private tree: BranchInfo[] | undefined;
  /** The roots, in the order of their paths' first number. */
  private roots: number[] | undefined;
  private triangleRanges: Uint32Array | undefined;
  private triangles = 0;

  constructor(private core: WasmPlantEditor) {}

  branches(): BranchInfo[] {
    if (!this.tree) {
      const ranks = guarded(() => this.core.branchRanks());
      const parents = guarded(() => this.core.branchParents());
      const tree: Branch[] = [];
      this.roots = [];
      for (let index = 0; index < ranks.length; index++) {
        const parent = parents[index] === 0xffffffff ? null : parents[index];
        tree.push(new Branch(index, ranks[index], parent, tree));
        if (parent === null) this.roots.push(index);
        else tree[parent].children.push(index);
      }
      this.tree = tree;
    }
    return this.tree;
  }

  /** Down from the roots by each index of `path` (as the core's `BranchTree::find`). */
  findBranch(path: readonly number[]): number | null {
    const tree = this.branches();
    let at: number | undefined = this.roots?.[path[0]];
    for (let k = 1; k < path.length && at !== undefined; k++) at = tree[at].children[path[k]];
    return path.length > 0 && at !== undefined ? at : null;
  }

  controlPoints(): Float32Array {
    return ownedArray(guarded(() => this.core.branchControlPoints()));
  }

  joints(branch: number): Float32Array {
    return ownedArray(guarded(() => this.core.branchJoints(branch)));
  }

  parameters(branch: number): Float32Array {
    return ownedArray(guarded(() => this.core.branchParameters(branch)));
  }

  branchAt(triangle: number): number | null {
    if (!this.triangleRanges) {
      this.triangleRanges = ownedArray(guarded(() => this.core.branchRanges()));
      this.triangles = (JSON.parse(guarded(() => this.core.stats())) as PlantStats).triangles;
    }
    const r = this.triangleRanges;
    // The last range whose first triangle is at or before `triangle`.
    let lo = 0;
    let hi = r.length / 2 - 1;
    if (hi < 0 || !Number.isInteger(triangle) || triangle < r[0] || triangle >= this.triangles) return null;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (r[2 * mid] <= triangle) lo = mid;
      else hi = mid - 1;
    }
    const branch = r[2 * lo + 1];
    return branch === 0xffffffff ? null : branch;
  }

  drag(branch: number, handle: Handle, position: Vec3): MeshUpdate {
    let full: boolean;
    try {
      full = guarded(() => this.core.drag(branch, handle, position[0], position[1], position[2]));
    } catch (error) {
      if (error instanceof Error && error.name === 'DragRefused') throw new DragRefused(error.message);
      throw error;
    }
    return this.update(full);
  }

  applyEdits(document: EditsDocument): { report: EditReport; update: MeshUpdate } {
    const report = JSON.parse(guarded(() => this.core.applyEdits(JSON.stringify(document)))) as EditReport;
    return { report, update: this.update(true) };
  }

  edits(): EditsDocument {
    return JSON.parse(guarded(() => this.core.edits())) as EditsDocument;
  }

  mesh(): MeshBuffers {
    return copyMesh(this.core);
  }

  free(): void {
    this.core.free();
  }

  private update(full: boolean): MeshUpdate {
    const core = this.core;
    const stats = JSON.parse(guarded(() => core.stats())) as PlantStats;
    if (full) {
      this.triangleRanges = undefined;
      const mesh = copyMesh(core);
      return {
        full,
        reason: guarded(() => core.changeReason()) ?? null,
        ranges: Uint32Array.of(0, mesh.positions.length / 3),
        positions: mesh.positions,
        normals: mesh.normals,
        uvs: mesh.uvs,
        growthOrigins: mesh.growthOrigins ?? new Float32Array(0),
        mesh,
        stats,
      };
    }
    return guarded(() => ({
      full,
      reason: null,
      ranges: ownedArray(core.changedRanges()),
      positions: ownedArray(core.changedPositions()),
      normals: ownedArray(core.changedNormals()),
      uvs: ownedArray(core.changedUvs()),
      growthOrigins: ownedArray(core.changedGrowthOrigins()),
      mesh: null,
      stats,
    }));
  }
}
