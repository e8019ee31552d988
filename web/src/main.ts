// The studio page: wires the grammar editor, the core and the 3D view together.
// Edits rebuild the plant after a short pause; a grammar with errors keeps the last good plant.
// The Download menu saves the plant on screen as a model file (written by the core) or a PNG.
import './style.css';
import { coreVersion, exportModel, grammarDirectives, initCore, MODEL_FORMATS, turtleCommands, type BuildOptions, type ModelFormat, type PlantStats } from './core';
import { createGrammarEditor, type GrammarEditor } from './editor';
import { PlantView } from './view';
import {
  ContextView,
  PlantBuilder,
  afterPaint,
  debounce,
  fileSize,
  pictureSize,
  reportErrors,
  reportPlant,
  saveFile,
  type StatusReport,
  type TimedBuild,
} from './studio';

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
  downloads: HTMLDetailsElement;
  modelDownloads: HTMLElement;
  pngWidth: HTMLInputElement;
  pngHeight: HTMLInputElement;
  downloadPng: HTMLButtonElement;
  exportStatus: HTMLElement;
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
    downloads: byId('downloads', HTMLDetailsElement),
    modelDownloads: byId('model-downloads', HTMLElement),
    pngWidth: byId('png-width', HTMLInputElement),
    pngHeight: byId('png-height', HTMLInputElement),
    downloadPng: byId('download-png', HTMLButtonElement),
    exportStatus: byId('export-status', HTMLElement),
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
  /** The grammar and build options of the plant on screen: what a download saves. */
  let shown: { source: string; options: BuildOptions } | undefined;

  /** The toolbar's options: iterations, and the view options of the mesh. */
  const buildOptions = (): BuildOptions => ({
    iterations: iterationsOverride(els.iterations),
    sides: Number(els.sides.value),
    smoothAll: els.smoothAll.checked,
  });

  /** The build of `text`, or undefined once the core has crashed (the page then says so). */
  const buildOf = (text: string): TimedBuild | undefined => {
    if (crashed) return undefined;
    try {
      return builder.build(text, buildOptions());
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
    const options = buildOptions();
    const result = buildOf(text);
    if (!result) return;
    const { build, millis } = result;
    if (build.ok) {
      view.showPlant(build.mesh);
      result.adopted = true;
      contexts.setBuild(build, result.inspector, text);
      contexts.cursorAt(editor.view.state.selection.main.head);
      hasPlant = true;
      shown = { source: text, options };
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

  /** Runs one download with the menu's buttons disabled and its progress on the export status. */
  const menuButtons = (): HTMLButtonElement[] => [...els.downloads.querySelectorAll('button')];
  const download = async (what: string, save: () => Promise<string>): Promise<void> => {
    if (crashed || menuButtons().some((b) => b.disabled)) return;
    els.downloads.open = false;
    menuButtons().forEach((b) => (b.disabled = true));
    showExportStatus(els.exportStatus, 'busy', `Exporting ${what}…`);
    try {
      await afterPaint(); // the status shows while the core works (it blocks this thread)
      showExportStatus(els.exportStatus, 'done', await save());
    } catch (error) {
      console.error(`Export of ${what} failed:`, error);
      showExportStatus(els.exportStatus, 'error', `Export of ${what} failed: ${String(error)}`);
      if (error instanceof WebAssembly.RuntimeError) {
        // A panic in the core: its state is unknown, as after a crash while building.
        crashed = true;
        showStatus(els.status, { state: 'crashed', text: 'The core crashed — reload the page to continue' });
      }
    } finally {
      menuButtons().forEach((b) => (b.disabled = false));
    }
  };
  const downloadModel = (format: ModelFormat, label: string): Promise<void> =>
    download(label, async () => {
      if (!shown) throw new Error('no plant yet');
      const file = exportModel(shown.source, format, shown.options);
      saveFile(file.bytes, file.fileName, file.mimeType);
      return `Saved ${file.fileName} · ${fileSize(file.bytes.length)}`;
    });
  for (const { format, label, file } of MODEL_FORMATS) {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'menu-item';
    button.dataset.testid = `download-${format}`;
    button.append(label, Object.assign(document.createElement('span'), { className: 'file-type', textContent: file }));
    button.addEventListener('click', () => void downloadModel(format, label));
    els.modelDownloads.append(button);
  }
  // The menu closes like a menu: on a click elsewhere and on Escape.
  document.addEventListener('pointerdown', (event) => {
    if (els.downloads.open && !els.downloads.contains(event.target as Node)) els.downloads.open = false;
  });
  els.downloads.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || !els.downloads.open) return;
    els.downloads.open = false;
    els.downloads.querySelector('summary')?.focus();
  });
  els.downloadPng.addEventListener('click', () => {
    const size = pictureSize(els.pngWidth.value, els.pngHeight.value, view.maxPictureSide());
    if (!size.ok) {
      showExportStatus(els.exportStatus, 'error', size.message);
      return;
    }
    void download(`PNG ${size.width} × ${size.height}`, async () => {
      const png = await view.snapshot(size.width, size.height);
      saveFile(png, 'plant.png', 'image/png');
      return `Saved plant.png · ${size.width} × ${size.height} · ${fileSize(png.size)}`;
    });
  });
  rebuild();
}

/** Shows the state of the last download next to the build status. */
function showExportStatus(element: HTMLElement, state: 'busy' | 'done' | 'error', text: string): void {
  element.textContent = text;
  element.dataset.state = state;
}

const els = studioElements();
const hook: StudioTestHook = { ready: Promise.resolve(), lastStats: null };
hook.ready = startStudio(els, hook);
hook.ready.catch((error: unknown) => {
  console.error('Meristem could not start:', error);
  showStatus(els.status, { state: 'crashed', text: `Could not start: ${String(error)}` });
});
window.__meristem = hook;
