import { describe, expect, it } from 'vitest';
import { divergence, trunkWidth, trunkWidthRatio, type TrunkMesh } from './plant-measures';

/** Organs at n·angle about an axis: on a disk at r = √n (Vogel) or on a cylinder rising by h. */
function organs(count: number, angle: number, place: 'disk' | 'cylinder'): number[][] {
  return Array.from({ length: count }, (_, n) => {
    const a = (n * angle * Math.PI) / 180;
    return place === 'disk' ? [Math.sqrt(n) * Math.cos(a), 5, Math.sqrt(n) * Math.sin(a)] : [Math.cos(a), 0.15 * n, Math.sin(a)];
  });
}

/** A tube of radius `r` from (0,0,0) up to (0,len,0) as one hexagonal prism, module 3, then a second segment. */
function tubeMesh(r: number, len: number): TrunkMesh {
  const positions: number[] = [];
  for (const y of [0, len]) for (let k = 0; k < 6; k++) positions.push(r * Math.cos((k * Math.PI) / 3), y, r * Math.sin((k * Math.PI) / 3));
  // The next segment's ring, narrower, at the top joint: not the trunk's width.
  for (let k = 0; k < 6; k++) positions.push(0.5 * r * Math.cos((k * Math.PI) / 3), len, 0.5 * r * Math.sin((k * Math.PI) / 3));
  const indices: number[] = [];
  for (let k = 0; k < 6; k++) indices.push(k, 6 + ((k + 1) % 6), 6 + k);
  for (let k = 0; k < 6; k++) indices.push(6 + k, 12 + ((k + 1) % 6), 12 + k);
  return {
    positions: new Float32Array(positions),
    indices: new Uint32Array(indices),
    ranges: new Uint32Array([0, 3, 6, 5]),
    segmentEnds: new Float32Array([0, 0, 0, 0, len, 0, 0, len, 0, 0, 2 * len, 0]),
    segmentModules: new Uint32Array([3, 5]),
  };
}

describe('the trunk\'s proportion', () => {
  it('is the first tube\'s diameter at its base over the plant\'s height', () => {
    const mesh = tubeMesh(0.25, 2);
    expect(trunkWidth(mesh)).toBeCloseTo(0.5, 6);
    expect(trunkWidthRatio(mesh, { bounds: [[-1, 0, -1], [1, 10, 1]] })).toBeCloseTo(0.05, 6);
  });

  it('is not a number without a tube (lines) or without height', () => {
    const lines = { ...tubeMesh(0.25, 2), indices: new Uint32Array(), ranges: new Uint32Array() };
    expect(trunkWidth(lines)).toBeNaN();
    expect(trunkWidthRatio(tubeMesh(0.25, 2), { bounds: [[0, 0, 0], [1, 0, 1]] })).toBeNaN();
    expect(trunkWidth({ ...lines, segmentModules: new Uint32Array(), segmentEnds: new Float32Array() })).toBeNaN();
  });
});

describe('the divergence angle', () => {
  it.each([137.5, 137.3, 99.5, 90, 180, 222.5])('reads %s° off a Vogel head and off a cylinder', (angle) => {
    const expected = angle > 180 ? 360 - angle : angle;
    // A head's centre is its florets' centroid, a cylinder's axis their greatest spread: both a
    // little off for a helix of 100 organs, which the median over the pairs mostly cancels.
    expect(Math.abs(divergence(organs(600, angle, 'disk')) - expected)).toBeLessThan(0.05);
    expect(Math.abs(divergence(organs(100, angle, 'cylinder')) - expected)).toBeLessThan(0.25);
  });

  it('tells 137.3° from 137.5° on a head', () => {
    expect(Math.abs(divergence(organs(600, 137.3, 'disk')) - 137.3)).toBeLessThan(0.05);
    expect(Math.abs(divergence(organs(600, 137.5, 'disk')) - 137.5)).toBeLessThan(0.05);
  });

  it('is 0 for fewer than three organs', () => {
    expect(divergence(organs(2, 137.5, 'cylinder'))).toBe(0);
  });
});
