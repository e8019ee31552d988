// Cross-boundary tests: the TypeScript facade over the REAL WebAssembly core (crate/pkg, built by
// `npm run build:wasm`), compared with the command-line tool built from the same Rust code.
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, byteOffsetToUtf16, initCore, inspectPlant, NOT_REWRITTEN, prepareSpares, type Bounds, type PlantBuild, type PlantSketch } from '../../web/src/core';

const repoRoot = fileURLToPath(new URL('../..', import.meta.url));
const EXAMPLE = 'public/examples/abop-1.24d.lsys';

/** What `meristem derive FILE --stats` prints. */
interface CliStats {
  modules: number;
  segments: number;
  vertices: number;
  triangles: number;
  bounds: Bounds;
}

beforeAll(async () => {
  await initCore(readFileSync(new URL('../../crate/pkg-core/meristem_core_bg.wasm', import.meta.url)));
});

function expectFinite(name: string, values: Float32Array): void {
  const bad = values.findIndex((v) => !Number.isFinite(v));
  expect(bad, `${name}[${bad}] is not finite`).toBe(-1);
}

describe('buildPlant on the gallery example', () => {
  let plant: PlantBuild;
  beforeAll(() => {
    plant = buildPlant(readFileSync(new URL(`../../${EXAMPLE}`, import.meta.url), 'utf8'));
  });

  it('builds without diagnostics and reports positive sizes', () => {
    expect([...plant.diagnostics]).toEqual([]);
    expect(plant.ok).toBe(true);
    const { stats } = plant;
    expect(stats.iterations).toBe(7);
    for (const key of ['modules', 'segments', 'vertices', 'triangles'] as const) expect(stats[key]).toBeGreaterThan(0);
    expect(plant.derived.length).toBeGreaterThan(0);
    expect(plant.derived.length).toBeLessThanOrEqual(10_001);
  });

  it('returns mesh arrays whose lengths agree with the stats', () => {
    const { mesh, stats } = plant;
    expect(mesh.positions).toBeInstanceOf(Float32Array);
    expect(mesh.indices).toBeInstanceOf(Uint32Array);
    expect(mesh.positions.length).toBe(3 * stats.vertices);
    expect(mesh.normals.length).toBe(3 * stats.vertices);
    expect(mesh.colors.length).toBe(3 * stats.vertices);
    expect(mesh.indices.length).toBe(3 * stats.triangles);
  });

  it('returns a well-formed mesh: indices in range, finite floats, unit normals, colours in 0..1', () => {
    const { mesh, stats } = plant;
    let maxIndex = 0;
    for (const i of mesh.indices) maxIndex = Math.max(maxIndex, i);
    expect(maxIndex).toBeLessThan(stats.vertices);
    expectFinite('positions', mesh.positions);
    expectFinite('normals', mesh.normals);
    expectFinite('colors', mesh.colors);
    let worstNormal = 0;
    for (let v = 0; v < stats.vertices; v++) {
      const n = mesh.normals;
      worstNormal = Math.max(worstNormal, Math.abs(Math.hypot(n[3 * v], n[3 * v + 1], n[3 * v + 2]) - 1));
    }
    expect(worstNormal).toBeLessThan(1e-3);
    const outOfRange = mesh.colors.findIndex((c) => c < 0 || c > 1);
    expect(outOfRange, `colors[${outOfRange}] outside 0..1`).toBe(-1);
  });

  it('puts every vertex inside the reported bounds (+Y up: the plant grows upwards)', () => {
    const [min, max] = plant.stats.bounds;
    const eps = 1e-3;
    for (let v = 0; v < plant.stats.vertices; v++)
      for (let axis = 0; axis < 3; axis++) {
        const c = plant.mesh.positions[3 * v + axis];
        if (c < min[axis] - eps || c > max[axis] + eps) throw new Error(`vertex ${v} axis ${axis}: ${c} outside bounds`);
      }
    expect(max[1] - min[1]).toBeGreaterThan(max[0] - min[0]);
  });

  it('owns its arrays: later builds (which grow wasm memory) do not change them', () => {
    const before = plant.mesh.positions.slice();
    const bigger = buildPlant(readFileSync(new URL(`../../${EXAMPLE}`, import.meta.url), 'utf8'), { iterations: 8 });
    expect(bigger.ok).toBe(true);
    expect(bigger.stats.iterations).toBe(8);
    expect(bigger.stats.segments).toBeGreaterThan(plant.stats.segments);
    expect(plant.mesh.positions).toEqual(before);
    expect(plant.mesh.positions.buffer.byteLength).toBe(plant.mesh.positions.byteLength);
  });

  it(
    'agrees with the command-line tool (`meristem derive --stats`)',
    () => {
      const stdout = execFileSync(
        'cargo',
        ['run', '--quiet', '--release', '--manifest-path', 'crate/Cargo.toml', '--bin', 'meristem', '--', 'derive', EXAMPLE, '--stats'],
        { cwd: repoRoot, encoding: 'utf8', stdio: ['ignore', 'pipe', 'inherit'] },
      );
      const cli = JSON.parse(stdout.trim()) as CliStats;
      const { stats } = plant;
      expect({ modules: stats.modules, segments: stats.segments, vertices: stats.vertices, triangles: stats.triangles }).toEqual({
        modules: cli.modules,
        segments: cli.segments,
        vertices: cli.vertices,
        triangles: cli.triangles,
      });
      for (let corner = 0; corner < 2; corner++)
        for (let axis = 0; axis < 3; axis++)
          expect(Math.abs(stats.bounds[corner][axis] - cli.bounds[corner][axis])).toBeLessThan(1e-4);
    },
    180_000,
  );
});

