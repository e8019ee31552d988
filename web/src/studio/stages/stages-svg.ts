// The Stages figure as one SVG: the core's SVG drawing of each plant (the X–Y plane, Y up, in
// model units), placed in a grid like the 3D figure (stages-layout.ts): at one scale, or each
// enlarged to fill its tile; a caption under each. Pure string work, so it is tested without a browser.
import type { StageScale } from '../../view/stages-layout';

/** One plant's drawing: the core's SVG file, or `null` for a tile with only its caption. */
export interface StageDrawing {
  svg: string | null;
  caption: string;
}

interface Parsed {
  viewBox: [number, number, number, number];
  body: string;
}

/** The `viewBox` and the drawing inside the root element of the core's SVG, without its title and description. */
export function parseStageSvg(svg: string): Parsed | null {
  const open = /<svg\b[^>]*\bviewBox="([^"]+)"[^>]*>/.exec(svg);
  const close = svg.lastIndexOf('</svg>');
  if (!open || close < 0) return null;
  const viewBox = open[1].trim().split(/[\s,]+/).map(Number);
  if (viewBox.length !== 4 || !viewBox.every(Number.isFinite)) return null;
  const body = svg
    .slice(open.index + open[0].length, close)
    .replace(/<title>[\s\S]*?<\/title>\s*/, '')
    .replace(/<desc>[\s\S]*?<\/desc>\s*/, '');
  return { viewBox: viewBox as Parsed['viewBox'], body };
}

const escapeText = (text: string) => text.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;');
const round = (v: number) => String(Math.round(v * 1e4) / 1e4);

/** Longer side of the figure, in CSS pixels (its `width` and `height`; the drawing scales freely). */
const FIGURE_SIZE = 1600;

/**
 * The figure of `drawings` (row by row) in a `columns` × `rows` grid: every plant at the same
 * scale, centred in its tile and standing on the row's baseline, its caption under it; no stroke
 * thinner than a pixel of the figure's `width` × `height`. With `lineWidth` (pixels of the
 * figure), every stroke of every plant is that wide, as the view's Lines mode draws them: each
 * stage's own widths are in its own unit (docs/LANGUAGE.md, widths), which differs from stage to stage.
 */
export function stagesSvg(drawings: readonly StageDrawing[], columns: number, rows: number, title: string, fit: StageScale = 'one', lineWidth?: number): string {
  const parsed = drawings.map((d) => (d.svg ? parseStageSvg(d.svg) : null));
  const widest = Math.max(1e-9, ...parsed.map((p) => (p ? p.viewBox[2] : 0)));
  const tallest = Math.max(1e-9, ...parsed.map((p) => (p ? p.viewBox[3] : 0)));
  // With `each`, every drawing is enlarged to fit a tile sized for the largest.
  const enlarge = (p: Parsed) => (fit === 'one' ? 1 : Math.min(widest / Math.max(p.viewBox[2], 1e-9), tallest / Math.max(p.viewBox[3], 1e-9)));
  const tileWidth = widest * 1.1;
  const plantHeight = tallest * 1.04;
  const caption = Math.max(tallest, widest) * 0.09;
  const rowHeight = plantHeight + caption;
  const width = tileWidth * columns;
  const height = rowHeight * rows;
  const scale = FIGURE_SIZE / Math.max(width, height);
  // Strokes at least a pixel wide at the figure's size: the small, early stages stay visible.
  const thinnest = 1 / scale;
  const widen = (body: string, factor: number) =>
    body.replace(/stroke-width="([^"]+)"/g, (all, w: string) =>
      lineWidth !== undefined
        ? `stroke-width="${Number((lineWidth / scale / factor).toPrecision(4))}"`
        : Number(w) * factor < thinnest
          ? `stroke-width="${Number((thinnest / factor).toPrecision(4))}"`
          : all,
    );
  const parts: string[] = [
    '<?xml version="1.0" encoding="UTF-8"?>',
    `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${round(width)} ${round(height)}" width="${round(width * scale)}" height="${round(height * scale)}">`,
    `<title>${escapeText(title)}</title>`,
    '<desc>Made with Meristem: the stages side by side, each plant projected onto the X-Y plane, Y up, all at one scale.</desc>',
  ];
  drawings.forEach((drawing, i) => {
    const column = i % columns;
    const row = Math.floor(i / columns);
    const centreX = column * tileWidth + tileWidth / 2;
    const baseline = row * rowHeight + plantHeight;
    const p = parsed[i];
    if (p) {
      const [x, y, w, h] = p.viewBox;
      const k = Number(enlarge(p).toPrecision(8));
      const place = `translate(${round(centreX - k * (x + w / 2))} ${round(baseline - k * (y + h))})${k === 1 ? '' : ` scale(${k})`}`;
      parts.push(`<g transform="${place}">`, widen(p.body.trim(), k), '</g>');
    }
    parts.push(
      `<text x="${round(centreX)}" y="${round(baseline + caption * 0.7)}" font-family="system-ui, sans-serif" font-size="${round(caption * 0.55)}" text-anchor="middle" fill="#1f2328">${escapeText(drawing.caption)}</text>`,
    );
  });
  parts.push('</svg>', '');
  return parts.join('\n');
}
