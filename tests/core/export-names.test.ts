// exportModel's `name` option through the REAL WebAssembly core (issue 50, 14): whatever name a
// caller of the API gives, the files are named by a safe stem (crate/src/export/mod.rs,
// `safe_stem`): no zip entry outside the folder it is unpacked into, no line added to an OBJ,
// no failure for a long name.
import { unzipSync } from 'fflate';
import { describe, expect, it } from 'vitest';
import { exportModel } from '../../web/src/core';

const PLANT = '#angle 30\n#iterations 2\naxiom: F\nF -> F[+;F]F[-;;F]F';

/** The names of a zip's entries and the text of each. */
function entries(bytes: Uint8Array): Map<string, string> {
  const files = unzipSync(bytes);
  return new Map(Object.entries(files).map(([name, data]) => [name, new TextDecoder().decode(data)]));
}

describe("exportModel's name", () => {
  it('names no zip entry outside the folder', () => {
    const file = exportModel(PLANT, 'obj', { name: '../../x' });
    expect(file.fileName).toBe('x-obj.zip');
    expect([...entries(file.bytes).keys()]).toEqual(['x.obj', 'x.mtl']);
    const windows = exportModel(PLANT, 'pov', { name: '..\\..\\x' });
    expect([...entries(windows.bytes).keys()].every((name) => !/[\\/]/.test(name) && !name.startsWith('.'))).toBe(true);
  });

  it('adds no line to an OBJ', () => {
    const file = exportModel(PLANT, 'obj', { name: 'a\nv nan nan nan' });
    const files = entries(file.bytes);
    expect([...files.keys()]).toEqual(['a-v-nan-nan-nan.obj', 'a-v-nan-nan-nan.mtl']);
    const obj = files.get('a-v-nan-nan-nan.obj')!;
    expect(obj).toContain('\nmtllib a-v-nan-nan-nan.mtl\n');
    expect(obj).not.toMatch(/^v nan/m);
  });

  it('cuts a long name instead of failing', () => {
    const file = exportModel(PLANT, 'obj', { name: 'n'.repeat(100_000) });
    expect(file.fileName).toBe(`${'n'.repeat(64)}-obj.zip`);
    expect(exportModel(PLANT, 'glb', { name: 'ω'.repeat(1000) }).fileName).toBe(`${'ω'.repeat(64)}.glb`);
  });

  it('keeps a safe name as it is, and an empty one is the default', () => {
    expect(exportModel(PLANT, 'glb', { name: 'fougère_2' }).fileName).toBe('fougère_2.glb');
    expect(exportModel(PLANT, 'wrl', { name: '' }).fileName).toBe('plant.wrl');
    expect(exportModel(PLANT, 'svg', { name: ' / ' }).fileName).toBe('plant.svg');
  });
});
