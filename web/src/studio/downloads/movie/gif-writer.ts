// Animated GIFs through gifenc: one palette of 256 colours for the whole movie, made from a key
// frame (the whole plant), so colours do not flicker from frame to frame; looped forever, for
// slides and learning platforms. Loaded with the first GIF.
import { GIFEncoder, applyPalette, quantize, type Palette } from 'gifenc';
import type { MovieWriter } from './movie-writer';

/** The RGBA pixels of `frame`, read through a 2D canvas of its size. */
function pixelsOf(frame: HTMLCanvasElement | OffscreenCanvas, reader: OffscreenCanvasRenderingContext2D, width: number, height: number): Uint8ClampedArray {
  reader.clearRect(0, 0, width, height);
  reader.drawImage(frame, 0, 0, width, height);
  return reader.getImageData(0, 0, width, height).data;
}

/** A writer of a `width` × `height` GIF at `fps` (whole hundredths of a second a frame), its palette made from `key`. */
export function gifWriter(width: number, height: number, fps: number, key: HTMLCanvasElement | OffscreenCanvas): MovieWriter {
  const reader = new OffscreenCanvas(width, height).getContext('2d', { willReadFrequently: true });
  if (!reader) throw new Error(`the browser could not make a ${width} × ${height} canvas for the GIF`);
  const palette: Palette = quantize(pixelsOf(key, reader, width, height), 256);
  let gif: ReturnType<typeof GIFEncoder> | undefined = GIFEncoder();
  const delay = 1000 / fps;
  return {
    add: async (frame, index) => {
      if (!gif) throw new Error('the GIF was closed');
      const indexed = applyPalette(pixelsOf(frame, reader, width, height), palette);
      gif.writeFrame(indexed, width, height, index === 0 ? { palette, delay, repeat: 0 } : { delay });
    },
    finish: async () => {
      if (!gif) throw new Error('the GIF was closed');
      gif.finish();
      const bytes = gif.bytes();
      gif = undefined;
      return new Blob([bytes.slice().buffer as ArrayBuffer], { type: 'image/gif' });
    },
    close: () => {
      gif = undefined;
    },
  };
}
