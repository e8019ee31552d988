// Writes the app's icons (public/icons/): an SVG of a plant grown by a bracketed L-system (ABOP
// fig. 1.24d's X -> F[+X][-X]FX, F -> FF, drawn by a small turtle here), and the PNGs the web app
// manifest and iOS need, rendered from that SVG by the system's Chromium: 192 and 512 px on a
// rounded square, 512 px "maskable" (full-bleed background, the plant inside the central 80 % safe
// zone) and a 180 px apple-touch-icon. Reproducible; run again only to change the picture.
// Usage: node scripts/make-icons.mjs  (from the repository root)
import { mkdirSync, writeFileSync } from 'node:fs';
import { chromium } from 'playwright-core';

const OUT = new URL('../public/icons/', import.meta.url);
const GREEN = '#2e7d32';
const LEAF = '#c8e6c9';

/** The derived string of the plant. */
function derive(axiom, rules, n) {
  let s = axiom;
  for (let i = 0; i < n; i++) s = [...s].map((c) => rules[c] ?? c).join('');
  return s;
}

/** Line segments of the turtle reading `s` (F draws a unit step; + and - turn; [ ] push and pop). */
function turtle(s, angle) {
  const segments = [];
  let state = { x: 0, y: 0, a: 90, depth: 0 };
  const stack = [];
  for (const c of s) {
    if (c === 'F') {
      const r = (state.a * Math.PI) / 180;
      const next = { ...state, x: state.x + Math.cos(r), y: state.y + Math.sin(r) };
      segments.push({ x1: state.x, y1: state.y, x2: next.x, y2: next.y, depth: state.depth });
      state = next;
    } else if (c === '+') state = { ...state, a: state.a + angle };
    else if (c === '-') state = { ...state, a: state.a - angle };
    else if (c === '[') {
      stack.push(state);
      state = { ...state, depth: state.depth + 1 };
    } else if (c === ']') state = stack.pop();
  }
  return segments;
}

/** The plant as SVG path data fitted into the box (x, y, size) of a 100 × 100 view. */
function plantPaths(x0, y0, size) {
  const segments = turtle(derive('X', { X: 'F[+X][-X]FX', F: 'FF' }, 5), 25.7);
  const xs = segments.flatMap((s) => [s.x1, s.x2]);
  const ys = segments.flatMap((s) => [s.y1, s.y2]);
  const [minX, maxX, minY, maxY] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const scale = size / Math.max(maxX - minX, maxY - minY);
  const ox = x0 + (size - (maxX - minX) * scale) / 2;
  const px = (x) => (ox + (x - minX) * scale).toFixed(2);
  const py = (y) => (y0 + size - (y - minY) * scale).toFixed(2); // y up in the turtle, down in SVG
  const byDepth = new Map();
  for (const s of segments) {
    const d = Math.min(s.depth, 3);
    byDepth.set(d, `${byDepth.get(d) ?? ''}M${px(s.x1)} ${py(s.y1)}L${px(s.x2)} ${py(s.y2)}`);
  }
  return [...byDepth.entries()]
    .sort(([a], [b]) => a - b)
    .map(([d, path]) => `<path d="${path}" stroke="${d === 0 ? '#ffffff' : LEAF}" stroke-width="${(3.2 - 0.7 * d).toFixed(1)}" stroke-linecap="round" fill="none"/>`)
    .join('');
}

/** The icon: a rounded square, or (maskable) a full-bleed square with the plant in the safe zone. */
function iconSvg(maskable) {
  const back = maskable ? `<rect width="100" height="100" fill="${GREEN}"/>` : `<rect x="2" y="2" width="96" height="96" rx="22" fill="${GREEN}"/>`;
  const plant = maskable ? plantPaths(24, 22, 54) : plantPaths(14, 12, 74);
  return `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">${back}${plant}</svg>\n`;
}

mkdirSync(OUT, { recursive: true });
const icon = iconSvg(false);
const maskable = iconSvg(true);
writeFileSync(new URL('icon.svg', OUT), icon);
const browser = await chromium.launch({ executablePath: '/usr/bin/chromium' });
for (const [file, svg, size] of [['icon-192.png', icon, 192], ['icon-512.png', icon, 512], ['maskable-512.png', maskable, 512], ['apple-touch-icon.png', maskable, 180]]) {
  const page = await browser.newPage({ viewport: { width: size, height: size } });
  await page.setContent(`<html><body style="margin:0;background:transparent">${svg.replace('<svg ', `<svg width="${size}" height="${size}" `)}</body></html>`);
  writeFileSync(new URL(file, OUT), await page.screenshot({ omitBackground: true }));
  await page.close();
}
await browser.close();
console.log(`icons written to ${OUT.pathname}`);
