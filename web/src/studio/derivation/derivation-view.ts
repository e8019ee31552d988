// The derivation view: how the string unfolds, step by step. When the whole derivation is short, it
// shows every step 0 … n as rows (as ABOP's derivation figures do), each module of step k inside a
// band of the colour of the production that wrote it, grouped by the module of step k − 1 it came
// from, and for small derivations the derivation tree. When it is long, it shows the last step: each
// module of step n − 1 beside the substring of step n it became, virtualised. Hovering a module
// says where it came from and which rule wrote it, and lights up in the 3D view the part of the
// plant that grew from it and in the editor the production.
import { lineageShown } from './lineage-list';
import './derivation-view.css';
import { NOT_REWRITTEN, type DerivationStep, type PlantBuild, type PlantInspector } from '../../core';
import { cssColour, PRODUCTION_COLOURS } from '../../view/highlight';
import { shortModuleText, shortNumber } from './module-text';
// Loaded on demand: it imports other areas' files, not their indexes, which would bring their
// wiring into its chunk's graph (and split the first load into more files).
import { plural } from '../preview/status';

/** The whole derivation is shown when its steps hold this many modules or fewer together. */
export const SEQUENCE_MAX_MODULES = 4_000;
/** The derivation tree is drawn when the steps hold this many modules or fewer together. */
export const TREE_MAX_MODULES = 160;
/** Height of a row of the last-step list in pixels (keep in step with `.dv-pair` in derivation-view.css). */
const PAIR_HEIGHT = 24;
const OVERSCAN = 6;

/** What the view needs of the studio around it. */
export interface DerivationViewHost {
  /**
   * Lights up modules of the derived string (the last step) in the 3D view and the string panel,
   * and a production in the editor; `null, null` restores the context view's own highlight.
   */
  preview(modules: Iterable<number> | null, production: number | null): void;
  /** A module of the last step was clicked: the context view explains it. */
  pick(module: number): void;
  /** A production as the user wrote it, with its number and line (`rule 2 (line 8: F -> FF)`). */
  describeProduction(index: number): string;
  /** A production's condition as written (`x>=1`), or null. */
  conditionOf(index: number): string | null;
}

/** A timed derivation's growth time as the view writes it (`2.5`, `0.333333`). */
export function timeWords(time: number): string {
  return `t = ${shortNumber(String(time))}`;
}

/**
 * Step `k` as the view names it: `step 2`, or in a timed derivation (ABOP 6.1, each step a round
 * of replacements at its time) `t = 2`.
 */
export function stepWords(steps: readonly DerivationStep[], k: number): string {
  const time = steps[k].time;
  return time === undefined ? `step ${k}` : timeWords(time);
}

/** Where a module of a step comes from, in words. */
export function originInWords(
  steps: readonly DerivationStep[],
  step: number,
  module: number,
  host: Pick<DerivationViewHost, 'describeProduction' | 'conditionOf'>,
): string {
  const text = shortModuleText(steps[step].texts[module]);
  const at = (k: number) => stepWords(steps, k);
  if (step === 0) return `${text} is part of the axiom (${at(0)}).`;
  const parent = steps[step].parent[module];
  const from = shortModuleText(steps[step - 1].texts[parent]);
  const origin = steps[step].origin[module];
  const time = steps[step].time;
  const timed = time !== undefined;
  const At = timed ? `At ${timeWords(time)}` : `Step ${step}`;
  if (origin === NOT_REWRITTEN) {
    return timed
      ? `${At}: ${text} is ${from} of ${at(step - 1)}, older (not replaced: it had not reached its terminal age, or no production matched it).`
      : `${At}: ${text} is ${from} of ${at(step - 1)}, copied (no production rewrote it).`;
  }
  const siblings = steps[step].parent.filter((p) => p === parent).length;
  const became = siblings > 1 ? `one of the ${siblings} modules ${from} became` : `what ${from} became`;
  const condition = host.conditionOf(origin);
  const when = timed ? `, at its terminal age (${from} is its age at ${at(step - 1)})` : '';
  return `${At}: ${text} is ${became}${when}, by ${host.describeProduction(origin)}${condition === null ? '' : `; ${condition} held`}.`;
}

