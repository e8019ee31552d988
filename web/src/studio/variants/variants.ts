// Variants: two to six plants side by side in one view (issue 48): other grammars, or one grammar
// with a constant at several values or grown with several seeds, like ABOP's Fig. 1.27 row of
// specimens. One figure drawn by Stages' view (one renderer, a viewport per plant, one camera: drag
// to turn them all, the wheel zooms them all), grown one after the other in a build worker of its
// own with progress and Stop; under it a card per plant with its figures and its diff against the
// first; the row downloads as one PNG and one SVG, each plant captioned. Loaded on first use
// (variants-loader.ts).
import '../stages/stages.css';
import './variants.css';
import type { PlantSketch } from '../../core';
import type { BuildClient, BuildResult } from '../../build';
import type { SharedVariant } from '../../share';
import { MIN_SHARED_VARIANTS as MIN_VARIANTS, MAX_SHARED_VARIANTS as MAX_VARIANTS } from '../../share/variants-state';
import { StagesView, type StagePlant, type StagesGrid } from '../../view/stages-view';
import { loadVocabulary } from '../../core';
import { FigureBudget, figureDrawings, figurePlant } from '../stages/stages';
import { pixelsPerCssPixel, stagesPictureSize } from '../stages/stages-picture';
import { stagesSvg } from '../stages/stages-svg';
import { saveFile } from '../files/save-file';
import { el } from '../page/make-element';
import { VariantCards, type VariantFigures } from './variant-cards';
import { defineVariants, numericConstants, parseValues, seedVariants, valuesAround } from './variant-making';
import { VariantsBar } from './variants-bar';

/** The pause after typing in a card before its plants are grown again. */
const TYPING_MS = 400;

/** What Variants needs of the studio. */
export interface VariantsHost {
  /** Where the view goes: over the 3D view. */
  viewport: HTMLElement;
  /** The plant on screen (the last good build): its text and options start the variants. */
  shown(): BuildResult | undefined;
  /** A client of a build worker of its own (not the live preview's), made when Variants opens. */
  createClient(): BuildClient;
  /** Whether the plants are lit (the view's Light option). */
  lighting(): boolean;
  /** The file name the downloads start with (no extension). */
  fileName(): string;
  /** Variants turned on or off (the 3D view's own tools pause meanwhile). */
  toggled(on: boolean): void;
}

export class VariantsMode {
  private readonly panel: HTMLElement;
  private readonly figure: HTMLElement;
  private readonly bar: VariantsBar;
  private readonly cards: VariantCards;
  private view: StagesView | undefined;
  private client: BuildClient | undefined;
  private variants: SharedVariant[] = [];
  private ticket = 0;
  private typing: ReturnType<typeof setTimeout> | undefined;
  /** The plants on screen (shown again at another scale). */
  private plants: StagePlant[] = [];
  /** The figure on screen: which plants drew something (for the SVG). */
  private drawn: boolean[] | undefined;

  constructor(
    private readonly toggleButton: HTMLButtonElement,
    private readonly host: VariantsHost,
  ) {
    this.bar = new VariantsBar({
      make: (kind, what, values) => this.make(kind, what, values),
      add: (text, caption) => this.add({ text, caption }),
      addShown: () => this.add({ ...this.fromShown(), caption: `plant ${this.variants.length + 1}` }),
      constants: () => numericConstants(this.fromShown().text).map((c) => c.name),
      rescaled: () => this.view?.show(this.plants, this.grid()),
      stop: () => this.stop(),
      png: () => void this.downloadPng(),
      svg: () => void this.downloadSvg(),
      close: () => this.close(),
    });
    this.figure = el('div', { className: 'stages-figure variants-figure', testid: 'variants-figure', role: 'img', ariaLabel: 'The variants side by side: drag or the arrow keys turn them all, the wheel or + and − zoom them all' });
    const list = el('ol', { className: 'variant-cards', testid: 'variant-cards', ariaLabel: 'The variants: their figures and differences' });
    this.cards = new VariantCards(list, { edited: (i, regrow) => (regrow ? this.edited() : this.recaption(i)), removed: (i) => this.remove(i) });
    this.panel = el('div', { className: 'stages variants', testid: 'variants', id: 'variants', hidden: true }, this.bar.element, el('div', { className: 'variants-body' }, this.figure, list));
    this.panel.setAttribute('role', 'region');
    this.panel.setAttribute('aria-label', 'Variants');
    host.viewport.append(this.panel);
  }

  get open(): boolean {
    return this.view !== undefined;
  }

  /** Opens or closes the view. */
  toggle(): void {
    if (this.open) this.close();
    else void this.show();
  }

