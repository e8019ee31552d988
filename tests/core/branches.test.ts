// Cross-boundary tests of branch editing (issue 8): the TypeScript facade over the REAL WebAssembly
// core, against itself (a partial update applied to the page's copy equals the core's whole mesh)
// and against the command-line tool (a download with edits is `meristem export --edits`'s file).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import {
  applyMeshUpdate,
  DragRefused,
  exportModel,
  exportModelWithProgress,
  initCore,
  noEdits,
  type EditsDocument,
  type MeshBuffers,
  type PlantEditor,
  type Vec3,
} from '../../web/src/core';
// Not in the core's index: the page loads it on the first edit (loadBranchEditing, issue 22).
import { editPlant } from '../../web/src/core/branch-editor';
import { validateEdits } from '../../web/src/core/edits-check';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const GAME_TREE = readFileSync(new URL('../../public/examples/game-tree.lsys', import.meta.url), 'utf8');
const LEAFY = '#angle 22.5\n#width 3\naxiom: A\nA -> !(2)F[&(30)FL@O(0.05)A]/(137)[&(30)F{.+f.-f.-f.}A]F/(90)A\nL -> ~l(0.4)';

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
});

function point(array: Float32Array, k: number): Vec3 {
  return [array[3 * k], array[3 * k + 1], array[3 * k + 2]];
}

/** Exactly the same values (typed arrays are too large for `toEqual`'s diffing). */
function same(a: Float32Array | Uint32Array, b: Float32Array | Uint32Array): boolean {
  return a.length === b.length && Buffer.from(a.buffer, a.byteOffset, a.byteLength).equals(Buffer.from(b.buffer, b.byteOffset, b.byteLength));
}

/** The POSITION accessor of a GLB (one mesh sharing one POSITION accessor, as ours are). */
function glbPositions(bytes: Uint8Array): Float32Array {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  const json = JSON.parse(new TextDecoder().decode(bytes.subarray(20, 20 + jsonLength))) as {
    meshes: { primitives: { attributes: { POSITION: number } }[] }[];
    accessors: { bufferView: number; byteOffset?: number; count: number }[];
    bufferViews: { byteOffset?: number }[];
  };
  const accessor = json.accessors[json.meshes[0].primitives[0].attributes.POSITION];
  const start = 20 + jsonLength + 8 + (json.bufferViews[accessor.bufferView].byteOffset ?? 0) + (accessor.byteOffset ?? 0);
  return new Float32Array(bytes.slice(start, start + 12 * accessor.count).buffer);
}

