// The live preview: every change of the text or of a build option sends a build to the worker;
// only the newest one is shown. A grammar with errors keeps the last good plant on screen, marked
// stale. A build that takes a while says so ("Building… step k of n") with a Stop button. The
// editor's linter gets its diagnostics from the same builds (DiagnosticsFeed).
import { NO_DIAGNOSTICS, type BuildOptions, type BuildProgress, type DiagnosticList, type PlantSketch } from '../../core';
import type { PlantView } from '../../view';
import { DiagnosticsFeed } from './diagnostics-feed';
import { reportBuilding, reportErrors, reportPlant, type StatusReport } from './status';
import type { BuildClient, BuildOutcome, BuildResult } from '../../build';

/** A build not delivered after this long (ms) is shown as under way, with its Stop button. */
export const BUILDING_AFTER = 300;

/** At most this long (ms), a build waits for the frame of its sketch (see `LivePreview.sketchFrame`). */
const SKETCH_FRAME_WAIT = 250;

/** What the preview reads and writes on the page. */
export interface LivePreviewParts {
  client: BuildClient;
  view: PlantView;
  /** The status line: its text, `data-state` and `data-generation` (a counter of delivered builds). */
  status: HTMLElement;
  /** Stops the build under way (shown while one takes longer than {@link BUILDING_AFTER}). */
  stop?: HTMLButtonElement;
  /**
   * Lists the text's errors and warnings in full (the status line has room for one, cut to its
   * width: on a phone, a few words): shown while the last build delivered has any.
   */
  problems?: HTMLButtonElement;
  staleBadge: HTMLElement;
  /**
   * The String and Derivation panels' mark, shown with the view's stale badge: the panels go on
   * showing the plant on screen, which is then of an earlier text.
   */
  inspectorStale?: HTMLElement;
  /**
   * Called after a build was stopped or crashed (its worker replaced): the panels ask the plant on
   * screen again (its build is kept anew by the next worker), so nothing they lost stays empty.
   */
  workerReplaced?: () => void;
  /** The diagnostics of delivered builds, for the editor's linter (made by the preview if not given). */
  feed?: DiagnosticsFeed;
  /** The grammar text now (read when a rebuild is not given the text). */
  text: () => string;
  /** The build options now (iterations, seed, view options). */
  options: () => BuildOptions;
  /**
   * The diagnostics the text is to answer for (its linter's, the status line's): without those
   * the options caused, which say so where they are set (the Iterations box's limits).
   */
  blamed?: (diagnostics: DiagnosticList) => DiagnosticList;
  /** Called when a build's diagnostics may differ from what the linter showed for the same text. */
  diagnosticsChanged: () => void;
  /**
   * Takes over a build without errors that is now on screen, its `inspector` included (and frees
   * the one it held before). Without it the preview frees each inspector itself.
   */
  adopt?: (result: BuildResult) => void;
  /** Told the core's message when it crashed on a build (the next build runs on a fresh worker). */
  crashed?: (message: string) => void;
}

/** A status line state beyond a build's own. */
type PageStatus = StatusReport | { state: 'loading' | 'crashed' | 'building' | 'stopped'; text: string };

/** Shows a report in the status line: its text, and its state as `data-state` (for CSS and tests). */
export function showStatus(status: HTMLElement, report: PageStatus): void {
  status.textContent = report.text;
  status.title = report.text; // the line is cut to one line on screen
  status.dataset.state = report.state;
}

/** Keeps the view in step with the text and options. */
export class LivePreview {
  /** The diagnostics of delivered builds, for the editor's linter. */
  readonly feed: DiagnosticsFeed;
  /** The last build delivered (with or without errors). */
  lastResult: BuildResult | undefined;
  /** The last build without errors: the plant on screen. */
  lastGood: BuildResult | undefined;
  /** Delivered builds so far (also `data-generation` on the status line). */
  generation = 0;
  private requestedKey: string | undefined;
  private deliveredKey: string | undefined;
  private readonly listeners = new Set<(result: BuildResult) => void>();
  private readonly sketchListeners = new Set<(sketch: PlantSketch) => void>();
  private readonly progressWaiters: (() => void)[] = [];
  /** Who waits for no build to be under way ({@link answered}). */
  private readonly answerWaiters: (() => void)[] = [];
  /** When the oldest request not yet delivered was made (undefined: none waits). */
  private pendingSince: number | undefined;
  /** The newest request's progress, as its worker tells it. */
  private progress: BuildProgress | undefined;
  /** Shows the build as under way, {@link BUILDING_AFTER} after it was asked for, then every second. */
  private buildingTimer: ReturnType<typeof setTimeout> | undefined;
  /** True while the status line says "Building…". */
  private building = false;
  /**
   * Settles once the sketch shown last has had a frame of its own; undefined when it has. A build
   * that arrives before that frame (the Lines mode's can, a few milliseconds after its sketch)
   * waits for it: applied at once, it took the frame, and nothing new showed until the build was
   * drawn (`npm run bench:studio`, the Lines mode: the first frame 61-70 ms after the keystroke,
   * 33-38 with the wait).
   */
  private sketchFrame: Promise<void> | undefined;

