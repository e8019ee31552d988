// A plant embedded in another page: the 3D view of a grammar (drag or the arrow keys to orbit),
// its growth played in time (`animate`: at once, looped or not; Play: on demand), optional
// iteration buttons with Play and `#define` sliders, and a link that opens the grammar in the
// studio. Used by the view-only page (embed.html) and the <meristem-plant> element; the builds
// go to the page's one shared worker. Small enough for 320 × 240.
import type { BuildOptions, BuildProgress } from '../core';
import { cleanGrowth, decodeState, encodeState, type SharedGrowth } from '../share';
import { derivedBuildOptions, derivedTime, LazySliderPanel, Playback } from '../plant-controls';
import { GrowthShow, Timeline } from '../plant-controls/timeline';
import type { BuildOutcome } from '../build';
import { PlantView, sharedTarget } from '../view';
import type { RenderTarget } from '../view';
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
  /**
   * The growth in time: its time, speed, range and loop, and `playing` (the `animate` attribute):
   * play at once (unless the reader asked for reduced motion). Absent: the plant is shown whole
   * until Play.
   */
  growth?: SharedGrowth;
  /** The site's root: the studio (index.html) and its textures are there. */
  siteRoot: string;
  builds: SharedBuilds;
  /** What is wrong with the element's attributes (each ignored), shown above the plant. */
  notes?: readonly string[];
}

/** How long a build runs before the plant says it is growing (ms): a quick one shows no message. */
export const GROWING_AFTER_MS = 300;

/**
 * What a plant asked for says until it is shown: "Growing…", with the derivation step when it is
 * known; before its build has begun (the page's plants build one at a time, the core may still be
 * loading), that it waits.
 */
export function growingMessage(progress: BuildProgress | undefined): string {
  if (!progress) return 'Waiting to grow…';
  if (progress.stage === 'deriving' && progress.steps > 0) return `Growing… step ${progress.step} of ${progress.steps}`;
  return 'Growing…';
}

/** The controls given as a list (`"iterations, sliders"`), unknown names ignored. */
export function parseControls(list: string | null): Set<EmbedControl> {
  const known: EmbedControl[] = ['iterations', 'sliders'];
  return new Set(known.filter((c) => (list ?? '').split(/[\s,]+/).includes(c)));
}

/** The attributes of the growth in time. */
export const GROWTH_ATTRIBUTES = ['animate', 'loop', 'speed', 't', 'from', 'to'];

/** The growth the attributes ask for (checked and clamped: they may hold anything), or undefined. */
export function growthAttributes(element: Pick<Element, 'getAttribute' | 'hasAttribute'>): SharedGrowth | undefined {
  if (!GROWTH_ATTRIBUTES.some((name) => element.hasAttribute(name))) return undefined;
  const read = (name: string) => element.getAttribute(name) ?? undefined;
  return cleanGrowth({ playing: element.hasAttribute('animate'), loop: element.hasAttribute('loop'), speed: read('speed'), t: read('t'), from: read('from'), to: read('to') });
}

/** The largest value of each whole-number attribute: the core's limits for its options. */
export const ATTRIBUTE_MAX = { iterations: 2 ** 32 - 1, seed: Number.MAX_SAFE_INTEGER } as const;

/**
 * A whole-number attribute (`iterations`, `seed`): its value, or undefined when absent or not a
 * whole number from 0 to its largest (issue 50, finding 9c: the core refused `iterations="4294967296"`
 * and the plant said "a bug of Meristem"), with what is wrong with it then, to show in the element.
 */
export function wholeAttribute(name: keyof typeof ATTRIBUTE_MAX, value: string | null): { value?: number; problem?: string } {
  if (value === null) return {};
  const n = value.trim() === '' ? NaN : Number(value);
  if (Number.isInteger(n) && n >= 0 && n <= ATTRIBUTE_MAX[name]) return { value: n };
  const shown = value.length > 40 ? `${value.slice(0, 40)}…` : value;
  return { problem: `${name}="${shown}" is not a whole number from 0 to ${ATTRIBUTE_MAX[name]}: the grammar’s own value is used.` };
}

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

/** Said when the browser took the page's 3D drawing back, or gave it none. */
export const VIEW_LOST = 'This plant’s 3D view was taken back by the browser (too many 3D views on this page). Scroll it out of sight and back to draw it again.';