describe('inspectPlant with a sketch (the live preview of big plants)', () => {
  const TREE = '#angle 25.7\naxiom: F\nF -> F[+F]F[-F]F';
  it('hands over the segments as lines first, then gives exactly the build of one call', () => {
    const sketches: { lines: number; segments: number }[] = [];
    const { build, inspector } = inspectPlant(TREE, { iterations: 4, sides: 5 }, {
      sketch: { minSegments: 100, show: (s) => sketches.push({ lines: s.lines.length, segments: s.segments }) },
    });
    inspector.free();
    const plain = buildPlant(TREE, { iterations: 4, sides: 5 });
    expect(sketches).toEqual([{ lines: 6 * plain.stats.segments, segments: plain.stats.segments }]);
    expect(build.stats).toEqual(plain.stats);
    expect(build.mesh.positions).toEqual(plain.mesh.positions);
    expect(build.mesh.indices).toEqual(plain.mesh.indices);
    expect(build.mesh.lines.length).toBe(0);
    expect(build.timings.mesh).toBeGreaterThan(0);
  });

  it('gives no sketch for a small plant or a grammar with errors', () => {
    const sketches: unknown[] = [];
    const show = (s: unknown) => sketches.push(s);
    inspectPlant(TREE, { iterations: 1 }, { sketch: { minSegments: 100, show } }).inspector.free();
    const broken = inspectPlant('axiom: F[', {}, { sketch: { minSegments: 0, show } });
    broken.inspector.free();
    expect(broken.build.ok).toBe(false);
    expect(sketches).toEqual([]);
  });
});

