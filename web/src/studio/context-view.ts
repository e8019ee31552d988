// The context-sensitivity view, what no other L-system tool offers: put the cursor on a production
// and the 3D view and the derived-string panel show every module it wrote in the last step, and the
// modules that served as its left and right contexts; click a segment (or a module in the panel)
// and the production that made it is marked in the editor, with the contexts of that rewriting.
// "Colour by production" paints every module by the production that wrote it, so stepping the
// iterations shows which production rewrote what from step k to k + 1.
import { NOT_REWRITTEN, type Explanation, type PlantBuild, type PlantInspector, type ProductionInfo } from '../core';
import type { GrammarEditor } from '../editor';
import { cssColour, HIGHLIGHT, PRODUCTION_COLOURS, type Rgb } from '../view/highlight';
import type { PlantView } from '../view';
import { StringPanel, type ModuleRole } from './string-panel';
import type { ViewOptions } from './view-options';
import { plural } from './status';

/** The page elements of the view. */
export interface ContextViewElements {
  /** Where the derived-string panel goes. */
  panel: HTMLElement;
  /** The one-line explanation (counts). */
  summary: HTMLElement;
  /** The legend of "colour by production". */
  legend: HTMLElement;
}

type Focus = { kind: 'production'; index: number } | { kind: 'module'; index: number } | null;

const ROLE_CODE: Record<ModuleRole, number> = { produced: 1, left: 2, right: 3, selected: 4 };
const CODE_ROLE: (ModuleRole | null)[] = [null, 'produced', 'left', 'right', 'selected'];
const ROLE_RGB: (Rgb | null)[] = [null, HIGHLIGHT.produced, HIGHLIGHT.left, HIGHLIGHT.right, HIGHLIGHT.selected];

/** The 1-based line of a UTF-16 offset. */
function lineOf(source: string, offset: number): number {
  let line = 1;
  for (let i = 0; i < offset && i < source.length; i++) if (source.charCodeAt(i) === 10) line++;
  return line;
}

export class ContextView {
  private readonly panel: StringPanel;
  private build: PlantBuild | undefined;
  private inspector: PlantInspector | undefined;
  private source = '';
  private focus: Focus = null;
  /** Bumped by every change of focus or build, so late answers are dropped. */
  private ticket = 0;

