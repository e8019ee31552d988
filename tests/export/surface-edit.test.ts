// The surface editor's result, exported (issue 46: "the surface editor changes a petal and the glTF
// export carries it, validator clean"): a flower whose petal is the library's, written out as
// `#patch` lines by the editor's core call (`surfacePreview`'s writeOut), one control point then
// moved as a drag writes it (`movePoints`), exported as GLB by the studio's facade (what the
// Download menu calls). Both files pass the Khronos validator with no error and no warning, and the
// edited one carries the moved point: its petals reach further.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { validateBytes } from 'gltf-validator';
import { beforeAll, describe, expect, it } from 'vitest';
import { exportModel, initIo, loadSurfacePreview, type SurfacePreviewer } from '../../web/src/core';
import { movePoints } from '../../web/src/studio/surfaces/point-text';
import { repoRoot } from './tools';

/** Three petals of the library's shape, 2 long, at 60° from the stem. */
const FLOWER = '#surface P petal\naxiom: F(1) [&(60) ~P(2)] /(120) [&(60) ~P(2)] /(120) [&(60) ~P(2)]\n';

let preview: SurfacePreviewer;

beforeAll(async () => {
  await initIo(readFileSync(join(repoRoot, 'crate/pkg/meristem_bg.wasm')));
  preview = await loadSurfacePreview();
});

/** The POSITION accessors' bounds of a GLB (its JSON chunk). */
function positionBounds(glb: Uint8Array): { min: number[]; max: number[] } {
  const bytes = Buffer.from(glb);
  const json = JSON.parse(bytes.subarray(20, 20 + bytes.readUInt32LE(12)).toString('utf8')) as {
    meshes: { primitives: { attributes: { POSITION: number } }[] }[];
    accessors: { min: number[]; max: number[] }[];
  };
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (const mesh of json.meshes) {
    for (const primitive of mesh.primitives) {
      const a = json.accessors[primitive.attributes.POSITION];
      a.min.forEach((v, i) => (min[i] = Math.min(min[i], v)));
      a.max.forEach((v, i) => (max[i] = Math.max(max[i], v)));
    }
  }
  return { min, max };
}

async function validGlb(text: string, name: string): Promise<Uint8Array> {
  const file = exportModel(text, 'glb', { name });
  const report = await validateBytes(file.bytes, { uri: `${name}.glb`, maxIssues: 20 });
  const problems = report.issues.messages.map((m) => `${m.code} ${m.pointer ?? ''}: ${m.message}`).join('\n');
  expect(report.issues.numErrors, problems).toBe(0);
  expect(report.issues.numWarnings, problems).toBe(0);
  return file.bytes;
}

const apply = (text: string, changes: { from: number; to: number; insert: string }[]) =>
  [...changes].sort((a, b) => b.from - a.from).reduce((t, c) => t.slice(0, c.from) + c.insert + t.slice(c.to), text);

describe('a petal edited by the surface editor, exported as glTF', () => {
  it('is written out, moved, exported valid, and the file carries the moved point', async () => {
    const library = preview(FLOWER, 'P').surface!;
    expect(library.organ).toBe('petal');
    const written = apply(FLOWER, library.writeOut);
    const before = preview(written, 'P').surface!;
    expect(before.organ).toBeNull();
    expect(before.written).toHaveLength(library.net.length); // every point of the library's petal, now in the text
    // The same petal, up to the 4 decimals written.
    expect(before.positions.length).toBe(library.positions.length);
    expect(before.positions.every((v, k) => Math.abs(v - library.positions[k]) < 1e-4)).toBe(true);

    // The tip of the midrib (row 4, column 1 of the first patch), and its copy in the other half,
    // dragged 0.5 further along the petal, as the editor writes it.
    const tip = before.written.findIndex((w) => w.patch === 0 && w.index === 12);
    const copies = before.written.filter((w) => w.value.every((v, i) => v === before.written[tip].value[i]));
    expect(copies.length).toBe(2);
    const moved = before.written[tip].value.map((v, i) => (i === 1 ? v + 0.5 : v)) as [number, number, number];
    const edited = apply(written, movePoints(copies, moved).changes);
    const after = preview(edited, 'P').surface!;
    expect(Math.max(...after.net.map((p) => p[1]))).toBeCloseTo(Math.max(...before.net.map((p) => p[1])) + 0.5, 6);

    const plain = positionBounds(await validGlb(written, 'flower'));
    const changed = positionBounds(await validGlb(edited, 'flower-edited'));
    // The petals lean out at 60° from the stem: a longer midrib reaches higher and wider.
    expect(changed.max[1]).toBeGreaterThan(plain.max[1] + 0.1);
  });
});
