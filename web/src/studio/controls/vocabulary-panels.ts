// What reads the text with the language's vocabulary (the sliders, the Growth panel, the
// iterations line) starts once it has arrived, after the first plant (issue 22, the first load:
// core/vocabulary.ts); the text is built meanwhile. The Growth panel's code arrives with it.
import { loadVocabulary } from '../../core';
import type { GrammarEditor } from '../../editor/grammar-text';
import type { DerivationControls } from '../derivation';
import type { StudioElements } from '../page';
import type { GrowthPanel } from './growth-panel';
import type { LazySliderPanel } from '../../plant-controls';

/** What the panels read and write. */
export interface VocabularyPanelParts {
  els: StudioElements;
  editor: GrammarEditor;
  sliders: LazySliderPanel;
  derivation: DerivationControls;
}

/** The panels that read the text with the vocabulary, told every change of the text. */
export class VocabularyPanels {
  private growth: GrowthPanel | undefined;
  private arrived = false;
  private asked = false;
  private failed = false;

  constructor(private readonly parts: VocabularyPanelParts) {}

  /** The text is now `text`: the panels read it (nothing before the vocabulary has arrived). */
  read(text: string): void {
    if (!this.arrived) {
      if (this.failed) void this.load(); // after a failed fetch, each edit tries again
      return;
    }
    this.parts.sliders.update(text);
    this.growth?.update(text);
    this.parts.derivation.textChanged(text);
  }

  /**
   * Once: the panels that need the vocabulary. A failed fetch (the network gone between the first
   * plant and it) is logged, the studio goes on without them, and the next edit tries again.
   */
  async load(): Promise<void> {
    if (this.asked) return;
    this.asked = true;
    this.failed = false;
    try {
      const [vocabulary, { GrowthPanel }, { growthAttributes }] = await Promise.all([
        loadVocabulary(),
        this.parts.sliders.load().then(() => import('./growth-panel')),
        import('../../editor/growth-directives'),
      ]);
      this.arrived = true;
      const { els, editor } = this.parts;
      this.growth = new GrowthPanel(
        els.growthRows,
        els.growthCount,
        { text: () => editor.text(), replaceRange: (from, to, insert) => editor.replaceRange(from, to, insert) },
        growthAttributes(vocabulary),
      );
      this.read(editor.text());
    } catch (error) {
      this.asked = false;
      this.failed = true;
      console.error('Could not load the language vocabulary (sliders, Growth panel):', error);
    }
  }
}
