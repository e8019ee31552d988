// Where each plant of a Stages figure goes: a grid of tiles (a column per iteration, a row per
// seed), every plant drawn at one scale, centred in its tile and standing on the tile's baseline,
// so the figure reads like ABOP's developmental sequences (Figs 1.24, 1.30) and rows of specimens
// (Fig. 1.27). Pure arithmetic on the plants' extents as the camera sees them.

/** A plant's extent in the camera's view plane (x right, y up), in model units. */
export interface ViewExtent {
  minX: number;
  maxX: number;
  minY: number;
  maxY: number;
}

/** A rectangle of the picture, in pixels from its top-left corner. */
export interface PixelRect {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** One tile of the figure: where it is, what its camera sees, where its caption goes. */
export interface StageTile {
  /** The plant's part of the picture (above the caption). */
  viewport: PixelRect;
  /** The orthographic camera's frustum for this tile, in view-plane units. */
  frustum: { left: number; right: number; top: number; bottom: number };
  /** Centre of the caption's baseline, in pixels. */
  caption: { x: number; y: number };
}

/**
 * The caption band under each row, in pixels, for a picture `height` pixels high whose CSS pixel is
 * `scale` of its pixels (a PNG at 300 DPI: 3.1): from 18 to 44 CSS pixels.
 */
export function captionHeight(height: number, rows: number, scale = 1): number {
  return Math.round(Math.min(44 * scale, Math.max(18 * scale, (0.07 * height) / Math.sqrt(rows))));
}

/** Share of a tile's width and height a plant may fill (the rest is the gap to the next). */
const FILL = 0.9;
/** Space under each plant, as a share of the tile's height. */
const FOOT = 0.03;

/** How the plants of a figure are scaled: `one` scale for all (growth compared), or `each` fitted to its tile (shapes compared). */
export type StageScale = 'one' | 'each';

/**
 * The tiles of a `columns` × `rows` figure of `width` × `height` pixels for plants whose view
 * extents are `extents` (row by row; `null`: nothing drawn). With `one` scale, the widest and the
 * tallest plant just fit their tiles; with `each`, every plant just fits its own. `pixels`: the
 * picture's pixels a CSS pixel (see {@link captionHeight}).
 */
export function stageTiles(
  extents: readonly (ViewExtent | null)[],
  columns: number,
  rows: number,
  width: number,
  height: number,
  scale: StageScale = 'one',
  pixels = 1,
): StageTile[] {
  const caption = captionHeight(height, rows, pixels);
  const tileWidth = width / columns;
  const tileHeight = Math.max(1, height / rows - caption);
  // Model units per pixel that fit `plants`; a figure of points only (or nothing) gets an arbitrary one.
  const fitting = (plants: readonly (ViewExtent | null)[]) => {
    let widest = 0;
    let tallest = 0;
    for (const e of plants) {
      if (!e) continue;
      widest = Math.max(widest, e.maxX - e.minX);
      tallest = Math.max(tallest, e.maxY - e.minY);
    }
    return Math.max(widest / (tileWidth * FILL), tallest / (tileHeight * (FILL - FOOT)), 1e-9) || 1;
  };
  const common = fitting(extents);
  return extents.map((extent, i) => {
    const perPixel = scale === 'one' ? common : fitting([extent]);
    const column = i % columns;
    const row = Math.floor(i / columns);
    const viewport = { x: column * tileWidth, y: row * (tileHeight + caption), width: tileWidth, height: tileHeight };
    const centreX = extent ? (extent.minX + extent.maxX) / 2 : 0;
    const bottom = (extent ? extent.minY : 0) - FOOT * tileHeight * perPixel;
    const halfWidth = (tileWidth * perPixel) / 2;
    return {
      viewport,
      frustum: { left: centreX - halfWidth, right: centreX + halfWidth, bottom, top: bottom + tileHeight * perPixel },
      caption: { x: viewport.x + tileWidth / 2, y: viewport.y + tileHeight + caption * 0.7 },
    };
  });
}
