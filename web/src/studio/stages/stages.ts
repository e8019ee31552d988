// Stages: a view mode that draws iterations a … b of the grammar side by side (ABOP Figs 1.24,
// 1.30), and with several seeds a row of specimens per seed (Fig. 1.27), every plant at one scale;
// the figure downloads as one PNG and one SVG. The plants are grown in a build worker of their own
// (the live preview's keeps serving the editor), one after the other; a change of the grammar, the
// options or the range starts again and drops what was under way.
import './stages.css';
import type { BuildOptions, PlantSketch } from '../../core';
import type { StageScale } from '../../view/stages-layout';
import { StagesView, type StagePlant, type StagesGrid } from '../../view/stages-view';
// Loaded on demand: it imports other areas' files, not their indexes, which would bring their
// wiring into its chunk's graph (and split the first load into more files).
import { afterPaint, withResolution } from '../downloads/downloads';
import { saveFile } from '../files/save-file';
import { createExportWorker, runExport } from '../downloads/export-client';
import { stagesSvg, type StageDrawing } from './stages-svg';
import { addPictureControls, MAX_STAGE_STEP, pixelsPerCssPixel, stagesPictureSize, type StagesPictureControls } from './stages-picture';
import { growthKey } from '../controls/view-following';
import type { BuildClient, BuildResult } from '../../build';

/** Most iterations side by side, and most seeds, in one figure. */
export const MAX_STAGE_COLUMNS = 10;
export const MAX_STAGE_SEEDS = 8;
/** The pause after typing in the range before the figure is grown again. */
const RANGE_TYPING_MS = 300;

/** The controls (see index.html). */
export interface StagesElements {
  /** The view tool that turns Stages on and off. */
  toggle: HTMLButtonElement;
  /** The panel over the 3D view: the bar and the figure. */
  panel: HTMLElement;
  figure: HTMLElement;
  from: HTMLInputElement;
  to: HTMLInputElement;
  seeds: HTMLInputElement;
  /** `one` scale for all the plants, or `each` fitted to its tile. */
  scale: HTMLSelectElement;
  /** What is happening, with `data-state`: `growing`, `done` or `error`. */
  status: HTMLElement;
  png: HTMLButtonElement;
  svg: HTMLButtonElement;
}

/** What Stages needs of the studio. */
export interface StagesHost {
  /** The plant on screen (the last good build): its text and options are the figure's. */
  shown(): BuildResult | undefined;
  /** A client of a build worker of its own (not the live preview's), made when Stages opens. */
  createClient(): BuildClient;
  /** Whether the plants are lit (the view's Light option). */
  lighting(): boolean;
  /** The width of the view's lines in CSS pixels (its Lines mode's). */
  lineWidth(): number;
  /** The file name the downloads start with (no extension). */
  fileName(): string;
  /** Stages turned on or off (the 3D view's own tools pause meanwhile). */
  toggled(on: boolean): void;
}

/** One plant of the figure, as asked of the core. */
interface Stage {
  iterations: number;
  seed: number | undefined;
  caption: string;
}

/** How many stages iterations `from` to `to`, every `step`-th, are. */
export function stageCount(from: number, to: number, step = 1): number {
  return Math.floor((to - from) / step) + 1;
}

/** The figure a range asks for (every `step`-th iteration from `from`, up to `to`): its stages (row by row) and grid. */
export function stagesOf(from: number, to: number, seeds: readonly (number | undefined)[], scale: StageScale = 'one', step = 1): { stages: Stage[]; grid: StagesGrid } {
  const stages: Stage[] = [];
  const specimens = from === to && seeds.length > 1; // one row of specimens (ABOP Fig. 1.27)
  for (const seed of seeds)
    for (let n = from; n <= to; n += step) {
      const caption = specimens ? `seed ${seed}` : seeds.length > 1 ? `n = ${n}, seed ${seed}` : `n = ${n}`;
      stages.push({ iterations: n, seed, caption });
    }
  const grid = specimens ? { columns: seeds.length, rows: 1, scale } : { columns: stageCount(from, to, step), rows: seeds.length, scale };
  return { stages, grid };
}

function wholeNumber(input: HTMLInputElement): number | undefined {
  const value = input.valueAsNumber;
  return Number.isFinite(value) ? Math.floor(value) : undefined;
}

