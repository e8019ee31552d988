// Variants (./variants.ts, with its bar, cards and figure), loaded when first opened (the first
// plant needs none of it): until then only its button listens.
import type { SharedVariant } from '../../share';
import type { VariantsHost, VariantsMode } from './variants';
import { onDemand } from '../page';

/** A {@link VariantsMode} that loads with its first opening. */
export class LazyVariants {
  private mode: VariantsMode | undefined;

  constructor(
    private readonly toggle: HTMLButtonElement,
    private readonly host: VariantsHost,
  ) {
    this.toggle.addEventListener('click', () => this.load((mode) => mode.toggle()));
  }

  /** As {@link VariantsMode.show}: with a link's `variants`. */
  show(variants?: readonly SharedVariant[]): void {
    this.load((mode) => void mode.show(variants));
  }

  /** As {@link VariantsMode.close}. */
  close(): void {
    this.mode?.close();
  }

  /** As {@link VariantsMode.shared}: none before it has loaded. */
  shared(): SharedVariant[] | undefined {
    return this.mode?.shared();
  }

  /** As {@link VariantsMode.setLighting}: read from the host when it opens. */
  setLighting(lit: boolean): void {
    this.mode?.setLighting(lit);
  }

  private readonly loaded = onDemand(async () => (this.mode = new (await import('./variants')).VariantsMode(this.toggle, this.host)));

  /** Runs `then` on the view, loaded (a failure is said in the console; the next click tries again). */
  private load(then: (mode: VariantsMode) => void): void {
    this.loaded().then(then, (error: unknown) => console.error('Variants could not load:', error));
  }
}
