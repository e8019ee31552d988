// Downloads: the small parsing and wording around the Download menu's files and pictures (their
// names and the browser's download: ../files/save-file.ts).

/** The smallest and (unless the GPU allows less) largest side of a PNG picture, in pixels. */
export const PICTURE_MIN = 16;
export const PICTURE_MAX = 8192;

/** A picture size, or the reason the inputs do not make one. */
export type PictureSize = { ok: true; width: number; height: number } | { ok: false; message: string };

/**
 * Reads the picture's width and height inputs: whole numbers from {@link PICTURE_MIN} to `max`
 * (for a PNG the GPU's limit, at most {@link PICTURE_MAX}); `what` names the picture in the message.
 */
export function pictureSize(width: string, height: string, max = PICTURE_MAX, what = 'PNG'): PictureSize {
  const limit = Math.min(max, PICTURE_MAX);
  const read = (text: string): number | undefined => {
    const value = Number(text.trim());
    return text.trim() !== '' && Number.isInteger(value) && value >= PICTURE_MIN && value <= limit ? value : undefined;
  };
  const w = read(width);
  const h = read(height);
  if (w === undefined || h === undefined) {
    return { ok: false, message: `${what} size: width and height must be whole numbers from ${PICTURE_MIN} to ${limit}` };
  }
  return { ok: true, width: w, height: h };
}

const decimal = new Intl.NumberFormat('en-US', { maximumFractionDigits: 1 });

/** `812 bytes`, `14.2 KB`, `3.4 MB` (powers of 1000, as file managers show). */
export function fileSize(bytes: number): string {
  if (bytes < 1000) return `${bytes} ${bytes === 1 ? 'byte' : 'bytes'}`;
  if (bytes < 1e6) return `${decimal.format(bytes / 1e3)} KB`;
  if (bytes < 1e9) return `${decimal.format(bytes / 1e6)} MB`;
  return `${decimal.format(bytes / 1e9)} GB`;
}

/** Resolves after the browser has painted, so a status set before it is on screen during long work. */
export function afterPaint(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}

/** The resolutions a picture is offered at, in dots per inch. */
export const PICTURE_DPIS = [72, 150, 300] as const;

/** Paper a picture can fill (ISO sizes and US Letter, portrait), in millimetres. */
export const PAPERS = {
  a5: { label: 'A5', width: 148, height: 210 },
  a4: { label: 'A4', width: 210, height: 297 },
  letter: { label: 'Letter', width: 215.9, height: 279.4 },
} as const;

/** A paper and its orientation, as the menu offers them: `a5-portrait`, `a4-landscape`. */
export type PaperChoice = `${keyof typeof PAPERS}-${'portrait' | 'landscape'}`;

/** The pixels of a whole sheet of `paper` at `dpi` (rounded to whole pixels). */
export function paperPixels(paper: PaperChoice, dpi: number): { width: number; height: number } {
  const [name, orientation] = paper.split('-') as [keyof typeof PAPERS, string];
  const { width, height } = PAPERS[name];
  const px = (mm: number) => Math.round((mm / 25.4) * dpi);
  return orientation === 'landscape' ? { width: px(height), height: px(width) } : { width: px(width), height: px(height) };
}

const CRC_TABLE = Uint32Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});

/** The CRC-32 of PNG chunks (ISO 3309). */
function crc32(bytes: Uint8Array): number {
  let c = 0xffffffff;
  for (const byte of bytes) c = CRC_TABLE[(c ^ byte) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/**
 * `png` with its resolution recorded (a `pHYs` chunk right after the header, replacing any the
 * encoder wrote), so that it prints at `dpi`: 300 DPI and 1748 pixels wide is an A5 page's width.
 */
export function withResolution(png: Uint8Array, dpi: number): Uint8Array {
  const view = new DataView(png.buffer, png.byteOffset, png.byteLength);
  const chunks: Uint8Array[] = [png.subarray(0, 8)];
  for (let at = 8; at + 12 <= png.length; ) {
    const length = view.getUint32(at);
    const type = String.fromCharCode(...png.subarray(at + 4, at + 8));
    const end = at + 12 + length;
    if (type !== 'pHYs') chunks.push(png.subarray(at, end));
    if (type === 'IHDR') {
      const chunk = new Uint8Array(21);
      const data = new DataView(chunk.buffer);
      const perMetre = Math.round(dpi / 0.0254);
      data.setUint32(0, 9);
      chunk.set([0x70, 0x48, 0x59, 0x73], 4); // pHYs
      data.setUint32(8, perMetre);
      data.setUint32(12, perMetre);
      chunk[16] = 1; // the unit is the metre
      data.setUint32(17, crc32(chunk.subarray(4, 17)));
      chunks.push(chunk);
    }
    at = end;
  }
  const out = new Uint8Array(chunks.reduce((n, c) => n + c.length, 0));
  let offset = 0;
  for (const chunk of chunks) (out.set(chunk, offset), (offset += chunk.length));
  return out;
}