/**
 * Most bytes the plants of one figure (Stages, Variants) may hold in the page together: meshes,
 * lines and GPU arrays. Ten stages of a plant near the mesh's limit, times eight seeds, would
 * otherwise ask the page for gigabytes (a phone's tab dies; the text is autosaved, the figure lost).
 */
export const MAX_FIGURE_BYTES = 512 * 2 ** 20;

/** Bytes a plant of a figure holds in the page. */
export function plantBytes(plant: StagePlant): number {
  const arrays = [plant.mesh, plant.gpu, plant.lines].flatMap((group) => Object.values(group ?? {}) as unknown[]);
  return arrays.reduce<number>((sum, a) => sum + (ArrayBuffer.isView(a) ? a.byteLength : 0), 0);
}

/** The bytes a figure's plants hold so far, and the plants left out to stay within its budget. */
export class FigureBudget {
  private held = 0;
  leftOut = 0;

  constructor(private readonly limit = MAX_FIGURE_BYTES) {}

  /** `plant`, or a tile with only its caption when it would take the figure past the budget. */
  keep(plant: StagePlant): StagePlant {
    const bytes = plantBytes(plant);
    if (this.held + bytes <= this.limit) {
      this.held += bytes;
      return plant;
    }
    this.leftOut += 1;
    return { mesh: null, lines: null, flat: true, bounds: [[0, 0, 0], [0, 0, 0]], caption: `${plant.caption}: left out (over ${this.limit / 2 ** 20} MB)` };
  }

  /** The status's words for the plants left out ('' when none was). */
  words(): string {
    if (this.leftOut === 0) return '';
    return `; ${this.leftOut} left out: the figure would hold more than ${this.limit / 2 ** 20} MB (fewer iterations or seeds)`;
  }
}

/**
 * A plant of a figure from its build's outcome (freeing the build's inspector), with its `caption`;
 * a tile with only its caption, saying why, when there is nothing to draw. Stages and Variants.
 */
export function figurePlant(caption: string, result: BuildResult | 'superseded' | 'crashed' | 'stopped', sketch: PlantSketch | null): StagePlant {
  const empty: StagePlant = { mesh: null, lines: null, flat: true, bounds: [[0, 0, 0], [0, 0, 0]], caption };
  if (result === 'superseded' || result === 'stopped') return { ...empty, caption: `${caption}: not grown` };
  if (result === 'crashed') return { ...empty, caption: `${caption}: the core crashed` };
  result.inspector.free();
  const { build } = result;
  if (!build.ok) return { ...empty, caption: `${caption}: ${build.diagnostics.first('error')?.message ?? 'errors'}` };
  const drawn = build.mesh.indices.length > 0 || build.mesh.lines.length > 0;
  if (!drawn) return { ...empty, caption: `${caption} (nothing drawn)` };
  return { mesh: build.mesh, gpu: result.gpu, lines: sketch, flat: build.flat, bounds: build.stats.bounds, caption };
}

/** One plant of a figure's SVG, as asked of the core. */
export interface FigureSource {
  source: string;
  options: BuildOptions;
  caption: string;
  /** False for a tile that drew nothing (only its caption). */
  drawn: boolean;
}

/**
 * The core's SVG of each plant, written one after the other in an export worker (as the Download
 * menu's SVG), `say`ing which; undefined when `wanted` turns false meanwhile. Throws what failed.
 */
export async function figureDrawings(plants: readonly FigureSource[], say: (text: string) => void, wanted: () => boolean): Promise<StageDrawing[] | undefined> {
  const drawings: StageDrawing[] = [];
  for (const [i, plant] of plants.entries()) {
    if (!plant.drawn) {
      drawings.push({ svg: null, caption: plant.caption });
      continue;
    }
    say(`Drawing the SVG of ${plant.caption} (${i + 1} of ${plants.length})…`);
    await afterPaint();
    const outcome = await runExport(createExportWorker, { source: plant.source, format: 'svg', options: plant.options }, () => {}).done;
    if (!wanted()) return undefined;
    if (outcome.kind !== 'done') throw new Error(outcome.kind === 'failed' ? outcome.message : 'cancelled');
    drawings.push({ svg: new TextDecoder().decode(outcome.file.bytes), caption: plant.caption });
  }
  return drawings;
}

