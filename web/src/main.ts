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
  type EditsDocument,
  type ExportOptions,
  type ModelFormat,
  type PlantStats,
} from './core';
import { createGrammarEditor, type GrammarEditor } from './editor';
import { decodeState, encodeState, hasSharedState, type SharedState } from './share/codec';
import { GrammarStore, titleOf, type KeyValueStorage } from './share/storage';
import { PlantView, type ProjectionMode } from './view';
import {
  BranchEditSession,
  BuildClient,
  ContextView,
  GalleryDialog,
  GalleryThumbnails,
  GrowthPanel,
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
  LibraryDialog,
  linkWithFragment,
  lsysFileName,
  Notice,
  openGrammarBytes,
  dialectName,
  pictureSize,
  runExport,
  ShareDialog,
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
  /** The derived string's fingerprint of the plant on screen (share links must reproduce it). */
  derivedHash?: () => Promise<string>;
  /** Where the camera in use stands. */
  cameraPose?: () => { position: number[]; target: number[]; zoom: number };
  /** Branch editing: the selected branch's handles on the page, its path, and the edits. */
  branches?: {
    handlesOnPage: () => { x: number; y: number }[];
    selectedPath: () => number[] | null;
    document: () => unknown;
  };
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
    textures: byId('textures', HTMLButtonElement),
    staleBadge: byId('stale-badge', HTMLElement),
    sliders: byId('sliders', HTMLElement),
    constantsCount: byId('constants-count', HTMLElement),
    constantsEmpty: byId('constants-empty', HTMLElement),
    growthRows: byId('growth-rows', HTMLElement),
    growthCount: byId('growth-count', HTMLElement),
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
    branchEditing: {
      toggle: byId('edit-branches', HTMLButtonElement),
      undo: byId('edit-undo', HTMLButtonElement),
      redo: byId('edit-redo', HTMLButtonElement),
      reset: byId('edit-reset', HTMLButtonElement),
    },
    fileMenu: byId('file-menu', HTMLDetailsElement),
    openFile: byId('open-file', HTMLButtonElement),
    saveFile: byId('save-file', HTMLButtonElement),
    openLibrary: byId('open-library', HTMLButtonElement),
    fileInput: byId('file-input', HTMLInputElement),
    share: byId('share', HTMLButtonElement),
    notice: {
      root: byId('notice', HTMLElement),
      text: byId('notice-text', HTMLElement),
      list: byId('notice-list', HTMLElement),
      close: byId('notice-close', HTMLButtonElement),
    },
    shareDialog: {
      dialog: byId('share-dialog', HTMLDialogElement),
      link: byId('share-link', HTMLInputElement),
      copy: byId('share-copy', HTMLButtonElement),
      status: byId('share-status', HTMLElement),
      size: byId('share-size', HTMLElement),
    },
    library: {
      dialog: byId('library', HTMLDialogElement),
      name: byId('library-name', HTMLInputElement),
      save: byId('library-save', HTMLButtonElement),
      list: byId('library-list', HTMLElement),
      empty: byId('library-empty', HTMLElement),
      status: byId('library-status', HTMLElement),
    },
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
  const notice = new Notice(els.notice);
  const store = new GrammarStore(browserStorage());
  // The page's own core instance serves the tables (commands, directives, version) and the
  // importers of opened files; builds run in the worker's.
  const [start] = await Promise.all([startingText(store, notice), initCore()]);
  const source = start.text;
  els.version.textContent = `core ${coreVersion()}`;

  const view = new PlantView(els.viewport);
  const options = (): BuildOptions => ({
    iterations: wholeNumber(els.iterations),
    seed: wholeNumber(els.seed),
    sides: Number(els.sides.value),
    smoothAll: els.smoothAll.checked,
  });
  let editor: GrammarEditor | undefined;
  /** Set once autosave is ready (below); the editor calls it on every change. */
  let autosaveOnChange = () => {};
  /** Set once branch editing is ready (below): the edits for downloads and links, and a link's. */
  let editsForExport: () => EditsDocument | undefined = () => undefined;
  let editsForLink: () => EditsDocument | undefined = () => undefined;
  let restoreEdits: (doc: EditsDocument) => void = () => {};
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
  const growth = new GrowthPanel(els.growthRows, els.growthCount, {
    text: () => editor?.text() ?? source,
    replaceRange: (from, to, insert) => editor?.replaceRange(from, to, insert),
  });
  editor = createGrammarEditor({
    parent: els.editor,
    doc: source,
    onChange: (text) => {
      sliders.update(text);
      growth.update(text);
      preview.rebuild();
      autosaveOnChange();
    },
    diagnose: (text) => preview.feed.diagnose(text),
    commands: turtleCommands(),
    directives: grammarDirectives(),
    onCursor: (pos) => contexts.cursorAt(pos),
  });
  const grammarEditor = editor;
  sliders.update(source);
  growth.update(source);

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
  els.textures.addEventListener('click', () => {
    els.textures.setAttribute('aria-pressed', String(!pressed(els.textures)));
    view.setTextures(pressed(els.textures));
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

  // Opening another text (an example, a file, a saved grammar, a shared link). The text the user
  // started from, if it was an example left unchanged, is `pristine`; anything else is theirs, and
  // opening something else asks first (and stays undoable in the editor).
  let pristine: string | undefined = start.from === 'example' ? source : undefined;
  let currentFile = start.from === 'example' ? INITIAL_EXAMPLE : '';
  const replaceText = async (text: string, title: string, file = ''): Promise<boolean> => {
    const mine = grammarEditor.text();
    if (mine !== pristine && mine !== text && !(await askToReplace(els.confirm, els.confirmExample, title))) {
      grammarEditor.view.focus();
      return false;
    }
    playback.pause();
    els.iterations.value = '';
    els.seed.value = '';
    sliders.reset();
    view.setProjectionMode('auto');
    view.frameNextPlant();
    pristine = file.endsWith('.lsys') && currentIsExample(file) ? text : undefined;
    currentFile = file;
    grammarEditor.replaceText(text);
    grammarEditor.view.focus();
    preview.rebuild(true);
    return true;
  };
  const currentIsExample = (file: string) => file !== '' && !file.includes('/');
  const openExample = async (entry: GalleryEntry) => {
    const text = await fetchExample(entry.file);
    if (await replaceText(text, entry.title, entry.file)) notice.hide();
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

  // Autosave: every change, shortly after typing stops, and when the page goes away.
  let autosaveTimer: ReturnType<typeof setTimeout> | undefined;
  let autosaveFailed = false;
  const autosaveNow = () => {
    clearTimeout(autosaveTimer);
    autosaveTimer = undefined;
    const ok = store.autosave(grammarEditor.text());
    if (!ok && !autosaveFailed) notice.show('error', 'Your text cannot be saved in this browser (its storage is full or switched off): save it as a file or share it.');
    autosaveFailed = !ok;
  };
  autosaveOnChange = () => {
    clearTimeout(autosaveTimer);
    autosaveTimer = setTimeout(autosaveNow, 300);
  };
  window.addEventListener('pagehide', () => autosaveTimer !== undefined && autosaveNow());
  document.addEventListener('visibilitychange', () => document.visibilityState === 'hidden' && autosaveTimer !== undefined && autosaveNow());
  if (start.from === 'link') autosaveNow(); // the link's text is now the work in progress

  // Files: open (picker, Ctrl+O, drag and drop; other dialects imported with their notes) and save.
  const openFile = async (file: File) => {
    const opened = openGrammarBytes(file.name, new Uint8Array(await file.arrayBuffer()));
    if (!opened.ok) {
      notice.show('error', `Could not open ${file.name}: ${opened.error}.`);
      return;
    }
    if (!(await replaceText(opened.text, file.name, `file/${file.name}`))) return;
    if (opened.dialect) {
      const what = `Imported ${file.name} from ${dialectName(opened.dialect)}`;
      notice.show(
        'info',
        opened.notes.length === 0 ? `${what}: everything was translated.` : `${what}. Not translated, or only approximately (${opened.notes.length}):`,
        opened.notes,
      );
    } else if (opened.notes.length > 0) notice.show('info', `Opened ${file.name}.`, opened.notes);
    else notice.hide();
  };
  const pickFile = () => {
    els.fileMenu.open = false;
    els.fileInput.value = '';
    els.fileInput.click();
  };
  els.openFile.addEventListener('click', pickFile);
  els.fileInput.addEventListener('change', () => {
    const file = els.fileInput.files?.[0];
    if (file) void openFile(file).catch((error: unknown) => notice.show('error', `Could not open ${file.name}: ${String(error)}`));
  });
  const saveAsFile = () => {
    els.fileMenu.open = false;
    const text = grammarEditor.text();
    saveFile(new TextEncoder().encode(text), lsysFileName(titleOf(text)), 'text/plain');
  };
  els.saveFile.addEventListener('click', saveAsFile);
  installDrop(els.studio, (file) => void openFile(file).catch((error: unknown) => notice.show('error', `Could not open ${file.name}: ${String(error)}`)));
  window.addEventListener(
    'keydown',
    (event) => {
      if (!(event.ctrlKey || event.metaKey) || event.altKey || event.shiftKey || event.repeat) return;
      if (event.code === 'KeyO') pickFile();
      else if (event.code === 'KeyS') saveAsFile();
      else return;
      event.preventDefault();
      event.stopPropagation();
    },
    { capture: true },
  );
  closeLikeAMenu(els.fileMenu);

  // My grammars.
  const library = new LibraryDialog(els.library, store, {
    text: () => grammarEditor.text(),
    open: (entry) => void replaceText(entry.text, entry.name, `saved/${entry.id}`).then((done) => done && notice.hide()),
  });
  els.openLibrary.addEventListener('click', () => {
    els.fileMenu.open = false;
    library.open();
  });

  // Share: the whole state in the link's fragment.
  const shareDialog = new ShareDialog(els.shareDialog);
  const sharedState = (): SharedState => {
    const state: SharedState = { text: grammarEditor.text() };
    const iterations = wholeNumber(els.iterations);
    const seed = wholeNumber(els.seed);
    if (iterations !== undefined) state.iterations = iterations;
    if (seed !== undefined) state.seed = seed;
    const values = sliders.values();
    if (Object.keys(values).length > 0) state.sliders = values;
    state.view = {
      sides: Number(els.sides.value),
      smoothAll: els.smoothAll.checked,
      byProduction: els.byProduction.checked,
      grid: pressed(els.grid),
      lighting: pressed(els.lighting),
      projection: view.projectionMode,
    };
    state.camera = view.cameraPose();
    const edits = editsForLink();
    if (edits) state.edits = edits;
    return state;
  };
  els.share.addEventListener('click', () => {
    void encodeState(sharedState())
      .then((fragment) => shareDialog.open(linkWithFragment(location, fragment)))
      .catch((error: unknown) => notice.show('error', `Could not make a link: ${String(error)}`));
  });
  // A link pasted into this tab's address bar.
  window.addEventListener('hashchange', () => {
    if (!hasSharedState(location.hash)) return;
    if (autosaveTimer !== undefined) autosaveNow(); // the text now is what the link may replace
    void openLink(location.hash, store, notice).then((opened) => {
      history.replaceState(null, '', linkWithFragment(location, ''));
      if (!opened) return;
      void replaceText(opened.state.text, 'the shared link', 'link').then((done) => {
        if (!done) return;
        applyLinkOptions(opened.state);
        if (opened.state.edits) restoreEdits(opened.state.edits);
        if (opened.state.camera) cameraToApply = opened.state.camera;
        preview.rebuild(true);
      });
    });
  });
  // The link's view options, before its first build (the camera after it: it needs the plant).
  const applyLinkOptions = (state: SharedState) => {
    els.iterations.value = state.iterations === undefined ? '' : String(state.iterations);
    els.seed.value = state.seed === undefined ? '' : String(state.seed);
    const v = state.view ?? {};
    if (v.sides !== undefined && [...els.sides.options].some((o) => o.value === String(v.sides))) els.sides.value = String(v.sides);
    if (v.smoothAll !== undefined) els.smoothAll.checked = v.smoothAll;
    if (v.grid !== undefined && v.grid !== pressed(els.grid)) els.grid.click();
    if (v.lighting !== undefined && v.lighting !== pressed(els.lighting)) els.lighting.click();
    if (v.byProduction !== undefined && v.byProduction !== els.byProduction.checked) els.byProduction.click();
    if (v.projection !== undefined) view.setProjectionMode(v.projection as ProjectionMode);
    showProjection();
  };
  let cameraToApply: SharedState['camera'] = undefined;
  preview.onDelivered((result) => {
    if (!cameraToApply || !result.build.ok) return;
    view.setCameraPose({ zoom: 1, ...cameraToApply });
    cameraToApply = undefined;
  });
  if (start.from === 'link' && start.state) {
    applyLinkOptions(start.state);
    cameraToApply = start.state.camera;
  }
  // Branch editing (issue 8): the plant on screen with its edits, handles in Edit mode.
  const branchEdits = new BranchEditSession(els.branchEditing, view, {
    shown: () => {
      const good = preview.lastGood;
      return good && { source: good.source, options: good.options, segments: good.build.stats.segments, flat: good.build.flat };
    },
    tell: (kind, message, items) => (message === null ? notice.hide() : notice.show(kind, message, items)),
    modeChanged: (on) => {
      contexts.picking = !on;
      if (on) contexts.pickModule(null);
    },
  });
  preview.onDelivered((result) => {
    if (result.build.ok) branchEdits.plantShown();
  });
  window.addEventListener('keydown', (event) => {
    // Ctrl+Z over the view undoes branch edits; in the editor and fields it stays theirs.
    const inText = (event.target as HTMLElement | null)?.closest('input, textarea, select, .cm-editor, dialog');
    if (!inText && (branchEdits.active || branchEdits.document()) && branchEdits.handleKey(event)) event.preventDefault();
  });
  if (start.from === 'link' && start.state?.edits) branchEdits.restore(start.state.edits);
  editsForExport = () => branchEdits.document();
  editsForLink = () => branchEdits.document();
  restoreEdits = (doc) => branchEdits.restore(doc);
  hook.branches = {
    handlesOnPage: () => branchEdits.handlesOnPage(),
    selectedPath: () => branchEdits.selectedPath(),
    document: () => branchEdits.document() ?? null,
  };
  hook.derivedHash = () => preview.lastGood?.inspector.derivedHash() ?? Promise.resolve('');
  hook.cameraPose = () => view.cameraPose();

  // Downloads: the plant on screen (the last good build's text and options), written by the page's
  // own core instance, as a model file or a PNG of the view.
  installDownloads(els, view, () => preview.lastGood && { source: preview.lastGood.source, options: { ...preview.lastGood.options, edits: editsForExport() } });

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
  shown: () => { source: string; options: ExportOptions } | undefined,
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
  closeLikeAMenu(els.downloads);
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

/** A `<details>` menu closes like a menu: on a click elsewhere and on Escape. */
function closeLikeAMenu(menu: HTMLDetailsElement): void {
  document.addEventListener('pointerdown', (event) => {
    if (menu.open && !menu.contains(event.target as Node)) menu.open = false;
  });
  menu.addEventListener('keydown', (event) => {
    if (event.key !== 'Escape' || !menu.open) return;
    menu.open = false;
    menu.querySelector('summary')?.focus();
  });
}

/** Files dropped anywhere on `target` open with `open` (before the editor can insert them as text). */
function installDrop(target: HTMLElement, open: (file: File) => void): void {
  const hasFiles = (event: DragEvent) => event.dataTransfer?.types.includes('Files') ?? false;
  let depth = 0;
  const leave = () => {
    depth = 0;
    target.classList.remove('drop-target');
  };
  target.addEventListener('dragenter', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    depth++;
    target.classList.add('drop-target');
  });
  target.addEventListener('dragover', (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    event.dataTransfer!.dropEffect = 'copy';
  });
  target.addEventListener('dragleave', (event) => {
    if (!hasFiles(event)) return;
    depth = Math.max(0, depth - 1);
    if (depth === 0) leave();
  });
  target.addEventListener(
    'drop',
    (event) => {
      if (!hasFiles(event)) return;
      event.preventDefault();
      event.stopPropagation();
      leave();
      const file = event.dataTransfer?.files[0];
      if (file) open(file);
    },
    { capture: true },
  );
}

/** `localStorage`, or nothing where the browser refuses it (private modes, sandboxed frames). */
function browserStorage(): KeyValueStorage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}

/** Where the editor's first text comes from. */
interface StartingText {
  text: string;
  from: 'link' | 'autosave' | 'example';
  /** The link's state, when it came from one. */
  state?: SharedState;
}

/**
 * The text the studio opens with: a shared link's (its fragment is then removed from the address,
 * so a reload restores the user's later edits), else the autosaved text, else the first example.
 * A link that cannot be opened is said in the notice, and the studio opens as if it had none.
 */
async function startingText(store: GrammarStore, notice: Notice): Promise<StartingText> {
  if (hasSharedState(location.hash)) {
    const opened = await openLink(location.hash, store, notice);
    history.replaceState(null, '', linkWithFragment(location, ''));
    if (opened) return { text: opened.state.text, from: 'link', state: opened.state };
  }
  const saved = store.restore();
  if (saved && saved.text.trim() !== '') return { text: saved.text, from: 'autosave' };
  return { text: await fetchExample(INITIAL_EXAMPLE), from: 'example' };
}

/**
 * Decodes a shared link. A rejected one is said in the notice (and nothing changes). An accepted
 * one first keeps the autosaved work in My grammars, unless it is the link's text or saved there
 * already: opening a link never loses a user's text.
 */
async function openLink(fragment: string, store: GrammarStore, notice: Notice): Promise<{ state: SharedState } | null> {
  const decoded = await decodeState(fragment);
  if (!decoded.ok) {
    notice.show('error', `This link could not be opened: ${decoded.error}. The studio opened as usual.`);
    return null;
  }
  const previous = store.restore();
  if (previous && previous.text.trim() !== '' && previous.text !== decoded.state.text && !store.list().some((g) => g.text === previous.text)) {
    const kept = store.save(`Before a shared link: ${titleOf(previous.text)}`, previous.text);
    notice.show(
      'info',
      kept
        ? `Opened a shared link. Your previous text is kept in My grammars as “${kept.name}”.`
        : 'Opened a shared link. Your previous text could not be kept (this browser’s storage is full): Ctrl+Z in the editor does not reach it.',
    );
  } else notice.hide();
  return { state: decoded.state };
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