describe('inspectPlant for the GPU (what the build worker sends the view)', () => {
  it('packs the normals and colours in the core: Math.round of the clamped, scaled floats', () => {
    // Leaves (colour and normals of their own), tubes of two colours and a sphere.
    const source = '#angle 30\naxiom: A\nA -> F[+A][-{.f.-f.-f.}]\'F@O(1)A';
    const { build, inspector, gpu } = inspectPlant(source, { iterations: 3 }, { forGpu: true });
    inspector.free();
    const plain = buildPlant(source, { iterations: 3 });
    expect(build.mesh.normals.length).toBe(0);
    expect(build.mesh.colors.length).toBe(0);
    expect(build.mesh.positions).toEqual(plain.mesh.positions);
    expect(gpu.normals.length).toBe(plain.mesh.normals.length);
    expect(gpu.colors.length).toBe(plain.mesh.colors.length);
    expect(new Set(plain.mesh.colors).size).toBeGreaterThan(2);
    plain.mesh.normals.forEach((n, i) => expect(gpu.normals[i], `normal ${i}`).toBe(Math.round(Math.max(-1, Math.min(1, n)) * 32767) || 0));
    plain.mesh.colors.forEach((c, i) => expect(gpu.colors[i], `colour ${i}`).toBe(Math.round(Math.max(0, Math.min(1, c)) * 255) || 0));
  });

  it('copies a big plant’s biggest arrays into the spare buffers prepared for them: the same values', () => {
    // 1.24d at n = 10: 1,087,919 vertices and 116,050 segments, every one of the seven arrays
    // over a megabyte.
    const source = readFileSync(new URL(`../../${EXAMPLE}`, import.meta.url), 'utf8');
    const first = inspectPlant(source, { iterations: 10 }, { forGpu: true });
    first.inspector.free();
    const big = (b: PlantBuild, g: typeof first.gpu) => [b.mesh.positions, b.mesh.indices, b.mesh.uvs, g.normals, g.colors, b.mesh.segmentEnds, b.mesh.segmentColors];
    const sizes = big(first.build, first.gpu).map((array) => array.byteLength);
    expect(Math.min(...sizes)).toBeGreaterThanOrEqual(1 << 20);
    // Spares an eighth bigger than the arrays (within what is taken and held), so that they show.
    const spareSizes = sizes.map((bytes) => Math.round(1.125 * bytes));
    prepareSpares(spareSizes);
    const again = inspectPlant(source, { iterations: 10 }, { forGpu: true });
    again.inspector.free();
    const arrays = big(again.build, again.gpu);
    arrays.forEach((array, k) => {
      expect(array.byteLength, `array ${k}`).toBe(sizes[k]);
      expect(array.buffer.byteLength, `array ${k}'s buffer`).toBe(spareSizes[k]);
    });
    // The spares are taken once: the next build gets new arrays.
    const third = inspectPlant(source, { iterations: 10 }, { forGpu: true });
    third.inspector.free();
    big(third.build, third.gpu).forEach((array, k) => expect(array.buffer.byteLength, `array ${k}'s buffer`).toBe(sizes[k]));
    const before = big(first.build, first.gpu);
    // Byte for byte (toEqual on millions of values takes seconds).
    const bytes = (array: ArrayBufferView) => Buffer.from(array.buffer, array.byteOffset, array.byteLength);
    arrays.forEach((array, k) => expect(bytes(array).equals(bytes(before[k])), `array ${k}`).toBe(true));
    expect(again.build.mesh.ranges).toEqual(first.build.mesh.ranges);
  });

  it('copies a big plant’s sketch into the spare buffers prepared for it: the same lines', () => {
    // 1.24d at n = 10: 116,050 lines, their ends and their colours 2.8 MB each.
    const source = readFileSync(new URL(`../../${EXAMPLE}`, import.meta.url), 'utf8');
    const sketchOf = () => {
      const sketches: PlantSketch[] = [];
      inspectPlant(source, { iterations: 10 }, { sketch: { minSegments: 1, show: (s) => sketches.push(s) }, forGpu: true }).inspector.free();
      expect(sketches).toHaveLength(1);
      return [sketches[0].lines, sketches[0].lineColors];
    };
    const first = sketchOf();
    const sizes = first.map((array) => array.byteLength);
    expect(sizes).toEqual([2_785_200, 2_785_200]);
    const spareSizes = sizes.map((bytes) => Math.round(1.125 * bytes));
    prepareSpares(spareSizes);
    const again = sketchOf();
    again.forEach((array, k) => {
      expect(array.buffer.byteLength, `array ${k}'s buffer`).toBe(spareSizes[k]);
      expect(Buffer.from(array.buffer, 0, array.byteLength).equals(Buffer.from(first[k].buffer)), `array ${k}`).toBe(true);
    });
  });
});

describe('what buildPlant reports beyond the mesh', () => {
  it('times each stage with the page’s clock', () => {
    const plant = buildPlant(readFileSync(new URL(`../../${EXAMPLE}`, import.meta.url), 'utf8'));
    const { parseResolve, derive, interpret, mesh } = plant.timings;
    for (const t of [parseResolve, derive, interpret, mesh]) expect(t).toBeGreaterThanOrEqual(0);
    expect(parseResolve + derive + interpret + mesh).toBeGreaterThan(0);
    const broken = buildPlant('axiom: F[').timings;
    expect([broken.derive, broken.interpret, broken.mesh]).toEqual([0, 0, 0]);
  });

  it('tells a flat drawing from a 3D one', () => {
    expect(buildPlant('#angle 30\naxiom: F[+F]-F').flat).toBe(true);
    expect(buildPlant('#angle 30\naxiom: F[&F]-F').flat).toBe(false);
  });

  it('gives the production that made each module of the derived string', () => {
    const plant = buildPlant('#iterations 1\naxiom: A B\nA -> C D\np2: B -> B');
    expect(plant.derived).toBe('CDB');
    expect([...plant.origins]).toEqual([0, 0, 1]);
    expect(buildPlant('#iterations 1\naxiom: A B\nA -> C').origins[1]).toBe(NOT_REWRITTEN);
  });
});

