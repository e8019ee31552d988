// The studio's state as a share link holds it (`SharedState`): gathered from the pieces that keep
// it, and given back to them when a link is opened.
import type { SharedState } from '../../share';
import type { GrammarEditor } from '../../editor';
import type { PlantView } from '../../view';
import type { BranchEdits } from '../branches';
import type { DerivationControls } from '../derivation';
import type { LivePreview } from '../preview';
import type { LazySliderPanel } from '../../plant-controls';
import type { ViewOptions } from '../controls';
import type { LazyTimeline } from '../timeline';
import type { LazyVariants } from '../variants';

/** The pieces that keep what a link holds. */
export interface LinkStateParts {
  editor: GrammarEditor;
  derivation: DerivationControls;
  sliders: LazySliderPanel;
  viewOptions: ViewOptions;
  view: PlantView;
  branchEdits: BranchEdits;
  /** The growth timeline: time, speed, range. */
  timeline: LazyTimeline;
  /** Its builds: a link's camera is set once the link's plant is on screen. */
  preview: LivePreview;
  /** The Variants view: its plants, when open. */
  variants: LazyVariants;
}

/** Gathers and restores the state of a share link. */
export class LinkState {
  /** A link's camera, waiting for the first good build of its plant. */
  private camera: SharedState['camera'];

  constructor(private readonly parts: LinkStateParts) {
    parts.preview.onDelivered((result) => {
      if (!this.camera || !result.build.ok) return;
      parts.view.setCameraPose({ zoom: 1, ...this.camera });
      this.camera = undefined;
    });
  }

  /** The state now: text, iterations and seed, sliders, view options, camera, branch edits, the timeline, the variants. */
  capture(): SharedState {
    const { editor, derivation, sliders, viewOptions, view, branchEdits } = this.parts;
    const state: SharedState = { text: editor.text(), ...derivation.toShared() };
    const values = sliders.values();
    if (Object.keys(values).length > 0) state.sliders = values;
    state.view = viewOptions.toShared();
    state.camera = view.cameraPose();
    const edits = branchEdits.document();
    if (edits) state.edits = edits;
    const growth = this.parts.timeline.toShared();
    if (growth) state.growth = growth;
    const variants = this.parts.variants.shared();
    if (variants) state.variants = variants;
    return state;
  }

  /**
   * Restores a link's options and edits, its text being in the editor already and its build not yet
   * asked for (the caller asks); its camera is set once the plant is on screen.
   */
  restore(state: SharedState): void {
    this.parts.derivation.applyShared(state);
    this.parts.viewOptions.applyShared(state.view);
    if (state.edits) this.parts.branchEdits.restore(state.edits);
    if (state.camera) this.camera = state.camera;
    this.parts.timeline.applyShared(state.growth);
    if (state.variants) this.parts.variants.show(state.variants);
  }
}
