// A sketch build's bounds are the box of its line ends as stored (`Extent::of_f32_points`, after the
// plain loop): here through crate/pkg, whose WebAssembly SIMD path takes four points at a time and
// folds the lanes and the last points at the end; `cargo test` checks the scalar path natively.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { buildSketch } from '../../crate/pkg/meristem.js';

const EXAMPLES = new URL('../../public/examples/', import.meta.url);

/** [[min x, y, z], [max x, y, z]] of the points (x, y, z each), a zero as +0. */
function boxOf(points: Float32Array): number[][] {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < points.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      min[k] = Math.min(min[k], points[i + k]);
      max[k] = Math.max(max[k], points[i + k]);
    }
  }
  return [min.map((v) => v + 0), max.map((v) => v + 0)];
}

function sketchOf(source: string): { lines: Float32Array; bounds: number[][] } {
  const build = buildSketch(source, undefined);
  try {
    return { lines: build.lines(), bounds: JSON.parse(build.stats()).bounds };
  } finally {
    build.free();
  }
}

describe('the bounds of a sketch build', () => {
  // 1 to 5 lines: no whole group of four points, one, and one with points left over; in 3D, with
  // negative coordinates in every axis.
  const small = ['F', 'F+F', 'F&F/F', 'F&F/F^F', 'F&F/F^F-F'].map((axiom) => `#angle 30\naxiom: ${axiom}\n`);
  const examples = readdirSync(EXAMPLES)
    .filter((name) => name.endsWith('.lsys'))
    .map((name) => readFileSync(new URL(name, EXAMPLES), 'utf8'));

  it('are the box of its line ends, for small drawings and every example', () => {
    let drawn = 0;
    for (const source of [...small, ...examples]) {
      const { lines, bounds } = sketchOf(source);
      if (lines.length === 0) continue;
      drawn++;
      expect(bounds, source.split('\n')[0]).toEqual(boxOf(lines));
    }
    expect(drawn).toBeGreaterThan(30);
  });

  it('reach below zero where the drawing does', () => {
    const { bounds } = sketchOf('#angle 30\naxiom: F&F/F^F-F\n');
    expect(bounds[0].some((v) => v < 0)).toBe(true);
  });
});
