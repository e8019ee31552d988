// Pixel measurements on PNG screenshots, for asserting that the 3D view shows a plant.
import { PNG } from 'pngjs';

/** A decoded RGBA picture. */
export interface Picture {
  width: number;
  height: number;
  data: Uint8Array;
}

/** Decodes a PNG screenshot. */
export function decodePng(png: Buffer): Picture {
  const { width, height, data } = PNG.sync.read(png);
  return { width, height, data };
}

/** Colour distance that counts as "clearly different" (sum of |ΔR|+|ΔG|+|ΔB|, 0..765). */
export const CLEARLY_DIFFERENT = 60;

function distance(a: Uint8Array, i: number, b: Uint8Array | readonly number[], j: number): number {
  return Math.abs(a[i] - b[j]) + Math.abs(a[i + 1] - b[j + 1]) + Math.abs(a[i + 2] - b[j + 2]);
}

/** The background colour: the most common colour along the picture's edges (two pixels in). */
export function backgroundColour(picture: Picture): [number, number, number] {
  const counts = new Map<number, number>();
  const { width, height, data } = picture;
  const add = (x: number, y: number) => {
    const i = 4 * (y * width + x);
    const key = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
    counts.set(key, (counts.get(key) ?? 0) + 1);
  };
  // Two pixels in from the edges: a screenshot of an element at a fractional place on the page
  // may hold a row of its neighbour's border (the timeline bar's under the view, the toolbar's).
  const inset = Math.min(2, Math.floor((Math.min(width, height) - 1) / 2));
  for (let x = inset; x < width - inset; x++) (add(x, inset), add(x, height - 1 - inset));
  for (let y = inset; y < height - inset; y++) (add(inset, y), add(width - 1 - inset, y));
  const [key] = [...counts.entries()].sort((a, b) => b[1] - a[1])[0];
  return [(key >> 16) & 255, (key >> 8) & 255, key & 255];
}

/** Which pixels are clearly not background (1) — the plant — as a mask. */
export function foregroundMask(picture: Picture, background = backgroundColour(picture)): Uint8Array {
  const mask = new Uint8Array(picture.width * picture.height);
  for (let p = 0; p < mask.length; p++) mask[p] = distance(picture.data, 4 * p, background, 0) > CLEARLY_DIFFERENT ? 1 : 0;
  return mask;
}

/** Share of pixels (0..1) that are clearly not background. */
export function foregroundShare(picture: Picture): number {
  const mask = foregroundMask(picture);
  return mask.reduce((sum, v) => sum + v, 0) / mask.length;
}

/** Number of distinct colours, a cheap sign of shading (a flat fill has one or two). */
export function distinctColours(picture: Picture): number {
  const seen = new Set<number>();
  const { data } = picture;
  for (let i = 0; i < data.length; i += 4) seen.add((data[i] << 16) | (data[i + 1] << 8) | data[i + 2]);
  return seen.size;
}

/**
 * How different two same-sized pictures are: the share of the pixels that are foreground in either
 * picture whose colour changed clearly. 0 = same picture, 1 = nothing in common.
 */
export function changedShare(a: Picture, b: Picture): number {
  if (a.width !== b.width || a.height !== b.height) throw new Error('pictures differ in size');
  const maskA = foregroundMask(a);
  const maskB = foregroundMask(b);
  let union = 0;
  let changed = 0;
  for (let p = 0; p < maskA.length; p++) {
    if (!maskA[p] && !maskB[p]) continue;
    union++;
    if (distance(a.data, 4 * p, b.data, 4 * p) > CLEARLY_DIFFERENT) changed++;
  }
  return union === 0 ? 0 : changed / union;
}

/** How much the foregrounds of two same-sized pictures overlap: |A ∩ B| / |A ∪ B| (1 = same silhouette). */
export function foregroundOverlap(a: Picture, b: Picture): number {
  if (a.width !== b.width || a.height !== b.height) throw new Error('pictures differ in size');
  const maskA = foregroundMask(a);
  const maskB = foregroundMask(b);
  let union = 0;
  let both = 0;
  for (let p = 0; p < maskA.length; p++) {
    union += maskA[p] | maskB[p];
    both += maskA[p] & maskB[p];
  }
  return union === 0 ? 0 : both / union;
}

