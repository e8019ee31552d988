// Issue 50, findings 1, 2 and 8 through the REAL WebAssembly core: a build of any grammar ends with
// a plant or a diagnostic, never a trap, whatever #max_modules says. Before, 26 million modules
// of F[+F]F[-F]F trapped meshing ("unreachable": out of memory) and F -> FF at 24 steps panicked
// with "capacity overflow"; the same instance then refused every later build. The native side is
// crate/tests/drawing_budget.rs.
import { describe, expect, it } from 'vitest';
import { buildPlant } from '../../web/src/core';

const NORMAL = '#angle 25.7\n#iterations 4\naxiom: F\nF -> F[+F]F[-F]F';

function codes(plant: ReturnType<typeof buildPlant>): string[] {
  return [...plant.diagnostics].map((d) => `${d.code} ${d.line}:${d.column} ${d.message}`);
}

describe('the drawing budget in the wasm core', () => {
  it('draws 9.8 million segments as lines only, with a warning, and builds on', () => {
    const plant = buildPlant('#max_modules 100000000\n#iterations 10\naxiom: F\nF -> F[+F]F[-F]F');
    expect(plant.ok, codes(plant).join('\n')).toBe(true);
    const warning = [...plant.diagnostics].find((d) => d.code === 'E0414');
    expect(warning?.message).toContain('9765625 segments');
    expect(warning?.line).toBe(2);
    expect(plant.stats.lines).toBe(9_765_625);
    expect(plant.mesh.lines.length).toBe(6 * 9_765_625);
    expect(buildPlant(NORMAL).stats.segments).toBe(625);
  }, 120_000);

  it('refuses 16.8 million segments before the turtle runs, and builds on', () => {
    const plant = buildPlant('#max_modules 40000000\n#iterations 24\naxiom: F\nF -> FF');
    expect(plant.ok).toBe(false);
    const error = [...plant.diagnostics].find((d) => d.code === 'E0413');
    expect(error?.message, codes(plant).join('\n')).toContain('16777216 segments');
    expect(buildPlant(NORMAL).stats.segments).toBe(625);
  }, 120_000);

  it('ends a derivation that would work for minutes with its work budget', () => {
    const plant = buildPlant('#iterations 10000\naxiom: A(0)\nA(x) : x < 22 -> A(x+1)A(x+1)\nA(x) -> A(x+1)');
    const error = [...plant.diagnostics].find((d) => d.code === 'E0415');
    expect(error?.message, codes(plant).join('\n')).toContain('by step 44');
    expect(buildPlant(NORMAL).stats.segments).toBe(625);
  }, 120_000);
});
