// A numbered PNG sequence: each frame encoded by the browser as a PNG, stored (PNGs are compressed
// already) in a zip as it comes (fflate's streaming Zip), the zip's pieces kept as they are and
// joined by the Blob.
import { Zip, ZipPassThrough } from 'fflate';
import { frameFileName } from './movie-plan';
import type { MovieWriter } from './movie-writer';

/** The PNG of `frame`, encoded by the browser. */
async function pngOf(frame: HTMLCanvasElement | OffscreenCanvas): Promise<Uint8Array> {
  const blob = 'convertToBlob' in frame ? await frame.convertToBlob({ type: 'image/png' }) : await new Promise<Blob | null>((resolve) => frame.toBlob(resolve, 'image/png'));
  if (!blob) throw new Error(`the browser could not encode a ${frame.width} × ${frame.height} PNG`);
  return new Uint8Array(await blob.arrayBuffer());
}

/** A writer of `frames` PNGs named after `name` (`name-0001.png`…) into a zip. */
export function pngSequenceWriter(name: string, frames: number): MovieWriter {
  let pieces: Uint8Array[] = [];
  let failure: Error | null = null;
  const zip = new Zip((error, piece) => {
    if (error) failure = error;
    else pieces.push(piece);
  });
  return {
    add: async (frame, index) => {
      const png = await pngOf(frame);
      const file = new ZipPassThrough(frameFileName(name, index, frames));
      zip.add(file);
      file.push(png, true);
      if (failure) throw failure;
    },
    finish: async () => {
      zip.end();
      if (failure) throw failure;
      const blob = new Blob(pieces as BlobPart[], { type: 'application/zip' });
      pieces = [];
      return blob;
    },
    close: () => {
      zip.terminate();
      pieces = [];
    },
  };
}
