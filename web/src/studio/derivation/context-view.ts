// The context-sensitivity view, what no other L-system tool offers: put the cursor on a production
// and the 3D view and the derived-string panel show every module it wrote in the last step, and the
// modules that served as its left and right contexts; click a segment (or a module in the panel)
// and the production that made it is marked in the editor, with the contexts of that rewriting.
// "Colour by production" paints every module by the production that wrote it, so stepping the
// iterations shows which production rewrote what from step k to k + 1.
import { loadVocabulary, NOT_REWRITTEN, type BuildOptions, type Explanation, type MatchReport, type PlantBuild, type PlantInspector } from '../../core';
import type { GrammarEditor } from '../../editor';
import { cssColour, HIGHLIGHT, PRODUCTION_COLOURS, type Rgb } from '../../view/highlight';
import type { PlantView } from '../../view';
import { StringPanel, type ModuleRole } from './string-panel';
import type { ViewOptions } from '../controls';
import { branchQuery, EnvironmentTools, REPLY_REACH, replyInWords } from '../environment';
import { BreakpointPanel } from './breakpoints';
import { LineageList } from './lineage-list';
import { conditionText, copiedInWords, countsInWords, describeProduction, madeInWords, reportInWords, stringAtTime } from './explain-words';

/** The page elements of the view. */
export interface ContextViewElements {
  /** Where the derived-string panel goes. */
  panel: HTMLElement;
  /** The one-line explanation (counts). */
  summary: HTMLElement;
  /** The legend of "colour by production". */
  legend: HTMLElement;
  /** The legend of the highlight colours (written, left and right context, picked), shown with a highlight. */
  highlightLegend: HTMLElement;
}

const ROLE_CODE: Record<ModuleRole, number> = { produced: 1, left: 2, right: 3, selected: 4 };
const CODE_ROLE: (ModuleRole | null)[] = [null, 'produced', 'left', 'right', 'selected'];
const ROLE_RGB: (Rgb | null)[] = [null, HIGHLIGHT.produced, HIGHLIGHT.left, HIGHLIGHT.right, HIGHLIGHT.selected];

/** What the view explains: the production under the cursor, the module picked, or both. */
interface Focus {
  production: number | null;
  module: number | null;
}

export class ContextView {
  private readonly panel: StringPanel;
  private build: PlantBuild | undefined;
  private inspector: PlantInspector | undefined;
  private source = '';
  /** A timed grammar's growth time of the string shown (the timeline's t, else its iterations); null when not timed. */
  private timedAt: number | null = null;
  private focus: Focus = { production: null, module: null };
  /** Modules lit up from elsewhere (the derivation view's hover), instead of the focus's highlight. */
  private preview: Set<number> | null = null;
  /** Bumped by every change of focus or build, so late answers are dropped. */
  private ticket = 0;
  /** The View toolbar's Environment tools: each build's environment drawn with its plant. */
  private readonly environment: EnvironmentTools;
  /** The picked module's lineage, under the summary. */
  private readonly lineage: LineageList;
  /** The breakpoints, under the lineage: where Play pauses. */
  private readonly breakpoints: BreakpointPanel;

  constructor(
    private readonly els: ContextViewElements,
    private readonly view: PlantView,
    private readonly editor: () => GrammarEditor | undefined,
    /** The view options: `byProduction` paints every module by the production that wrote it. */
    private readonly viewOptions: ViewOptions,
  ) {
    this.panel = new StringPanel(els.panel, (module) => this.pickModule(module));
    this.environment = new EnvironmentTools(view);
    this.lineage = new LineageList({
      describeProduction: (index) => this.describeProduction(index),
      preview: (modules, production) => this.showPreview(modules, production),
    });
    this.breakpoints = new BreakpointPanel({ describeProduction: (index) => this.describeProduction(index) });
    els.summary.after(this.lineage.element, this.breakpoints.element);
    // One definition of the highlight colours: the 3D view's, passed on to the page's CSS.
    for (const [role, rgb] of Object.entries(HIGHLIGHT)) {
      document.documentElement.style.setProperty(`--hl-${role}`, cssColour(rgb));
    }
    viewOptions.onChange((_, changed) => changed.has('byProduction') && this.refresh());
    view.canvas.addEventListener('click', (event) => {
      // A click, not the end of an orbit drag (nor a click that selects a branch to edit).
      if (!this.picking || event.detail === 0 || this.dragged(event)) return;
      this.pickModule(view.pickModule(event.clientX, event.clientY));
    });
    view.canvas.addEventListener('pointerdown', (event) => {
      this.down = { x: event.clientX, y: event.clientY };
    });
  }

  private down = { x: 0, y: 0 };
  /** Clicks on the plant pick modules (off while branches are edited: clicks select branches). */
  picking = true;

  private dragged(event: MouseEvent): boolean {
    return Math.hypot(event.clientX - this.down.x, event.clientY - this.down.y) > 4;
  }