/** The modules of the last step that descend from module `module` of step `step`. */
export function descendants(steps: readonly DerivationStep[], step: number, module: number): number[] {
  let current = new Set([module]);
  for (let k = step + 1; k < steps.length; k++) {
    const next = new Set<number>();
    steps[k].parent.forEach((p, i) => current.has(p) && next.add(i));
    current = next;
  }
  return [...current];
}

/** For each module of a step, the index of its first child in the next step (and a last entry). */
export function firstChildren(parents: ArrayLike<number>, previousCount: number): Uint32Array {
  const first = new Uint32Array(previousCount + 1);
  let child = 0;
  for (let p = 0; p <= previousCount; p++) {
    while (child < parents.length && parents[child] < p) child++;
    first[p] = child;
  }
  return first;
}

export class DerivationView {
  private readonly caption: HTMLElement;
  private readonly status: HTMLElement;
  private readonly body: HTMLElement;
  private build: PlantBuild | undefined;
  private inspector: PlantInspector | undefined;
  private steps: DerivationStep[] | null = null;
  /** The last step's links when the derivation is too long to show whole. */
  private pairs: { first: Uint32Array; count: number; origins: Uint32Array } | null = null;
  private shown = false;
  private stale = true;
  /** Bumped on every new build, so late answers are dropped. */
  private ticket = 0;
  /** The picked module's lineage (the String tab's), marked in the rows: (step, module) pairs. */
  private lineage: readonly { step: number; module: number }[] = [];

  constructor(
    root: HTMLElement,
    private readonly host: DerivationViewHost,
  ) {
    this.caption = element('p', 'dv-caption');
    this.status = element('p', 'dv-status');
    this.status.setAttribute('aria-live', 'polite');
    this.status.dataset.testid = 'derivation-status';
    this.body = element('div', 'dv-body');
    this.body.tabIndex = 0;
    this.body.setAttribute('role', 'region');
    this.body.setAttribute('aria-label', 'Derivation, step by step');
    this.body.dataset.testid = 'derivation';
    root.append(this.caption, this.body, this.status);
    this.body.addEventListener('pointerover', (event) => this.hover(event.target as HTMLElement));
    // A finger leaves as it lifts: what it tapped stays lit up until the next tap (on a module, or
    // beside the modules to clear it), as a mouse's hover stays while the mouse does.
    this.body.addEventListener('pointerleave', (event) => event.pointerType !== 'touch' && this.hover(null));
    this.body.addEventListener('click', (event) => this.click(event.target as HTMLElement));
    this.body.addEventListener('scroll', () => this.pairs && this.renderPairs());
    lineageShown.listeners.add((rows) => this.showLineage(rows));
    this.showLineage(lineageShown.rows);
  }

  /** Marks the chain of a module's lineage in the rows (null: none). */
  showLineage(rows: readonly { step: number; module: number }[] | null): void {
    this.lineage = rows ?? [];
    this.markLineage();
  }

  private markLineage(): void {
    for (const old of this.body.querySelectorAll('.dv-lineage')) old.classList.remove('dv-lineage');
    for (const { step, module } of this.lineage) this.mark(step, module, 'dv-lineage');
  }

  /** Shows the derivation of a new build (fetched when the view is on screen). */
  setBuild(build: PlantBuild, inspector: PlantInspector | undefined): void {
    this.build = build;
    this.inspector = inspector;
    this.stale = true;
    if (this.shown) void this.load();
  }

  /**
   * Asks the build again (when shown; else when next shown): after its worker was replaced, a
   * derivation lost with that worker comes back.
   */
  reload(): void {
    this.stale = true;
    if (this.shown) void this.load();
  }

  /** The view's tab was shown or hidden: it computes only while shown. */
  setShown(shown: boolean): void {
    this.shown = shown;
    if (shown && this.stale) void this.load();
  }