export class StagesMode {
  private view: StagesView | undefined;
  private client: BuildClient | undefined;
  private ticket = 0;
  /** What the figure on screen was grown from (a delivered build with another key grows it again). */
  private key: string | undefined;
  /** The figure on screen: the text and options, and its stages, for the SVG. */
  private figure: { source: string; options: BuildOptions; stages: Stage[]; grid: StagesGrid; drawn: boolean[]; lines: number | null } | undefined;
  /** The step and the PNG's settings (made with Stages). */
  private readonly picture: StagesPictureControls;

  constructor(
    private readonly els: StagesElements,
    private readonly host: StagesHost,
  ) {
    els.toggle.addEventListener('click', () => (this.open ? this.close() : this.show()));
    // The figure follows the range as it is typed (after a pause, so "12" is not grown as "1" first).
    let typing: ReturnType<typeof setTimeout> | undefined;
    els.scale.addEventListener('change', () => void this.grow());
    this.picture = addPictureControls(els.to, els.png);
    for (const input of [els.from, els.to, els.seeds, this.picture.step])
      input.addEventListener('input', () => {
        clearTimeout(typing);
        this.ticket++; // what was being grown is for the old range
        this.say('growing', 'Growing…');
        typing = setTimeout(() => void this.grow(), RANGE_TYPING_MS);
      });
    els.png.addEventListener('click', () => void this.downloadPng());
    els.svg.addEventListener('click', () => void this.downloadSvg());
  }

  get open(): boolean {
    return this.view !== undefined;
  }

  /** Turns Stages on: iterations up to the one on screen, five at most, unless a range was set. */
  show(): void {
    if (this.open) return;
    const shown = this.host.shown();
    if (this.els.to.value === '' && shown) {
      const n = shown.options.iterations ?? shown.build.grammarIterations;
      this.els.to.value = String(n);
      this.els.from.value = String(Math.max(n > 0 ? 1 : 0, n - 4));
    }
    if (this.els.seeds.value === '') this.els.seeds.value = '1';
    this.els.panel.hidden = false;
    this.els.toggle.setAttribute('aria-pressed', 'true');
    this.view = new StagesView(this.els.figure);
    this.client = this.host.createClient();
    this.view.setLighting(this.host.lighting());
    this.host.toggled(true);
    void this.grow();
  }

  /** Turns Stages off: the 3D view of the plant is back. */
  close(): void {
    if (!this.view) return;
    this.ticket++;
    this.view.dispose();
    this.view = undefined;
    this.client?.dispose(); // its worker and the wasm memory of the stages go
    this.client = undefined;
    this.key = undefined;
    this.figure = undefined;
    this.els.panel.hidden = true;
    this.els.toggle.setAttribute('aria-pressed', 'false');
    this.host.toggled(false);
  }

  /** A build is on screen: a different text or options grow the figure again. */
  delivered(result: BuildResult): void {
    if (this.open && result.build.ok && growthKey(result) !== this.key) void this.grow();
  }

  /** The view's Light option changed. */
  setLighting(lit: boolean): void {
    this.view?.setLighting(lit);
  }

  private say(state: 'growing' | 'done' | 'error', text: string): void {
    this.els.status.textContent = text;
    this.els.status.dataset.state = state;
  }

  /** The range asked for, or why it cannot be drawn. */
  private range(): { from: number; to: number; seeds: number; step: number } | string {
    const from = wholeNumber(this.els.from);
    const to = wholeNumber(this.els.to);
    const seeds = wholeNumber(this.els.seeds) ?? 1;
    const step = this.picture.step.valueAsNumber;
    if (from === undefined || to === undefined || from < 0 || to < 0) return 'Give the first and last iteration (0 or more).';
    if (from > to) return `The first iteration (${from}) is after the last (${to}).`;
    if (!(Number.isInteger(step) && step >= 1 && step <= MAX_STAGE_STEP)) return `Every k-th step: a whole k from 1 to ${MAX_STAGE_STEP}.`;
    const count = stageCount(from, to, step);
    if (count > MAX_STAGE_COLUMNS) return `At most ${MAX_STAGE_COLUMNS} iterations side by side (${from} to ${to}${step > 1 ? ` every ${step}` : ''} is ${count}).`;
    if (seeds < 1 || seeds > MAX_STAGE_SEEDS) return `Seeds: 1 to ${MAX_STAGE_SEEDS}.`;
    return { from, to, seeds, step };
  }