export class EmbedPlant {
  readonly root: HTMLElement;
  /**
   * The 3D view, while the plant is on screen or near it: made when the plant scrolls into sight,
   * released when it scrolls out. It draws into a 2D canvas with the page's one WebGL renderer
   * (issue 50, finding 9b: a WebGL context per plant, and Chromium keeps 16 a page, dropping the
   * oldest: ../view/shared-renderer.ts).
   */
  private view: PlantView | undefined;
  /** Ends the view's listener on the shared renderer's canvas. */
  private viewListening: AbortController | undefined;
  private readonly stage: HTMLElement;
  /** What the view is asked to show, kept to show again in a view made again. */
  private lastPlant: Parameters<PlantView['showPlant']> | undefined;
  private growthTime: number | null = null;
  private readonly visibility: IntersectionObserver | undefined;
  /** Why the plant is not drawn (its view lost or refused), or ''. */
  private viewProblem = '';
  private readonly message: HTMLElement;
  private readonly open: HTMLAnchorElement;
  private readonly count: HTMLElement;
  private readonly playback: Playback;
  /** The growth played in time (the view's growth time: no build a frame; a timed grammar's build at t). */
  private readonly timeline: Timeline;
  /** The plant at t, as the studio's timeline shows it: a timed grammar derived at t, any other grown on the GPU. */
  private readonly growth: GrowthShow;
  /** Builds carry growth arrays: asked by `growth`, or by the first Play (not for a timed grammar: it is derived at t). */
  private growthWanted: boolean;
  /** The plant on screen is of a timed grammar (ABOP 6.1) or a stepwise one: derived at t, not grown on the GPU. */
  private timed = false;
  /** The plant on screen is of a stepwise grammar (a `#dt` without timed modules): derived to ⌊t⌋. */
  private stepwise = false;
  /** The growth time a timed (or stepwise) grammar's builds are derived at, or null for its iterations. */
  private timedAt: number | null = null;
  /** Builds asked for and not yet answered. */
  private underWay = 0;
  /** Bumped by every writing of the studio link, so a late one is dropped. */
  private linkTicket = 0;
  private readonly sliders: LazySliderPanel | undefined;
  private source: string;
  private iterations: number | undefined;
  private grammarIterations = 0;
  /** Bumped by every request, so a late answer is dropped. */
  private ticket = 0;
  /** Shows "Growing…" when the build under way takes long. */
  private growingTimer: ReturnType<typeof setTimeout> | undefined;
  /** The grammar as a file, when the link cannot hold it ({@link writeLink}). */
  private savedUrl: string | undefined;

  constructor(
    parent: HTMLElement | ShadowRoot,
    private readonly settings: EmbedSettings,
  ) {
    this.source = settings.source;
    this.iterations = settings.iterations;
    this.root = element('div', 'mp');
    const stage = element('div', 'mp-view');
    this.stage = stage;
    this.message = element('p', 'mp-message');
    this.message.setAttribute('role', 'status');
    stage.append(this.message);
    if (settings.notes && settings.notes.length > 0) {
      const note = element('p', 'mp-note', settings.notes.join(' '));
      note.setAttribute('role', 'note');
      stage.append(note);
    }
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
    this.growthWanted = settings.growth !== undefined;
    this.growth = new GrowthShow(
      {
        growthSpan: () => this.view?.growthSpan() ?? null,
        setGrowthTime: (t) => {
          this.growthTime = t;
          this.view?.setGrowthTime(t);
        },
      },
      {
        timedSpan: () => (this.timed ? (this.iterations ?? this.grammarIterations) : null),
        deriveAt: (t) => {
          const at = derivedTime(t, this.stepwise);
          if (at === this.timedAt) return;
          this.timedAt = at;
          this.rebuild();
        },
        busy: () => this.underWay > 0,
      },
    );
    this.timeline = new Timeline(
      { span: () => this.growth.span(), show: (t) => this.showGrowth(t) },
      { speed: settings.growth?.speed, loop: settings.growth?.loop },
    );
    if (settings.controls.has('iterations')) bar.append(...this.iterationControls());
    bar.append(this.open);
    this.root.append(stage, bar);
    if (settings.controls.has('sliders')) {
      const list = element('div', 'mp-sliders');
      this.root.append(list);
      this.sliders = new LazySliderPanel([
        list,
        element('span', 'mp-hidden'),
        element('span', 'mp-hidden'),
        {
          replaceRange: (from, to, insert) => {
            this.source = this.source.slice(0, from) + insert + this.source.slice(to);
            this.sliders?.update(this.source);
            this.rebuild();
          },
        },
      ]);
      this.sliders.update(this.source);
      this.sliders.load().catch((error: unknown) => console.error('The sliders could not load:', error));
    }
    parent.append(this.root);
    if (typeof IntersectionObserver === 'function') {
      this.visibility = new IntersectionObserver((entries) => (entries.at(-1)?.isIntersecting ? this.makeView() : this.releaseView()), { rootMargin: '200px' });
      this.visibility.observe(this.root);
    } else {
      this.makeView();
    }
    let wasPlaying = false;
    this.timeline.onChange(({ playing }) => {
      if (wasPlaying && !playing) void this.writeLink(); // paused: the link opens at this t
      wasPlaying = playing;
    });
    this.startGrowth(settings.growth);
    this.rebuild();
  }

