// The controls around the view, wired to the studio's parts: the derivation's and the view's
// options (a change of either asks for a build, when it meshes), the view's tools, the view
// following the plant, Stages; the layout for the room; the keyboard.
import { figureName } from '../files';
import { browserStorage } from '../files';
import type { LazyDialog } from '../page';
import type { StudioParts } from '../parts';
import { LazyStagesMode } from '../stages';
import { lazyVariants, type LazyVariants } from '../variants';
import { BuildClient, createBuildWorker } from '../../build';
import { LayoutModes } from './layout-modes';
import { installShortcuts, renderShortcutHelp, type ShortcutAction } from './shortcuts';
import { attachSplitter } from './splitter';
import { ViewFollowing } from './view-following';
import { ViewTools } from './view-tools';

/** The controls of the view that other areas reach. */
export interface ViewControls {
  viewTools: ViewTools;
  following: ViewFollowing;
  stages: LazyStagesMode;
  variants: LazyVariants;
}

/** Connects the options to the builds, and the view's tools, following and Stages to the plant on screen. */
export function wireViewControls({ els, derivation, viewOptions, view, preview, opening }: StudioParts): ViewControls {
  derivation.onChange(() => preview.rebuild());
  const viewTools = new ViewTools(els.viewTools, viewOptions, view);
  viewOptions.onChange((_, changed) => (changed.has('sides') || changed.has('smoothAll') || changed.has('render')) && preview.rebuild());
  // The view follows the plant (the timeline's camera frames the growth: ../timeline).
  const following = new ViewFollowing(els.following, view);
  // Stages (the iterations side by side) and Variants (two to six plants, cameras linked): over the
  // view, one at a time, grown in a worker of their own; each loaded when first opened.
  const figures = {
    shown: () => preview.lastGood,
    createClient: () => new BuildClient(createBuildWorker),
    lighting: () => viewOptions.values.lighting,
    lineWidth: () => viewOptions.values.lineWidth,
    fileName: () => figureName(opening.namedFile, preview.lastGood?.source),
  };
  const stages = new LazyStagesMode(els.stages, { ...figures, toggled: (on) => (on && variants.close(), viewTools.pauseForStages(on)) });
  const variants = lazyVariants(els.variants, { ...figures, viewport: els.viewport, toggled: (on) => (on && stages.close(), viewTools.pauseForStages(on)) });
  viewOptions.onChange((values, changed) => changed.has('lighting') && [stages, variants].forEach((shown) => shown.setLighting(values.lighting)));
  preview.onDelivered((result) => {
    stages.delivered(result);
    derivation.buildShown(result.build);
    viewTools.showProjection();
  });
  return { viewTools, following, stages, variants };
}

/** The layout for the room: narrow screens, Large for a projector, fullscreen. */
export function wireLayout({ els, editor, view }: StudioParts): LayoutModes {
  const layout = new LayoutModes(
    els.layout,
    { remeasureEditor: () => editor.requestMeasure(), largeChanged: (large) => view.setLineScale(large ? 2 : 1) },
    browserStorage(),
  );
  els.stopBuild.addEventListener('click', () => editor.focus()); // the text stays, to edit on
  els.showProblems.addEventListener('click', () => {
    layout.showPane('grammar'); // on a narrow screen the list is under the text, in the grammar's pane
    editor.showProblems();
  });
  return layout;
}

/** What the keyboard reaches beyond the parts. */
export interface KeyboardTargets extends ViewControls {
  layout: LayoutModes;
  gallery: LazyDialog;
}

/** Keyboard: shortcuts anywhere, their help, the splitter. */
export function wireKeyboard({ els, derivation, view, help, timeline }: StudioParts, { viewTools, stages, layout, gallery }: KeyboardTargets): void {
  const actions: Record<ShortcutAction, () => void> = {
    stepBack: () => derivation.playback.stepBy(-1),
    stepForward: () => derivation.playback.stepBy(+1),
    playPause: () => timeline.toggle(),
    reroll: () => derivation.reroll(),
    gallery: () => gallery.open(),
    frame: () => view.frame(),
    projection: () => viewTools.toggleProjection(),
    stages: () => (stages.open ? stages.close() : stages.show()),
    fullscreen: () => layout.toggleViewOnly(),
    large: () => layout.setLarge(!layout.large),
    help: () => help.open(),
  };
  installShortcuts(window, (action) => actions[action]());
  renderShortcutHelp(els.shortcutList);
  attachSplitter(els.splitter, els.studio);
}
