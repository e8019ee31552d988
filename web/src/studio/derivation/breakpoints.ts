// The debugger's breakpoints (issue 48), as L-Py's debugger has them: on a production (Play pauses
// at the first step where it fires, and says how many times it fired) and a watch, a pattern with
// a condition (`A(x) : x > 3`) that pauses Play at the first step where it holds for a module. The
// core finds the step (pipeline/breakpoints.rs, in the build worker); the timeline bar pauses there.
import type { BreakpointAnswer, PlantBuild, PlantInspector } from '../../core';
import './breakpoints.css';

/** What the panel asks of the view around it. */
export interface BreakpointHost {
  /** `rule 2 (line 8: F -> FF)`. */
  describeProduction(index: number): string;
}

/** Where Play pauses, and what it says there. */
interface Stop {
  step: number;
  words: string;
}

/**
 * Where the toolbar's Play pauses: the timeline bar (loaded after the first plant, as this panel
 * is) imports it when it loads; the panel on the page sets it.
 */
export const playStop = {
  panel: null as BreakpointPanel | null,
  /** The growth time Play pauses at (a whole step), or null. */
  at(): number | null {
    return this.panel?.at() ?? null;
  },
  /** Play paused at {@link at}: the panel says why. */
  paused(): void {
    this.panel?.paused();
  },
};

const plural = (n: number, word: string) => `${n} ${word}${n === 1 ? '' : 's'}`;

/** The panel under the String tab's summary, and the step Play pauses at. */
export class BreakpointPanel {
  readonly element = document.createElement('details');
  private readonly rules = document.createElement('div');
  private readonly watch = document.createElement('input');
  private readonly status = document.createElement('p');
  /** The productions with a breakpoint, by index. */
  private readonly on = new Set<number>();
  private build: PlantBuild | undefined;
  private inspector: PlantInspector | undefined;
  private source = '';
  private stop: Stop | null = null;
  private ticket = 0;

  constructor(private readonly host: BreakpointHost) {
    this.element.className = 'breakpoints';
    this.element.dataset.testid = 'breakpoints';
    const summary = document.createElement('summary');
    summary.textContent = 'Breakpoints';
    summary.title = 'Pause Play where a production first fires, or where a condition first holds for a module';
    this.watch.type = 'text';
    this.watch.placeholder = 'A(x) : x > 3';
    this.watch.spellcheck = false;
    this.watch.dataset.testid = 'breakpoint-watch';
    this.watch.setAttribute('aria-label', 'Pause where this holds for a module: a predecessor, its contexts and a condition');
    const watchLabel = document.createElement('label');
    watchLabel.append('Pause when a module matches ', this.watch);
    this.status.className = 'breakpoint-status';
    this.status.dataset.testid = 'breakpoint-status';
    this.status.setAttribute('aria-live', 'polite');
    this.element.append(summary, this.rules, watchLabel, this.status);
    this.watch.addEventListener('change', () => void this.find());
    playStop.panel = this;
  }

  /** A new build on screen: the breakpoints stay (by production), their step is found again. */
  setBuild(build: PlantBuild, inspector: PlantInspector | undefined, source: string): void {
    this.build = build;
    this.inspector = inspector;
    this.source = source;
    for (const p of [...this.on]) if (p >= build.productions.length) this.on.delete(p);
    this.rules.replaceChildren(
      ...build.productions.map((p) => {
        const box = document.createElement('input');
        box.type = 'checkbox';
        box.checked = this.on.has(p.index);
        box.dataset.production = String(p.index);
        box.addEventListener('change', () => {
          if (box.checked) this.on.add(p.index);
          else this.on.delete(p.index);
          void this.find();
        });
        const label = document.createElement('label');
        label.append(box, ` ${this.host.describeProduction(p.index)}`);
        return label;
      }),
    );
    void this.find();
  }

  /** The growth time Play pauses at (a whole step), or null. */
  at(): number | null {
    return this.stop?.step ?? null;
  }

  /** Play paused at {@link at}: says why. */
  paused(): void {
    if (this.stop) this.status.textContent = `Paused at step ${this.stop.step}: ${this.stop.words}.`;
    this.status.dataset.paused = String(this.stop?.step ?? '');
  }

  /** Asks the core where each breakpoint pauses; the first step wins. */
  private async find(): Promise<void> {
    const ticket = ++this.ticket;
    const build = this.build;
    const inspector = this.inspector;
    const watch = this.watch.value.trim();
    this.stop = null;
    delete this.status.dataset.paused;
    if (!build || !inspector || (this.on.size === 0 && watch === '')) {
      this.status.textContent = '';
      return;
    }
    if (build.timed || build.stepwise) {
      this.status.textContent = 'Breakpoints pause a plant that grows from its whole derivation; a timed or stepwise grammar is derived again at each time played, so they are not available for it.';
      return;
    }
    const asked = [...this.on].map((p) => ({ p, answer: inspector.breakpoint(this.source, p, '') }));
    const watched = watch === '' ? null : inspector.breakpoint(this.source, 0, watch);
    const stops: Stop[] = [];
    const problems: string[] = [];
    for (const { p, answer } of asked) this.take(await answer, (count) => `${this.host.describeProduction(p)} fired ${plural(count, 'time')}`, stops, problems);
    if (watched) this.take(await watched, (count) => `${watch} holds for ${plural(count, 'module')}`, stops, problems);
    if (ticket !== this.ticket) return;
    stops.sort((a, b) => a.step - b.step);
    this.stop = stops[0] ?? null;
    const where = this.stop ? `Play pauses at step ${this.stop.step}: ${this.stop.words}.` : `Play does not pause: no breakpoint is reached in the ${plural(build.stats.iterations, 'step')} derived.`;
    this.status.textContent = [where, ...problems].join(' ');
    this.status.dataset.step = String(this.stop?.step ?? '');
  }

  private take(answer: BreakpointAnswer, words: (count: number) => string, stops: Stop[], problems: string[]): void {
    if ('pause' in answer) stops.push({ step: answer.pause.step, words: words(answer.pause.count) });
    else if ('error' in answer && answer.error) problems.push(answer.error);
  }
}