function worst(a: Float32Array, b: Float32Array): number {
  expect(a.length).toBe(b.length);
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

describe('a comb of 60,000 segments, the most the studio edits', () => {
  // 1,875 steps of 16 forks: 30,000 forks along one axis, the deepest branch 30,001 deep. The
  // tree kept every branch's whole path (n²/2 numbers, 3.6 GB in the core, then as JSON): the
  // page's core trapped. Paths are now made when one is asked for.
  it('opens for editing, and its deepest branch is found by its path', () => {
    const comb = `#max_steps 2000\n#max_modules 40000000\naxiom: A\nA -> ${'F[+F]'.repeat(16)}A`;
    const { build, editor } = editPlant(comb, { iterations: 1875 });
    try {
      expect(build.stats.segments).toBe(60_000);
      const branches = editor.branches();
      // (Parents come before children: each depth from its parent's, no path made.)
      const depth: number[] = [];
      for (const b of branches) depth.push(b.parent === null ? 1 : depth[b.parent] + 1);
      const deepest = branches[depth.indexOf(Math.max(...depth))];
      const path = deepest.path;
      expect(path.length).toBe(30_001);
      expect(editor.findBranch(path)).toBe(deepest.index);
    } finally {
      editor.free();
    }
  }, 120_000);
});

describe('the branches of the game tree', () => {
  let editor: PlantEditor;
  let mesh: MeshBuffers;
  beforeAll(() => {
    const opened = editPlant(GAME_TREE);
    editor = opened.editor;
    mesh = opened.build.mesh;
  });
  afterAll(() => editor.free());

  it('are a tree of paths: one root, children in order, each path its parent’s plus an index', () => {
    const branches = editor.branches();
    expect(branches.length).toBe(364);
    expect(branches[0]).toMatchObject({ index: 0, path: [0], parent: null });
    expect(branches[0].children.length).toBe(3);
    for (const b of branches) {
      if (b.parent === null) continue;
      const parent = branches[b.parent];
      expect(b.path).toEqual([...parent.path, parent.children.indexOf(b.index)]);
      expect(editor.findBranch(b.path)).toBe(b.index);
    }
    expect(editor.findBranch([0, 7])).toBeNull();
    expect(editor.controlPoints().length).toBe(12 * 364);
  });

  it('have control points from their attachment to their tip, and joints at parameters 0 to 1', () => {
    const bough = editor.findBranch([0, 0])!;
    const control = editor.controlPoints().subarray(12 * bough, 12 * bough + 12);
    const joints = editor.joints(bough);
    const params = editor.parameters(bough);
    expect(joints.length / 3).toBe(10);
    expect(params.length).toBe(10);
    expect(params[0]).toBe(0);
    expect(params[9]).toBe(1);
    expect(point(control, 0)).toEqual(point(joints, 0));
    expect(point(control, 3)).toEqual(point(joints, 9));
    // The bough grows out of the trunk's end joint.
    const trunk = editor.joints(0);
    expect(point(joints, 0)).toEqual(point(trunk, 9));
  });

  it('are picked by triangle', () => {
    // The first triangles are the trunk's tube.
    expect(editor.branchAt(0)).toBe(0);
    expect(editor.branchAt(-1)).toBeNull();
    expect(editor.branchAt(mesh.indices.length / 3)).toBeNull();
    const seen = new Set<number | null>();
    for (let t = 0; t < mesh.indices.length / 3; t += 97) seen.add(editor.branchAt(t));
    expect(seen.size).toBeGreaterThan(300);
    expect(seen.has(null)).toBe(false);
  });

  it('drag with only the changed vertices crossing the boundary, which patch the page’s copy into the core’s mesh', () => {
    const bough = editor.findBranch([0, 0])!;
    const p3 = point(editor.controlPoints(), 4 * bough + 3);
    let copy: MeshBuffers = { ...mesh, positions: mesh.positions.slice(), normals: mesh.normals.slice() };
    for (let frame = 1; frame <= 3; frame++) {
      const target: Vec3 = [p3[0] + 0.1 * frame, p3[1] - 0.05, p3[2] + 0.02];
      const update = editor.drag(bough, 3, target);
      expect(update.full).toBe(false);
      expect(update.mesh).toBeNull();
      const changed = update.positions.length / 3;
      expect(changed).toBeGreaterThan(mesh.positions.length / 3 / 5);
      expect(changed).toBeLessThan(mesh.positions.length / 3 / 2);
      copy = applyMeshUpdate(copy, update);
      const core = editor.mesh();
      expect(same(copy.positions, core.positions)).toBe(true);
      expect(same(copy.normals, core.normals)).toBe(true);
      expect(same(core.indices, mesh.indices)).toBe(true);
      // The handle is where it was dragged to.
      const now = point(editor.controlPoints(), 4 * bough + 3);
      for (let k = 0; k < 3; k++) expect(Math.abs(now[k] - target[k])).toBeLessThan(1e-5);
    }
    const edits = editor.edits();
    expect(edits.version).toBe(1);
    expect(edits.edits.map((e) => e.path)).toEqual([[0, 0]]);
  });

  it('rebuild the whole mesh when a joint folds, and say why', () => {
    const trunk = 0;
    const p0 = point(editor.controlPoints(), 0);
    const update = editor.drag(trunk, 3, [p0[0] + 0.5, p0[1] - 3, p0[2]]);
    expect(update.full).toBe(true);
    expect(update.reason).toMatch(/sharp enough to split its tube/);
    expect(update.mesh).not.toBeNull();
    expect(same(update.mesh!.positions, editor.mesh().positions)).toBe(true);
    expect(() => editor.drag(9999, 3, [0, 0, 0])).toThrow(/no branch 9999/);
    expect(() => editor.drag(0, 4 as 3, [0, 0, 0])).toThrow(/handles are 1, 2 and 3/);
  });

  it('apply a document: the edits that name no branch are reported, and no edits undo everything', () => {
    const { report, update } = editor.applyEdits({
      version: 1,
      edits: [
        { path: [0, 1], handles: [[0, 0, 0], [0, 0.1, 0], [0, 0.2, 0.1]] },
        { path: [0, 3], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]] },
      ],
    });
    expect(report.applied).toEqual([[0, 1]]);
    expect(report.notApplied).toEqual([{ path: [0, 3], reason: 'no branch at this path: branch [0] has 3 child branches' }]);
    expect(update.full).toBe(true);
    expect(update.reason).toBe('edits applied');
    const undone = editor.applyEdits(noEdits());
    expect(undone.report).toEqual({ applied: [], notApplied: [] });
    expect(same(undone.update.mesh!.positions, mesh.positions)).toBe(true);
    expect(undone.update.stats.bounds).toEqual(editPlant(GAME_TREE).build.stats.bounds);
    expect(() => editor.applyEdits({ version: 2 } as unknown as EditsDocument)).toThrow(/newer Meristem/);
  });
});