  private async load(): Promise<void> {
    const ticket = ++this.ticket;
    this.stale = false;
    const build = this.build;
    const inspector = this.inspector;
    if (!build || !inspector) return;
    const steps = await inspector.sequence(SEQUENCE_MAX_MODULES);
    if (ticket !== this.ticket) return;
    this.steps = steps;
    this.pairs = null;
    if (steps) {
      this.renderSequence(steps);
      return;
    }
    const last = await inspector.lastStep();
    if (ticket !== this.ticket) return;
    this.pairs = { first: firstChildren(last.parents, last.previousCount), count: last.previousCount, origins: build.origins };
    this.caption.textContent = `Step ${build.stats.iterations - 1} → step ${build.stats.iterations}: each module of the string before the last step, and what it became (${plural(last.previousCount, 'module')} → ${plural(build.moduleCount, 'module')}). Hover one (tap it, on a touch screen) to see it in the plant.`;
    this.body.replaceChildren(element('div', 'dv-sizer'));
    (this.body.firstChild as HTMLElement).style.height = `${last.previousCount * PAIR_HEIGHT}px`;
    this.body.classList.add('dv-long');
    await this.renderPairs();
  }

  private renderSequence(steps: DerivationStep[]): void {
    this.body.classList.remove('dv-long');
    this.body.classList.toggle('dv-timed', steps[0].time !== undefined);
    const total = steps.reduce((n, s) => n + s.texts.length, 0);
    this.caption.textContent = sequenceCaption(steps);
    const rows = steps.map((step, k) => this.sequenceRow(step, k));
    this.body.replaceChildren(...rows);
    if (steps.length > 1 && total <= TREE_MAX_MODULES) this.body.append(derivationTree(steps));
    this.status.textContent = '';
    this.markLineage();
  }

  private sequenceRow(step: DerivationStep, k: number): HTMLElement {
    const row = element('div', 'dv-row');
    row.dataset.step = String(k);
    const [text, title] = stepLabel(step, k);
    const label = element('span', 'dv-step', text);
    label.title = title;
    row.append(label);
    let group: HTMLElement | undefined;
    step.texts.forEach((text, i) => {
      const parent = step.parent[i];
      if (!group || k === 0 || parent !== step.parent[i - 1]) {
        group = element('span', 'dv-group');
        const origin = step.origin[i];
        if (k > 0 && origin !== NOT_REWRITTEN) group.style.setProperty('--band', cssColour(PRODUCTION_COLOURS[origin % PRODUCTION_COLOURS.length]));
        else group.classList.add('dv-copy');
        row.append(group);
      }
      const chip = moduleChip(text);
      chip.dataset.step = String(k);
      chip.dataset.i = String(i);
      group.append(chip);
    });
    return row;
  }

  private async renderPairs(): Promise<void> {
    const pairs = this.pairs;
    const inspector = this.inspector;
    if (!pairs || !inspector) return;
    const ticket = this.ticket;
    const first = Math.max(0, Math.floor(this.body.scrollTop / PAIR_HEIGHT) - OVERSCAN);
    const last = Math.min(pairs.count, Math.ceil((this.body.scrollTop + (this.body.clientHeight || 200)) / PAIR_HEIGHT) + OVERSCAN);
    const childFrom = pairs.first[first];
    const [before, after] = await Promise.all([
      inspector.previousTexts(first, last - first),
      inspector.moduleTexts(childFrom, pairs.first[last] - childFrom),
    ]);
    if (ticket !== this.ticket || this.pairs !== pairs) return;
    const window = element('div', 'dv-window');
    for (let j = first; j < last; j++) {
      const pair = element('div', 'dv-pair');
      pair.style.top = `${j * PAIR_HEIGHT}px`;
      pair.dataset.j = String(j);
      const from = pairs.first[j];
      const to = pairs.first[j + 1];
      const origin = from < to ? pairs.origins[from] : NOT_REWRITTEN;
      const band = element('span', 'dv-group');
      if (origin !== NOT_REWRITTEN) band.style.setProperty('--band', cssColour(PRODUCTION_COLOURS[origin % PRODUCTION_COLOURS.length]));
      else band.classList.add('dv-copy');
      const became = after.slice(from - childFrom, to - childFrom);
      band.textContent = became.map(shortModuleText).join('') || 'ε';
      band.title = became.join('');
      pair.append(element('span', 'dv-index', String(j)), moduleChip(before[j - first] ?? ''), element('span', 'dv-arrow', '⇒'), band);
      window.append(pair);
    }
    const sizer = this.body.firstChild as HTMLElement;
    sizer.replaceChildren(window);
  }