  /**
   * Opens the view with `variants` (a link's), else with those it had, else with those made from
   * the plant on screen: its first numeric constant at three values, or the grammar and a copy.
   */
  async show(variants?: readonly SharedVariant[]): Promise<void> {
    if (variants) this.variants = variants.map((v) => ({ ...v }));
    if (!this.open) {
      this.panel.hidden = false;
      this.toggleButton.setAttribute('aria-pressed', 'true');
      this.view = new StagesView(this.figure, { orbit: true });
      this.view.setLighting(this.host.lighting());
      this.client = this.host.createClient();
      this.host.toggled(true);
    }
    await loadVocabulary().catch(() => undefined); // the constants are read as the core's vocabulary spells #define
    this.bar.showConstants(numericConstants(this.fromShown().text).map((c) => c.name));
    if (this.variants.length < MIN_VARIANTS) this.variants = this.firstVariants();
    this.cards.render(this.variants, { min: MIN_VARIANTS });
    void this.grow();
  }

  /** Closes the view: the 3D view of the plant is back; the variants stay for the next opening. */
  close(): void {
    if (!this.view) return;
    this.ticket++;
    clearTimeout(this.typing);
    this.view.dispose();
    this.view = undefined;
    this.client?.dispose();
    this.client = undefined;
    this.drawn = undefined;
    this.plants = [];
    this.panel.hidden = true;
    this.toggleButton.setAttribute('aria-pressed', 'false');
    this.host.toggled(false);
  }

  /** The variants on screen, for a share link (none when the view is closed). */
  shared(): SharedVariant[] | undefined {
    return this.open ? this.variants.map((v) => ({ ...v })) : undefined;
  }

  /** The view's Light option changed. */
  setLighting(lit: boolean): void {
    this.view?.setLighting(lit);
  }

  /** The plant on screen as a variant: its text, and the iterations and seed it was built with when set. */
  private fromShown(): SharedVariant {
    const shown = this.host.shown();
    if (!shown) return { text: '' };
    const { iterations, seed } = shown.options;
    return { text: shown.source, ...(iterations === undefined ? {} : { iterations }), ...(seed === undefined ? {} : { seed }) };
  }

  private firstVariants(): SharedVariant[] {
    const base = this.fromShown();
    const [constant] = numericConstants(base.text);
    if (constant) {
      const { name } = constant;
      const values = valuesAround(constant.value);
      const made = defineVariants(base.text, name, values, base.seed);
      if (typeof made !== 'string') return made.map((v) => ({ ...v, ...(base.iterations === undefined ? {} : { iterations: base.iterations }) }));
    }
    // No constant to vary: the grammar and a copy of it to edit (seeds may make no difference).
    return [
      { ...base, caption: 'plant 1' },
      { ...base, caption: 'copy' },
    ];
  }

  /** Replaces the variants by those made from the plant on screen: a constant at `values`, or `values` as seeds. */
  private make(kind: 'define' | 'seeds', name: string, typed: string): void {
    const values = parseValues(typed);
    if (typeof values === 'string') return this.bar.say('error', values);
    if (values.length < MIN_VARIANTS) return this.bar.say('error', `Give ${MIN_VARIANTS} to ${MAX_VARIANTS} values.`);
    const base = this.fromShown();
    const made = kind === 'define' ? defineVariants(base.text, name, values, base.seed) : seedVariants(base.text, values);
    if (typeof made === 'string') return this.bar.say('error', made);
    this.variants = made.map((v) => (base.iterations === undefined ? v : { ...v, iterations: base.iterations }));
    this.cards.render(this.variants, { min: MIN_VARIANTS });
    void this.grow();
  }

  private add(variant: SharedVariant): void {
    if (this.variants.length >= MAX_VARIANTS) return this.bar.say('error', `At most ${MAX_VARIANTS} plants side by side: remove one first.`);
    this.variants.push(variant);
    this.cards.render(this.variants, { min: MIN_VARIANTS });
    void this.grow();
  }

  private remove(index: number): void {
    if (this.variants.length <= MIN_VARIANTS) return;
    this.variants.splice(index, 1);
    this.cards.render(this.variants, { min: MIN_VARIANTS });
    void this.grow();
  }

  /** A card's text, seed or iterations changed: the plants are grown again after a pause in the typing. */
  private edited(): void {
    clearTimeout(this.typing);
    this.ticket++; // what was being grown is for the old texts
    this.bar.growing(true); // Stop works from the first key: it also cancels the pending growing
    this.bar.say('growing', 'Growing…');
    this.typing = setTimeout(() => void this.grow(), TYPING_MS);
  }