  /**
   * Shows a new build on screen, built with `options` (a timed grammar's at a time: the timeline's
   * t); the view takes ownership of `inspector` (frees the old one).
   */
  setBuild(build: PlantBuild, inspector: PlantInspector | undefined, source: string, options: BuildOptions = {}): void {
    if (this.inspector !== inspector) this.inspector?.free();
    this.build = build;
    this.inspector = inspector;
    this.source = source;
    this.timedAt = build.timed ? (options.time ?? options.iterations ?? build.grammarIterations) : null;
    this.els.summary.dataset.t = this.timedAt === null ? '' : String(this.timedAt);
    this.panel.show(build.moduleCount, inspector);
    this.environment.show(build.environment, build.flat);
    this.focus = { ...this.focus, module: null }; // module indices belong to the old string
    this.lineage.clear();
    this.breakpoints.setBuild(build, inspector, source);
    this.preview = null;
    this.renderLegend();
    this.refresh();
  }

  /** The editor's cursor moved to `pos`: focus the production there (or none); a picked module stays. */
  cursorAt(pos: number): void {
    const editor = this.editor();
    if (!this.build || !editor || editor.text() !== this.source) return;
    const production = this.build.productions.find((p) => p.from <= pos && pos <= p.to)?.index ?? null;
    if (production === this.focus.production) return;
    editor.markProduction(null);
    this.setFocus({ ...this.focus, production });
  }

  /** A module picked in the 3D view or the panel (null: a click on nothing clears the pick). */
  pickModule(module: number | null): void {
    // A pick speaks for itself: the cursor's production is set aside until the cursor moves again.
    this.setFocus({ production: null, module });
    if (module !== null) this.panel.scrollToModule(module);
    void this.lineage.show(this.inspector, module, this.source, this.build?.productions ?? []);
  }

  /**
   * Lights up `modules` of the derived string and marks production `production` in the editor
   * (from the derivation view's hover), or restores the focus's own highlight (`null`).
   */
  showPreview(modules: Iterable<number> | null, production: number | null): void {
    this.preview = modules === null ? null : new Set(modules);
    const p = production === null ? undefined : this.build?.productions[production];
    // The preview's production is marked while it lasts; the focus's own mark comes back after.
    this.editor()?.markProduction(modules !== null && p ? { from: p.from, to: p.to } : null);
    this.refresh();
  }

  /** A production as the user knows it (`rule 2 (line 8: F -> FF)`). */
  describeProduction(index: number): string {
    const p = this.build?.productions[index];
    return p ? describeProduction(this.source, p) : `rule ${index + 1}`;
  }

  /** A production's condition as written, or null. */
  conditionOf(index: number): string | null {
    const p = this.build?.productions[index];
    return p ? conditionText(this.source, p) : null;
  }

  private setFocus(focus: Focus): void {
    this.focus = focus;
    if (focus.module === null) this.editor()?.markProduction(null);
    this.refresh();
  }

  /**
   * Asks the build on screen again for everything shown (the string's rows, the highlight and its
   * words): after its worker was replaced, answers lost with that worker come back.
   */
  reload(): void {
    this.panel.reload();
    this.refresh();
  }

  /** Recomputes the highlight and the words for the current build, focus and mode. */
  private refresh(): void {
    const ticket = ++this.ticket;
    const build = this.build;
    const inspector = this.inspector;
    const focus = this.focus;
    if (!build) return;
    void this.ask(inspector, focus).then(({ explanation, report, text }) => {
      if (ticket !== this.ticket) return;
      this.apply(build, focus, explanation);
      this.describe(build, focus, explanation, report, text);
      if (focus.module !== null && build.environment) void this.describeReply(build, inspector, focus.module, ticket);
    });
  }

  /**
   * Adds to the summary the reply of the picked module's `?E` (the first after it on its branch,
   * else the last before it): its values named by the programs' reply words.
   */
  private async describeReply(build: PlantBuild, inspector: PlantInspector | undefined, module: number, ticket: number): Promise<void> {
    const vocabulary = await loadVocabulary();
    const nameOf = (meaning: string) => vocabulary.modules.find((m) => m.meaning === meaning)?.name;
    const [query, open, close] = [nameOf('QueryEnvironment'), nameOf('Push'), nameOf('Pop')];
    if (!inspector || !query || !open || !close || !build.environment) return;
    const first = Math.max(0, module - REPLY_REACH);
    const texts = await inspector.moduleTexts(first, module + REPLY_REACH + 1 - first);
    if (ticket !== this.ticket) return;
    const found = branchQuery(texts, first, module, { query, open, close });
    const line = document.createElement('span');
    line.className = 'environment-reply';
    line.dataset.testid = 'environment-reply';
    line.textContent = found ? ` Its ${replyInWords(found, build.environment.replies, query)}.` : ` No ${query} on this branch.`;
    if (found) line.dataset.module = String(found.module);
    this.els.summary.append(line);
  }

