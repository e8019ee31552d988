// The sliders of a grammar's constants, their code loaded on first use (issue 22, the first load):
// the studio makes them when the language's vocabulary arrives after the first plant (the panel
// reads the text only with it, studio/controls/vocabulary-panels.ts); an embed, when its controls
// ask for sliders.
import type { SliderPanel } from './sliders';

/** A {@link SliderPanel} made by {@link LazySliderPanel.load}; until then it has no sliders. */
export class LazySliderPanel {
  private panel: SliderPanel | undefined;
  /** The last text to show, until the panel is made. */
  private text: string | undefined;

  constructor(private readonly args: ConstructorParameters<typeof SliderPanel>) {}

  /** Loads the panel's code and makes it (once). */
  async load(): Promise<void> {
    const { SliderPanel } = await import('./sliders');
    if (this.panel) return;
    this.panel = new SliderPanel(...this.args);
    if (this.text !== undefined) this.panel.update(this.text);
  }

  /** As {@link SliderPanel.values}: none before the panel is made. */
  values(): Record<string, number> {
    return this.panel?.values() ?? {};
  }

  /** As {@link SliderPanel.reset}. */
  reset(): void {
    this.panel?.reset();
  }

  /** As {@link SliderPanel.update} (shown when the panel is made, before). */
  update(text: string): void {
    this.text = text;
    this.panel?.update(text);
  }
}