  constructor(
    private readonly els: ContextViewElements,
    private readonly view: PlantView,
    private readonly editor: () => GrammarEditor | undefined,
    /** The view options: `byProduction` paints every module by the production that wrote it. */
    private readonly viewOptions: ViewOptions,
  ) {
    this.panel = new StringPanel(els.panel, (module) => this.pickModule(module));
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

  /** Shows a new build on screen; the view takes ownership of `inspector` (frees the old one). */
  setBuild(build: PlantBuild, inspector: PlantInspector | undefined, source: string): void {
    if (this.inspector !== inspector) this.inspector?.free();
    this.build = build;
    this.inspector = inspector;
    this.source = source;
    this.panel.show(build.moduleCount, inspector);
    if (this.focus?.kind === 'module') this.focus = null; // module indices belong to the old string
    this.renderLegend();
    this.refresh();
  }

  /** The editor's cursor moved to `pos`: focus the production there (or nothing). */
  cursorAt(pos: number): void {
    const editor = this.editor();
    if (!this.build || !editor || editor.text() !== this.source) return;
    const production = this.build.productions.find((p) => p.from <= pos && pos <= p.to);
    if (production === undefined) {
      if (this.focus?.kind === 'production') this.setFocus(null);
      return;
    }
    if (this.focus?.kind === 'production' && this.focus.index === production.index) return;
    this.editor()?.markProduction(null);
    this.setFocus({ kind: 'production', index: production.index });
  }

  /** A module picked in the 3D view or the panel (null: a click on nothing clears the pick). */
  pickModule(module: number | null): void {
    this.setFocus(module === null ? null : { kind: 'module', index: module });
    if (module !== null) this.panel.scrollToModule(module);
  }

  private setFocus(focus: Focus): void {
    this.focus = focus;
    if (!focus) this.editor()?.markProduction(null);
    this.refresh();
  }

  /** Recomputes the highlight for the current build, focus and mode. */
  private refresh(): void {
    const ticket = ++this.ticket;
    const build = this.build;
    const focus = this.focus;
    if (!build) return;
    const explain = !this.inspector || !focus
      ? Promise.resolve(null)
      : focus.kind === 'production'
        ? this.inspector.explain(focus.index)
        : this.inspector.explainModule(focus.index);
    void explain.then((explanation) => {
      if (ticket !== this.ticket) return;
      this.apply(build, focus, explanation);
    });
  }

  private apply(build: PlantBuild, focus: Focus, explanation: Explanation | null): void {
    const roles = new Uint8Array(build.moduleCount);
    const mark = (list: Uint32Array, role: ModuleRole) => list.forEach((i) => (roles[i] = ROLE_CODE[role]));
    if (explanation) {
      mark(explanation.produced, 'produced');
      mark(explanation.leftContext, 'left');
      mark(explanation.rightContext, 'right');
    }
    if (focus?.kind === 'module' && focus.index < roles.length) roles[focus.index] = ROLE_CODE.selected;
    const byProduction = this.viewOptions.values.byProduction;
    const productionRgb = (module: number): Rgb | null => {
      const origin = build.origins[module];
      return origin === undefined || origin === NOT_REWRITTEN ? null : PRODUCTION_COLOURS[origin % PRODUCTION_COLOURS.length];
    };
    const highlighted = explanation !== null || focus?.kind === 'module';
    if (highlighted || byProduction) {
      this.view.colourModules((m) => ROLE_RGB[roles[m]] ?? (byProduction ? productionRgb(m) : null));
    } else {
      this.view.colourModules(null);
    }
    this.panel.highlight(
      (m) => CODE_ROLE[roles[m]] ?? null,
      byProduction ? (m) => { const rgb = productionRgb(m); return rgb ? cssColour(rgb) : null; } : null,
    );
    this.describe(build, focus, explanation);
  }

  private describe(build: PlantBuild, focus: Focus, explanation: Explanation | null): void {
    const summary = this.els.summary;
    const production = explanation ? build.productions[explanation.production] : undefined;
    delete summary.dataset.fired;
    delete summary.dataset.contextMatched;
    delete summary.dataset.conditionFailed;
    if (!focus) {
      summary.textContent =
        build.stats.iterations === 0
          ? 'Step 0: the axiom. Put the cursor on a production after a step to see where it fired.'
          : 'Put the cursor on a production to see where it fired in the last step, or click the plant.';
      return;
    }
    if (!explanation || !production) {
      summary.textContent =
        focus.kind === 'module'
          ? `Module ${focus.index} was copied: no production rewrote it in the last step.`
          : 'This production has nothing to show before the first step.';
      return;
    }
    const name = this.productionName(production);
    // A context-free production has no context to match: say what its count means there.
    const matched = production.context ? 'contexts matched' : 'predecessor matched';
    const counts = `fired ${plural(explanation.fired, 'time')} · ${matched} ${explanation.contextMatched} · condition failed ${explanation.conditionFailed}`;
    summary.dataset.fired = String(explanation.fired);
    summary.dataset.contextMatched = String(explanation.contextMatched);
    summary.dataset.conditionFailed = String(explanation.conditionFailed);
    if (focus.kind === 'module') {
      this.editor()?.markProduction({ from: production.from, to: production.to });
      summary.textContent = `Module ${focus.index} was written by ${name} — that production ${counts}`;
    } else {
      summary.textContent = `${name}: ${counts}`;
    }
  }

  private productionName(p: ProductionInfo): string {
    const text = this.source.slice(p.from, p.to).trim();
    return `${p.label ?? `production ${p.index + 1}`} (line ${lineOf(this.source, p.from)}: ${text})`;
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
