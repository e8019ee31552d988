// Variants (./variants.ts, with its bar, cards and figure), loaded when first opened (the first
// plant needs none of it): until then only its button listens.
import type { SharedVariant } from '../../share';
import type { VariantsHost, VariantsMode } from './variants';
import { onDemand } from '../page';

/** The Variants view as the studio reaches it before and after it has loaded. */
export interface LazyVariants {
  /** As {@link VariantsMode.show}: with a link's `variants`; the first call loads it. */
  show(variants?: readonly SharedVariant[]): void;
  /** As {@link VariantsMode.close}. */
  close(): void;
  /** As {@link VariantsMode.shared}: none before it has loaded. */
  shared(): SharedVariant[] | undefined;
  /** As {@link VariantsMode.setLighting}: read from the host when it opens. */
  setLighting(lit: boolean): void;
}

/** The Variants view of `toggle`, loaded with its first opening (a failure is said in the console; the next click tries again). */
export function lazyVariants(toggle: HTMLButtonElement, host: VariantsHost): LazyVariants {
  let mode: VariantsMode | undefined;
  const loaded = onDemand(async () => (mode = new (await import('./variants')).VariantsMode(toggle, host)));
  const then = (run: (mode: VariantsMode) => unknown) => void loaded().then(run, (error: unknown) => console.error('Variants could not load:', error));
  toggle.addEventListener('click', () => then((m) => m.toggle()));
  return {
    show: (variants) => then((m) => m.show(variants)),
    close: () => mode?.close(),
    shared: () => mode?.shared(),
    setLighting: (lit) => mode?.setLighting(lit),
  };
}
