// The studio page: wires the grammar editor, the core and the 3D view together.
// Edits rebuild the plant after a short pause; a grammar with errors keeps the last good plant.
import './style.css';
import { coreVersion, grammarDirectives, initCore, turtleCommands, type PlantStats } from './core';
import { createGrammarEditor, type GrammarEditor } from './editor';
import { PlantView } from './view';
import { ContextView, PlantBuilder, debounce, reportErrors, reportPlant, type StatusReport, type TimedBuild } from './studio';

/** The grammar shown at start, relative to the page so the site works from any sub-path. */
const INITIAL_EXAMPLE_URL = 'examples/abop-1.24d.lsys';
/** Pause after the last keystroke before rebuilding, in ms. */
const REBUILD_DELAY_MS = 150;

/** What the page exposes for its end-to-end tests (and nothing else is global). */
interface StudioTestHook {
  /** Settles when the first build is on screen (rejects if the studio could not start). */
  ready: Promise<void>;
  /** Stats of the plant on screen. */
  lastStats: PlantStats | null;
}

declare global {
  interface Window {
    __meristem?: StudioTestHook;
  }
}

/** The page's fixed elements (see index.html). */
interface StudioElements {
  editor: HTMLElement;
  viewport: HTMLElement;
  status: HTMLElement;
  version: HTMLElement;
  iterations: HTMLInputElement;
  sides: HTMLSelectElement;
  smoothAll: HTMLInputElement;
  frame: HTMLButtonElement;
  staleBadge: HTMLElement;
  stringPanel: HTMLElement;
  explainSummary: HTMLElement;
  byProduction: HTMLInputElement;
  productionLegend: HTMLElement;
}

function byId<T extends HTMLElement>(id: string, type: new () => T): T {
  const element = document.getElementById(id);
  if (!(element instanceof type)) throw new Error(`index.html lacks #${id}`);
  return element;
}

function studioElements(): StudioElements {
  return {
    editor: byId('editor', HTMLElement),
    viewport: byId('viewport', HTMLElement),
    status: byId('status', HTMLElement),
    version: byId('core-version', HTMLElement),
    iterations: byId('iterations', HTMLInputElement),
    sides: byId('sides', HTMLSelectElement),
    smoothAll: byId('smooth-all', HTMLInputElement),
    frame: byId('frame', HTMLButtonElement),
    staleBadge: byId('stale-badge', HTMLElement),
    stringPanel: byId('string-panel', HTMLElement),
    explainSummary: byId('explain-summary', HTMLElement),
    byProduction: byId('by-production', HTMLInputElement),
    productionLegend: byId('production-legend', HTMLElement),
  };
}

async function fetchText(url: string): Promise<string> {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.text();
}

/** Shows a report in the status line: its text, and its state as `data-state` (for CSS and tests). */
function showStatus(status: HTMLElement, report: StatusReport | { state: 'loading' | 'crashed'; text: string }): void {
  status.textContent = report.text;
  status.dataset.state = report.state;
}

/** The override typed into the iterations box, or undefined to use the grammar's `#iterations`. */
function iterationsOverride(input: HTMLInputElement): number | undefined {
  const value = input.valueAsNumber;
  return Number.isFinite(value) && value >= 0 ? Math.floor(value) : undefined;
}

async function startStudio(els: StudioElements, hook: StudioTestHook): Promise<void> {
  showStatus(els.status, { state: 'loading', text: 'Loading…' });
  const [source] = await Promise.all([fetchText(INITIAL_EXAMPLE_URL), initCore()]);
  els.version.textContent = `core ${coreVersion()}`;

  const builder = new PlantBuilder();
  const view = new PlantView(els.viewport);
  let crashed = false;
  let hasPlant = false;
  let generation = 0;

  /** The build of `text`, or undefined once the core has crashed (the page then says so). */
  const buildOf = (text: string): TimedBuild | undefined => {
    if (crashed) return undefined;
    try {
      return builder.build(text, {
        iterations: iterationsOverride(els.iterations),
        sides: Number(els.sides.value),
        smoothAll: els.smoothAll.checked,
      });
    } catch (error) {
      crashed = true;
      console.error('Meristem core crashed:', error);
      showStatus(els.status, { state: 'crashed', text: 'The core crashed — reload the page to continue' });
      return undefined;
    }
  };

  let editor: GrammarEditor | undefined;
  const contexts = new ContextView(
    { panel: els.stringPanel, summary: els.explainSummary, byProduction: els.byProduction, legend: els.productionLegend },
    view,
    () => editor,
  );
  const rebuild = (): void => {
    if (!editor) return;
    const text = editor.text();
    const result = buildOf(text);
    if (!result) return;
    const { build, millis } = result;
    if (build.ok) {
      view.showPlant(build.mesh);
      result.adopted = true;
      contexts.setBuild(build, result.inspector, text);
      contexts.cursorAt(editor.view.state.selection.main.head);
      hasPlant = true;
      hook.lastStats = build.stats;
      if (iterationsOverride(els.iterations) === undefined) els.iterations.placeholder = String(build.stats.iterations);
      showStatus(els.status, reportPlant(build.stats, build.diagnostics, millis));
    } else {
      showStatus(els.status, reportErrors(build.diagnostics, hasPlant));
    }
    const stale = !build.ok && hasPlant;
    view.setStale(stale);
    els.staleBadge.hidden = !stale;
    els.status.dataset.generation = String(++generation); // counts builds: tests wait for the next one
  };
  const scheduleRebuild = debounce(rebuild, REBUILD_DELAY_MS);

  editor = createGrammarEditor({
    parent: els.editor,
    doc: source,
    onChange: scheduleRebuild,
    diagnose: (text) => buildOf(text)?.build.diagnostics ?? [],
    commands: turtleCommands(),
    directives: grammarDirectives(),
    onCursor: (pos) => contexts.cursorAt(pos),
  });
  els.iterations.addEventListener(
    'input',
    debounce(() => {
      rebuild();
      editor?.refreshDiagnostics();
    }, REBUILD_DELAY_MS),
  );
  // View options re-mesh the plant at once (the editor's diagnostics do not depend on them).
  els.sides.addEventListener('change', rebuild);
  els.smoothAll.addEventListener('change', rebuild);
  els.frame.addEventListener('click', () => view.frame());
  rebuild();
}

const els = studioElements();
const hook: StudioTestHook = { ready: Promise.resolve(), lastStats: null };
hook.ready = startStudio(els, hook);
hook.ready.catch((error: unknown) => {
  console.error('Meristem could not start:', error);
  showStatus(els.status, { state: 'crashed', text: `Could not start: ${String(error)}` });
});
window.__meristem = hook;