  /** Makes the 3D view (the plant came into sight) and shows the plant in it; says so if the browser gives none. */
  private makeView(): void {
    if (this.view) return;
    let view: PlantView;
    let target: RenderTarget;
    try {
      target = sharedTarget();
      view = new PlantView(this.stage, { assetBase: this.settings.siteRoot, target: () => target });
    } catch (error) {
      console.warn('Meristem: no 3D view for a plant:', error);
      this.viewProblem = VIEW_LOST;
      this.say(VIEW_LOST);
      return;
    }
    this.view = view;
    view.onPlantShown(() => this.timeline.refresh());
    // Lost while on screen (the page made too many other WebGL views): said, and made again (with
    // a new shared renderer) when it comes back into sight.
    this.viewListening = new AbortController();
    const lost = () => {
      if (this.view !== view) return;
      this.releaseView();
      this.viewProblem = VIEW_LOST;
      this.say(VIEW_LOST);
    };
    target.contextCanvas.addEventListener('webglcontextlost', lost, { signal: this.viewListening.signal });
    if (this.viewProblem !== '') {
      this.viewProblem = '';
      if (this.message.textContent === VIEW_LOST) this.say('');
    }
    if (this.lastPlant) {
      view.showPlant(...this.lastPlant);
      if (this.growthTime !== null) view.setGrowthTime(this.growthTime);
    }
  }

  /** Releases the 3D view and its WebGL context (the plant went out of sight, or away). */
  private releaseView(): void {
    const view = this.view;
    if (!view) return;
    this.view = undefined;
    this.viewListening?.abort();
    view.dispose();
  }

  /** The growth as the settings ask: its range, its time, and playing if animated. */
  private startGrowth(growth: SharedGrowth | undefined): void {
    if (!growth) return;
    this.timeline.setRange(growth.from ?? 0, growth.to ?? null);
    if (growth.t !== undefined) this.timeline.seek(growth.t);
    const still = globalThis.matchMedia?.('(prefers-reduced-motion: reduce)').matches ?? false;
    if (growth.playing && !still) this.timeline.play();
  }

