// Downloads: handing a file to the browser, and the small parsing and wording around it.

/** The smallest and (unless the GPU allows less) largest side of a PNG picture, in pixels. */
export const PICTURE_MIN = 16;
export const PICTURE_MAX = 8192;

/** A picture size, or the reason the inputs do not make one. */
export type PictureSize = { ok: true; width: number; height: number } | { ok: false; message: string };

/**
 * Reads the PNG width and height inputs: whole numbers from {@link PICTURE_MIN} to `max` (the
 * GPU's limit, at most {@link PICTURE_MAX}).
 */
export function pictureSize(width: string, height: string, max = PICTURE_MAX): PictureSize {
  const limit = Math.min(max, PICTURE_MAX);
  const read = (text: string): number | undefined => {
    const value = Number(text.trim());
    return text.trim() !== '' && Number.isInteger(value) && value >= PICTURE_MIN && value <= limit ? value : undefined;
  };
  const w = read(width);
  const h = read(height);
  if (w === undefined || h === undefined) {
    return { ok: false, message: `PNG size: width and height must be whole numbers from ${PICTURE_MIN} to ${limit}` };
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

/** Hands `data` to the browser as a download named `fileName`. */
export function saveFile(data: Blob | Uint8Array, fileName: string, mimeType: string): void {
  const blob = data instanceof Blob ? data : new Blob([data.slice().buffer as ArrayBuffer], { type: mimeType });
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  // The download has started from the URL by now; a minute is generous before letting it go.
  setTimeout(() => URL.revokeObjectURL(url), 60_000);
}

/** Resolves after the browser has painted, so a status set before it is on screen during long work. */
export function afterPaint(): Promise<void> {
  return new Promise((resolve) => requestAnimationFrame(() => setTimeout(resolve, 0)));
}