describe('edits in the document that share links carry', () => {
  const documents: unknown[] = [
    { version: 1, edits: [] },
    { version: 1, edits: [{ path: [0, 2, 1], handles: [[0, 0.1, 0], [0, 0, 0], [0.05, 0.3, -1.5]] }] },
    [],
    { edits: [] },
    { version: 2, edits: [] },
    { version: 1 },
    { version: 1, edits: [], extra: true },
    { version: 1, edits: [{ path: [], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]] }] },
    { version: 1, edits: [{ path: [-1], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]] }] },
    { version: 1, edits: [{ path: [0.5], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]] }] },
    { version: 1, edits: [{ path: [0], handles: [[0, 0, 0], [0, 0]] }] },
    { version: 1, edits: [{ path: [0], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 1e9]] }] },
    { version: 1, edits: [{ path: [0], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]], note: 'x' }] },
  ];

  it('are checked in TypeScript exactly as the core checks them', () => {
    const { editor } = editPlant('axiom: F');
    try {
      for (const document of documents) {
        const checked = validateEdits(document);
        let coreError: string | null = null;
        try {
          editor.applyEdits(document as EditsDocument);
        } catch (error) {
          coreError = (error as Error).message;
        }
        expect(checked.ok, JSON.stringify(document)).toBe(coreError === null);
        if (!checked.ok) expect(coreError!.startsWith(checked.error), `${coreError} / ${checked.error}`).toBe(true);
      }
    } finally {
      editor.free();
    }
    expect(validateEdits(documents[1])).toEqual({ ok: true, document: documents[1] });
  });
});

describe('a download with edits', () => {
  const edits: EditsDocument = {
    version: 1,
    edits: [
      { path: [0, 0], handles: [[0, 0, 0], [0, 0.2, 0], [0, 0.4, 0.1]] },
      { path: [0, 9], handles: [[0, 0, 0], [0, 0, 0], [0, 0, 0]] },
    ],
  };

  it(
    'is meristem export --edits’s file byte for byte, and differs from the unedited one',
    () => {
      const dir = mkdtempSync(join(tmpdir(), 'meristem-edits-'));
      try {
        const grammar = join(dir, 'leafy.lsys');
        const document = join(dir, 'edits.json');
        writeFileSync(grammar, LEAFY);
        writeFileSync(document, JSON.stringify(edits));
        for (const format of ['glb', 'wrl'] as const) {
          const out = join(dir, `plant.${format}`);
          execFileSync(
            'cargo',
            ['run', '--quiet', '--release', '--manifest-path', 'crate/Cargo.toml', '--bin', 'meristem', '--', 'export', grammar, '-o', out, '-n', '3', '--edits', document],
            { cwd: repoRoot, stdio: ['ignore', 'ignore', 'pipe'] },
          );
          const edited = exportModel(LEAFY, format, { iterations: 3, edits });
          expect(Buffer.from(edited.bytes).equals(readFileSync(out))).toBe(true);
          const unedited = exportModel(LEAFY, format, { iterations: 3 });
          expect(Buffer.from(unedited.bytes).equals(Buffer.from(edited.bytes))).toBe(false);
        }
      } finally {
        rmSync(dir, { recursive: true, force: true });
      }
    },
    300_000,
  );

  it('holds the plant the editor shows: its edits, re-applied, give the mesh its drags showed', () => {
    const { editor } = editPlant(LEAFY, { iterations: 3 });
    try {
      const bough = editor.findBranch([0, 0])!;
      const p2 = point(editor.controlPoints(), 4 * bough + 2);
      editor.drag(bough, 2, [p2[0], p2[1] + 0.05, p2[2] - 0.1]);
      const shown = editor.mesh();
      const document = editor.edits();
      const download = exportModel(LEAFY, 'glb', { iterations: 3, edits: document }).bytes;
      const { update } = editor.applyEdits(document);
      // The drag's partial mesh is within rounding of the whole one…
      expect(worst(shown.positions, update.mesh!.positions)).toBeLessThan(1e-5);
      // …which is exactly what the download holds.
      expect(same(glbPositions(download), update.mesh!.positions)).toBe(true);
      expect(same(glbPositions(exportModel(LEAFY, 'glb', { iterations: 3 }).bytes), update.mesh!.positions)).toBe(false);
    } finally {
      editor.free();
    }
  });
});

