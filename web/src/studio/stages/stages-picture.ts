// Stages' picture settings: every k-th step between the first and the last iteration, and the PNG's
// background (white, transparent, or as shown), paper (A4, A5, Letter, turned to the figure's
// shape; or none: a tile of 420 × 560 pixels at 150 DPI a plant) and resolution (150 or 300 DPI),
// as the Download menu offers them for the view's PNG. Its controls are made with Stages (its
// chunk), not in index.html: the first plant needs none of them.
import { PAPERS, paperPixels, PICTURE_MAX } from '../downloads/downloads';
import type { PictureLook } from '../../view';

/** A tile of the PNG without paper at 150 DPI, in pixels. */
export const PNG_TILE = { width: 420, height: 560 };
/** The resolution the PNG without paper is laid out at (a tile's size above). */
const TILE_DPI = 150;
/** The resolution of CSS pixels, in which the view's line width is given. */
const CSS_DPI = 96;
/** The most steps between two stages. */
export const MAX_STAGE_STEP = 10;

/** The PNG's settings as chosen. */
export interface StagesPicture {
  background: PictureLook['background'];
  /** A paper of {@link PAPERS} the figure fills, or '' for none. */
  paper: keyof typeof PAPERS | '';
  dpi: number;
}

/**
 * The PNG's size in pixels for a figure of `columns` × `rows` plants: the paper's, landscape when
 * the figure is wider than tall, or a tile a plant (at most {@link PICTURE_MAX} a side, the tiles
 * shrunk to fit).
 */
export function stagesPictureSize(columns: number, rows: number, { paper, dpi }: Pick<StagesPicture, 'paper' | 'dpi'>): { width: number; height: number } {
  const wide = columns * PNG_TILE.width > rows * PNG_TILE.height;
  if (paper !== '') return paperPixels(`${paper}-${wide ? 'landscape' : 'portrait'}`, dpi);
  const tile = dpi / TILE_DPI;
  const scale = Math.min(tile, PICTURE_MAX / (columns * PNG_TILE.width), PICTURE_MAX / (rows * PNG_TILE.height));
  return { width: Math.round(columns * PNG_TILE.width * scale), height: Math.round(rows * PNG_TILE.height * scale) };
}

/** How many pixels of a PNG at `dpi` a CSS pixel of the screen (a 96th of an inch) is: the lines' and captions' scale. */
export function pixelsPerCssPixel(dpi: number): number {
  return dpi / CSS_DPI;
}

/** The controls Stages adds to its bar: the step, and the PNG's background, paper and DPI. */
export interface StagesPictureControls {
  step: HTMLInputElement;
  background: HTMLSelectElement;
  paper: HTMLSelectElement;
  dpi: HTMLSelectElement;
  /** The settings chosen. */
  picture(): StagesPicture;
}

/** A select of `options` ([value, text]), `chosen` selected, in a label `name` with the title `title`. */
function select(testId: string, name: string, title: string, options: [string, string][], chosen: string): { label: HTMLLabelElement; element: HTMLSelectElement } {
  const element = document.createElement('select');
  element.dataset.testid = testId;
  for (const [value, text] of options) element.append(new Option(text, value, value === chosen, value === chosen));
  const label = Object.assign(document.createElement('label'), { className: 'field', title });
  label.append(`${name} `, element);
  return { label, element };
}

/** Makes the controls: the step after the last iteration's box (`to`), the PNG's before `png`. */
export function addPictureControls(to: HTMLInputElement, png: HTMLButtonElement): StagesPictureControls {
  const step = Object.assign(document.createElement('input'), { type: 'number', min: '1', max: String(MAX_STAGE_STEP), step: '1', value: '1', inputMode: 'numeric' });
  step.dataset.testid = 'stages-step';
  const stepLabel = Object.assign(document.createElement('label'), { className: 'field', title: 'Every k-th step from the first iteration: 2 draws n = 0, 2, 4, 6' });
  stepLabel.append('every ', step);
  to.closest('label')?.after(stepLabel);
  const background = select('stages-background', 'Background', 'The PNG’s background: white, transparent, or as the figure is shown', [['white', 'white'], ['transparent', 'transparent'], ['view', 'as shown']], 'white');
  const papers = Object.entries(PAPERS).map(([key, p]): [string, string] => [key, p.label]);
  const paper = select('stages-paper', 'Paper', 'A sheet the PNG fills, turned to the figure’s shape; none: a tile of 420 × 560 pixels a plant at 150 DPI', [['', 'none'], ...papers], '');
  const dpi = select('stages-dpi', 'DPI', 'The PNG’s resolution, in dots per inch: its lines and captions keep their size on paper', [['150', '150'], ['300', '300']], '150');
  png.before(background.label, paper.label, dpi.label);
  return {
    step,
    background: background.element,
    paper: paper.element,
    dpi: dpi.element,
    picture: () => ({ background: background.element.value as StagesPicture['background'], paper: paper.element.value as StagesPicture['paper'], dpi: Number(dpi.element.value) }),
  };
}
