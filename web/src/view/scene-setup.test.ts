import { describe, expect, it } from 'vitest';
import type { Vector4} from 'three';
import { MeshBasicMaterial, type WebGLRenderer } from 'three';
import { atLeastAPixelWide, drawnSupersampled } from './scene-setup';

describe('atLeastAPixelWide', () => {
  /** The material's pixel uniform after a draw into a target `height` pixels high. */
  function pixelsHigh(height: number): number {
    const material = atLeastAPixelWide(new MeshBasicMaterial());
    const shader = { uniforms: {} as Record<string, { value: number }>, vertexShader: 'void main() {\n}' };
    material.onBeforeCompile(shader as never, undefined as never);
    const renderer = { getCurrentViewport: (v: Vector4) => v.set(0, 0, 2 * height, height) } as unknown as WebGLRenderer;
    material.onBeforeRender(renderer, undefined as never, undefined as never, undefined as never, undefined as never, null as never);
    return shader.uniforms.meristemPixelsHigh.value;
  }

  it('takes the pixel of the target drawn into, or of the picture while it is drawn supersampled', () => {
    expect(pixelsHigh(400)).toBe(400);
    expect(drawnSupersampled(2, () => pixelsHigh(800))).toBe(400);
    expect(pixelsHigh(800)).toBe(800); // back to the target's own pixels
    expect(() => drawnSupersampled(2, () => { throw new Error('lost context'); })).toThrow('lost context');
    expect(pixelsHigh(800)).toBe(800); // also after a draw that threw
  });
});
