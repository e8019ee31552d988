// The studio page: wires the grammar editor, the build worker, the 3D view, the context-sensitivity
// view, the downloads and the controls around them (see index.html). The logic lives in ./studio,
// ./editor and ./view; this file only connects the pieces.
import './style.css';
import {
  coreVersion,
  grammarDirectives,
  initCore,
  MODEL_FORMATS,
  turtleCommands,
  type BuildOptions,
  type ModelFormat,
  type PlantStats,
} from './core';
import { createGrammarEditor, type GrammarEditor } from './editor';
import { PlantView } from './view';
import {
  BuildClient,
  ContextView,
  GalleryDialog,
  GalleryThumbnails,
  LivePreview,
  Playback,
  SliderPanel,
  afterPaint,
  askToReplace,
  attachSplitter,
  createBuildWorker,
  createExportWorker,
  describeProgress,
  fetchExample,
  fileSize,
  installShortcuts,
  pictureSize,
  runExport,
  renderShortcutHelp,
  saveFile,
  showStatus,
  type GalleryEntry,
  type ShortcutAction,
} from './studio';

/** The example shown at start (in public/examples). */
const INITIAL_EXAMPLE = 'abop-1.24d.lsys';

/** What the page exposes for its end-to-end tests and benchmarks (and nothing else is global). */
interface StudioTestHook {
  /** Settles when the first build is on screen (rejects if the studio could not start). */
  ready: Promise<void>;
  /** Stats of the plant on screen. */
  lastStats: PlantStats | null;
  /** The live preview (last builds, delivery events). */
  preview?: LivePreview;
  /** The last frame drawn: the delivered-build counter at the time, and `performance.now()`. */
  rendered: { generation: number; at: number } | null;
  /** `performance.now()` at the end of the first frame that drew the last sketch (a big plant as lines). */
  sketched: number | null;
}

declare global {
  interface Window {
    __meristem?: StudioTestHook;
  }
}

function byId<T extends HTMLElement>(id: string, type: new () => T): T {
  const element = document.getElementById(id);
  if (!(element instanceof type)) throw new Error(`index.html lacks #${id}`);
  return element;
}

/** The page's fixed elements (see index.html). */
function studioElements() {
  return {
    studio: byId('studio', HTMLElement),
    editor: byId('editor', HTMLElement),
    viewport: byId('viewport', HTMLElement),
    status: byId('status', HTMLElement),
    version: byId('core-version', HTMLElement),
    iterations: byId('iterations', HTMLInputElement),
    stepBack: byId('step-back', HTMLButtonElement),
    stepForward: byId('step-forward', HTMLButtonElement),
    play: byId('play', HTMLButtonElement),
    seed: byId('seed', HTMLInputElement),
    reroll: byId('reroll', HTMLButtonElement),
    sides: byId('sides', HTMLSelectElement),
    smoothAll: byId('smooth-all', HTMLInputElement),
    frame: byId('frame', HTMLButtonElement),
    projection: byId('projection', HTMLButtonElement),
    grid: byId('grid', HTMLButtonElement),
    lighting: byId('lighting', HTMLButtonElement),
    staleBadge: byId('stale-badge', HTMLElement),
    sliders: byId('sliders', HTMLElement),
    constantsCount: byId('constants-count', HTMLElement),
    constantsEmpty: byId('constants-empty', HTMLElement),
    splitter: byId('splitter', HTMLElement),
    openGallery: byId('open-gallery', HTMLButtonElement),
    gallery: byId('gallery', HTMLDialogElement),
    galleryList: byId('gallery-list', HTMLElement),
    confirm: byId('confirm-replace', HTMLDialogElement),
    confirmExample: byId('confirm-example', HTMLElement),
    shortcutList: byId('shortcut-list', HTMLElement),
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
    exportProgress: byId('export-progress', HTMLProgressElement),
    exportCancel: byId('export-cancel', HTMLButtonElement),
  };
}
type StudioElements = ReturnType<typeof studioElements>;

/** A whole number typed into `input` (0 or more), or undefined when it is empty or not one. */
function wholeNumber(input: HTMLInputElement): number | undefined {
  const value = input.valueAsNumber;
  return Number.isFinite(value) && value >= 0 ? Math.floor(value) : undefined;
}

/** A toggle button's state, kept in `aria-pressed`. */
function pressed(button: HTMLButtonElement): boolean {
  return button.getAttribute('aria-pressed') === 'true';
}