/** The box around the foreground as shares (0..1) of the picture's width and height. */
export function foregroundExtent(picture: Picture): { width: number; height: number } {
  const mask = foregroundMask(picture);
  let minX = Infinity;
  let maxX = -Infinity;
  let minY = Infinity;
  let maxY = -Infinity;
  for (let y = 0; y < picture.height; y++)
    for (let x = 0; x < picture.width; x++)
      if (mask[y * picture.width + x]) {
        minX = Math.min(minX, x);
        maxX = Math.max(maxX, x);
        minY = Math.min(minY, y);
        maxY = Math.max(maxY, y);
      }
  if (maxX < minX) return { width: 0, height: 0 };
  return { width: (maxX - minX + 1) / picture.width, height: (maxY - minY + 1) / picture.height };
}

/** Share (0..1) of the foreground pixels whose colour satisfies `test` (r, g, b in 0..255). */
export function colourShare(picture: Picture, test: (r: number, g: number, b: number) => boolean): number {
  const mask = foregroundMask(picture);
  let foreground = 0;
  let matching = 0;
  for (let p = 0; p < mask.length; p++) {
    if (!mask[p]) continue;
    foreground++;
    const i = 4 * p;
    if (test(picture.data[i], picture.data[i + 1], picture.data[i + 2])) matching++;
  }
  return foreground === 0 ? 0 : matching / foreground;
}

/** Share (0..1) of all pixels whose colour differs by more than `threshold` (|ΔR|+|ΔG|+|ΔB|) between two same-sized pictures. */
export function differingShare(a: Picture, b: Picture, threshold = 0): number {
  if (a.width !== b.width || a.height !== b.height) throw new Error('pictures differ in size');
  let differing = 0;
  for (let i = 0; i < a.data.length; i += 4) if (distance(a.data, i, b.data, i) > threshold) differing++;
  return differing / (a.width * a.height);
}

/**
 * The width, in pixels, of the strokes of a line drawing in one colour on a plain
 * background, measured where strokes are straight and alone. Each pixel's coverage is its distance
 * from the background over the ink's (the farthest pixel's); a run of covered pixels across a row
 * is a stroke's section, its length the coverage summed (antialiased edges count in part). Where
 * the rows `k` above and below cross the same stroke with sections of the same length, the stroke
 * is straight there: its slope s comes from the sections' centres, and its width is the section's
 * length × 1/√(1 + s²). Joints, crossings and tips, where sections differ, are left out, and the
 * most common width is the answer.
 */
export function strokeWidth(picture: Picture, background = backgroundColour(picture), k = 2): number {
  const { width, height, data } = picture;
  let ink = 0;
  for (let p = 0; p < width * height; p++) ink = Math.max(ink, distance(data, 4 * p, background, 0));
  /** Each row's sections: (start, end, length by coverage, centre by coverage). */
  const rows: { start: number; end: number; length: number; centre: number }[][] = [];
  for (let y = 0; y < height; y++) {
    const sections: (typeof rows)[number] = [];
    let start = -1;
    let length = 0;
    let moment = 0;
    for (let x = 0; x <= width; x++) {
      const c = x < width ? Math.min(1, distance(data, 4 * (y * width + x), background, 0) / Math.max(1, ink)) : 0;
      if (c >= 0.08) {
        if (start < 0) [start, length, moment] = [x, 0, 0];
        length += c;
        moment += c * x;
      } else if (start >= 0) {
        sections.push({ start, end: x, length, centre: moment / length });
        start = -1;
      }
    }
    rows.push(sections);
  }
  const overlapping = (y: number, s: { start: number; end: number }) => rows[y].filter((o) => o.start < s.end + k * 2 && o.end > s.start - k * 2);
  const widths: number[] = [];
  for (let y = k; y < height - k; y++) {
    for (const section of rows[y]) {
      const [above, below] = [overlapping(y - k, section), overlapping(y + k, section)];
      if (above.length !== 1 || below.length !== 1) continue;
      if (Math.abs(above[0].length - section.length) > 0.75 || Math.abs(below[0].length - section.length) > 0.75) continue;
      const slope = (below[0].centre - above[0].centre) / (2 * k);
      widths.push(section.length / Math.sqrt(1 + slope * slope));
    }
  }
  // The most common width (to a quarter pixel): sections of merged strokes spread over many widths.
  const bins = new Map<number, number>();
  for (const w of widths) bins.set(Math.round(4 * w), (bins.get(Math.round(4 * w)) ?? 0) + 1);
  const [bin] = [...bins.entries()].sort((a, b) => b[1] - a[1])[0] ?? [0];
  return bin / 4;
}