  /** A card's caption changed: under its plant at once (a plant that drew nothing keeps saying why until grown again). */
  private recaption(index: number): void {
    const plant = this.plants[index];
    if (!plant?.mesh) return;
    plant.caption = captionOf(this.variants[index], index);
    this.view?.setCaptions(this.plants.map((p) => p.caption));
  }

  private stop(): void {
    this.ticket++;
    clearTimeout(this.typing);
    this.client?.stop();
    this.bar.growing(false);
    this.bar.say('done', 'Stopped: press a plant’s Text, or Make, to grow them again.');
  }

  /** Grows every variant, one after the other, then shows the row. */
  private async grow(): Promise<void> {
    const ticket = ++this.ticket;
    const { view, client } = this;
    if (!view || !client) return;
    const variants = this.variants.map((v) => ({ ...v }));
    const options = this.host.shown()?.options ?? {};
    const plants: StagePlant[] = [];
    const figures: (VariantFigures | string)[] = [];
    this.bar.growing(true);
    const budget = new FigureBudget();
    for (const [i, variant] of variants.entries()) {
      const caption = captionOf(variant, i);
      this.bar.say('growing', `Growing ${caption} (${i + 1} of ${variants.length})…`);
      let sketch: PlantSketch | null = null;
      const asked = { ...options, tubes: true, iterations: variant.iterations, seed: variant.seed };
      const outcome = await client.request(variant.text, asked, { onSketch: (s) => (sketch = s), sketchFrom: 0 });
      if (ticket !== this.ticket) {
        if (outcome.kind === 'built') outcome.result.inspector.free();
        return;
      }
      const build = outcome.kind === 'built' ? outcome.result.build : undefined;
      figures.push(build?.ok ? { modules: build.stats.modules, segments: build.stats.segments, height: build.stats.bounds[1][1] - build.stats.bounds[0][1] } : 'No plant: see its caption');
      plants.push(budget.keep(figurePlant(caption, outcome.kind === 'built' ? outcome.result : outcome.kind, sketch)));
    }
    this.bar.growing(false);
    this.plants = plants;
    view.show(plants, this.grid());
    this.drawn = plants.map((p) => p.mesh !== null);
    this.cards.showFigures(figures);
    const missing = plants.filter((p) => !p.mesh).length - budget.leftOut;
    this.bar.say('done', `${plants.length} plants at ${this.grid().scale === 'one' ? 'one scale' : 'each fitted'}${missing ? `; ${missing} drew nothing` : ''}${budget.words()}. Drag to turn them all.`);
  }

  private grid(): StagesGrid {
    return { columns: this.variants.length, rows: 1, scale: this.bar.scale() };
  }

  private async downloadPng(): Promise<void> {
    if (!this.view || !this.drawn) return;
    // A tile of 420 × 560 pixels a plant at 150 DPI, on white, as Stages' PNG without paper.
    const grid = this.grid();
    const { width, height } = stagesPictureSize(grid.columns, grid.rows, { paper: '', dpi: 150 });
    try {
      const png = await this.view.picture(width, height, { background: 'white', scale: pixelsPerCssPixel(150) });
      saveFile(png, `${this.host.fileName()}-variants.png`, 'image/png');
      this.bar.say('done', `Saved the row as a ${width} × ${height} PNG`);
    } catch (error) {
      this.bar.say('error', `Could not draw the PNG: ${error instanceof Error ? error.message : String(error)}`);
    }
  }

  /** Each plant's SVG from the core (the X–Y plane), then the row as one SVG. */
  private async downloadSvg(): Promise<void> {
    const drawn = this.drawn;
    if (!drawn) return;
    const ticket = this.ticket;
    const options = this.host.shown()?.options ?? {};
    const plants = this.variants.map((v, i) => ({ source: v.text, options: { ...options, iterations: v.iterations, seed: v.seed }, caption: captionOf(v, i), drawn: drawn[i] }));
    try {
      const drawings = await figureDrawings(plants, (text) => this.bar.say('growing', text), () => ticket === this.ticket);
      if (!drawings) return;
      const name = this.host.fileName();
      const svg = stagesSvg(drawings, drawings.length, 1, `${name}: variants`, this.grid().scale);
      saveFile(new Blob([svg], { type: 'image/svg+xml' }), `${name}-variants.svg`, 'image/svg+xml');
      this.bar.say('done', 'Saved the row as an SVG');
    } catch (error) {
      this.bar.say('error', `Could not write the SVG: ${error instanceof Error ? error.message : String(error)}`);
    }
  }
}

/** A variant's caption: its own, else its number. */
function captionOf(variant: SharedVariant, index: number): string {
  return variant.caption?.trim() || `plant ${index + 1}`;
}
