// The studio page's composition root: creates the parts (./studio's areas, ./editor, ./view),
// wires each area to them by one call, then starts: the first plant, then what it did not need.
// See index.html for the page, ARCHITECTURE.md for the areas.
import './style.css';
import { BuildClient, createBuildWorker } from './build';
import { CORE_VERSION, coreModule, loadVocabulary } from './core';
import { createLazyGrammarEditor } from './editor/grammar-text';
import { wireBranchEditing } from './studio/branches';
import { LazySliderPanel } from './plant-controls';
import { sidesChoices, ViewOptions, VocabularyPanels, wireKeyboard, wireLayout, wireViewControls } from './studio/controls';
import { createInspector, DerivationControls } from './studio/derivation';
import { loadDownloads } from './studio/downloads';
import { Autosave, browserKeeping, createOpening, INITIAL_EXAMPLE, wireFiles } from './studio/files';
import { installLearnPanel } from './studio/learn';
import { startingText, wireLinks } from './studio/links';
import { delay, lazyHelp, loadAppUpdates, nextFrame, Notice, studioElements, type StudioElements } from './studio/page';
import type { StudioParts } from './studio/parts';
import { connectTestHook, emptyTestHook, type StudioTestHook } from './studio/test-hook';
import { createLivePreview, DiagnosticsFeed, showStatus } from './studio/preview';
import { wireSurfaceEditingLater } from './studio/surfaces';
import { LazyTimeline, wireTimeline } from './studio/timeline';
import { PlantView } from './view';

/** `firstLoadDone` is called when what the first plant downloads has arrived (the rest may load then). */
async function startStudio(els: StudioElements, hook: StudioTestHook, firstLoadDone: () => void): Promise<void> {
  showStatus(els.status, { state: 'loading', text: 'Loading…' });
  const notice = new Notice(els.notice);
  const keeping = browserKeeping(); // the user's work, kept before anything replaces it
  // The page compiles the core and hands it to the build worker (builds run there, imports of
  // opened files in an import worker's); the page has no instance of it. The build worker starts
  // at once, and the studio is set up (the view's WebGL context, the panels) while the core still
  // downloads: the first build is asked for once it has arrived (issue 22).
  const buildClient = new BuildClient(createBuildWorker);
  buildClient.warmUp();
  const coreStarted = coreModule();
  coreStarted.catch(() => undefined); // awaited below, before the first build: a failure is reported there
  const start = await startingText({ ...keeping, notice, cannotKeep: els.cannotKeep }, INITIAL_EXAMPLE);

  // The parts, each after those it needs.
  const view = new PlantView(els.viewport);
  void view.compileShaders(); // while the core downloads: its first frame then compiles nothing
  const viewOptions = new ViewOptions(sidesChoices(els.viewTools.sides));
  viewOptions.applyShared(start.state?.view); // a link's, before anything follows the options
  const derivation = new DerivationControls(els.derivation, notice);
  const autosave = new Autosave(keeping.store, keeping.kept, notice);
  const help = lazyHelp(els.help);
  const feed = new DiagnosticsFeed();
  // The grammar in a plain textarea until CodeMirror arrives, after the first plant (below).
  const editor = createLazyGrammarEditor(
    { parent: els.editor, doc: start.text, diagnose: (text) => feed.diagnose(text), vocabulary: loadVocabulary, openReference: (anchor) => help.open(anchor) },
    () => import('./editor/grammar-editor'),
  );
  const sliders = new LazySliderPanel([els.sliders, els.constantsCount, els.constantsEmpty, editor]); // with the vocabulary
  const inspector = createInspector(els, view, editor, viewOptions);
  const timeline = new LazyTimeline(els.timeline);
  const preview = createLivePreview({ els, client: buildClient, feed, view, editor, ...inspector, derivation, viewOptions, notice, timeline });
  const opening = createOpening({ els, notice, keeper: keeping.keeper, editor, derivation, sliders, viewOptions, view, preview, timeline }, start);
  const parts: StudioParts = { els, notice, ...keeping, view, viewOptions, derivation, help, editor, sliders, ...inspector, preview, opening, timeline };

  // The keystroke route: each change carries its text to the panels, the build and the autosave.
  const panels = new VocabularyPanels(parts); // the sliders, the Growth panel: once the vocabulary has arrived
  editor.onChange((text) => {
    panels.read(text);
    preview.rebuild({ text });
    autosave.changed(text);
  });
  editor.onCursor((pos) => inspector.contexts.cursorAt(pos));

  // Each area, wired to the parts.
  const layout = wireLayout(parts);
  const controls = wireViewControls(parts);
  wireTimeline(parts);
  const dialogs = wireFiles(parts);
  installLearnPanel({ preview, open: (text, title, key) => opening.replace(text, title, key), text: () => editor.text() }); // lessons (issue 17), loaded on first use
  if (start.from === 'link') void autosave.save(start.text); // the link's text is now the work in progress
  const branchEdits = wireBranchEditing(parts, controls);
  const links = wireLinks(parts, branchEdits, start);
  connectTestHook(hook, { preview, view, branchEdits, surfaces: wireSurfaceEditingLater(parts) }); // (the surface editor: view tools, text)
  wireKeyboard(parts, { ...controls, layout, gallery: dialogs.gallery });

  // Start: the first plant, as soon as the core has arrived.
  await coreStarted;
  els.version.textContent = `core ${CORE_VERSION}`;
  const firstBuild = preview.nextDelivery();
  const underWay = preview.nextProgress();
  preview.rebuild();
  // The editor (issue 22, the first load) loads after the first plant's frame; or, when that build
  // takes long (or is stopped), a second after the worker started it: every download of the first
  // plant is done by then. The studio is ready with the plant and the editor.
  await Promise.race([firstBuild, underWay.then(() => delay(1000))]);
  await nextFrame();
  firstLoadDone();
  const vocabularyRead = panels.load();
  void Promise.all([inspector.contexts.load(), timeline.preload()]); // the String tab, the bar under the view
  const downloadsInstalled = loadDownloads(parts, branchEdits);
  // Then the mouse moves the camera (view.controlsReady: the OrbitControls load after the first plant's frame).
  await Promise.all([firstBuild, vocabularyRead, editor.loaded, view.controlsReady, downloadsInstalled]);
  // The first load is done: the build worker loads the studio core (crate/pkg, built for speed:
  // a big plant's tubes in about half the time) for the builds after it.
  buildClient.useStudioCore();
  // The dialogs and branch editing load now, in the background, so that the first click opens one
  // at once (a failure here is tried again by that click).
  await Promise.all([dialogs.gallery.preload(), dialogs.library.preload(), links.preload(), help.preload(), branchEdits.preload()]);
}

const els = studioElements();
const hook = emptyTestHook();
// Offline use, and "a new version is ready" (issue 22): registered once the first plant's downloads
// are done (or the studio could not start), so the service worker's precaching (the whole site, a
// few MB) never competes with them.
const firstLoad = new Promise<void>((firstLoadDone) => {
  hook.ready = startStudio(els, hook, firstLoadDone);
  hook.ready.catch((error: unknown) => {
    console.error('Meristem could not start:', error);
    showStatus(els.status, { state: 'crashed', text: `Could not start: ${String(error)}` });
  });
  hook.ready.catch(() => firstLoadDone());
});
window.__meristem = hook;
void firstLoad.then(loadAppUpdates);
