// What the studio loads on first use (issue 22: the first load carries none of it): dialogs,
// Stages, branch editing (by the core's `onDemand`).
import { onDemand } from '../../core';

/** A dialog loaded when first opened. */
export interface LazyDialog {
  /** Opens the dialog, loading it first if need be (a failure is logged and tried again next time). */
  open(): void;
  /** Loads the dialog in the background, so that the first click opens it at once. */
  preload(): Promise<unknown>;
}

/** The dialog `make` makes, on its first opening; `what` names it in the console if it cannot load. */
export function lazyDialog(what: string, make: () => Promise<{ open(): unknown }>): LazyDialog {
  const made = onDemand(make);
  return {
    open: () => void made().then((dialog) => dialog.open()).catch((error: unknown) => console.error(`Could not open ${what}:`, error)),
    preload: () => made().catch(() => undefined),
  };
}
