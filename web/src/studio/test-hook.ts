// What the page exposes for its end-to-end tests and benchmarks, as `window.__meristem` (nothing
// else is global). The browser tests read this shape: change it only with them.
import type { PlantStats } from '../core';
import type { PlantView } from '../view';
import type { BranchEdits } from './branches';
import type { LivePreview } from './preview';
import type { SurfaceEditing } from './surfaces';

/** The studio as its tests see it. */
export interface StudioTestHook {
  /** Settles when the first build is on screen (rejects if the studio could not start). */
  ready: Promise<void>;
  /**
   * Set by a test: the time an import may take, in ms, instead of the studio's 10 s. The importers
   * now translate any file the studio opens (up to 1 MB) in a few seconds, so the test of the
   * limit lowers it rather than look for a slower file.
   */
  importTimeLimitMs?: number;
  /** Stats of the plant on screen. */
  lastStats: PlantStats | null;
  /** `Date.now()` when the first plant (a build with segments) arrived: the first-load test's end. */
  firstPlantAt?: number;
  /** The live preview (last builds, delivery events). */
  preview?: LivePreview;
  /**
   * The last frame that drew the plant last given to the view: the delivered-build counter at the
   * time, and `performance.now()` (frames drawn while a big plant uploads show the one before).
   */
  rendered: { generation: number; at: number } | null;
  /** A big plant is on its way to the GPU: the plant on screen is the one before. */
  uploading?: () => boolean;
  /** `performance.now()` at the end of the first frame that drew the last sketch (a big plant as lines). */
  sketched: number | null;
  /** The derived string's fingerprint of the plant on screen (share links must reproduce it). */
  derivedHash?: () => Promise<string>;
  /** The growth time the view shows (null: the whole plant) and N, once the plant carries growth arrays. */
  growth?: () => { t: number | null; span: number | null };
  /** Where the camera in use stands. */
  cameraPose?: () => { position: number[]; target: number[]; zoom: number };
  /** Branch editing: the selected branch's handles on the page, its path, and the edits. */
  branches?: {
    handlesOnPage: () => { x: number; y: number }[];
    selectedPath: () => number[] | null;
    document: () => unknown;
  };
  /** The surface editor: net point k of the surface it shows, on the page (null when closed). */
  surfacePointOnPage?: (k: number) => { x: number; y: number } | null;
}

declare global {
  interface Window {
    __meristem?: StudioTestHook;
  }
}

/** The hook of a studio that shows nothing yet. */
export function emptyTestHook(): StudioTestHook {
  return { ready: Promise.resolve(), lastStats: null, rendered: null, sketched: null };
}

/** The pieces the hook reports on. */
export interface TestedStudio {
  preview: LivePreview;
  view: PlantView;
  branchEdits: BranchEdits;
  surfaces: SurfaceEditing;
}

/** Fills `hook` from the studio's pieces and keeps it current as builds arrive and frames are drawn. */
export function connectTestHook(hook: StudioTestHook, { preview, view, branchEdits, surfaces }: TestedStudio): void {
  preview.onDelivered((result) => {
    if (result.build.ok) hook.lastStats = result.build.stats;
    if (result.build.ok && result.build.stats.segments > 0) hook.firstPlantAt ??= Date.now();
  });
  let sketchPending = false;
  preview.onSketched(() => (sketchPending = true));
  view.onRender(() => {
    const at = performance.now();
    if (sketchPending) hook.sketched = at;
    sketchPending = false;
    if (!view.uploading) hook.rendered = { generation: preview.generation, at };
  });
  hook.uploading = () => view.uploading;
  hook.branches = {
    handlesOnPage: () => branchEdits.handlesOnPage(),
    selectedPath: () => branchEdits.selectedPath(),
    document: () => branchEdits.document() ?? null,
  };
  hook.surfacePointOnPage = (k) => surfaces.pointOnPage(k);
  hook.derivedHash = () => preview.lastGood?.inspector.derivedHash() ?? Promise.resolve('');
  hook.cameraPose = () => view.cameraPose();
  hook.growth = () => ({ t: view.growthTime, span: view.growthSpan() });
  hook.preview = preview;
}
