// A plant embedded in another page: the 3D view of a grammar (drag or the arrow keys to orbit),
// optional iteration buttons with Play and `#define` sliders, and a link that opens the grammar in
// the studio. Used by the view-only page (embed.html) and the <meristem-plant> element; the builds
// go to the page's one shared worker. Small enough for 320 × 240.
import type { BuildOptions } from '../core';
import { encodeState } from '../share';
import { Playback, SliderPanel } from '../plant-controls';
import type { BuildOutcome } from '../build';
import { PlantView } from '../view';
import type { SharedBuilds } from './shared-builds';

/** The controls an embedded plant can show. */
export type EmbedControl = 'iterations' | 'sliders';

/** What to show and where Meristem is. */
export interface EmbedSettings {
  /** The grammar. */
  source: string;
  /** Overrides `#iterations` at the start (the buttons change it). */
  iterations?: number;
  seed?: number;
  controls: ReadonlySet<EmbedControl>;
  /** The site's root: the studio (index.html) and its textures are there. */
  siteRoot: string;
  builds: SharedBuilds;
}

/** The controls given as a list (`"iterations, sliders"`), unknown names ignored. */
export function parseControls(list: string | null): Set<EmbedControl> {
  const known: EmbedControl[] = ['iterations', 'sliders'];
  return new Set(known.filter((c) => (list ?? '').split(/[\s,]+/).includes(c)));
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

export class EmbedPlant {
  readonly root: HTMLElement;
  private readonly view: PlantView;
  private readonly message: HTMLElement;
  private readonly open: HTMLAnchorElement;
  private readonly count: HTMLElement;
  private readonly playback: Playback;
  private readonly sliders: SliderPanel | undefined;
  private source: string;
  private iterations: number | undefined;
  private grammarIterations = 0;
  /** Bumped by every request, so a late answer is dropped. */
  private ticket = 0;

  constructor(
    parent: HTMLElement | ShadowRoot,
    private readonly settings: EmbedSettings,
  ) {
    this.source = settings.source;
    this.iterations = settings.iterations;
    this.root = element('div', 'mp');
    const stage = element('div', 'mp-view');
    this.message = element('p', 'mp-message');
    this.message.setAttribute('role', 'status');
    stage.append(this.message);
    const bar = element('div', 'mp-bar');
    this.count = element('span', 'mp-count');
    this.open = element('a', 'mp-open', 'Open in Meristem ↗');
    this.open.target = '_blank';
    this.open.rel = 'noopener';
    this.playback = new Playback({
      shown: () => this.iterations ?? this.grammarIterations,
      grammarIterations: () => this.grammarIterations,
      show: (n) => {
        this.iterations = n;
        this.rebuild();
      },
    });
    if (settings.controls.has('iterations')) bar.append(...this.iterationControls());
    bar.append(this.open);
    this.root.append(stage, bar);
    if (settings.controls.has('sliders')) {
      const list = element('div', 'mp-sliders');
      this.root.append(list);
      this.sliders = new SliderPanel(list, element('span', 'mp-hidden'), element('span', 'mp-hidden'), {
        replaceRange: (from, to, insert) => {
          this.source = this.source.slice(0, from) + insert + this.source.slice(to);
          this.sliders?.update(this.source);
          this.rebuild();
        },
      });
      this.sliders.update(this.source);
    }
    parent.append(this.root);
    this.view = new PlantView(stage, { assetBase: settings.siteRoot });
    this.rebuild();
  }

  /** − n + and Play. */
  private iterationControls(): HTMLElement[] {
    const less = element('button', 'mp-button', '−');
    less.type = 'button';
    less.setAttribute('aria-label', 'One iteration fewer');
    less.addEventListener('click', () => this.playback.stepBy(-1));
    const more = element('button', 'mp-button', '+');
    more.type = 'button';
    more.setAttribute('aria-label', 'One iteration more');
    more.addEventListener('click', () => this.playback.stepBy(+1));
    const play = element('button', 'mp-button mp-play', 'Play');
    play.type = 'button';
    play.setAttribute('aria-pressed', 'false');
    play.addEventListener('click', () => this.playback.toggle());
    this.playback.onPlayingChange((playing) => {
      play.textContent = playing ? 'Pause' : 'Play';
      play.setAttribute('aria-pressed', String(playing));
    });
    return [less, this.count, more, play];
  }

  /** Shows another grammar (the element's `src` or text changed). */
  setSource(source: string, iterations: number | undefined): void {
    this.source = source;
    this.iterations = iterations;
    this.playback.pause();
    this.sliders?.reset();
    this.sliders?.update(source);
    this.view.frameNextPlant();
    this.rebuild();
  }

  /** Stops its builds and releases the view. */
  dispose(): void {
    this.ticket++;
    this.playback.pause();
    this.settings.builds.forget(this);
    this.view.dispose();
    this.root.remove();
  }

  private options(): BuildOptions {
    return { iterations: this.iterations, seed: this.settings.seed };
  }

  private rebuild(): void {
    const ticket = ++this.ticket;
    const options = this.options();
    void this.settings.builds.build(this, this.source, options).then((outcome) => {
      if (ticket === this.ticket) void this.show(outcome, options);
      else if (outcome.kind === 'built') outcome.result.inspector.free();
    });
  }

  private async show(outcome: BuildOutcome, options: BuildOptions): Promise<void> {
    if (outcome.kind === 'superseded' || outcome.kind === 'stopped') return;
    if (outcome.kind === 'crashed') {
      this.say('The plant could not be built (a bug of Meristem).');
      return;
    }
    const { build, inspector } = outcome.result;
    inspector.free();
    this.grammarIterations = build.grammarIterations;
    if (build.ok) {
      this.view.showPlant(build.mesh, build.flat, outcome.result.gpu, build.stats.bounds);
      this.say('');
    } else {
      const first = build.diagnostics.find((d) => d.severity === 'error');
      this.say(first ? `Line ${first.line}: ${first.message}` : 'The grammar has errors.');
    }
    this.count.textContent = `n = ${options.iterations ?? build.grammarIterations}`;
    this.root.dataset.state = build.ok ? 'ok' : 'error';
    this.root.dataset.iterations = String(build.stats.iterations);
    this.playback.shownBuild();
    const { seed } = this.settings;
    const fragment = await encodeState({ text: this.source, ...(this.iterations === undefined ? {} : { iterations: this.iterations }), ...(seed === undefined ? {} : { seed }) });
    this.open.href = new URL(`./${fragment}`, this.settings.siteRoot).href;
  }

  private say(text: string): void {
    this.message.textContent = text;
    this.message.hidden = text === '';
  }
}