  private hover(target: HTMLElement | null): void {
    for (const old of this.body.querySelectorAll('.dv-hover, .dv-parent, .dv-child')) old.classList.remove('dv-hover', 'dv-parent', 'dv-child');
    const chip = target?.closest<HTMLElement>('.dv-m[data-step], .dv-pair');
    if (!chip) {
      this.host.preview(null, null);
      return;
    }
    if (chip.classList.contains('dv-pair')) {
      this.hoverPair(chip);
      return;
    }
    const steps = this.steps;
    if (!steps) return;
    const k = Number(chip.dataset.step);
    const i = Number(chip.dataset.i);
    this.mark(k, i, 'dv-hover');
    if (k > 0) this.mark(k - 1, steps[k].parent[i], 'dv-parent');
    if (k + 1 < steps.length) steps[k + 1].parent.forEach((p, c) => p === i && this.mark(k + 1, c, 'dv-child'));
    this.status.textContent = originInWords(steps, k, i, this.host);
    const origin = k > 0 ? steps[k].origin[i] : NOT_REWRITTEN;
    this.host.preview(descendants(steps, k, i), origin === NOT_REWRITTEN ? null : origin);
  }

  private hoverPair(pair: HTMLElement): void {
    const pairs = this.pairs;
    const build = this.build;
    if (!pairs || !build) return;
    pair.classList.add('dv-hover');
    const j = Number(pair.dataset.j);
    const children = Array.from({ length: pairs.first[j + 1] - pairs.first[j] }, (_, c) => pairs.first[j] + c);
    const origin = children.length > 0 ? pairs.origins[children[0]] : NOT_REWRITTEN;
    const from = pair.querySelector('.dv-m')?.textContent ?? '';
    const n = build.stats.iterations;
    this.status.textContent =
      origin === NOT_REWRITTEN
        ? `${from} (module ${j} of step ${n - 1}) was copied into step ${n}.`
        : `${from} (module ${j} of step ${n - 1}) became ${plural(children.length, 'module')} of step ${n}, by ${this.host.describeProduction(origin)}.`;
    this.host.preview(children, origin === NOT_REWRITTEN ? null : origin);
  }

  private click(target: HTMLElement): void {
    const chip = target.closest<HTMLElement>('.dv-m[data-step]');
    if (!chip || !this.steps) return;
    const k = Number(chip.dataset.step);
    if (k === this.steps.length - 1) this.host.pick(Number(chip.dataset.i));
  }

  /** Marks module `i` of step `step` with `className`, in the rows and in the tree. */
  private mark(step: number, i: number, className: string): void {
    for (const chip of this.body.querySelectorAll(`.dv-m[data-step="${step}"][data-i="${i}"]`)) chip.classList.add(className);
  }
}

/**
 * What the view says above the rows: the steps shown, or for a timed grammar (ABOP 6.1) the rounds
 * of replacements up to its time and, last, the string at that time.
 */
export function sequenceCaption(steps: readonly DerivationStep[]): string {
  const last = steps[steps.length - 1].time;
  if (last !== undefined) {
    const ageing = steps.length > 1 && steps[steps.length - 1].origin.every((o) => o === NOT_REWRITTEN);
    return (
      `The timed derivation up to ${timeWords(last)}: a row per round of replacements, at its time` +
      `${ageing ? `, and last the string at ${timeWords(last)} (every module older since)` : ''}. ` +
      'Each band is what one module of the row before became, in the colour of the production that wrote it. Hover a module.'
    );
  }
  return steps.length === 1
    ? 'Step 0: the axiom. Step the iterations up to watch it being rewritten.'
    : `The derivation, step 0 to ${steps.length - 1}: each band is what one module of the step before became, in the colour of the production that wrote it. Hover a module.`;
}