  constructor(private readonly parts: LivePreviewParts) {
    this.feed = parts.feed ?? new DiagnosticsFeed();
    parts.stop?.addEventListener('click', () => this.stop());
  }

  /**
   * Stops the build under way (its worker is terminated; the text stays as it is): the plant on
   * screen, if any, is marked as being of an earlier text, and the next change builds again.
   */
  stop(): void {
    this.parts.client.stop();
  }

  /** Calls `listener` after every delivered build has been applied to the page. */
  onDelivered(listener: (result: BuildResult) => void): () => void {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  }

  /** Settles after the next build is delivered (applied to the page). */
  nextDelivery(): Promise<void> {
    return new Promise((resolve) => {
      const stop = this.onDelivered(() => {
        stop();
        resolve();
      });
    });
  }

  /** Settles at the next progress report of a build: the worker is at work (its core has loaded). */
  nextProgress(): Promise<void> {
    return new Promise((resolve) => this.progressWaiters.push(resolve));
  }

  /**
   * Builds `text` (the change's; by default the text now) with the current options, unless that
   * is what was asked last (or `force`: e.g. an example opened again must be framed again).
   */
  rebuild({ text, force = false }: { text?: string; force?: boolean } = {}): void {
    const source = text ?? this.parts.text();
    const options = this.parts.options();
    const key = JSON.stringify(options) + '\n' + source;
    if (key === this.requestedKey && !force) return;
    this.requestedKey = key;
    this.progress = undefined;
    if (this.pendingSince === undefined) {
      this.pendingSince = performance.now();
      this.buildingTimer = setTimeout(() => this.showBuilding(), BUILDING_AFTER);
    } else if (this.building) this.showBuilding();
    void this.parts.client
      .request(source, options, {
        onSketch: (sketch) => this.sketch(sketch, key),
        onProgress: (progress) => {
          for (const resolve of this.progressWaiters.splice(0)) resolve();
          if (key !== this.requestedKey) return;
          this.progress = progress;
          if (this.building) this.showBuilding();
        },
      })
      .then(async (outcome) => {
        // A build that arrives before its sketch had a frame waits for that frame ({@link
        // sketchFrame}); if the text changed meanwhile, it is not shown (as if superseded).
        if (this.sketchFrame && outcome.kind === 'built') {
          await this.sketchFrame;
          if (key !== this.requestedKey) return void outcome.result.inspector.free();
        }
        this.deliver(outcome, key);
      });
  }

  /** Says the build is under way (stage or step, time so far) and offers Stop; again each second. */
  private showBuilding(): void {
    if (this.pendingSince === undefined) return;
    clearTimeout(this.buildingTimer);
    const elapsed = performance.now() - this.pendingSince;
    showStatus(this.parts.status, reportBuilding(this.progress, elapsed));
    if (this.parts.stop) this.parts.stop.hidden = false;
    this.building = true;
    this.buildingTimer = setTimeout(() => this.showBuilding(), 1000 - (elapsed % 1000));
  }

  /** The newest request was delivered (or stopped, or crashed): nothing is under way any more. */
  private doneBuilding(): void {
    clearTimeout(this.buildingTimer);
    this.buildingTimer = undefined;
    this.pendingSince = undefined;
    this.building = false;
    if (this.parts.stop) this.parts.stop.hidden = true;
  }

  /** Marks the plant on screen (if any) as not of the text now, saying `why` on the view. */
  private markStale(stale: boolean, why: string): void {
    this.parts.view.setStale(stale);
    this.parts.staleBadge.textContent = `Stale — ${why}`;
    this.parts.staleBadge.hidden = !stale;
    const mark = this.parts.inspectorStale;
    if (mark) {
      mark.hidden = !stale;
      mark.title = `The string and the derivation are of the plant shown: stale — ${why}`;
    }
  }

  /** Calls `listener` after each sketch (a big plant as lines, its tubes to follow) is on screen. */
  onSketched(listener: (sketch: PlantSketch) => void): () => void {
    this.sketchListeners.add(listener);
    return () => this.sketchListeners.delete(listener);
  }