describe('buildPlant on a grammar with an error', () => {
  it('reports ok=false and a diagnostic on the right line, with no geometry', () => {
    const plant = buildPlant('axiom: X\nX -> F[');
    expect(plant.ok).toBe(false);
    const errors = [...plant.diagnostics].filter((d) => d.severity === 'error');
    expect(errors.length).toBeGreaterThan(0);
    expect(errors[0]).toMatchObject({ line: 2, column: 7, fromByte: 15, toByte: 16 });
    expect(errors[0].code).toMatch(/^E\d{4}$/);
    expect(plant.mesh.positions.length).toBe(0);
    expect(plant.mesh.indices.length).toBe(0);
  });

  it('locates the error after multi-byte characters (byte offsets → UTF-16 positions)', () => {
    const source = '// 🌱 é →\naxiom: X\nX -> F[';
    const [error] = buildPlant(source).diagnostics;
    expect(error.line).toBe(3);
    const from = byteOffsetToUtf16(source, error.fromByte);
    const to = byteOffsetToUtf16(source, error.toByte);
    expect(source.slice(from, to)).toBe('[');
  });

  it('overrides the grammar’s iterations when asked, and still reports the grammar’s own', () => {
    const plant = buildPlant('#iterations 5\naxiom: F\nF -> FF', { iterations: 2 });
    expect(plant.ok).toBe(true);
    expect(plant.stats.iterations).toBe(2);
    expect(plant.grammarIterations).toBe(5);
    expect(plant.stats.segments).toBe(4);
    expect(plant.derived).toBe('FFFF');
  });

  it('meshes with the view options: more sides, and every axis smooth', () => {
    const source = 'axiom: F+F+F';
    const plain = buildPlant(source);
    const sides = buildPlant(source, { sides: 12 });
    // One axis of three segments (joints share rings): 4 rings of `sides` vertices plus a seam
    // vertex for the texture's wrap, and 2 caps of `sides` vertices and a centre each.
    expect(plain.stats.segments).toBe(3);
    expect(plain.stats.vertices).toBe(4 * (6 + 1) + 2 * (6 + 1));
    expect(sides.stats.vertices).toBe(4 * (12 + 1) + 2 * (12 + 1));
    const bent = '#angle 20\naxiom: F+F+F+F';
    const sharp = buildPlant(bent);
    const smooth = buildPlant(bent, { smoothAll: true });
    expect(smooth.stats.segments).toBe(sharp.stats.segments);
    expect(smooth.stats.vertices, 'a smooth axis has rings between the joints').toBeGreaterThan(sharp.stats.vertices);
  });
});

describe('inspectPlant: provenance and explanations across the boundary', () => {
  const signal = readFileSync(new URL('../../public/examples/abop-sec-1.8-signal.lsys', import.meta.url), 'utf8');

  it('locates the productions in the text and tells which production wrote each module', () => {
    const { build, inspector } = inspectPlant(signal);
    try {
      expect(build.moduleCount).toBe(9);
      expect(build.productions.map((p) => signal.slice(p.from, p.to).trim())).toEqual(['b < a -> b', 'b -> a']);
      expect(build.productions.map((p) => p.context)).toEqual([true, false]);
      // aaaabaaaa: the b at 4 was written by production 0, the a at 3 by production 1, the rest copied.
      expect(Array.from(build.origins)).toEqual([
        NOT_REWRITTEN, NOT_REWRITTEN, NOT_REWRITTEN, 1, 0, NOT_REWRITTEN, NOT_REWRITTEN, NOT_REWRITTEN, NOT_REWRITTEN,
      ]);
    } finally {
      inspector.free();
    }
  });

  it('explains a context-sensitive production and gives module texts', async () => {
    const { inspector } = inspectPlant(signal);
    const explained = await inspector.explain(0);
    expect(explained).not.toBeNull();
    expect(explained!.fired).toBe(1);
    expect(explained!.contextMatched).toBe(1);
    expect(explained!.conditionFailed).toBe(0);
    expect(Array.from(explained!.produced)).toEqual([4]);
    expect(Array.from(explained!.leftContext)).toEqual([3]);
    expect(Array.from(explained!.rightContext)).toEqual([]);
    expect(await inspector.moduleTexts(2, 4)).toEqual(['a', 'a', 'b', 'a']);
    expect(await inspector.moduleTexts(7, 100)).toEqual(['a', 'a']);
    expect(await inspector.derivedHash()).toMatch(/^[0-9a-f]{16}$/);
    inspector.free();
    expect(await inspector.derivedHash()).toBe('');
    expect(await inspector.explain(0)).toBeNull();
    expect(await inspector.moduleTexts(0, 3)).toEqual([]);
  });

  it('gives parametric module texts as the derived string writes them', async () => {
    const { inspector } = inspectPlant('axiom: A(1)\nA(x) -> A(x+0.5)B(x*2,3)', { iterations: 1 });
    expect(await inspector.moduleTexts(0, 2)).toEqual(['A(1.5)', 'B(2,3)']);
    inspector.free();
  });
});
