import { describe, expect, it } from 'vitest';
import { fittedCaption } from '../../view/stages-view';
import { captionHeight } from '../../view/stages-layout';
import { paperPixels } from '../downloads/downloads';
import { stageCount, stagesOf } from './stages';
import { pixelsPerCssPixel, stagesPictureSize } from './stages-picture';

describe("Stages' step and picture", () => {
  it('draws every k-th iteration from the first, up to the last', () => {
    expect(stagesOf(0, 6, [undefined], 'one', 2).stages.map((s) => s.caption)).toEqual(['n = 0', 'n = 2', 'n = 4', 'n = 6']);
    expect(stagesOf(1, 8, [undefined], 'one', 3).stages.map((s) => s.iterations)).toEqual([1, 4, 7]);
    expect(stagesOf(1, 8, [3, 4], 'one', 3).grid).toEqual({ columns: 3, rows: 2, scale: 'one' });
    expect([stageCount(0, 9), stageCount(0, 9, 2), stageCount(5, 5, 4)]).toEqual([10, 5, 1]);
  });

  it('fills a paper turned to the figure, or gives each plant a tile, at the DPI chosen', () => {
    // A row of four plants is landscape; a column of specimens of two seeds of one step, portrait.
    expect(stagesPictureSize(4, 1, { paper: 'a5', dpi: 300 })).toEqual({ width: 2480, height: 1748 });
    expect(stagesPictureSize(1, 2, { paper: 'a4', dpi: 150 })).toEqual(paperPixels('a4-portrait', 150));
    // US Letter, 8.5 × 11 inches.
    expect(stagesPictureSize(1, 1, { paper: 'letter', dpi: 300 })).toEqual({ width: 2550, height: 3300 });
    expect(stagesPictureSize(5, 1, { paper: '', dpi: 150 })).toEqual({ width: 2100, height: 560 });
    expect(stagesPictureSize(5, 1, { paper: '', dpi: 300 })).toEqual({ width: 4200, height: 1120 });
    // Never past 8192 pixels a side: the tiles shrink.
    expect(stagesPictureSize(10, 8, { paper: '', dpi: 300 }).height).toBeLessThanOrEqual(8192);
    expect(pixelsPerCssPixel(96)).toBe(1);
  });

  it('shrinks a caption that would pass its tile, and scales the caption band with the picture', () => {
    const width = (text: string, size: number) => text.length * size * 0.5; // half an em a character
    expect(fittedCaption('n = 3', 20, 400, width)).toEqual({ lines: ['n = 3'], size: 20 });
    // 21 characters: 210 pixels at 20; broken, its widest line (15 characters, 150 pixels) shrunk to 100.
    const broken = fittedCaption('n = 0 (nothing drawn)', 20, 100, width);
    expect(broken.lines).toEqual(['n = 0', '(nothing drawn)']);
    expect(broken.size).toBeCloseTo((20 * 100) / 150);
    expect(fittedCaption('n = 2: the core crashed', 20, 200, width).lines).toEqual(['n = 2:', 'the core crashed']);
    expect(captionHeight(300, 1, 1)).toBe(21);
    expect(captionHeight(1748, 1, 300 / 96)).toBe(Math.round(1748 * 0.07)); // on A5 at 300 DPI: type as large as on screen, not 44 px
    expect(captionHeight(5000, 1, 2)).toBe(88);
  });
});
