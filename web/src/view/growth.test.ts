import { Box3, BufferGeometry, LineBasicMaterial, ShaderLib, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { blendedBox, growingMaterial, growthBoxes, grownFraction, injectGrowth } from './growth';
import { addGrowthAttributes, growthSpanOf, WHOLE } from './growth-arrays';
import { litPlantMaterial } from './scene-setup';

describe('grownFraction (the smoothstep of the interfaces)', () => {
  it('is 0 before t0, 1 after t1, and smooth between', () => {
    expect(grownFraction(0, 1, 2)).toBe(0);
    expect(grownFraction(1, 1, 2)).toBe(0);
    expect(grownFraction(2, 1, 2)).toBe(1);
    expect(grownFraction(7, 1, 2)).toBe(1);
    expect(grownFraction(1.5, 1, 2)).toBeCloseTo(0.5, 12);
    // g(x) = x²(3 − 2x): g(0.25) = 0.15625
    expect(grownFraction(1.25, 1, 2)).toBeCloseTo(0.15625, 12);
    expect(grownFraction(-0.5, -1, 0)).toBeCloseTo(0.5, 12);
  });

  it('treats times without a span (a vertex without growth attributes reads (0, 0)) as whole', () => {
    expect(grownFraction(-5, 0, 0)).toBe(1);
    expect(grownFraction(WHOLE, 0, 3)).toBe(1);
  });
});

describe('injectGrowth', () => {
  it('places the vertex after begin_vertex, with the attributes and the uniform declared', () => {
    const uniform = { value: 2.5 };
    const shader = { vertexShader: ShaderLib.standard.vertexShader, uniforms: {} as Record<string, unknown> };
    injectGrowth(shader, uniform);
    expect(shader.uniforms.meristemGrowthTime).toBe(uniform);
    const text = shader.vertexShader;
    expect(text).toMatch(/attribute vec3 growthOrigin;/);
    expect(text).toMatch(/attribute vec2 growthTime;/);
    expect(text.indexOf('float meristemGrown = 1.0;')).toBeLessThan(text.indexOf('void main()'));
    const begin = text.indexOf('#include <begin_vertex>');
    const placed = text.indexOf('transformed = growthOrigin + (transformed - growthOrigin) * meristemGrown;');
    expect(begin).toBeGreaterThan(0);
    expect(placed).toBeGreaterThan(begin);
    expect(placed).toBeLessThan(text.indexOf('#include <project_vertex>'));
  });

  it('refuses a shader it cannot place the growth in', () => {
    expect(() => injectGrowth({ vertexShader: 'void main() {}', uniforms: {} }, { value: 0 })).toThrow(/no longer fits/);
  });

  it('keeps the material\'s own onBeforeCompile and caches its programs apart', () => {
    const uniform = { value: 1 };
    const plain = litPlantMaterial();
    const growing = growingMaterial(litPlantMaterial(), uniform);
    expect(growing.customProgramCacheKey()).not.toBe(plain.customProgramCacheKey());
    const shader = { vertexShader: ShaderLib.standard.vertexShader, fragmentShader: '', uniforms: {} as Record<string, unknown> };
    growing.onBeforeCompile(shader as never, undefined as never);
    // The half-pixel push of atLeastAPixelWide ran first and is switched off for ungrown elements.
    expect(shader.uniforms.meristemPixelsHigh).toBeDefined();
    expect(shader.uniforms.meristemGrowthTime).toBe(uniform);
    expect(shader.vertexShader).toMatch(/if \(outwardsLength > 0\.0 && meristemGrown > 0\.0\)/);
    expect(shader.vertexShader.match(/float meristemGrown = 1\.0;/g)).toHaveLength(1);
    // Made to grow twice (a material shared by two lists), it is injected once.
    expect(growingMaterial(growing, uniform)).toBe(growing);
    const again = { vertexShader: ShaderLib.standard.vertexShader, fragmentShader: '', uniforms: {} as Record<string, unknown> };
    growing.onBeforeCompile(again as never, undefined as never);
    expect(again.vertexShader.match(/attribute vec2 growthTime;/g)).toHaveLength(1);
    // A line material (the fallback's) takes it too.
    const line = growingMaterial(new LineBasicMaterial(), uniform);
    const lineShader = { vertexShader: ShaderLib.basic.vertexShader, fragmentShader: '', uniforms: {} as Record<string, unknown> };
    line.onBeforeCompile(lineShader as never, undefined as never);
    expect(lineShader.vertexShader).toMatch(/meristemGrown/);
  });
});

describe('growth arrays on a geometry', () => {
  it('adds the attributes only when they fit the vertices', () => {
    const geometry = new BufferGeometry();
    const origins = new Float32Array(6);
    const times = new Float32Array([-1, 0, 0, 1]);
    expect(addGrowthAttributes(geometry, 2, { growthOrigins: origins, growthTimes: times })).toBe(true);
    expect(geometry.getAttribute('growthOrigin').itemSize).toBe(3);
    expect(geometry.getAttribute('growthTime').itemSize).toBe(2);
    expect(geometry.getAttribute('growthTime').array).toBe(times);
    const other = new BufferGeometry();
    expect(addGrowthAttributes(other, 3, { growthOrigins: origins, growthTimes: times })).toBe(false);
    expect(addGrowthAttributes(other, 2, {})).toBe(false);
    expect(addGrowthAttributes(other, 0, { growthOrigins: new Float32Array(0), growthTimes: new Float32Array(0) })).toBe(false);
    expect(other.getAttribute('growthTime')).toBeUndefined();
  });

  it('spans N, the last t1 up to a whole step', () => {
    expect(growthSpanOf(undefined)).toBeNull();
    expect(growthSpanOf(new Float32Array(0))).toBeNull();
    expect(growthSpanOf(new Float32Array([-1, 0, 0, 1, 3, 4]))).toBe(4);
    expect(growthSpanOf(new Float32Array([-1, 0]))).toBe(0);
    expect(growthSpanOf(new Float32Array([2.2, 2.5]))).toBe(3);
  });

  it('boxes the plant of each step, and blends them between steps', () => {
    // Three points: the axiom's at 0, one grown by step 1, one by step 2.
    const points = new Float32Array([0, 0, 0, 0, 1, 0, 2, 3, 0]);
    const times = new Float32Array([-1, 0, 0, 1, 1, 2]);
    const boxes = growthBoxes(points, times, 2);
    expect(boxes.map((b) => [b.max.x, b.max.y])).toEqual([
      [0, 0],
      [0, 1],
      [2, 3],
    ]);
    const half = blendedBox(boxes, 1.5);
    expect(half.max.toArray()).toEqual([1, 2, 0]);
    expect(blendedBox(boxes, 9).max.toArray()).toEqual([2, 3, 0]);
    expect(blendedBox(boxes, -3).max.toArray()).toEqual([0, 0, 0]);
    const emptyFirst = [new Box3(), new Box3(new Vector3(0, 0, 0), new Vector3(1, 1, 1))];
    expect(blendedBox(emptyFirst, 0.5).max.x).toBe(1);
  });
});