  /**
   * The core's answers for `focus`: the production's explanation (the cursor's, or the one that
   * wrote the picked module), and with a picked module its text and the match report of that
   * production at the module it came from.
   */
  private async ask(inspector: PlantInspector | undefined, { production, module }: Focus) {
    if (!inspector || (production === null && module === null)) return { explanation: null, report: null, text: '' };
    const [explanation, text] = await Promise.all([
      production !== null ? inspector.explain(production) : inspector.explainModule(module!),
      module !== null ? inspector.moduleTexts(module, 1) : Promise.resolve(['']),
    ]);
    const asked = production ?? explanation?.production;
    const report = module !== null && asked !== undefined ? await inspector.matchReport(asked, module) : null;
    return { explanation, report, text: text[0] ?? '' };
  }

  private apply(build: PlantBuild, focus: Focus, explanation: Explanation | null): void {
    const roles = new Uint8Array(build.moduleCount);
    const mark = (list: Iterable<number>, role: ModuleRole) => {
      for (const i of list) if (i < roles.length) roles[i] = ROLE_CODE[role];
    };
    const preview = this.preview;
    if (preview) mark(preview, 'produced');
    else if (explanation) {
      mark(explanation.produced, 'produced');
      mark(explanation.leftContext, 'left');
      mark(explanation.rightContext, 'right');
    }
    if (!preview && focus.module !== null && focus.module < roles.length) roles[focus.module] = ROLE_CODE.selected;
    const byProduction = this.viewOptions.values.byProduction;
    const productionRgb = (module: number): Rgb | null => {
      const origin = build.origins[module];
      return origin === undefined || origin === NOT_REWRITTEN ? null : PRODUCTION_COLOURS[origin % PRODUCTION_COLOURS.length];
    };
    const highlighted = preview !== null || explanation !== null || focus.module !== null;
    if (highlighted || byProduction) {
      this.view.colourModules((m) => ROLE_RGB[roles[m]] ?? (byProduction ? productionRgb(m) : null));
    } else {
      this.view.colourModules(null);
    }
    this.panel.highlight(
      (m) => CODE_ROLE[roles[m]] ?? null,
      byProduction ? (m) => { const rgb = productionRgb(m); return rgb ? cssColour(rgb) : null; } : null,
    );
    this.els.highlightLegend.hidden = !highlighted;
  }

  /** The summary: what the focus is, in words, with the counts as data attributes for tests. */
  private describe(build: PlantBuild, focus: Focus, explanation: Explanation | null, report: MatchReport | null, moduleText: string): void {
    const summary = this.els.summary;
    delete summary.dataset.fired;
    delete summary.dataset.contextMatched;
    delete summary.dataset.conditionFailed;
    if (focus.production === null && focus.module === null) {
      const idle =
        build.stats.iterations === 0
          ? 'Step 0: the axiom. Put the cursor on a production after a step to see where it fired.'
          : 'Put the cursor on a production to see where it fired in the last step, or click the plant to ask how a part of it was made.';
      summary.textContent = this.timedAt === null ? idle : stringAtTime(this.timedAt);
      return;
    }
    const production = explanation ? build.productions[explanation.production] : undefined;
    if (explanation && production) {
      summary.dataset.fired = String(explanation.fired);
      summary.dataset.contextMatched = String(explanation.contextMatched);
      summary.dataset.conditionFailed = String(explanation.conditionFailed);
    }
    if (focus.production !== null) {
      // The cursor's production; with a picked module, why it did or did not rewrite that one.
      const counts = production && explanation ? countsInWords(this.source, production, explanation) : `${this.describeProduction(focus.production)} has nothing to show before the first step.`;
      const p = build.productions[focus.production];
      const why = report && p ? ' ' + reportInWords(this.source, p, report, report.rewrittenBy === null ? undefined : build.productions[report.rewrittenBy]) : '';
      summary.textContent = counts + why;
      return;
    }
    if (!explanation || !production) {
      summary.textContent = copiedInWords(focus.module!, moduleText);
      return;
    }
    this.editor()?.markProduction({ from: production.from, to: production.to });
    summary.textContent = madeInWords(this.source, production, explanation, report, focus.module!, moduleText);
  }

  private renderLegend(): void {
    const legend = this.els.legend;
    legend.replaceChildren();
    const build = this.build;
    if (!build) return;
    build.productions.forEach((p) => {
      const item = document.createElement('li');
      const swatch = document.createElement('span');
      swatch.className = 'legend-swatch';
      swatch.style.background = cssColour(PRODUCTION_COLOURS[p.index % PRODUCTION_COLOURS.length]);
      const text = document.createElement('code');
      text.textContent = this.source.slice(p.from, p.to).trim();
      item.append(swatch, text);
      legend.append(item);
    });
  }
}