describe('exportModelWithProgress (the export worker\'s call)', () => {
  it('tells each stage in order and writes the same bytes as exportModel, with and without edits', () => {
    const stages: string[] = [];
    const file = exportModelWithProgress(LEAFY, 'glb', { iterations: 3 }, (p) => {
      expect(p.count).toBe(6);
      stages.push(`${p.index}:${p.stage}`);
    });
    expect(stages).toEqual(['0:parsing', '1:deriving', '2:interpreting', '3:meshing', '5:writing']);
    expect(file.bytes).toEqual(exportModel(LEAFY, 'glb', { iterations: 3 }).bytes);
    const { editor } = editPlant(LEAFY, { iterations: 3 });
    try {
      const branch = editor.branches().find((b) => b.parent !== null)!;
      const points = editor.controlPoints();
      const end = points.slice(12 * branch.index + 9, 12 * branch.index + 12);
      editor.drag(branch.index, 3, [end[0] + 0.5, end[1], end[2]]);
      const edits = editor.edits();
      stages.length = 0;
      const edited = exportModelWithProgress(LEAFY, 'wrl', { iterations: 3, edits }, (p) => stages.push(p.stage));
      expect(stages).toContain('applying edits');
      expect(edited.bytes).toEqual(exportModel(LEAFY, 'wrl', { iterations: 3, edits }).bytes);
    } finally {
      editor.free();
    }
  });

  it('refuses a grammar with errors after parsing, as exportModel does', () => {
    const stages: string[] = [];
    expect(() => exportModelWithProgress('axiom: F[', 'obj', {}, (p) => stages.push(p.stage))).toThrow(/errors/);
    expect(stages[0]).toBe('parsing');
  });
});

