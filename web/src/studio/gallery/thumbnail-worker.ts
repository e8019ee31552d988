// The thumbnail worker: builds a gallery example with its own core instance and draws it with
// ThumbnailRenderer on an OffscreenCanvas, so neither the build nor the drawing (slow for big
// plants without a GPU) ever holds up the page. Answers each request with a PNG, in order.
import { buildPlant, initCore, loadStudioCore, needsStudioCore } from '../../core';
import { ThumbnailRenderer } from '../../view/thumbnail';

/** Page → worker. */
export interface ThumbnailRequest {
  file: string;
  source: string;
}

/** Worker → page: the picture, or why there is none. */
export type ThumbnailResponse = { file: string; picture: Blob } | { file: string; error: string };

const ready = initCore();
let renderer: ThumbnailRenderer | undefined;

addEventListener('message', async (event: MessageEvent<ThumbnailRequest>) => {
  const { file, source } = event.data;
  let response: ThumbnailResponse;
  try {
    await ready;
    let build = buildPlant(source);
    if (needsStudioCore(build)) {
      // As in the build worker: the studio core draws those examples as the studio shows them.
      await loadStudioCore();
      build = buildPlant(source);
    }
    if (!build.ok) throw new Error(`${build.diagnostics.length} diagnostics`);
    renderer ??= new ThumbnailRenderer(new OffscreenCanvas(320, 240));
    response = { file, picture: await renderer.render(build.mesh, build.flat) };
  } catch (error) {
    response = { file, error: error instanceof Error ? error.message : String(error) };
  }
  postMessage(response);
});
