// Hostile input (issue 19) through the REAL WebAssembly core: every grammar of
// crate/tests/hostile/ (and the large ones its recipes generate) gives what its first line says
// (`// expect: ok` or `// expect: E0xxx`) as a result, never a trap; and the same instance then
// still builds a normal grammar (a stack overflow or a failed allocation used to leave it broken:
// "memory access out of bounds"). The native side of the same corpus is crate/tests/hostile.rs.
import { readdirSync, readFileSync } from 'node:fs';
import { beforeAll, describe, expect, it } from 'vitest';
import { buildPlant, exportModel, inspectPlant, MODEL_FORMATS } from '../../web/src/core';
import { buildsWithStudioCore } from '../../web/src/core/build';
import { startStudioCore } from '../../web/src/core/studio-core';

const corpus = new URL('../../crate/tests/hostile/', import.meta.url);

interface Recipe {
  head: string;
  unit: string;
  count: number;
  tail: string;
}

/** Every case: [file name, grammar text]. */
function cases(): [string, string][] {
  return readdirSync(corpus)
    .filter((name) => name.endsWith('.lsys') || name.endsWith('.recipe.json'))
    .sort()
    .map((name) => {
      const text = readFileSync(new URL(name, corpus), 'utf8');
      if (!name.endsWith('.recipe.json')) return [name, text];
      const r = JSON.parse(text) as Recipe;
      return [name, r.head + r.unit.repeat(r.count) + r.tail];
    });
}

// Grammars the first plant's core cannot build (an environment, a clock, surfaces) are built
// again by the studio core, as the build worker does.
beforeAll(startStudioCore);

/** `text` built as the studio builds it: by the first plant's core, or again by the studio's. */
function built(text: string): ReturnType<typeof buildPlant> {
  const first = buildPlant(text);
  if (!buildsWithStudioCore(first)) return first;
  const { build, inspector } = inspectPlant(text);
  inspector.free();
  return build;
}

const NORMAL = '#angle 25.7\n#iterations 4\naxiom: F\nF -> F[+F]F[-F]F';

function expectation(text: string): string {
  const match = /^\uFEFF?\/\/ expect: (\S+)/.exec(text); // one file starts with a byte order mark
  if (!match) throw new Error('the first line must say // expect: ok or // expect: E0xxx');
  return match[1];
}

function expectFinite(values: Float32Array): void {
  const bad = values.findIndex((v) => !Number.isFinite(v));
  expect(bad, `value ${bad} is not finite`).toBe(-1);
}

describe('hostile grammars in the wasm core', () => {
  const all = cases();

  it('has the corpus', () => {
    expect(all.length).toBeGreaterThanOrEqual(30);
  });

  it.each(all)('%s gives its result or its diagnostic, and the instance builds on', (name, text) => {
    const expected = expectation(text);
    const plant = built(text);
    const codes = [...plant.diagnostics].map((d) => `${d.code} ${d.line}:${d.column} ${d.message}`);
    if (expected === 'ok') {
      expect(plant.ok, codes.join('\n')).toBe(true);
    } else {
      const found = [...plant.diagnostics].find((d) => d.code === expected);
      expect(found, `${name}: expected ${expected}, got\n${codes.join('\n')}`).toBeDefined();
      expect(found!.line).toBeGreaterThanOrEqual(1);
      if (found!.severity === 'error') expect(plant.ok).toBe(false);
    }
    if (plant.ok) {
      expectFinite(plant.mesh.positions);
      expectFinite(plant.mesh.normals);
      expect(JSON.stringify(plant.stats)).not.toContain('null');
    }
    const after = buildPlant(NORMAL);
    expect(after.ok).toBe(true);
    expect(after.stats.segments).toBe(625);
  }, 60_000);

  it('writes every format of the plants past f32 with finite numbers only', () => {
    for (const [name, text] of all.filter(([, t]) => expectation(t) === 'E0406')) {
      for (const { format } of MODEL_FORMATS) {
        const file = exportModel(text, format);
        if (format === 'glb') {
          const json = new TextDecoder().decode(file.bytes.subarray(20, 20 + new DataView(file.bytes.buffer, file.bytes.byteOffset).getUint32(12, true)));
          // JSON has no Infinity or NaN: a writer that met one would have written null.
          expect(json, `${name} ${format}`).not.toContain('null');
          const accessors = (JSON.parse(json) as { accessors?: { min?: number[]; max?: number[] }[] }).accessors ?? [];
          for (const a of accessors) expect([...(a.min ?? []), ...(a.max ?? [])].every(Number.isFinite)).toBe(true);
        } else if (!file.fileName.endsWith('.zip')) {
          const text = new TextDecoder().decode(file.bytes);
          expect(text, `${name} ${format}`).not.toMatch(/\b(nan|-?inf|-?infinity)\b/i);
        }
      }
    }
  }, 60_000);
});
