// The Derivation tab's view, loaded when the tab is first shown (issue 22: the first plant needs
// none of it). Until then it only remembers the last build, and hands it over when it arrives.
import type { PlantBuild, PlantInspector } from '../../core';
import type { DerivationView, DerivationViewHost } from './derivation-view';

/** A {@link DerivationView} in `root` that loads with the tab's first showing. */
export class LazyDerivationView {
  private view: DerivationView | undefined;
  private loading: Promise<void> | undefined;
  private build: [PlantBuild, PlantInspector | undefined] | undefined;
  private shown = false;

  constructor(
    private readonly root: HTMLElement,
    private readonly host: DerivationViewHost,
  ) {}

  /** As {@link DerivationView.setBuild}: kept for the view until it has loaded. */
  setBuild(build: PlantBuild, inspector: PlantInspector | undefined): void {
    this.build = [build, inspector];
    this.view?.setBuild(build, inspector);
  }

  /** As {@link DerivationView.reload}: nothing to reload before the view has loaded (it asks when it does). */
  reload(): void {
    this.view?.reload();
  }

  /** As {@link DerivationView.setShown}; the first showing loads the view. */
  setShown(shown: boolean): void {
    this.shown = shown;
    if (this.view) return this.view.setShown(shown);
    if (shown) this.loading ??= this.load();
  }

  private async load(): Promise<void> {
    try {
      const { DerivationView } = await import('./derivation-view');
      const view = new DerivationView(this.root, this.host);
      if (this.build) view.setBuild(...this.build);
      view.setShown(this.shown);
      this.view = view;
    } catch (error) {
      this.loading = undefined; // the next showing tries again
      console.error('The derivation view could not load:', error);
    }
  }
}
