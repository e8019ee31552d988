// The parts of the studio page that its areas share, made once by the composition root (main.ts)
// and handed to each area's `wire…` call: the areas reach each other only through these.
import type { LazyGrammarEditor } from '../editor/grammar-text';
import type { GrammarStore, KeptTexts } from '../share';
import type { PlantView } from '../view';
import type { LazySliderPanel } from '../plant-controls';
import type { ViewOptions } from './controls';
import type { DerivationControls, LazyContextView, LazyDerivationView } from './derivation';
import type { TextKeeper, TextOpening } from './files';
import type { HelpOpener, Notice, StudioElements } from './page';
import type { LivePreview } from './preview';
import type { LazyTimeline } from './timeline';

/** The user's work: the grammars kept in the browser (localStorage, else IndexedDB). */
export interface KeptWork {
  store: GrammarStore;
  kept: KeptTexts;
  keeper: TextKeeper;
}

/** What every area of the studio may use. */
export interface StudioParts extends KeptWork {
  els: StudioElements;
  notice: Notice;
  view: PlantView;
  viewOptions: ViewOptions;
  /** The iterations, seed and playback. */
  derivation: DerivationControls;
  help: HelpOpener;
  editor: LazyGrammarEditor;
  sliders: LazySliderPanel;
  contexts: LazyContextView;
  derivationView: LazyDerivationView;
  preview: LivePreview;
  opening: TextOpening;
  /** The growth timeline (its bar loads after the first plant). */
  timeline: LazyTimeline;
}