async function startStudio(els: StudioElements, hook: StudioTestHook): Promise<void> {
  showStatus(els.status, { state: 'loading', text: 'Loading…' });
  // The page's own core instance only serves the tables (commands, directives, version); builds
  // run in the worker's.
  const [source] = await Promise.all([fetchExample(INITIAL_EXAMPLE), initCore()]);
  els.version.textContent = `core ${coreVersion()}`;

  const view = new PlantView(els.viewport);
  const options = (): BuildOptions => ({
    iterations: wholeNumber(els.iterations),
    seed: wholeNumber(els.seed),
    sides: Number(els.sides.value),
    smoothAll: els.smoothAll.checked,
  });
  let editor: GrammarEditor | undefined;
  // The context-sensitivity view: the cursor on a production lights up what it wrote.
  const contexts = new ContextView(
    { panel: els.stringPanel, summary: els.explainSummary, byProduction: els.byProduction, legend: els.productionLegend },
    view,
    () => editor,
  );
  const preview = new LivePreview({
    client: new BuildClient(createBuildWorker),
    view,
    status: els.status,
    staleBadge: els.staleBadge,
    text: () => editor?.text() ?? source,
    options,
    diagnosticsChanged: () => editor?.refreshDiagnostics(),
    adopt: (result) => {
      contexts.setBuild(result.build, result.inspector, result.source);
      if (editor) contexts.cursorAt(editor.view.state.selection.main.head);
    },
  });
  const sliders = new SliderPanel(els.sliders, els.constantsCount, els.constantsEmpty, {
    replaceRange: (from, to, insert, history) => editor?.replaceRange(from, to, insert, history),
  });
  editor = createGrammarEditor({
    parent: els.editor,
    doc: source,
    onChange: (text) => {
      sliders.update(text);
      preview.rebuild();
    },
    diagnose: (text) => preview.feed.diagnose(text),
    commands: turtleCommands(),
    directives: grammarDirectives(),
    onCursor: (pos) => contexts.cursorAt(pos),
  });
  const grammarEditor = editor;
  sliders.update(source);

  // Iterations: the box, step −/+, play / pause.
  const grammarIterations = () => preview.lastResult?.build.grammarIterations ?? 0;
  const playback = new Playback(
    {
      shown: () => wholeNumber(els.iterations) ?? grammarIterations(),
      grammarIterations,
      show: (n) => {
        els.iterations.value = n === undefined ? '' : String(n);
        preview.rebuild();
      },
    },
    { maxIterations: Number(els.iterations.max) },
  );
  playback.onPlayingChange((playing) => {
    els.play.setAttribute('aria-pressed', String(playing));
    els.play.textContent = playing ? 'Pause' : 'Play';
  });
  els.iterations.addEventListener('input', () => {
    playback.pause();
    preview.rebuild();
  });
  els.stepBack.addEventListener('click', () => playback.stepBy(-1));
  els.stepForward.addEventListener('click', () => playback.stepBy(+1));
  els.play.addEventListener('click', () => playback.toggle());

  // Seed.
  const reroll = () => {
    els.seed.value = String(crypto.getRandomValues(new Uint32Array(1))[0]);
    preview.rebuild();
  };
  els.seed.addEventListener('input', () => preview.rebuild());
  els.reroll.addEventListener('click', reroll);

  // View options and tools.
  const showProjection = () => els.projection.setAttribute('aria-pressed', String(view.projection === 'orthographic'));
  const toggleProjection = () => {
    view.setProjectionMode(view.projection === 'orthographic' ? 'perspective' : 'orthographic');
    showProjection();
  };
  els.sides.addEventListener('change', () => preview.rebuild());
  els.smoothAll.addEventListener('change', () => preview.rebuild());
  els.frame.addEventListener('click', () => view.frame());
  els.projection.addEventListener('click', toggleProjection);
  els.grid.addEventListener('click', () => {
    els.grid.setAttribute('aria-pressed', String(!pressed(els.grid)));
    view.setGridVisible(pressed(els.grid));
  });
  els.lighting.addEventListener('click', () => {
    els.lighting.setAttribute('aria-pressed', String(!pressed(els.lighting)));
    view.setLighting(pressed(els.lighting));
  });

  preview.onDelivered((result) => {
    els.iterations.placeholder = String(result.build.grammarIterations);
    if (result.build.ok) hook.lastStats = result.build.stats;
    showProjection();
    playback.shownBuild();
  });
  let sketchPending = false;
  preview.onSketched(() => (sketchPending = true));
  view.onRender(() => {
    hook.rendered = { generation: preview.generation, at: performance.now() };
    if (sketchPending) hook.sketched = hook.rendered.at;
    sketchPending = false;
  });

  // The gallery. The text the user started from (an example, unchanged) is `pristine`; anything
  // else is theirs, and opening an example asks first (and stays undoable in the editor).
  let pristine = source;
  let currentFile = INITIAL_EXAMPLE;
  const openExample = async (entry: GalleryEntry) => {
    const text = await fetchExample(entry.file);
    const mine = grammarEditor.text();
    if (mine !== pristine && mine !== text && !(await askToReplace(els.confirm, els.confirmExample, entry.title))) {
      grammarEditor.view.focus();
      return;
    }
    playback.pause();
    els.iterations.value = '';
    els.seed.value = '';
    sliders.reset();
    view.setProjectionMode('auto');
    view.frameNextPlant();
    pristine = text;
    currentFile = entry.file;
    grammarEditor.replaceText(text);
    grammarEditor.view.focus();
    preview.rebuild(true);
  };
  const gallery = new GalleryDialog(
    els.gallery,
    els.galleryList,
    new GalleryThumbnails(fetchExample),
    (entry) => void openExample(entry).catch((error: unknown) => console.error('Could not open the example:', error)),
    () => currentFile,
  );
  const openGallery = () => void gallery.open().catch((error: unknown) => console.error('Could not open the gallery:', error));
  els.openGallery.addEventListener('click', openGallery);
  window.addEventListener('beforeunload', (event) => {
    if (grammarEditor.text() !== pristine) event.preventDefault(); // the browser asks before leaving
  });

  // Downloads: the plant on screen (the last good build's text and options), written by the page's
  // own core instance, as a model file or a PNG of the view.
  installDownloads(els, view, () => preview.lastGood && { source: preview.lastGood.source, options: preview.lastGood.options });

  // Keyboard: shortcuts anywhere, their help, the splitter.
  const actions: Record<ShortcutAction, () => void> = {
    stepBack: () => playback.stepBy(-1),
    stepForward: () => playback.stepBy(+1),
    playPause: () => playback.toggle(),
    reroll,
    gallery: openGallery,
    frame: () => view.frame(),
    projection: toggleProjection,
  };
  installShortcuts(window, (action) => actions[action]());
  renderShortcutHelp(els.shortcutList);
  attachSplitter(els.splitter, els.studio);

  hook.preview = preview;
  const firstBuild = new Promise<void>((resolve) => {
    const stop = preview.onDelivered(() => {
      stop();
      resolve();
    });
  });
  preview.rebuild();
  await firstBuild;
}

