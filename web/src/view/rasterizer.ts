// Whether the view's WebGL is drawn by a software rasterizer (no usable GPU: SwiftShader in
// Chromium, llvmpipe or softpipe in Mesa), where 4× multisampling costs as much as the rest of a
// frame, so the view draws without it (see `viewRenderer` in ./plant-view.ts).

/** The renderer names of software rasterizers, as WebGL reports them. */
const SOFTWARE = /swiftshader|llvmpipe|softpipe|software rasterizer|microsoft basic render/i;

/** Whether a WebGL renderer name (`UNMASKED_RENDERER_WEBGL`, else `RENDERER`) is a software rasterizer's. */
export function isSoftwareRendererName(name: string): boolean {
  return SOFTWARE.test(name);
}

/** Whether `gl` is drawn by a software rasterizer. A browser that names no renderer is taken to have a GPU. */
export function drawnBySoftware(gl: WebGLRenderingContext | WebGL2RenderingContext): boolean {
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  const name: unknown = gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER);
  return typeof name === 'string' && isSoftwareRendererName(name);
}
