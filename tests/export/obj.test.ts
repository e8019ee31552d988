// OBJ + MTL: every gallery example and the golden grammars, exported by the command-line tool,
// are read back by three.js's OBJLoader and MTLLoader with no warning, every vertex and triangle,
// and every `usemtl` naming a material of the MTL file written beside the OBJ.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { Mesh, type Material, type Object3D } from 'three';
import { MTLLoader } from 'three/examples/jsm/loaders/MTLLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { afterAll, afterEach, describe, expect, it, vi } from 'vitest';
import { exportWithCli, galleryDir, galleryExamples, goldenDir, goldenNames, removeScratch, scratchDir, statsOf } from './tools';

const dir = scratchDir('obj');
afterAll(() => removeScratch(dir));

interface ObjRead {
  vertices: number;
  triangles: number;
  lines: number;
  /** Names of the materials the meshes use. */
  used: Set<string>;
  /** Names the MTL file defines. */
  defined: Set<string>;
}

/** Reads an OBJ and its MTL with three's loaders, counting what they built. */
function readObj(obj: string, mtl: string): ObjRead {
  const materials = new MTLLoader().parse(mtl, '');
  materials.preload();
  const group = new OBJLoader().setMaterials(materials).parse(obj);
  let triangles = 0;
  let lines = 0;
  const used = new Set<string>();
  group.traverse((object: Object3D) => {
    if (!('geometry' in object)) return;
    const mesh = object as Mesh;
    const count = mesh.geometry.getAttribute('position').count;
    if (object instanceof Mesh) triangles += count / 3;
    else lines += count / 2;
    const list = Array.isArray(mesh.material) ? mesh.material : [mesh.material];
    list.forEach((m: Material) => used.add(m.name));
  });
  const vertices = obj.split('\n').filter((line) => line.startsWith('v ')).length;
  return { vertices, triangles, lines, used, defined: new Set(Object.keys(materials.materialsInfo)) };
}

afterEach(() => {
  vi.restoreAllMocks();
});

describe('OBJ + MTL from the command-line tool, read by three.js', () => {
  it.each(galleryExamples())('%s: every vertex and triangle, every material defined', (name) => {
    const grammar = join(galleryDir, name);
    const base = join(dir, name.replace(/\.lsys$/, ''));
    const obj = exportWithCli(grammar, `${base}.obj`).toString('utf8');
    const mtl = readFileSync(`${base}.mtl`, 'utf8');
    expect(obj).toContain(`\nmtllib ${name.replace(/\.lsys$/, '')}.mtl\n`);
    const stats = statsOf(grammar);
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const read = readObj(obj, mtl);
    expect(warn.mock.calls).toEqual([]);
    expect(read.vertices).toBe(stats.vertices);
    expect(read.triangles).toBe(stats.triangles);
    expect(read.used.size).toBeGreaterThan(0);
    for (const material of read.used) expect(read.defined, `material ${material}`).toContain(material);
  });

  it.each(goldenNames())('golden %s.obj with its MTL', (name) => {
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const read = readObj(readFileSync(join(goldenDir, `${name}.obj`), 'utf8'), readFileSync(join(goldenDir, `${name}.mtl`), 'utf8'));
    expect(warn.mock.calls).toEqual([]);
    expect(name.endsWith('-lines') ? read.lines : read.triangles).toBeGreaterThan(0);
    for (const material of read.used) expect(read.defined).toContain(material);
  });

  it('the material check can fail: a usemtl the MTL does not define', () => {
    const obj = readFileSync(join(goldenDir, 'leafy-3d.obj'), 'utf8').replace('usemtl color_0', 'usemtl color_99');
    const read = readObj(obj, readFileSync(join(goldenDir, 'leafy-3d.mtl'), 'utf8'));
    expect(read.used).toContain('color_99');
    expect(read.defined).not.toContain('color_99');
  });
});
