import { describe, expect, it } from 'vitest';
import { drawnBySoftware, isSoftwareRendererName } from './rasterizer';

describe('isSoftwareRendererName', () => {
  it('knows the software rasterizers by the names browsers give them, and no GPU as one', () => {
    for (const name of [
      'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)',
      'Google SwiftShader',
      'llvmpipe (LLVM 15.0.6, 256 bits)',
      'Mesa/X.org, llvmpipe (LLVM 12.0.0, 256 bits)',
      'softpipe',
      'ANGLE (Microsoft, Microsoft Basic Render Driver Direct3D11 vs_5_0 ps_5_0, D3D11)',
    ]) {
      expect(isSoftwareRendererName(name), name).toBe(true);
    }
    for (const name of [
      'ANGLE (NVIDIA, NVIDIA GeForce RTX 3060 Direct3D11 vs_5_0 ps_5_0, D3D11)',
      'ANGLE (Intel, Mesa Intel(R) UHD Graphics 620 (KBL GT2), OpenGL 4.6)',
      'Apple M1',
      'Mali-G78',
      'WebKit WebGL',
    ]) {
      expect(isSoftwareRendererName(name), name).toBe(false);
    }
  });
});

describe('drawnBySoftware', () => {
  /** A context that names `unmasked` through the debug extension (when given) and `plain` as RENDERER. */
  const context = (plain: string, unmasked?: string) =>
    ({
      RENDERER: 0x1f01,
      getExtension: (name: string) => (name === 'WEBGL_debug_renderer_info' && unmasked !== undefined ? { UNMASKED_RENDERER_WEBGL: 0x9246 } : null),
      getParameter: (p: number) => (p === 0x9246 ? unmasked : p === 0x1f01 ? plain : null),
    }) as unknown as WebGL2RenderingContext;

  it('reads the unmasked renderer where the browser gives it, else RENDERER', () => {
    expect(drawnBySoftware(context('WebKit WebGL', 'ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero)), SwiftShader driver)'))).toBe(true);
    expect(drawnBySoftware(context('WebKit WebGL', 'ANGLE (NVIDIA, NVIDIA GeForce GTX 1050)'))).toBe(false);
    expect(drawnBySoftware(context('llvmpipe, or similar'))).toBe(true); // Firefox: no extension, a sanitised name
    expect(drawnBySoftware(context('Mali-G78'))).toBe(false);
  });
});