describe('drag targets and the edits document (issue 19)', () => {
  it('a wrong document is refused in the same words by the page’s check and by the core', () => {
    const { editor } = editPlant(LEAFY, { iterations: 2 });
    const ok = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
    const cases: [unknown, string][] = [
      [{ version: 1, edits: [{ path: [0], handles: [...ok, [0, 0, 0]] }] }, 'edit 0: "handles" must hold 3 points (P1, P2, P3), not 4'],
      [{ version: 1, edits: [{ path: [0], handles: [[0, 0, 0], [0, 0], [0, 0, 0]] }] }, 'edit 0: handle P2 must be 3 numbers (heading, left, up), not 2 numbers'],
      [{ version: 1, edits: [{ path: [0], handles: ok }, { path: [-1], handles: ok }] }, 'edit 1: index 0 of "path" must be a whole number from 0 to 4294967295, not -1'],
      [{ version: 1, edits: [{ path: [0], handles: ok, x: 1 }] }, 'edit 0: unknown field "x" (an edit holds only "path" and "handles")'],
      [{ version: 1, edits: [], extra: true }, 'the edits document has an unknown field "extra" (it holds only "version" and "edits")'],
      [{ version: 1, edits: {} }, '"edits" must be a list of edits, not an object'],
    ];
    for (const [document, words] of cases) {
      expect(validateEdits(document)).toEqual({ ok: false, error: words });
      expect(() => editor.applyEdits(document as EditsDocument)).toThrow(words);
    }
    editor.free();
  });

  it('whatever a drag accepts, the edits it leaves are a document the same core reads back; the rest is refused, changing nothing', () => {
    // xorshift32: deterministic, so a failure repeats.
    let state = 0x2545f491;
    const random = () => {
      state ^= state << 13;
      state ^= state >>> 17;
      state ^= state << 5;
      return (state >>> 0) / 2 ** 32;
    };
    const grammars = [LEAFY, '#angle 30\naxiom: F(1e-9)[+F(1e-9)]F(1e-9)[-F(5)]F', '#angle 25\naxiom: F(1e6)[+F(1e-6)[-F(1)]F(1e6)]F(3)'];
    let accepted = 0;
    let refused = 0;
    for (const grammar of grammars) {
      const { editor } = editPlant(grammar, { iterations: 2 });
      const { editor: fresh } = editPlant(grammar, { iterations: 2 });
      const branches = editor.branches().length;
      expect(branches).toBeGreaterThan(0);
      for (let k = 0; k < 200; k++) {
        const branch = Math.floor(random() * branches);
        const handle = (1 + Math.floor(random() * 3)) as 1 | 2 | 3;
        const at = point(editor.controlPoints(), 4 * branch + handle);
        const scale = 10 ** (-8 + 20 * random());
        const target: Vec3 = [at[0] + scale * (2 * random() - 1), at[1] + scale * (2 * random() - 1), at[2] + scale * (2 * random() - 1)];
        const before = JSON.stringify(editor.edits());
        try {
          editor.drag(branch, handle, target);
          accepted++;
        } catch (error) {
          expect(error).toBeInstanceOf(DragRefused);
          expect((error as Error).message).toMatch(/branch lengths|no length/);
          expect(JSON.stringify(editor.edits()), 'a refused drag changes nothing').toBe(before);
          refused++;
        }
        // Fed back: the page's own check and the core accept it, and every edit applies.
        const document = editor.edits();
        expect(validateEdits(JSON.parse(JSON.stringify(document)))).toEqual({ ok: true, document });
        const { report } = fresh.applyEdits(document);
        expect(report.notApplied).toEqual([]);
        expect(fresh.edits()).toEqual(document);
      }
      editor.free();
      fresh.free();
    }
    expect(accepted).toBeGreaterThan(200);
    expect(refused).toBeGreaterThan(50);
  });
});

describe('a plant that grows in time (issue 45)', () => {
  it('is dragged with its growth origins crossing with the changed vertices, its growth times kept', () => {
    const { editor, build } = editPlant(GAME_TREE, { growth: true });
    try {
      const mesh = build.mesh;
      expect(mesh.growthOrigins?.length).toBe(mesh.positions.length);
      const times = mesh.growthTimes!.slice();
      let copy: MeshBuffers = { ...mesh, positions: mesh.positions.slice(), normals: mesh.normals.slice(), growthOrigins: mesh.growthOrigins!.slice() };
      const bough = editor.findBranch([0, 0])!;
      const p3 = point(editor.controlPoints(), 4 * bough + 3);
      for (let frame = 1; frame <= 2; frame++) {
        const update = editor.drag(bough, 3, [p3[0] + 0.1 * frame, p3[1] - 0.05, p3[2] + 0.02]);
        // (A partial re-mesh: before, a tube meshed alone had no growth and another ring count.)
        expect(update.full).toBe(false);
        expect(update.growthOrigins.length).toBe(update.positions.length);
        copy = applyMeshUpdate(copy, update);
        const core = editor.mesh();
        expect(same(copy.growthOrigins!, core.growthOrigins!)).toBe(true);
        expect(same(core.growthTimes!, times)).toBe(true);
        expect(worst(copy.growthOrigins!, mesh.growthOrigins!)).toBeGreaterThan(0.05);
      }
    } finally {
      editor.free();
    }
  });
});