  /** Grows every stage of the range, one after the other, then shows the figure. */
  private async grow(): Promise<void> {
    const ticket = ++this.ticket;
    const shown = this.host.shown();
    const view = this.view;
    const client = this.client;
    if (!view || !client || !shown) return;
    const range = this.range();
    if (typeof range === 'string') {
      this.say('error', range);
      return;
    }
    this.key = growthKey(shown);
    const { source, options } = shown;
    const first = options.seed ?? shown.build.seed;
    const seeds = range.seeds === 1 ? [options.seed] : Array.from({ length: range.seeds }, (_, i) => first + i);
    const { stages, grid } = stagesOf(range.from, range.to, seeds, this.els.scale.value === 'each' ? 'each' : 'one', range.step);
    // Drawn as the view draws the plant: lines of one width in pixels in every stage (the Lines
    // mode, and a flat plant in Auto), or tubes.
    const lines = options.tubes === false || (options.tubes === 'unlessFlat' && shown.build.flat) ? this.host.lineWidth() : null;
    const plants: StagePlant[] = [];
    const budget = new FigureBudget();
    for (const [i, stage] of stages.entries()) {
      this.say('growing', `Growing ${stage.caption} (${i + 1} of ${stages.length})…`);
      // The sketch (the segments as lines) of every stage: drawn with the tubes, it keeps the early,
      // small stages visible where their tubes are thinner than a pixel.
      let sketch: PlantSketch | null = null;
      // Tubes whatever the view's render mode: the figure draws every stage with its tubes.
      const outcome = await client.request(source, { ...options, tubes: true, iterations: stage.iterations, seed: stage.seed }, { onSketch: (s) => (sketch = s), sketchFrom: 0 });
      if (ticket !== this.ticket) {
        if (outcome.kind === 'built') outcome.result.inspector.free();
        return;
      }
      plants.push(budget.keep(figurePlant(stage.caption, outcome.kind === 'built' ? outcome.result : outcome.kind, sketch)));
    }
    view.show(plants, grid, lines);
    this.figure = { source, options, stages, grid, drawn: plants.map((p) => p.mesh !== null), lines };
    const missing = plants.filter((p) => !p.mesh).length - budget.leftOut;
    const scaled = `${stages.length} plants ${grid.scale === 'one' ? 'at one scale' : 'each fitted to its tile'}`;
    this.say('done', (missing === 0 ? scaled : `${scaled}; ${missing} drew nothing`) + budget.words());
  }

  private async downloadPng(): Promise<void> {
    const view = this.view;
    const figure = this.figure;
    if (!view || !figure) return;
    const chosen = this.picture.picture();
    const { width, height } = stagesPictureSize(figure.grid.columns, figure.grid.rows, chosen);
    try {
      const drawn = await view.picture(width, height, { background: chosen.background, scale: pixelsPerCssPixel(chosen.dpi) });
      const png = withResolution(new Uint8Array(await drawn.arrayBuffer()), chosen.dpi);
      saveFile(png, `${this.host.fileName()}-stages.png`, 'image/png');
      this.say('done', `Saved the figure as a ${width} × ${height} PNG at ${chosen.dpi} DPI`);
    } catch (error) {
      this.say('error', `Could not draw the PNG: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  /** Writes each plant's SVG in an export worker (as the Download menu's SVG), then the figure. */
  private async downloadSvg(): Promise<void> {
    const figure = this.figure;
    if (!figure) return;
    const ticket = this.ticket;
    this.els.svg.disabled = true;
    try {
      const plants = figure.stages.map((stage, i) => ({
        source: figure.source,
        options: { ...figure.options, iterations: stage.iterations, seed: stage.seed },
        caption: stage.caption,
        drawn: figure.drawn[i],
      }));
      const drawings = await figureDrawings(plants, (text) => this.say('growing', text), () => ticket === this.ticket);
      if (!drawings) return;
      const name = this.host.fileName();
      const svg = stagesSvg(drawings, figure.grid.columns, figure.grid.rows, `${name}: stages`, figure.grid.scale, figure.lines ?? undefined);
      saveFile(new Blob([svg], { type: 'image/svg+xml' }), `${name}-stages.svg`, 'image/svg+xml');
      this.say('done', `Saved the figure as an SVG`);
    } catch (error) {
      this.say('error', `Could not write the SVG: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      this.els.svg.disabled = false;
    }
  }
}