/**
 * The Download menu: a button per model format, written in an export worker with its progress and
 * a Cancel button on the status line (the page stays responsive), and the PNG of the view. One
 * download at a time: the menu is disabled meanwhile.
 */
function installDownloads(
  els: StudioElements,
  view: PlantView,
  shown: () => { source: string; options: BuildOptions } | undefined,
): void {
  const menuButtons = (): HTMLButtonElement[] => [...els.downloads.querySelectorAll('button')];
  const busy = (on: boolean) => {
    menuButtons().forEach((b) => (b.disabled = on));
    els.exportProgress.hidden = !on;
    els.exportCancel.hidden = !on;
    if (on) els.exportProgress.removeAttribute('value'); // indeterminate until the first stage
  };
  let cancel: (() => void) | undefined;
  els.exportCancel.addEventListener('click', () => cancel?.());
  /** Runs one download; `save` returns the status text, or null when cancelled. */
  const download = async (what: string, save: () => Promise<string | null>): Promise<void> => {
    if (menuButtons().some((b) => b.disabled)) return;
    els.downloads.open = false;
    busy(true);
    showExportStatus(els.exportStatus, 'busy', `Exporting ${what}…`);
    try {
      const done = await save();
      showExportStatus(els.exportStatus, done === null ? 'cancelled' : 'done', done ?? `Export of ${what} cancelled`);
    } catch (error) {
      console.error(`Export of ${what} failed:`, error);
      showExportStatus(els.exportStatus, 'error', `Export of ${what} failed: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      cancel = undefined;
      busy(false);
    }
  };
  const downloadModel = (format: ModelFormat, label: string): Promise<void> =>
    download(label, async () => {
      const plant = shown();
      if (!plant) throw new Error('no plant yet');
      const running = runExport(createExportWorker, { source: plant.source, format, options: plant.options }, (progress) => {
        els.exportProgress.max = progress.count;
        els.exportProgress.value = progress.index + 1;
        showExportStatus(els.exportStatus, 'busy', describeProgress(label, progress));
      });
      cancel = running.cancel;
      const outcome = await running.done;
      if (outcome.kind === 'cancelled') return null;
      if (outcome.kind === 'failed') {
        throw new Error(outcome.crashed ? `the core crashed (a bug): ${outcome.message}` : outcome.message);
      }
      saveFile(outcome.file.bytes, outcome.file.fileName, outcome.file.mimeType);
      return `Saved ${outcome.file.fileName} · ${fileSize(outcome.file.bytes.length)}`;
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
    // The picture is drawn by the page's WebGL context: it cannot move to a worker (it is one draw).
    void download(`PNG ${size.width} × ${size.height}`, async () => {
      await afterPaint(); // the status shows before the draw
      const png = await view.snapshot(size.width, size.height);
      saveFile(png, 'plant.png', 'image/png');
      return `Saved plant.png · ${size.width} × ${size.height} · ${fileSize(png.size)}`;
    });
  });
}

/** Shows the state of the last download next to the build status. */
function showExportStatus(element: HTMLElement, state: 'busy' | 'done' | 'cancelled' | 'error', text: string): void {
  element.textContent = text;
  element.dataset.state = state;
}

const els = studioElements();
const hook: StudioTestHook = { ready: Promise.resolve(), lastStats: null, rendered: null, sketched: null };
hook.ready = startStudio(els, hook);
hook.ready.catch((error: unknown) => {
  console.error('Meristem could not start:', error);
  showStatus(els.status, { state: 'crashed', text: `Could not start: ${String(error)}` });
});
window.__meristem = hook;