  /** Shows growth time `t` (the whole plant at its end; a timed grammar derived at t). */
  private showGrowth(t: number): void {
    this.growth.show(t);
    this.root.dataset.t = String(t);
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
    play.title = 'Play the growth';
    play.addEventListener('click', () => {
      if (!this.growthWanted) {
        this.growthWanted = true;
        this.rebuild(); // with growth arrays: Play waits for them, playing
      }
      this.timeline.toggle();
    });
    this.timeline.onChange(({ playing }) => {
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
    this.timeline.pause();
    this.timedAt = null; // derived at its own iterations until the timeline shows a time again
    this.sliders?.reset();
    this.sliders?.update(source);
    this.view?.frameNextPlant();
    this.rebuild();
  }

  /** Stops its builds and releases the view. */
  dispose(): void {
    this.ticket++;
    this.playback.pause();
    this.timeline.dispose();
    this.settings.builds.forget(this);
    clearTimeout(this.growingTimer);
    if (this.savedUrl) URL.revokeObjectURL(this.savedUrl);
    this.visibility?.disconnect();
    this.releaseView();
    this.lastPlant = undefined;
    this.root.remove();
  }

  private options(): BuildOptions {
    return {
      iterations: this.iterations,
      seed: this.settings.seed,
      ...derivedBuildOptions(this.timedAt, this.stepwise, this.growthWanted && !this.timed),
    };
  }

  private rebuild(): void {
    const ticket = ++this.ticket;
    const options = this.options();
    this.underWay++;
    let progress: BuildProgress | undefined;
    clearTimeout(this.growingTimer);
    this.growingTimer = setTimeout(() => {
      this.growingTimer = undefined;
      if (ticket === this.ticket) this.say(growingMessage(progress), true);
    }, GROWING_AFTER_MS);
    const onProgress = (now: BuildProgress) => {
      progress = now;
      if (ticket === this.ticket && this.growingTimer === undefined) this.say(growingMessage(progress), true);
    };
    void this.settings.builds.build(this, this.source, options, onProgress).then((outcome) => {
      this.underWay--;
      if (ticket === this.ticket) {
        clearTimeout(this.growingTimer);
        this.growingTimer = undefined;
        void this.show(outcome, options);
      }
      else if (outcome.kind === 'built') outcome.result.inspector.free();
      this.growth.delivered(); // a time wanted meanwhile is derived now
    });
  }

  private async show(outcome: BuildOutcome, options: BuildOptions): Promise<void> {
    if (outcome.kind === 'superseded' || outcome.kind === 'stopped') return;
    if (outcome.kind === 'crashed') {
      // The core refuses options it cannot use (`bad options: …`): not a bug, and it says why.
      const refused = /bad options: (.*)$/.exec(outcome.message);
      this.say(refused ? `The plant could not be built: its ${refused[1]}.` : 'The plant could not be built (a bug of Meristem).');
      return;
    }
    const { build, inspector } = outcome.result;
    inspector.free();
    this.grammarIterations = build.grammarIterations;
    if (build.ok) {
      this.timed = build.timed || build.stepwise;
      this.stepwise = build.stepwise;
      this.lastPlant = [build.mesh, build.flat, outcome.result.gpu, build.stats.bounds];
      this.view?.showPlant(...this.lastPlant);
      this.say(this.viewProblem);
    } else {
      const first = build.diagnostics.first('error');
      this.say(first ? `Line ${first.line}: ${first.message}` : 'The grammar has errors.');
    }
    this.count.textContent = `n = ${options.iterations ?? build.grammarIterations}`;
    this.root.dataset.state = build.ok ? 'ok' : 'error';
    this.root.dataset.iterations = String(build.stats.iterations);
    // What the plant on screen is (for tests, and for a page that reads it): its modules and size.
    this.root.dataset.modules = String(build.stats.modules);
    this.root.dataset.bounds = build.stats.bounds.flat().join(' ');
    this.playback.shownBuild();
    await this.writeLink();
  }

  /**
   * "Open in Meristem": the grammar, its iterations and seed, and once the growth is in use its
   * timeline (the time shown, speed, range, loop), so the studio opens on the same plant at the
   * same t (a timed grammar derived at t there too). Written after each build and at each pause.
   */
  private async writeLink(): Promise<void> {
    const ticket = ++this.linkTicket;
    const { seed } = this.settings;
    const given = this.settings.growth;
    const { t, speed, loop, from } = this.timeline.state;
    const growth = this.growthWanted || given ? cleanGrowth({ t, ...(speed === 1 ? {} : { speed }), ...(loop ? { loop } : {}), ...(from > 0 ? { from } : {}), to: given?.to }) : undefined;
    const fragment = await encodeState({
      text: this.source,
      ...(this.iterations === undefined ? {} : { iterations: this.iterations }),
      ...(seed === undefined ? {} : { seed }),
      ...(growth ? { growth } : {}),
    });
    // The studio opens the link with this very decoder: a link it would refuse (a grammar too
    // long for a link: issue 50, finding 9d) is never offered; the grammar is, as a file.
    const opened = await decodeState(fragment);
    if (ticket !== this.linkTicket) return;
    if (opened.ok) this.offerLink(new URL(`./${fragment}`, this.settings.siteRoot).href);
    else this.offerFile(opened.error);
  }

  /** "Open in Meristem ↗": the studio, on this plant. */
  private offerLink(href: string): void {
    if (this.savedUrl) URL.revokeObjectURL(this.savedUrl);
    this.savedUrl = undefined;
    this.open.textContent = 'Open in Meristem ↗';
    this.open.removeAttribute('download');
    this.open.removeAttribute('title');
    this.open.target = '_blank';
    this.open.href = href;
  }

  /** No link can open this plant in the studio (`why`): the grammar as a file to open there instead. */
  private offerFile(why: string): void {
    if (this.savedUrl) URL.revokeObjectURL(this.savedUrl);
    this.savedUrl = URL.createObjectURL(new Blob([this.source], { type: 'text/plain' }));
    this.open.textContent = 'Save the grammar ↓';
    this.open.title = `Too long to open in Meristem by a link: ${why}. Save the grammar, then open the file in Meristem (File ▸ Open).`;
    this.open.download = 'plant.lsys';
    this.open.removeAttribute('target');
    this.open.href = this.savedUrl;
  }

  /** Shows `text` over the plant (nothing when empty); `busy`: a note that it is being built, not an error. */
  private say(text: string, busy = false): void {
    this.message.textContent = text;
    this.message.hidden = text === '';
    this.message.classList.toggle('mp-busy', busy);
  }
}