/** A row's label and its tooltip: `ω`, `⇒ 2`; a timed derivation's rows say their time (`⇒ t 2`, `t 2.5`). */
export function stepLabel(step: DerivationStep, k: number): [string, string] {
  if (step.time === undefined) return k === 0 ? ['ω', 'Step 0: the axiom'] : [`⇒ ${k}`, `Step ${k}`];
  const t = shortNumber(String(step.time));
  if (k === 0) return ['ω', `The axiom, ${timeWords(step.time)}`];
  if (step.origin.every((o) => o === NOT_REWRITTEN)) return [`t ${t}`, `The string at ${timeWords(step.time)}: nothing replaced since the row before, every timed module older`];
  return [`⇒ t ${t}`, `Round ${k}, at ${timeWords(step.time)}: the modules at their terminal age replaced`];
}

/** A module as the string panel writes it (numbers to 6 significant digits), the exact text in its tooltip. */
function moduleChip(text: string): HTMLElement {
  const chip = element('span', 'dv-m', shortModuleText(text));
  if (chip.textContent !== text) chip.title = text;
  return chip;
}

function element(tag: string, className: string, text?: string): HTMLElement {
  const e = document.createElement(tag);
  e.className = className;
  if (text !== undefined) e.textContent = text;
  return e;
}

const SVG = 'http://www.w3.org/2000/svg';

/**
 * The derivation tree: each module a node in its step's row, an edge from each module to those it
 * became. The last step's modules are spaced evenly; a module sits above the middle of its children
 * (a module erased, with no children, next to its left neighbour).
 */
function derivationTree(steps: readonly DerivationStep[]): SVGSVGElement {
  // The last step's modules side by side: room for the longest text (about 7.5 px a character).
  const longest = Math.max(...steps[steps.length - 1].texts.map((t) => shortModuleText(t).length));
  const dx = Math.max(28, longest * 7.5 + 10);
  const dy = 34;
  const last = steps.length - 1;
  const xs: number[][] = steps.map(() => []);
  xs[last] = steps[last].texts.map((_, i) => 20 + i * dx);
  for (let k = last - 1; k >= 0; k--) {
    const sums = new Map<number, { sum: number; n: number }>();
    steps[k + 1].parent.forEach((p, c) => {
      const s = sums.get(p) ?? { sum: 0, n: 0 };
      sums.set(p, { sum: s.sum + xs[k + 1][c], n: s.n + 1 });
    });
    xs[k] = steps[k].texts.map((_, i) => {
      const s = sums.get(i);
      return s ? s.sum / s.n : 0;
    });
    xs[k].forEach((_, i) => {
      if (!sums.has(i)) xs[k][i] = i > 0 ? xs[k][i - 1] + dx / 2 : 20;
    });
  }
  const width = Math.max(...xs.flat()) + 40;
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('class', 'dv-tree');
  svg.setAttribute('viewBox', `0 0 ${width} ${steps.length * dy}`);
  svg.setAttribute('width', String(width));
  svg.setAttribute('height', String(steps.length * dy));
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', 'Derivation tree');
  for (let k = 1; k <= last; k++) {
    steps[k].parent.forEach((p, c) => {
      const line = document.createElementNS(SVG, 'line');
      line.setAttribute('x1', String(xs[k - 1][p]));
      line.setAttribute('y1', String((k - 1) * dy + 20));
      line.setAttribute('x2', String(xs[k][c]));
      line.setAttribute('y2', String(k * dy + 8));
      svg.append(line);
    });
  }
  steps.forEach((step, k) =>
    step.texts.forEach((text, i) => {
      const label = document.createElementNS(SVG, 'text');
      label.setAttribute('x', String(xs[k][i]));
      label.setAttribute('y', String(k * dy + 18));
      label.setAttribute('class', 'dv-m');
      label.dataset.step = String(k);
      label.dataset.i = String(i);
      label.textContent = shortModuleText(text);
      svg.append(label);
    }),
  );
  return svg;
}