  /**
   * A big plant's skeleton, while its tubes are meshed in the worker: drawn as lines at once, so an
   * edit shows within a frame; the build replaces it (or, if it has errors, the last good plant
   * comes back). Not a delivery: the generation counter and `settled` wait for the build.
   */
  private sketch(sketch: PlantSketch, key: string): void {
    if (key !== this.requestedKey) return;
    this.parts.view.showSketch(sketch.lines, sketch.lineColors, sketch.flat);
    const frame: Promise<void> = new Promise((resolve) => {
      const done = () => {
        clearTimeout(timer);
        stop();
        if (this.sketchFrame === frame) this.sketchFrame = undefined;
        resolve();
      };
      // A task after the frame's own (what that task does goes into the frame), or at the latest
      // after SKETCH_FRAME_WAIT: a hidden page draws no frames, and its builds go on arriving.
      const stop = this.parts.view.onRender(() => setTimeout(done, 0));
      const timer = setTimeout(done, SKETCH_FRAME_WAIT);
    });
    this.sketchFrame = frame;
    this.markStale(false, '');
    // The status line keeps the last report until the build: a second text change per keystroke
    // costs a compositor pass that, without a GPU, delays the tubes' frame by a second.
    for (const listener of this.sketchListeners) listener(sketch);
  }

  /**
   * Settles once no build asked for is under way: at once when none is, else after a delivery
   * (or a stop, or a crash) that leaves none (a build its listeners asked for is waited for too).
   * Then {@link settled} and {@link lastResult} say what is on screen.
   */
  answered(): Promise<void> {
    return this.busy ? new Promise((resolve) => this.answerWaiters.push(resolve)) : Promise.resolve();
  }

  /** Tells those waiting for no build under way, if none is. */
  private tellAnswered(): void {
    if (!this.busy) for (const resolve of this.answerWaiters.splice(0)) resolve();
  }

  /** A build asked for is under way (not yet delivered, stopped or crashed). */
  get busy(): boolean {
    return this.pendingSince !== undefined;
  }

  /** The last build asked for has been delivered: what is on screen is of the text and options now. */
  get settled(): boolean {
    return this.requestedKey !== undefined && this.deliveredKey === this.requestedKey;
  }

  private deliver(outcome: BuildOutcome, key: string): void {
    if (outcome.kind === 'superseded') return;
    this.doneBuilding();
    const { view, status } = this.parts;
    if (outcome.kind === 'crashed' || outcome.kind === 'stopped') {
      if (outcome.kind === 'crashed') {
        console.error('Meristem core crashed:', outcome.message);
        this.parts.crashed?.(outcome.message);
      }
      this.requestedKey = undefined; // the same text may be tried again, on a fresh worker
      this.feed.delivered(this.parts.text(), NO_DIAGNOSTICS);
      const shown = this.lastGood !== undefined;
      if (outcome.kind === 'crashed') {
        showStatus(status, { state: 'crashed', text: 'The core crashed on this grammar (a bug); edit to try again' });
        this.markStale(shown, 'the core crashed on this text');
      } else {
        const plant = shown ? 'the plant shown is of an earlier text' : 'no plant yet';
        showStatus(status, { state: 'stopped', text: `Build stopped — ${plant}; change the text or an option to build again` });
        this.markStale(shown, 'the build was stopped');
      }
      if (shown) this.parts.workerReplaced?.();
      if (this.parts.problems) this.parts.problems.hidden = true;
      status.dataset.generation = String(++this.generation);
      this.tellAnswered();
      return;
    }
    const { result } = outcome;
    const { build } = result;
    const sameText = this.lastResult?.source === result.source;
    const blamed = this.parts.blamed?.(build.diagnostics) ?? build.diagnostics;
    const own = blamed.count('error') > 0;
    if (build.ok) {
      view.showPlant(build.mesh, build.flat, result.gpu, build.stats.bounds);
      this.lastGood = result;
      if (this.parts.adopt) this.parts.adopt(result);
      else result.inspector.free();
      showStatus(status, reportPlant(build.stats, build.diagnostics, build.timings, result.roundTripMillis));
    } else {
      result.inspector.free(); // not shown: the plant on screen stays the last good one
      showStatus(status, own ? reportErrors(blamed, this.lastGood !== undefined) : { state: 'stale', text: 'Too many iterations in the Iterations box — showing last good plant' });
    }
    this.markStale(!build.ok && this.lastGood !== undefined, own ? 'the grammar has errors' : 'too many iterations');
    if (this.parts.problems) this.parts.problems.hidden = blamed.length === 0;
    this.lastResult = result;
    this.feed.delivered(result.source, blamed);
    if (sameText) this.parts.diagnosticsChanged();
    this.deliveredKey = key;
    status.dataset.generation = String(++this.generation);
    for (const listener of this.listeners) listener(result);
    this.tellAnswered();
  }
}
