import { describe, expect, it } from 'vitest';
import { captionHeight, stageTiles, type ViewExtent } from './stages-layout';

const extent = (minX: number, maxX: number, minY: number, maxY: number): ViewExtent => ({ minX, maxX, minY, maxY });
/** Model units per pixel of a tile (its frustum over its viewport). */
const perPixel = (t: ReturnType<typeof stageTiles>[number]) => (t.frustum.right - t.frustum.left) / t.viewport.width;

describe('stage tiles', () => {
  const plants = [extent(-1, 1, 0, 2), extent(-2, 4, 0, 10), null, extent(5, 6, 3, 4)];
  const tiles = stageTiles(plants, 4, 1, 800, 300);

  it('draws every plant at one scale, the tallest just fitting its tile', () => {
    const scales = tiles.map(perPixel);
    for (const s of scales) expect(s).toBeCloseTo(scales[0], 12);
    for (const t of tiles) expect((t.frustum.top - t.frustum.bottom) / t.viewport.height).toBeCloseTo(scales[0], 12);
    const plantHeight = 300 - captionHeight(300, 1);
    expect(10 / scales[0], 'the tallest plant fills most of its tile').toBeGreaterThan(0.8 * plantHeight);
    expect(10 / scales[0]).toBeLessThan(plantHeight);
  });

  it('centres each plant in its column and stands it on the baseline', () => {
    tiles.forEach((t, i) => {
      expect(t.viewport.x).toBeCloseTo(i * 200);
      expect(t.viewport.y).toBe(0);
      const e = plants[i];
      if (!e) return;
      expect((t.frustum.left + t.frustum.right) / 2).toBeCloseTo((e.minX + e.maxX) / 2);
      // Every plant's lowest point is the same small height above its tile's bottom.
      expect((e.minY - t.frustum.bottom) / perPixel(t)).toBeCloseTo((plants[0]!.minY - tiles[0].frustum.bottom) / perPixel(tiles[0]));
    });
  });

  it('puts each caption under its tile, centred', () => {
    for (const t of tiles) {
      expect(t.caption.x).toBeCloseTo(t.viewport.x + t.viewport.width / 2);
      expect(t.caption.y).toBeGreaterThan(t.viewport.y + t.viewport.height);
      expect(t.caption.y).toBeLessThan(300);
    }
  });

  it('lays rows of plants under each other, with a caption band each', () => {
    const grid = stageTiles([extent(0, 1, 0, 1), extent(0, 1, 0, 1), extent(0, 1, 0, 1), extent(0, 1, 0, 1)], 2, 2, 400, 400);
    expect(grid.map((t) => [t.viewport.x, t.viewport.y])).toEqual([
      [0, 0],
      [200, 0],
      [0, 200],
      [200, 200],
    ]);
    expect(grid[0].viewport.height).toBe(200 - captionHeight(400, 2));
  });

  it('fits each plant to its own tile when asked', () => {
    const each = stageTiles(plants, 4, 1, 800, 300, 'each');
    expect(perPixel(each[0])).toBeLessThan(perPixel(each[1]));
    // Every plant now fills its tile's width or height (as the largest did with one scale).
    each.forEach((t, i) => {
      const e = plants[i];
      if (!e) return;
      const share = Math.max((e.maxX - e.minX) / (t.frustum.right - t.frustum.left), (e.maxY - e.minY) / (t.frustum.top - t.frustum.bottom));
      expect(share).toBeGreaterThan(0.85);
    });
  });

  it('survives a figure with nothing drawn', () => {
    const empty = stageTiles([null, null], 2, 1, 100, 100);
    for (const t of empty) for (const v of Object.values(t.frustum)) expect(Number.isFinite(v)).toBe(true);
  });
});
